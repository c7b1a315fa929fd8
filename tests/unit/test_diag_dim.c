/*
** test_diag_dim.c - the interpenetration check (diag_overlap.c) and the
** bodies' spin (diag.c) in whichever dimension the build has, on a
** cube (a square in 2-D) of particles whose answers are known.
*/
#include "diag.h"
#include "diag_hotspot.h"
#include "diag_overlap.h"
#include "shape.h"
#include "thermal.h"
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
  a2 = (2 * s.cfg.lp) * (2 * s.cfg.lp);
  f = 2 * Q / (2 * Q + (double)out[0].n * a2 / 6);
  for (d = 0; d < 3; d++)
    UNIT_NEAR(out[0].omega[d], f * w[d], 1e-12, "rigid spin: omega component");
  for (d = 0; d < DIM; d++) UNIT_NEAR(out[0].x[d], 8.5, 1e-12, "centroid");
  {
    /* hot spots: the particles with x_0 < 6 and those with x_0 > 7 hot,
    ** a gap of two spacings between: two sets, each's volume the sum of
    ** its particles' (F = 1: V0), slabs 2 and 6 cells thick */
    hotspots hs = {0};
    double *T, big = 0, small = 0, tot = 0;
    size_t i;
    UNIT_CHECK(thermal_enable(&s) == 0, "temperature field");
    T = particles_comp(&s.ps, s.ftemp, 0);
    for (i = 0; i < s.ps.n; i++) {
      T[i] = s.ps.x[0][i] < 6 || s.ps.x[0][i] > 7 ? 10 : 0;
      if (s.ps.body[i] == 0 && s.ps.x[0][i] < 6) small += s.ps.vol0[i];
      if (s.ps.body[i] == 0 && s.ps.x[0][i] > 7) big += s.ps.vol0[i];
      tot += s.ps.vol0[i];
    }
    UNIT_CHECK(diag_hotspots(&s, 5, HOTSPOT_LINK, &hs) == 0, "hotspots run");
    UNIT_NEAR((double)hs.n, 2, 0, "hot spots: two slabs");
    /* b's particle at the centre is hot, inside the larger slab */
    UNIT_NEAR(hs.r[0].area, big + pow(0.5, DIM), 1e-12, "hot spot: the larger slab's volume");
    UNIT_NEAR(hs.r[1].area, small, 1e-12, "hot spot: the smaller slab's volume");
    UNIT_NEAR(hs.area_all, tot, 1e-12, "hot spots: all particles' volume");
    hotspots_free(&hs);
  }
  sim_free(&s);
  UNIT_END("test_diag_dim");
}
