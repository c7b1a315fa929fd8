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
** lp <= 1/2), the particle domain kept at its initial size.  The
** particle lies within half a cell of the stencil's middle node, at
** offset f in [-1/2, 1/2).  Where it overlaps that node (|f| < lp) the
** outer weights are the overlaps (lp -+ f)^2 / 4lp; beyond, one outer
** node takes the hat's linear part and the other nothing.  With f
** clamped to [-lp, lp] (c) and the rest (e = f - c) both cases are one
** expression, without branches on where the particle is (they were
** mispredicted at every cell crossing); the middle weight is what the
** outer two leave (the weights sum to one).
*/
static inline int shape_gimp(double xi, double lp, double *w, double *dw) {
  double b = floor(xi + 0.5), f = xi - b;
  double c = f < -lp ? -lp : f > lp ? lp : f, e = f - c;
  double q = 0.25 / lp, lo = lp - c, hi = lp + c;
  w[0] = q * lo * lo - (e < 0 ? e : 0.0);
  w[2] = q * hi * hi + (e > 0 ? e : 0.0);
  w[1] = 1.0 - w[0] - w[2];
  dw[0] = -2 * q * lo;
  dw[2] = 2 * q * hi;
  dw[1] = -c / lp;
  return (int)b - 1;
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
