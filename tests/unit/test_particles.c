/*
** test_particles.c - the particle store: compaction and the sort keep
** every particle's data together, whatever the type of the array.
*/
#include <stdint.h>
#include "particles.h"
#include "unit.h"

#define NP 1000

/* fill particle i with data that names it: x = i, body = 3 i, cell = key */
static void fill(particles *ps) {
  size_t i;
  particles_init(ps);
  for (i = 0; i < NP; i++) {
    size_t k = particles_push(ps);
    ps->x[0][k] = (double)i;
    ps->x[1][k] = -(double)i;
    ps->body[k] = (int32_t)(3 * i);
    ps->cell[k] = (int32_t)((7 * i) % 13);
  }
}

/* every particle's fields still agree with each other */
static int consistent(const particles *ps) {
  size_t k, bad = 0;
  for (k = 0; k < ps->n; k++) {
    double i = ps->x[0][k];
    bad += ps->x[1][k] != -i || ps->body[k] != (int32_t)(3 * i) ||
           ps->cell[k] != (int32_t)(((long)(7 * i)) % 13);
  }
  return bad == 0;
}

static void compact(void) {
  particles ps;
  unsigned char keep[NP];
  size_t i, order = 1;
  fill(&ps);
  for (i = 0; i < NP; i++) keep[i] = i % 3 != 1; /* drop a third */
  UNIT_CHECK(particles_compact(&ps, keep) == NP - NP / 3, "compact count");
  UNIT_CHECK(consistent(&ps), "compact keeps double and int32 arrays together");
  for (i = 1; i < ps.n; i++) order &= ps.x[0][i] > ps.x[0][i - 1];
  UNIT_CHECK(order, "compact keeps the order");
  particles_free(&ps);
}

static void sort(void) {
  particles ps;
  size_t i, sorted = 1, stable = 1;
  fill(&ps);
  UNIT_CHECK(particles_sort(&ps, ps.cell, 13, NULL) == 0, "sort runs");
  UNIT_CHECK(ps.n == NP && consistent(&ps), "sort keeps every particle's data together");
  for (i = 1; i < ps.n; i++) {
    sorted &= ps.cell[i] >= ps.cell[i - 1];
    if (ps.cell[i] == ps.cell[i - 1]) stable &= ps.x[0][i] > ps.x[0][i - 1];
  }
  UNIT_CHECK(sorted && stable, "sort orders by key, stably");
  particles_free(&ps);
}

/* giving back the spare capacity keeps the data, and the store grows
** again afterwards */
static void fit(void) {
  particles ps;
  size_t k;
  fill(&ps);
  UNIT_CHECK(ps.cap > ps.n, "seeding leaves spare capacity (cap %zu, n %zu)", ps.cap, ps.n);
  particles_fit(&ps);
  UNIT_CHECK(ps.cap == NP && consistent(&ps), "fit: cap = n, data kept");
  k = particles_push(&ps);
  ps.x[0][k] = (double)NP;
  ps.x[1][k] = -(double)NP;
  ps.body[k] = 3 * NP;
  ps.cell[k] = (7 * NP) % 13;
  UNIT_CHECK(ps.n == NP + 1 && ps.cap > NP && consistent(&ps), "push after fit");
  UNIT_CHECK(particles_sort(&ps, ps.cell, 13, NULL) == 0 && consistent(&ps), "sort after fit");
  particles_free(&ps);
}

int main(void) {
  compact();
  sort();
  fit();
  UNIT_END("test_particles");
}
