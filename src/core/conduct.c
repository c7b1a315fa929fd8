/*
** conduct.c - heat conduction on the grid (the equations and the
** contract are in conduct.h).
**
** One pass maps the capacity, the heat and the volume gradient to the
** nodes (per field at shared nodes under an interface conductance, on the
** centre-of-mass arrays otherwise); each substep then gathers every
** particle's temperature gradient from the nodes and scatters its heat
** flow back, updates the nodes, and applies the reservoirs, the walls and
** the interfaces; a last pass maps each node's whole increment back.
** The passes are serial: the sums come out the same at any thread count.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conduct.h"
#include "heat.h"
#include "stencil.h"
#include "vec.h"

#define NARR (6 + DIM) /* C, T, Q, T0, H, HT, A[DIM] */

/* det F of particle i: its volume is J V0 */
static inline double jac(const particles *ps, size_t i) {
  double F[NTENS];
  int k;
  for (k = 0; k < NTENS; k++) F[k] = ps->F[k][i];
  return vec_det(F);
}

static double **arrs(heat_state *h, int slot, double **a) {
  if (slot) {
    a[0] = h->sC; a[1] = h->sT; a[2] = h->sQ; a[3] = h->sT0; a[4] = h->sH;
    a[5] = h->sHT;
  } else {
    a[0] = h->nC; a[1] = h->nT; a[2] = h->nQ; a[3] = h->nT0; a[4] = h->nH;
    a[5] = h->nHT;
  }
  return a;
}

static int alloc_set(double **p[NARR], size_t n) {
  int k;
  for (k = 0; k < NARR; k++) {
    double *q = realloc(*p[k], n * sizeof *q);
    if (!q) return -1;
    *p[k] = q;
  }
  return 0;
}

static void set_ptrs(heat_state *h, int slot, double **p[NARR]) {
  int d;
  if (slot) {
    p[0] = &h->sC; p[1] = &h->sT; p[2] = &h->sQ; p[3] = &h->sT0;
    p[4] = &h->sH; p[5] = &h->sHT;
    for (d = 0; d < DIM; d++) p[6 + d] = &h->sA[d];
  } else {
    p[0] = &h->nC; p[1] = &h->nT; p[2] = &h->nQ; p[3] = &h->nT0;
    p[4] = &h->nH; p[5] = &h->nHT;
    for (d = 0; d < DIM; d++) p[6 + d] = &h->nA[d];
  }
}

int conduct_start(sim *s) {
  heat_state *h = s->heat;
  double **p[NARR];
  int k;
  h->conduct = h->contact == HEAT_CONDUCTANCE && h->hc > 0;
  for (k = 0; k < s->nmat; k++) h->conduct |= s->mats[k].kcond > 0;
  for (k = 0; k < NSIDES; k++) h->conduct |= h->walls[k].kind != HEAT_INSULATED;
  for (k = 0; k < s->nbody; k++) h->conduct |= s->bodies[k].hold;
  if (!h->conduct) return 0;
  set_ptrs(h, 0, p);
  if (alloc_set(p, s->g.nnodes)) {
    snprintf(s->err, sizeof s->err, "heat: out of memory for conduction");
    return -1;
  }
  return 0;
}

int conduct_prepare(sim *s) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  double **p[NARR];
  if (h->contact == HEAT_CONDUCTANCE && g->slotcap > h->hscap_c) {
    set_ptrs(h, 1, p);
    if (alloc_set(p, g->slotcap)) goto oom;
    h->hscap_c = g->slotcap;
  }
  if (s->ps.n > h->pgcap) {
    double *q = realloc(h->hcond, s->ps.cap * sizeof *q);
    if (!q) goto oom;
    h->hcond = q;
    q = realloc(h->tgrid, s->ps.cap * sizeof *q);
    if (!q) goto oom;
    h->tgrid = q;
    h->pgcap = s->ps.cap;
  }
  return 0;
oom:
  snprintf(s->err, sizeof s->err, "heat: out of memory for conduction");
  return -1;
}

void conduct_free(sim *s) {
  heat_state *h = s->heat;
  double **p[NARR];
  int k, slot;
  for (slot = 0; slot < 2; slot++) {
    set_ptrs(h, slot, p);
    for (k = 0; k < NARR; k++) { free(*p[k]); *p[k] = NULL; }
  }
  free(h->hcond);
  free(h->tgrid);
  h->hcond = h->tgrid = NULL;
}

double conduct_dt(const sim *s) {
  double dt = INFINITY, j = s->e.jmax > 1 ? s->e.jmax : 1, h2 = s->g.h * s->g.h;
  int k;
  for (k = 0; k < s->nmat; k++) {
    const material *m = &s->mats[k];
    if (m->kcond > 0) {
      double d = h2 * (m->rho / j) * m->cv / (2 * DIM * m->kcond);
      if (d < dt) dt = d;
    }
  }
  return 0.9 * dt;
}

/* where particle-node pair (n, field f) keeps its values: a slot under an
** interface conductance at a shared node, else the node */
static inline int at(const sim *s, int perfield, int32_t n, int32_t f,
                     size_t *j) {
  if (perfield && s->g.head[n] >= 0) {
    *j = (size_t)grid_slot(&s->g, n, f);
    return 1;
  }
  *j = (size_t)n;
  return 0;
}

/* the mapping of capacity, heat, held capacity and volume gradient */
STENCIL_INLINE void map_kind(sim *s, const int kind, int perfield) {
  const sim_cfg *cfg = &s->cfg;
  heat_state *h = s->heat;
  const particles *ps = &s->ps;
  const double *T = particles_comp(ps, s->ftemp, 0);
  stencil_geo geo;
  stencil st;
  size_t i;
  stencil_geo_init(&geo, &s->g);
  for (i = 0; i < ps->n; i++) {
    const body *bd = &s->bodies[ps->body[i]];
    int32_t mi = s->bmat[ps->body[i]];
    double x[DIM], mc, V;
    int k, d;
    if (mi < 0) continue;
    mc = ps->m[i] * s->mats[mi].cv;
    V = ps->vol0[i] * jac(ps, i);
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    stencil_eval(&geo, kind, x, cfg->lp, &st);
    for (k = 0; k < st.n; k++) {
      double *a[6], w = st.w[k];
      size_t j;
      int sl = at(s, perfield, st.node[k], bd->field, &j);
      arrs(h, sl, a);
      a[0][j] += w * mc;
      a[1][j] += w * mc * T[i];
      for (d = 0; d < DIM; d++) (sl ? h->sA : h->nA)[d][j] += V * st.dw[d][k];
      if (bd->hold) {
        a[4][j] += w * mc;
        a[5][j] += w * mc * bd->T_hold;
      }
    }
  }
}

/* one substep's heat flow Q from the particles' gradients */
STENCIL_INLINE void flow_kind(sim *s, const int kind, int perfield) {
  const sim_cfg *cfg = &s->cfg;
  heat_state *h = s->heat;
  const particles *ps = &s->ps;
  stencil_geo geo;
  stencil st;
  size_t i;
  stencil_geo_init(&geo, &s->g);
  for (i = 0; i < ps->n; i++) {
    int32_t mi = s->bmat[ps->body[i]], f = s->bodies[ps->body[i]].field;
    double x[DIM], gT[DIM] = {0}, kV;
    size_t j[STENCIL_MAX];
    int sl[STENCIL_MAX], k, d;
    if (mi < 0 || !(s->mats[mi].kcond > 0)) continue;
    kV = s->mats[mi].kcond * ps->vol0[i] * jac(ps, i);
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    stencil_eval(&geo, kind, x, cfg->lp, &st);
    for (k = 0; k < st.n; k++) {
      double Tj;
      sl[k] = at(s, perfield, st.node[k], f, &j[k]);
      Tj = (sl[k] ? h->sT : h->nT)[j[k]];
      for (d = 0; d < DIM; d++) gT[d] += st.dw[d][k] * Tj;
    }
    for (k = 0; k < st.n; k++) {
      double dot = 0;
      for (d = 0; d < DIM; d++) dot += st.dw[d][k] * gT[d];
      (sl[k] ? h->sQ : h->nQ)[j[k]] -= kV * dot;
    }
  }
}

/* each particle's share of its nodes' increments, and the nodes'
** temperature at the particle (the field the reaction sees) */
STENCIL_INLINE double back_kind(sim *s, const int kind, int perfield) {
  const sim_cfg *cfg = &s->cfg;
  heat_state *h = s->heat;
  const particles *ps = &s->ps;
  double held = 0;
  stencil_geo geo;
  stencil st;
  size_t i;
  stencil_geo_init(&geo, &s->g);
  for (i = 0; i < ps->n; i++) {
    const body *bd = &s->bodies[ps->body[i]];
    int32_t mi = s->bmat[ps->body[i]];
    double x[DIM], dT = 0, Tg = 0, q;
    int k, d;
    h->hcond[i] = 0;
    h->tgrid[i] = 0;
    if (mi < 0) continue;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    stencil_eval(&geo, kind, x, cfg->lp, &st);
    for (k = 0; k < st.n; k++) {
      size_t j;
      int sl = at(s, perfield, st.node[k], bd->field, &j);
      const double *T = sl ? h->sT : h->nT, *T0 = sl ? h->sT0 : h->nT0;
      dT += st.w[k] * (T[j] - T0[j]);
      Tg += st.w[k] * T[j];
    }
    h->tgrid[i] = Tg;
    q = ps->m[i] * s->mats[mi].cv * dT;
    if (bd->hold) held += q; /* the reservoir keeps its temperature */
    else h->hcond[i] = q;
  }
  return held;
}

/* nodes (or slots) [0, n) of one set: T from the heat, or the update */
static void nodes_start(double *C, double *T, double *T0, size_t n) {
  size_t j;
  for (j = 0; j < n; j++) {
    T[j] = C[j] > 0 ? T[j] / C[j] : 0;
    T0[j] = T[j];
  }
}

static void nodes_update(double *C, double *T, const double *Q, const double *H,
                         const double *HT, size_t n, double dt, double *in) {
  size_t j;
  for (j = 0; j < n; j++) {
    if (!(C[j] > 0)) continue;
    T[j] += dt * Q[j] / C[j];
    if (H[j] > 0) { /* the held bodies' share back to their temperature */
      double dE = HT[j] - H[j] * T[j];
      T[j] += dE / C[j];
      *in += dE;
    }
  }
}

/* one node or slot j against wall w over dt; k the side */
static double wall_one(const heat_wall *w, int k, double *C, double *T,
                       double *const A[DIM], size_t j, double dt) {
  double Tn;
  if (!(C[j] > 0)) return 0;
  if (w->kind == HEAT_FIXED) Tn = w->T;
  else {
    double a = ((k & 1) ? 1.0 : -1.0) * A[k / 2][j];
    if (!(a > 0)) return 0;
    Tn = w->T + (T[j] - w->T) * exp(-w->h * a / C[j] * dt);
  }
  {
    double dE = C[j] * (Tn - T[j]);
    T[j] = Tn;
    return dE;
  }
}

static double walls(sim *s, int perfield, double dt) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  double in = 0;
  int k;
  for (k = 0; k < NSIDES; k++) {
    const heat_wall *w = &h->walls[k];
    int d = k / 2, first, last, line, inner;
    size_t j, nf;
    if (w->kind == HEAT_INSULATED || g->periodic[d]) continue;
    /* the wall plane and the ghost planes; a film also the planes inside
    ** whose nodes' support reaches the wall (the pad), so that their
    ** areas add up to the material's face on the wall */
    inner = w->kind == HEAT_FILM ? g->pad : 0;
    nf = grid_face_count(g, d);
    if (k & 1) { first = g->pad + g->cells[d] - inner; last = g->n[d] - 1; }
    else { first = 0; last = g->pad + inner; }
    for (line = first; line <= last; line++)
      for (j = 0; j < nf; j++) {
        int32_t n = grid_face_node(g, d, line, j), sl;
        if (perfield && g->head[n] >= 0) {
          for (sl = g->head[n]; sl >= 0; sl = g->snext[sl])
            in += wall_one(w, k, h->sC, h->sT, h->sA, (size_t)sl, dt);
        } else
          in += wall_one(w, k, h->nC, h->nT, h->nA, (size_t)n, dt);
      }
  }
  return in;
}

static double norm(double *const A[DIM], size_t j) {
  double a = 0;
  int d;
  for (d = 0; d < DIM; d++) a += A[d][j] * A[d][j];
  return sqrt(a);
}

/* the fields at each shared node exchange h A (T_b - T_a), pair by pair
** in slot order, each pair exactly over dt */
static void interfaces(sim *s, double dt) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  size_t k;
  for (k = 0; k < g->nshared; k++) {
    int32_t a, b;
    for (a = g->head[g->shared[k]]; a >= 0; a = g->snext[a])
      for (b = g->snext[a]; b >= 0; b = g->snext[b]) {
        double Ca = h->sC[a], Cb = h->sC[b], A, e, Tm;
        if (!(Ca > 0) || !(Cb > 0)) continue;
        A = 0.5 * (norm(h->sA, (size_t)a) + norm(h->sA, (size_t)b));
        e = exp(-h->hc * A * (1 / Ca + 1 / Cb) * dt);
        Tm = (Ca * h->sT[a] + Cb * h->sT[b]) / (Ca + Cb);
        h->sT[a] = Tm + (h->sT[a] - Tm) * e;
        h->sT[b] = Tm + (h->sT[b] - Tm) * e;
      }
  }
}

STENCIL_INLINE int conduct_kind(sim *s, const int kind) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  int perfield = h->contact == HEAT_CONDUCTANCE;
  size_t nn = g->nnodes, ns = perfield ? g->nslot : 0, sub, nsub, j;
  double dtc = conduct_dt(s), dts, in = 0;
  double **p[NARR];
  int k, slot;
  for (slot = 0; slot <= perfield; slot++) {
    set_ptrs(h, slot, p);
    for (k = 0; k < NARR; k++) memset(*p[k], 0, (slot ? ns : nn) * sizeof(double));
  }
  nsub = dtc < s->dt ? (size_t)ceil(s->dt / dtc) : 1;
  if (nsub > 100000) {
    snprintf(s->err, sizeof s->err, "heat: conduction would need %zu substeps "
             "in a step (stable step %g, step %g): lower k, raise c or the "
             "cell, or give a smaller dt", nsub, dtc, s->dt);
    return -1;
  }
  h->nsub = nsub;
  h->dtc = dtc;
  dts = s->dt / (double)nsub;
  map_kind(s, kind, perfield);
  nodes_start(h->nC, h->nT, h->nT0, nn);
  if (ns) nodes_start(h->sC, h->sT, h->sT0, ns);
  for (sub = 0; sub < nsub; sub++) {
    memset(h->nQ, 0, nn * sizeof(double));
    if (ns) memset(h->sQ, 0, ns * sizeof(double));
    flow_kind(s, kind, perfield);
    nodes_update(h->nC, h->nT, h->nQ, h->nH, h->nHT, nn, dts, &in);
    if (ns) nodes_update(h->sC, h->sT, h->sQ, h->sH, h->sHT, ns, dts, &in);
    in += walls(s, perfield, dts);
    if (perfield && h->hc > 0) interfaces(s, dts);
  }
  for (j = 0; j < nn; j++)
    if (!isfinite(h->nT[j])) {
      snprintf(s->err, sizeof s->err, "heat: step %ld: the temperature is not "
               "finite at a node after conduction", s->step);
      return -1;
    }
  in -= back_kind(s, kind, perfield);
  s->e.heat_boundary += in;
  return 0;
}

int conduct(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  switch (cfg->shape) {
  case SHAPE_GIMP: return conduct_kind(s, SHAPE_GIMP);
  case SHAPE_BSPLINE2: return conduct_kind(s, SHAPE_BSPLINE2);
  default: return conduct_kind(s, SHAPE_LINEAR);
  }
}
