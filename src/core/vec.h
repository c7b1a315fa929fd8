/*
** vec.h - small vectors and tensors of DIM components, written once for
** either dimension.  Full tensors (F, grad v) are stored row by row,
** T[a * DIM + b]; symmetric ones (stress, strain) in NSTRESS slots whose
** order dim.h fixes (plus zz in plane strain), read through vec_sym.
*/
#ifndef mvmpm_vec_h
#define mvmpm_vec_h

#include <math.h>
#include "dim.h"

static inline double vec_dot(const double *a, const double *b) {
  double s = 0;
  int d;
  for (d = 0; d < DIM; d++) s += a[d] * b[d];
  return s;
}

static inline double vec_norm(const double *a) { return sqrt(vec_dot(a, a)); }

/* a / |a| in place; returns |a| (a is left alone when it is 0) */
static inline double vec_unit(double *a) {
  double l = vec_norm(a);
  int d;
  if (l > 0)
    for (d = 0; d < DIM; d++) a[d] /= l;
  return l;
}

/* the slot of component (a, b) of a symmetric tensor */
static inline int vec_sym(int a, int b) {
#if DIM == 2
  return a == b ? a : S_XY;
#elif DIM == 3
  /* (0,1) -> xy, (1,2) -> yz, (0,2) -> xz */
  return a == b ? a : a + b == 1 ? S_XY : a + b == 3 ? S_YZ : S_XZ;
#else
#error "vec_sym: DIM must be 2 or 3"
#endif
}

/* n . S . n of a symmetric tensor S (NSTRESS slots) */
static inline double vec_nsn(const double *S, const double *n) {
  double r = 0;
  int a, b;
  for (a = 0; a < DIM; a++)
    for (b = 0; b < DIM; b++) r += n[a] * S[vec_sym(a, b)] * n[b];
  return r;
}

/* determinant of a full tensor */
static inline double vec_det(const double *T) {
#if DIM == 2
  return T[0] * T[3] - T[1] * T[2];
#elif DIM == 3
  return T[0] * (T[4] * T[8] - T[5] * T[7]) - T[1] * (T[3] * T[8] - T[5] * T[6]) +
         T[2] * (T[3] * T[7] - T[4] * T[6]);
#else
#error "vec_det: DIM must be 2 or 3"
#endif
}

/* |a x b|: the distance of a from the line along the unit vector b */
static inline double vec_crossnorm(const double *a, const double *b) {
#if DIM == 2
  return fabs(a[0] * b[1] - a[1] * b[0]);
#elif DIM == 3
  double c0 = a[1] * b[2] - a[2] * b[1], c1 = a[2] * b[0] - a[0] * b[2],
         c2 = a[0] * b[1] - a[1] * b[0];
  return sqrt(c0 * c0 + c1 * c1 + c2 * c2);
#else
#error "vec_crossnorm: DIM must be 2 or 3"
#endif
}

/* am += m (x x v), am of 3 components: the angular momentum about the
** origin (2-D: the plane's motion has only its z component, am[2]) */
static inline void vec_moment(double am[3], double m, const double *x,
                              const double *v) {
#if DIM == 2
  am[2] += m * (x[0] * v[1] - x[1] * v[0]);
#elif DIM == 3
  am[0] += m * (x[1] * v[2] - x[2] * v[1]);
  am[1] += m * (x[2] * v[0] - x[0] * v[2]);
  am[2] += m * (x[0] * v[1] - x[1] * v[0]);
#else
#error "vec_moment: DIM must be 2 or 3"
#endif
}

/* the angular velocity w of a rigid motion with angular momentum L and
** inertia tensor I (3 x 3) about the same point: I w = L.  2-D: about z
** alone, w[2] = L[2] / I[2][2]; 0 where I is singular */
static inline void vec_spin(const double I[3][3], const double L[3],
                            double w[3]) {
#if DIM == 2
  w[0] = w[1] = 0;
  w[2] = I[2][2] > 0 ? L[2] / I[2][2] : 0.0;
#elif DIM == 3
  double c[3][3], det;
  int a, b;
  for (a = 0; a < 3; a++)
    for (b = 0; b < 3; b++) {
      /* cofactor of I[b][a]: the inverse's (a, b) times det */
      int r0 = (b + 1) % 3, r1 = (b + 2) % 3, k0 = (a + 1) % 3, k1 = (a + 2) % 3;
      c[a][b] = I[r0][k0] * I[r1][k1] - I[r0][k1] * I[r1][k0];
    }
  det = I[0][0] * c[0][0] + I[0][1] * c[1][0] + I[0][2] * c[2][0];
  for (a = 0; a < 3; a++) {
    w[a] = 0;
    if (det > 0)
      for (b = 0; b < 3; b++) w[a] += c[a][b] * L[b] / det;
  }
#else
#error "vec_spin: DIM must be 2 or 3"
#endif
}

#endif
