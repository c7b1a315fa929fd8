/*
** grid.c - allocation and per-step reset of the background grid, and the
** sparse per-field slots of shared nodes.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grid.h"

static int nodes_along(const double lo[DIM], const double hi[DIM], double h,
                       int d, int periodic, int pad) {
  int cells = (int)((hi[d] - lo[d]) / h + 0.5);
  return periodic ? cells : cells + 1 + 2 * pad;
}

double grid_bytes(const double lo[DIM], const double hi[DIM], double h,
                  int pad) {
  double nodes = 1;
  int d;
  /* in doubles: this is what refuses a grid whose counts would not fit
  ** an int (a 1e308 domain, a 1e-300 cell), before nodes_along casts */
  for (d = 0; d < DIM; d++)
    nodes *= floor((hi[d] - lo[d]) / h + 0.5) + 1 + 2 * pad;
  /* m, p, f, q, fi, ni per dimension, owner, head */
  return nodes * (8.0 * (1 + 5 * DIM) + 8.0);
}

int grid_init(grid *g, const double lo[DIM], const double hi[DIM], double h,
              const int periodic[DIM], int pad) {
  int d;
  memset(g, 0, sizeof *g);
  g->h = h;
  g->inv_h = 1.0 / h;
  g->pad = pad;
  g->nnodes = 1;
  for (d = 0; d < DIM; d++) {
    g->lo[d] = lo[d];
    g->hi[d] = hi[d];
    g->periodic[d] = periodic[d];
    g->cells[d] = (int)((hi[d] - lo[d]) / h + 0.5);
    g->n[d] = nodes_along(lo, hi, h, d, periodic[d], pad);
    g->nnodes *= (size_t)g->n[d];
  }
  g->m = calloc(g->nnodes, sizeof(double));
  g->owner = malloc(g->nnodes * sizeof(int32_t));
  g->head = malloc(g->nnodes * sizeof(int32_t));
  if (!g->m || !g->owner || !g->head) return -1;
  for (d = 0; d < DIM; d++) {
    g->p[d] = calloc(g->nnodes, sizeof(double));
    g->f[d] = calloc(g->nnodes, sizeof(double));
    g->q[d] = calloc(g->nnodes, sizeof(double));
    g->fi[d] = calloc(g->nnodes, sizeof(double));
    g->ni[d] = calloc(g->nnodes, sizeof(double));
    if (!g->p[d] || !g->f[d] || !g->q[d] || !g->fi[d] || !g->ni[d]) return -1;
  }
  memset(g->owner, 0xff, g->nnodes * sizeof(int32_t));
  memset(g->head, 0xff, g->nnodes * sizeof(int32_t));
  return 0;
}

static void slots_free(grid *g) {
  int d;
  free(g->snext); free(g->sfield); free(g->snode); free(g->sm);
  free(g->sext); free(g->sb); free(g->scut); free(g->sbonded);
  free(g->sbo); free(g->smo); free(g->ssw); free(g->srm);
  free(g->sft); free(g->sfok);
  for (d = 0; d < DIM; d++) free(g->sru[d]);
  for (d = 0; d < DIM * (DIM + 1) / 2; d++) free(g->sst[d]);
  for (d = 0; d < DIM; d++) free(g->sv[d]);
  free(g->sw);
  for (d = 0; d < DIM; d++) free(g->sx[d]);
  for (d = 0; d < DIM * (DIM + 1) / 2; d++) free(g->sxx[d]);
  free(g->scs); free(g->sdm); free(g->sdn);
  for (d = 0; d < DIM; d++) free(g->sci[d]);
  for (d = 0; d < DIM; d++) {
    free(g->sp[d]); free(g->sf[d]); free(g->sq[d]);
    free(g->sg[d]); free(g->sn[d]);
    free(g->sfi[d]); free(g->sni[d]);
    free(g->sbi[d]); free(g->sbf[d]);
  }
}

void grid_free(grid *g) {
  int d;
  free(g->m); free(g->owner); free(g->head); free(g->shared);
  for (d = 0; d < DIM; d++) {
    free(g->p[d]); free(g->f[d]); free(g->q[d]);
    free(g->fi[d]); free(g->ni[d]);
  }
  slots_free(g);
  memset(g, 0, sizeof *g);
}

size_t grid_mem(const grid *g) {
  size_t dense = g->nnodes * ((1 + 5 * DIM) * sizeof(double) + 2 * sizeof(int32_t));
  size_t slot = g->slotcap * (3 * sizeof(int32_t) + (2 + 7 * DIM) * sizeof(double));
  size_t mom = g->momcap * (1 + DIM + DIM * (DIM + 1) / 2) * sizeof(double);
  size_t coh = g->cohcap * (3 + DIM) * sizeof(double);
  return dense + slot + mom + coh + g->sharedcap * sizeof(int32_t);
}

void grid_clear(grid *g, size_t i0, size_t i1, int clear_q) {
  size_t n = (i1 - i0) * sizeof(double);
  int d;
  memset(g->m + i0, 0, n);
  for (d = 0; d < DIM; d++) {
    memset(g->p[d] + i0, 0, n);
    memset(g->f[d] + i0, 0, n);
    if (clear_q) memset(g->q[d] + i0, 0, n);
    memset(g->fi[d] + i0, 0, n);
    memset(g->ni[d] + i0, 0, n);
  }
  memset(g->owner + i0, 0xff, (i1 - i0) * sizeof(int32_t));
}

void grid_reset(grid *g, int clear_q) {
  grid_clear(g, 0, g->nnodes, clear_q);
  grid_reset_slots(g);
}

void grid_reset_slots(grid *g) {
  size_t k;
  /* only shared nodes carry slot heads; clear just those */
  for (k = 0; k < g->nshared; k++) g->head[g->shared[k]] = -1;
  g->nshared = 0;
  g->nslot = 0;
}

#define GROW(ptr, type, cap)                                \
  do {                                                      \
    void *np_ = realloc(ptr, (cap) * sizeof(type));         \
    if (!np_) return -1;                                    \
    ptr = np_;                                              \
  } while (0)

/* Slots grow geometrically: after the first steps of a run the pool is
** large enough and no step allocates. */
static int slots_grow(grid *g) {
  size_t cap = g->slotcap ? 2 * g->slotcap : 1024;
  int d;
  GROW(g->snext, int32_t, cap); GROW(g->sfield, int32_t, cap);
  GROW(g->snode, int32_t, cap); GROW(g->sm, double, cap);
  GROW(g->sext, double, cap);
  GROW(g->sb, double, cap); GROW(g->scut, double, cap);
  GROW(g->sbonded, unsigned char, cap);
  GROW(g->sbo, double, cap); GROW(g->smo, double, cap);
  GROW(g->ssw, double, cap); GROW(g->srm, double, cap);
  GROW(g->sft, double, cap); GROW(g->sfok, unsigned char, cap);
  for (d = 0; d < DIM; d++) GROW(g->sru[d], double, cap);
  for (d = 0; d < DIM * (DIM + 1) / 2; d++) GROW(g->sst[d], double, cap);
  for (d = 0; d < DIM; d++) GROW(g->sv[d], double, cap);
  for (d = 0; d < DIM; d++) {
    GROW(g->sp[d], double, cap); GROW(g->sf[d], double, cap);
    GROW(g->sq[d], double, cap); GROW(g->sg[d], double, cap);
    GROW(g->sn[d], double, cap);
    GROW(g->sfi[d], double, cap); GROW(g->sni[d], double, cap);
    GROW(g->sbi[d], double, cap); GROW(g->sbf[d], double, cap);
  }
  g->slotcap = cap;
  return 0;
}

/* the moments' arrays, as many as the slots, only while they are used */
static int moments_grow(grid *g) {
  size_t cap = g->slotcap;
  int d;
  GROW(g->sw, double, cap);
  for (d = 0; d < DIM; d++) GROW(g->sx[d], double, cap);
  for (d = 0; d < DIM * (DIM + 1) / 2; d++) GROW(g->sxx[d], double, cap);
  g->momcap = cap;
  return 0;
}

/* the cohesive law's arrays, likewise */
static int cohesion_grow(grid *g) {
  size_t cap = g->slotcap;
  int d;
  GROW(g->scs, double, cap); GROW(g->sdm, double, cap);
  GROW(g->sdn, double, cap);
  for (d = 0; d < DIM; d++) GROW(g->sci[d], double, cap);
  g->cohcap = cap;
  return 0;
}

int grid_slots_reserve(grid *g, size_t nslot, size_t nshared) {
  while (g->slotcap < nslot)
    if (slots_grow(g)) return -1;
  if (g->moments && g->momcap < g->slotcap && moments_grow(g)) return -1;
  if (g->cohesive && g->cohcap < g->slotcap && cohesion_grow(g)) return -1;
  if (g->sharedcap < nshared) {
    size_t cap = g->sharedcap ? 2 * g->sharedcap : 1024;
    while (cap < nshared) cap *= 2;
    GROW(g->shared, int32_t, cap);
    g->sharedcap = cap;
  }
  return 0;
}

/* whole arrays at a time: the slots of a part are consecutive */
void grid_slots_clear(grid *g, size_t s0, size_t s1) {
  size_t n = (s1 - s0) * sizeof(double), s;
  int d;
  memset(g->sm + s0, 0, n);
  for (s = s0; s < s1; s++) g->sext[s] = -1e300;
  memset(g->sb + s0, 0, n);
  memset(g->scut + s0, 0, n);
  memset(g->sbonded + s0, 0, s1 - s0);
  memset(g->sbo + s0, 0, n);
  memset(g->smo + s0, 0, n);
  memset(g->ssw + s0, 0, n);
  memset(g->srm + s0, 0, n);
  for (d = 0; d < DIM; d++) memset(g->sru[d] + s0, 0, n);
  for (d = 0; d < DIM * (DIM + 1) / 2; d++) memset(g->sst[d] + s0, 0, n);
  for (d = 0; d < DIM; d++) {
    memset(g->sv[d] + s0, 0, n);
    memset(g->sp[d] + s0, 0, n);
    memset(g->sf[d] + s0, 0, n);
    memset(g->sq[d] + s0, 0, n);
    memset(g->sg[d] + s0, 0, n);
    memset(g->sn[d] + s0, 0, n);
    memset(g->sfi[d] + s0, 0, n);
    memset(g->sni[d] + s0, 0, n);
    memset(g->sbi[d] + s0, 0, n); /* sbf: written where it is read */
  }
  if (g->moments) {
    memset(g->sw + s0, 0, n);
    for (d = 0; d < DIM; d++) memset(g->sx[d] + s0, 0, n);
    for (d = 0; d < DIM * (DIM + 1) / 2; d++) memset(g->sxx[d] + s0, 0, n);
  }
  if (g->cohesive) {
    memset(g->scs + s0, 0, n);
    memset(g->sdm + s0, 0, n);
    memset(g->sdn + s0, 0, n);
    for (d = 0; d < DIM; d++) memset(g->sci[d] + s0, 0, n);
  }
}
