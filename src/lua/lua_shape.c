/*
** lua_shape.c - regions to seed bodies from: disk, annulus, rect,
** polygon, cylinder, extrude, a Lua predicate, and "rest" (every seeding
** point no earlier body took: the binder between grains).
**
** Every point and extent has DIM coordinates.  The round shapes are the
** same code in either dimension: disk is a ball in 3-D (ball is its
** other name, in both), annulus a spherical shell (shell), rect a box
** (box).  polygon is 2-D; its 3-D counterpart is extrude, a polygon
** swept along one axis.  cylinder runs from a base point to an end point
** (in 2-D: the strip of width 2 radius along that segment).
*/
#include <math.h>
#include <string.h>
#include "lcheck.h"
#include "vec.h"
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

/* the name the scene called a shape by (disk or ball ...): an upvalue */
static const char *fname(lua_State *L) {
  return lua_tostring(L, lua_upvalueindex(1));
}

static int disk(lua_State *L) {
  static const char *const keys[] = {"center", "radius", NULL};
  const char *what = fname(L);
  double c[DIM] = {0}, r;
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  chk_vec(L, 1, what, "center", c, DIM, 1);
  r = chk_num(L, 1, what, "radius", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
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
  const char *what = fname(L);
  double c[DIM] = {0}, r0, r;
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  chk_vec(L, 1, what, "center", c, DIM, 1);
  r0 = chk_num(L, 1, what, "inner", 0, 0, HUGE_VAL, CHK_REQUIRED);
  r = chk_num(L, 1, what, "outer", 0, r0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
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
  const char *what = fname(L);
  double lo[DIM], hi[DIM];
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  chk_vec(L, 1, what, "lo", lo, DIM, 1);
  chk_vec(L, 1, what, "hi", hi, DIM, 1);
  for (d = 0; d < DIM; d++)
    if (!(hi[d] > lo[d]))
      chk_error(L, "%s: field 'hi' must exceed 'lo' in every coordinate "
                    "(coordinate %d: lo %g, hi %g)", what, d + 1, lo[d], hi[d]);
  sh = newshape(L, SH_RECT, 0);
  for (d = 0; d < DIM; d++) { sh->lo[d] = lo[d]; sh->hi[d] = hi[d]; }
  return 1;
}

/* read the polygon at idx (a list of {a, b} vertices) into sh->pts,
** widening the bounding box along the axes p0, p1 */
static void readpoly(lua_State *L, int idx, const char *what, lshape *sh,
                     int p0, int p1) {
  int k, j;
  for (k = 0; k < sh->npts; k++) {
    lua_geti(L, idx, k + 1);
    if (!lua_istable(L, -1) || luaL_len(L, -1) != 2)
      luaL_error(L, "%s: vertex %d must be a list of 2 numbers {a, b} (the "
                    "polygon is plane)", what, k + 1);
    for (j = 0; j < 2; j++) {
      int isnum, d = j ? p1 : p0;
      double v;
      lua_geti(L, -1, j + 1);
      v = lua_tonumberx(L, -1, &isnum);
      if (!isnum || !isfinite(v))
        luaL_error(L, "%s: vertex %d coordinate %d must be a finite number",
                   what, k + 1, j + 1);
      lua_pop(L, 1);
      sh->pts[2 * k + j] = v;
      if (v < sh->lo[d]) sh->lo[d] = v;
      if (v > sh->hi[d]) sh->hi[d] = v;
    }
    lua_pop(L, 1);
  }
}

/* polygon{{x1,y1}, {x2,y2}, ...}: simple polygon, either orientation;
** plane, so 2-D only (3-D: extrude) */
static int polygon(lua_State *L) {
  int n, d;
  lshape *sh;
  if (DIM != 2)
    luaL_error(L, "polygon: a polygon is plane and the scene is %d-D: "
                  "sweep it into a prism with mvmpm.extrude{polygon = {...}, "
                  "axis = \"z\", lo = , hi = }", DIM);
  luaL_checktype(L, 1, LUA_TTABLE);
  n = (int)luaL_len(L, 1);
  if (n < 3) luaL_error(L, "polygon: needs at least 3 vertices (got %d)", n);
  sh = newshape(L, SH_POLYGON, n);
  for (d = 0; d < DIM; d++) { sh->lo[d] = HUGE_VAL; sh->hi[d] = -HUGE_VAL; }
  sh->p0 = 0;
  sh->p1 = 1;
  readpoly(L, 1, "polygon", sh, 0, 1);
  return 1;
}

/* extrude{polygon = {{a, b}, ...}, axis = "z", lo = z0, hi = z1}: the
** prism swept by a polygon from lo to hi along axis; the polygon lies in
** the other two axes in their order (axis x: (y, z), y: (x, z), z: (x,
** y)).  3-D only (in 2-D the polygon itself is the shape) */
static int extrude(lua_State *L) {
  static const char *const keys[] = {"polygon", "axis", "lo", "hi", NULL};
  static const char *const axes[] = {"x", "y", "z", NULL};
  int n, d, ax, p0, p1;
  double lo, hi;
  lshape *sh;
  if (DIM != 3)
    luaL_error(L, "extrude: the scene is %d-D, where the polygon itself is "
                  "the shape: use mvmpm.polygon{...} (a 3-D scene gives "
                  "mvmpm.sim{dim = 3, ...} before its shapes)", DIM);
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "extrude", keys);
  ax = chk_option(L, 1, "extrude", "axis", 2, axes);
  lo = chk_num(L, 1, "extrude", "lo", 0, -HUGE_VAL, HUGE_VAL, CHK_REQUIRED);
  hi = chk_num(L, 1, "extrude", "hi", 0, -HUGE_VAL, HUGE_VAL, CHK_REQUIRED);
  if (!(hi > lo))
    chk_error(L, "extrude: field 'hi' must exceed 'lo' (lo %g, hi %g)", lo, hi);
  lua_getfield(L, 1, "polygon");
  if (!lua_istable(L, -1))
    luaL_error(L, "extrude: field 'polygon' must be a list of vertices {a, b}");
  n = (int)luaL_len(L, -1);
  if (n < 3)
    luaL_error(L, "extrude: field 'polygon' needs at least 3 vertices (got %d)", n);
  p0 = ax == 0 ? 1 : 0;
  p1 = ax == 2 ? 1 : 2;
  sh = newshape(L, SH_EXTRUDE, n);
  for (d = 0; d < DIM; d++) { sh->lo[d] = HUGE_VAL; sh->hi[d] = -HUGE_VAL; }
  sh->axis = ax;
  sh->p0 = p0;
  sh->p1 = p1;
  sh->lo[ax] = lo;
  sh->hi[ax] = hi;
  readpoly(L, -2, "extrude", sh, p0, p1);
  return 1;
}

/* cylinder{from = {..}, to = {..}, radius = r}: the points within r of
** the segment from -> to, between the planes through its ends normal to
** it (flat ends).  In 2-D the strip of width 2r along the segment */
static int cylinder(lua_State *L) {
  static const char *const keys[] = {"from", "to", "radius", NULL};
  double a[DIM], b[DIM], r, len;
  lshape *sh;
  int d;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, "cylinder", keys);
  chk_vec(L, 1, "cylinder", "from", a, DIM, 1);
  chk_vec(L, 1, "cylinder", "to", b, DIM, 1);
  r = chk_num(L, 1, "cylinder", "radius", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  sh = newshape(L, SH_CYLINDER, 0);
  for (d = 0; d < DIM; d++) sh->ax[d] = b[d] - a[d];
  len = vec_unit(sh->ax);
  if (!(len > 0) || !isfinite(len))
    luaL_error(L, "cylinder: fields 'from' and 'to' must be distinct points");
  for (d = 0; d < DIM; d++) {
    /* the ends' discs reach sqrt(1 - ax_d^2) r beyond them along d */
    double e = r * sqrt(fmax(0, 1 - sh->ax[d] * sh->ax[d]));
    sh->c[d] = a[d];
    sh->lo[d] = fmin(a[d], b[d]) - e;
    sh->hi[d] = fmax(a[d], b[d]) + e;
  }
  sh->r = r;
  sh->len = len;
  return 1;
}

/* region{inside = function(x, y[, z]) ... end, lo = {..}, hi = {..}} */
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
    luaL_error(L, "region: field 'inside' must be a function(%s)",
               DIM == 2 ? "x, y" : "x, y, z");
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
  /* (x, y): the point in the polygon's two axes */
  int k, j, in = 0;
  for (k = 0, j = sh->npts - 1; k < sh->npts; j = k++) {
    double xk = sh->pts[2 * k], yk = sh->pts[2 * k + 1];
    double xj = sh->pts[2 * j], yj = sh->pts[2 * j + 1];
    if ((yk > y) != (yj > y) && x < (xj - xk) * (y - yk) / (yj - yk) + xk)
      in = !in;
  }
  return in;
}

/* the measure of a ball of radius r: area in 2-D, volume in 3-D */
static double ballvol(double r) {
  return DIM == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
}

int lshape_inside(lua_State *L, int idx, const lshape *sh, const double *x) {
  double r2 = 0, t = 0;
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
  case SH_EXTRUDE:
    if (x[sh->axis] < sh->lo[sh->axis] || x[sh->axis] >= sh->hi[sh->axis])
      return 0;
    return inpoly(sh, x[sh->p0], x[sh->p1]);
  case SH_CYLINDER:
    /* t along the axis from the base, r2 the squared distance from it */
    for (d = 0; d < DIM; d++) t += (x[d] - sh->c[d]) * sh->ax[d];
    if (t < 0 || t >= sh->len) return 0;
    for (d = 0; d < DIM; d++) {
      double e = x[d] - sh->c[d] - t * sh->ax[d];
      r2 += e * e;
    }
    return r2 < sh->r * sh->r;
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

/* the polygon's area (shoelace) */
static double polyarea(const lshape *sh) {
  double a = 0;
  int k, j;
  for (k = 0, j = sh->npts - 1; k < sh->npts; j = k++)
    a += sh->pts[2 * j] * sh->pts[2 * k + 1] - sh->pts[2 * k] * sh->pts[2 * j + 1];
  return fabs(a) / 2;
}

double lshape_area(const lshape *sh) {
  double v = 1;
  int d;
  switch (sh->kind) {
  case SH_DISK: return ballvol(sh->r);
  case SH_ANNULUS:
    return DIM == 2 ? M_PI * (sh->r * sh->r - sh->r0 * sh->r0)
                    : ballvol(sh->r) - ballvol(sh->r0);
  case SH_RECT:
    for (d = 0; d < DIM; d++) v *= sh->hi[d] - sh->lo[d];
    return v;
  case SH_POLYGON: return polyarea(sh);
  case SH_EXTRUDE: return polyarea(sh) * (sh->hi[sh->axis] - sh->lo[sh->axis]);
  case SH_CYLINDER:
    /* the cross-section (a disc; in 2-D the strip's width) times length */
    return (DIM == 2 ? 2 * sh->r : M_PI * sh->r * sh->r) * sh->len;
  default: return -1;
  }
}

static int area(lua_State *L) {
  double a = lshape_area(lshape_check(L, 1));
  if (a < 0) lua_pushnil(L); else lua_pushnumber(L, a);
  return 1;
}

static int tostr(lua_State *L) {
  static const char *const names[] = {DIM == 2 ? "disk" : "ball",
      DIM == 2 ? "annulus" : "shell", DIM == 2 ? "rect" : "box", "polygon",
      "rest", "region", "cylinder", "extrude"};
  lshape *sh = lshape_check(L, 1);
  lua_pushfstring(L, "shape %s", names[sh->kind]);
  return 1;
}

void lshape_open(lua_State *L, int modidx) {
  /* each name once; the round and box shapes under both their names (the
  ** upvalue is the name their messages use) */
  static const struct { const char *name; lua_CFunction fn; } named[] = {
      {"disk", disk}, {"ball", disk}, {"annulus", annulus}, {"shell", annulus},
      {"rect", rect}, {"box", rect}};
  static const luaL_Reg fns[] = {{"polygon", polygon}, {"extrude", extrude},
                                 {"cylinder", cylinder}, {"region", region},
                                 {"rest", rest}, {NULL, NULL}};
  static const luaL_Reg meth[] = {{"area", area}, {"volume", area},
                                  {NULL, NULL}};
  size_t k;
  luaL_newmetatable(L, LSHAPE_MT);
  lua_pushcfunction(L, tostr);
  lua_setfield(L, -2, "__tostring");
  luaL_newlib(L, meth);
  lua_setfield(L, -2, "__index");
  lsim_lock(L, -1);
  lua_pop(L, 1);
  lua_pushvalue(L, modidx);
  luaL_setfuncs(L, fns, 0);
  for (k = 0; k < sizeof named / sizeof named[0]; k++) {
    lua_pushstring(L, named[k].name);
    lua_pushcclosure(L, named[k].fn, 1);
    lua_setfield(L, -2, named[k].name);
  }
  lua_pop(L, 1);
}
