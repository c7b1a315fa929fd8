/*
** diag_overlap.c - bodies buried in one another (diag_overlap.h).
**
** Cost O(particles + cells): the particles are bucketed by cell with a
** counting sort, each cell's holder is the mode of its bucket, and only
** particles whose own cell another body holds look at their
** neighbourhood.  A cell's bucket holds few distinct bodies (its
** particles come from at most the few bodies meeting there), so the
** mode is a short linear tally.
*/
#include <stdlib.h>
#include "diag_overlap.h"

#define TALLY 16   /* distinct bodies tallied per cell; more is not met */

/* cell index of x, or -1 outside the domain */
static long cell_of(const grid *g, const double *x) {
  long c = 0, stride = 1;
  int d;
  for (d = 0; d < DIM; d++) {
    double u = (x[d] - g->lo[d]) * g->inv_h;
    long i;
    if (!(u >= 0) || u >= g->cells[d]) return -1;
    i = (long)u;
    c += stride * i;
    stride *= g->cells[d];
  }
  return c;
}

/* the holder of each cell: the body with strictly the most particles */
static void holders(const sim *s, const size_t *start, const size_t *order,
                    long ncell, int32_t *hold) {
  long c;
  for (c = 0; c < ncell; c++) {
    int32_t b[TALLY];
    int cnt[TALLY], nb = 0, k, best = -1, tie = 0;
    size_t j;
    for (j = start[c]; j < start[c + 1]; j++) {
      int32_t bj = s->ps.body[order[j]];
      for (k = 0; k < nb && b[k] != bj; k++) {}
      if (k == nb) {
        if (nb == TALLY) continue;
        b[nb] = bj;
        cnt[nb++] = 0;
      }
      cnt[k]++;
    }
    for (k = 0; k < nb; k++)
      if (best < 0 || cnt[k] > cnt[best]) { best = k; tie = 0; }
      else if (cnt[k] == cnt[best]) tie = 1;
    hold[c] = best < 0 || tie ? -1 : b[best];
  }
}

/* is every cell of the ring at Chebyshev distance r around cell c held
** by body h?  Cells beyond a side that is not periodic are held by none.
** The block's offsets o run over [-r, r]^DIM, x fastest; the ring is
** those with some |o_d| = r */
static int ring_held(const grid *g, const int32_t *hold, const int c[DIM],
                     int r, int32_t h) {
  int o[DIM], d;
  for (d = 0; d < DIM; d++) o[d] = -r;
  for (;;) {
    long cell = 0, stride = 1;
    int edge = 0;
    for (d = 0; d < DIM; d++) edge |= o[d] == -r || o[d] == r;
    for (d = 0; d < DIM && edge; d++) {
      int x = c[d] + o[d];
      if (x < 0 || x >= g->cells[d]) {
        if (!g->periodic[d]) return 0;
        x = ((x % g->cells[d]) + g->cells[d]) % g->cells[d];
      }
      cell += stride * x;
      stride *= g->cells[d];
    }
    if (edge && hold[cell] != h) return 0;
    for (d = 0; d < DIM; d++) {
      if (++o[d] <= r) break;
      o[d] = -r;
    }
    if (d == DIM) return 1;
  }
}

int diag_overlap(const sim *s, int maxdepth, overlap_info *out) {
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  long ncell = 1, c;
  size_t i, *start, *order, *fill;
  long *cellof;
  int32_t *hold;
  int d;
  out->n = 0;
  out->depth = 0;
  out->body = out->host = -1;
  for (d = 0; d < DIM; d++) ncell *= g->cells[d];
  start = calloc((size_t)ncell + 1, sizeof *start);
  fill = malloc(((size_t)ncell + 1) * sizeof *fill);
  order = malloc((ps->n + 1) * sizeof *order);
  cellof = malloc((ps->n + 1) * sizeof *cellof);
  hold = malloc((size_t)ncell * sizeof *hold);
  if (!start || !fill || !order || !cellof || !hold) {
    free(start); free(fill); free(order); free(cellof); free(hold);
    return -1;
  }
  for (i = 0; i < ps->n; i++) {
    double x[DIM];
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    cellof[i] = cell_of(g, x);
    if (cellof[i] >= 0) start[cellof[i] + 1]++;
  }
  for (c = 0; c < ncell; c++) start[c + 1] += start[c];
  for (c = 0; c <= ncell; c++) fill[c] = start[c];
  for (i = 0; i < ps->n; i++)
    if (cellof[i] >= 0) order[fill[cellof[i]]++] = i;
  holders(s, start, order, ncell, hold);
  for (i = 0; i < ps->n; i++) {
    int32_t h, a = ps->body[i];
    int ci[DIM], r;
    long rest;
    if (cellof[i] < 0 || (h = hold[cellof[i]]) < 0 || h == a) continue;
    for (rest = cellof[i], d = 0; d < DIM; d++) {
      ci[d] = (int)(rest % g->cells[d]);
      rest /= g->cells[d];
    }
    for (r = 1; r <= maxdepth && ring_held(g, hold, ci, r, h); r++) {}
    if (r == 1) continue;   /* within a cell of the surface: contact */
    out->n++;
    if (r - 1 > out->depth) {
      out->depth = r - 1;
      out->body = a;
      out->host = h;
    }
  }
  free(start); free(fill); free(order); free(cellof); free(hold);
  return 0;
}
