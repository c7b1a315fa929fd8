/*
** lua_shape.c - regions to seed bodies from: disk, annulus, rect,
** polygon, a Lua predicate, and "rest" (every seeding point no earlier
** body took: the binder between grains).
*/
#include <math.h>
#include <string.h>
#include "lcheck.h"
#include "lsim.h"

lshape *lshape_check(lua_State *L, int idx) {
  return luaL_checkudata(L, idx, LSHAPE_MT);
}

static lshape *newshape(lua_State *L, int kind, int npts) {
  lshape *sh = lua_newuserdatauv(L, sizeof *sh + 2 * npts * sizeof(double), 1);
  memset(sh, 0, sizeof *sh);
  sh->kind = kind;
  sh->npts = npts;
  luaL_setmetatable(L, LSHAPE_MT);
  return sh;
}

static int disk(lua_State *L) {
  static const char *const keys[] = {"center", "radius", NULL};
  double c[DIM] = {0}, r;
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "disk", keys);
  chk_vec(L, 1, "disk", "center", c, DIM, 1);
  r = chk_num(L, 1, "disk", "radius", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  sh = newshape(L, SH_DISK, 0);
  for (d = 0; d < DIM; d++) {
    sh->c[d] = c[d];
    sh->lo[d] = c[d] - r;
    sh->hi[d] = c[d] + r;
  }
  sh->r = r;
  return 1;
}

static int annulus(lua_State *L) {
  static const char *const keys[] = {"center", "inner", "outer", NULL};
  double c[DIM] = {0}, r0, r;
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "annulus", keys);
  chk_vec(L, 1, "annulus", "center", c, DIM, 1);
  r0 = chk_num(L, 1, "annulus", "inner", 0, 0, HUGE_VAL, CHK_REQUIRED);
  r = chk_num(L, 1, "annulus", "outer", 0, r0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  sh = newshape(L, SH_ANNULUS, 0);
  for (d = 0; d < DIM; d++) {
    sh->c[d] = c[d];
    sh->lo[d] = c[d] - r;
    sh->hi[d] = c[d] + r;
  }
  sh->r = r;
  sh->r0 = r0;
  return 1;
}

static int rect(lua_State *L) {
  static const char *const keys[] = {"lo", "hi", NULL};
  double lo[DIM], hi[DIM];
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "rect", keys);
  chk_vec(L, 1, "rect", "lo", lo, DIM, 1);
  chk_vec(L, 1, "rect", "hi", hi, DIM, 1);
  for (d = 0; d < DIM; d++)
    if (!(hi[d] > lo[d]))
      chk_error(L, "rect: field 'hi' must exceed 'lo' in every coordinate "
                    "(coordinate %d: lo %g, hi %g)", d + 1, lo[d], hi[d]);
  sh = newshape(L, SH_RECT, 0);
  for (d = 0; d < DIM; d++) { sh->lo[d] = lo[d]; sh->hi[d] = hi[d]; }
  return 1;
}

/* polygon{{x1,y1}, {x2,y2}, ...}: simple polygon, either orientation */
static int polygon(lua_State *L) {
  int n, k, d;
  lshape *sh;
  luaL_checktype(L, 1, LUA_TTABLE);
  n = (int)luaL_len(L, 1);
  if (n < 3) luaL_error(L, "polygon: needs at least 3 vertices (got %d)", n);
  sh = newshape(L, SH_POLYGON, n);
  for (d = 0; d < DIM; d++) { sh->lo[d] = HUGE_VAL; sh->hi[d] = -HUGE_VAL; }
  for (k = 0; k < n; k++) {
    lua_geti(L, 1, k + 1);
    if (!lua_istable(L, -1) || luaL_len(L, -1) != 2)
      luaL_error(L, "polygon: vertex %d must be {x, y}", k + 1);
    for (d = 0; d < 2; d++) {
      int isnum;
      double v;
      lua_geti(L, -1, d + 1);
      v = lua_tonumberx(L, -1, &isnum);
      if (!isnum || !isfinite(v))
        luaL_error(L, "polygon: vertex %d coordinate %d must be a finite number",
                   k + 1, d + 1);
      lua_pop(L, 1);
      sh->pts[2 * k + d] = v;
      if (v < sh->lo[d]) sh->lo[d] = v;
      if (v > sh->hi[d]) sh->hi[d] = v;
    }
    lua_pop(L, 1);
  }
  return 1;
}

/* region{inside = function(x, y) ... end, lo = {..}, hi = {..}} */
static int region(lua_State *L) {
  static const char *const keys[] = {"inside", "lo", "hi", NULL};
  lshape *sh;
  double lo[DIM], hi[DIM];
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "region", keys);
  chk_vec(L, 1, "region", "lo", lo, DIM, 1);
  chk_vec(L, 1, "region", "hi", hi, DIM, 1);
  lua_getfield(L, 1, "inside");
  if (!lua_isfunction(L, -1))
    luaL_error(L, "region: field 'inside' must be a function(x, y)");
  sh = newshape(L, SH_FUNC, 0);
  for (d = 0; d < DIM; d++) { sh->lo[d] = lo[d]; sh->hi[d] = hi[d]; }
  lua_insert(L, -2);
  lua_setiuservalue(L, -2, 1);
  return 1;
}

static int rest(lua_State *L) {
  lshape *sh = newshape(L, SH_REST, 0);
  int d;
  for (d = 0; d < DIM; d++) { sh->lo[d] = -HUGE_VAL; sh->hi[d] = HUGE_VAL; }
  return 1;
}

static int inpoly(const lshape *sh, double x, double y) {
  int k, j, in = 0;
  for (k = 0, j = sh->npts - 1; k < sh->npts; j = k++) {
    double xk = sh->pts[2 * k], yk = sh->pts[2 * k + 1];
    double xj = sh->pts[2 * j], yj = sh->pts[2 * j + 1];
    if ((yk > y) != (yj > y) && x < (xj - xk) * (y - yk) / (yj - yk) + xk)
      in = !in;
  }
  return in;
}

int lshape_inside(lua_State *L, int idx, const lshape *sh, const double *x) {
  double r2 = 0;
  int d, in;
  switch (sh->kind) {
  case SH_DISK:
  case SH_ANNULUS:
    for (d = 0; d < DIM; d++) r2 += (x[d] - sh->c[d]) * (x[d] - sh->c[d]);
    return r2 < sh->r * sh->r && (sh->kind == SH_DISK || r2 >= sh->r0 * sh->r0);
  case SH_RECT:
    for (d = 0; d < DIM; d++)
      if (x[d] < sh->lo[d] || x[d] >= sh->hi[d]) return 0;
    return 1;
  case SH_POLYGON: return inpoly(sh, x[0], x[1]);
  case SH_REST: return 1;
  default:
    lua_getiuservalue(L, idx, 1);
    for (d = 0; d < DIM; d++) lua_pushnumber(L, x[d]);
    lua_call(L, DIM, 1);
    in = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return in;
  }
}

double lshape_area(const lshape *sh) {
  double a = 0;
  int k, j;
  switch (sh->kind) {
  case SH_DISK: return M_PI * sh->r * sh->r;
  case SH_ANNULUS: return M_PI * (sh->r * sh->r - sh->r0 * sh->r0);
  case SH_RECT: return (sh->hi[0] - sh->lo[0]) * (sh->hi[1] - sh->lo[1]);
  case SH_POLYGON:
    for (k = 0, j = sh->npts - 1; k < sh->npts; j = k++)
      a += sh->pts[2 * j] * sh->pts[2 * k + 1] - sh->pts[2 * k] * sh->pts[2 * j + 1];
    return fabs(a) / 2;
  default: return -1;
  }
}

static int area(lua_State *L) {
  double a = lshape_area(lshape_check(L, 1));
  if (a < 0) lua_pushnil(L); else lua_pushnumber(L, a);
  return 1;
}

static int tostr(lua_State *L) {
  static const char *const names[] = {"disk", "annulus", "rect", "polygon",
                                      "rest", "region"};
  lshape *sh = lshape_check(L, 1);
  lua_pushfstring(L, "shape %s", names[sh->kind]);
  return 1;
}

void lshape_open(lua_State *L, int modidx) {
  static const luaL_Reg fns[] = {{"disk", disk}, {"annulus", annulus},
                                 {"rect", rect}, {"polygon", polygon},
                                 {"region", region}, {"rest", rest},
                                 {NULL, NULL}};
  static const luaL_Reg meth[] = {{"area", area}, {NULL, NULL}};
  luaL_newmetatable(L, LSHAPE_MT);
  lua_pushcfunction(L, tostr);
  lua_setfield(L, -2, "__tostring");
  luaL_newlib(L, meth);
  lua_setfield(L, -2, "__index");
  lsim_lock(L, -1);
  lua_pop(L, 1);
  lua_pushvalue(L, modidx);
  luaL_setfuncs(L, fns, 0);
  lua_pop(L, 1);
}
