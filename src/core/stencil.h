/*
** stencil.h - the nodes a particle touches, with weights and gradients.
** Inline so that each phase's loop, compiled for one shape kind at a
** time (kind is a constant there), folds the shape function in.
*/
#ifndef mvmpm_stencil_h
#define mvmpm_stencil_h

#include "grid.h"
#include "shape.h"

#if DIM == 2
#define STENCIL_MAX (SHAPE_MAXW * SHAPE_MAXW)
#else
#define STENCIL_MAX (SHAPE_MAXW * SHAPE_MAXW * SHAPE_MAXW)
#endif

typedef struct stencil {
  int n;
  int32_t node[STENCIL_MAX];
  double w[STENCIL_MAX];
  double dw[DIM][STENCIL_MAX]; /* physical gradient */
} stencil;

/*
** The grid's geometry as the stencil needs it.  A phase copies it into a
** local before its loop: the grid's own lo and inv_h are doubles like the
** arrays the loop stores into, so read through the grid they would be
** reloaded after every store.
*/
typedef struct stencil_geo {
  double lo[DIM], inv_h;
  double off[DIM];     /* xi = (x - lo) inv_h + off: the ghost nodes */
  int32_t n[DIM];
  int periodic[DIM];
} stencil_geo;

#define STENCIL_INLINE static inline __attribute__((always_inline))

STENCIL_INLINE void stencil_geo_init(stencil_geo *geo, const grid *g) {
  int d;
  geo->inv_h = g->inv_h;
  for (d = 0; d < DIM; d++) {
    geo->lo[d] = g->lo[d];
    geo->off[d] = g->periodic[d] ? 0 : g->pad;
    geo->n[d] = g->n[d];
    geo->periodic[d] = g->periodic[d];
  }
}

/* as grid_wrap */
STENCIL_INLINE int stencil_wrap(const stencil_geo *geo, int d, int i) {
  if (geo->periodic[d]) {
    if (i < 0) i += geo->n[d];
    else if (i >= geo->n[d]) i -= geo->n[d];
  }
  return i;
}

/* the first node along d of the stencil at coordinate x, unwrapped:
** what shape_eval returns, without the weights */
STENCIL_INLINE int stencil_first(const stencil_geo *geo, int kind, int d,
                                 double x) {
  double xi = (x - geo->lo[d]) * geo->inv_h + geo->off[d];
  return kind == SHAPE_LINEAR ? (int)floor(xi)
         : kind == SHAPE_GIMP ? (int)floor(xi + 0.5) - 1
                              : (int)floor(xi - 0.5);
}

/* 1-D part: node indices (wrapped) and weights along d */
STENCIL_INLINE int stencil_1d(const stencil_geo *geo, int kind, int d,
                              double x, double lp, int32_t *idx, double *w,
                              double *dw) {
  int nw = shape_width(kind), k;
  double xi = (x - geo->lo[d]) * geo->inv_h + geo->off[d];
  int i0 = shape_eval(kind, xi, lp, w, dw);
  for (k = 0; k < nw; k++) {
    idx[k] = stencil_wrap(geo, d, i0 + k);
    dw[k] *= geo->inv_h;
  }
  return nw;
}

STENCIL_INLINE void stencil_eval(const stencil_geo *geo, int kind,
                                 const double *x, double lp, stencil *st) {
  int32_t ix[SHAPE_MAXW], iy[SHAPE_MAXW];
  double wx[SHAPE_MAXW], wy[SHAPE_MAXW], dx[SHAPE_MAXW], dy[SHAPE_MAXW];
  int nw = stencil_1d(geo, kind, 0, x[0], lp, ix, wx, dx), a, b, k = 0;
  stencil_1d(geo, kind, 1, x[1], lp, iy, wy, dy);
#if DIM == 2
  for (b = 0; b < nw; b++)
    for (a = 0; a < nw; a++, k++) {
      st->node[k] = ix[a] + geo->n[0] * iy[b];
      st->w[k] = wx[a] * wy[b];
      st->dw[0][k] = dx[a] * wy[b];
      st->dw[1][k] = wx[a] * dy[b];
    }
#elif DIM == 3
  {
    int32_t iz[SHAPE_MAXW], plane = geo->n[0] * geo->n[1];
    double wz[SHAPE_MAXW], dz[SHAPE_MAXW];
    int c;
    stencil_1d(geo, kind, 2, x[2], lp, iz, wz, dz);
    for (c = 0; c < nw; c++)
      for (b = 0; b < nw; b++) {
        int32_t row = geo->n[0] * iy[b] + plane * iz[c];
        double wyz = wy[b] * wz[c], dyz = dy[b] * wz[c], wdz = wy[b] * dz[c];
        for (a = 0; a < nw; a++, k++) {
          st->node[k] = ix[a] + row;
          st->w[k] = wx[a] * wyz;
          st->dw[0][k] = dx[a] * wyz;
          st->dw[1][k] = wx[a] * dyz;
          st->dw[2][k] = wx[a] * wdz;
        }
      }
  }
#else
#error "stencil_eval: DIM must be 2 or 3"
#endif
  st->n = k;
}

/*
** The stencil with each node's offset from the particle, r = x_i - x_p
** (unwrapped: across a periodic seam it is the near image), for the
** affine transfer (APIC).  A separate function so that the other phases
** store nothing they do not read.
*/
STENCIL_INLINE void stencil_eval_r(const stencil_geo *geo, int kind,
                                   const double *x, double lp, stencil *st,
                                   double r[DIM][STENCIL_MAX]) {
  double rr[DIM][SHAPE_MAXW], h = 1.0 / geo->inv_h;
  int nw = shape_width(kind), a, b, k = 0, d;
  stencil_eval(geo, kind, x, lp, st);
  for (d = 0; d < DIM; d++) {
    double xi = (x[d] - geo->lo[d]) * geo->inv_h + geo->off[d];
    /* the first node of the stencil, as shape.h chooses it */
    int i0 = kind == SHAPE_LINEAR ? (int)floor(xi)
             : kind == SHAPE_GIMP ? (int)floor(xi + 0.5) - 1
                                  : (int)floor(xi - 0.5);
    for (a = 0; a < nw; a++) rr[d][a] = (i0 + a - xi) * h;
  }
#if DIM == 2
  for (b = 0; b < nw; b++)
    for (a = 0; a < nw; a++, k++) {
      r[0][k] = rr[0][a];
      r[1][k] = rr[1][b];
    }
#elif DIM == 3
  {
    int c;
    for (c = 0; c < nw; c++)
      for (b = 0; b < nw; b++)
        for (a = 0; a < nw; a++, k++) {
          r[0][k] = rr[0][a];
          r[1][k] = rr[1][b];
          r[2][k] = rr[2][c];
        }
  }
#else
#error "stencil_eval_r: DIM must be 2 or 3"
#endif
}

/* the nodes of a stencil, nw^DIM */
STENCIL_INLINE int stencil_size(int kind) {
  int r = 1, d;
  for (d = 0; d < DIM; d++) r *= shape_width(kind);
  return r;
}

/* stencil entries per node row along the last dimension: entry k lies
** on row k / stencil_rowlen (bands.h) */
STENCIL_INLINE int stencil_rowlen(int kind) {
  int r = 1, d;
  for (d = 1; d < DIM; d++) r *= shape_width(kind);
  return r;
}

/* node indices only (for marking shared nodes), in stencil_eval's order */
STENCIL_INLINE int stencil_nodes(const grid *g, int kind, const double *x,
                                 int32_t *node) {
  int nw = shape_width(kind), a, k = 0, d, n = 1;
  int32_t idx[DIM][SHAPE_MAXW];
  int i[DIM], t[DIM];
  for (d = 0; d < DIM; d++) {
    double xi = (x[d] - g->lo[d]) * g->inv_h + (g->periodic[d] ? 0 : g->pad);
    int i0 = kind == SHAPE_LINEAR  ? (int)floor(xi)
             : kind == SHAPE_GIMP  ? (int)floor(xi + 0.5) - 1
                                   : (int)floor(xi - 0.5);
    for (a = 0; a < nw; a++) idx[d][a] = grid_wrap(g, d, i0 + a);
    n *= nw;
    t[d] = 0;
  }
  /* an odometer over the DIM indices, x fastest (counted up digit by
  ** digit: the kind is not a constant here, and k % nw would divide) */
  for (k = 0; k < n; k++) {
    for (d = 0; d < DIM; d++) i[d] = idx[d][t[d]];
    node[k] = grid_node(g, i);
    for (d = 0; d < DIM && ++t[d] == nw; d++) t[d] = 0;
  }
  return k;
}

#endif
