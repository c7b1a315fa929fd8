/*
** law.c - the contact laws between velocity fields (sim.h): the pairs a
** scene or a callback overrides, sorted for a binary search, and the
** default elsewhere.  A table of its own, so that contact.c, which reads
** it in the step, does not call back into sim.c, which calls contact.c.
*/
#include <stdlib.h>
#include "sim.h"

static int lawcmp(const void *x, const void *y) {
  const pairlaw *a = x, *b = y;
  if (a->a != b->a) return a->a < b->a ? -1 : 1;
  return (a->b > b->b) - (a->b < b->b);
}

int sim_set_law(sim *s, int32_t a, int32_t b, double mu, double bond) {
  pairlaw key;
  int k;
  if (a > b) { int32_t t = a; a = b; b = t; }
  for (k = 0; k < s->nlaw; k++)
    if (s->laws[k].a == a && s->laws[k].b == b) {
      s->laws[k].mu = mu;
      s->laws[k].bond = bond;
      return 0;
    }
  if (s->nlaw == s->lawcap) {
    int cap = s->lawcap ? 2 * s->lawcap : 16;
    pairlaw *p = realloc(s->laws, cap * sizeof *p);
    if (!p) return -1;
    s->laws = p;
    s->lawcap = cap;
  }
  key.a = a; key.b = b; key.mu = mu; key.bond = bond;
  s->laws[s->nlaw++] = key;
  qsort(s->laws, s->nlaw, sizeof *s->laws, lawcmp);
  s->flaw[a] = s->flaw[b] = 1;
  return 0;
}

const pairlaw *sim_law_of(const sim *s, int32_t a, int32_t b) {
  pairlaw key;
  if (b < 0 || !(s->flaw[a] && s->flaw[b])) return NULL;
  if (a > b) { int32_t t = a; a = b; b = t; }
  key.a = a; key.b = b;
  return bsearch(&key, s->laws, s->nlaw, sizeof *s->laws, lawcmp);
}

double sim_law(const sim *s, int32_t a, int32_t b) {
  const sim_cfg *cfg = &s->cfg;
  const pairlaw *l = sim_law_of(s, a, b);
  return l ? l->mu : cfg->mu_default;
}
