/*
** lua_render.c - pictures from Lua: sim:render{...} draws the particles
** now, mvmpm.plot{...} draws line plots.  Both run between steps only
** (as every Lua call does) and write PNG files under a temporary name.
**
**   sim:render{file = "x.png" | "x.svg", by = "body" | "pressure" |
**              "sdiff" | "speed" | "FIELD[.COMP]", width = 800,
**              range = {lo, hi} | "robust" | "full", title = "...",
**              colormap = "auto" | "seq" | "div", log = false,
**              axes = true, matrix = "NAME",
**              3-D: axis = "z" | "x" | "y", at = POS, thick = T,
**              project = false}
**   In 3-D the picture looks along axis: a slice at `at` (default the
**   middle of the domain) or with project = true all the particles
**   (render_png.h); the window is the domain in the other two axes.
**   A relative file goes in the run's output directory when it has one
**   (mvmpm run, or the scene's output{dir = ...}), else in the current
**   directory.
**   mvmpm.plot{file = "x.png", title =, xlabel =, ylabel =, xlog =,
**              ylog =, width = 800, height = 560, xrange =, yrange =,
**              series = {{x = {...}, y = {...}, label = "...",
**                         style = "line" | "points" | "both"}, ...}}
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "cmap.h"
#include "lcheck.h"
#include "lsim.h"
#include "plot_png.h"
#include "png.h"
#include "render_png.h"
#include "sandbox.h"

static const char *const cmaps[] = {"auto", "seq", "div", NULL};
static const char *const styles[] = {"line", "points", "both", NULL};

/* luaL_error with the C library's formats: lua_pushfstring has no %g */
static int rerror(lua_State *L, const char *fmt, ...) {
  char buf[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return luaL_error(L, "%s", buf);
}

/* a whole number of pixels in [lo, hi]; def if absent */
static int pixels(lua_State *L, int idx, const char *what, const char *key,
                  int def, int lo, int hi) {
  double v = chk_num(L, idx, what, key, def, -HUGE_VAL, HUGE_VAL, 0);
  if (!(v >= lo && v <= hi) || v != floor(v))
    rerror(L, "%s: field '%s' must be a whole number in [%d, %d] (got %g)",
           what, key, lo, hi, v);
  return (int)v;
}

/* optional string field; def if absent */
static const char *optstr(lua_State *L, int idx, const char *what,
                          const char *key, const char *def) {
  const char *s;
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return def; }
  if (lua_type(L, -1) != LUA_TSTRING)
    luaL_error(L, "%s: field '%s' must be a string (got %s)", what, key,
               luaL_typename(L, -1));
  s = lua_tostring(L, -1);
  lua_pop(L, 1); /* the string stays alive in the argument table */
  return s;
}

static const char *reqstr(lua_State *L, int idx, const char *what,
                          const char *key) {
  const char *s = optstr(L, idx, what, key, NULL);
  if (!s || !s[0])
    luaL_error(L, "%s: field '%s' is required (a file name ending in .png%s)",
               what, key, strcmp(what, "render") == 0 ? " or .svg" : "");
  return s;
}

/* a {lo, hi} range field; 1 if given */
static int optrange(lua_State *L, int idx, const char *what, const char *key,
                    double *r) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return 0; }
  lua_pop(L, 1);
  chk_vec(L, idx, what, key, r, 2, 1);
  if (!(r[1] > r[0]))
    rerror(L, "%s: field '%s' = {%g, %g} must have hi > lo", what, key,
              r[0], r[1]);
  return 1;
}

/*
** Where sim:render writes: under --sandbox inside its root
** (sandbox_path); else a relative name goes in the run's output
** directory, made if need be, when the run writes output.
*/
static const char *render_path(lua_State *L, lsim *ls, const char *file,
                               char *buf, size_t len) {
  const char *what = "render";
  char err[1200];
  if (sandbox_on(L)) return sandbox_path(L, file, what, buf, len);
  if (file[0] == '/' || !ls->out_enabled || !ls->outdir[0]) return file;
  if ((size_t)snprintf(buf, len, "%s/%s", ls->outdir, file) >= len)
    luaL_error(L, "%s: path '%s/%s' is too long", what, ls->outdir, file);
  if (run_mkdirs(ls->outdir, err, sizeof err))
    luaL_error(L, "%s: %s", what, err);
  return buf;
}

/* sim:render{...} */
int lrender_sim(lua_State *L) {
  static const char *const keys[] = {"file", "by", "width", "range", "title",
      "colormap", "log", "axes", "matrix", "axis", "at", "thick", "project",
      NULL};
  static const char *const axisnames[] = {"z", "x", "y", NULL};
  static const char *const autos[] = {"robust", "full", NULL};
  const char *what = "render", *file, *title;
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  render_opts o;
  char err[2048], deftitle[160], path[1100];
  const char **names;
  int b, d, *driven, h, u, a;
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 2);
  lsim_hold(L, ls); /* the options table may have metamethods */
  chk_keys(L, 2, what, keys);
  memset(&o, 0, sizeof o);
  file = render_path(L, ls, reqstr(L, 2, what, "file"), path, sizeof path);
  o.by = optstr(L, 2, what, "by", "body");
  o.width = pixels(L, 2, what, "width", 800, RENDER_MINW, PNG_MAXDIM);
  lua_getfield(L, 2, "range");
  if (lua_type(L, -1) == LUA_TSTRING) {
    lua_pop(L, 1);
    o.autorange = chk_option(L, 2, what, "range", RENDER_ROBUST, autos);
  } else {
    lua_pop(L, 1);
    o.has_range = optrange(L, 2, what, "range", o.range);
  }
  o.cmap = chk_option(L, 2, what, "colormap", 0, cmaps) - 1; /* auto = -1 */
  o.log = chk_bool(L, 2, what, "log", 0);
  o.noaxes = !chk_bool(L, 2, what, "axes", 1);
  o.matrix = optstr(L, 2, what, "matrix", NULL);
  o.unit = render_length_unit(ls->units);
  o.axis = axisnames[chk_option(L, 2, what, "axis", 0, axisnames)];
  if (render_view_axes(o.axis, &h, &u, &a, err, sizeof err))
    luaL_error(L, "%s: field 'axis': %s", what, err);
  o.project = chk_bool(L, 2, what, "project", 0);
  o.thick = chk_num(L, 2, what, "thick", 0, 0, HUGE_VAL, 0);
  lua_getfield(L, 2, "at");
  o.has_at = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (o.has_at) o.at = chk_num(L, 2, what, "at", 0, -HUGE_VAL, HUGE_VAL, 0);
  else if (a >= 0) { /* a 3-D slice through the middle of the domain */
    o.at = s->g.lo[a] / 2 + s->g.hi[a] / 2;
    o.has_at = 1;
  }
  if (render_values(&s->ps, o.by, 0, NULL, err, sizeof err) < 0)
    luaL_error(L, "%s: field 'by': %s", what, err);
  snprintf(deftitle, sizeof deftitle, "%s   t = %.6g", o.by, s->t);
  title = optstr(L, 2, what, "title", deftitle);
  o.title = title;
  for (d = 0; d < 2; d++) {  /* the window: h across, u up */
    o.lo[d] = s->g.lo[d ? u : h];
    o.hi[d] = s->g.hi[d ? u : h];
  }
  /* names live in the bodies; the array in a userdata Lua will collect */
  names = lua_newuserdatauv(L, (s->nbody ? s->nbody : 1) * sizeof *names, 0);
  driven = lua_newuserdatauv(L, (s->nbody ? s->nbody : 1) * sizeof *driven, 0);
  for (b = 0; b < s->nbody; b++) {
    names[b] = s->bodies[b].name;
    driven[b] = s->bodies[b].driven != 0;
  }
  o.names = names;
  o.driven = driven;
  o.nnames = s->nbody;
  if (o.matrix) {
    for (b = 0; b < s->nbody && strcmp(names[b], o.matrix) != 0; b++) {}
    if (b == s->nbody)
      luaL_error(L, "%s: field 'matrix': no body named '%s'", what, o.matrix);
  }
  if (render_file(file, &s->ps, &o, err, sizeof err))
    luaL_error(L, "%s: %s", what, err);
  lua_pushstring(L, file); /* where it went (the prompt shows it) */
  return 1;
}

/* a list of numbers into a userdata array (NaN and infinities allowed:
** the plot skips them); leaves the userdata on the stack */
static double *numbers(lua_State *L, int idx, const char *what,
                       const char *key, size_t *n) {
  lua_Integer k, len;
  double *v;
  int isnum;
  lua_getfield(L, idx, key);
  if (!lua_istable(L, -1))
    luaL_error(L, "%s: field '%s' must be a list of numbers (got %s)", what,
               key, luaL_typename(L, -1));
  len = luaL_len(L, -1);
  v = lua_newuserdatauv(L, (size_t)(len > 0 ? len : 1) * sizeof *v, 0);
  for (k = 1; k <= len; k++) {
    lua_geti(L, -2, k);
    v[k - 1] = lua_tonumberx(L, -1, &isnum);
    if (!isnum)
      luaL_error(L, "%s: field '%s' entry %d must be a number (got %s)", what,
                 key, (int)k, luaL_typename(L, -1));
    lua_pop(L, 1);
  }
  lua_remove(L, -2);
  *n = (size_t)len;
  return v;
}

/* mvmpm.plot{...} */
static int lplot(lua_State *L) {
  static const char *const keys[] = {"file", "title", "xlabel", "ylabel",
      "xlog", "ylog", "width", "height", "xrange", "yrange", "series", NULL};
  static const char *const skeys[] = {"x", "y", "label", "style", NULL};
  const char *what = "plot", *file;
  plot_opts o;
  plot_series *sv;
  char err[1024], sw[48], path[1100];
  int ns, k, top;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  memset(&o, 0, sizeof o);
  file = sandbox_path(L, reqstr(L, 1, what, "file"), what, path, sizeof path);
  o.title = optstr(L, 1, what, "title", NULL);
  o.xlabel = optstr(L, 1, what, "xlabel", NULL);
  o.ylabel = optstr(L, 1, what, "ylabel", NULL);
  o.xlog = chk_bool(L, 1, what, "xlog", 0);
  o.ylog = chk_bool(L, 1, what, "ylog", 0);
  o.width = pixels(L, 1, what, "width", 800, PLOT_MINW, PNG_MAXDIM);
  o.height = pixels(L, 1, what, "height", 560, PLOT_MINH, PNG_MAXDIM);
  o.has_xrange = optrange(L, 1, what, "xrange", o.xrange);
  o.has_yrange = optrange(L, 1, what, "yrange", o.yrange);
  if (o.has_xrange && o.xlog && !(o.xrange[0] > 0))
    rerror(L, "plot: field 'xrange' must be > 0 on a log axis (got {%g, %g})",
              o.xrange[0], o.xrange[1]);
  if (o.has_yrange && o.ylog && !(o.yrange[0] > 0))
    rerror(L, "plot: field 'yrange' must be > 0 on a log axis (got {%g, %g})",
              o.yrange[0], o.yrange[1]);
  lua_getfield(L, 1, "series");
  if (!lua_istable(L, -1) || luaL_len(L, -1) < 1)
    luaL_error(L, "plot: field 'series' is required: a list of {x = {...}, "
                  "y = {...}, label = \"...\", style = \"line\"|\"points\"|\"both\"}");
  ns = (int)luaL_len(L, -1);
  if (ns > 64) luaL_error(L, "plot: field 'series' must have at most 64 entries (got %d)", ns);
  top = lua_gettop(L);
  sv = lua_newuserdatauv(L, ns * sizeof *sv, 0);
  for (k = 0; k < ns; k++) {
    size_t nx, ny;
    int si;
    snprintf(sw, sizeof sw, "plot.series[%d]", k + 1);
    lua_geti(L, top, k + 1);
    if (!lua_istable(L, -1))
      luaL_error(L, "%s must be a table {x = {...}, y = {...}}", sw);
    si = lua_gettop(L);
    chk_keys(L, si, sw, skeys);
    sv[k].y = numbers(L, si, sw, "y", &ny);
    lua_getfield(L, si, "x");
    if (lua_isnil(L, -1)) { /* x = 1, 2, ... */
      double *x = lua_newuserdatauv(L, (ny ? ny : 1) * sizeof *x, 0);
      size_t i;
      for (i = 0; i < ny; i++) x[i] = (double)(i + 1);
      sv[k].x = x;
      nx = ny;
      lua_remove(L, -2);
    } else {
      lua_pop(L, 1);
      sv[k].x = numbers(L, si, sw, "x", &nx);
    }
    if (nx != ny)
      luaL_error(L, "%s: fields 'x' and 'y' must have the same length (got %d and %d)",
                 sw, (int)nx, (int)ny);
    sv[k].n = nx;
    sv[k].label = optstr(L, si, sw, "label", NULL);
    sv[k].style = chk_option(L, si, sw, "style", PLOT_LINE, styles);
    /* the arrays stay on the stack (anchored) until the plot is drawn */
    lua_remove(L, si);
  }
  if (plot_png(file, sv, ns, &o, err, sizeof err))
    luaL_error(L, "plot: %s", err);
  return 0;
}

void lrender_open(lua_State *L, int modidx) {
  lua_pushcfunction(L, lplot);
  lua_setfield(L, modidx, "plot");
}
