/*
** test_core.c - shape functions, transfer and contact invariants.
*/
#include <math.h>
#include <string.h>
#include "shape.h"
#include "sim.h"
#include "unit.h"

/* partition of unity and zero-sum gradients, every kind, many points */
static void shapes(void) {
  int kind, k, j;
  for (kind = 0; kind < SHAPE_NKINDS; kind++) {
    double worst = 0, worstg = 0, worstfd = 0;
    for (j = 0; j < 1000; j++) {
      double xi = 3.0 + j * 0.000997 * 2.3, w[3], dw[3], sum = 0, gsum = 0, h = 1e-6;
      int n = shape_width(kind), i0 = shape_eval(kind, xi, 0.25, w, dw);
      for (k = 0; k < n; k++) {
        double wp[3], dwp[3], wm[3], dwm[3];
        int ip = shape_eval(kind, xi + h, 0.25, wp, dwp);
        int im = shape_eval(kind, xi - h, 0.25, wm, dwm);
        sum += w[k];
        gsum += dw[k];
        if (ip == i0 && im == i0) {
          double fd = (wp[k] - wm[k]) / (2 * h);
          if (fabs(fd - dw[k]) > worstfd) worstfd = fabs(fd - dw[k]);
        }
      }
      if (fabs(sum - 1) > worst) worst = fabs(sum - 1);
      if (fabs(gsum) > worstg) worstg = fabs(gsum);
    }
    printf("%s: ", shape_names[kind]);
    UNIT_NEAR(worst, 0, 1e-14, "max |sum w - 1|");
    printf("%s: ", shape_names[kind]);
    UNIT_NEAR(worstg, 0, 1e-13, "max |sum dw|");
    printf("%s: ", shape_names[kind]);
    UNIT_NEAR(worstfd, 0, 1e-6, "max |dw - finite difference|");
  }
}

static void block(sim *s, int twobodies) {
  double lo[2] = {0, 0}, hi[2] = {2, 2};
  int per[2] = {0, 0}, i, j;
  material m;
  sim_init(s, lo, hi, 0.125, per, SHAPE_LINEAR, 2);
  material_init(&m, &mat_elastic, "m", 1, 1, 0.5);
  sim_add_material(s, &m);
  sim_add_body(s, "a", 0, -1);
  if (twobodies) sim_add_body(s, "b", 0, -1);
  for (i = 0; i < 16; i++)
    for (j = 0; j < 16; j++) {
      double x[2] = {0.5 + i * 0.0625 + 0.03125, 0.5 + j * 0.0625 + 0.03125};
      double v[2] = {0.1 * sin(3 * x[1]), -0.05 * cos(2 * x[0])};
      int b = twobodies && i >= 8;
      if (b) { v[0] = -0.2; v[1] = 0.05; }
      sim_add_particle(s, b, x, v, 0.0625 * 0.0625);
    }
}

/* p2g conserves mass and momentum exactly (to round-off) */
static void transfer(void) {
  sim s;
  double M = 0, P[2] = {0, 0}, gm = 0, gp[2] = {0, 0};
  size_t i;
  block(&s, 1);
  s.mcut = 0;
  grid_reset(&s.g, 1);
  p2g_plan(&s);
  p2g_mark(&s);
  p2g(&s);
  for (i = 0; i < s.ps.n; i++) {
    M += s.ps.m[i];
    P[0] += s.ps.m[i] * s.ps.v[0][i];
    P[1] += s.ps.m[i] * s.ps.v[1][i];
  }
  for (i = 0; i < s.g.nnodes; i++) {
    gm += s.g.m[i];
    gp[0] += s.g.p[0][i];
    gp[1] += s.g.p[1][i];
  }
  UNIT_NEAR(gm / M, 1, 1e-14, "p2g: grid mass / particle mass");
  UNIT_NEAR(gp[0] - P[0], 0, 1e-15, "p2g: grid - particle momentum x");
  UNIT_NEAR(gp[1] - P[1], 0, 1e-15, "p2g: grid - particle momentum y");
  UNIT_CHECK(s.g.nshared > 0, "two touching bodies share nodes");
  /* contact at shared nodes conserves each node's momentum */
  s.dt = 0.01;
  solve_momentum(&s);
  contact_normals(&s);
  reach(&s);
  {
    double before[2] = {0, 0}, after[2] = {0, 0}, worst = 0, nsum = 0;
    size_t k;
    for (k = 0; k < s.g.nshared; k++) {
      int32_t n = s.g.shared[k], sl, first = s.g.head[n];
      double mx = 0, my = 0;
      for (sl = first; sl >= 0; sl = s.g.snext[sl]) {
        before[0] += s.g.sq[0][sl]; before[1] += s.g.sq[1][sl];
      }
      /* normals on a straight vertical interface: +-x, equal and opposite */
      for (sl = first; sl >= 0; sl = s.g.snext[sl]) {
        mx += s.g.sn[0][sl]; my += s.g.sn[1][sl];
        if (fabs(fabs(s.g.sn[0][sl]) - 1) > worst) worst = fabs(fabs(s.g.sn[0][sl]) - 1);
      }
      nsum += fabs(mx) + fabs(my);
    }
    UNIT_NEAR(worst, 0, 1e-12, "straight interface: |n_x| = 1 at shared nodes");
    UNIT_NEAR(nsum, 0, 1e-12, "normals of the two sides sum to zero");
    contact_apply(&s);
    for (k = 0; k < s.g.nshared; k++) {
      int32_t sl;
      for (sl = s.g.head[s.g.shared[k]]; sl >= 0; sl = s.g.snext[sl]) {
        after[0] += s.g.sq[0][sl]; after[1] += s.g.sq[1][sl];
      }
    }
    UNIT_NEAR(after[0] - before[0], 0, 1e-15, "contact: momentum x conserved");
    UNIT_NEAR(after[1] - before[1], 0, 1e-15, "contact: momentum y conserved");
  }
  sim_free(&s);
}

/* a simulation with a wall of friction mu on the left and one node on
** it, node (0, 2), of mass 2 that began the step with momentum p and has
** q after this step's force; returns the node */
static int32_t wall_scene(sim *s, double mu, const double p[2], const double q[2]) {
  double lo[2] = {0, 0}, hi[2] = {1, 1};
  int per[2] = {0, 0}, d;
  int32_t n;
  sim_init(s, lo, hi, 0.25, per, SHAPE_LINEAR, 2);
  s->sides[0].kind = SIDE_WALL;
  s->sides[0].mu = mu;
  s->cfg.gap_check = 0;
  s->nbody = 0;
  grid_reset(&s->g, 1);
  n = 2 * s->g.n[0];
  s->g.m[n] = 2.0;
  for (d = 0; d < 2; d++) {
    s->g.p[d][n] = p[d];
    s->g.q[d][n] = q[d];
  }
  return n;
}

/* the second half of the impulses' work (book.c), with the particles
** moving as the node does (USL: on vL); q is then a velocity */
static void finish(sim *s, int32_t n) {
  int d;
  for (d = 0; d < 2; d++) s->g.q[d][n] /= s->g.m[n];
  s->cfg.update = UPDATE_USL;
  book_finish(s);
}

/* Coulomb at a wall: a node sliding along a wall keeps |t| - mu dn of its
** tangential momentum, and sticks when mu dn >= |t| */
static void coulomb(void) {
  /* into the wall (dn = 0.2) and along it (|t| = 0.1); no force on the
  ** node this step: it began with the same momentum */
  const double q[2] = {-0.2, 0.1};
  double mus[2] = {0.1, 10.0};
  int c;
  for (c = 0; c < 2; c++) {
    sim s;
    int32_t n = wall_scene(&s, mus[c], q, q);
    boundary_apply(&s);
    UNIT_NEAR(s.g.q[0][n], 0, 1e-15, "wall: normal momentum removed");
    if (c == 0) {
      UNIT_NEAR(s.g.q[1][n], 0.1 - 0.1 * 0.2, 1e-15, "wall: slides, t reduced by mu dn");
      finish(&s, n);
      UNIT_NEAR(s.e.friction, (0.01 - 0.08 * 0.08) / 4, 1e-15, "wall: friction work = -c_t (t + t')/2m = (|t|^2-|t'|^2)/2m");
    } else
      UNIT_NEAR(s.g.q[1][n], 0, 1e-15, "wall: sticks when mu dn >= |t|");
    sim_free(&s);
  }
}

/* A node at rest against a sticking wall, pushed along it by this step's
** force: the wall takes the force's momentum back, the node never moved,
** and nothing is dissipated (the kinetic energy the correction removes,
** |t|^2 / 2m, would book the force's work as friction) */
static void stick_at_rest(void) {
  const double p[2] = {0, 0}, q[2] = {-0.05, 0.05};
  sim s;
  int32_t n = wall_scene(&s, 10.0, p, q);
  boundary_apply(&s);
  UNIT_NEAR(s.g.q[1][n], 0, 1e-15, "wall: sticks, tangential momentum removed");
  finish(&s, n);
  UNIT_NEAR(s.e.friction, 0, 1e-15, "wall: a node held at rest dissipates nothing");
  sim_free(&s);
}

int main(void) {
  shapes();
  transfer();
  coulomb();
  stick_at_rest();
  UNIT_END("test_core");
}
