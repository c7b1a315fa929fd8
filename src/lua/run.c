/*
** run.c - stepping a simulation from Lua: between steps it evaluates the
** drives (Lua functions of time, once per step), records the diagnostics
** row, calls the scene's callbacks, writes snapshots, shows progress, and
** honours Ctrl-C.  Nothing here runs inside a step.
*/
#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "lckpt.h"
#include "interrupt.h"
#include "lcheck.h"
#include "lmvmpm.h"
#include "lsim.h"
#include "out_h5.h"
#include "prof.h"
#include "react.h"
#include "sandbox.h"
#include "version.h"

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* mkdir -p */
int run_mkdirs(const char *path, char *err, size_t errlen) {
  char buf[1024];
  size_t k, n = strlen(path);
  if (n >= sizeof buf) { snprintf(err, errlen, "%s: path too long", path); return -1; }
  memcpy(buf, path, n + 1);
  for (k = 1; k <= n; k++)
    if (buf[k] == '/' || buf[k] == 0) {
      char c = buf[k];
      buf[k] = 0;
      if (mkdir(buf, 0777) && errno != EEXIST) {
        snprintf(err, errlen, "%s: cannot create directory (%s)", buf, strerror(errno));
        return -1;
      }
      buf[k] = c;
    }
  return 0;
}

/* the names a run writes in its directory (and their .tmp/.part while
** being written): what --overwrite removes, and nothing else */
static int run_output_name(const char *n) {
  static const char *const pre[] = {"particles_", "checkpoint_", "failed_",
                                    "hotspots_"};
  char rest[32];
  size_t k, len;
  int d;
  if (strcmp(n, "particles.xmf") == 0 || strcmp(n, "diagnostics.csv") == 0 ||
      strcmp(n, "diagnostics.csv.part") == 0 ||
      strcmp(n, "particles.xmf.tmp") == 0)
    return 1;
  for (k = 0; k < sizeof pre / sizeof pre[0]; k++) {
    len = strlen(pre[k]);
    if (strncmp(n, pre[k], len) != 0) continue;
    for (d = 0; d < 6; d++)
      if (n[len + d] < '0' || n[len + d] > '9') break;
    if (d < 6) continue;
    snprintf(rest, sizeof rest, "%s", n + len + 6);
    if (strcmp(rest, ".h5") == 0 || strcmp(rest, ".h5.tmp") == 0) return 1;
    if (k == 3 && (strcmp(rest, ".csv") == 0 || strcmp(rest, ".csv.tmp") == 0))
      return 1;
  }
  return 0;
}

int run_claim_outdir(const char *dir, int overwrite, char *err,
                     size_t errlen) {
  DIR *d = opendir(dir);
  struct dirent *de;
  char first[300] = "", path[1400];
  int n = 0, ck = 0;
  if (!d) return 0; /* not there yet: made when output starts */
  while ((de = readdir(d))) {
    struct stat st;
    if (!run_output_name(de->d_name)) continue;
    /* only regular files: a run never writes a link or anything else */
    snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode)) continue;
    if (!n++) snprintf(first, sizeof first, "%s", de->d_name);
    ck |= strncmp(de->d_name, "checkpoint_", 11) == 0;
    if (!overwrite) continue;
    if (unlink(path) != 0 && errno != ENOENT) {
      snprintf(err, errlen, "%s: --overwrite cannot remove it (%s)", path,
               strerror(errno));
      closedir(d);
      return -1;
    }
  }
  closedir(d);
  if (n && !overwrite) {
    snprintf(err, errlen, "%s holds the outputs of another run (%s%s); give "
             "--overwrite to remove them (only a run's snapshots, index, "
             "table, checkpoints and failed states) or another --out%s%s%s",
             dir, first, n > 1 ? " and more" : "",
             ck ? ", or --restart " : "", ck ? dir : "",
             ck ? " to continue it" : "");
    return -1;
  }
  return 0;
}

/* every term of the budget (docs/algorithm.md) is a column: total =
** kinetic + strain + potential + lag, residual = initial + boundary_work
** + thermal_work - dissipated - plastic - viscous - settled - transfer
** - impact - bonding - cohesion - removed - total, and
** scale (sim_scale) the size it is measured against */
static const char *const cols[] = {"step", "t", "dt", "kinetic", "strain",
    "dissipated", "plastic", "viscous", "boundary_work", "thermal_work",
    "total", "residual", "px", "py", "angmom", "jmin", "jmax", "particles",
    "debonded", "bonded_area", "potential", "lag", "settled", "initial",
    "scale", "transfer", "impact", "bonding",
    /* the reaction's heat and burn, the first ignition and the hot spots
    ** of sim:output{hotspots =} (react.h, lua_hotspot.c) */
    "chemical", "reacted", "ignition_time", "hotspots",
    "hotspot_area_fraction",
    /* the cohesive law's work of separation (sim.bond_energy); what
    ** particles leaving through free sides took (sim.c) */
    "cohesion", "removed",
    /* scenes with heat only (heat.h): the heat the sources put in, what
    ** walls and held bodies exchanged, the thermal energy the particles
    ** hold, and the two residuals */
    "heat_friction", "heat_plastic", "heat_viscous", "heat_source",
    "heat_wall", "cold_work", "heat_boundary", "thermal_energy",
    "heat_residual", "residual_with_heat"};
#define NCOLS_ALL (int)(sizeof cols / sizeof cols[0])
#define NCOLS_HEAT 10
/* in 3-D, after the hot spots and before the heat: the third momentum
** and the x, y components of the angular momentum ("angmom" is its z) */
static const char *const cols3[] = {"pz", "angmom_x", "angmom_y"};
#define NCOLS_3D (DIM == 3 ? 3 : 0)
#define NCOLS_BASE (NCOLS_ALL - NCOLS_HEAT)
#define NCOLS (NCOLS_BASE + NCOLS_3D + (ls->s.heat ? NCOLS_HEAT : 0))

/* the columns in this build's order: the 2-D ones, the 3-D ones, heat */
static void csv_cols(const char **names) {
  int k;
  for (k = 0; k < NCOLS_BASE; k++) names[k] = cols[k];
  for (k = 0; k < NCOLS_3D; k++) names[NCOLS_BASE + k] = cols3[k];
  for (k = 0; k < NCOLS_HEAT; k++)
    names[NCOLS_BASE + NCOLS_3D + k] = cols[NCOLS_BASE + k];
}

static void csv_row(lua_State *L, lsim *ls) {
  sim *s = &ls->s;
  double v[NCOLS_ALL], tot = sim_total(s);
  char err[256];
  v[0] = (double)s->step; v[1] = s->t; v[2] = s->dt;
  v[3] = s->e.kinetic; v[4] = s->e.strain; v[5] = s->e.friction;
  v[6] = s->e.plastic; v[7] = s->e.viscous;
  v[8] = s->e.boundary; v[9] = s->e.thermal; v[10] = tot;
  v[11] = sim_residual(s);
  v[12] = s->e.mom[0]; v[13] = s->e.mom[1];
  v[14] = s->e.angmom[2];
  v[15] = s->e.jmin; v[16] = s->e.jmax; v[17] = (double)s->ps.n;
  v[18] = (double)s->ncut_total; v[19] = s->bond_area;
  v[20] = s->e.potential; v[21] = s->e.lag; v[22] = s->e.settled;
  v[23] = s->e.initial; v[24] = sim_scale(s);
  v[25] = s->e.transfer; v[26] = s->e.impact; v[27] = s->e.bonding;
  /* the reaction's heat and burn; the first ignition (-1 before) */
  v[28] = s->e.chemical; v[29] = react_mean(s);
  v[30] = s->t_ignition < INFINITY ? s->t_ignition : -1;
  lsim_hotspot_row(L, ls, &v[31], &v[32]);
  v[33] = s->e.cohesion; v[34] = s->e.removed;
  if (s->heat) {
    v[35] = s->e.heat_friction; v[36] = s->e.heat_plastic;
    v[37] = s->e.heat_viscous; v[38] = s->e.heat_source;
    v[39] = s->e.heat_wall; v[40] = s->e.cold; v[41] = s->e.heat_boundary;
    v[42] = s->e.heat_thermal; v[43] = sim_heat_residual(s);
    v[44] = sim_residual_all(s);
  }
  if (NCOLS_3D) { /* the 3-D columns go before the heat's */
    double w[NCOLS_ALL + 3];
    int k;
    for (k = 0; k < NCOLS_BASE; k++) w[k] = v[k];
    w[NCOLS_BASE] = s->e.mom[DIM - 1];
    w[NCOLS_BASE + 1] = s->e.angmom[0];
    w[NCOLS_BASE + 2] = s->e.angmom[1];
    for (k = 0; s->heat && k < NCOLS_HEAT; k++)
      w[NCOLS_BASE + 3 + k] = v[NCOLS_BASE + k];
    if (out_csv_row(&ls->csv, w, err, sizeof err)) luaL_error(L, "%s", err);
  } else if (out_csv_row(&ls->csv, v, err, sizeof err))
    luaL_error(L, "%s", err);
}

/* the provenance every output file carries: the strings are pushed on
** the stack (3 values), where they stay alive until the caller pops */
void run_provenance(lua_State *L, h5prov *meta) {
  char *p = lmvmpm_params_text(L);
  memset(meta, 0, sizeof *meta);
  meta->version = mvmpm_version;
  meta->build = mvmpm_build;
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.command");
  meta->command = lua_tostring(L, -1);
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.restarted");
  meta->restarted = lua_tostring(L, -1);
  lua_pushstring(L, p ? p : "");
  meta->params = lua_tostring(L, -1);
  free(p);
}

/* the same as "# name: value" lines for the head of the diagnostics
** table, pushed as one string (readers skip lines starting with '#') */
static const char *csv_preamble(lua_State *L, const sim *s) {
  static const char *const name[] = {"version", "build", "command",
                                     "restarted_from", "scheme"};
  const char *val[5], *p, *nl;
  char scheme[256];
  h5prov m;
  luaL_Buffer b;
  int k;
  run_provenance(L, &m);
  sim_scheme(s, scheme, sizeof scheme);
  val[0] = m.version; val[1] = m.build; val[2] = m.command;
  val[3] = m.restarted; val[4] = scheme;
  luaL_buffinit(L, &b);
  for (k = 0; k < 5; k++)
    if (val[k]) {
      luaL_addstring(&b, "# ");
      luaL_addstring(&b, name[k]);
      luaL_addstring(&b, ": ");
      luaL_addstring(&b, val[k]);
      luaL_addchar(&b, '\n');
    }
  luaL_addstring(&b, "# params:\n");
  for (p = m.params; *p && (nl = strchr(p, '\n')); p = nl + 1) {
    luaL_addstring(&b, "#   ");
    luaL_addlstring(&b, p, (size_t)(nl - p + 1));
  }
  luaL_pushresult(&b);
  lua_replace(L, -4);
  lua_pop(L, 2);
  return lua_tostring(L, -1);
}

int run_frame(const sim *s, h5frame *fr) {
  int b, d;
  memset(fr, 0, sizeof *fr);
  for (d = 0; d < DIM; d++) {
    fr->lo[d] = s->g.lo[d];
    fr->hi[d] = s->g.hi[d];
    fr->periodic[d] = s->g.periodic[d];
  }
  fr->name = calloc(s->nbody ? s->nbody : 1, sizeof *fr->name);
  fr->driven = calloc(s->nbody ? s->nbody : 1, sizeof *fr->driven);
  if (!fr->name || !fr->driven) return -1;
  for (b = 0; b < s->nbody; b++) {
    snprintf(fr->name[b], sizeof fr->name[b], "%s", s->bodies[b].name);
    fr->driven[b] = s->bodies[b].driven != 0;
  }
  fr->nbody = s->nbody;
  return 0;
}

/* the particles as they stand to path, with the meta data, provenance
** and frame every snapshot carries; 0, or -1 with err */
static int write_snapshot(lua_State *L, lsim *ls, const char *path, char *err,
                          size_t errlen) {
  h5meta meta;
  h5prov prov;
  h5frame fr;
  char scheme[256];
  int r;
  memset(&meta, 0, sizeof meta);
  meta.time = ls->s.t;
  meta.step = ls->s.step;
  meta.cell = ls->s.g.h;
  meta.units = ls->units;
  meta.scene = ls->scene;
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.source");
  meta.source = lua_tostring(L, -1);
  run_provenance(L, &prov);
  sim_scheme(&ls->s, scheme, sizeof scheme);
  prov.scheme = scheme;
  meta.frame = &fr;
  if (run_frame(&ls->s, &fr)) {
    snprintf(err, errlen, "%s: out of memory", path);
    r = -1;
  } else
    r = out_h5_write_prov(path, &ls->s.ps, &meta, &prov, err, errlen);
  out_h5_frame_free(&fr);
  lua_pop(L, 4);
  return r;
}

int run_snapshot(lua_State *L, lsim *ls, const char *path) {
  char err[512];
  if (write_snapshot(L, ls, path, err, sizeof err))
    return luaL_error(L, "%s", err);
  return 0;
}

static void snapshot(lua_State *L, lsim *ls) {
  char path[1100], name[64], err[512];
  xdmf_entry *e;
  snprintf(name, sizeof name, "particles_%06d.h5", ls->nsnap);
  snprintf(path, sizeof path, "%s/%s", ls->outdir, name);
  sandbox_file(L, path, "output");
  run_snapshot(L, ls, path);
  lsim_hotspot_file(L, ls, ls->nsnap);
  if (ls->nsnap == ls->snapcap) {
    int cap = ls->snapcap ? 2 * ls->snapcap : 64;
    void *p = realloc(ls->snaps, cap * sizeof *ls->snaps);
    if (!p) luaL_error(L, "output: out of memory");
    ls->snaps = p;
    ls->snapcap = cap;
  }
  e = &ls->snaps[ls->nsnap++];
  snprintf(e->file, sizeof e->file, "%s", name);
  e->time = ls->s.t;
  e->n = ls->s.ps.n;
  snprintf(path, sizeof path, "%s/particles.xmf", ls->outdir);
  sandbox_file(L, path, "output");
  if (out_xdmf_write(path, ls->snaps, ls->nsnap, &ls->s.ps, err, sizeof err))
    luaL_error(L, "%s", err);
}

long run_sync(lua_State *L, lsim *ls) {
  char err[1100];
  long n;
  if (!ls->csv_open || !ls->csv.f) return -1;
  n = out_csv_sync(&ls->csv, err, sizeof err);
  if (n == -2) luaL_error(L, "%s", err);
  return n;
}

/* the table and its .part (written first, renamed at the end) */
static void csv_check(lua_State *L, const char *path) {
  char part[1100];
  sandbox_file(L, path, "output");
  snprintf(part, sizeof part, "%s.part", path);
  sandbox_file(L, part, "output");
}

/* a restarted run: the table continues where the checkpoint left it, the
** index lists the snapshots up to then, the rest is already scheduled */
static void out_resume(lua_State *L, lsim *ls) {
  char err[1100], path[1100];
  if (ls->csv_resume >= 0) {
    snprintf(path, sizeof path, "%s/diagnostics.csv", ls->outdir);
    csv_check(L, path);
    const char *names[NCOLS_ALL + 3];
    csv_cols(names);
    if (out_csv_resume(&ls->csv, path, ls->csv_resume, names, NCOLS, err,
                       sizeof err))
      luaL_error(L, "%s", err);
  }
  ls->csv_open = 1;
  if (ls->nsnap > 0) {
    snprintf(path, sizeof path, "%s/particles.xmf", ls->outdir);
    sandbox_file(L, path, "output");
    if (out_xdmf_write(path, ls->snaps, ls->nsnap, &ls->s.ps, err, sizeof err))
      luaL_error(L, "%s", err);
  }
}

static void out_start(lua_State *L, lsim *ls) {
  char err[512], path[1100];
  if (!ls->out_enabled || !ls->outdir[0] || ls->csv_open) return;
  if (run_mkdirs(ls->outdir, err, sizeof err)) luaL_error(L, "%s", err);
  if (ls->restarted) {
    out_resume(L, ls);
    return;
  }
  if (ls->ck_every > 0) ls->ck_next = ls->s.t + ls->ck_every;
  if (!ls->s.started) sim_begin(&ls->s); /* the first row is the start */
  if (ls->csv_every > 0) {
    snprintf(path, sizeof path, "%s/diagnostics.csv", ls->outdir);
    csv_check(L, path);
    const char *names[NCOLS_ALL + 3];
    csv_cols(names);
    if (out_csv_open(&ls->csv, path, csv_preamble(L, &ls->s), names, NCOLS, err,
                     sizeof err))
      luaL_error(L, "%s", err);
    lua_pop(L, 1);
    csv_row(L, ls);
  }
  ls->csv_open = 1;
  if (ls->out_every > 0) {
    snapshot(L, ls);
    ls->out_next = ls->s.t + ls->out_every;
  }
}

/* drives and moving walls given as functions of time; what they return
** is checked here, and an error names where the function was defined
** (between steps no scene line is on the stack) */
static void drives(lua_State *L, int simidx, lsim *ls) {
  int d, k;
  if (ls->drives) {
    lsim_uv(L, simidx, "drives");
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      int b = (int)lua_tointeger(L, -2), fn = lua_gettop(L);
      const char *name = ls->s.bodies[b].name;
      double v[DIM];
      lua_pushvalue(L, fn);
      lua_pushnumber(L, ls->s.t);
      lua_call(L, 1, DIM);
      for (d = 0; d < DIM; d++)
        v[d] = chk_result(L, d - DIM, fn, "drive of body '%s' at t = %g",
                          name, ls->s.t);
      lsim_check_speed(L, ls, v, fn, "drive of body '%s' at t = %g", name,
                       ls->s.t);
      for (d = 0; d < DIM; d++) ls->s.bodies[b].vdrive[d] = v[d];
      lua_pop(L, DIM + 1);
    }
    lua_pop(L, 1);
  }
  if (ls->sidefns) {
    lsim_uv(L, simidx, "sidefn");
    for (k = 0; k < NSIDES; k++) {
      int fn;
      double v[DIM];
      if (lua_rawgeti(L, -1, k) != LUA_TFUNCTION) { lua_pop(L, 1); continue; }
      fn = lua_gettop(L);
      lua_pushvalue(L, fn);
      lua_pushnumber(L, ls->s.t);
      lua_call(L, 1, DIM);
      for (d = 0; d < DIM; d++)
        v[d] = chk_result(L, d - DIM, fn, "velocity of side '%s' at t = %g",
                          lsim_side_names[k], ls->s.t);
      if (v[k / 2] != 0)
        chk_fnerror(L, fn, "velocity of side '%s' at t = %g: the wall "
                    "slides along its own line, so the %c component must "
                    "be 0 (got %g)", lsim_side_names[k], ls->s.t,
                    "xyz"[k / 2], v[k / 2]);
      lsim_check_speed(L, ls, v, fn, "velocity of side '%s' at t = %g",
                       lsim_side_names[k], ls->s.t);
      for (d = 0; d < DIM; d++) ls->s.sides[k].v[d] = v[d];
      lua_pop(L, DIM + 1);
    }
    lua_pop(L, 1);
  }
}

/* the next time of a schedule next, next + every, ... that lies after t
** (tol absorbs rounding).  A step longer than the interval skips the
** times it covered in one jump, not one by one: there is at most one
** event per step, and a tiny interval costs nothing extra */
static double sched_next(double next, double every, double t, double tol) {
  next += every;
  if (next > t + tol) return next;
  next += every * (floor((t + tol - next) / every) + 1);
  if (!(next > t + tol)) next = t + tol + every; /* every below t's ulp */
  if (!(next > t)) next = nextafter(t, HUGE_VAL);
  return next;
}

static void callbacks(lua_State *L, int simidx, lsim *ls) {
  lua_Integer k, n;
  lsim_uv(L, simidx, "every");
  n = luaL_len(L, -1);
  for (k = 1; k <= n; k++) {
    int due;
    lua_rawgeti(L, -1, k);
    lua_getfield(L, -1, "time");
    if (!lua_isnil(L, -1)) {
      double dt = lua_tonumber(L, -1);
      lua_getfield(L, -2, "next");
      due = ls->s.t >= lua_tonumber(L, -1) - 1e-12 * dt;
      if (due) {
        lua_pushnumber(L, sched_next(lua_tonumber(L, -1), dt, ls->s.t, 1e-12 * dt));
        lua_setfield(L, -4, "next");
      }
    } else {
      lua_getfield(L, -2, "steps");
      lua_Integer st = lua_tointeger(L, -1);
      lua_getfield(L, -3, "next");
      due = ls->s.step >= lua_tointeger(L, -1);
      if (due) {
        lua_pushinteger(L, ls->s.step + st);
        lua_setfield(L, -5, "next");
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 2);
    if (due) {
      lua_getfield(L, -1, "fn");
      lua_pushvalue(L, simidx);
      lua_call(L, 1, 0);
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

/* before a run to t_end: refuse what would not finish, naming why.  The
** step count comes from the step the run starts with (fixed, or the
** CFL step of the fastest wave and particle); a schedule whose interval
** makes more than LSIM_MAX_EVENTS events is refused too */
void run_check_steps(lua_State *L, lsim *ls, double t_end) {
  sim *s = &ls->s;
  double span = t_end - s->t, dt, steps;
  if (!(span > 0)) return;
  if (!s->started) sim_measure(s); /* the particle speeds */
  dt = s->cfg.dt_fixed > 0 ? s->cfg.dt_fixed : sim_stable_dt(s);
  steps = span / dt;
  if (!(steps <= LSIM_MAX_STEPS)) {
    double c = 0;
    int m;
    for (m = 0; m < s->nmat; m++)
      if (s->mats[m].c > c) c = s->mats[m].c;
    if (s->cfg.dt_fixed > 0)
      chk_error(L, "run: from t = %g to t = %g steps of dt = %g would take "
                   "%.3g steps (at most %.0e); give a larger 'dt'", s->t,
                t_end, dt, steps, LSIM_MAX_STEPS);
    chk_error(L, "run: from t = %g to t = %g the step cfl * cell / (wave "
                 "speed + particle speed) = %g * %g / (%g + %g) = %g would "
                 "take %.3g steps (at most %.0e)", s->t, t_end, s->cfg.cfl,
              s->g.h, c, s->vmax, dt, steps, LSIM_MAX_STEPS);
  }
}

static void run_check(lua_State *L, int simidx, lsim *ls, double t_end) {
  double span = t_end - ls->s.t;
  lua_Integer k, n;
  if (!(span > 0)) return;
  run_check_steps(L, ls, t_end);
  lsim_check_every(L, "output: field 'every'", ls->out_every, span);
  lsim_check_every(L, "output: checkpoint interval", ls->ck_every, span);
  lsim_uv(L, simidx, "every");
  n = luaL_len(L, -1);
  for (k = 1; k <= n; k++) {
    lua_rawgeti(L, -1, k);
    lua_getfield(L, -1, "time");
    lsim_check_every(L, "every: field 'time'", lua_tonumber(L, -1), span);
    lua_pop(L, 2);
  }
  lua_pop(L, 1);
}

static void progress(lsim *ls, double t_end, double t0, double wall0,
                     long step0, int last) {
  static double shown;
  double w = now(), rate, eta;
  if (!last && w - shown < 0.25) return;
  shown = w;
  rate = (ls->s.step - step0) / (w - wall0 + 1e-9);
  eta = (ls->s.t > t0 && isfinite(t_end))
            ? (w - wall0) * (t_end - ls->s.t) / (ls->s.t - t0) : 0;
  fprintf(stderr, "\rstep %ld  t %.4g / %.4g  dt %.3g  %.0f steps/s  ETA %.0f s   %s",
          ls->s.step, ls->s.t, t_end, ls->s.dt, rate, eta > 0 ? eta : 0,
          last ? "\n" : "");
  fflush(stderr);
}

/* progress where stderr is no terminal (a batch job, 2>log): a plain
** line each time the run passes another tenth of its span, or after
** PLAIN_WALL seconds without one, whichever comes first */
#define PLAIN_WALL 30.0
typedef struct plain { double next_t, last_w; } plain;

static void plain_progress(lsim *ls, plain *p, double t_end, double t0,
                           double wall0, long step0) {
  double w, span = t_end - t0, rate, eta;
  if (!isfinite(t_end) || !(span > 0)) return;
  w = now();
  /* a tenth reached up to rounding (steps land on output times) */
  if (ls->s.t < p->next_t - 1e-9 * span && w - p->last_w < PLAIN_WALL) return;
  while (p->next_t <= ls->s.t + 1e-9 * span) p->next_t += 0.1 * span;
  p->last_w = w;
  rate = (ls->s.step - step0) / (w - wall0 + 1e-9);
  eta = ls->s.t > t0 ? (w - wall0) * (t_end - ls->s.t) / (ls->s.t - t0) : 0;
  fprintf(stderr, "progress: step %ld  t %.6g / %.6g (%.0f %%)  dt %.3g  "
          "%.0f steps/s  wall %.1f s  ETA %.0f s\n", ls->s.step, ls->s.t,
          t_end, 100 * (ls->s.t - t0) / span, ls->s.dt, rate, w - wall0,
          eta > 0 ? eta : 0);
  fflush(stderr);
}

/* the energy budget: warn once when the residual passes warn_residual of
** the energy scale (the largest of the initial energy, the boundary and
** thermal work, and the kinetic + strain energy seen so far).  Not in
** the first WARN_FROM of the run: a scene driven from rest starts with
** energies near zero, against which any rounding is a large fraction */
#define WARN_RESIDUAL 0.05
#define WARN_FROM 0.05
static void residual_check(lsim *ls, double from) {
  const sim_energy *e = &ls->s.e;
  double lim = ls->warn_given ? ls->warn_residual : WARN_RESIDUAL;
  double scale, r;
  if (ls->warned || !(lim > 0)) return;
  if (e->kinetic + e->strain > ls->e_peak) ls->e_peak = e->kinetic + e->strain;
  /* the budget's scale (no choice of origin changes it, as the initial
  ** energy's potential would), or the peak of kinetic + strain if more */
  scale = sim_scale(&ls->s);
  if (ls->e_peak > scale) scale = ls->e_peak;
  r = sim_residual(&ls->s);
  if (ls->s.t < from || !(scale > 0) || !(fabs(r) > lim * scale)) return;
  ls->warned = 1;
  fprintf(stderr, "%smvmpm: warning: %s: the energy budget's residual is %.3g "
          "at step %ld, t = %g: %.3g %% of the energy scale %.3g, above "
          "warn_residual = %g (the diagnostics table has the terms)\n",
          ls->progress && isatty(2) ? "\n" : "",
          ls->scene[0] ? ls->scene : "sim", r, ls->s.step, ls->s.t,
          100 * fabs(r) / scale, scale, lim);
}

/*
** A guard stopped the step (det F <= 0, a NaN): the particles as they
** stand go to failed_NNNNNN.h5 (the step number) beside the snapshots,
** for inspection, and the message says where.  The state is the one the
** failed step left, part-way through an update.
*/
static void failed_state(lua_State *L, lsim *ls) {
  char path[1100], err[512];
  ls->failed[0] = '\0';
  if (!ls->csv_open || !ls->outdir[0]) return;
  snprintf(path, sizeof path, "%s/failed_%06ld.h5", ls->outdir, ls->s.step);
  sandbox_file(L, path, "output");
  if (write_snapshot(L, ls, path, err, sizeof err) == 0)
    snprintf(ls->failed, sizeof ls->failed, "; the state it stopped in is "
             "%s", path);
  else
    snprintf(ls->failed, sizeof ls->failed, "; the state it stopped in "
             "could not be written (%s)", err);
}

/* a warning about the scene's settings, printed once per process (*done) */
static void warn_once(const lsim *ls, int *done, const char *adv) {
  if (!adv || *done) return;
  *done = 1;
  fprintf(stderr, "mvmpm: warning: %s: %s\n", ls->scene[0] ? ls->scene : "sim", adv);
}

int run_until(lua_State *L, int simidx, double t_end, long max_steps) {
  lsim *ls = lsim_check(L, simidx);
  sim *s = &ls->s;
  double t0 = s->t, wall0 = now();
  long step0 = s->step, k = 0;
  int show = ls->progress && isatty(2);
  int quietly = ls->progress && !isatty(2);
  plain pl;
  double warn_from;
  simidx = lua_absindex(L, simidx);
  if (s->ps.n == 0)
    luaL_error(L, "run: %s: the simulation has no particles (add a body with "
                  "sim:body{...})", ls->scene[0] ? ls->scene : "sim");
  if (!ls->advised) { /* now that the bodies (fields) are known */
    /* printed once per process: a study or a test script that builds
    ** many such scenes says it once; each keeps it in sim.advice */
    static int printed, wprinted, nprinted;
    ls->advised = 1;
    warn_once(ls, &printed, sim_advice(s));
    warn_once(ls, &wprinted, sim_wall_advice(s));
    warn_once(ls, &nprinted, sim_normals_advice(s));
  }
  if (isfinite(t_end)) run_check(L, simidx, ls, t_end);
  out_start(L, ls);
  pl.next_t = t0 + 0.1 * (t_end - t0);
  warn_from = isfinite(t_end) ? t0 + WARN_FROM * (t_end - t0) : t0;
  pl.last_w = wall0;
  prof_start(s->work.prof);
  /* t_end = HUGE_VAL (sim:step) would make the tolerance inf - inf = NaN */
  while ((max_steps < 0 || k < max_steps) &&
         (isinf(t_end) || s->t < t_end - 1e-12 * (1 + fabs(t_end)))) {
    /* steps land on the output times and on the end of the run */
    s->t_stop = ls->csv_open && ls->out_every > 0 && ls->out_next < t_end
                    ? ls->out_next : t_end;
    if (ls->drives || ls->sidefns) drives(L, simidx, ls);
    /* the temperature at the end of the coming step */
    if (ls->tempfn) s->temp = lsim_temperature_at(L, simidx, s->t + sim_next_dt(s));
    prof_mark(s->work.prof, PROF_DIAG);
    if (sim_step(s)) {
      failed_state(L, ls);
      luaL_error(L, "%s%s", s->err, ls->failed);
    }
    k++;
    if (ls->csv_open) residual_check(ls, warn_from);
    if (ls->csv_open && ls->csv_every > 0 && s->step % ls->csv_every == 0) csv_row(L, ls);
    if (ls->nevery) callbacks(L, simidx, ls);
    prof_mark(s->work.prof, PROF_DIAG);
    if (ls->csv_open && ls->out_every > 0 && s->t >= ls->out_next - 1e-9 * ls->out_every) {
      snapshot(L, ls);
      ls->out_next = sched_next(ls->out_next, ls->out_every, s->t, 1e-9 * ls->out_every);
    }
    /* checkpoints do not change the steps: one is written at the first
    ** step boundary at or after its time */
    if (ls->csv_open && ls->ck_every > 0 && s->t >= ls->ck_next - 1e-9 * ls->ck_every) {
      ls->ck_next = sched_next(ls->ck_next, ls->ck_every, s->t, 1e-9 * ls->ck_every);
      ckpt_write(L, simidx);
    }
    if (show) progress(ls, max_steps < 0 ? t_end : s->t, t0, wall0, step0, 0);
    else if (quietly && max_steps < 0)
      plain_progress(ls, &pl, t_end, t0, wall0, step0);
    prof_mark(s->work.prof, PROF_OUTPUT);
    if (interrupt_pending()) {
      interrupt_clear();
      if (show) progress(ls, t_end, t0, wall0, step0, 1);
      if (ls->ck_on_interrupt && ls->csv_open) {
        ckpt_write(L, simidx);
        ls->interrupted = 1;
      }
      luaL_error(L, "interrupted at step %d, t = %f", (int)s->step, s->t);
    }
  }
  if (show) progress(ls, max_steps < 0 ? t_end : s->t, t0, wall0, step0, 1);
  /* the scene's end reached: its sim:at_end functions, once per end
  ** time (a later sim:run to the same end takes no step and runs none) */
  if (ls->nat_end && s->t >= s->t_end - 1e-12 * (1 + fabs(s->t_end)) &&
      !(ls->ended == s->t_end)) {
    lua_Integer j, n;
    ls->ended = s->t_end;
    lsim_uv(L, simidx, "at_end");
    n = luaL_len(L, -1);
    for (j = 1; j <= n; j++) {
      lua_rawgeti(L, -1, j);
      lua_pushvalue(L, simidx);
      lua_call(L, 1, 0);
    }
    lua_pop(L, 1);
  }
  if (!ls->budgeted) { /* once per process, as the advice above */
    static int printed;
    const char *adv = sim_budget_advice(s);
    if (adv) {
      ls->budgeted = 1;
      warn_once(ls, &printed, adv);
    }
  }
  return 0;
}
