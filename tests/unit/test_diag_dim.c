/*
** test_diag_dim.c - the interpenetration check (diag_overlap.c) and the
** bodies' spin (diag.c) in whichever dimension the build has, on a
** cube (a square in 2-D) of particles whose answers are known.
*/
#include "diag.h"
#include "diag_overlap.h"
#include "shape.h"
#include "unit.h"

#define SIDE 9 /* cells of the block along each axis, from cell 4 */

static void domain(sim *s) {
  double lo[DIM], hi[DIM];
  int per[DIM], d;
  material m;
  for (d = 0; d < DIM; d++) {
    lo[d] = 0;
    hi[d] = 16;
    per[d] = 0;
  }
  sim_init(s, lo, hi, 1.0, per, SHAPE_LINEAR, 2);
  material_init(&m, &mat_elastic, "m", 1, 1, 0.5);
  sim_add_material(s, &m);
  sim_add_body(s, "a", 0, -1);
  sim_add_body(s, "b", 0, -1);
}

/* the block of body 0, 2 particles per cell and direction, spinning
** rigidly with w about its centre c; Q: sum of r_0^2 over its particles */
static void block(sim *s, const double w[3], double *Q) {
  int p[DIM], d;
  const double c = 4 + 0.5 * SIDE, vol = pow(0.5, DIM);
  *Q = 0;
  for (d = 0; d < DIM; d++) p[d] = 0;
  for (;;) {
    double x[DIM], r[3] = {0, 0, 0}, v[DIM], rot[3];
    for (d = 0; d < DIM; d++) r[d] = (x[d] = 4.25 + 0.5 * p[d]) - c;
    rot[0] = w[1] * r[2] - w[2] * r[1];
    rot[1] = w[2] * r[0] - w[0] * r[2];
    rot[2] = w[0] * r[1] - w[1] * r[0];
    for (d = 0; d < DIM; d++) v[d] = rot[d];
    sim_add_particle(s, 0, x, v, vol);
    *Q += r[0] * r[0];
    for (d = 0; d < DIM && ++p[d] >= 2 * SIDE; d++) p[d] = 0;
    if (d == DIM) break;
  }
}

int main(void) {
  sim s;
  overlap_info o;
  bdiag out[2];
  const double w[3] = {DIM == 3 ? 0.3 : 0, DIM == 3 ? -0.2 : 0, 0.5};
  double x[DIM], v[DIM] = {0}, Q, a2, f;
  long last;
  int d;
  domain(&s);
  block(&s, w, &Q);
  /* a particle of b at the block's centre: buried (SIDE - 1) / 2 cells */
  for (d = 0; d < DIM; d++) x[d] = 8.5;
  last = sim_add_particle(&s, 1, x, v, pow(0.5, DIM));
  UNIT_CHECK(diag_overlap(&s, 8, &o) == 0, "overlap runs");
  UNIT_NEAR((double)o.n, 1, 0, "centre of the block: particles buried");
  UNIT_NEAR(o.depth, 4, 0, "centre of the block: depth (cells)");
  /* moved along the last axis into the block's outer layer: contact */
  s.ps.x[DIM - 1][last] = 12.5;
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 0, 0, "outer layer: particles buried");
  s.ps.x[DIM - 1][last] = 11.5;
  diag_overlap(&s, 8, &o);
  UNIT_NEAR(o.depth, 1, 0, "a cell inside: depth");
  /* the spin: the particles move with w, L = w sum m r_perp^2 on the
  ** symmetric lattice, and I adds the particles' own a^2 / 6; each axis
  ** has the two others' sums 2 Q (2-D: z with x and y) */
  UNIT_CHECK(diag_bodies(&s, out) == 0, "diag runs");
  a2 = (2 * s.lp) * (2 * s.lp);
  f = 2 * Q / (2 * Q + (double)out[0].n * a2 / 6);
  for (d = 0; d < 3; d++)
    UNIT_NEAR(out[0].omega[d], f * w[d], 1e-12, "rigid spin: omega component");
  for (d = 0; d < DIM; d++) UNIT_NEAR(out[0].x[d], 8.5, 1e-12, "centroid");
  sim_free(&s);
  UNIT_END("test_diag_dim");
}
