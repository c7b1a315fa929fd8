/*
** bands.c - the plan of a deterministic scatter (see bands.h): each
** part's reach in node rows, measured in parallel, then the first part
** and the count of parts per row.
*/
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "bands.h"

int bands_init(bands *b, int nrows) {
  memset(b, 0, sizeof *b);
  b->first = malloc((size_t)nrows * sizeof *b->first);
  b->count = malloc((size_t)nrows);
  b->nrows = nrows;
  return b->first && b->count ? 0 : -1;
}

void bands_free(bands *b) {
  free(b->first);
  free(b->count);
  memset(b, 0, sizeof *b);
}

typedef struct reach_job {
  bands *b;
  stencil_geo geo;
  int kind;
  const double *y;
} reach_job;

/* part t: the lowest and highest first node row of its particles */
static void reach_part(void *arg, int t, int nparts) {
  reach_job *j = arg;
  bands *b = j->b;
  int lo = INT_MAX, hi = INT_MIN;
  size_t i;
  for (i = b->i[t]; i < b->i[t + 1]; i++) {
    int r = stencil_first(&j->geo, j->kind, BANDS_DIM, j->y[i]);
    if (r < lo) lo = r;
    if (r > hi) hi = r;
  }
  b->lo[t] = lo;
  b->hi[t] = hi == INT_MIN ? hi : hi + shape_width(j->kind) - 1;
}

/* part t: the first and last particle with a node row that part t
** writes in pass 2, so that pass 2 looks at those alone */
static void span_part(void *arg, int t, int nparts) {
  reach_job *j = arg;
  bands *b = j->b;
  const int nw = shape_width(j->kind);
  size_t i, j0 = b->i[t + 1], j1 = b->i[t];
  for (i = b->i[t]; i < b->i[t + 1]; i++) {
    int r = stencil_first(&j->geo, j->kind, BANDS_DIM, j->y[i]), k;
    for (k = 0; k < nw; k++)
      if (b->first[stencil_wrap(&j->geo, BANDS_DIM, r + k)] != t) {
        if (i < j0) j0 = i;
        j1 = i + 1;
        break;
      }
  }
  b->j[t][0] = j0 < j1 ? j0 : b->i[t];
  b->j[t][1] = j0 < j1 ? j1 : b->i[t];
}

void bands_plan(bands *b, par *p, const grid *g, int kind, const double *y,
                size_t n) {
  int nb = par_threads(p), t, r;
  reach_job j;
  b->nb = 0;
  b->plans++;
  if (nb < 2 || n < (size_t)nb * BANDS_MIN) return;
  for (t = 0; t <= nb; t++) b->i[t] = n * (size_t)t / (size_t)nb;
  j.b = b;
  stencil_geo_init(&j.geo, g);
  j.kind = kind;
  j.y = y;
  par_run(p, reach_part, &j);
  memset(b->count, 0, (size_t)b->nrows);
  for (t = 0; t < nb; t++) {
    int lo = b->lo[t], hi = b->hi[t];
    if (lo > hi) continue; /* no particles */
    if (hi - lo + 1 >= b->nrows) { lo = 0; hi = b->nrows - 1; }
    for (r = lo; r <= hi; r++) {
      int w = stencil_wrap(&j.geo, BANDS_DIM, r);
      if (b->count[w]++ == 0) b->first[w] = t;
      else if (b->count[w] > 2) return; /* one pass in order */
    }
  }
  par_run(p, span_part, &j);
  b->nb = nb;
  b->split++;
}

typedef struct run_job {
  const bands *b;
  bands_fn *fn;
  void *arg;
  int pass;
} run_job;

static void run_part(void *arg, int t, int nparts) {
  run_job *j = arg;
  size_t i0, i1;
  bands_span(j->b, t, j->pass, &i0, &i1);
  j->fn(j->arg, i0, i1, t, j->pass);
}

void bands_run(const bands *b, par *p, bands_fn *fn, void *arg) {
  run_job j = {b, fn, arg, 1};
  par_run(p, run_part, &j);
  j.pass = 2;
  par_run(p, run_part, &j);
}
