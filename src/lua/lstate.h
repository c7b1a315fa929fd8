/*
** lstate.h - a scene's own state (sim:state{...}) as bytes, so that a
** checkpoint carries it and a restart puts it back.
**
** The state is a plain table: keys are strings, numbers or booleans;
** values are numbers (integers and floats keep their subtype and every
** bit), strings, booleans and tables of the same.  Functions, userdata,
** threads, metatables and shared or cyclic references are not saved:
** save refuses them, naming where they sit (state.series[3].fn).
*/
#ifndef mvmpm_lstate_h
#define mvmpm_lstate_h

#include <stddef.h>
#include "lua.h"

/* registry table: state table (by address) -> "scene.lua:7: ", where
** sim:state registered it, so that a save's error names the scene line */
#define LSTATE_WHERE "mvmpm.statewhere"

/* push the table at idx as a string of bytes; raises a Lua error (the
** message names the offending entry) when it holds what cannot be saved */
void lstate_save(lua_State *L, int idx);
/* replace the contents of the table at idx, in place (so closures that
** hold it see the restored values), by the bytes s[0..n) of a save;
** 0, or -1 with a message in err when the bytes are not a saved table */
int lstate_load(lua_State *L, int idx, const char *s, size_t n, char *err,
                size_t errlen);

#endif
