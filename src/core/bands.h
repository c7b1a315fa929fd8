/*
** bands.h - which thread adds into which grid node, so that a scatter
** from particles to the grid gives the same sums with any thread count.
**
** The particles are cut into parts of consecutive indices, one per
** thread.  Kept sorted by cell (row by row along the last dimension), a
** part reaches a band of node rows (a row: the nodes of one index along
** the last dimension, a line in 2-D, a plane in 3-D).  Every node's sum must be added in
** the particles' stored order: that is what one thread does, and it is
** what the sums are with any number.  So each node row is written in
** two passes: in the first, by the first part that reaches it; in the
** second, by the part after (if any).  Within a pass no two parts write
** one row, and a row's contributions arrive part by part, each part's in
** its stored order.  This holds while no row is reached by more than two
** parts; when one is (few rows per part, or particles far from sorted
** before the first sort) the plan falls back to one pass in order.
** The plan follows the particles: it is made again from their positions
** for every scatter.
*/
#ifndef mvmpm_bands_h
#define mvmpm_bands_h

#include <stddef.h>
#include <stdint.h>
#include "par.h"
#include "stencil.h"

/* the dimension whose node rows are banded: the slowest in a cell index */
#define BANDS_DIM (DIM - 1)
/* fewer particles per part than this are not worth a second pass */
#define BANDS_MIN 1024

typedef struct bands {
  int nb;               /* parts; 0: one pass over all in order */
  size_t i[PAR_MAX + 1]; /* part b holds particles i[b] .. i[b + 1] - 1 */
  int lo[PAR_MAX], hi[PAR_MAX]; /* node rows part b reaches, unwrapped */
  size_t j[PAR_MAX][2]; /* part b's particles with rows in pass 2: kept
                           sorted, a few at the lower edge */
  int32_t *first;       /* per node row: the first part that reaches it */
  unsigned char *count; /* per node row: the parts that reach it */
  int nrows;
  long plans, split;    /* plans made, and those in two passes */
} bands;

/* room for a grid of nrows node rows; 0 or -1 (out of memory) */
int bands_init(bands *b, int nrows);
void bands_free(bands *b);
/* the plan for the n particles with coordinates y along BANDS_DIM, cut
** into par_threads(p) parts (none with one thread); sets b->nb */
void bands_plan(bands *b, par *p, const grid *g, int kind, const double *y,
                size_t n);

/* A scatter over the plan: fn(arg, i0, i1, part, pass) on each part's
** span of particles (bands_span), all parts of pass 1 over the threads,
** then all of pass 2.  Needs a plan (b->nb > 0). */
typedef void bands_fn(void *arg, size_t i0, size_t i1, int part, int pass);
void bands_run(const bands *b, par *p, bands_fn *fn, void *arg);

/* the particles part blk looks at in a pass: all of its own in pass 1,
** in pass 2 only the stretch that has rows to write */
static inline void bands_span(const bands *b, int blk, int pass, size_t *i0,
                              size_t *i1) {
  *i0 = pass == 1 ? b->i[blk] : b->j[blk][0];
  *i1 = pass == 1 ? b->i[blk + 1] : b->j[blk][1];
}

/* For a particle of part blk at coordinate y: per stencil row k, whether
** this pass writes it (pass 1 or 2); nonzero if any row is written. */
STENCIL_INLINE int bands_rows(const bands *b, const stencil_geo *geo,
                              int kind, double y, int blk, int pass,
                              unsigned char *mine) {
  int r0 = stencil_first(geo, kind, BANDS_DIM, y), k, any = 0;
  for (k = 0; k < shape_width(kind); k++) {
    int r = stencil_wrap(geo, BANDS_DIM, r0 + k);
    mine[k] = (b->first[r] == blk) == (pass == 1);
    any |= mine[k];
  }
  return any;
}

#endif
