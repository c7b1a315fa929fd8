/*
** lstate.c - a plain Lua table as bytes (see lstate.h).
** Encoding, one tag byte per value:
**   'i' int64 (8 bytes, little end first)   'f' double (its 8 bytes)
**   's' length (4 bytes) then the bytes    'T' true   'F' false
**   '{' pairs of key and value ... '}'
** A table's array part 1..#t goes first, in order, so that a restored
** table is built in the order the scene built it.
*/
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lauxlib.h"
#include "lstate.h"

#define MAXDEPTH 64

typedef struct wbuf {
  char *b;
  size_t n, cap;
  int bad;                 /* out of memory */
  char where[256];         /* path of the value being written */
  char err[320];
} wbuf;

static void put(wbuf *w, const void *p, size_t n) {
  if (w->bad) return;
  if (w->n + n > w->cap) {
    size_t cap = w->cap ? 2 * w->cap : 256;
    char *q;
    while (cap < w->n + n) cap *= 2;
    if (!(q = realloc(w->b, cap))) { w->bad = 1; return; }
    w->b = q;
    w->cap = cap;
  }
  memcpy(w->b + w->n, p, n);
  w->n += n;
}

static void put64(wbuf *w, char tag, uint64_t u) {
  unsigned char b[9];
  int k;
  b[0] = (unsigned char)tag;
  for (k = 0; k < 8; k++) b[k + 1] = (unsigned char)(u >> (8 * k));
  put(w, b, 9);
}

/* extend the path with a key: .name or [k] */
static size_t push_where(lua_State *L, wbuf *w, int key) {
  size_t len = strlen(w->where);
  if (lua_type(L, key) == LUA_TSTRING)
    snprintf(w->where + len, sizeof w->where - len, ".%s", lua_tostring(L, key));
  else if (lua_isinteger(L, key))
    snprintf(w->where + len, sizeof w->where - len, "[%lld]",
             (long long)lua_tointeger(L, key));
  else if (lua_type(L, key) == LUA_TNUMBER)
    snprintf(w->where + len, sizeof w->where - len, "[%.17g]", lua_tonumber(L, key));
  else
    snprintf(w->where + len, sizeof w->where - len, "[%s]",
             lua_toboolean(L, key) ? "true" : "false");
  return len;
}

static int value(lua_State *L, wbuf *w, int idx, int depth, int iskey);

static int pair(lua_State *L, wbuf *w, int k, int v, int depth) {
  size_t len;
  int t = lua_type(L, k), r;
  if (t != LUA_TSTRING && t != LUA_TNUMBER && t != LUA_TBOOLEAN) {
    snprintf(w->err, sizeof w->err, "%s has a key that is a %s; keys must "
             "be strings, numbers or booleans", w->where, luaL_typename(L, k));
    return -1;
  }
  if (value(L, w, k, depth, 1)) return -1;
  len = push_where(L, w, k);
  r = value(L, w, v, depth, 0);
  w->where[len] = '\0';
  return r;
}

static int table(lua_State *L, wbuf *w, int idx, int depth) {
  lua_Integer n, i;
  if (depth >= MAXDEPTH) {
    snprintf(w->err, sizeof w->err, "%s is nested more than %d tables deep "
             "(or refers to itself)", w->where, MAXDEPTH);
    return -1;
  }
  if (lua_getmetatable(L, idx)) {
    lua_pop(L, 1);
    snprintf(w->err, sizeof w->err, "%s has a metatable, which is not saved",
             w->where);
    return -1;
  }
  luaL_checkstack(L, 6, "state");
  put(w, "{", 1);
  n = (lua_Integer)lua_rawlen(L, idx);
  for (i = 1; i <= n; i++) {
    lua_pushinteger(L, i);
    lua_rawgeti(L, idx, i);
    if (lua_isnil(L, -1)) { lua_pop(L, 2); continue; }
    if (pair(L, w, lua_absindex(L, -2), lua_absindex(L, -1), depth + 1))
      return -1;
    lua_pop(L, 2);
  }
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    int k = lua_absindex(L, -2), v = lua_absindex(L, -1);
    if (!(lua_isinteger(L, k) && lua_tointeger(L, k) >= 1 &&
          lua_tointeger(L, k) <= n) &&
        pair(L, w, k, v, depth + 1)) {
      lua_pop(L, 2);
      return -1;
    }
    lua_pop(L, 1);
  }
  put(w, "}", 1);
  return 0;
}

static int value(lua_State *L, wbuf *w, int idx, int depth, int iskey) {
  switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) put64(w, 'i', (uint64_t)lua_tointeger(L, idx));
      else {
        double d = lua_tonumber(L, idx);
        uint64_t u;
        memcpy(&u, &d, 8);
        put64(w, 'f', u);
      }
      return 0;
    case LUA_TBOOLEAN:
      put(w, lua_toboolean(L, idx) ? "T" : "F", 1);
      return 0;
    case LUA_TSTRING: {
      size_t len;
      const char *s = lua_tolstring(L, idx, &len);
      unsigned char b[5];
      int k;
      if (len > 0xffffffffu) {
        snprintf(w->err, sizeof w->err, "%s: a string longer than 4 GB", w->where);
        return -1;
      }
      b[0] = 's';
      for (k = 0; k < 4; k++) b[k + 1] = (unsigned char)(len >> (8 * k));
      put(w, b, 5);
      put(w, s, len);
      return 0;
    }
    case LUA_TTABLE:
      if (!iskey) return table(L, w, idx, depth);
      break; /* pair() refused table keys already */
    default:
      break;
  }
  snprintf(w->err, sizeof w->err, "%s is a %s; a state holds only "
               "numbers, strings, booleans and tables of them", w->where,
               luaL_typename(L, idx));
  return -1;
}

void lstate_save(lua_State *L, int idx) {
  wbuf w;
  int r;
  memset(&w, 0, sizeof w);
  snprintf(w.where, sizeof w.where, "state");
  idx = lua_absindex(L, idx);
  r = table(L, &w, idx, 0);
  if (r == 0 && w.bad) {
    r = -1;
    snprintf(w.err, sizeof w.err, "state: out of memory");
  }
  if (r == 0) lua_pushlstring(L, w.b ? w.b : "", w.n);
  free(w.b);
  if (r) { /* at checkpoint time: named where sim:state took the table */
    lua_getfield(L, LUA_REGISTRYINDEX, LSTATE_WHERE);
    if (lua_istable(L, -1) && lua_rawgetp(L, -1, lua_topointer(L, idx)) == LUA_TSTRING)
      luaL_error(L, "%ssim:state: %s", lua_tostring(L, -1), w.err);
    luaL_error(L, "sim:state: %s", w.err);
  }
}

/*
** {======================================================
** Reading back
** =======================================================
*/

typedef struct rbuf {
  const unsigned char *p, *end;
  char *err;
  size_t errlen;
} rbuf;

static int bad(rbuf *r, const char *what) {
  snprintf(r->err, r->errlen, "the saved state is damaged (%s)", what);
  return -1;
}

static int get64(rbuf *r, uint64_t *u) {
  int k;
  if (r->end - r->p < 8) return bad(r, "truncated number");
  *u = 0;
  for (k = 0; k < 8; k++) *u |= (uint64_t)r->p[k] << (8 * k);
  r->p += 8;
  return 0;
}

/* push the value at r->p; tables are filled into a new table */
static int rvalue(lua_State *L, rbuf *r, int depth);

static int rpairs(lua_State *L, rbuf *r, int t, int depth) {
  for (;;) {
    if (r->p >= r->end) return bad(r, "unterminated table");
    if (*r->p == '}') { r->p++; return 0; }
    if (rvalue(L, r, depth) || rvalue(L, r, depth)) return -1;
    if (lua_isnil(L, -2) || (lua_type(L, -2) == LUA_TNUMBER &&
                             lua_tonumber(L, -2) != lua_tonumber(L, -2)))
      return bad(r, "a nil or NaN key");
    lua_rawset(L, t);
  }
}

static int rvalue(lua_State *L, rbuf *r, int depth) {
  uint64_t u;
  if (r->p >= r->end) return bad(r, "truncated");
  luaL_checkstack(L, 4, "state");
  switch (*r->p++) {
    case 'i':
      if (get64(r, &u)) return -1;
      lua_pushinteger(L, (lua_Integer)u);
      return 0;
    case 'f': {
      double d;
      if (get64(r, &u)) return -1;
      memcpy(&d, &u, 8);
      lua_pushnumber(L, d);
      return 0;
    }
    case 'T': lua_pushboolean(L, 1); return 0;
    case 'F': lua_pushboolean(L, 0); return 0;
    case 's': {
      size_t len = 0;
      int k;
      if (r->end - r->p < 4) return bad(r, "truncated string");
      for (k = 0; k < 4; k++) len |= (size_t)r->p[k] << (8 * k);
      r->p += 4;
      if ((size_t)(r->end - r->p) < len) return bad(r, "truncated string");
      lua_pushlstring(L, (const char *)r->p, len);
      r->p += len;
      return 0;
    }
    case '{':
      if (depth >= MAXDEPTH) return bad(r, "nested too deep");
      lua_newtable(L);
      return rpairs(L, r, lua_absindex(L, -1), depth + 1);
    default:
      return bad(r, "unknown tag");
  }
}

int lstate_load(lua_State *L, int idx, const char *s, size_t n, char *err,
                size_t errlen) {
  rbuf r;
  int top = lua_gettop(L);
  idx = lua_absindex(L, idx);
  r.p = (const unsigned char *)s;
  r.end = r.p + n;
  r.err = err;
  r.errlen = errlen;
  if (n < 2 || *r.p != '{') return bad(&r, "not a table");
  /* build it aside first: a damaged state leaves the scene's table as is */
  if (rvalue(L, &r, 0) || r.p != r.end) {
    if (r.p != r.end && lua_gettop(L) > top) bad(&r, "trailing bytes");
    lua_settop(L, top);
    return -1;
  }
  /* empty the scene's table (clearing fields during a traversal is
  ** allowed), then copy the saved entries in, array part in order */
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    lua_pop(L, 1);
    lua_pushvalue(L, -1);
    lua_pushnil(L);
    lua_rawset(L, idx);
  }
  {
    lua_Integer i, len = (lua_Integer)lua_rawlen(L, -1);
    for (i = 1; i <= len; i++) {
      lua_rawgeti(L, -1, i);
      lua_rawseti(L, idx, i);
    }
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      if (lua_isinteger(L, -2) && lua_tointeger(L, -2) >= 1 &&
          lua_tointeger(L, -2) <= len) {
        lua_pop(L, 1);
        continue;
      }
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_rawset(L, idx);
    }
  }
  lua_settop(L, top);
  return 0;
}

/* }====================================================== */
