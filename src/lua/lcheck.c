/*
** lcheck.c - checking scene tables with messages a user can act on.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "dim.h"
#include "lcheck.h"

/* edits between a and b: insertions, deletions, substitutions and swaps
** of two neighbours (optimal string alignment), so "stpe" is one edit
** from "step" and not two */
static int distance(const char *a, const char *b) {
  int la = (int)strlen(a), lb = (int)strlen(b), i, j;
  int pp[64], prev[64], cur[64];
  if (la > 60 || lb > 60) return 99;
  for (j = 0; j <= lb; j++) pp[j] = prev[j] = j;
  for (i = 1; i <= la; i++) {
    cur[0] = i;
    for (j = 1; j <= lb; j++) {
      int c = prev[j - 1] + (a[i - 1] != b[j - 1]);
      if (prev[j] + 1 < c) c = prev[j] + 1;
      if (cur[j - 1] + 1 < c) c = cur[j - 1] + 1;
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
          pp[j - 2] + 1 < c)
        c = pp[j - 2] + 1;
      cur[j] = c;
    }
    memcpy(pp, prev, sizeof(int) * (lb + 1));
    memcpy(prev, cur, sizeof(int) * (lb + 1));
  }
  return prev[lb];
}

const char *chk_suggest(const char *key, const char *const allowed[]) {
  const char *best = NULL;
  int bd = 99, k, lim = (int)strlen(key) / 3 + 1;
  for (k = 0; allowed[k]; k++) {
    int d = distance(key, allowed[k]);
    /* ties go to the first in byte order: a table's keys come in no set order */
    if (d < bd || (d == bd && best && strcmp(allowed[k], best) < 0)) {
      bd = d;
      best = allowed[k];
    }
  }
  return bd <= lim ? best : NULL;
}

int chk_nokey(lua_State *L, const char *what, const char *key, int tab,
              const char *const extra[]) {
  const char *names[128];
  const char *s;
  int n = 0, k;
  tab = lua_absindex(L, tab);
  lua_pushnil(L);
  /* the strings stay alive: they are keys of the table, which is on the
  ** stack until the error is raised */
  while (lua_next(L, tab)) {
    lua_pop(L, 1);
    if (n < 120 && lua_type(L, -1) == LUA_TSTRING &&
        lua_tostring(L, -1)[0] != '_')
      names[n++] = lua_tostring(L, -1);
  }
  for (k = 0; extra && extra[k] && n < 127; k++) names[n++] = extra[k];
  names[n] = NULL;
  s = chk_suggest(key, names);
  if (s) return luaL_error(L, "%s has no field or function '%s' (did you "
                              "mean '%s'?)", what, key, s);
  return luaL_error(L, "%s has no field or function '%s'", what, key);
}

static void listall(luaL_Buffer *b, const char *const allowed[]) {
  int k;
  for (k = 0; allowed[k]; k++) {
    if (k) luaL_addstring(b, ", ");
    luaL_addstring(b, allowed[k]);
  }
}

void chk_keys(lua_State *L, int idx, const char *what,
              const char *const allowed[]) {
  idx = lua_absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    int k, ok = 0;
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) {
      const char *key = lua_tostring(L, -1);
      for (k = 0; allowed[k]; k++)
        if (strcmp(key, allowed[k]) == 0) { ok = 1; break; }
      if (!ok) {
        const char *s = chk_suggest(key, allowed);
        luaL_Buffer b;
        if (s)
          luaL_error(L, "%s: unknown field '%s' (did you mean '%s'?)", what,
                     key, s);
        luaL_buffinit(L, &b);
        listall(&b, allowed);
        luaL_pushresult(&b);
        luaL_error(L, "%s: unknown field '%s' (allowed: %s)", what, key,
                   lua_tostring(L, -1));
      }
    } else if (lua_type(L, -1) == LUA_TNUMBER) {
      /* positional entries are checked by the caller */
    } else
      luaL_error(L, "%s: field names must be strings", what);
  }
}

static void range(char *buf, size_t n, double lo, double hi, int flags) {
  const char *l = flags & CHK_OPENLO ? ">" : ">=";
  const char *h = flags & CHK_OPENHI ? "<" : "<=";
  if (lo == -HUGE_VAL && hi == HUGE_VAL) snprintf(buf, n, "finite");
  else if (hi == HUGE_VAL) snprintf(buf, n, "%s %g", l, lo);
  else if (lo == -HUGE_VAL) snprintf(buf, n, "%s %g", h, hi);
  else
    snprintf(buf, n, "in %s%g, %g%s", flags & CHK_OPENLO ? "(" : "[", lo, hi,
             flags & CHK_OPENHI ? ")" : "]");
}

/* %g, but NaN as "nan" whatever its sign bit (0/0 prints "-nan") */
static const char *numstr(char *buf, size_t n, double v) {
  if (isnan(v)) snprintf(buf, n, "nan");
  else snprintf(buf, n, "%g", v);
  return buf;
}

/* is v outside the range, or not finite? */
static int outside(double v, double lo, double hi, int flags) {
  return !isfinite(v) || v < lo || v > hi ||
         ((flags & CHK_OPENLO) && v == lo) || ((flags & CHK_OPENHI) && v == hi);
}

double chk_num(lua_State *L, int idx, const char *what, const char *key,
               double def, double lo, double hi, int flags) {
  double v;
  char r[80], got[32];
  int isnum;
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    if (flags & CHK_REQUIRED)
      luaL_error(L, "%s: field '%s' is required", what, key);
    return def;
  }
  v = lua_tonumberx(L, -1, &isnum);
  if (!isnum)
    luaL_error(L, "%s: field '%s' must be a number (got %s)", what, key,
               luaL_typename(L, -1));
  lua_pop(L, 1);
  range(r, sizeof r, lo, hi, flags);
  /* lua_pushfstring knows no %g: format the number here */
  numstr(got, sizeof got, v);
  if (outside(v, lo, hi, flags))
    luaL_error(L, "%s: field '%s' must be %s (got %s)", what, key, r, got);
  if ((flags & CHK_INT) && v != floor(v))
    luaL_error(L, "%s: field '%s' must be a whole number (got %s)", what, key,
               got);
  return v;
}

double chk_arg(lua_State *L, int arg, const char *what, const char *name,
               double def, double lo, double hi, int flags) {
  double v;
  char r[80], got[32];
  int isnum;
  if (lua_isnoneornil(L, arg)) {
    if (flags & CHK_REQUIRED)
      luaL_error(L, "%s: argument '%s' is required (a number)", what, name);
    return def;
  }
  v = lua_tonumberx(L, arg, &isnum);
  if (!isnum)
    luaL_error(L, "%s: argument '%s' must be a number (got %s)", what, name,
               luaL_typename(L, arg));
  if (outside(v, lo, hi, flags)) {
    range(r, sizeof r, lo, hi, flags);
    numstr(got, sizeof got, v);
    luaL_error(L, "%s: argument '%s' must be %s (got %s)", what, name, r, got);
  }
  if ((flags & CHK_INT) && v != floor(v)) {
    snprintf(got, sizeof got, "%g", v);
    luaL_error(L, "%s: argument '%s' must be a whole number (got %s)", what,
               name, got);
  }
  return v;
}

const char *chk_where(lua_State *L, int idx, char *buf, size_t n) {
  lua_Debug ar;
  if (lua_type(L, idx) != LUA_TFUNCTION) {
    snprintf(buf, n, "[C]");
    return buf;
  }
  lua_pushvalue(L, idx);
  lua_getinfo(L, ">S", &ar); /* pops the function */
  if (ar.linedefined < 0) snprintf(buf, n, "[C]");
  else snprintf(buf, n, "%s:%d", ar.short_src, ar.linedefined);
  return buf;
}

int chk_fnerror(lua_State *L, int fnidx, const char *fmt, ...) {
  char where[LUA_IDSIZE + 16], buf[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  chk_where(L, fnidx, where, sizeof where);
  lua_pushfstring(L, "%s: %s", where, buf);
  return lua_error(L);
}

double chk_result(lua_State *L, int idx, int fnidx, const char *fmt, ...) {
  char what[256], got[32];
  int isnum;
  double v = lua_tonumberx(L, idx, &isnum);
  va_list ap;
  if (isnum && isfinite(v)) return v;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  if (isnum)
    return chk_fnerror(L, fnidx, "%s returned %s (it must return finite "
                       "numbers)", what, numstr(got, sizeof got, v));
  return chk_fnerror(L, fnidx, "%s returned %s (not a number)", what,
                     luaL_typename(L, idx));
}

int chk_oneof(lua_State *L, const char *s, const char *what,
              const char *const opts[]) {
  int k;
  for (k = 0; opts[k]; k++)
    if (strcmp(s, opts[k]) == 0) return k;
  {
    luaL_Buffer b;
    const char *sug = chk_suggest(s, opts);
    luaL_buffinit(L, &b);
    listall(&b, opts);
    luaL_pushresult(&b);
    luaL_error(L, "%s must be one of %s (got '%s'%s%s%s)", what,
               lua_tostring(L, -1), s, sug ? "; did you mean '" : "",
               sug ? sug : "", sug ? "'?" : "");
  }
  return -1;
}

int chk_option(lua_State *L, int idx, const char *what, const char *key,
               int def, const char *const opts[]) {
  char field[160];
  int k;
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return def; }
  if (lua_type(L, -1) != LUA_TSTRING)
    luaL_error(L, "%s: field '%s' must be a string (got %s)", what, key,
               luaL_typename(L, -1));
  snprintf(field, sizeof field, "%s: field '%s'", what, key);
  k = chk_oneof(L, lua_tostring(L, -1), field, opts);
  lua_pop(L, 1);
  return k;
}

int chk_bool(lua_State *L, int idx, const char *what, const char *key,
             int def) {
  int v;
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return def; }
  if (!lua_isboolean(L, -1))
    luaL_error(L, "%s: field '%s' must be true or false (got %s)", what, key,
               luaL_typename(L, -1));
  v = lua_toboolean(L, -1);
  lua_pop(L, 1);
  return v;
}

void chk_vec(lua_State *L, int idx, const char *what, const char *key,
             double *v, int n, int required) {
  int k;
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    if (required) luaL_error(L, "%s: field '%s' is required", what, key);
    return;
  }
  if (!lua_istable(L, -1))
    luaL_error(L, "%s: field '%s' must be a list of %d numbers (got %s)", what,
               key, n, luaL_typename(L, -1));
  if (luaL_len(L, -1) != n)
    luaL_error(L, "%s: field '%s' must be a list of %d numbers (got %d)%s",
               what, key, n, (int)luaL_len(L, -1),
               n == DIM ? (DIM == 2 ? "; the scene is 2-D"
                                    : "; the scene is 3-D") : "");
  for (k = 0; k < n; k++) {
    int isnum;
    lua_geti(L, -1, k + 1);
    v[k] = lua_tonumberx(L, -1, &isnum);
    if (!isnum || !isfinite(v[k]))
      luaL_error(L, "%s: field '%s' entry %d must be a finite number", what,
                 key, k + 1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

const char *chk_pt(char *buf, const double *x) {
  int d, n = 0;
  for (d = 0; d < DIM; d++)
    n += snprintf(buf + n, (size_t)(CHK_PTLEN - n), "%s%g", d ? ", " : "(", x[d]);
  snprintf(buf + n, (size_t)(CHK_PTLEN - n), ")");
  return buf;
}

/* luaL_error with the C library's formats (lua_pushfstring knows no %g):
** the message is formatted here, then raised with the scene's position */
int chk_error(lua_State *L, const char *fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return luaL_error(L, "%s", buf);
}
