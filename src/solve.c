/*
** solve.c - the grid momentum update and the nodal velocities.
**   q_i = p_i + dt f_i                     (updated momentum)
** then, once contact and sides have corrected q,
**   vL_i = q_i / m_i,   dv_i = (q_i - p_i) / m_i
** so the FLIP increment dv always carries the contact and wall impulses
** exactly as the positions' velocity vL does.  Nodes lighter than mcut
** are treated as empty: no acceleration, so a sliver of mass at the edge
** of a body cannot turn a finite force into a huge velocity.
*/
#include <string.h>
#include "sim.h"

void solve_momentum(sim *s) {
  grid *g = &s->g;
  const double dt = s->dt;
  size_t i;
  int d;
  for (d = 0; d < DIM; d++) {
    double *q = g->q[d];
    const double *p = g->p[d], *f = g->f[d];
    for (i = 0; i < g->nnodes; i++) q[i] = p[i] + dt * f[i];
    for (i = 0; i < g->nslot; i++) g->sq[d][i] = g->sp[d][i] + dt * g->sf[d][i];
  }
}

/* q -> vL, f -> dv, for n entries of one field table */
static void velocity(size_t n, const double *m, double *const p[DIM],
                     double *const q[DIM], double *const f[DIM], double mcut,
                     int clearp) {
  size_t i;
  int d;
  for (i = 0; i < n; i++) {
    double mi = m[i];
    if (mi > mcut) {
      double inv = 1.0 / mi;
      for (d = 0; d < DIM; d++) {
        f[d][i] = (q[d][i] - p[d][i]) * inv;
        q[d][i] *= inv;
      }
    } else if (mi > 0) {
      double inv = 1.0 / mi;
      for (d = 0; d < DIM; d++) {
        f[d][i] = 0;
        q[d][i] = p[d][i] * inv;
      }
    } else
      for (d = 0; d < DIM; d++) f[d][i] = q[d][i] = 0;
    if (clearp)
      for (d = 0; d < DIM; d++) p[d][i] = 0;
  }
}

void solve_velocity(sim *s) {
  grid *g = &s->g;
  int musl = s->update == UPDATE_MUSL;
  velocity(g->nnodes, g->m, g->p, g->q, g->f, s->mcut, musl);
  velocity(g->nslot, g->sm, g->sp, g->sq, g->sf, s->mcut, musl);
}

static void remap(size_t n, const double *m, double *const p[DIM]) {
  size_t i;
  int d;
  for (i = 0; i < n; i++) {
    double inv = m[i] > 0 ? 1.0 / m[i] : 0.0;
    for (d = 0; d < DIM; d++) p[d][i] *= inv;
  }
}

void solve_remap(sim *s) {
  grid *g = &s->g;
  remap(g->nnodes, g->m, g->p);
  remap(g->nslot, g->sm, g->sp);
}
