/*
** diag_bond.c - the bond test's reading at each bonded node (diag_bond.h).
**
** Cost: one p2g, the bonds' gather and one pass over the shared nodes,
** only when asked (between steps): a run that never asks pays nothing.
*/
#include <stdio.h>
#include <stdlib.h>
#include "diag_bond.h"
#include "diag_contact.h"

/* the records of shared node k, appended at out[*nr] */
static void node_bonds(const sim *s, size_t k, const int32_t *fbody,
                       bond_node *out, size_t *nr) {
  const grid *g = &s->g;
  int32_t n = g->shared[k], sl, q, drv = -1;
  int id[DIM], d;
  if (!(g->m[n] > s->mcut)) return;
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl])
    if (s->fdriven[g->sfield[sl]] >= 0 && g->sm[sl] > s->mcut) { drv = sl; break; }
  grid_ijk(g, n, id);
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
    int32_t o = -1;
    double mo = -1, b;
    bond_node *e;
    if (sl == drv || s->fdriven[g->sfield[sl]] >= 0 || !(g->sm[sl] > s->mcut))
      continue;
    for (q = g->head[n]; q >= 0; q = g->snext[q])
      if (q != sl && g->sm[q] > s->mcut && g->sm[q] > mo) { mo = g->sm[q]; o = q; }
    if (drv >= 0) o = drv;
    if (o < 0 || !((b = contact_bond(s, sl, o, drv >= 0)) > 0)) continue;
    e = &out[(*nr)++];
    for (d = 0; d < DIM; d++) e->x[d] = grid_x(g, d, id[d]);
    e->body = fbody[g->sfield[sl]];
    e->partner = fbody[g->sfield[o]];
    e->traction = contact_bond_traction(s, n, sl, drv >= 0);
    e->strength = b;
  }
}

int diag_bonds(sim *s, bond_node **out, size_t *n) {
  const grid *g = &s->g;
  bond_node *rc = NULL;
  int32_t *fbody = NULL;
  size_t nr = 0, k;
  *out = NULL;
  *n = 0;
  if (!s->ps.n || s->fbond < 0) return 0;
  if (diag_grid(s)) return -1;
  if (!g->nshared) return 0;
  bond_gather(s);
  contact_bond_fits(s);
  rc = malloc(g->nslot * sizeof *rc);
  fbody = malloc((size_t)s->nfield * sizeof *fbody);
  if (!rc || !fbody) {
    free(rc);
    free(fbody);
    snprintf(s->err, sizeof s->err, "bonds: out of memory");
    return -1;
  }
  for (k = 0; k < (size_t)s->nfield; k++) fbody[k] = -1;
  for (k = (size_t)s->nbody; k-- > 0;) fbody[s->bodies[k].field] = (int32_t)k;
  for (k = 0; k < g->nshared; k++) node_bonds(s, k, fbody, rc, &nr);
  free(fbody);
  if (!nr) {
    free(rc);
    return 0;
  }
  *out = rc;
  *n = nr;
  return 0;
}
