/*
** xpic.c - the extended PIC update of order m, XPIC(m) (Hammerquist and
** Nairn 2017), m = 2 or 3.
**
** With S the particles' weights at the nodes, S+ the mass-weighted map
** back (v_i = sum_p m_p S_ip v_p / m_i) and A = S+ S (grid -> particles
** -> grid), FLIP keeps every particle velocity component the grid cannot
** see, (I - S S+) V, and PIC (XPIC(1)) drops it all.  XPIC(m) drops
** (I - S S+)^m V instead: the grid-invisible noise that cell crossing
** makes is removed while the smooth motion PIC smears is kept to order m.
** Expanded, the particle velocities become
**   v_p <- sum_i S_ip (vL_i + c_i),  c = sum_{k=1..m-1} (I - A)^k v
** with v the grid velocity at the start of the step (before forces) and
** vL the updated one (contact and walls included).  For m <= 3 two grid
** vectors suffice: u1 = (I - A) v, and c = u1 (m = 2) or 2 u1 - A u1
** (m = 3).  xpic() writes c into f, where FLIP's dv was (g2p reads it).
**
** Where a wall acted this step the normal part of c is zeroed, so that
** the correction does not carry material back into the wall the wall
** stopped.  Contact is not imposed again on c: at shared nodes each
** field's c is its own field's (Hammerquist and Nairn re-impose contact
** on each increment; here the bodies' fields just do not mix).
**
** A u is a gather and a scatter per particle, run on one thread in the
** particles' order (the sums into the nodes are then the same for any
** thread count); the node passes run on all threads.  It costs one to
** two extra particle passes per step.
*/
#include "sim.h"
#include "par.h"
#include "stencil.h"

/* acc += A-numerator of u: each particle reads u at its nodes (its
** field's slot at shared nodes) and adds m_p S_ip (S u)_p to acc.
** keep: the first pass, u = v; (S v)_p is kept in the particle's L[0],
** L[1] for g2p, which books the transfer's change beyond FLIP's
** v_p + S (vL - v) (g2p.c; the remap sets L afterwards) */
STENCIL_INLINE void apply_kind(sim *s, const int kind, const int shared,
                               const int keep) {
  const sim_cfg *cfg = &s->cfg;
  grid *g = &s->g;
  particles *ps = &s->ps;
  const double lp = cfg->lp;
  stencil_geo geo;
  stencil st;
  size_t i;
  stencil_geo_init(&geo, g);
  for (i = 0; i < ps->n; i++) {
    double x[DIM], u[DIM] = {0};
    const double mp = ps->m[i];
    const int32_t *slot = shared ? s->work.pslot + i * stencil_size(kind) : NULL;
    int k, d;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    stencil_eval(&geo, kind, x, lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      const double w = st.w[k];
      if (shared && slot[k] >= 0) {
        for (d = 0; d < DIM; d++) u[d] += w * g->sf[d][slot[k]];
      } else {
        for (d = 0; d < DIM; d++) u[d] += w * g->f[d][n];
      }
    }
    if (keep)
      for (d = 0; d < DIM; d++) ps->L[d][i] = u[d];
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      const double wm = st.w[k] * mp;
      for (d = 0; d < DIM; d++) g->p[d][n] += wm * u[d];
      if (shared && slot[k] >= 0)
        for (d = 0; d < DIM; d++) g->sp[d][slot[k]] += wm * u[d];
    }
  }
}

static void apply(sim *s, int keep) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0;
#define APPLY(K)                                                         \
  if (shared) { if (keep) apply_kind(s, K, 1, 1); else apply_kind(s, K, 1, 0); } \
  else { if (keep) apply_kind(s, K, 0, 1); else apply_kind(s, K, 0, 0); }
  switch (cfg->shape) {
  case SHAPE_GIMP: APPLY(SHAPE_GIMP) break;
  case SHAPE_BSPLINE2: APPLY(SHAPE_BSPLINE2) break;
  default: APPLY(SHAPE_LINEAR)
  }
#undef APPLY
}

/* the node passes, entries [i0, i1) of one field table: stage 0 sets
** u = v = vL - dv and clears the accumulator; stage a >= 1 sets
** u <- a u - acc / m and clears the accumulator */
static void nodes(size_t i0, size_t i1, const double *m, double *const p[DIM],
                  double *const q[DIM], double *const f[DIM], int stage) {
  size_t i;
  int d;
  for (i = i0; i < i1; i++) {
    double inv = m[i] > 0 ? 1.0 / m[i] : 0.0;
    for (d = 0; d < DIM; d++) {
      if (stage == 0) f[d][i] = m[i] > 0 ? q[d][i] - f[d][i] : 0.0;
      else f[d][i] = stage * f[d][i] - p[d][i] * inv;
      p[d][i] = 0;
    }
  }
}

typedef struct xjob { sim *s; int stage; } xjob;

static void nodes_part(void *arg, int t, int nparts) {
  xjob *j = arg;
  grid *g = &j->s->g;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  nodes(i0, i1, g->m, g->p, g->q, g->f, j->stage);
  par_range(g->nslot, t, nparts, &i0, &i1);
  nodes(i0, i1, g->sm, g->sp, g->sq, g->sf, j->stage);
}


void xpic(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  xjob j = {s, 0};
  par_run(wk->par, nodes_part, &j); /* u = v */
  apply(s, 1);
  j.stage = 1;                     /* u1 = v - A v */
  par_run(wk->par, nodes_part, &j);
  if (cfg->xpic >= 3) {              /* c = 2 u1 - A u1 */
    apply(s, 0);
    j.stage = 2;
    par_run(wk->par, nodes_part, &j);
  }
  /* the correction's normal part off where a wall acted */
  boundary_normal_set(s, s->g.f, s->g.sf, 0);
}
