/*
** usf.c - the first half of USAVG's stress update ("update stress first
** and last").  MUSL and USL update the stresses once, after the grid
** step, with the velocity at its end: a step is then a kick followed by
** a drift (symplectic Euler), which is not symmetric in time.  When the
** operator the grid makes changes from step to step (particles crossing
** cells), that asymmetry leaves an energy drift in free flight which
** grows with the number of cells crossed.  USAVG splits the update:
**   sigma <- sigma + C : (dt/2) D(v_i^n)        here, before the forces
**   sigma <- sigma + C : (dt/2) D(v_i^n+1)      after g2p (MUSL's remap)
** with v_i^n = p_i / m_i the velocity the particles map to the grid at
** the start of the step and D the particles' rate of deformation from
** the step's weights.  The step is then drift, kick, drift (a Stormer-
** Verlet step): symmetric in time, with the stresses and velocities at
** its end at the same time level (sim.c drops the lag term).
**
** The cost: one gather of the velocity gradient, one constitutive
** update and a second scatter (the forces, p2g_force) per step.
*/
#include "sim.h"
#include "par.h"
#include "stencil.h"

/* v_i = p_i / m_i into q (which solve_momentum overwrites next), for
** entries [i0, i1) of one field table */
static void velocity(size_t i0, size_t i1, const double *m,
                     double *const p[DIM], double *const q[DIM]) {
  size_t i;
  int d;
  for (i = i0; i < i1; i++) {
    double inv = m[i] > 0 ? 1.0 / m[i] : 0.0;
    for (d = 0; d < DIM; d++) q[d][i] = p[d][i] * inv;
  }
}

static void velocity_part(void *arg, int t, int nparts) {
  grid *g = arg;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  velocity(i0, i1, g->m, g->p, g->q);
  par_range(g->nslot, t, nparts, &i0, &i1);
  velocity(i0, i1, g->sm, g->sp, g->sq);
}

/* L_p = sum_i v_i (x) grad S_ip, each particle from its own field */
STENCIL_INLINE void gradient_kind(sim *s, const int kind, const int shared,
                                  size_t i0, size_t i1) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  particles *ps = &s->ps;
  const double lp = cfg->lp;
  const double *restrict gq[DIM];
  stencil_geo geo;
  stencil st;
  size_t i;
  int a, c;
  for (a = 0; a < DIM; a++) gq[a] = g->q[a];
  stencil_geo_init(&geo, g);
  for (i = i0; i < i1; i++) {
    double x[DIM], l[NTENS] = {0};
    const int32_t *slot = shared ? s->work.pslot + i * stencil_size(kind) : NULL;
    int k;
    for (a = 0; a < DIM; a++) x[a] = ps->x[a][i];
    stencil_eval(&geo, kind, x, lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double q[DIM];
      if (shared && slot[k] >= 0) {
        for (a = 0; a < DIM; a++) q[a] = g->sq[a][slot[k]];
      } else {
        for (a = 0; a < DIM; a++) q[a] = gq[a][n];
      }
      for (a = 0; a < DIM; a++)
        for (c = 0; c < DIM; c++) l[a * DIM + c] += q[a] * st.dw[c][k];
    }
    for (a = 0; a < NTENS; a++) ps->L[a][i] = l[a];
  }
}

static void gradient_range(sim *s, size_t i0, size_t i1) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0;
#define GRAD(K)                                                          \
  if (shared) gradient_kind(s, K, 1, i0, i1);                            \
  else gradient_kind(s, K, 0, i0, i1);
  switch (cfg->shape) {
  case SHAPE_GIMP: GRAD(SHAPE_GIMP) break;
  case SHAPE_BSPLINE2: GRAD(SHAPE_BSPLINE2) break;
  default: GRAD(SHAPE_LINEAR)
  }
#undef GRAD
}

static void gradient_part(void *arg, int t, int nparts) {
  sim *s = arg;
  size_t i0, i1;
  par_range(s->ps.n, t, nparts, &i0, &i1);
  gradient_range(s, i0, i1);
}

/*
** Bonds beside a driven body.  MUSL's remap gives a bonded slot there the
** drive's velocity (bond.c bond_remap); the first half-step must strain
** its particles by the same motion, or the two halves work on different
** velocities and the bonded interface makes energy (measured: a bar
** bonded to a grip at rest, ringing, gained 1.1 % of its energy by t = 40
** at 16 cells; a brittle pull's bars ended with 1.2 times the grips'
** work).  A slot is held where it and its partner still carry strength
** and their law bonds them (contact.c decides the cut later in the step:
** in the step of a cut the first half still holds).  What the held
** velocity adds to the strain, dt/2 f_r . (v_drive - v_r^n), is booked
** with the bonded impulses by a second pass once the forces are known
** (v_r^n is still p_r / m_r then), as bond_remap books the second
** half's.  book = 0: hold, and say whether any slot was held; book = 1:
** book what the hold added.
*/
static int hold(sim *s, int book) {
  grid *g = &s->g;
  size_t k;
  double w = 0;
  int held = 0, d;
  for (k = 0; k < g->nshared; k++) {
    int32_t n = g->shared[k], sl, drv = bond_driven(s, n);
    const double *vd;
    if (drv < 0) continue;
    vd = s->bodies[s->fdriven[g->sfield[drv]]].vdrive;
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
      if (sl == drv || s->fdriven[g->sfield[sl]] >= 0 || !(g->sm[sl] > s->mcut) ||
          !(contact_bond(s, sl, drv, 1) > 0))
        continue;
      held = 1;
      for (d = 0; d < DIM; d++) {
        if (book) /* v^n as velocity() made it */
          w += (g->sf[d][sl] - g->sm[sl] * s->cfg.gravity[d]) *
               (vd[d] - g->sp[d][sl] * (1.0 / g->sm[sl]));
        else
          g->sq[d][sl] = vd[d];
      }
    }
  }
  if (book) s->e.bonding += 0.5 * s->dt * w;
  return held;
}

int usf(sim *s) {
  sim_work *wk = &s->work;
  int held = 0;
  par_run(wk->par, velocity_part, &s->g);
  if (s->fbond >= 0 && s->ndriven) held = hold(s, 0);
  /* where MUSL's remap holds the walls (gravity on), this velocity too,
  ** at the nodes where a wall acted in the last step: otherwise a body
  ** resting on a floor is pumped as boundary.c describes */
  if (sim_wall_hold(s)) boundary_normal_set(s, s->g.q, s->g.sq, 1);
  par_run(wk->par, gradient_part, s);
  if (constitutive(s, 0.5 * s->dt)) return -1;
  p2g_force(s);
  if (held) hold(s, 1);
  return 0;
}
