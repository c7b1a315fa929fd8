/*
** lua_sim.c - the simulation object in Lua: mvmpm.sim{...} and its
** methods.  The table is checked field by field; errors name the scene
** line, the field and its allowed range.
*/
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "diag_bond.h"
#include "diag_contact.h"
#include "diag_overlap.h"
#include "diag_wall.h"
#include "lcheck.h"
#include "lsim.h"
#include "lstate.h"
#include "react.h"
#include "sandbox.h"
#include "shape.h"

lsim *lsim_check(lua_State *L, int idx) {
  lsim *ls = luaL_checkudata(L, idx, LSIM_MT);
  if (ls->closed)
    luaL_error(L, "the simulation was closed (its __gc ran and its memory "
                  "is released): it cannot be used any more");
  if (!ls->ok) luaL_error(L, "simulation is not set up");
  return ls;
}

/*
** A method that calls Lua (callbacks, drives, a body's velocity function)
** keeps pointers into the simulation across the call.  Lua never collects
** the simulation meanwhile (the method's stack holds it), but a script
** with the real metatable (debug) can call __gc by hand; busy makes that
** an error instead of freeing memory under the method.  The count goes
** back in a to-be-closed slot, so an error unwinding the method ends the
** hold as well as a return does.
*/
static int unhold(lua_State *L) {
  lsim **p = luaL_checkudata(L, 1, "mvmpm.hold" LSIM_TAG);
  if (*p) {
    (*p)->busy--;
    *p = NULL;
  }
  return 0;
}

void lsim_lock(lua_State *L, int mtidx) {
  mtidx = lua_absindex(L, mtidx);
  lua_pushliteral(L, "mvmpm: this metatable is not accessible");
  lua_setfield(L, mtidx, "__metatable");
}

void lsim_hold(lua_State *L, lsim *ls) {
  lsim **p = lua_newuserdatauv(L, sizeof *p, 0);
  *p = NULL;
  if (luaL_newmetatable(L, "mvmpm.hold" LSIM_TAG)) {
    lua_pushcfunction(L, unhold);
    lua_setfield(L, -2, "__close");
    lsim_lock(L, -1);
  }
  lua_setmetatable(L, -2);
  *p = ls;
  ls->busy++;
  lua_toclose(L, -1);
}

void lsim_uv(lua_State *L, int idx, const char *field) {
  lua_getiuservalue(L, idx, 1);
  lua_getfield(L, -1, field);
  lua_remove(L, -2);
}

const char *const lsim_side_names[] = {"left", "right", "bottom", "top",
                                       "back", "front", NULL};

void lsim_check_speed(lua_State *L, lsim *ls, const double *v, int fnidx,
                      const char *fmt, ...) {
  const sim *s = &ls->s;
  double speed = 0, span = s->t_end > s->t ? s->t_end - s->t : 0, steps;
  char what[256], msg[512];
  va_list ap;
  int d;
  for (d = 0; d < DIM; d++) speed = hypot(speed, v[d]);
  steps = span * speed / (s->cfg.cfl * s->g.h);
  /* 1e150: squared, a speed stays finite */
  if (speed <= 1e150 && steps <= LSIM_MAX_SPAN) return;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  snprintf(msg, sizeof msg, "%s: a speed of %g is more than the step can "
           "follow: its CFL step cfl * cell / speed = %g would need %.3g "
           "steps to t_end = %g (at most %.0e)", what, speed,
           s->cfg.cfl * s->g.h / speed, steps, s->t_end, LSIM_MAX_SPAN);
  if (fnidx) chk_fnerror(L, fnidx, "%s", msg);
  luaL_error(L, "%s", msg);
}

void lsim_check_every(lua_State *L, const char *what, double every,
                      double span) {
  if (every > 0 && span / every > LSIM_MAX_EVENTS)
    chk_error(L, "%s = %g would make %.3g events in %g of simulated time "
                 "(at most %.0e): give at least %g", what, every, span / every,
              span, LSIM_MAX_EVENTS, span / LSIM_MAX_EVENTS);
}
static const char *const side_kinds[] = {"free", "wall", "periodic",
                                         "symmetry", NULL};
#define SIDE_SYMMETRY 3 /* a wall with mirror set (sim.h) */

/* one side: "wall" | "free" | "periodic" | "symmetry" |
** {"wall", friction=, velocity=} */
static void side_spec(lua_State *L, lsim *ls, int simidx, int k, int idx,
                      int *periodic) {
  static const char *const keys[] = {"friction", "velocity", NULL};
  side *sd = &ls->s.sides[k];
  char what[48];
  int kind;
  snprintf(what, sizeof what, "sides.%s", lsim_side_names[k]);
  sd->mu = 0;
  if (lua_type(L, idx) == LUA_TSTRING) {
    lua_newtable(L);
    lua_pushvalue(L, idx);
    lua_rawseti(L, -2, 1);
    lua_replace(L, idx);
  }
  if (!lua_istable(L, idx))
    luaL_error(L, "%s must be \"wall\", \"free\", \"periodic\", \"symmetry\" or a table "
                  "{\"wall\", friction = mu, velocity = {%s}}", what,
               DIM == 2 ? "vx, vy" : "vx, vy, vz");
  chk_keys(L, idx, what, keys);
  if (lua_rawgeti(L, idx, 1) == LUA_TNIL) kind = SIDE_WALL;
  else {
    char kw[80];
    if (lua_type(L, -1) != LUA_TSTRING)
      luaL_error(L, "%s: the side's kind (its first entry) must be a string "
                    "(got %s)", what, luaL_typename(L, -1));
    snprintf(kw, sizeof kw, "%s: the side's kind", what);
    kind = chk_oneof(L, lua_tostring(L, -1), kw, side_kinds);
  }
  lua_pop(L, 1);
  sd->mirror = kind == SIDE_SYMMETRY;
  sd->kind = sd->mirror ? SIDE_WALL : kind;
  periodic[k] = kind == SIDE_PERIODIC;
  if (kind != SIDE_WALL) {
    lua_getfield(L, idx, "friction");
    if (!lua_isnil(L, -1))
      luaL_error(L, "%s: only a wall has friction (this side is %s)", what,
                 side_kinds[kind]);
    lua_pop(L, 1);
  }
  lua_getfield(L, idx, "friction");
  if (lua_type(L, -1) == LUA_TSTRING && strcmp(lua_tostring(L, -1), "stick") == 0)
    sd->mu = INFINITY;
  else
    sd->mu = chk_num(L, idx, what, "friction", 0, 0, HUGE_VAL, 0);
  lua_pop(L, 1);
  lua_getfield(L, idx, "velocity");
  if (lua_isfunction(L, -1)) {
    if (kind != SIDE_WALL) luaL_error(L, "%s: only a wall can move", what);
    lsim_uv(L, simidx, "sidefn");
    lua_pushvalue(L, -2);
    lua_rawseti(L, -2, k);
    lua_pop(L, 1);
    ls->sidefns++;
  } else if (!lua_isnil(L, -1)) {
    if (kind != SIDE_WALL) luaL_error(L, "%s: only a wall can move", what);
    chk_vec(L, idx, what, "velocity", sd->v, DIM, 1);
    if (sd->v[k / 2] != 0)
      chk_error(L, "%s: the wall slides along its own %s: velocity's %c "
                   "component must be 0 (got %g)", what,
                DIM == 2 ? "line" : "plane", "xyz"[k / 2],
                sd->v[k / 2]);
  }
  lua_pop(L, 1);
}

/* The cohesive law acts at nodes both sides share, and they stop sharing
** a node once the opening passes about half a cell (linear hats: each
** side's particle beside the interface, a quarter cell from it, leaves
** the node's cell): on scenarios/bond_pull.lua with an opening at failure
** of 0.01 the work of separation was 1.005 of G_c at 48 cells (half a
** cell 0.0104) and 0.979 at 64 (0.0078).  Every strength (a body's bond,
** a law's cap) passes here, after bond_energy and the cell are fixed. */
void lsim_check_cohesion(lua_State *L, const sim *s, double strength,
                         const char *what, const char *field) {
  double gc = s->cfg.bond_gc, dc;
  if (!(gc > 0) || !(strength > 0) || !isfinite(strength)) return;
  dc = 2 * gc / strength;
  if (dc > 0.5 * s->g.h)
    chk_error(L, "%s: field '%s' = %g with sim.bond_energy = %g opens the "
                 "interface by 2 G/strength = %g before it gives out, more "
                 "than half a cell (%g), where the sides stop sharing nodes; "
                 "allowed: %s >= %g at this cell and energy", what, field,
              strength, gc, dc, 0.5 * s->g.h, field, 4 * gc / s->g.h);
}

/* bond = true | false | strength cap (>= 0) */
static double bondcap(lua_State *L, const sim *s, int idx, const char *what,
                      double def) {
  double b;
  lua_getfield(L, idx, "bond");
  if (lua_isboolean(L, -1)) b = lua_toboolean(L, -1) ? INFINITY : 0;
  else b = chk_num(L, idx, what, "bond", def, 0, HUGE_VAL, 0);
  lua_pop(L, 1);
  lsim_check_cohesion(L, s, b, what, "bond");
  return b;
}

/* friction = mu | "stick"; def when absent */
static double friction(lua_State *L, int idx, const char *what, double def) {
  double mu;
  lua_getfield(L, idx, "friction");
  if (lua_type(L, -1) == LUA_TSTRING && strcmp(lua_tostring(L, -1), "stick") == 0)
    mu = INFINITY;
  else mu = chk_num(L, idx, what, "friction", def, 0, HUGE_VAL, 0);
  lua_pop(L, 1);
  return mu;
}

static void newuv(lua_State *L) {
  static const char *const t[] = {"mats", "bodies", "every", "drives",
                                  "sidefn", "fieldnames", "at_end", NULL};
  int k;
  lua_createtable(L, 0, 8);
  for (k = 0; t[k]; k++) {
    lua_newtable(L);
    lua_setfield(L, -2, t[k]);
  }
  lua_setiuservalue(L, -2, 1);
}

int lsim_push_rot(lua_State *L, const double *q, int as_table) {
  int k;
  if (DIM == 2) {
    lua_pushnumber(L, q[2]);
    return 1;
  }
  if (as_table) lua_createtable(L, 3, 0);
  for (k = 0; k < 3; k++) {
    lua_pushnumber(L, q[k]);
    if (as_table) lua_rawseti(L, -2, k + 1);
  }
  return as_table ? 1 : 3;
}

/* sim{dim = N}: the dimension the scene is written for, 2 unless it
** says.  Returns 0 when it is this one; otherwise the other dimension's
** constructor has run and left its result: returns 1.  Under a command
** that must start again in the other dimension (the registry's
** "mvmpm.redo", set by mvmpm run and a scene given to the REPL: their C
** side holds this dimension's simulation), the dimension is noted in
** "mvmpm.redo_dim" and the scene stops with an error saying so. */
int lsim_dim_check(lua_State *L, int idx) {
  int dim = (int)chk_num(L, idx, "sim", "dim", 2, 2, 3, CHK_INT);
  int redo;
  if (dim == DIM) return 0;
  if (!lmvmpm_enter_other)
    luaL_error(L, "sim: field 'dim' is %d, but this build simulates %d-D only",
               dim, DIM);
  redo = lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.redo") == LUA_TBOOLEAN;
  lua_pop(L, 1);
  if (redo) {
    lua_pushinteger(L, dim);
    lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.redo_dim");
    luaL_error(L, "sim: the scene is %d-D: starting again in %d-D", dim, dim);
  }
  lmvmpm_enter_other(L);
  return 1;
}

/* the default thread count: $MVMPM_THREADS if it is a count, else 1 */
int lsim_env_threads(void) {
  const char *e = getenv("MVMPM_THREADS");
  char *end;
  long n = e ? strtol(e, &end, 10) : 1;
  if (!e || end == e || *end || n < 1) return 1;
  return n > PAR_MAX ? PAR_MAX : (int)n;
}

/* the contact options' names, in their enums' order (sim.h): what the
** constructor accepts and what sim.<option> reads back */
static const char *const remapopt[] = {"auto", "hold", "free", NULL};
static const char *const gapopt[] = {"touch", "step", NULL};
static const char *const wallopt[] = {"node", "patch", "couple", "penalty", "spring", "auto",
                                      NULL};
/* in enum body_rule's order */
static const char *const bodyopt[] = {"node", "patch", "auto", NULL};
static const char *const releaseopt[] = {"open", "contact", NULL};
static const char *const tractionopt[] = {"mixture", "fit", NULL};
/* in enum normals_kind's order */
static const char *const normalsopt[] = {"mass", "volume", "maxvolume", "plane", "auto", NULL};

int lsim_new(lua_State *L) {
  static const char *const keys[] = {"domain", "cell", "ppc", "shape",
      "update", "transfer", "flip", "cfl", "dt", "t_end", "gravity", "sides",
      "contact", "fields", "units", "sort_every", "mass_cutoff", "threads",
      "wall_remap", "wall_contact", "wall_stiffness", "wall_band", "body_contact", "normals", "normal_window", "normal_patch", "contact_gap",
      "xpic", "bond_release", "bond_traction", "bond_length", "bond_energy", "dim",
      NULL};
  static const char *const fieldsopt[] = {"body", "single", NULL};
  const char *what = "sim";
  double lo[DIM], hi[DIM], h, nodes, bytes;
  int periodic[NSIDES] = {0}, pdim[DIM], shape, ppc, k, d, sidx;
  lsim *ls;
  sim *s;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  if (lsim_dim_check(L, 1)) return 1;
  /* domain = {x = {0, 3}, y = {0, 3}} */
  lua_getfield(L, 1, "domain");
  if (!lua_istable(L, -1))
    luaL_error(L, "sim: field 'domain' is required: {x = {xmin, xmax}, "
                  "y = {ymin, ymax}%s}", DIM == 3 ? ", z = {zmin, zmax}" : "");
  {
    static const char *const dk[] = {"x", "y", "z", NULL};
    static const char *const dk2[] = {"x", "y", NULL};
    chk_keys(L, -1, "sim.domain", DIM == 2 ? dk2 : dk);
    for (d = 0; d < DIM; d++) {
      double r[2];
      chk_vec(L, -1, "sim.domain", dk[d], r, 2, 1);
      if (!(r[1] > r[0]))
        chk_error(L, "sim.domain: %s = {%g, %g} must have max > min", dk[d], r[0], r[1]);
      lo[d] = r[0];
      hi[d] = r[1];
    }
  }
  lua_pop(L, 1);
  h = chk_num(L, 1, what, "cell", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  if (h < DBL_MIN) /* a denormal: 1 / h, the grid's scale, overflows */
    chk_error(L, "sim: field 'cell' must be >= %g (got %g)", DBL_MIN, h);
  nodes = 1;
  for (d = 0; d < DIM; d++) {
    double c = (hi[d] - lo[d]) / h;
    if (fabs(c - floor(c + 0.5)) > 1e-6 * c)
      chk_error(L, "sim: the domain's extent along %c (%g) must be a whole "
                    "number of cells of size %g (got %g cells)", "xyz"[d],
                 hi[d] - lo[d], h, c);
    nodes *= c + 3;
  }
  ppc = (int)chk_num(L, 1, what, "ppc", 2, 1, 8, CHK_INT);
  /* quadratic B-splines by default: linear hats' gradient jumps where a
  ** particle crosses a cell face, and under FLIP that noise stays, so
  ** their error grows as the grid is refined (the free bar crossing
  ** cells, the bounce: docs/accuracy.md); B-splines' errors fall there,
  ** at about 1.5 times the cost per particle-step in 2-D */
  shape = chk_option(L, 1, what, "shape", SHAPE_BSPLINE2, shape_names);
  bytes = grid_bytes(lo, hi, h, shape_pad(shape)) +
          nodes * pow(ppc, DIM) * (8.0 * (2 * DIM + 2 + 2 * NTENS + NSTRESS + 2) + 16);
  /* refuse before allocating; MVMPM_MAX_GB lowers (or raises) the
  ** 16 GB ceiling, e.g. for fuzzing under a memory limit */
  {
    const char *env = getenv("MVMPM_MAX_GB");
    double limit = env && atof(env) > 0 ? atof(env) * 1e9 : 16e9;
    if (bytes > limit)
      chk_error(L, "sim: %.3g cells would need about %.3g GB (limit %.3g GB); "
                   "use a coarser 'cell' or a smaller domain", nodes,
                bytes / 1e9, limit / 1e9);
  }
  /* sides */
  lua_getfield(L, 1, "sides");
  sidx = lua_gettop(L);
  ls = lua_newuserdatauv(L, sizeof *ls, 1);
  memset(ls, 0, sizeof *ls);
  ls->ended = NAN; /* sim:at_end has run at no end yet */
  luaL_setmetatable(L, LSIM_MT);
  newuv(L);
  {
    int simidx = lua_gettop(L);
    for (k = 0; k < NSIDES; k++) ls->s.sides[k].kind = SIDE_WALL;
    int all = lua_type(L, sidx) == LUA_TSTRING || lua_isnil(L, sidx);
    if (lua_istable(L, sidx)) { /* {"wall", friction = mu}: every side */
      all = lua_rawgeti(L, sidx, 1) == LUA_TSTRING;
      lua_pop(L, 1);
    }
    if (all) {
      for (k = 0; k < NSIDES; k++) {
        if (lua_isnil(L, sidx)) lua_pushstring(L, "wall");
        else lua_pushvalue(L, sidx);
        side_spec(L, ls, simidx, k, lua_gettop(L), periodic);
        lua_pop(L, 1);
      }
    } else if (lua_istable(L, sidx)) {
      const char *sk[NSIDES + 1]; /* the sides this dimension has */
      for (k = 0; k < NSIDES; k++) sk[k] = lsim_side_names[k];
      sk[NSIDES] = NULL;
      chk_keys(L, sidx, "sides", sk);
      for (k = 0; k < NSIDES; k++) {
        lua_getfield(L, sidx, lsim_side_names[k]);
        if (lua_isnil(L, -1)) { lua_pop(L, 1); lua_pushstring(L, "wall"); }
        side_spec(L, ls, simidx, k, lua_gettop(L), periodic);
        lua_pop(L, 1);
      }
    } else
      luaL_error(L, "sim: field 'sides' must be a string or a table of sides");
    for (d = 0; d < DIM; d++) {
      if (periodic[2 * d] != periodic[2 * d + 1])
        luaL_error(L, "sim: sides.%s and sides.%s must both be periodic or neither",
                   lsim_side_names[2 * d], lsim_side_names[2 * d + 1]);
      pdim[d] = periodic[2 * d];
    }
    {
      side keep[NSIDES];
      memcpy(keep, ls->s.sides, sizeof keep);
      if (sim_init(&ls->s, lo, hi, h, pdim, shape, ppc))
        luaL_error(L, "sim: %s", ls->s.err);
      for (k = 0; k < NSIDES; k++) {
        double *ext = ls->s.sides[k].ext, *ext2 = ls->s.sides[k].ext2;
        int32_t *efld = ls->s.sides[k].efld;
        unsigned char *acted = ls->s.sides[k].acted;
        double *hm = ls->s.sides[k].hm, *dl = ls->s.sides[k].dl;
        double *ph = ls->s.sides[k].ph;
        unsigned char *son = ls->s.sides[k].son;
        size_t next = ls->s.sides[k].next;
        ls->s.sides[k] = keep[k];
        ls->s.sides[k].ext = ext;
        ls->s.sides[k].ext2 = ext2;
        ls->s.sides[k].efld = efld;
        ls->s.sides[k].acted = acted;
        ls->s.sides[k].hm = hm;
        ls->s.sides[k].dl = dl;
        ls->s.sides[k].ph = ph;
        ls->s.sides[k].son = son;
        ls->s.sides[k].next = next;
      }
    }
    ls->ok = 1;
    s = &ls->s;
    s->cfg.update = chk_option(L, 1, what, "update", UPDATE_MUSL, update_names);
    s->cfg.transfer = chk_option(L, 1, what, "transfer", TRANSFER_FLIP, transfer_names);
    {
      double m = chk_num(L, 1, what, "xpic", 2, 2, 3, 0);
      if (m != 2 && m != 3)
        luaL_error(L, "sim: field 'xpic' (the XPIC order) must be 2 or 3 (got %g)", m);
      s->cfg.xpic = (int)m;
    }
    if (s->cfg.transfer == TRANSFER_APIC) {
      /* measured: a spinning disc on linear hats with C = grad v has
      ** det F < 0 within 450 steps, in USL and MUSL alike */
      if (shape == SHAPE_LINEAR)
        luaL_error(L, "sim: transfer = \"apic\" needs shape = \"gimp\" or "
                      "\"bspline2\" (on linear hats the affine transfer is "
                      "unstable)");
      if (sim_enable_apic(s))
        luaL_error(L, "sim: out of memory for the affine transfer");
    }
    if (s->cfg.transfer == TRANSFER_SPIN) {
      /* the spin's increment is taken as APIC takes its matrix on
      ** B-splines, from the weights (g2p.c) */
      if (shape != SHAPE_BSPLINE2)
        luaL_error(L, "sim: transfer = \"spin\" needs shape = \"bspline2\" (the "
                      "spin's increment is taken from the quadratic B-splines' "
                      "weights)");
      if (sim_enable_apic(s))
        luaL_error(L, "sim: out of memory for the particles' spin");
    }
    s->cfg.flip = chk_num(L, 1, what, "flip", 1.0, 0, 1, 0);
    s->cfg.cfl = chk_num(L, 1, what, "cfl", 0.25, 0, 1, CHK_OPENLO);
    s->cfg.dt_fixed = chk_num(L, 1, what, "dt", 0, 0, HUGE_VAL, 0);
    s->t_end = chk_num(L, 1, what, "t_end", 1.0, 0, HUGE_VAL, 0);
    chk_vec(L, 1, what, "gravity", s->cfg.gravity, DIM, 0);
    /* now that the step's terms are known */
    for (k = 0; k < NSIDES; k++)
      lsim_check_speed(L, ls, s->sides[k].v, 0, "sim: sides.%s velocity",
                       lsim_side_names[k]);
    if (s->cfg.dt_fixed > 0 && s->t_end / s->cfg.dt_fixed > LSIM_MAX_SPAN)
      chk_error(L, "sim: field 'dt' = %g would take %.3g steps to t_end = %g "
                   "(at most %.0e); give 'dt' >= %g", s->cfg.dt_fixed,
                s->t_end / s->cfg.dt_fixed, s->t_end, LSIM_MAX_SPAN,
                s->t_end / LSIM_MAX_SPAN);
    s->cfg.sort_every = (int)chk_num(L, 1, what, "sort_every", 20, 0, 1e9, CHK_INT);
    s->cfg.mcut_rel = chk_num(L, 1, what, "mass_cutoff", 1e-9, 0, 1, 0);
    sim_set_threads(s, (int)chk_num(L, 1, what, "threads", lsim_env_threads(),
                                    1, PAR_MAX, CHK_INT));
    ls->fields_single = chk_option(L, 1, what, "fields", 0, fieldsopt);
    s->cfg.wall_remap = chk_option(L, 1, what, "wall_remap", WALL_REMAP_AUTO, remapopt);
    s->cfg.wall_rule = chk_option(L, 1, what, "wall_contact", WALL_AUTO, wallopt);
    s->cfg.wall_stiffness = chk_num(L, 1, what, "wall_stiffness",
                                    s->cfg.wall_rule == WALL_SPRING ? 1 : 2, 0.01, 16, 0);
    s->cfg.wall_band = (int)chk_num(L, 1, what, "wall_band", 2, 0, 4, CHK_INT);
    for (k = 0; k < NSIDES; k++)
      if (sim_spring_side(s, k) && s->sides[k].mu > 0)
        chk_error(L, "%s: wall_contact = \"%s\" takes frictionless walls; "
                     "side '%s' has friction %g (use \"patch\" for walls with "
                     "friction)", what, wallopt[s->cfg.wall_rule], lsim_side_names[k],
                  s->sides[k].mu);
    if (s->cfg.wall_rule == WALL_PENALTY && sim_lossy(&s->cfg))
      chk_error(L, "%s: wall_contact = \"penalty\" needs pure FLIP (transfer = "
                   "\"flip\", flip = 1): under a smoothing transfer its energy budget "
                   "does not close (a disc thrown at a wall, APIC: residual 5 to 18 %% "
                   "of E0)", what);
    if (s->cfg.wall_rule == WALL_SPRING && sim_lossy(&s->cfg))
      chk_error(L, "%s: wall_contact = \"spring\" needs pure FLIP (transfer = "
                   "\"flip\", flip = 1): a smoothing transfer's own loss is booked "
                   "on the particles' motion, the springs' work on the nodes', and "
                   "the budget does not close (a disc dropped on a floor, APIC: "
                   "residual 4 %% of E0 at 8 and 16 cells)", what);
    s->cfg.body_rule = chk_option(L, 1, what, "body_contact", BODY_AUTO, bodyopt);
    s->cfg.normals = chk_option(L, 1, what, "normals", NORMALS_AUTO, normalsopt);
    s->cfg.gap_step = chk_option(L, 1, what, "contact_gap", s->cfg.gap_step, gapopt);
    s->cfg.release = chk_option(L, 1, what, "bond_release", RELEASE_OPEN, releaseopt);
    s->cfg.bond_fit = chk_option(L, 1, what, "bond_traction", 0, tractionopt);
    s->cfg.bond_length = chk_num(L, 1, what, "bond_length", 0, 0, HUGE_VAL, 0);
    s->cfg.bond_gc = chk_num(L, 1, what, "bond_energy", 0, 0, HUGE_VAL, 0);
    /* GIMP's volume gradient at the shared node shrinks as the sides
    ** part (a particle three quarters of a cell from it sits where its
    ** weight's slope starts to fall): the work of separation came out
    ** 0.98 / 0.95 / 0.87 of G_c at 16 / 32 / 64 cells (docs/verification.md,
    ** the cohesive law) */
    if (s->cfg.bond_gc > 0 && s->cfg.shape == SHAPE_GIMP)
      chk_error(L, "%s: field 'bond_energy' needs shape = \"linear\" or "
                   "\"bspline2\" (under GIMP the cohesive law loses work of "
                   "separation as the grid is refined)", what);
    s->cfg.normal_window = (int)chk_num(L, 1, what, "normal_window", s->cfg.normal_window,
                                    0, NORMAL_WINDOW_MAX, CHK_INT);
    s->cfg.normal_patch = chk_bool(L, 1, what, "normal_patch", 0);
    lua_getfield(L, 1, "units");
    snprintf(ls->units, sizeof ls->units, "%s",
             lua_isnil(L, -1) ? "nondimensional" : luaL_checkstring(L, -1));
    lua_pop(L, 1);
    lua_getfield(L, 1, "contact");
    if (!lua_isnil(L, -1)) {
      static const char *const ck[] = {"friction", "separation", "bond", NULL};
      int ci = lua_gettop(L);
      if (!lua_istable(L, ci)) luaL_error(L, "sim: field 'contact' must be a table");
      chk_keys(L, ci, "sim.contact", ck);
      s->cfg.mu_default = friction(L, ci, "sim.contact", 0);
      s->cfg.gap_check = chk_bool(L, ci, "sim.contact", "separation", 1);
      s->cfg.bond_default = bondcap(L, s, ci, "sim.contact", INFINITY);
    }
    lua_pop(L, 1);
    lua_pushvalue(L, simidx);
  }
  /* remember the newest simulation, for scenes that do not return it */
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.last");
  return 1;
}

/* the finalizer; called by hand (debug.getmetatable) it closes the
** simulation too, and every later use is a Lua error (lsim_check).  A
** second call does nothing. */
static int lgc(lua_State *L) {
  lsim *ls = luaL_checkudata(L, 1, LSIM_MT);
  if (ls->busy)
    return luaL_error(L, "the simulation is running (a callback, drive or "
                         "velocity function is under way): it cannot be "
                         "closed now");
  ls->closed = 1;
  if (ls->ok) {
    char err[256];
    /* no raising in __gc; an interrupted run's table stays .part */
    if (ls->csv_open && ls->interrupted) out_csv_leave(&ls->csv);
    else if (ls->csv_open) out_csv_close(&ls->csv, err, sizeof err);
    ls->csv_open = 0;
    free(ls->occ);
    free(ls->claim);
    ls->claim = NULL;
    free(ls->snaps);
    hotspots_free(&ls->hs);
    ls->occ = NULL;
    ls->snaps = NULL;
    ls->nsnap = ls->snapcap = 0;
    sim_free(&ls->s);
    ls->ok = 0;
  }
  return 0;
}

/* sim:contact(a, b, {friction = mu, bond = true|false}) or
** sim:contact{friction = mu, separation = true|false, bond = true|false} */
static int lcontact(lua_State *L) {
  static const char *const ck[] = {"friction", "separation", "bond", NULL};
  static const char *const pk[] = {"friction", "bond", NULL};
  lsim *ls = lsim_check(L, 1);
  lsim_hold(L, ls); /* the option tables may have metamethods */
  if (lua_istable(L, 2)) {
    chk_keys(L, 2, "contact", ck);
    ls->s.cfg.mu_default = friction(L, 2, "contact", ls->s.cfg.mu_default);
    ls->s.cfg.gap_check = chk_bool(L, 2, "contact", "separation", ls->s.cfg.gap_check);
    ls->s.cfg.bond_default = bondcap(L, &ls->s, 2, "contact", ls->s.cfg.bond_default);
    return 0;
  } else {
    lbody *a = lbody_check(L, 2, ls, "contact");
    lbody *b = lbody_check(L, 3, ls, "contact");
    int32_t fa = ls->s.bodies[a->idx].field, fb = ls->s.bodies[b->idx].field;
    double mu;
    luaL_checktype(L, 4, LUA_TTABLE);
    chk_keys(L, 4, "contact", pk);
    if (fa == fb)
      luaL_error(L, "contact: bodies '%s' and '%s' share one velocity field, so "
                    "they are bonded; give them different fields",
                 ls->s.bodies[a->idx].name, ls->s.bodies[b->idx].name);
    mu = friction(L, 4, "contact", ls->s.cfg.mu_default);
    if (sim_set_law(&ls->s, fa, fb, mu,
                    bondcap(L, &ls->s, 4, "contact", ls->s.cfg.bond_default)))
      luaL_error(L, "contact: out of memory");
    return 0;
  }
}

/* sim:every{time = dt | steps = n, fn = function(sim) ... end} */
static int levery(lua_State *L) {
  static const char *const keys[] = {"time", "steps", "fn", NULL};
  lsim *ls = lsim_check(L, 1);
  double dt, n;
  luaL_checktype(L, 2, LUA_TTABLE);
  chk_keys(L, 2, "every", keys);
  dt = chk_num(L, 2, "every", "time", 0, 0, HUGE_VAL, 0);
  n = chk_num(L, 2, "every", "steps", 0, 0, 1e15, CHK_INT);
  if ((dt > 0) == (n > 0))
    luaL_error(L, "every: give exactly one of 'time' (> 0) and 'steps' (> 0)");
  lsim_check_every(L, "every: field 'time'", dt, ls->s.t_end - ls->s.t);
  lua_getfield(L, 2, "fn");
  if (!lua_isfunction(L, -1)) luaL_error(L, "every: field 'fn' must be a function(sim)");
  lua_pop(L, 1);
  lsim_uv(L, 1, "every");
  lua_createtable(L, 0, 4);
  lua_getfield(L, 2, "fn");
  lua_setfield(L, -2, "fn");
  if (dt > 0) {
    lua_pushnumber(L, dt); lua_setfield(L, -2, "time");
    lua_pushnumber(L, ls->s.t + dt); lua_setfield(L, -2, "next");
  } else {
    lua_pushinteger(L, (lua_Integer)n); lua_setfield(L, -2, "steps");
    lua_pushinteger(L, ls->s.step + (lua_Integer)n); lua_setfield(L, -2, "next");
  }
  lua_rawseti(L, -2, luaL_len(L, -2) + 1);
  ls->nevery++;
  return 0;
}

/* sim:at_end(fn): fn(sim) runs once when a run reaches the scene's end
** time (run.c), after the last step and its output: a summary, a
** figure, a table, with the final state */
static int lat_end(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lsim_uv(L, 1, "at_end");
  lua_pushvalue(L, 2);
  lua_rawseti(L, -2, luaL_len(L, -2) + 1);
  ls->nat_end++;
  return 0;
}

/* sim:output{dir = "out/x", every = 0.5, csv_every = 1, checkpoint = 2,
** warn_residual = 0.05, hotspots = {threshold = T, link = 1.5}} */
static int loutput(lua_State *L) {
  static const char *const keys[] = {"dir", "every", "csv_every",
                                     "checkpoint", "warn_residual",
                                     "hotspots", NULL};
  lsim *ls = lsim_check(L, 1);
  char buf[1100];
  luaL_checktype(L, 2, LUA_TTABLE);
  chk_keys(L, 2, "output", keys);
  /* verification scripts load scenes to measure them, not to write files */
  if (lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.testing") == LUA_TBOOLEAN) return 0;
  lua_pop(L, 1);
  lua_getfield(L, 2, "dir");
  /* sandboxed, the command line fixes the directory: a dir is only
  ** checked, so a scene cannot aim anywhere else */
  if (!lua_isnil(L, -1) && sandbox_on(L))
    sandbox_path(L, luaL_checkstring(L, -1), "output", buf, sizeof buf);
  else if (!lua_isnil(L, -1) && !ls->outdir[0])  /* --out on the command line wins */
    snprintf(ls->outdir, sizeof ls->outdir, "%s", luaL_checkstring(L, -1));
  lua_pop(L, 1);
  ls->ck_every = chk_num(L, 2, "output", "checkpoint", ls->ck_every, 0,
                         HUGE_VAL, 0);
  ls->out_every = chk_num(L, 2, "output", "every", ls->out_every, 0, HUGE_VAL, 0);
  lsim_check_every(L, "output: field 'checkpoint'", ls->ck_every,
                   ls->s.t_end - ls->s.t);
  lsim_check_every(L, "output: field 'every'", ls->out_every,
                   ls->s.t_end - ls->s.t);
  ls->csv_every = (long)chk_num(L, 2, "output", "csv_every",
                                ls->csv_every ? (double)ls->csv_every : 1, 0, 1e15,
                                CHK_INT);
  lua_getfield(L, 2, "warn_residual");
  if (!lua_isnil(L, -1)) {
    ls->warn_residual = chk_num(L, 2, "output", "warn_residual", 0, 0,
                                HUGE_VAL, 0);
    ls->warn_given = 1;
  }
  lua_pop(L, 1);
  if (lua_getfield(L, 2, "hotspots") != LUA_TNIL) {
    lsim_hotspot_opts(L, lua_gettop(L), "output.hotspots", &ls->hs_threshold,
                      &ls->hs_link);
    ls->hs_on = 1;
  }
  lua_pop(L, 1);
  ls->out_enabled = 1;
  return 0;
}

static int lstep(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  lua_Integer n = luaL_optinteger(L, 2, 1);
  if (n < 0) luaL_argerror(L, 2, "number of steps must be >= 0");
  lsim_hold(L, ls);
  run_until(L, 1, HUGE_VAL, (long)n);
  lua_pushnumber(L, ls->s.t);
  return 1;
}

static int lrun(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  double t = chk_arg(L, 2, "run", "t", ls->s.t_end, -HUGE_VAL, HUGE_VAL, 0);
  if (t < ls->s.t)
    chk_error(L, "run: t = %g lies before the simulation's time %g (a run "
                 "goes forward)", t, ls->s.t);
  lsim_hold(L, ls);
  run_until(L, 1, t, -1);
  lua_pushnumber(L, ls->s.t);
  return 1;
}


static void setnum(lua_State *L, const char *k, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, k);
}

/*
** sim:settle{tol = 1e-3, t_max = ...}: let a packing come to rest under
** its loads by kinetic damping (dynamic relaxation): step, and each time
** the kinetic energy passes a maximum stop every particle (sim_stop), so
** the energy the loads release goes into strain and out of the motion,
** with no damping parameter to tune and no damping force in the step.
** A maximum below tol times the largest kinetic energy seen is the
** transfer's noise, not motion, and stops nothing (stopping there would
** hold a body that is still falling).  Settled when over a window no
** body's centre of mass moved more than a twentieth of a cell: the window is the time
** a free particle takes to fall one cell under the gravity, or 100 steps
** without gravity, so a body still in free fall cannot pass.  Refused
** past t_max.  Returns true (false at t_max), the time taken and the
** kinetic energy left.  The energy taken out is booked
** (sim:energy().settled) and the budget still closes.
*/
/* each body's centre of mass into c (nbody x DIM): particles are sorted
** by cell within steps, so a particle's index does not follow it */
static void centres(const sim *s, double *c, double *m) {
  const particles *ps = &s->ps;
  size_t i;
  int b, d;
  for (b = 0; b < s->nbody; b++) {
    m[b] = 0;
    for (d = 0; d < DIM; d++) c[DIM * b + d] = 0;
  }
  for (i = 0; i < ps->n; i++) {
    b = ps->body[i];
    m[b] += ps->m[i];
    for (d = 0; d < DIM; d++) c[DIM * b + d] += ps->m[i] * ps->x[d][i];
  }
  for (b = 0; b < s->nbody; b++)
    for (d = 0; d < DIM; d++) c[DIM * b + d] /= m[b] > 0 ? m[b] : 1;
}

static int lsettle(lua_State *L) {
  static const char *const keys[] = {"tol", "t_max", NULL};
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  double tol, tmax, t0 = s->t, kprev, kmax = 0, g2 = 0, tw, twin;
  double *c0, *c1, *m;
  int rising = 0, done = 0, d, b, nb = s->nbody;
  if (lua_isnoneornil(L, 2)) lua_newtable(L);
  luaL_checktype(L, 2, LUA_TTABLE);
  chk_keys(L, 2, "settle", keys);
  tol = chk_num(L, 2, "settle", "tol", 1e-3, 0, 1, CHK_OPENLO);
  tmax = chk_num(L, 2, "settle", "t_max", s->t_end > s->t ? s->t_end - s->t : 1,
                 0, LSIM_MAX_SPAN, CHK_OPENLO);
  lsim_hold(L, ls);
  if (!s->started) sim_begin(s);
  for (d = 0; d < DIM; d++) g2 += s->cfg.gravity[d] * s->cfg.gravity[d];
  tw = g2 > 0 ? sqrt(2 * s->g.h / sqrt(g2)) : 100 * s->dt;
  c0 = lua_newuserdatauv(L, (size_t)(nb + 1) * (2 * DIM + 1) * sizeof *c0, 0);
  c1 = c0 + (size_t)(nb + 1) * DIM;
  m = c1 + (size_t)(nb + 1) * DIM;
  centres(s, c0, m);
  twin = s->t + tw;
  kprev = s->e.kinetic;
  while (s->t < t0 + tmax) {
    double k;
    run_until(L, 1, HUGE_VAL, 1);
    k = s->e.kinetic;
    if (k > kmax) kmax = k;
    if (k > kprev) rising = 1;
    else if (rising && k < kprev) { /* kprev was a maximum */
      rising = 0;
      if (kprev > tol * kmax) {
        sim_stop(s);
        k = s->e.kinetic;
      }
    }
    kprev = k;
    if (s->t >= twin) {
      double far = 0;
      centres(s, c1, m);
      for (b = 0; b < nb; b++)
        for (d = 0; d < DIM; d++) {
          double u = fabs(c1[DIM * b + d] - c0[DIM * b + d]);
          if (m[b] > 0 && u > far) far = u;
        }
      if (far <= 0.05 * s->g.h) { done = 1; break; }
      memcpy(c0, c1, (size_t)nb * DIM * sizeof *c0);
      twin = s->t + tw;
    }
  }
  lua_pushboolean(L, done);
  lua_pushnumber(L, s->t - t0);
  lua_pushnumber(L, s->e.kinetic);
  return 3;
}

/* sim:energy() -> the budget and momenta */
static int lenergy(lua_State *L) {
  static const char *const pnames[] = {"px", "py", "pz"};
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  int d;
  if (!s->started) sim_begin(s);
  lua_createtable(L, 0, 24);
  setnum(L, "kinetic", s->e.kinetic);
  setnum(L, "strain", s->e.strain);
  setnum(L, "potential", s->e.potential);
  setnum(L, "wall_spring", s->e.wall_spring);
  lua_pushinteger(L, (lua_Integer)s->nheld);
  lua_setfield(L, -2, "wall_held");
  setnum(L, "dissipated", s->e.friction);
  setnum(L, "plastic", s->e.plastic);
  setnum(L, "viscous", s->e.viscous);
  setnum(L, "boundary_work", s->e.boundary);
  setnum(L, "thermal_work", s->e.thermal);
  setnum(L, "settled", s->e.settled);
  setnum(L, "removed", s->e.removed);
  setnum(L, "chemical", s->e.chemical);
  setnum(L, "latent", s->e.latent);
  setnum(L, "transfer", s->e.transfer);
  setnum(L, "impact", s->e.impact);
  setnum(L, "bonding", s->e.bonding);
  setnum(L, "cohesion", s->e.cohesion);
  setnum(L, "numerical", s->e.transfer + s->e.impact + s->e.bonding);
  setnum(L, "initial", s->e.initial);
  setnum(L, "scale", sim_scale(s));
  setnum(L, "total", sim_total(s));
  setnum(L, "residual", sim_residual(s));
  lua_pushinteger(L, (lua_Integer)s->ncut_total);
  lua_setfield(L, -2, "debonded");
  setnum(L, "bonded_area", s->bond_area);
  for (d = 0; d < DIM; d++) setnum(L, pnames[d], s->e.mom[d]);
  lsim_push_rot(L, s->e.angmom, 1);
  lua_setfield(L, -2, "angmom");
  setnum(L, "jmin", s->e.jmin);
  setnum(L, "jmax", s->e.jmax);
  if (s->heat) { /* heat.h */
    setnum(L, "heat_friction", s->e.heat_friction);
    setnum(L, "heat_plastic", s->e.heat_plastic);
    setnum(L, "heat_viscous", s->e.heat_viscous);
    setnum(L, "heat_source", s->e.heat_source);
    setnum(L, "heat_wall", s->e.heat_wall);
    setnum(L, "cold_work", s->e.cold);
    setnum(L, "heat_boundary", s->e.heat_boundary);
    setnum(L, "thermal_energy", s->e.heat_thermal);
    setnum(L, "heat_residual", sim_heat_residual(s));
    setnum(L, "residual_with_heat", sim_residual_all(s));
  }
  return 1;
}

static int lbodies(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  int b;
  lua_createtable(L, ls->s.nbody, 0);
  for (b = 0; b < ls->s.nbody; b++) {
    lbody_push(L, 1, b);
    lua_rawseti(L, -2, b + 1);
  }
  return 1;
}

static int lsnapshot(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  char buf[1100];
  const char *path = sandbox_path(L, luaL_checkstring(L, 2), "snapshot", buf,
                                  sizeof buf);
  run_snapshot(L, ls, path);
  lua_pushstring(L, path); /* where it went (the prompt shows it) */
  return 1;
}

/* sim:state(tbl) -> tbl: a plain table a checkpoint saves and a restart
** puts back (lstate.h), for callbacks that accumulate */
static int lstate(lua_State *L) {
  lsim_check(L, 1);
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_getiuservalue(L, 1, 1);
  if (lua_getfield(L, -1, "state") != LUA_TNIL && !lua_rawequal(L, -1, 2))
    luaL_error(L, "sim:state: a state table is already registered (put "
                  "everything in one table)");
  lua_pop(L, 1);
  lua_pushvalue(L, 2);
  lua_setfield(L, -2, "state");
  /* a save at checkpoint time runs where no scene line is on the stack */
  if (lua_getfield(L, LUA_REGISTRYINDEX, LSTATE_WHERE) != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, LSTATE_WHERE);
  }
  luaL_where(L, 1);
  lua_rawsetp(L, -2, lua_topointer(L, 2));
  lua_settop(L, 2);
  return 1;
}

/* sim:particles("stress") -> {xx = {...}, yy = {...}, ...} (copies);
** sim:particles() -> the list of field names */
static int lparticles(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  particles *ps = &ls->s.ps;
  int f, c;
  size_t i;
  if (lua_isnoneornil(L, 2)) {
    lua_createtable(L, ps->nfields, 0);
    for (f = 0; f < ps->nfields; f++) {
      lua_pushstring(L, ps->fields[f].name);
      lua_rawseti(L, -2, f + 1);
    }
    return 1;
  }
  f = particles_find(ps, luaL_checkstring(L, 2));
  if (f < 0) luaL_error(L, "particles: no field '%s' (sim:particles() lists them)",
                        lua_tostring(L, 2));
  lua_createtable(L, 0, ps->fields[f].ncomp);
  for (c = 0; c < ps->fields[f].ncomp; c++) {
    const pfield *pf = &ps->fields[f];
    lua_createtable(L, (int)ps->n, 0);
    for (i = 0; i < ps->n; i++) {
      if (pf->type == PF_INT32)
        lua_pushinteger(L, ((int32_t *)particles_comp(ps, f, c))[i] +
                               (strcmp(pf->name, "body") == 0));
      else lua_pushnumber(L, ((double *)particles_comp(ps, f, c))[i]);
      lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    if (pf->ncomp == 1) return 1;
    lua_setfield(L, -2, pf->comp_names[c] ? pf->comp_names[c] : "?");
  }
  return 1;
}

/* sim:wall_force("left") -> fx, fy[, fz]: the force that side put on the
** material in the last step */
static int lwall_force(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  const char *name = luaL_checkstring(L, 2);
  int k, d;
  for (k = 0; k < NSIDES && strcmp(lsim_side_names[k], name) != 0; k++) {}
  if (k == NSIDES)
    luaL_error(L, "wall_force: no side '%s' (the sides are left, right, "
                  "bottom, top%s)", name, DIM == 3 ? ", back, front" : "");
  for (d = 0; d < DIM; d++) lua_pushnumber(L, ls->s.sides[k].force[d]);
  return DIM;
}

/* sim:wall_nodes("bottom") -> {x = {}, y = {}[, z = {}], force = {}}:
** the nodes the wall presses on now and the compressive normal force at
** each (diag_wall.h), as arrays in node order; empty for a side that is
** not a wall */
static int lwall_nodes(lua_State *L) {
  static const char *const xn[] = {"x", "y", "z"};
  lsim *ls = lsim_check(L, 1);
  const char *name = luaL_checkstring(L, 2);
  wall_press *w;
  size_t n, i;
  int k, d;
  for (k = 0; k < NSIDES && strcmp(lsim_side_names[k], name) != 0; k++) {}
  if (k == NSIDES)
    luaL_error(L, "wall_nodes: no side '%s' (the sides are left, right, "
                  "bottom, top%s)", name, DIM == 3 ? ", back, front" : "");
  if (sim_penalty_side(&ls->s, k))
    luaL_error(L, "wall_nodes: under wall_contact = \"penalty\" the walls push "
                  "particles, not nodes; sim:wall_force('%s') gives the force", name);
  if (sim_spring_side(&ls->s, k))
    luaL_error(L, "wall_nodes: under wall_contact = \"spring\" the walls push "
                  "columns of nodes, not single nodes; sim:wall_force('%s') gives "
                  "the force", name);
  if (diag_wall(&ls->s, k, &w, &n)) return luaL_error(L, "%s", ls->s.err);
  lua_createtable(L, 0, DIM + 1);
  for (d = 0; d <= DIM; d++) {
    lua_createtable(L, (int)n, 0);
    for (i = 0; i < n; i++) {
      lua_pushnumber(L, d < DIM ? w[i].x[d] : w[i].fn);
      lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, d < DIM ? xn[d] : "force");
  }
  free(w);
  return 1;
}

/* sim:overlap([maxdepth]) -> n, depth, body, host: particles buried in
** another body by a cell or more (diag_overlap.h), the deepest in cells,
** and for a deepest one its body and the body it lies in (ids, or nil) */
static int loverlap(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  lua_Integer maxd = luaL_optinteger(L, 2, 8);
  overlap_info o;
  luaL_argcheck(L, maxd >= 1 && maxd <= 1000, 2, "maxdepth must be 1 ... 1000 cells");
  if (diag_overlap(&ls->s, (int)maxd, &o)) return luaL_error(L, "overlap: out of memory");
  lua_pushinteger(L, (lua_Integer)o.n);
  lua_pushinteger(L, o.depth);
  if (o.body >= 0) lua_pushinteger(L, o.body + 1); else lua_pushnil(L);
  if (o.host >= 0) lua_pushinteger(L, o.host + 1); else lua_pushnil(L);
  return 4;
}

/* sim:contacts() -> {{a =, b =, force =, fx =, fy =, nodes =}, ...}: the
** pairs of bodies pressing on each other now (diag_contact.h): ids
** (1-based, a < b), the compressive normal force, the normal force on a
** from b, and the shared nodes where they press */
static int lcontacts(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  contact_pair *cp;
  size_t n, k;
  if (diag_contacts(&ls->s, &cp, &n)) return luaL_error(L, "%s", ls->s.err);
  lua_createtable(L, (int)n, 0);
  for (k = 0; k < n; k++) {
    lua_createtable(L, 0, 6);
    lua_pushinteger(L, cp[k].a + 1);
    lua_setfield(L, -2, "a");
    lua_pushinteger(L, cp[k].b + 1);
    lua_setfield(L, -2, "b");
    lua_pushnumber(L, cp[k].fn);
    lua_setfield(L, -2, "force");
    lua_pushnumber(L, cp[k].f[0]);
    lua_setfield(L, -2, "fx");
    lua_pushnumber(L, cp[k].f[1]);
    lua_setfield(L, -2, "fy");
    if (DIM == 3) {
      lua_pushnumber(L, cp[k].f[DIM - 1]);
      lua_setfield(L, -2, "fz");
    }
    lua_pushinteger(L, cp[k].nodes);
    lua_setfield(L, -2, "nodes");
    lua_rawseti(L, -2, (lua_Integer)k + 1);
  }
  free(cp);
  return 1;
}

/* sim:bonds() -> {x =, y =, (z =,) body =, partner =, traction =,
** strength =}: arrays over the bonded interface nodes (diag_bond.h),
** body ids 1-based */
static int lbonds(lua_State *L) {
  static const char *const xn[] = {"x", "y", "z"};
  static const char *const fn[] = {"body", "partner", "traction", "strength"};
  lsim *ls = lsim_check(L, 1);
  bond_node *b;
  size_t n, i;
  int d;
  if (diag_bonds(&ls->s, &b, &n)) return luaL_error(L, "%s", ls->s.err);
  lua_createtable(L, 0, DIM + 4);
  for (d = 0; d < DIM + 4; d++) {
    lua_createtable(L, (int)n, 0);
    for (i = 0; i < n; i++) {
      if (d < DIM) lua_pushnumber(L, b[i].x[d]);
      else if (d == DIM) lua_pushinteger(L, b[i].body + 1);
      else if (d == DIM + 1) lua_pushinteger(L, b[i].partner + 1);
      else lua_pushnumber(L, d == DIM + 2 ? b[i].traction : b[i].strength);
      lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, d < DIM ? xn[d] : fn[d - DIM]);
  }
  free(b);
  return 1;
}

static int lstable_dt(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  if (!ls->s.started) sim_begin(&ls->s);
  lua_pushnumber(L, sim_stable_dt(&ls->s));
  return 1;
}

static int lindex(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  const char *k = luaL_checkstring(L, 2);
  if (strcmp(k, "t") == 0) lua_pushnumber(L, s->t);
  else if (strcmp(k, "dt") == 0) {
    if (!s->started) sim_begin(s);
    lua_pushnumber(L, s->dt);
  }
  else if (strcmp(k, "steps") == 0) lua_pushinteger(L, s->step); /* "step" is the method */
  else if (strcmp(k, "t_end") == 0) lua_pushnumber(L, s->t_end);
  else if (strcmp(k, "n") == 0) lua_pushinteger(L, (lua_Integer)s->ps.n);
  else if (strcmp(k, "nbody") == 0) lua_pushinteger(L, s->nbody);
  else if (strcmp(k, "nfield") == 0) lua_pushinteger(L, s->nfield);
  else if (strcmp(k, "advice") == 0) {
    const char *adv = sim_advice(s);
    if (adv) lua_pushstring(L, adv); else lua_pushnil(L);
  }
  else if (strcmp(k, "wall_advice") == 0) {
    const char *adv = sim_wall_advice(s);
    if (adv) lua_pushstring(L, adv); else lua_pushnil(L);
  }
  else if (strcmp(k, "normals_advice") == 0) {
    const char *adv = sim_normals_advice(s);
    if (adv) lua_pushstring(L, adv); else lua_pushnil(L);
  }
  else if (strcmp(k, "cell") == 0) lua_pushnumber(L, s->g.h);
  else if (strcmp(k, "dim") == 0) lua_pushinteger(L, DIM);
  else if (strcmp(k, "flip") == 0) lua_pushnumber(L, s->cfg.flip);
  else if (strcmp(k, "cfl") == 0) lua_pushnumber(L, s->cfg.cfl);
  else if (strcmp(k, "friction") == 0) lua_pushnumber(L, s->cfg.mu_default);
  else if (strcmp(k, "bond_energy") == 0) lua_pushnumber(L, s->cfg.bond_gc);
  else if (strcmp(k, "removed") == 0) lua_pushinteger(L, (lua_Integer)s->nremoved);
  else if (strcmp(k, "threads") == 0) lua_pushinteger(L, s->cfg.threads);
  else if (strcmp(k, "shared_nodes") == 0) lua_pushinteger(L, (lua_Integer)s->g.nshared);
  else if (strcmp(k, "memory") == 0) { /* bytes allocated, by owner */
    lua_createtable(L, 0, 4);
    setnum(L, "particles", (double)particles_mem(&s->ps));
    setnum(L, "threads", (double)(s->work.redcap + s->work.bands.nrows *
                                  (sizeof *s->work.bands.first + 1) +
                                  marks_mem(&s->work.marks) +
                                  (s->work.wext ? (size_t)(par_threads(s->work.par) - 1) *
                                             s->work.wextn * sizeof *s->work.wext : 0)));
    setnum(L, "capacity", (double)s->ps.cap);
    setnum(L, "grid", (double)grid_mem(&s->g));
    setnum(L, "contact", (double)contact_mem(s));
  }
  else if (strcmp(k, "outdir") == 0) lua_pushstring(L, ls->outdir);
  else if (strcmp(k, "update") == 0) lua_pushstring(L, update_names[s->cfg.update]);
  else if (strcmp(k, "shape") == 0) lua_pushstring(L, shape_names[s->cfg.shape]);
  else if (strcmp(k, "ignition_time") == 0) {
    if (s->t_ignition < INFINITY) lua_pushnumber(L, s->t_ignition);
    else lua_pushnil(L);
  }
  else if (strcmp(k, "ignition") == 0) lua_pushnumber(L, s->cfg.react_ign);
  else if (strcmp(k, "reaction_tol") == 0) lua_pushnumber(L, s->cfg.react_tol);
  else if (strcmp(k, "reacted") == 0) lua_pushnumber(L, react_mean(s));
  else if (strcmp(k, "reaction_substeps") == 0) lua_pushinteger(L, s->react_nsub);
  else if (strcmp(k, "transfer") == 0) lua_pushstring(L, transfer_names[s->cfg.transfer]);
  /* the contact options as the scene set them (or their defaults) */
  else if (strcmp(k, "wall_contact") == 0) lua_pushstring(L, wallopt[s->cfg.wall_rule]);
  else if (strcmp(k, "body_contact") == 0) lua_pushstring(L, bodyopt[s->cfg.body_rule]);
  else if (strcmp(k, "normals") == 0) lua_pushstring(L, normalsopt[s->cfg.normals]);
  else if (strcmp(k, "normal_window") == 0) lua_pushinteger(L, s->cfg.normal_window);
  else if (strcmp(k, "normal_patch") == 0) lua_pushboolean(L, s->cfg.normal_patch);
  else if (strcmp(k, "contact_gap") == 0) lua_pushstring(L, gapopt[s->cfg.gap_step]);
  else if (strcmp(k, "separation") == 0) lua_pushboolean(L, s->cfg.gap_check);
  else if (strcmp(k, "wall_remap") == 0) lua_pushstring(L, remapopt[s->cfg.wall_remap]);
  else if (strcmp(k, "bond_traction") == 0) lua_pushstring(L, tractionopt[s->cfg.bond_fit]);
  else if (strcmp(k, "bond_length") == 0) lua_pushnumber(L, s->cfg.bond_length);
  else if (strcmp(k, "bond_release") == 0) lua_pushstring(L, releaseopt[s->cfg.release]);
  else {
    static const char *const fields[] = {
        "t", "dt", "steps", "t_end", "n", "nbody", "nfield", "advice", "wall_advice",
        "normals_advice", "cell",
        "dim", "flip", "cfl", "friction", "bond_energy", "removed", "threads", "shared_nodes",
        "memory", "outdir", "update", "shape", "transfer", "ignition_time",
        "ignition", "reaction_tol", "reacted", "reaction_substeps", "wall_contact",
        "body_contact", "normals", "normal_window", "normal_patch", "contact_gap",
        "separation", "wall_remap", "bond_traction", "bond_length", "bond_release", NULL};
    luaL_getmetafield(L, 1, "methods");
    if (lua_getfield(L, -1, k) == LUA_TNIL) chk_nokey(L, "sim", k, -2, fields);
  }
  return 1;
}

/* settable between steps: flip, cfl, dt (0 = automatic), t_end, friction,
** threads */
static int lnewindex(lua_State *L) {
  static const char *const keys[] = {"flip", "cfl", "dt", "t_end", "friction",
                                     "progress", "threads", "ignition",
                                     "reaction_tol", NULL};
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  const char *k = luaL_checkstring(L, 2);
  lua_settop(L, 3);
  lua_createtable(L, 0, 1);
  lua_pushvalue(L, 3);
  lua_setfield(L, -2, k);
  chk_keys(L, 4, "sim", keys);
  if (strcmp(k, "flip") == 0) {
    double f = chk_num(L, 4, "sim", k, 1, 0, 1, 0);
    if ((s->cfg.wall_rule == WALL_PENALTY || s->cfg.wall_rule == WALL_SPRING) && f < 1)
      chk_error(L, "sim: field 'flip' must be 1 with wall_contact = \"%s\" "
                   "(got %g): its energy budget closes under pure FLIP only",
                s->cfg.wall_rule == WALL_PENALTY ? "penalty" : "spring", f);
    s->cfg.flip = f;
  }
  else if (strcmp(k, "cfl") == 0) s->cfg.cfl = chk_num(L, 4, "sim", k, 0.25, 0, 1, CHK_OPENLO);
  else if (strcmp(k, "dt") == 0) s->cfg.dt_fixed = chk_num(L, 4, "sim", k, 0, 0, HUGE_VAL, 0);
  else if (strcmp(k, "t_end") == 0) s->t_end = chk_num(L, 4, "sim", k, 0, 0, HUGE_VAL, 0);
  else if (strcmp(k, "friction") == 0) s->cfg.mu_default = friction(L, 4, "sim", s->cfg.mu_default);
  else if (strcmp(k, "progress") == 0) ls->progress = lua_toboolean(L, 3);
  else if (strcmp(k, "ignition") == 0)
    s->cfg.react_ign = chk_num(L, 4, "sim", k, 0.5, 0, 1, CHK_OPENLO);
  else if (strcmp(k, "reaction_tol") == 0)
    s->cfg.react_tol = chk_num(L, 4, "sim", k, REACT_TOL, 0, 1, CHK_OPENLO);
  else if (strcmp(k, "threads") == 0)
    sim_set_threads(s, (int)chk_num(L, 4, "sim", k, 1, 1, PAR_MAX, CHK_INT));
  /* a step made too small (or an end too far) while running: refused
  ** here, where the number enters */
  if (strcmp(k, "dt") == 0 || strcmp(k, "cfl") == 0 || strcmp(k, "t_end") == 0)
    run_check_steps(L, ls, s->t_end);
  return 0;
}

static int ltostr(lua_State *L) {
  lsim *ls = luaL_checkudata(L, 1, LSIM_MT);
  if (ls->closed || !ls->ok) {
    lua_pushstring(L, ls->closed ? "sim (closed)" : "sim (not set up)");
    return 1;
  }
  lua_pushfstring(L, "sim: %d bodies, %d particles, t = %f, step %d",
                  ls->s.nbody, (int)ls->s.ps.n, ls->s.t, (int)ls->s.step);
  return 1;
}

void lsim_open(lua_State *L) {
  static const luaL_Reg meth[] = {
      {"body", lbody_new}, {"contact", lcontact}, {"every", levery},
      {"output", loutput}, {"step", lstep}, {"run", lrun},
      {"energy", lenergy}, {"bodies", lbodies}, {"snapshot", lsnapshot},
      {"particles", lparticles}, {"stable_dt", lstable_dt},
      {"temperature", lsim_temperature}, {"render", lrender_sim},
      {"hotspots", lsim_hotspots},
      {"heat", lsim_heat},
      {"wall_force", lwall_force}, {"wall_nodes", lwall_nodes},
      {"overlap", loverlap},
      {"contacts", lcontacts}, {"bonds", lbonds}, {"state", lstate},
      {"settle", lsettle}, {"at_end", lat_end},
      {NULL, NULL}};
  luaL_newmetatable(L, LSIM_MT);
  lua_pushcfunction(L, lindex);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, lnewindex);
  lua_setfield(L, -2, "__newindex");
  lua_pushcfunction(L, lgc);
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, ltostr);
  lua_setfield(L, -2, "__tostring");
  lsim_lock(L, -1);
  luaL_newlib(L, meth);
  lua_setfield(L, -2, "methods");
  lua_pop(L, 1);
}
