/*
** test_walls.c - the walls (boundary.c) on a grid filled by hand, in
** whichever dimension the build has: every side stops the motion through
** it along its own normal only; Coulomb friction bounds the length of
** the tangential impulse (a vector of DIM - 1 components) along the slip
** relative to the wall's own tangential velocity, under the node and the
** patch rules; mu = INFINITY sticks; a contact patch across a periodic
** seam is one patch, and one apart from it is another.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "sim.h"
#include "unit.h"

/* a box [0, 1]^DIM of 8 cells, periodic along x when perx */
static int box(sim *s, int perx) {
  double lo[DIM], hi[DIM];
  int per[DIM], d;
  for (d = 0; d < DIM; d++) {
    lo[d] = 0;
    hi[d] = 1;
    per[d] = d == 0 && perx;
  }
  if (sim_init(s, lo, hi, 0.125, per, SHAPE_LINEAR, 2)) return -1;
  s->nfield = 1;
  s->mcut = 1e-12;
  s->dt = 1e-3;
  s->cfg.gap_check = 0;
  return 0;
}

static void node_set(sim *s, int32_t n, double m, const double v[DIM]) {
  int e;
  s->g.m[n] = m;
  s->g.owner[n] = 0;
  for (e = 0; e < DIM; e++) s->g.q[e][n] = s->g.p[e][n] = m * v[e];
}

/* a node beside each wall, moving out through it and along the others */
static void sides(void) {
  sim S;
  int k, e, worst = 0;
  if (box(&S, 0)) { UNIT_CHECK(0, "sim_init"); return; }
  for (k = 0; k < NSIDES; k++) {
    grid *g = &S.g;
    int i[DIM], d = k / 2;
    double v[DIM], sg = (k & 1) ? 1 : -1;
    int32_t n;
    memset(g->m, 0, g->nnodes * sizeof(double));
    for (e = 0; e < DIM; e++) {
      i[e] = 4;
      v[e] = sg * 0.5 * (e + 1);
    }
    i[d] = (k & 1) ? g->n[d] - 1 - g->pad : g->pad; /* the wall plane */
    n = grid_node(g, i);
    node_set(&S, n, 2, v);
    boundary_apply(&S);
    for (e = 0; e < DIM; e++) {
      double want = e == d ? 0 : 2 * v[e];
      if (fabs(g->q[e][n] - want) > 1e-15) worst++;
    }
    for (e = 0; e < DIM; e++) g->q[e][n] = 0;
  }
  UNIT_CHECK(worst == 0, "each side stops only its normal component (%d wrong)", worst);
  sim_free(&S);
}

/* a block of nodes on the floor (side 2), slipping at v against a wall
** moving at vw along it; friction mu under wall rule `rule` */
static void slip(int rule, double mu) {
  sim S;
  grid *g = &S.g;
  double v[DIM], vw[DIM], t0 = 0, dn = 0.5, err = 0, dir = 0, inner = 0;
  size_t n;
  int e;
  const char *names[] = {"node", "patch", "couple"};
  if (box(&S, 0)) { UNIT_CHECK(0, "sim_init"); return; }
  S.cfg.wall_rule = rule;
  S.sides[2].mu = mu;
  for (e = 0; e < DIM; e++) {
    v[e] = e == 1 ? -dn : 0.3 + 0.1 * e;
    vw[e] = e == 1 ? 0 : 0.1 - 0.12 * e;
    S.sides[2].v[e] = vw[e];
    if (e != 1) t0 += (v[e] - vw[e]) * (v[e] - vw[e]);
  }
  t0 = sqrt(t0);
  for (n = 0; n < g->nnodes; n++) {
    int i[DIM], in = 1;
    grid_ijk(g, (int32_t)n, i);
    for (e = 0; e < DIM; e++)
      in &= e == 1 ? i[e] <= 4 : i[e] >= 3 && i[e] <= 6;
    if (in) node_set(&S, (int32_t)n, 1, v);
  }
  boundary_apply(&S);
  for (n = 0; n < g->nnodes; n++) {
    int i[DIM];
    double t1 = 0, want, cr = 0;
    if (!(g->m[n] > 0)) continue;
    grid_ijk(g, (int32_t)n, i);
    if (i[1] > g->pad) { /* above the wall plane */
      if (rule == WALL_NODE || i[1] > g->pad + 1)
        for (e = 0; e < DIM; e++) inner += fabs(g->q[e][n] - v[e]);
      continue;
    }
    for (e = 0; e < DIM; e++)
      if (e != 1) t1 += (g->q[e][n] - vw[e]) * (g->q[e][n] - vw[e]);
    t1 = sqrt(t1);
    want = t0 > mu * dn ? t0 - mu * dn : 0;
    err = fmax(err, fabs(g->q[1][n]) + fabs(t1 - want));
    /* the slip keeps its direction: (q - vw) parallel to (v - vw) */
    for (e = 0; e < DIM; e++)
      if (e != 1) cr += (g->q[e][n] - vw[e]) * (v[e] - vw[e]);
    if (want > 0) dir = fmax(dir, fabs(cr / (t1 * t0) - 1));
  }
  UNIT_CHECK(err < 1e-14 && dir < 1e-14 && inner == 0,
             "%s rule, mu %g: slip left %g off mu N, direction %g, inner nodes moved %g",
             names[rule], mu, err, dir, inner);
  sim_free(&S);
}

/* the patch rule along a periodic floor: columns at x = 0 and x = the
** last node are one patch, moving into the floor at different speeds:
** both get one velocity change; a blob apart gets its own */
static void seam(void) {
  sim S;
  grid *g = &S.g;
  int i[DIM], e, last;
  int32_t a, b, c;
  double va[DIM], vb[DIM], vc[DIM], da, db, dc;
  if (box(&S, 1)) { UNIT_CHECK(0, "sim_init"); return; }
  S.cfg.wall_rule = WALL_PATCH;
  last = g->n[0] - 1;
  for (e = 0; e < DIM; e++) {
    i[e] = 4;
    va[e] = vb[e] = vc[e] = 0;
  }
  i[1] = g->pad;
  va[1] = -1;
  vb[1] = -0.5;
  vc[1] = -0.25;
  i[0] = 0;
  a = grid_node(g, i);
  i[0] = last;
  b = grid_node(g, i);
  i[0] = 4;
  c = grid_node(g, i);
  node_set(&S, a, 1, va);
  node_set(&S, b, 3, vb);
  node_set(&S, c, 1, vc);
  boundary_apply(&S);
  da = g->q[1][a] / g->m[a] - va[1];
  db = g->q[1][b] / g->m[b] - vb[1];
  dc = g->q[1][c] / g->m[c] - vc[1];
  /* the seam's patch: mean approach (1 + 1.5) / 4 removed from both */
  UNIT_CHECK(fabs(da - 0.625) < 1e-15 && fabs(db - 0.625) < 1e-15 &&
                 fabs(dc - 0.25) < 1e-15,
             "patch across the seam: dv %g and %g (0.625), apart %g (0.25)", da, db, dc);
  sim_free(&S);
}

int main(void) {
  int rule;
  sides();
  for (rule = WALL_NODE; rule <= WALL_COUPLE; rule++) {
    slip(rule, 0.2);     /* slides */
    slip(rule, 2.0);     /* sticks: friction would exceed the slip */
    slip(rule, INFINITY);
  }
  seam();
  UNIT_END("test_walls");
}
