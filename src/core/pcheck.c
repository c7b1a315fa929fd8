/*
** pcheck.c - particles from a file, judged (pcheck.h).
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pcheck.h"
#include "vec.h"

/* one failure: the dataset, its component, the row, the value, the range */
static int bad(char *err, size_t errlen, const char *path, const pfield *f,
               int c, size_t i, double x, const char *range) {
  char comp[40] = "";
  if (f->ncomp > 1 && c >= 0)
    snprintf(comp, sizeof comp, ", component %d (%s)", c,
             f->comp_names[c] ? f->comp_names[c] : "-");
  snprintf(err, errlen, "%s: dataset '%s'%s, row %zu: %.17g is not %s", path,
           f->name, comp, i, x, range);
  return -1;
}

/* the lower bounds by name: 0 excluded (gt) or included */
typedef struct rule { const char *name; int gt, inf; const char *range; } rule;
static const rule rules[] = {
  {"mass", 1, 0, "in (0, inf)"},
  {"volume0", 1, 0, "in (0, inf)"},
  {"plastic_strain", 0, 0, "in [0, inf)"},
  {"plastic_work", 0, 0, "in [0, inf)"},
  {"viscous_work", 0, 0, "in [0, inf)"},
  {"bond", 0, 1, "in [0, inf]"},
  {NULL, 0, 0, NULL}};

static int reals(const char *path, const particles *ps, const pfield *f,
                 char *err, size_t errlen) {
  const rule *r = rules;
  int c;
  size_t i;
  while (r->name && strcmp(r->name, f->name) != 0) r++;
  for (c = 0; c < f->ncomp; c++) {
    const double *a = *f->slot[c];
    for (i = 0; i < ps->n; i++) {
      double x = a[i];
      if (!r->name) {
        if (!isfinite(x)) return bad(err, errlen, path, f, c, i, x, "finite");
      } else if (isnan(x) || (isinf(x) && !r->inf) || x < 0 ||
                 (r->gt && x == 0))
        return bad(err, errlen, path, f, c, i, x, r->range);
    }
  }
  return 0;
}

static double det(const particles *ps, size_t i) {
  double F[NTENS];
  int k;
  for (k = 0; k < NTENS; k++) F[k] = ps->F[k][i];
  return vec_det(F);
}

static int field_read(const particles *ps, const char *name) {
  int f = particles_find(ps, name);
  return f >= 0 && (ps->fields[f].flags & PF_READ) ? f : -1;
}

int pcheck_particles(const char *path, const particles *ps,
                     const pcheck_lim *lim, char *err, size_t errlen) {
  char range[160];
  size_t i, n = ps->n, top;
  int f, d;
  if (n > INT32_MAX) {
    snprintf(err, errlen, "%s: %zu particles, at most %d", path, n, INT32_MAX);
    return -1;
  }
  for (f = 0; f < ps->nfields; f++)
    if ((ps->fields[f].flags & PF_READ) && ps->fields[f].type == PF_DOUBLE &&
        reals(path, ps, &ps->fields[f], err, errlen))
      return -1;
  if ((f = field_read(ps, "body")) >= 0)
    for (i = 0; i < n; i++)
      if (ps->body[i] < 0 || ps->body[i] >= lim->nbody) {
        snprintf(range, sizeof range, "in [0, %d)%s", lim->nbody,
                 lim->domain ? " (the scene's bodies)" : "");
        return bad(err, errlen, path, &ps->fields[f], 0, i, ps->body[i], range);
      }
  if ((f = field_read(ps, "F")) >= 0)
    for (i = 0; i < n; i++)
      if (!(det(ps, i) > 0))
        return bad(err, errlen, path, &ps->fields[f], -1, i, det(ps, i),
                   "> 0 (that is det F, an inverted or crushed particle)");
  if ((f = field_read(ps, "halfsize")) >= 0)
    for (i = 0; i < n; i++)
      if (!(ps->lp[i] > 0 && ps->lp[i] <= 0.5))
        return bad(err, errlen, path, &ps->fields[f], 0, i, ps->lp[i],
                   "in (0, 0.5] cells");
  if ((f = field_read(ps, "position")) >= 0 && lim->domain)
    for (d = 0; d < DIM; d++)
      for (i = 0; i < n; i++) {
        double x = ps->x[d][i];
        /* settle's rule (g2p.c) */
        if (!(x >= lim->lo[d] && x < lim->hi[d] &&
              (x - lim->lo[d]) / lim->h < lim->cells[d])) {
          snprintf(range, sizeof range, "in [%.17g, %.17g) (the domain: a "
                   "particle that leaves it is removed)", lim->lo[d],
                   lim->hi[d]);
          return bad(err, errlen, path, &ps->fields[f], d, i, x, range);
        }
      }
  if ((f = field_read(ps, "id")) >= 0) {
    unsigned char *seen;
    top = lim->nmade ? lim->nmade : INT32_MAX;
    for (i = 0; i < n; i++)
      if (ps->id[i] < 1 || (size_t)ps->id[i] > top) {
        snprintf(range, sizeof range, "in [1, %zu]%s", top,
                 lim->nmade ? " (the particles made so far)" : "");
        return bad(err, errlen, path, &ps->fields[f], 0, i, ps->id[i], range);
      }
    /* a bit per id up to the largest: fewer bytes than the ids had */
    for (top = 0, i = 0; i < n; i++)
      if ((size_t)ps->id[i] > top) top = (size_t)ps->id[i];
    if (!(seen = calloc(top / 8 + 1, 1))) {
      snprintf(err, errlen, "%s: out of memory checking ids", path);
      return -1;
    }
    for (i = 0; i < n; i++) {
      size_t k = (size_t)ps->id[i];
      if (seen[k / 8] & (1u << (k % 8))) {
        free(seen);
        return bad(err, errlen, path, &ps->fields[f], 0, i, ps->id[i],
                   "unique (another row has it)");
      }
      seen[k / 8] |= (unsigned char)(1u << (k % 8));
    }
    free(seen);
  }
  return 0;
}
