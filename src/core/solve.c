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
#include "par.h"
#include "sim.h"

/* Every loop here is node by node: the threads take parts of the node
** and slot ranges, and the numbers cannot depend on how many. */

static void momentum(size_t i0, size_t i1, double dt, double *const q[DIM],
                     double *const p[DIM], double *const f[DIM]) {
  size_t i;
  int d;
  for (d = 0; d < DIM; d++) {
    double *restrict qd = q[d];
    const double *pd = p[d], *fd = f[d];
    for (i = i0; i < i1; i++) qd[i] = pd[i] + dt * fd[i];
  }
}

static void momentum_part(void *arg, int t, int nparts) {
  sim *s = arg;
  grid *g = &s->g;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  momentum(i0, i1, s->dt, g->q, g->p, g->f);
  par_range(g->nslot, t, nparts, &i0, &i1);
  momentum(i0, i1, s->dt, g->sq, g->sp, g->sf);
}

void solve_momentum(sim *s) { par_run(s->work.par, momentum_part, s); }

/* q -> vL, f -> dv, for entries [i0, i1) of one field table */
static void velocity(size_t i0, size_t i1, const double *m, double *const p[DIM],
                     double *const q[DIM], double *const f[DIM], double mcut,
                     int clearp) {
  size_t i;
  int d;
  for (i = i0; i < i1; i++) {
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

static void velocity_part(void *arg, int t, int nparts) {
  sim *s = arg;
  const sim_cfg *cfg = &s->cfg;
  grid *g = &s->g;
  int musl = cfg->update != UPDATE_USL;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  velocity(i0, i1, g->m, g->p, g->q, g->f, s->mcut, musl);
  par_range(g->nslot, t, nparts, &i0, &i1);
  velocity(i0, i1, g->sm, g->sp, g->sq, g->sf, s->mcut, musl);
}

void solve_velocity(sim *s) { par_run(s->work.par, velocity_part, s); }

static void remap(size_t i0, size_t i1, const double *m, double *const p[DIM]) {
  size_t i;
  int d;
  for (i = i0; i < i1; i++) {
    double inv = m[i] > 0 ? 1.0 / m[i] : 0.0;
    for (d = 0; d < DIM; d++) p[d][i] *= inv;
  }
}

static void remap_part(void *arg, int t, int nparts) {
  grid *g = arg;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  remap(i0, i1, g->m, g->p);
  par_range(g->nslot, t, nparts, &i0, &i1);
  remap(i0, i1, g->sm, g->sp);
}

void solve_remap(sim *s) { par_run(s->work.par, remap_part, &s->g); }
