/*
** version.c - the build's identity (version.h).  The values come from
** the generated $(BUILD)/version_gen.h, which the Makefile rewrites only
** when they change.
*/
#include "lmvmpm.h"
#include "version.h"
#include "version_gen.h"

#ifndef MVMPM_GIT_VERSION
#define MVMPM_GIT_VERSION MVMPM_VERSION
#endif
#ifndef MVMPM_BUILD
#define MVMPM_BUILD "unknown"
#endif

const char mvmpm_version[] = MVMPM_GIT_VERSION;
const char mvmpm_build[] = MVMPM_BUILD;
