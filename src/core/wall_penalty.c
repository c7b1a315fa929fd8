/*
** wall_penalty.c - walls that push on particles (sim.wall_contact =
** "penalty"), frictionless.
**
** The node rules (boundary.c) stop a node that approaches a wall.  At
** the first contact that node holds the material of a whole stencil
** beside the wall, not only the material that touches it, and its
** approach is taken away in one step: a perfectly inelastic impact of
** that mass (quadratic B-splines: the frictionless bounce loses 2.3 % of
** its energy at the first impact at 8 cells per diameter, 1.1 % at 16,
** and more as the step shrinks).
**
** Here a wall acts on each particle whose square (half size l) passes
** the wall line, by a distance pen, with a normal force
**   f = k pen,   k = wall_stiffness * rho c^2 * (2l)^(DIM-2)
** (rho c^2 = K + 4G/3, the particle material's P-wave modulus at rest):
** a pressure of wall_stiffness * rho c^2 times pen / 2l, the particle's
** compression by the wall.  It is a spring, so what the impact stores in
** it comes back; its energy, sum k pen^2 / 2, is part of the total
** (wall_penalty_energy), and a fixed wall does no work.  The force
** reaches the grid as a body force does, f_i = S_ip f, on the particle's
** own field.  k dt^2 / m_p = wall_stiffness / 4 at CFL 0.25 with 2 x 2
** particles per cell: the spring's period spans many steps, and explicit
** stepping is stable.  As the grid is refined 2l shrinks with the
** penetration (pen / 2l is the pressure over the stiffness), so the wall
** tends to the rigid one.
**
** The spring reaches a particle through the nodes, which carry its
** neighbours' mass too, so a sharp tip (a sphere's first touch) can be
** pushed further than its own spring would allow; a particle whose
** centre would leave the domain is held at the wall line instead of
** being dropped, and counted (sim.nheld, g2p.c): a sign that
** wall_stiffness is too low for the load.
**
** Friction is not modelled here: the constructor refuses a penalty wall
** with friction.  (Coulomb friction on the particles was tried: the
** springs of a round body's lowest particle row resist its turning, and
** a disc sliding down a 30 degree incline spun up at 0.04, 0.21, 0.77 of
** the friction torque at 8, 16, 32 cells per diameter, where the patch
** rule gives 0.81, 0.98, 1.05.)
**
** Serial over the particles, in their order: the same bits on any number
** of threads.  Mirror planes (kind "symmetry") keep the node rule.
*/
#include <math.h>
#include "sim.h"
#include "stencil.h"

/* particle i's penetration of side k (> 0: inside the wall) */
static double penetration(const sim *s, size_t i, int k) {
  const grid *g = &s->g;
  int d = k / 2;
  double l = s->cfg.lp * g->h;
  return (k & 1) ? s->ps.x[d][i] + l - g->hi[d] : g->lo[d] - (s->ps.x[d][i] - l);
}

/* the spring constant of particle i's contact with a wall: 0 for a driven
** body (a driven body is moved, not pushed) */
static double stiffness(const sim *s, size_t i) {
  int32_t mi = s->bmat[s->ps.body[i]];
  double k, a = 2.0 * s->cfg.lp * s->g.h;
  int d;
  if (mi < 0) return 0;
  k = s->cfg.wall_stiffness * s->mats[mi].rho * s->mats[mi].c * s->mats[mi].c;
  for (d = 2; d < DIM; d++) k *= a;
  return k;
}

/* the force f on particle i onto the updated momenta of the nodes of its
** stencil (its field's slot at a shared node), times dt */
STENCIL_INLINE void spread(sim *s, const int kind, const stencil_geo *geo,
                           unsigned char *fl, size_t i, const double *f) {
  grid *g = &s->g;
  stencil st;
  double x[DIM];
  int32_t fld = s->bodies[s->ps.body[i]].field;
  int k, a;
  for (a = 0; a < DIM; a++) x[a] = s->ps.x[a][i];
  stencil_eval(geo, kind, x, s->cfg.lp, &st);
  for (k = 0; k < st.n; k++) {
    int32_t n = st.node[k];
    double w = st.w[k] * s->dt;
    for (a = 0; a < DIM; a++) g->q[a][n] += w * f[a];
    if (fl)
      for (a = 0; a < DIM; a++)
        if (f[a] != 0) fl[n] |= (unsigned char)(1u << a);
    if (g->head[n] >= 0) {
      int32_t sl = grid_slot(g, n, fld);
      for (a = 0; a < DIM; a++) g->sq[a][sl] += w * f[a];
    }
  }
}

static void spread_any(sim *s, const stencil_geo *geo, unsigned char *fl,
                       size_t i, const double *f) {
  switch (s->cfg.shape) {
  case SHAPE_GIMP: spread(s, SHAPE_GIMP, geo, fl, i, f); break;
  case SHAPE_BSPLINE2: spread(s, SHAPE_BSPLINE2, geo, fl, i, f); break;
  default: spread(s, SHAPE_LINEAR, geo, fl, i, f);
  }
}

void wall_penalty(sim *s) {
  const particles *ps = &s->ps;
  stencil_geo geo;
  /* the nodes pushed are marked only where wall_penalty_hold will read
  ** (and clear) them */
  unsigned char *fl = sim_wall_hold(s) ? s->work.pflag : NULL;
  int sides[NSIDES], ns = 0, j;
  size_t i;
  for (j = 0; j < NSIDES; j++)
    if (sim_penalty_side(s, j)) sides[ns++] = j;
  stencil_geo_init(&geo, &s->g);
  for (i = 0; i < ps->n; i++) {
    double f[DIM] = {0};
    int any = 0;
    for (j = 0; j < ns; j++) {
      const int k = sides[j], d = k / 2;
      const double sign = (k & 1) ? 1.0 : -1.0; /* the outward normal */
      double pen, kp;
      if ((pen = penetration(s, i, k)) <= 0) continue;
      if ((kp = stiffness(s, i)) <= 0) continue;
      f[d] -= sign * kp * pen;
      s->sides[k].force[d] -= sign * kp * pen;
      any = 1;
    }
    if (any) spread_any(s, &geo, fl, i, f);
  }
}

/*
** MUSL with the walls held (sim.wall_remap; "auto": with gravity): at
** the nodes a spring pushed, the remapped velocity's component along the
** push is set back to the updated grid velocity (q, which
** solve_velocity made vL), so that the particles move and strain as the
** springs drove them.  Left to the remap, a body resting on a floor
** under gravity is pumped, as boundary.c describes for the node rule
** (measured: the block of tests/verify/wall_penalty.lua, K = 100, its
** kinetic energy 6.6e-5 -> 1.9e-3 over 11 time units; held, it decays
** to 3e-6).  Held, impacts lose more (the frictionless bounce at 8
** cells, the first impact: -4.9 % against -0.5 %), which is why "auto"
** holds only with gravity.
*/
void wall_penalty_hold(sim *s) {
  grid *g = &s->g;
  unsigned char *fl = s->work.pflag;
  size_t n;
  int d;
  if (!fl) return;
  for (n = 0; n < g->nnodes; n++) {
    int32_t sl;
    if (!fl[n]) continue;
    for (d = 0; d < DIM; d++) {
      if (!(fl[n] & (1u << d))) continue;
      g->p[d][n] = g->q[d][n];
      for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) g->sp[d][sl] = g->sq[d][sl];
    }
    fl[n] = 0;
  }
}

double wall_penalty_energy(const sim *s) {
  double e = 0;
  size_t i;
  int k;
  if (s->cfg.wall_rule != WALL_PENALTY) return 0;
  for (k = 0; k < NSIDES; k++) {
    if (!sim_penalty_side(s, k)) continue;
    for (i = 0; i < s->ps.n; i++) {
      double pen = penetration(s, i, k);
      if (pen > 0) e += 0.5 * stiffness(s, i) * pen * pen;
    }
  }
  return e;
}
