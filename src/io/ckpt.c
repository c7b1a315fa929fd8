/*
** ckpt.c - checkpoints of the simulation's state (the file is described
** in ckpt.h); the run's part, which lives in Lua, is lckpt.c's.
**
** One function, visit, walks every number of the state a step depends
** on; writing gathers them into named lists, applying looks each name up
** and assigns it back.  Both directions are the same code, so a number
** cannot be saved and then forgotten on restart, and a checkpoint made
** by a build or a scene with other state fails by name, not silently.
** The caller's numbers go through the same lists (ckpt_more, ckv_*).
*/
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "ckpt.h"
#include "heat.h"
#include "pcheck.h"

/* a list of named numbers, reals or integers */
typedef struct vlist {
  size_t n, cap, cur;
  char **name;            /* gathering: owned; applying: into names */
  double *r;
  int64_t *i;
  unsigned char *used;    /* applying: looked up */
  char *names;            /* applying: the '\n'-separated names, split */
} vlist;

struct ckv {
  int apply;              /* 0: gather from the state, 1: assign to it */
  vlist re, in;
  char err[512];
  int failed;
};

static void vlist_free(vlist *l, int owned) {
  size_t k;
  if (owned)
    for (k = 0; k < l->n; k++) free(l->name[k]);
  free(l->name);
  free(l->r);
  free(l->i);
  free(l->used);
  free(l->names);
  memset(l, 0, sizeof *l);
}

static int vpush(ckv *v, vlist *l, const char *name, double r, int64_t i) {
  if (l->n == l->cap) {
    size_t cap = l->cap ? 2 * l->cap : 64;
    char **nm = realloc(l->name, cap * sizeof *nm);
    double *rr;
    int64_t *ii;
    if (nm) l->name = nm;
    rr = nm ? realloc(l->r, cap * sizeof *rr) : NULL;
    if (rr) l->r = rr;
    ii = rr ? realloc(l->i, cap * sizeof *ii) : NULL;
    if (ii) l->i = ii;
    if (!ii) return ckv_fail(v, "out of memory");
    l->cap = cap;
  }
  if (!(l->name[l->n] = strdup(name))) return ckv_fail(v, "out of memory");
  l->r[l->n] = r;
  l->i[l->n] = i;
  l->n++;
  return 0;
}

/* the index of name in l: the next one in order is the usual case */
static long vfind(ckv *v, vlist *l, const char *name) {
  size_t k = l->cur;
  if (!(k < l->n && strcmp(l->name[k], name) == 0)) {
    for (k = 0; k < l->n; k++)
      if (strcmp(l->name[k], name) == 0) break;
    if (k == l->n)
      return ckv_fail(v, "it has no value '%s' (written by another version of "
                   "mvmpm, or for another scene)", name);
  }
  l->used[k] = 1;
  l->cur = k + 1;
  return (long)k;
}

/* the numbers that may be infinite: a stop never due, sticking
** friction, a bond without a cap, a time never reached */
static int may_be_inf(const char *name) {
  static const char *const end[] = {"t_stop", "t_ignition", "mu_default",
                                    "bond_default",
                                    ".mu", ".bond", "_next", ".next", NULL};
  size_t n = strlen(name), k;
  int j;
  for (j = 0; end[j]; j++)
    if (n >= (k = strlen(end[j])) && strcmp(name + n - k, end[j]) == 0)
      return 1;
  return 0;
}

static void vreal(ckv *v, const char *name, double *p) {
  long k;
  if (v->failed) return;
  if (!v->apply) { vpush(v, &v->re, name, *p, 0); return; }
  if ((k = vfind(v, &v->re, name)) < 0) return;
  if (isnan(v->re.r[k]) || (isinf(v->re.r[k]) && !may_be_inf(name)))
    ckv_fail(v, "its value '%s' in /state/real is %g, allowed: a finite "
          "number", name, v->re.r[k]);
  else *p = v->re.r[k];
}

/* a value a checkpoint may lack (added to the state after its format was
** set): def when absent, checked as vreal when present */
static void vreal_opt(ckv *v, const char *name, double *p, double def) {
  size_t k;
  if (v->failed) return;
  if (v->apply) {
    for (k = 0; k < v->re.n; k++)
      if (strcmp(v->re.name[k], name) == 0) break;
    if (k == v->re.n) { *p = def; return; }
  }
  vreal(v, name, p);
}

static void vint(ckv *v, const char *name, int64_t *p) {
  long k;
  if (v->failed) return;
  if (!v->apply) { vpush(v, &v->in, name, 0, *p); return; }
  if ((k = vfind(v, &v->in, name)) >= 0) *p = v->in.i[k];
}

#define VI(v, name, x, type)                      \
  do {                                            \
    int64_t t_ = (int64_t)(x);                    \
    vint(v, name, &t_);                           \
    (x) = (type)t_;                               \
  } while (0)

/* a count the scene fixes: the checkpoint must agree */
static void vsame(ckv *v, const char *name, int64_t have, const char *what) {
  int64_t t = have;
  vint(v, name, &t);
  if (!v->failed && t != have)
    ckv_fail(v, "it has %lld %s, the scene makes %lld", (long long)t, what,
          (long long)have);
}

static void vvec(ckv *v, const char *pre, const char *name, double *x, int n) {
  char nm[96];
  int d;
  for (d = 0; d < n; d++) {
    snprintf(nm, sizeof nm, "%s%s.%c", pre, name, "xyz"[d]);
    vreal(v, nm, &x[d]);
  }
}

/* the same lists for the caller's numbers (ckpt.h) */
int ckv_applying(const ckv *v) { return v->apply; }

int ckv_failed(const ckv *v) { return v->failed; }

int ckv_fail(ckv *v, const char *fmt, ...) {
  va_list ap;
  if (v->failed) return -1;
  v->failed = 1;
  va_start(ap, fmt);
  vsnprintf(v->err, sizeof v->err, fmt, ap);
  va_end(ap);
  return -1;
}

void ckv_real(ckv *v, const char *name, double *p) { vreal(v, name, p); }

void ckv_int(ckv *v, const char *name, int64_t *p) { vint(v, name, p); }

void ckv_same(ckv *v, const char *name, int64_t have, const char *what) {
  vsame(v, name, have, what);
}

static const char *const side_names[] = {"left", "right", "bottom", "top",
                                         "back", "front"};

static void visit_sim(ckv *v, sim *s) {
  sim_energy *e = &s->e;
  char pre[64], nm[96];
  int64_t nlaw;
  int k;
  vsame(v, "nmat", s->nmat, "materials");
  vsame(v, "nbody", s->nbody, "bodies");
  vsame(v, "nfield", s->nfield, "velocity fields");
  vsame(v, "dim", DIM, "dimensions");
  vsame(v, "transfer", s->cfg.transfer, "as its transfer (0 FLIP, 1 APIC, 2 XPIC, 3 spin)");
  VI(v, "step", s->step, long);
  VI(v, "started", s->started, int);
  vreal(v, "t", &s->t);
  vreal(v, "dt", &s->dt);
  vreal(v, "t_end", &s->t_end);
  vreal(v, "t_stop", &s->t_stop);
  vreal(v, "flip", &s->cfg.flip);
  vreal(v, "cfl", &s->cfg.cfl);
  vreal(v, "dt_fixed", &s->cfg.dt_fixed);
  vreal(v, "mu_default", &s->cfg.mu_default);
  vreal(v, "bond_default", &s->cfg.bond_default);
  VI(v, "gap_check", s->cfg.gap_check, int);
  VI(v, "sort_every", s->cfg.sort_every, int);
  vreal(v, "mcut", &s->mcut);
  vreal(v, "mcut_rel", &s->cfg.mcut_rel);
  vreal(v, "vmax", &s->vmax);
  VI(v, "nout", s->nout, size_t);
  VI(v, "nremoved", s->nremoved, size_t);
  { /* added later: a checkpoint from before has none */
    double held = (double)s->nheld;
    vreal_opt(v, "nheld", &held, 0);
    s->nheld = held >= 0 && held < 1e18 ? (size_t)held : 0;
  }
  VI(v, "ncut", s->ncut, size_t);
  VI(v, "ncut_total", s->ncut_total, size_t);
  vreal(v, "bond_area", &s->bond_area);
  VI(v, "temp_on", s->temp_on, int);
  vreal(v, "temp", &s->temp);
  VI(v, "nmade", s->ps.nmade, size_t);
  vvec(v, "", "gravity", s->cfg.gravity, DIM);
  vreal(v, "e.kinetic", &e->kinetic);
  vreal(v, "e.strain", &e->strain);
  vreal(v, "e.potential", &e->potential);
  vreal(v, "e.lag", &e->lag);
  vreal(v, "e.friction", &e->friction);
  vreal(v, "e.boundary", &e->boundary);
  vreal(v, "e.plastic", &e->plastic);
  vreal(v, "e.viscous", &e->viscous);
  vreal(v, "e.thermal", &e->thermal);
  vreal_opt(v, "e.transfer", &e->transfer, 0);
  vreal_opt(v, "e.impact", &e->impact, 0);
  vreal_opt(v, "e.bonding", &e->bonding, 0);
  vreal_opt(v, "e.cohesion", &e->cohesion, 0);
  vreal(v, "e.initial", &e->initial);
  /* newer than the format: a checkpoint without them settled nothing,
  ** and its potential's start is taken as where it was then */
  vreal_opt(v, "e.settled", &e->settled, 0);
  vreal_opt(v, "e.removed", &e->removed, 0);
  vreal_opt(v, "e.chemical", &e->chemical, 0);
  vreal_opt(v, "e.latent", &e->latent, 0);
  vreal_opt(v, "t_ignition", &s->t_ignition, INFINITY);
  vreal_opt(v, "e.potential0", &e->potential0, e->potential);
  { /* newer than the format too: a checkpoint without it wrapped nothing */
    int d;
    for (d = 0; d < DIM; d++) {
      snprintf(nm, sizeof nm, "e.wrap.%c", "xyz"[d]);
      vreal_opt(v, nm, &e->wrap[d], 0);
    }
  }
  vvec(v, "e.", "mom", e->mom, DIM);
  if (DIM == 2) vreal(v, "e.angmom", &e->angmom[2]);
  else vvec(v, "e.", "angmom", e->angmom, 3);
  vreal(v, "e.jmin", &e->jmin);
  vreal(v, "e.jmax", &e->jmax);
  VI(v, "e.nbadj", e->nbadj, size_t);
  if (s->heat) { /* heat.h: the budget's heat terms and its origin */
    vreal_opt(v, "e.heat_friction", &e->heat_friction, 0);
    vreal_opt(v, "e.heat_plastic", &e->heat_plastic, 0);
    vreal_opt(v, "e.heat_viscous", &e->heat_viscous, 0);
    vreal_opt(v, "e.heat_source", &e->heat_source, 0);
    vreal_opt(v, "e.heat_wall", &e->heat_wall, 0);
    vreal_opt(v, "e.cold", &e->cold, 0);
    vreal_opt(v, "e.heat_boundary", &e->heat_boundary, 0);
    vreal_opt(v, "e.heat_thermal", &e->heat_thermal, 0);
    vreal_opt(v, "heat.E0", &s->heat->E0, 0);
  }
  for (k = 0; k < NSIDES; k++) {
    side *sd = &s->sides[k];
    snprintf(pre, sizeof pre, "side.%s.", side_names[k]);
    snprintf(nm, sizeof nm, "%skind", pre);
    vsame(v, nm, sd->kind, "as its kind (0 free, 1 wall, 2 periodic)");
    snprintf(nm, sizeof nm, "%smu", pre);
    vreal(v, nm, &sd->mu);
    vvec(v, pre, "v", sd->v, DIM);
    vvec(v, pre, "force", sd->force, DIM);
    if (s->cfg.wall_rule == WALL_SPRING && sd->dl) { /* the springs' state */
      size_t j;
      int a;
      for (j = 0; j < sd->next && !v->failed; j++) {
        if (!v->apply && sd->dl[j] == 0) continue; /* absent reads as 0 */
        snprintf(nm, sizeof nm, "%sdl.%zu", pre, j);
        vreal_opt(v, nm, &sd->dl[j], 0);
        if (!(sd->dl[j] > 0)) continue;
        for (a = 0; a < DIM; a++) { /* its offset along the wall */
          if (a == k / 2) continue;
          snprintf(nm, sizeof nm, "%sph.%zu.%c", pre, j, "xyz"[a]);
          vreal_opt(v, nm, &sd->ph[j * DIM + a], 0);
        }
      }
    }
  }
  for (k = 0; k < s->nbody && !v->failed; k++) {
    body *b = &s->bodies[k];
    snprintf(pre, sizeof pre, "body%d.", k + 1);
    snprintf(nm, sizeof nm, "%sdriven", pre);
    vsame(v, nm, b->driven, "as its drive flag");
    vvec(v, pre, "vdrive", b->vdrive, DIM);
    vvec(v, pre, "force", b->force, DIM);
  }
  /* contact laws: a callback may add or change them */
  nlaw = s->nlaw;
  vint(v, "nlaw", &nlaw);
  if (v->apply && !v->failed) {
    if (nlaw < 0 || nlaw > 1000000) { ckv_fail(v, "it has %lld contact laws", (long long)nlaw); return; }
    s->nlaw = 0;
    memset(s->flaw, 0, (size_t)s->nfield);
  }
  for (k = 0; k < nlaw && !v->failed; k++) {
    pairlaw l = {0, 0, 0, 0};
    int64_t a, b;
    if (!v->apply) l = s->laws[k];
    a = l.a;
    b = l.b;
    snprintf(pre, sizeof pre, "law%d.", k + 1);
    snprintf(nm, sizeof nm, "%sa", pre); vint(v, nm, &a);
    snprintf(nm, sizeof nm, "%sb", pre); vint(v, nm, &b);
    snprintf(nm, sizeof nm, "%smu", pre); vreal(v, nm, &l.mu);
    snprintf(nm, sizeof nm, "%sbond", pre); vreal(v, nm, &l.bond);
    if (v->apply && !v->failed) {
      if (a < 0 || b < 0 || a >= s->nfield || b >= s->nfield || a == b)
        ckv_fail(v, "its contact law %d names fields %lld and %lld", k + 1,
              (long long)a, (long long)b);
      else if (sim_set_law(s, (int32_t)a, (int32_t)b, l.mu, l.bond))
        ckv_fail(v, "out of memory");
    }
  }
}

/*
** {======================================================
** Writing
** =======================================================
*/

/* a growing string (ckpt.h) */
void ckpt_buf_add(ckpt_buf *s, const char *p, size_t n) {
  if (s->bad) return;
  if (s->n + n + 1 > s->cap) {
    size_t cap = s->cap ? 2 * s->cap : 256;
    char *q;
    while (cap < s->n + n + 1) cap *= 2;
    if (!(q = realloc(s->b, cap))) { s->bad = 1; return; }
    s->b = q;
    s->cap = cap;
  }
  memcpy(s->b + s->n, p, n);
  s->n += n;
  s->b[s->n] = '\0';
}

static void names(ckpt_buf *s, const vlist *l) {
  size_t k;
  for (k = 0; k < l->n; k++) {
    ckpt_buf_add(s, l->name[k], strlen(l->name[k]));
    ckpt_buf_add(s, "\n", 1);
  }
}

int ckpt_syncdir(const char *dir) {
  int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC), r;
  if (fd < 0) return -1;
  r = fsync(fd);
  close(fd);
  return r;
}

void ckpt_name(char *buf, size_t len, const char *dir, int k) {
  snprintf(buf, len, "%s/checkpoint_%06d.h5", dir, k);
}

int ckpt_save(const char *path, sim *s, const ckpt_more *more, h5blob *b,
              h5meta *meta, const h5prov *prov, int nomem, char *err,
              size_t errlen) {
  ckv v;
  ckpt_buf rn = {0}, in = {0}, fl = {0};
  int k, r;
  memset(&v, 0, sizeof v);
  visit_sim(&v, s);
  if (more && more->visit) more->visit(&v, more->ud);
  names(&rn, &v.re);
  names(&in, &v.in);
  for (k = 0; k < s->ps.nfields; k++)
    if (s->ps.fields[k].flags & PF_RESTART) {
      ckpt_buf_add(&fl, s->ps.fields[k].name, strlen(s->ps.fields[k].name));
      ckpt_buf_add(&fl, "\n", 1);
    }
  if (v.failed || rn.bad || in.bad || fl.bad || nomem) {
    snprintf(err, errlen, "checkpoint: %s", v.failed ? v.err : "out of memory");
    r = -1;
  } else {
    b[CB_REALN] = (h5blob){"real_names", H5B_U8, rn.n, rn.b};
    b[CB_REAL] = (h5blob){"real", H5B_F64, v.re.n, v.re.r};
    b[CB_INTN] = (h5blob){"int_names", H5B_U8, in.n, in.b};
    b[CB_INT] = (h5blob){"int", H5B_I64, v.in.n, v.in.i};
    b[CB_FIELDS] = (h5blob){"fields", H5B_U8, fl.n, fl.b};
    meta->time = s->t;
    meta->step = s->step;
    meta->cell = s->g.h;
    r = out_h5_write_state(path, CKPT_FORMAT, &s->ps, PF_RESTART, meta,
                           prov, b, CB_N, err, errlen);
  }
  vlist_free(&v.re, 1);
  vlist_free(&v.in, 1);
  free(rn.b); free(in.b); free(fl.b);
  return r;
}

/* }====================================================== */


/*
** {======================================================
** Reading and applying
** =======================================================
*/

/* x (the value named) must lie in [lo, hi], or (lo, hi] with open */
static int vrange(ckv *v, const char *name, double x, double lo, double hi,
                  int open) {
  if (v->failed) return -1;
  if (open ? x > lo && x <= hi : x >= lo && x <= hi) return 0;
  return ckv_fail(v, "its value '%s' in /state is %.17g, allowed %c%.17g, "
               "%.17g]", name, x, open ? '(' : '[', lo, hi);
}

int ckv_range(ckv *v, const char *name, double x, double lo, double hi,
              int open) {
  return vrange(v, name, x, lo, hi, open);
}

/* the state's numbers in the ranges the engine keeps them in (finite
** already: vreal); n is the checkpoint's particle count */
static void state_ok(ckv *v, const sim *s, size_t n) {
  const double big = INFINITY, cnt = (double)INT64_MAX;
  int k;
  vrange(v, "t_end", s->t_end, 0, big, 1);
  vrange(v, "dt", s->dt, 0, big, 0);
  /* the last step ends on t_end up to rounding */
  vrange(v, "t", s->t, 0, s->t_end + s->dt, 0);
  vrange(v, "t_stop", s->t_stop, 0, big, 0);
  vrange(v, "step", (double)s->step, 0, cnt, 0);
  if (s->step > 0) vrange(v, "dt", s->dt, 0, big, 1);
  vrange(v, "started", s->started, 0, 1, 0);
  vrange(v, "flip", s->cfg.flip, 0, 1, 0);
  vrange(v, "cfl", s->cfg.cfl, 0, 1, 1);
  vrange(v, "dt_fixed", s->cfg.dt_fixed, 0, big, 0);
  vrange(v, "mu_default", s->cfg.mu_default, 0, big, 0);
  vrange(v, "bond_default", s->cfg.bond_default, 0, big, 0);
  vrange(v, "gap_check", s->cfg.gap_check, 0, 1, 0);
  vrange(v, "sort_every", s->cfg.sort_every, 0, INT32_MAX, 0);
  vrange(v, "mcut", s->mcut, 0, big, 0);
  vrange(v, "mcut_rel", s->cfg.mcut_rel, 0, big, 0);
  vrange(v, "vmax", s->vmax, 0, big, 0);
  vrange(v, "nout", (double)s->nout, 0, (double)n, 0);
  vrange(v, "nremoved", (double)s->nremoved, 0, cnt, 0);
  vrange(v, "ncut", (double)s->ncut, 0, cnt, 0);
  vrange(v, "ncut_total", (double)s->ncut_total, 0, cnt, 0);
  vrange(v, "bond_area", s->bond_area, 0, big, 0);
  vrange(v, "temp_on", s->temp_on, 0, 1, 0);
  /* ids run up to nmade, an int32 */
  vrange(v, "nmade", (double)s->ps.nmade, (double)n, INT32_MAX, 0);
  vrange(v, "e.nbadj", (double)s->e.nbadj, 0, cnt, 0);
  for (k = 0; k < NSIDES; k++)
    if (vrange(v, "side mu", s->sides[k].mu, 0, big, 0)) return;
  for (k = 0; k < s->nlaw; k++)
    if (vrange(v, "law mu", s->laws[k].mu, 0, big, 0) ||
        vrange(v, "law bond", s->laws[k].bond, 0, big, 0))
      return;
}

static const char *const blobnames[CB_N] = {"real_names", "real",
    "int_names", "int", "snap_files", "snap_time", "snap_n", "params",
    "scene", "source", "lua_state", "fields"};
static const int blobtypes[CB_N] = {H5B_U8, H5B_F64, H5B_U8, H5B_I64, H5B_U8,
    H5B_F64, H5B_I64, H5B_U8, H5B_U8, H5B_U8, H5B_U8, H5B_U8};

int ckpt_read(ckpt *c, const char *path, char *err, size_t errlen) {
  int k;
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  particles_init(&c->ps);
  for (k = 0; k < CB_N; k++) {
    c->b[k].name = blobnames[k];
    c->b[k].type = blobtypes[k];
  }
  return out_h5_read_state(path, CKPT_FORMAT, &c->ps, &c->meta, c->b, CB_N,
                           err, errlen);
}

void ckpt_free(ckpt *c) {
  int k;
  particles_free(&c->ps);
  for (k = 0; k < CB_N; k++) free(c->b[k].data);
  memset(c, 0, sizeof *c);
}

char *ckpt_string(const ckpt *c, int which) {
  char *s = malloc(c->b[which].n + 1);
  if (!s) return NULL;
  if (c->b[which].n) memcpy(s, c->b[which].data, c->b[which].n);
  s[c->b[which].n] = '\0';
  return s;
}

/* split '\n'-terminated names into a list for lookup */
static int vload(ckv *v, vlist *l, const ckpt *c, int nb, int vb, int isint) {
  size_t k = 0, cnt = c->b[vb].n;
  char *p, *q;
  l->names = ckpt_string(c, nb);
  l->name = calloc(cnt + 1, sizeof *l->name);
  l->used = calloc(cnt + 1, 1);
  if (!l->names || !l->name || !l->used) return ckv_fail(v, "out of memory");
  for (p = l->names; *p && k < cnt; p = q + 1) {
    if (!(q = strchr(p, '\n'))) break;
    *q = '\0';
    l->name[k++] = p;
  }
  if (k != cnt) return ckv_fail(v, "its lists of names and values differ in length");
  l->n = cnt;
  if (isint) l->i = malloc(cnt * 8 + 8);
  else l->r = malloc(cnt * 8 + 8);
  if (!l->i && !l->r) return ckv_fail(v, "out of memory");
  memcpy(isint ? (void *)l->i : (void *)l->r, c->b[vb].data, cnt * 8);
  return 0;
}

/* every saved value must have been asked for */
static void vleft(ckv *v, const vlist *l) {
  size_t k;
  for (k = 0; k < l->n && !v->failed; k++)
    if (!l->used[k])
      ckv_fail(v, "it has a value '%s' this scene does not make", l->name[k]);
}

/* the particle fields a checkpoint of this scene holds, in order */
static int fields_match(ckv *v, const sim *s, const ckpt *c) {
  ckpt_buf fl = {0};
  int k, r = 0;
  for (k = 0; k < s->ps.nfields; k++)
    if (s->ps.fields[k].flags & PF_RESTART) {
      const pfield *f = &s->ps.fields[k];
      int j = particles_find(&c->ps, f->name);
      ckpt_buf_add(&fl, f->name, strlen(f->name));
      ckpt_buf_add(&fl, "\n", 1);
      if (j < 0 || !(c->ps.fields[j].flags & PF_READ))
        r = ckv_fail(v, "it has no dataset '%s' (a particle field of this "
                  "scene)", f->name);
      else if (c->ps.fields[j].type != f->type ||
               c->ps.fields[j].ncomp != f->ncomp)
        r = ckv_fail(v, "its dataset '%s' is of another shape or type than "
                  "the particle field", f->name);
    }
  if (!r && (fl.bad || fl.n != c->b[CB_FIELDS].n ||
             memcmp(fl.b, c->b[CB_FIELDS].data, fl.n) != 0))
    r = ckv_fail(v, "it holds other particle fields than this scene makes "
              "(scene: %s; checkpoint: %.*s)", fl.b ? fl.b : "",
              (int)c->b[CB_FIELDS].n, (const char *)c->b[CB_FIELDS].data);
  free(fl.b);
  return r;
}

static int copy_particles(ckv *v, sim *s, const ckpt *c) {
  particles *ps = &s->ps;
  size_t n = c->ps.n;
  int k, comp;
  if (particles_reserve(ps, n ? n : 1)) return ckv_fail(v, "out of memory");
  for (k = 0; k < ps->nfields; k++) {
    const pfield *f = &ps->fields[k];
    int j = particles_find(&c->ps, f->name);
    size_t esz = f->type == PF_INT32 ? 4 : 8;
    if (!(f->flags & PF_RESTART)) continue;
    for (comp = 0; comp < f->ncomp; comp++)
      memcpy(particles_comp(ps, k, comp), particles_comp(&c->ps, j, comp),
             n * esz);
  }
  ps->n = n;
  return 0;
}

int ckpt_restore(sim *s, const ckpt *c, const ckpt_more *more, char *err,
                 size_t errlen) {
  ckv v;
  memset(&v, 0, sizeof v);
  v.apply = 1;
  if (vload(&v, &v.re, c, CB_REALN, CB_REAL, 0) == 0 &&
      vload(&v, &v.in, c, CB_INTN, CB_INT, 1) == 0 &&
      fields_match(&v, s, c) == 0) {
    visit_sim(&v, s);
    if (more && more->visit) more->visit(&v, more->ud);
    vleft(&v, &v.re);
    vleft(&v, &v.in);
    state_ok(&v, s, c->ps.n);
    if (more && more->check) more->check(&v, more->ud);
  }
  if (!v.failed) {
    pcheck_lim lim;
    int d;
    memset(&lim, 0, sizeof lim);
    lim.nbody = s->nbody;
    lim.nmade = s->ps.nmade;
    lim.domain = 1;
    lim.h = s->g.h;
    for (d = 0; d < DIM; d++) {
      lim.lo[d] = s->g.lo[d];
      lim.hi[d] = s->g.hi[d];
      lim.cells[d] = s->g.cells[d];
    }
    if (pcheck_particles(c->path, &c->ps, &lim, v.err, sizeof v.err)) {
      vlist_free(&v.re, 0);
      vlist_free(&v.in, 0);
      snprintf(err, errlen, "%s", v.err);
      return -1;
    }
  }
  if (!v.failed) copy_particles(&v, s, c);
  vlist_free(&v.re, 0);
  vlist_free(&v.in, 0);
  if (v.failed) {
    snprintf(err, errlen, "%s: cannot continue this scene from it: %s",
             c->path, v.err);
    return -1;
  }
  return 0;
}

int ckpt_sandboxed(const ckpt *c) {
  const char *p = c->b[CB_INTN].data, *end = p ? p + c->b[CB_INTN].n : p;
  size_t k;
  static const char name[] = "run.sandbox\n";
  for (k = 0; p && p < end && k < c->b[CB_INT].n; k++) {
    const char *nl = memchr(p, '\n', (size_t)(end - p));
    if (!nl) break;
    if ((size_t)(nl + 1 - p) == sizeof name - 1 &&
        memcmp(p, name, sizeof name - 1) == 0)
      return ((const int64_t *)c->b[CB_INT].data)[k] != 0;
    p = nl + 1;
  }
  return -1;
}

int ckpt_latest(const char *dir, char *out, size_t len, char *err,
                size_t errlen) {
  DIR *d = opendir(dir);
  struct dirent *de;
  int best = -1;
  if (!d) {
    snprintf(err, errlen, "%s: cannot open directory (%s)", dir, strerror(errno));
    return -1;
  }
  while ((de = readdir(d))) {
    int k, used = 0;
    if (strlen(de->d_name) == 20 &&
        sscanf(de->d_name, "checkpoint_%6d.h5%n", &k, &used) == 1 &&
        used == 20 && k > best)
      best = k;
  }
  closedir(d);
  if (best < 0) {
    snprintf(err, errlen, "%s: no checkpoint_NNNNNN.h5 in this directory", dir);
    return -1;
  }
  ckpt_name(out, len, dir, best);
  return 0;
}

/* }====================================================== */
