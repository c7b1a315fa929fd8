/*
** lcheck.h - checking scene tables.  Every error names the scene file
** and line (luaL_error's position: the Lua line that made the call), the
** object and field, and the allowed range, e.g.
**   bounce.lua:12: sim: field 'cell' must be > 0 (got -0.1)
**   bounce.lua:14: body: unknown field 'materal' (did you mean 'material'?)
*/
#ifndef mvmpm_lcheck_h
#define mvmpm_lcheck_h

#include "lua.h"
#include "lauxlib.h"

/* raise an error for every key of the table at idx not in allowed (NULL
** terminated) */
void chk_keys(lua_State *L, int idx, const char *what,
              const char *const allowed[]);
/* number field: def if absent; must lie in [lo, hi] (open ends if the
** flags say so); int_only refuses fractions */
enum { CHK_OPENLO = 1, CHK_OPENHI = 2, CHK_INT = 4, CHK_REQUIRED = 8 };
double chk_num(lua_State *L, int idx, const char *what, const char *key,
               double def, double lo, double hi, int flags);
/* the index of string s in opts (NULL-ended), else an error naming what
** ("sides.left: the kind"), the allowed values and the nearest */
int chk_oneof(lua_State *L, const char *s, const char *what,
              const char *const opts[]);
/* string field, one of the options (NULL terminated); returns its index */
int chk_option(lua_State *L, int idx, const char *what, const char *key,
               int def, const char *const opts[]);
/* boolean field */
int chk_bool(lua_State *L, int idx, const char *what, const char *key,
             int def);
/* vector field {x, y}: fills v (defaults kept if absent) */
void chk_vec(lua_State *L, int idx, const char *what, const char *key,
             double *v, int n, int required);
/* a point of DIM coordinates as "(x, y)" or "(x, y, z)" for messages,
** written into buf (CHK_PTLEN chars), which it returns */
#define CHK_PTLEN 80
const char *chk_pt(char *buf, const double *x);
/* a number argument of an API function (arg, named name for messages):
** finite and in [lo, hi] as chk_num's flags say; CHK_REQUIRED unset, def
** when absent.  "what: argument 'name' must be finite (got nan)" */
double chk_arg(lua_State *L, int arg, const char *what, const char *name,
               double def, double lo, double hi, int flags);
/* where the function at idx was defined: "scene.lua:12" ("[C]" for a C
** function); buf holds it */
const char *chk_where(lua_State *L, int idx, char *buf, size_t n);
/* the value at idx, which the scene function at fnidx returned, as a
** finite number; else raises "scene.lua:12: WHAT returned nan" (WHAT
** from fmt, formatted only then), placed where the function was defined:
** it runs between steps, where no scene line is on the stack */
double chk_result(lua_State *L, int idx, int fnidx, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* chk_error placed where the function at fnidx was defined, for errors
** raised between steps about a scene function (no scene line is on the
** stack then) */
int chk_fnerror(lua_State *L, int fnidx, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* luaL_error with printf formats (%g, %.3g ...), which luaL_error lacks */
int chk_error(lua_State *L, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* the closest allowed word to key, or NULL if none is close */
const char *chk_suggest(const char *key, const char *const allowed[]);
/* an unknown name read from an object: raises "WHAT has no field or
** function 'key' (did you mean 'x'?)", the names being the string keys
** of the table at tab (its methods, or a module's functions) and the
** NULL-terminated extra (its fields; may be NULL).  Never returns */
int chk_nokey(lua_State *L, const char *what, const char *key, int tab,
              const char *const extra[]);

#endif
