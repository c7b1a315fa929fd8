/*
** particles.c - the structure-of-arrays particle store.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "par.h"
#include "particles.h"

static const char *xyz[] = {"x", "y", "z"};
static const char *tens[] = DIM_TENSOR_NAMES;
static const char *sten[] = DIM_STRESS_NAMES;

static int add(particles *ps, const char *name, int ncomp, int type,
               const char *unit, unsigned flags, void **slots[],
               const char **cnames) {
  pfield *f;
  int c;
  if (ps->nfields >= PF_MAXFIELDS || ncomp < 1 || ncomp > PF_MAXCOMP)
    return -1;
  f = &ps->fields[ps->nfields];
  memset(f, 0, sizeof *f);
  strncpy(f->name, name, sizeof f->name - 1);
  strncpy(f->unit, unit ? unit : "", sizeof f->unit - 1);
  f->ncomp = ncomp;
  f->type = type;
  f->flags = flags;
  for (c = 0; c < ncomp; c++) {
    f->slot[c] = slots ? slots[c] : &f->own[c];
    f->comp_names[c] = cnames ? cnames[c] : NULL;
    if (ps->cap) {
      *f->slot[c] = calloc(ps->cap, 8);
      if (!*f->slot[c]) return -1;
    }
  }
  return ps->nfields++;
}

void particles_init(particles *ps) {
  void **s[PF_MAXCOMP];
  int d;
  memset(ps, 0, sizeof *ps);
  for (d = 0; d < DIM; d++) s[d] = (void **)&ps->x[d];
  add(ps, "position", DIM, PF_DOUBLE, "L", PF_OUTPUT | PF_RESTART, s, xyz);
  for (d = 0; d < DIM; d++) s[d] = (void **)&ps->v[d];
  add(ps, "velocity", DIM, PF_DOUBLE, "L/T", PF_OUTPUT | PF_RESTART, s, xyz);
  for (d = 0; d < NSTRESS; d++) s[d] = (void **)&ps->s[d];
  add(ps, "stress", NSTRESS, PF_DOUBLE, "M/(L T^2)", PF_OUTPUT | PF_RESTART,
      s, sten);
  s[0] = (void **)&ps->body;
  add(ps, "body", 1, PF_INT32, "", PF_OUTPUT | PF_RESTART, s, NULL);
  s[0] = (void **)&ps->m;
  add(ps, "mass", 1, PF_DOUBLE, "M", PF_OUTPUT | PF_RESTART, s, NULL);
  s[0] = (void **)&ps->vol0;
  add(ps, "volume0", 1, PF_DOUBLE, DIM_VOLUME_UNIT, PF_OUTPUT | PF_RESTART, s, NULL);
  for (d = 0; d < NTENS; d++) s[d] = (void **)&ps->F[d];
  add(ps, "F", NTENS, PF_DOUBLE, "1", PF_OUTPUT | PF_RESTART, s, tens);
  for (d = 0; d < NTENS; d++) s[d] = (void **)&ps->L[d];
  add(ps, "gradv", NTENS, PF_DOUBLE, "1/T", PF_RESTART, s, tens);
  s[0] = (void **)&ps->lp;
  add(ps, "halfsize", 1, PF_DOUBLE, "cells", PF_RESTART, s, NULL);
  s[0] = (void **)&ps->cell;
  add(ps, "cell", 1, PF_INT32, "", 0, s, NULL);
  s[0] = (void **)&ps->id;
  add(ps, "id", 1, PF_INT32, "", PF_OUTPUT | PF_RESTART, s, NULL);
}

void particles_free(particles *ps) {
  int f, c;
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++) free(*ps->fields[f].slot[c]);
  free(ps->scratch);
  free(ps->perm);
  free(ps->count);
  memset(ps, 0, sizeof *ps);
}

int particles_reserve(particles *ps, size_t cap) {
  int f, c;
  void *p;
  if (cap <= ps->cap) return 0;
  if (cap < 2 * ps->cap) cap = 2 * ps->cap;
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++) {
      p = realloc(*ps->fields[f].slot[c], cap * 8);
      if (!p) return -1;
      memset((char *)p + ps->cap * 8, 0, (cap - ps->cap) * 8);
      *ps->fields[f].slot[c] = p;
    }
  p = realloc(ps->scratch, cap * 8);
  if (!p) return -1;
  ps->scratch = p;
  p = realloc(ps->perm, cap * sizeof(size_t));
  if (!p) return -1;
  ps->perm = p;
  ps->cap = cap;
  return 0;
}

/* A shrink that fails leaves the array's larger block in place, which
** is as good: every array only has to hold at least cap entries. */
void particles_fit(particles *ps) {
  size_t cap = ps->n ? ps->n : 1;
  int f, c;
  void *p;
  if (cap >= ps->cap) return;
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++)
      if ((p = realloc(*ps->fields[f].slot[c], cap * 8))) *ps->fields[f].slot[c] = p;
  if ((p = realloc(ps->scratch, cap * 8))) ps->scratch = p;
  if ((p = realloc(ps->perm, cap * sizeof(size_t)))) ps->perm = p;
  ps->cap = cap;
}

int particles_add_field(particles *ps, const char *name, int ncomp,
                        int type, const char *unit, unsigned flags) {
  int f = particles_find(ps, name);
  if (f >= 0)
    return (ps->fields[f].ncomp == ncomp && ps->fields[f].type == type) ? f
                                                                        : -1;
  return add(ps, name, ncomp, type, unit, flags, NULL, NULL);
}

int particles_name_comps(pfield *f, const char *joined) {
  static const char *const *const sets[] = {xyz, tens, sten};
  static const int sizes[] = {DIM, NTENS, NSTRESS};
  size_t k;
  int c;
  for (k = 0; k < sizeof sets / sizeof sets[0]; k++) {
    char buf[128];
    size_t len = 0;
    if (sizes[k] != f->ncomp) continue;
    for (c = 0; c < f->ncomp; c++)
      len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%s",
                              c ? "," : "", sets[k][c]);
    if (strcmp(buf, joined) == 0) {
      for (c = 0; c < f->ncomp; c++) f->comp_names[c] = sets[k][c];
      return 1;
    }
  }
  return 0;
}

const char *particles_tens_name(int c) {
  return c >= 0 && c < NTENS ? tens[c] : NULL;
}

int particles_find(const particles *ps, const char *name) {
  int f;
  for (f = 0; f < ps->nfields; f++)
    if (strcmp(ps->fields[f].name, name) == 0) return f;
  return -1;
}

size_t particles_push(particles *ps) {
  size_t i = ps->n;
  int f, c, d;
  if (particles_reserve(ps, i + 1 < 64 ? 64 : i + 1)) return (size_t)-1;
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++)
      memset((char *)*ps->fields[f].slot[c] + i * 8, 0, 8);
  for (d = 0; d < DIM; d++) ps->F[d * DIM + d][i] = 1.0;
  ps->id[i] = (int32_t)(++ps->nmade);
  ps->n++;
  return i;
}

/*
** Counting sort: stable, so particles of one cell keep their relative
** order and the result is the same on every run.  Each array is gathered
** into the scratch buffer and the two pointers are swapped.
*/
/* one array of the sort: dst[j] = src[from[j]] over part t of the
** destinations (a gather: each thread writes a stretch of its own) */
typedef struct move_job {
  const void *src;
  void *dst;
  const size_t *from;
  size_t n;
  int type;
} move_job;

static void move_part(void *arg, int t, int nparts) {
  const move_job *j = arg;
  size_t i, i0, i1;
  par_range(j->n, t, nparts, &i0, &i1);
  if (j->type == PF_INT32) {
    const int32_t *a = j->src;
    int32_t *b = j->dst;
    for (i = i0; i < i1; i++) b[i] = a[j->from[i]];
  } else {
    const double *a = j->src;
    double *b = j->dst;
    for (i = i0; i < i1; i++) b[i] = a[j->from[i]];
  }
}

int particles_sort(particles *ps, const int32_t *key, size_t ncell, par *p) {
  size_t i, k, sum = 0;
  int f, c;
  if (ncell + 1 > ps->ncount) {
    size_t *q = realloc(ps->count, (ncell + 1) * sizeof *q);
    if (!q) return -1;
    ps->count = q;
    ps->ncount = ncell + 1;
  }
  memset(ps->count, 0, (ncell + 1) * sizeof *ps->count);
  for (i = 0; i < ps->n; i++) ps->count[key[i]]++;
  for (k = 0; k < ncell; k++) {
    size_t t = ps->count[k];
    ps->count[k] = sum;
    sum += t;
  }
  ps->count[ncell] = sum;
  /* where each place's particle comes from: stable, as i runs in order */
  for (i = 0; i < ps->n; i++) ps->perm[ps->count[key[i]]++] = i;
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++) {
      void **slot = ps->fields[f].slot[c];
      move_job j = {*slot, ps->scratch, ps->perm, ps->n, ps->fields[f].type};
      par_run(p, move_part, &j);
      *slot = ps->scratch;
      ps->scratch = (void *)j.src;
    }
  return 0;
}

size_t particles_compact(particles *ps, const unsigned char *keep) {
  size_t i, j;
  int f, c;
  for (f = 0; f < ps->nfields; f++) {
    /* arrays hold cap * 8 bytes, but int32 ones are indexed by 4 */
    size_t sz = ps->fields[f].type == PF_INT32 ? 4 : 8;
    for (c = 0; c < ps->fields[f].ncomp; c++) {
      char *a = *ps->fields[f].slot[c];
      for (i = j = 0; i < ps->n; i++)
        if (keep[i]) {
          if (i != j) memcpy(a + j * sz, a + i * sz, sz);
          j++;
        }
    }
  }
  for (i = j = 0; i < ps->n; i++) j += keep[i] != 0;
  ps->n = j;
  return j;
}

size_t particles_mem(const particles *ps) {
  size_t arrays = 1; /* the scratch buffer */
  int f;
  for (f = 0; f < ps->nfields; f++) arrays += (size_t)ps->fields[f].ncomp;
  return ps->cap * (arrays * 8 + sizeof *ps->perm) +
         ps->ncount * sizeof *ps->count;
}
