/*
** shape.h - grid shape functions as tensor products of 1-D weights.
** Coordinates are in cell units measured from the grid's lower corner,
** so node i sits at xi = i.  Each function fills the weights w[k] and
** their derivatives dw[k] (per cell; divide by h for physical units) of
** the nodes first, first+1, ... and returns first (which may lie outside
** the grid: the caller wraps or pads).
*/
#ifndef mvmpm_shape_h
#define mvmpm_shape_h

#include <math.h>

enum shape_kind { SHAPE_LINEAR, SHAPE_GIMP, SHAPE_BSPLINE2, SHAPE_NKINDS };
#define SHAPE_MAXW 3 /* nodes per dimension in the widest stencil */

extern const char *const shape_names[];

/* nodes per dimension */
static inline int shape_width(int kind) { return kind == SHAPE_LINEAR ? 2 : 3; }
/* ghost nodes needed beyond each non-periodic side */
static inline int shape_pad(int kind) { return kind == SHAPE_LINEAR ? 0 : 1; }

/* linear hat: the two nodes of the cell holding xi */
static inline int shape_linear(double xi, double *w, double *dw) {
  double i0 = floor(xi), f = xi - i0;
  w[0] = 1.0 - f; w[1] = f;
  dw[0] = -1.0; dw[1] = 1.0;
  return (int)i0;
}

/*
** uGIMP: the hat convolved with a particle of half width lp (cells,
** lp <= 1/2), the particle domain kept at its initial size.  r is the
** particle's offset from the node.
*/
static inline void shape_gimp1(double r, double lp, double *w, double *dw) {
  double a = fabs(r), s = r < 0 ? -1.0 : 1.0;
  if (a < lp) { *w = 1.0 - (r * r + lp * lp) / (2 * lp); *dw = -r / lp; }
  else if (a <= 1.0 - lp) { *w = 1.0 - a; *dw = -s; }
  else if (a < 1.0 + lp) {
    double t = 1.0 + lp - a;
    *w = t * t / (4 * lp); *dw = -s * t / (2 * lp);
  } else { *w = 0.0; *dw = 0.0; }
}

static inline int shape_gimp(double xi, double lp, double *w, double *dw) {
  int i0 = (int)floor(xi + 0.5) - 1, k;
  for (k = 0; k < 3; k++) shape_gimp1(xi - (i0 + k), lp, &w[k], &dw[k]);
  return i0;
}

/* quadratic B-spline: C1 weights, no gradient jump when crossing cells */
static inline int shape_bspline2(double xi, double *w, double *dw) {
  double b = floor(xi - 0.5), r;
  int i0 = (int)b;
  r = xi - b; /* in [0.5, 1.5): offset from node i0 */
  w[0] = 0.5 * (1.5 - r) * (1.5 - r); dw[0] = -(1.5 - r);
  r -= 1.0;   /* offset from node i0+1, in [-0.5, 0.5) */
  w[1] = 0.75 - r * r; dw[1] = -2.0 * r;
  r -= 1.0;   /* offset from node i0+2, in [-1.5, -0.5) */
  w[2] = 0.5 * (1.5 + r) * (1.5 + r); dw[2] = (1.5 + r);
  return i0;
}

static inline int shape_eval(int kind, double xi, double lp, double *w,
                             double *dw) {
  switch (kind) {
  case SHAPE_GIMP: return shape_gimp(xi, lp, w, dw);
  case SHAPE_BSPLINE2: return shape_bspline2(xi, w, dw);
  default: return shape_linear(xi, w, dw);
  }
}

#endif
