/*
** test_dimvec.c - the vector helpers contact and the diagnostics use
** (vec.h), in whichever dimension the build has: a rigid rotation's
** angular momentum and spin, and the distance from a line.
*/
#include "vec.h"
#include "unit.h"

int main(void) {
  /* particles on a lattice in a box about the origin, moving rigidly
  ** with spin w (in 2-D only its z part exists): L = sum m x x v and
  ** I = sum m (|x|^2 1 - x x^T) give back w through I w = L */
  const double w[3] = {DIM == 3 ? 0.3 : 0, DIM == 3 ? -0.2 : 0, 0.5};
  double L[3] = {0, 0, 0}, I[3][3] = {{0}}, got[3];
  int k[3] = {0, 0, 0}, d, e, n = 0;
  for (;;) {
    double x[DIM], v[DIM], r[3] = {0, 0, 0}, r2 = 0, m = 1 + 0.1 * (n % 3);
    for (d = 0; d < DIM; d++) r[d] = x[d] = -1.5 + k[d] + 0.3 * d;
    {
      const double u[3] = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2],
                           w[0] * r[1] - w[1] * r[0]};
      for (d = 0; d < DIM; d++) v[d] = u[d];
    }
    vec_moment(L, m, x, v);
    for (d = 0; d < 3; d++) r2 += r[d] * r[d];
    for (d = 0; d < 3; d++)
      for (e = 0; e < 3; e++) I[d][e] += m * ((d == e ? r2 : 0) - r[d] * r[e]);
    n++;
    for (d = 0; d < DIM && ++k[d] > 3; d++) k[d] = 0;
    if (d == DIM) break;
  }
  vec_spin(I, L, got);
  for (d = 0; d < 3; d++) UNIT_NEAR(got[d], w[d], 1e-12, "rigid spin: omega component");
  {
    /* the distance of a from the line along the unit vector b */
    double a[DIM], b[DIM], dist2 = 0, along = 0;
    for (d = 0; d < DIM; d++) { a[d] = 1 + d; b[d] = d == DIM - 1 ? 0.6 : 0.8 / (DIM - 1); }
    vec_unit(b);
    along = vec_dot(a, b);
    for (d = 0; d < DIM; d++) dist2 += (a[d] - along * b[d]) * (a[d] - along * b[d]);
    UNIT_NEAR(vec_crossnorm(a, b), sqrt(dist2), 1e-14, "distance from a line");
  }
  UNIT_END("test_dimvec");
}
