/*
** lua_body.c - bodies: seeding particles from shapes or point lists,
** and the body object's diagnostics.
**
** Seeding: every cell holds ppc^DIM points at the centres of its
** sub-cells; a body takes the points inside its shape.  One lattice for
** all bodies means "the rest" (binder) is simply the points no body
** took, and overlapping bodies are detected exactly.  Each point has
** its sub-cell's measure, or with volume = "cut" the shape's measure
** near it (seed_cut), the rest then taking what cut bodies leave
** (rest_cut).
**
** A body may instead be seeded on a lattice of its own, of the same
** spacing turned by an angle about z (sim:body's lattice): a face tilted
** to the grid is then a straight row of particles, not a staircase of
** the grid's lattice, whose steps turn the contact normals (a block
** sliding on a face tilted 15 or 22 degrees with friction, 8 cells per
** side, quadratic B-splines, "plane"/4 normals with the patch: 4.4 and
** 6.1 % slow on the grid's lattice, 2.7 % fast and 2.4 % slow on the
** bodies' own).  Such
** a body still takes the grid lattice's points inside its shape, so that
** "the rest" and later bodies see it.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "diag.h"
#include "interrupt.h"
#include "lcheck.h"
#include "lsim.h"
#include "melt.h"
#include "react.h"
#include "thermal.h"

/* a body whose simulation is open: its arrays are the body's memory */
static lbody *checkbody(lua_State *L, int idx) {
  lbody *lb = luaL_checkudata(L, idx, LBODY_MT);
  if (lb->ls->closed)
    luaL_error(L, "body %d: its simulation was closed (its memory is "
                  "released): the body cannot be used any more", lb->idx + 1);
  return lb;
}

lbody *lbody_check(lua_State *L, int idx, const lsim *ls, const char *what) {
  lbody *lb = checkbody(L, idx);
  /* its index means nothing in another simulation's arrays */
  if (lb->ls != ls)
    luaL_error(L, "%s: body '%s' belongs to another simulation", what,
               lb->ls->s.bodies[lb->idx].name);
  return lb;
}

static int occ_init(lua_State *L, lsim *ls) {
  size_t n = 1, k;
  int d;
  if (ls->occ) return 0;
  for (d = 0; d < DIM; d++) n *= (size_t)ls->s.g.cells[d] * ls->s.cfg.ppc;
  ls->occ = malloc(n * sizeof *ls->occ);
  ls->claim = calloc(n, sizeof *ls->claim);
  if (!ls->occ || !ls->claim) {
    free(ls->occ);
    free(ls->claim);
    ls->occ = NULL;
    ls->claim = NULL;
    return luaL_error(L, "body: out of memory for the seeding lattice");
  }
  for (k = 0; k < n; k++) ls->occ[k] = -1;
  ls->nocc = n;
  return 0;
}

/* material userdata at idx -> index in the simulation (added on first use) */
static int matindex(lua_State *L, int simidx, int idx) {
  lsim *ls = lsim_check(L, simidx);
  material *m = lmat_check(L, idx);
  int k;
  lsim_uv(L, simidx, "mats");
  lua_pushvalue(L, idx);
  if (lua_rawget(L, -2) == LUA_TNUMBER) {
    k = (int)lua_tointeger(L, -1);
    lua_pop(L, 2);
    return k;
  }
  lua_pop(L, 1);
  k = sim_add_material(&ls->s, m);
  if (k < 0) luaL_error(L, "body: %s", ls->s.err);
  lua_pushvalue(L, idx);
  lua_pushinteger(L, k);
  lua_rawset(L, -3);
  lua_pop(L, 1);
  return k;
}

/* field for the body: shared by name, or a new one */
/* field for the body: shared by name, or a new one.  fields = "single"
** puts every body that names no field on one shared field, except driven
** bodies: a drive moves its whole field, so a driven body always has a
** field of its own and meets the others through contact */
static int32_t fieldof(lua_State *L, int simidx, lsim *ls, int driven) {
  int32_t f;
  lua_getfield(L, 2, "field");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    if (!ls->fields_single || driven) return -1;
    lua_pushstring(L, "(all bodies)");
  } else if (lua_type(L, -1) != LUA_TSTRING)
    luaL_error(L, "body: field 'field' must be a name (string) shared by the "
                  "bodies that move as one velocity field");
  lsim_uv(L, simidx, "fieldnames");
  lua_pushvalue(L, -2);
  if (lua_rawget(L, -2) == LUA_TNUMBER) {
    f = (int32_t)lua_tointeger(L, -1);
    if (driven || ls->s.fdriven[f] >= 0)
      luaL_error(L, "body: a driven body moves its whole velocity field, so it "
                    "cannot share field '%s' with another body",
                 lua_tostring(L, -3));
    lua_pop(L, 3);
    return f;
  }
  lua_pop(L, 1);
  f = ls->s.nfield;
  lua_pushvalue(L, -2);
  lua_pushinteger(L, f);
  lua_rawset(L, -3);
  lua_pop(L, 2);
  return f;
}

typedef struct seed {
  double *x;    /* DIM per point */
  double *vol;
  size_t n, cap;
  /* volume = "cut": the points whose sub-cells hold slivers of the shape
  ** given to a neighbour, and how much (occ indices) */
  size_t *ck;
  double *cv;
  size_t nc, ccap;
} seed;

static void seed_claim(lua_State *L, seed *sd, size_t k, double v) {
  if (sd->nc == sd->ccap) {
    size_t cap = sd->ccap ? 2 * sd->ccap : 256;
    size_t *a = realloc(sd->ck, cap * sizeof *a);
    double *b;
    if (!a) luaL_error(L, "body: out of memory while seeding");
    sd->ck = a;
    b = realloc(sd->cv, cap * sizeof *b);
    if (!b) luaL_error(L, "body: out of memory while seeding");
    sd->cv = b;
    sd->ccap = cap;
  }
  sd->ck[sd->nc] = k;
  sd->cv[sd->nc++] = v;
}

static void seed_push(lua_State *L, seed *sd, const double *x, double vol) {
  int d;
  if (sd->n == sd->cap) {
    size_t cap = sd->cap ? 2 * sd->cap : 256;
    double *a = realloc(sd->x, cap * DIM * sizeof *a);
    double *b = a ? realloc(sd->vol, cap * sizeof *b) : NULL;
    if (!a || !b) {
      free(a ? a : sd->x);
      free(sd->vol);
      sd->x = sd->vol = NULL;
      luaL_error(L, "body: out of memory while seeding");
    }
    sd->x = a;
    sd->vol = b;
    sd->cap = cap;
  }
  for (d = 0; d < DIM; d++) sd->x[DIM * sd->n + d] = x[d];
  sd->vol[sd->n++] = vol;
}

/* the body being seeded (its name on the stack's top) meets body
** 'other' at x */
static void overlap_error(lua_State *L, const lsim *ls, int32_t other,
                          const double *x) {
  char pt[CHK_PTLEN];
  chk_error(L, "body '%s' overlaps body '%s' at %s; move it, or "
               "give overlap = \"skip\" to seed only the free points",
            lua_tostring(L, -1), ls->s.bodies[other].name, chk_pt(pt, x));
}

/* the lattice range [i0, i1) of shape sh, and the lattice's size N.
** Along a periodic dimension the range is not clipped but wrapped: a
** shape across the seam seeds its image on the far side (at most one
** period of it) */
static void shape_range(const lsim *ls, const lshape *sh, int N[DIM],
                        int i0[DIM], int i1[DIM]) {
  const grid *g = &ls->s.g;
  double hp = g->h / ls->s.cfg.ppc;
  int d;
  for (d = 0; d < DIM; d++) {
    double a = (sh->lo[d] - g->lo[d]) / hp - 1, b = (sh->hi[d] - g->lo[d]) / hp + 1;
    N[d] = g->cells[d] * ls->s.cfg.ppc;
    if (g->periodic[d] && !(isfinite(a) && isfinite(b))) {
      /* unbounded (rest): one period; casting an infinity to int is
      ** undefined, and on x86 gave an empty range */
      i0[d] = 0;
      i1[d] = N[d];
    } else if (g->periodic[d]) {
      i0[d] = (int)floor(a);
      i1[d] = (int)ceil(b);
      /* a shape spanning the whole period: one period from its first
      ** lattice point (from i0 the window lost the last row) */
      if (i1[d] - i0[d] > N[d]) {
        i0[d] = (int)ceil((sh->lo[d] - g->lo[d]) / hp - 0.5);
        i1[d] = i0[d] + N[d];
      }
    } else {
      i0[d] = a < 0 ? 0 : a > N[d] ? N[d] : (int)a;
      i1[d] = b > N[d] ? N[d] : b < 0 ? 0 : (int)b;
    }
  }
}

/* lattice points of the shape at index 'shidx' */
static void seed_shape(lua_State *L, lsim *ls, int shidx, int skip_taken,
                       int push, seed *sd, size_t **taken, size_t *ntaken) {
  const grid *g = &ls->s.g;
  lshape *sh = lshape_check(L, shidx);
  int ppc = ls->s.cfg.ppc, N[DIM], i0[DIM], i1[DIM], ix[DIM], iw[DIM], d;
  double hp = g->h / ppc, vol = pow(hp, DIM), x[DIM];
  size_t cap = 0;
  shape_range(ls, sh, N, i0, i1);
  /* an odometer over the lattice range, x fastest, then y (then z): the
  ** order, and so the particle numbers, of the 2-D double loop */
  for (d = 0; d < DIM; d++)
    if (i1[d] <= i0[d]) return;
  for (d = 0; d < DIM; d++) ix[d] = i0[d];
  for (;;) {
    size_t k = 0, stride = 1;
    int in;
    /* a large lattice takes a while: Ctrl-C is heard per row */
    if (ix[0] == i0[0] && interrupt_pending()) {
      interrupt_clear();
      luaL_error(L, "interrupted while seeding body '%s'", lua_tostring(L, -1));
    }
    /* the shape is tested where it is; the particle goes to the image */
    for (d = 0; d < DIM; d++) {
      iw[d] = ((ix[d] % N[d]) + N[d]) % N[d];
      k += (size_t)iw[d] * stride;
      stride *= (size_t)N[d];
      x[d] = g->lo[d] + (ix[d] + 0.5) * hp;
    }
    in = lshape_inside(L, shidx, sh, x);
    if (in) {
      for (d = 0; d < DIM; d++) x[d] = g->lo[d] + (iw[d] + 0.5) * hp;
      if (ls->occ[k] >= 0 && !skip_taken) overlap_error(L, ls, ls->occ[k], x);
      if (ls->occ[k] < 0) {
        if (*ntaken == cap) {
          size_t *p;
          cap = cap ? 2 * cap : 256;
          p = realloc(*taken, cap * sizeof *p);
          if (!p) luaL_error(L, "body: out of memory while seeding");
          *taken = p;
        }
        (*taken)[(*ntaken)++] = k;
        if (push) seed_push(L, sd, x, vol);
      }
    }
    for (d = 0; d < DIM && ++ix[d] == i1[d]; d++) ix[d] = i0[d];
    if (d == DIM) break;
  }
}

/* volume = "cut": each particle takes the measure of the shape inside
** its sub-cell, and the shape's slivers in the sub-cells whose centres
** lie outside it (no particle there) go to the nearest particles of the
** body, so that the body's mass is the shape's and sits where the
** shape's does.  Counting lattice points instead gives a disc 8 cells
** across (ppc 2) 3.5 % too much mass, all at its rim, and a polar
** inertia of 0.519 m R^2 (the disc's: 0.5): a rigid disc so built rolls
** 1.2 % slower and spins 3.7 % less under an impulse.  Cut: the mass to
** 1e-4, 0.503 m R^2.  The measures are counted on a sub-lattice of CUT_N
** points per axis in each sub-cell of the body whose corners are not all
** inside (one whose corners and centre are is taken whole) and in each
** sub-cell beside a particle of the body whose centre is outside. */
#define CUT_N (DIM == 2 ? 16 : 8)
/* The measures are summed as integers, in CUT_U-ths of a sample (a
** sample shared by 2 or 3 particles at the same distance is split
** exactly), so that a symmetric shape's particles get symmetric volumes
** to the bit, whatever the order of the sums. */
#define CUT_U 840
#define CUT_SITE ((long long)CUT_U * (DIM == 2 ? CUT_N * CUT_N : CUT_N * CUT_N * CUT_N))

/* the body's particle at site ix + o of the shape's range (sizes w,
** map from seed_cut), or -1: none there, or the site outside the range */
static int32_t range_at(const int32_t *map, const int w[DIM], const int ix[DIM],
                        const int o[DIM]) {
  size_t at = 0, stride = 1;
  int d;
  for (d = 0; d < DIM; d++) {
    int i = ix[d] + o[d];
    if (i < 0 || i >= w[d]) return -1;
    at += (size_t)i * stride;
    stride *= (size_t)w[d];
  }
  return map[at];
}

/* the next of the 3^DIM offsets o in {-1, 0, 1}^DIM; 0 after the last */
static int offset_next(int o[DIM]) {
  int d;
  for (d = 0; d < DIM && ++o[d] == 2; d++) o[d] = -1;
  return d < DIM;
}

/* A sample of a sub-cell without a particle of the body (site ix of the
** shape's range, of sizes w; sample s0 of CUT_N per axis) goes to the
** body's nearest particles beside it, shared equally between those at
** the same distance: taking the first found would turn a symmetric shape
** lopsided (a ball seeded so gained a spin of 2e-3 striking its mirror
** image).  Distances in sample units, exact integers.  Returns the
** measure given. */
static long long sliver(const int32_t *map, const int w[DIM], const int ix[DIM],
                        const int s0[DIM], long long *got) {
  long best = -1;
  int o[DIM], d, nb = 0;
  int32_t near[1 << (2 * DIM)];
  for (d = 0; d < DIM; d++) o[d] = -1;
  do {
    int32_t p = range_at(map, w, ix, o);
    long r2 = 0;
    for (d = 0; d < DIM; d++) {
      /* twice the offset from the neighbour's centre, in samples */
      long e = 2 * (long)s0[d] + 1 - (long)CUT_N * (2 * o[d] + 1);
      r2 += e * e;
    }
    if (p >= 0 && (best < 0 || r2 <= best)) {
      if (r2 < best || best < 0) nb = 0;
      best = r2;
      near[nb++] = p;
    }
  } while (offset_next(o));
  for (d = 0; d < nb; d++) got[near[d]] += CUT_U / nb;
  return nb ? CUT_U : 0;
}

/* whether site ix of the range (sizes w) has a particle of the body
** beside it */
static int beside(const int32_t *map, const int w[DIM], const int ix[DIM]) {
  int o[DIM], d;
  for (d = 0; d < DIM; d++) o[d] = -1;
  do
    if (range_at(map, w, ix, o) >= 0) return 1;
  while (offset_next(o));
  return 0;
}

static void seed_cut(lua_State *L, lsim *ls, int shidx, seed *sd, size_t n0) {
  const grid *g = &ls->s.g;
  lshape *sh = lshape_check(L, shidx);
  int N[DIM], i0[DIM], i1[DIM], w[DIM], ix[DIM], d, c;
  double hp = g->h / ls->s.cfg.ppc, sub = 1.0 / CUT_N;
  double vu = pow(hp * sub, DIM) / CUT_U; /* one unit's measure */
  size_t nsite = 1, p, np = sd->n - n0, k;
  int32_t *map;
  long long *got; /* in units of a sample's measure / CUT_U */
  shape_range(ls, sh, N, i0, i1);
  for (d = 0; d < DIM; d++) {
    w[d] = i1[d] - i0[d];
    nsite *= (size_t)w[d];
  }
  /* collected memory: a shape function may raise an error on the way */
  map = lua_newuserdatauv(L, nsite * sizeof *map, 0);
  got = lua_newuserdatauv(L, (np ? np : 1) * sizeof *got, 0);
  for (k = 0; k < nsite; k++) map[k] = -1;
  for (p = 0; p < np; p++) { /* the body's particles, by site */
    size_t at = 0, stride = 1;
    got[p] = 0;
    for (d = 0; d < DIM; d++) {
      int iw = (int)floor((sd->x[DIM * (n0 + p) + d] - g->lo[d]) / hp), i;
      i = iw;
      if (g->periodic[d]) /* the image's site in the shape's range */
        i = i0[d] + ((((iw - i0[d]) % N[d]) + N[d]) % N[d]);
      at += (size_t)(i - i0[d]) * stride;
      stride *= (size_t)w[d];
    }
    map[at] = (int32_t)p;
  }
  for (d = 0; d < DIM; d++) ix[d] = 0;
  for (k = 0; k < nsite; k++) {
    double lo[DIM], x[DIM];
    int32_t own = map[k];
    int whole = 0, s0[DIM], e;
    long long given = 0; /* what the body takes of this sub-cell */
    for (d = 0; d < DIM; d++) lo[d] = g->lo[d] + (i0[d] + ix[d]) * hp;
    /* the centre as seed_shape tested it, to the bit: on a shape's edge
    ** (a triangle's side through lattice points) the test could go
    ** either way */
    for (d = 0; d < DIM; d++) x[d] = g->lo[d] + (i0[d] + ix[d] + 0.5) * hp;
    c = lshape_inside(L, shidx, sh, x);
    /* a site whose centre is inside but holds no particle of this body
    ** is another body's (or an overlap skipped): none of it is ours; one
    ** whose centre is outside is searched for slivers where a particle
    ** of the body is beside it, whether or not a corner is inside (the
    ** tip of an acute corner may cross a sub-cell between its corners:
    ** a triangle cut at 20 cells lost 0.6 % of its area so) */
    if (own < 0 ? c || !beside(map, w, ix) : 0) {
      for (d = 0; d < DIM && ++ix[d] == w[d]; d++) ix[d] = 0;
      continue;
    }
    if (own >= 0 && c) { /* its corners all inside: taken whole */
      whole = 1;
      for (e = 0; e < (1 << DIM) && whole; e++) {
        for (d = 0; d < DIM; d++) x[d] = lo[d] + ((e >> d) & 1) * hp;
        whole = lshape_inside(L, shidx, sh, x);
      }
    }
    if (whole) {
      got[own] += CUT_SITE;
      given = CUT_SITE;
    } else {
      for (d = 0; d < DIM; d++) s0[d] = 0;
      for (;;) { /* the sub-lattice of the site */
        for (d = 0; d < DIM; d++) x[d] = lo[d] + (s0[d] + 0.5) * sub * hp;
        if (lshape_inside(L, shidx, sh, x)) {
          if (own >= 0) {
            got[own] += CUT_U;
            given += CUT_U;
          } else /* a sliver: the nearest particles beside it */
            given += sliver(map, w, ix, s0, got);
        }
        for (e = 0; e < DIM && ++s0[e] == CUT_N; e++) s0[e] = 0;
        if (e == DIM) break;
      }
    }
    if (given > 0) { /* the rest, seeded later, takes what is left */
      size_t kg = 0, stride = 1;
      for (d = 0; d < DIM; d++) {
        int i = i0[d] + ix[d];
        if (g->periodic[d]) i = ((i % N[d]) + N[d]) % N[d];
        kg += (size_t)i * stride;
        stride *= (size_t)N[d];
      }
      seed_claim(L, sd, kg, (double)given);
    }
    for (d = 0; d < DIM && ++ix[d] == w[d]; d++) ix[d] = 0;
  }
  /* a particle whose sub-cell the shape barely enters keeps one
  ** sample's measure: no particle is left without mass */
  for (p = 0; p < np; p++)
    sd->vol[n0 + p] = (double)(got[p] > CUT_U ? got[p] : CUT_U) * vu;
  lua_pop(L, 2);
}

/* The rest (mvmpm.rest()) around bodies seeded with cut volumes: what
** they took of its sub-cells (their slivers, ls->claim) is not its, and
** what they left of theirs (the part of a body's edge sub-cell outside
** its shape) goes to the rest's nearest particle beside it, so that the
** bodies and the rest fill the domain's measure.  sd holds the rest's
** points, taken their sites, in order. */
static void rest_cut(lua_State *L, lsim *ls, seed *sd, const size_t *taken) {
  const grid *g = &ls->s.g;
  int N[DIM], d;
  double hp = g->h / ls->s.cfg.ppc, vu = pow(hp / CUT_N, DIM) / CUT_U;
  size_t k, p;
  int32_t *map = lua_newuserdatauv(L, ls->nocc * sizeof *map, 0);
  /* the rest's measures, in units (seed_cut's) */
  long long *u = lua_newuserdatauv(L, (sd->n ? sd->n : 1) * sizeof *u, 0);
  for (d = 0; d < DIM; d++) N[d] = g->cells[d] * ls->s.cfg.ppc;
  for (k = 0; k < ls->nocc; k++) map[k] = -1;
  for (p = 0; p < sd->n; p++) {
    u[p] = CUT_SITE - (long long)ls->claim[taken[p]];
    map[taken[p]] = (int32_t)p;
  }
  for (k = 0; k < ls->nocc; k++) {
    long long left = CUT_SITE - (long long)ls->claim[k];
    int best = DIM + 1; /* squared offsets are at most DIM */
    int ix[DIM], o[DIM];
    size_t r = k;
    int32_t near[1 << (2 * DIM)];
    int nb = 0;
    /* a cut body's sub-cell (the claim holds its share) with room left */
    if (ls->occ[k] < 0 || !(ls->claim[k] > 0) || left < CUT_U) continue;
    for (d = 0; d < DIM; d++) {
      ix[d] = (int)(r % (size_t)N[d]);
      r /= (size_t)N[d];
      o[d] = -1;
    }
    for (;;) { /* the nearest of the rest's particles beside it */
      size_t at = 0, stride = 1;
      int ok = 1, n2 = 0;
      for (d = 0; d < DIM; d++) {
        int i = ix[d] + o[d];
        if (g->periodic[d]) i = ((i % N[d]) + N[d]) % N[d];
        else if (i < 0 || i >= N[d]) ok = 0;
        at += (size_t)i * stride;
        stride *= (size_t)N[d];
        n2 += o[d] * o[d];
      }
      if (ok && n2 > 0 && map[at] >= 0 && n2 <= best) {
        if (n2 < best) nb = 0;
        best = n2;
        near[nb++] = map[at];
      }
      if (!offset_next(o)) break;
    }
    /* split in whole units: what does not divide stays with the first */
    for (d = 0; d < nb; d++) u[near[d]] += left / nb + (d == 0 ? left % nb : 0);
  }
  for (p = 0; p < sd->n; p++) /* the others keep the sub-cell's measure */
    if (u[p] != CUT_SITE) sd->vol[p] = (double)(u[p] > CUT_U ? u[p] : CUT_U) * vu;
  lua_pop(L, 2);
}

/* a lattice turned by an angle about z, through the point o: lattice
** point (a, b[, z]) is at o + (ca a - sa b, sa a + ca b[, z]) */
typedef struct turned {
  double ca, sa, o[DIM];
} turned;

/* the grid lattice's site (occ index) whose sub-cell holds x, and its
** centre */
static size_t site_of(const lsim *ls, const double *x, double *xc) {
  const grid *g = &ls->s.g;
  int ppc = ls->s.cfg.ppc, d;
  double hp = g->h / ppc;
  size_t k = 0, stride = 1;
  for (d = 0; d < DIM; d++) {
    int n = g->cells[d] * ppc, i = (int)floor((x[d] - g->lo[d]) / hp);
    if (g->periodic[d]) i = ((i % n) + n) % n;
    else if (i < 0) i = 0;
    else if (i >= n) i = n - 1;
    xc[d] = g->lo[d] + (i + 0.5) * hp;
    k += (size_t)i * stride;
    stride *= (size_t)n;
  }
  return k;
}

/* The points of the shape at shidx on the turned lattice lt, in lattice
** order (a fastest, then b, then z).  A point is an overlap where the
** grid lattice's site holding it belongs to an earlier body and that
** site's centre lies inside this shape too (at a shared face the site
** may hold points of both, and is no overlap). */
static void seed_turned(lua_State *L, lsim *ls, int shidx, int skip_taken,
                        const turned *lt, seed *sd) {
  const grid *g = &ls->s.g;
  lshape *sh = lshape_check(L, shidx);
  double hp = g->h / ls->s.cfg.ppc, vol = pow(hp, DIM), lo[DIM], hi[DIM];
  int i0[DIM], i1[DIM], ix[DIM], c, d;
  /* the shape's box, clipped to the domain but along a periodic axis
  ** (z only: lattice_spec refuses periodic x and y), where the shape is
  ** tested where it is and its points go to their images */
  for (d = 0; d < DIM; d++) {
    lo[d] = sh->lo[d];
    hi[d] = sh->hi[d];
    if (!g->periodic[d]) {
      if (lo[d] < g->lo[d]) lo[d] = g->lo[d];
      if (hi[d] > g->hi[d]) hi[d] = g->hi[d];
    } else if (!(isfinite(lo[d]) && isfinite(hi[d]))) {
      lo[d] = g->lo[d];
      hi[d] = g->hi[d];
    }
    if (!(hi[d] > lo[d])) return;
  }
  /* the box's corners in the lattice's frame give its index range */
  for (d = 0; d < 2; d++) {
    i0[d] = INT32_MAX;
    i1[d] = INT32_MIN;
  }
  for (c = 0; c < 4; c++) {
    double dx = ((c & 1) ? hi[0] : lo[0]) - lt->o[0];
    double dy = ((c & 2) ? hi[1] : lo[1]) - lt->o[1];
    double ab[2];
    ab[0] = (lt->ca * dx + lt->sa * dy) / hp;
    ab[1] = (-lt->sa * dx + lt->ca * dy) / hp;
    for (d = 0; d < 2; d++) {
      int a = (int)floor(ab[d]) - 1, b = (int)ceil(ab[d]) + 1;
      if (a < i0[d]) i0[d] = a;
      if (b > i1[d]) i1[d] = b;
    }
  }
  for (d = 2; d < DIM; d++) {
    int n = g->cells[d] * ls->s.cfg.ppc;
    i0[d] = (int)floor((lo[d] - lt->o[d]) / hp) - 1;
    i1[d] = (int)ceil((hi[d] - lt->o[d]) / hp) + 1;
    /* at most one period's points: each image once */
    if (g->periodic[d] && i1[d] - i0[d] > n) {
      i0[d] = (int)ceil((lo[d] - lt->o[d]) / hp - 0.5);
      i1[d] = i0[d] + n;
    }
  }
  for (d = 0; d < DIM; d++) ix[d] = i0[d];
  for (;;) {
    double x[DIM], xc[DIM], a = (ix[0] + 0.5) * hp, b = (ix[1] + 0.5) * hp;
    int in = 1;
    if (ix[0] == i0[0] && interrupt_pending()) {
      interrupt_clear();
      luaL_error(L, "interrupted while seeding body '%s'", lua_tostring(L, -1));
    }
    x[0] = lt->o[0] + lt->ca * a - lt->sa * b;
    x[1] = lt->o[1] + lt->sa * a + lt->ca * b;
    for (d = 2; d < DIM; d++) x[d] = lt->o[d] + (ix[d] + 0.5) * hp;
    for (d = 0; d < DIM && in; d++)
      in = g->periodic[d] || (x[d] >= g->lo[d] && x[d] < g->hi[d]);
    if (in && lshape_inside(L, shidx, sh, x)) {
      double shift[DIM];
      size_t k;
      for (d = 0; d < DIM; d++) { /* to the image in the domain */
        double L0 = g->hi[d] - g->lo[d];
        shift[d] = g->periodic[d] ? L0 * floor((x[d] - g->lo[d]) / L0) : 0;
        x[d] -= shift[d];
      }
      k = site_of(ls, x, xc);
      /* the site's centre tested where the shape is, as the point was */
      for (d = 0; d < DIM; d++) xc[d] += shift[d];
      if (!(ls->occ[k] >= 0 && lshape_inside(L, shidx, sh, xc)))
        seed_push(L, sd, x, vol);
      else if (!skip_taken)
        overlap_error(L, ls, ls->occ[k], x);
    }
    for (d = 0; d < DIM && ++ix[d] == i1[d]; d++) ix[d] = i0[d];
    if (d == DIM) break;
  }
}

/* sim:body's lattice = {angle = degrees, origin = {x, y[, z]}}: 0 if
** absent, else 1 with lt filled */
static int lattice_spec(lua_State *L, lsim *ls, const char *name, turned *lt) {
  static const char *const keys[] = {"angle", "origin", NULL};
  const grid *g = &ls->s.g;
  double deg;
  int d;
  lua_getfield(L, 2, "lattice");
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return 0; }
  if (!lua_istable(L, -1))
    luaL_error(L, "body '%s': field 'lattice' must be a table {angle = "
                  "degrees, origin = {x, y%s}} (got %s)", name,
               DIM == 3 ? ", z" : "", luaL_typename(L, -1));
  chk_keys(L, -1, "body: lattice", keys);
  deg = chk_num(L, -1, "body: lattice", "angle", 0, -360, 360, CHK_REQUIRED);
  for (d = 0; d < DIM; d++) lt->o[d] = g->lo[d];
  chk_vec(L, -1, "body: lattice", "origin", lt->o, DIM, 0);
  lua_pop(L, 1);
  for (d = 0; d < 2; d++)
    if (g->periodic[d])
      luaL_error(L, "body '%s': field 'lattice': a lattice of the body's own "
                    "does not repeat across the periodic sides in %c; seed "
                    "on the grid's lattice (leave 'lattice' out)", name, "xy"[d]);
  lt->ca = cos(deg * M_PI / 180);
  lt->sa = sin(deg * M_PI / 180);
  return 1;
}

static void seed_points(lua_State *L, lsim *ls, seed *sd) {
  double hp = ls->s.g.h / ls->s.cfg.ppc, vdef = pow(hp, DIM);
  const char *const names[] = {"x", "y", "z"};
  lua_Integer n = -1, k;
  int d, tv;
  for (d = 0; d < DIM; d++) {
    lua_getfield(L, -1 - d, names[d]);
    if (!lua_istable(L, -1))
      luaL_error(L, "body: points.%s must be a list of numbers", names[d]);
    if (n < 0) n = luaL_len(L, -1);
    else if (luaL_len(L, -1) != n)
      luaL_error(L, "body: points.x and points.%s differ in length", names[d]);
  }
  lua_getfield(L, -1 - DIM, "volume");
  tv = lua_type(L, -1);
  if (tv == LUA_TNUMBER) vdef = lua_tonumber(L, -1); /* checked below */
  else if (tv != LUA_TNIL && tv != LUA_TTABLE)
    luaL_error(L, "body: points.volume must be a number or a list");
  /* stack: points, x, y, volume */
  for (k = 1; k <= n; k++) {
    double x[DIM], vol = vdef;
    for (d = 0; d < DIM; d++) {
      int isnum;
      lua_geti(L, -1 - DIM + d, k);
      x[d] = lua_tonumberx(L, -1, &isnum);
      if (!isnum || !isfinite(x[d]))
        luaL_error(L, "body: points.%s[%d] must be a finite number", names[d],
                   (int)k);
      lua_pop(L, 1);
    }
    if (tv == LUA_TTABLE) {
      lua_geti(L, -1, k);
      vol = lua_tonumber(L, -1);
      lua_pop(L, 1);
    }
    if (!(vol > 0) || !isfinite(vol))
      chk_error(L, "body: point %d has volume %g; volumes must be finite and > 0", (int)k,
                 vol);
    for (d = 0; d < DIM; d++)
      if (x[d] < ls->s.g.lo[d] || x[d] >= ls->s.g.hi[d]) {
        char pt[CHK_PTLEN];
        chk_error(L, "body: point %d %s lies outside the domain (%s from %g "
                     "to %g)", (int)k, chk_pt(pt, x), names[d],
                  ls->s.g.lo[d], ls->s.g.hi[d]);
      }
    seed_push(L, sd, x, vol);
  }
  lua_pop(L, DIM + 1);
}

static void drive_spec(lua_State *L, lsim *ls, int simidx, int b) {
  body *bd = &ls->s.bodies[b];
  lua_getfield(L, 2, "driven");
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return; }
  bd->driven = 1;
  ls->s.ndriven++;
  ls->s.bmat[b] = -1;
  if (ls->s.fdriven[bd->field] >= 0)
    luaL_error(L, "body: two driven bodies cannot share a velocity field");
  ls->s.fdriven[bd->field] = b;
  if (lua_isfunction(L, -1)) {
    lsim_uv(L, simidx, "drives");
    lua_pushvalue(L, -2);
    lua_rawseti(L, -2, b);
    lua_pop(L, 2);
    ls->drives++;
  } else {
    lua_pop(L, 1);
    chk_vec(L, 2, "body", "driven", bd->vdrive, DIM, 1);
    lsim_check_speed(L, ls, bd->vdrive, 0, "body '%s': field 'driven'",
                     bd->name);
  }
}

/* the seeding buffers of one body, in a userdata so that an error
** anywhere while seeding (a Lua error jumps past any free) leaves them
** to the collector */
typedef struct seedbox {
  seed sd;
  size_t *taken, ntaken;
} seedbox;

static void seedbox_free(seedbox *bx) {
  free(bx->sd.x);
  free(bx->sd.vol);
  free(bx->sd.ck);
  free(bx->sd.cv);
  free(bx->taken);
  memset(bx, 0, sizeof *bx);
}

static int seedbox_gc(lua_State *L) {
  seedbox_free(luaL_checkudata(L, 1, "mvmpm.seedbox" LSIM_TAG));
  return 0;
}

static seedbox *seedbox_new(lua_State *L) {
  seedbox *bx = lua_newuserdatauv(L, sizeof *bx, 0);
  memset(bx, 0, sizeof *bx);
  if (luaL_newmetatable(L, "mvmpm.seedbox" LSIM_TAG)) {
    lua_pushcfunction(L, seedbox_gc);
    lua_setfield(L, -2, "__gc");
    lsim_lock(L, -1);
  }
  lua_setmetatable(L, -2);
  return bx;
}

/* refuse a material whose wave speed makes a step too small to reach
** t_end (a fixed dt sets the step itself: sim{} checked it) */
static void material_speed(lua_State *L, lsim *ls, int mi, const char *name) {
  const sim *s = &ls->s;
  const material *m = &s->mats[mi];
  double dt = s->cfg.cfl * s->g.h / m->c, steps = s->t_end / dt;
  if (s->cfg.dt_fixed > 0 || steps <= LSIM_MAX_SPAN) return;
  chk_error(L, "body '%s': material '%s' has the wave speed sqrt((K + 4G/3) "
               "/ density) = %g (K = %g, G = %g, density = %g): its step "
               "cfl * cell / speed = %g would take %.3g steps to t_end = %g "
               "(at most %.0e)", name, m->name, m->c, m->K, m->G, m->rho, dt,
            steps, s->t_end, LSIM_MAX_SPAN);
}

/* r along d as the nearest image where d is periodic */
static double near(const sim *s, int d, double r) {
  if (s->g.periodic[d]) {
    double L = s->g.hi[d] - s->g.lo[d];
    if (r > L / 2) r -= L;
    else if (r < -L / 2) r += L;
  }
  return r;
}

/* angular_velocity: in 2-D a number (the spin about z), in 3-D the
** vector {wx, wy, wz}; w3 gets it as a 3-vector (2-D: its z slot) */
#define NROT (DIM * (DIM - 1) / 2)
static void body_omega(lua_State *L, double *w3) {
  double w[NROT] = {0};
  int d;
  if (NROT == 1)
    w[0] = chk_num(L, 2, "body", "angular_velocity", 0, -HUGE_VAL, HUGE_VAL, 0);
  else
    chk_vec(L, 2, "body", "angular_velocity", w, NROT, 0);
  for (d = 0; d < NROT; d++) w3[3 - NROT + d] = w[d];
}

/* a material or shape of the other dimension at the top: made before
** mvmpm.sim{dim = ...} switched the module (a script, not a scene file,
** which is read for its dimension first), so say that rather than
** "must be a material (got userdata)" */
static void other_dim(lua_State *L, const char *name, const char *what,
                      const char *mt) {
  if (luaL_testudata(L, -1, mt))
    luaL_error(L, "body '%s': field '%s' is a %d-D %s, made before this %d-D "
                  "simulation: make materials and shapes after mvmpm.sim{dim "
                  "= %d} (the mvmpm functions build for the dimension of the "
                  "last simulation made)", name, what, LSIM_OTHER_DIM, what,
               DIM, DIM);
}

int lbody_new(lua_State *L) {
  static const char *const keys[] = {"name", "shape", "points", "material",
      "velocity", "angular_velocity", "field", "driven", "volume", "overlap",
      "bond", "temperature", "hold_temperature", "lattice", NULL};
  static const char *const vols[] = {"cell", "exact", "cut", NULL};
  static const char *const ovl[] = {"error", "skip", NULL};
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  seedbox *bx;
  size_t k;
  double v0[DIM] = {0}, w3[3] = {0}, c[DIM] = {0}, scale = 1, bond, T0, Th;
  size_t first;
  int mi, b, d, exact, skip, isrest = 0, vfun, outside = 0, cut = 0, tfun, spin, own;
  int vgiven;
  int flat = 0; /* a shape with flat faces (sim_normals_advice) */
  turned lt;
  double blo[DIM], bhi[DIM];
  int32_t field;
  char name[32];
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 2);
  bx = seedbox_new(L); /* index 3: freed by the collector on any error */
  lsim_hold(L, ls);    /* index 4: the velocity and shape functions run */
  chk_keys(L, 2, "body", keys);
  if (s->started) luaL_error(L, "body: bodies must be added before the first step");
  lua_getfield(L, 2, "name");
  if (lua_isnil(L, -1)) snprintf(name, sizeof name, "body%d", s->nbody + 1);
  else snprintf(name, sizeof name, "%s", luaL_checkstring(L, -1));
  lua_pop(L, 1);
  lua_getfield(L, 2, "material");
  if (lua_isnil(L, -1)) luaL_error(L, "body '%s': field 'material' is required", name);
  if (!luaL_testudata(L, -1, LMAT_MT)) {
    other_dim(L, name, "material", "mvmpm.material" LSIM_OTHER_TAG);
    luaL_error(L, "body '%s': field 'material' must be a material (got %s)",
               name, luaL_typename(L, -1));
  }
  mi = matindex(L, 1, lua_gettop(L));
  lua_pop(L, 1);
  material_speed(L, ls, mi, name);
  lua_getfield(L, 2, "velocity");
  vfun = lua_isfunction(L, -1);
  lua_pop(L, 1);
  if (!vfun) chk_vec(L, 2, "body", "velocity", v0, DIM, 0);
  body_omega(L, w3);
  lua_getfield(L, 2, "temperature");
  tfun = lua_isfunction(L, -1);
  lua_pop(L, 1);
  T0 = tfun ? NAN : chk_num(L, 2, "body", "temperature", NAN, -HUGE_VAL, HUGE_VAL, 0);
  Th = chk_num(L, 2, "body", "hold_temperature", NAN, -HUGE_VAL, HUGE_VAL, 0);
  if (!isnan(Th) && !s->heat)
    luaL_error(L, "body '%s': hold_temperature needs heat on (call sim:heat{} "
                  "before adding the body)", name);
  if (!isnan(Th) && (tfun || !isnan(T0)))
    luaL_error(L, "body '%s': give temperature or hold_temperature, not both "
                  "(a held body is at its temperature from the start)", name);
  if (!isnan(Th)) T0 = Th;
  lua_getfield(L, 2, "driven"); /* a driven body takes no heat */
  if (s->heat && lua_isnil(L, -1) && !(s->mats[mi].cv > 0))
    luaL_error(L, "body '%s': with heat on, its material '%s' needs a specific "
                  "heat: give cv > 0 (per unit mass) in its constructor", name,
               s->mats[mi].name);
  lua_pop(L, 1);
  lua_getfield(L, 2, "volume");
  vgiven = !lua_isnil(L, -1);
  lua_pop(L, 1);
  exact = chk_option(L, 2, "body", "volume", 0, vols);
  bond = chk_num(L, 2, "body", "bond", 0, 0, HUGE_VAL, 0);
  lsim_check_cohesion(L, s, bond, "body", "bond");
  skip = chk_option(L, 2, "body", "overlap", 0, ovl);
  own = lattice_spec(L, ls, name, &lt);
  occ_init(L, ls);
  /* seed */
  lua_pushstring(L, name); /* for overlap messages */
  lua_getfield(L, 2, "shape");
  lua_getfield(L, 2, "points");
  if (!lua_isnil(L, -2) == !lua_isnil(L, -1))
    luaL_error(L, "body '%s': give exactly one of 'shape' and 'points'", name);
  if (!lua_isnil(L, -2)) {
    lshape *sh;
    lua_pop(L, 1);
    if (!luaL_testudata(L, -1, LSHAPE_MT)) {
      other_dim(L, name, "shape", "mvmpm.shape" LSIM_OTHER_TAG);
      luaL_error(L, "body '%s': field 'shape' must be a shape (mvmpm.%s, "
                    "cylinder, region or rest)", name,
                 DIM == 2 ? "disk, rect, polygon, annulus"
                          : "ball, box, extrude, shell");
    }
    sh = lshape_check(L, -1);
    isrest = sh->kind == SH_REST;
    flat = sh->kind == SH_RECT || sh->kind == SH_POLYGON || sh->kind == SH_EXTRUDE;
    if (own && isrest)
      luaL_error(L, "body '%s': field 'lattice': the rest is the grid "
                    "lattice's points no body took; it has no lattice of its "
                    "own", name);
    for (d = 0; d < DIM; d++) {
      blo[d] = sh->lo[d];
      bhi[d] = sh->hi[d];
      if (!s->g.periodic[d] && (sh->hi[d] <= s->g.lo[d] || sh->lo[d] >= s->g.hi[d]))
        outside = 1;
      /* past a side by more than round-off (a shape drawn to the side's
      ** coordinate is inside) */
      if (!isrest && sh->kind != SH_FUNC && !s->g.periodic[d] &&
          (sh->lo[d] < s->g.lo[d] - 1e-9 * s->g.h ||
           sh->hi[d] > s->g.hi[d] + 1e-9 * s->g.h))
        cut |= 1 << d;
    }
    lua_insert(L, -2);  /* name on top for messages */
    if (own) /* the points on its own lattice; the grid's sites marked */
      seed_turned(L, ls, lua_gettop(L) - 1, skip, &lt, &bx->sd);
    if (exact == 2 && (isrest || own))
      luaL_error(L, "body '%s': volume = \"cut\" cuts a shape seeded on the "
                    "grid's lattice: not %s", name,
                 isrest ? "the rest" : "a body with a lattice of its own");
    seed_shape(L, ls, lua_gettop(L) - 1, skip || isrest || own, !own, &bx->sd,
               &bx->taken, &bx->ntaken);
    if (exact == 2) seed_cut(L, ls, lua_gettop(L) - 1, &bx->sd, 0);
    else if (isrest && !vgiven && ls->ncut) rest_cut(L, ls, &bx->sd, bx->taken);
    else if (exact) {
      double a = lshape_area(sh);
      if (a < 0)
        luaL_error(L, "body '%s': volume = \"exact\" needs a shape of known %s",
                   name, DIM == 2 ? "area" : "volume");
      if (bx->sd.n) scale = a / (bx->sd.n * bx->sd.vol[0]);
    }
    lua_pop(L, 2);
  } else {
    if (own)
      luaL_error(L, "body '%s': field 'lattice' seeds a shape; 'points' are "
                    "placed as given", name);
    if (exact == 2)
      luaL_error(L, "body '%s': volume = \"cut\" cuts a shape; 'points' "
                    "carry their own volumes", name);
    seed_points(L, ls, &bx->sd);
    lua_pop(L, 3);
  }
  if (bx->sd.n == 0) {
    if (outside) {
      char sb[160], db[160];
      int nb = 0, nd = 0;
      for (d = 0; d < DIM; d++) {
        nb += snprintf(sb + nb, sizeof sb - nb, "%s%c %g .. %g", d ? ", " : "",
                       "xyz"[d], blo[d], bhi[d]);
        nd += snprintf(db + nd, sizeof db - nd, "%s%c %g .. %g", d ? ", " : "",
                       "xyz"[d], s->g.lo[d], s->g.hi[d]);
      }
      chk_error(L, "body '%s': its shape (%s) lies outside the domain (%s)",
                name, sb, db);
    }
    luaL_error(L, "body '%s': no particle falls inside its shape (is it at least "
                  "one seeding point, a cell / ppc, across?)", name);
  }
  if (cut) { /* seeded, but only the part inside: said, not refused (a
              ** slab may be meant to run past a side) */
    char sb[160];
    int nb = 0;
    for (d = 0; d < DIM; d++)
      if (cut & (1 << d))
        nb += snprintf(sb + nb, sizeof sb - nb, "%s%c %g .. %g against the "
                       "domain's %g .. %g", nb ? "; " : "", "xyz"[d], blo[d],
                       bhi[d], s->g.lo[d], s->g.hi[d]);
    luaL_where(L, 1);
    fprintf(stderr, "mvmpm: warning: %sbody '%s': its shape runs past the "
            "domain (%s); only the part inside is seeded (%zu particles)\n",
            lua_tostring(L, -1), name, sb, bx->sd.n);
    lua_pop(L, 1);
  }
  lua_getfield(L, 2, "driven");
  field = fieldof(L, 1, ls, !lua_isnil(L, -1));
  lua_pop(L, 1);
  b = sim_add_body(s, name, mi, field);
  if (b < 0) { luaL_error(L, "body: out of memory"); }
  s->bodies[b].flat = flat && !(bond > 0);
  for (k = 0; k < bx->ntaken; k++) ls->occ[bx->taken[k]] = b;
  for (k = 0; k < bx->sd.nc; k++) ls->claim[bx->sd.ck[k]] += bx->sd.cv[k];
  if (exact == 2) ls->ncut++;
  /* the centre of the spin, and each point's arm from it, measured as the
  ** nearest image across periodic sides (a body across a seam spins
  ** about where it is, not about the middle of the domain) */
  for (k = 0; k < bx->sd.n; k++)
    for (d = 0; d < DIM; d++) c[d] += near(s, d, bx->sd.x[DIM * k + d] - bx->sd.x[d]) / bx->sd.n;
  for (d = 0; d < DIM; d++) c[d] += bx->sd.x[d];
  first = s->ps.n;
  if (vfun) lua_getfield(L, 2, "velocity"); /* stays while seeding */
  spin = w3[0] != 0 || w3[1] != 0 || w3[2] != 0;
  for (k = 0; k < bx->sd.n; k++) {
    double *x = &bx->sd.x[DIM * k], v[DIM], r[3] = {0};
    char pt[CHK_PTLEN];
    for (d = 0; d < DIM; d++) v[d] = v0[d];
    /* the rigid spin w x r; in 2-D w has its z component only, and
    ** w x r is (-w r_y, w r_x) */
    for (d = 0; d < DIM; d++) r[d] = near(s, d, x[d] - c[d]);
    for (d = 0; d < DIM; d++)
      v[d] += w3[(d + 1) % 3] * r[(d + 2) % 3] - w3[(d + 2) % 3] * r[(d + 1) % 3];
    chk_pt(pt, x);
    if (vfun) { /* velocity = function(x, y[, z]) return vx, vy[, vz] end */
      int fn = lua_gettop(L);
      lua_pushvalue(L, fn);
      for (d = 0; d < DIM; d++) lua_pushnumber(L, x[d]);
      lua_call(L, DIM, DIM);
      for (d = 0; d < DIM; d++)
        v[d] += chk_result(L, d - DIM, fn, "velocity of body '%s' at %s",
                           name, pt);
      lsim_check_speed(L, ls, v, fn, "velocity of body '%s' at %s", name, pt);
      lua_pop(L, DIM);
    } else
      lsim_check_speed(L, ls, v, 0, "body '%s': velocity at %s", name, pt);
    if (sim_add_particle(s, b, x, v, bx->sd.vol[k] * scale) < 0) {
      luaL_error(L, "body: out of memory for particles");
    }
  }
  if (vfun) lua_pop(L, 1);
  if (s->faff >= 0 && spin) { /* APIC: the rigid spin is affine, C = [w]x:
    ** C_ab = -e_abc w_c (2-D: C_01 = -w, C_10 = w) */
    int a, bb;
    for (a = 0; a < DIM; a++)
      for (bb = 0; bb < DIM; bb++) {
        int cc = 3 - a - bb;
        double sgn = (bb == (a + 1) % 3) ? -1 : 1, *C;
        if (a == bb) continue;
        C = particles_comp(&s->ps, s->faff, a * DIM + bb);
        for (k = first; k < s->ps.n; k++) C[k] = sgn * w3[cc];
      }
  }
  if (bond > 0) { /* strength of the body's bonds to its neighbours */
    double *bp;
    if (sim_enable_bonds(s) < 0) luaL_error(L, "body: out of memory for bonds");
    bp = particles_comp(&s->ps, s->fbond, 0);
    for (k = first; k < s->ps.n; k++) bp[k] = bond;
  }
  seedbox_free(bx); /* done with it: give the memory back now */
  drive_spec(L, ls, 1, b);
  /* initial temperature: the body's, else the scene's (thermal.h) */
  if ((tfun || !isnan(T0)) && thermal_enable(s)) luaL_error(L, "body: out of memory");
  thermal_seed(s, first, s->ps.n, isnan(T0) ? NULL : &T0);
  /* a reacting material: every particle starts unburnt (zero-filled) */
  if (mi >= 0 && s->mats[mi].rx.Z > 0 && react_enable(s))
    luaL_error(L, "body: %s", s->err);
  /* the melting cap of friction heat needs heat on already */
  if (mi >= 0 && s->mats[mi].T_melt > 0) {
    if (!s->heat)
      luaL_error(L, "body '%s': its material '%s' has T_melt, which caps "
                    "friction heating: call sim:heat{} before adding the body",
                 name, s->mats[mi].name);
    if (melt_enable(s)) luaL_error(L, "body: %s", s->err);
  }
  if (tfun) { /* temperature = function(x, y) return T end */
    double *T = particles_comp(&s->ps, s->ftemp, 0);
    int fn;
    lua_getfield(L, 2, "temperature");
    fn = lua_gettop(L);
    for (k = first; k < s->ps.n; k++) {
      for (d = 0; d < DIM; d++) lua_pushnumber(L, s->ps.x[d][k]);
      lua_pushvalue(L, fn);
      lua_insert(L, -DIM - 1);
      lua_call(L, DIM, 1);
      double xk[DIM];
      char pt[CHK_PTLEN];
      for (d = 0; d < DIM; d++) xk[d] = s->ps.x[d][k];
      T[k] = chk_result(L, -1, fn, "temperature of body '%s' at %s", name,
                        chk_pt(pt, xk));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  if (!isnan(Th)) {
    s->bodies[b].hold = 1;
    s->bodies[b].T_hold = Th;
  }
  (void)isrest;
  return lbody_push(L, 1, b);
}

int lbody_push(lua_State *L, int simidx, int b) {
  lsim *ls = lsim_check(L, simidx);
  lbody *lb;
  lsim_uv(L, simidx, "bodies");
  if (lua_rawgeti(L, -1, b + 1) != LUA_TNIL) {
    lua_remove(L, -2);
    return 1;
  }
  lua_pop(L, 1);
  lb = lua_newuserdatauv(L, sizeof *lb, 1);
  lb->ls = ls;
  lb->idx = b;
  luaL_setmetatable(L, LBODY_MT);
  lua_pushvalue(L, simidx); /* keep the simulation alive */
  lua_setiuservalue(L, -2, 1);
  lua_pushvalue(L, -1);
  lua_rawseti(L, -3, b + 1);
  lua_remove(L, -2);
  return 1;
}

static void diag_of(lua_State *L, lbody *lb, bdiag *out) {
  sim *s = &lb->ls->s;
  bdiag *all = malloc((size_t)s->nbody * sizeof *all);
  if (!all) luaL_error(L, "body: out of memory");
  if (diag_bodies(s, all)) { free(all); luaL_error(L, "body: out of memory"); }
  *out = all[lb->idx];
  free(all);
}

static void setnum(lua_State *L, const char *k, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, k);
}

/* b:diag() -> {mass, x, y[, z], vx, vy[, vz], omega, angmom, inertia,
** kinetic, strain, n} */
static int bdiag_(lua_State *L) {
  lbody *lb = checkbody(L, 1);
  bdiag o;
  int d;
  diag_of(L, lb, &o);
  lua_createtable(L, 0, 12);
  setnum(L, "mass", o.mass);
  for (d = 0; d < DIM; d++) {
    static const char *const xs[] = {"x", "y", "z"}, *const vs[] = {"vx", "vy", "vz"};
    setnum(L, xs[d], o.x[d]);
    setnum(L, vs[d], o.v[d]);
  }
  lsim_push_rot(L, o.omega, 1);
  lua_setfield(L, -2, "omega");
  lsim_push_rot(L, o.angmom, 1);
  lua_setfield(L, -2, "angmom");
  if (DIM == 2) setnum(L, "inertia", o.inertia[2][2]);
  else { /* the inertia tensor about the centroid, row by row */
    int a, b;
    lua_createtable(L, 3, 0);
    for (a = 0; a < 3; a++) {
      lua_createtable(L, 3, 0);
      for (b = 0; b < 3; b++) {
        lua_pushnumber(L, o.inertia[a][b]);
        lua_rawseti(L, -2, b + 1);
      }
      lua_rawseti(L, -2, a + 1);
    }
    lua_setfield(L, -2, "inertia");
  }
  setnum(L, "kinetic", o.kinetic);
  setnum(L, "strain", o.strain);
  lua_pushinteger(L, (lua_Integer)o.n);
  lua_setfield(L, -2, "n");
  return 1;
}

static int bvec(lua_State *L, int which) {
  lbody *lb = checkbody(L, 1);
  bdiag o;
  int d;
  diag_of(L, lb, &o);
  if (which == 2) return lsim_push_rot(L, o.omega, 0);
  if (which == 3) { lua_pushnumber(L, o.mass); return 1; }
  for (d = 0; d < DIM; d++) lua_pushnumber(L, which ? o.v[d] : o.x[d]);
  return DIM;
}
static int bcentroid(lua_State *L) { return bvec(L, 0); }
static int bvelocity(lua_State *L) { return bvec(L, 1); }
static int bomega(lua_State *L) { return bvec(L, 2); }
static int bmass(lua_State *L) { return bvec(L, 3); }

/* b:force() -> fx, fy: the force a driven body put on the other bodies
** in the last step (the reaction it feels is minus this) */
static int bforce(lua_State *L) {
  lbody *lb = checkbody(L, 1);
  body *b = &lb->ls->s.bodies[lb->idx];
  int d;
  if (!b->driven)
    luaL_error(L, "body '%s' is not driven: only a driven body reports the "
                  "force it applies", b->name);
  for (d = 0; d < DIM; d++) lua_pushnumber(L, b->force[d]);
  return DIM;
}

/* b:drive(vx, vy): set a driven body's velocity from now on */
static int bdrive(lua_State *L) {
  lbody *lb = checkbody(L, 1);
  static const char *const arg[] = {"vx", "vy", "vz"};
  body *b = &lb->ls->s.bodies[lb->idx];
  double v[DIM];
  int d;
  if (!b->driven) luaL_error(L, "body '%s' is not driven (give it driven = {...})", b->name);
  for (d = 0; d < DIM; d++)
    v[d] = chk_arg(L, 2 + d, "drive", arg[d], 0, -HUGE_VAL, HUGE_VAL, CHK_REQUIRED);
  lsim_check_speed(L, lb->ls, v, 0, "drive of body '%s'", b->name);
  for (d = 0; d < DIM; d++) b->vdrive[d] = v[d];
  return 0;
}

static int bindex(lua_State *L) {
  lbody *lb = checkbody(L, 1);
  const char *k = luaL_checkstring(L, 2);
  body *b = &lb->ls->s.bodies[lb->idx];
  if (strcmp(k, "name") == 0) lua_pushstring(L, b->name);
  else if (strcmp(k, "id") == 0) lua_pushinteger(L, lb->idx + 1);
  else if (strcmp(k, "field") == 0) lua_pushinteger(L, b->field + 1);
  else if (strcmp(k, "driven") == 0) lua_pushboolean(L, b->driven);
  else {
    static const char *const fields[] = {"name", "id", "field", "driven",
                                         NULL};
    luaL_getmetafield(L, 1, "methods");
    if (lua_getfield(L, -1, k) == LUA_TNIL) chk_nokey(L, "body", k, -2, fields);
  }
  return 1;
}

static int btostr(lua_State *L) {
  lbody *lb = checkbody(L, 1);
  lua_pushfstring(L, "body %d '%s'", lb->idx + 1, lb->ls->s.bodies[lb->idx].name);
  return 1;
}

void lbody_open(lua_State *L) {
  static const luaL_Reg meth[] = {{"diag", bdiag_}, {"centroid", bcentroid},
                                  {"velocity", bvelocity}, {"omega", bomega},
                                  {"mass", bmass}, {"drive", bdrive},
                                  {"force", bforce},
                                  {NULL, NULL}};
  luaL_newmetatable(L, LBODY_MT);
  lua_pushcfunction(L, bindex);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, btostr);
  lua_setfield(L, -2, "__tostring");
  lsim_lock(L, -1);
  luaL_newlib(L, meth);
  lua_setfield(L, -2, "methods");
  lua_pop(L, 1);
}
