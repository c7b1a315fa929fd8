/*
** lmvmpm.h - the Lua module "mvmpm" and the scene loader the command
** line and the verification scripts share.
*/
#ifndef mvmpm_lmvmpm_h
#define mvmpm_lmvmpm_h

#include <stddef.h>
#include "lua.h"

#define MVMPM_VERSION "0.1.0"

/* open the module (also as global 'mvmpm') and set package.path to the
** project's lua/ directory found from the executable's location */
int luaopen_mvmpm(lua_State *L);
void lmvmpm_setpath(lua_State *L, const char *argv0);
/* parameter overrides from the command line: name=value strings */
void lmvmpm_override(lua_State *L, const char *name, const char *value);
/* after loading: every override must name a declared parameter; returns
** 0 or pushes an error message and returns -1 */
int lmvmpm_check_overrides(lua_State *L);
/* load and run a scene file: pushes its simulation; 0 or -1 with an
** error message pushed */
int lmvmpm_load(lua_State *L, const char *path);
/* the same with the scene's text given (path names it in messages): a
** restart runs the very text it compared with the checkpoint's */
int lmvmpm_load_text(lua_State *L, const char *path, const char *src);
/* the scene parameters in force (every mvmpm.params name the scene
** declared, overridden or not), one "name = value" line each in name
** order; malloc'ed, NULL when out of memory */
char *lmvmpm_params_text(lua_State *L);
/* a regular file's bytes, NUL-terminated (malloc'ed); NULL with the
** reason in err if it cannot be read or is no regular file */
char *lmvmpm_read(const char *path, char *err, size_t errlen);
/* 0 if path is a regular file one can open, else -1 with the reason in
** err: a FIFO or a device would block a reader or never end */
int lmvmpm_regular(const char *path, char *err, size_t errlen);

#endif
