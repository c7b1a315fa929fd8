/*
** diag_hotspot.c - connected hot regions of particles (diag_hotspot.h):
** the hot particles binned by a counting sort, neighbouring bins joined
** by union-find, then each set's sums in particle order.  The regions
** come out sorted by area (then by their first particle's id), so the
** answer is a function of the particles alone.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "diag_hotspot.h"
#include "vec.h"

static size_t uf_root(size_t *up, size_t i) {
  while (up[i] != i) {
    up[i] = up[up[i]]; /* path halving */
    i = up[i];
  }
  return i;
}

static void uf_join(size_t *up, size_t a, size_t b) {
  a = uf_root(up, a);
  b = uf_root(up, b);
  if (a == b) return;
  if (a < b) up[b] = a; else up[a] = b; /* the smaller index is the root */
}

/* the particle's current volume: vol0 det F (the in-plane determinant
** in 2-D, plane strain: an area) */
static double volume(const particles *ps, size_t i) {
  double F[NTENS];
  int k;
  for (k = 0; k < NTENS; k++) F[k] = ps->F[k][i];
  return ps->vol0[i] * vec_det(F);
}

static int bycmp(const void *x, const void *y) {
  const hotspot *a = x, *b = y;
  if (a->area != b->area) return a->area > b->area ? -1 : 1;
  return (a->first > b->first) - (a->first < b->first);
}

static int grow(hotspots *out, size_t n) {
  hotspot *r;
  if (n <= out->cap) return 0;
  if (!(r = realloc(out->r, n * sizeof *r))) return -1;
  out->r = r;
  out->cap = n;
  return 0;
}

int diag_hotspots(sim *s, double threshold, double link, hotspots *out) {
  const particles *ps = &s->ps;
  const double *T, *lam = NULL;
  size_t *hot = NULL, *up = NULL, *bin = NULL, *start = NULL, *order = NULL;
  size_t *slot = NULL, nhot = 0, nbin = 1, i, j, k;
  double L = link * s->g.h / s->cfg.ppc;
  long nb[DIM];
  int d, rc = -1;
  out->n = 0;
  out->area_hot = out->area_all = 0;
  if (s->ftemp < 0) {
    snprintf(s->err, sizeof s->err, "hotspots: the scene has no temperature "
             "(no body or material sets one)");
    return -1;
  }
  T = particles_comp(ps, s->ftemp, 0);
  if (s->freact >= 0) lam = particles_comp(ps, s->freact, 0);
  for (d = 0; d < DIM; d++) {
    nb[d] = (long)ceil((s->g.hi[d] - s->g.lo[d]) / L);
    if (nb[d] < 1) nb[d] = 1;
    nbin *= (size_t)nb[d];
  }
  for (i = 0; i < ps->n; i++) {
    if (s->bmat[ps->body[i]] < 0) continue;
    out->area_all += volume(ps, i);
    if (T[i] > threshold) nhot++;
  }
  hot = malloc((nhot + 1) * sizeof *hot);
  up = malloc((nhot + 1) * sizeof *up);
  bin = malloc((nhot + 1) * sizeof *bin);
  order = malloc((nhot + 1) * sizeof *order);
  slot = malloc((nhot + 1) * sizeof *slot);
  start = calloc(nbin + 1, sizeof *start);
  if (!hot || !up || !bin || !order || !slot || !start) goto oom;
  /* the hot particles and their bins */
  for (i = 0, k = 0; i < ps->n; i++) {
    size_t b = 0;
    if (s->bmat[ps->body[i]] < 0 || !(T[i] > threshold)) continue;
    for (d = DIM - 1; d >= 0; d--) {
      long c = (long)floor((ps->x[d][i] - s->g.lo[d]) / L);
      if (c < 0) c = 0;
      if (c >= nb[d]) c = nb[d] - 1;
      b = b * (size_t)nb[d] + (size_t)c;
    }
    hot[k] = i;
    bin[k] = b;
    up[k] = k;
    start[b + 1]++;
    k++;
  }
  for (j = 0; j < nbin; j++) start[j + 1] += start[j];
  for (k = 0; k < nhot; k++) order[start[bin[k]]++] = k; /* stable */
  for (j = nbin; j > 0; j--) start[j] = start[j - 1];
  start[0] = 0;
  /* each hot particle against those in its bin and the 3^DIM - 1 around */
  for (k = 0; k < nhot; k++) {
    long c[DIM], o[DIM];
    size_t b = bin[k], q;
    int m, nn = 1;
    for (d = 0; d < DIM; d++) {
      c[d] = (long)(b % (size_t)nb[d]);
      b /= (size_t)nb[d];
      nn *= 3;
    }
    for (m = 0; m < nn; m++) {
      size_t nbn = 0;
      int mm = m, out_of = 0;
      for (d = 0; d < DIM; d++) {
        o[d] = c[d] + mm % 3 - 1;
        mm /= 3;
        if (o[d] < 0 || o[d] >= nb[d]) out_of = 1;
      }
      if (out_of) continue;
      for (d = DIM - 1; d >= 0; d--) nbn = nbn * (size_t)nb[d] + (size_t)o[d];
      for (q = start[nbn]; q < start[nbn + 1]; q++) {
        size_t kk = order[q], a = hot[k], bb = hot[kk];
        double r2 = 0;
        if (kk <= k) continue;
        for (d = 0; d < DIM; d++) {
          double dx = ps->x[d][a] - ps->x[d][bb];
          r2 += dx * dx;
        }
        if (r2 <= L * L) uf_join(up, k, kk);
      }
    }
  }
  /* one region per root, summed in particle order */
  for (k = 0; k < nhot; k++) slot[k] = (size_t)-1;
  for (k = 0; k < nhot; k++) {
    size_t r = uf_root(up, k), i2 = hot[k];
    hotspot *h;
    double v = volume(ps, i2), m = ps->m[i2];
    if (slot[r] == (size_t)-1) {
      if (out->n == out->cap && grow(out, 2 * out->cap + 8)) goto oom;
      slot[r] = out->n++;
      h = &out->r[slot[r]];
      memset(h, 0, sizeof *h);
      h->Tmax = -HUGE_VAL;
      h->first = ps->id[i2];
    }
    h = &out->r[slot[r]];
    h->n++;
    h->area += v;
    h->mass += m;
    h->Tmean += m * T[i2];
    if (T[i2] > h->Tmax) h->Tmax = T[i2];
    for (d = 0; d < DIM; d++) h->x[d] += m * ps->x[d][i2];
    if (lam) h->reacted += m * lam[i2];
    if (ps->id[i2] < h->first) h->first = ps->id[i2];
    out->area_hot += v;
  }
  for (j = 0; j < out->n; j++) {
    hotspot *h = &out->r[j];
    h->Tmean /= h->mass;
    h->reacted /= h->mass;
    for (d = 0; d < DIM; d++) h->x[d] /= h->mass;
  }
  if (out->n > 1) qsort(out->r, out->n, sizeof *out->r, bycmp);
  rc = 0;
  goto done;
oom:
  snprintf(s->err, sizeof s->err, "hotspots: out of memory");
done:
  free(hot);
  free(up);
  free(bin);
  free(order);
  free(slot);
  free(start);
  return rc;
}

void hotspots_free(hotspots *h) {
  free(h->r);
  memset(h, 0, sizeof *h);
}
