/*
** version.h - what built this binary: the engine's version (git describe
** of the tree it was built from, else MVMPM_VERSION) and the compiler and
** flags.  Only version.c sees the generated values, so a new commit
** rebuilds one object, not all of them.
*/
#ifndef mvmpm_version_h
#define mvmpm_version_h

extern const char mvmpm_version[];   /* e.g. "007b9c9-dirty" or "0.1.0" */
extern const char mvmpm_build[];     /* compiler and flags */

#endif
