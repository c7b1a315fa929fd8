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

/* components of an angular momentum: its z alone in 2-D */
#if DIM == 2
#define NANG 1
#elif DIM == 3
#define NANG 3
#else
#error "NANG: DIM must be 2 or 3"
#endif

/* am += m (x cross v) */
static inline void vec_moment(double *am, double m, const double *x,
                              const double *v) {
#if DIM == 2
  am[0] += m * (x[0] * v[1] - x[1] * v[0]);
#elif DIM == 3
  am[0] += m * (x[1] * v[2] - x[2] * v[1]);
  am[1] += m * (x[2] * v[0] - x[0] * v[2]);
  am[2] += m * (x[0] * v[1] - x[1] * v[0]);
#else
#error "vec_moment: DIM must be 2 or 3"
#endif
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

#endif
