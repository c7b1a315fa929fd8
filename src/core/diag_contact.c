/*
** diag_contact.c - the contact forces between bodies (diag_contact.h).
**
** Cost: one p2g and one pass over the shared nodes, only when asked
** (between steps); the step itself is untouched, so a run that never
** asks pays nothing.  The records, one per slot in contact, are sorted
** by pair and node and added in that order: the sums do not depend on
** the thread count that built the grid.  Where contact acts per patch
** (body_contact = "patch", or "auto" between a round body and a flat
** one) the patches are applied dry (contact_patch.c) and each slot's
** normal impulse there is what it receives, so the forces are the ones
** the step applies.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "diag_contact.h"

typedef struct rec {
  int32_t r, o;      /* the field pressed and its partner */
  size_t k;          /* shared node index, for a fixed order */
  double fn, f[DIM]; /* the normal force on r */
} rec;

static int cmp(const void *pa, const void *pb) {
  const rec *a = pa, *b = pb;
  int32_t a0 = a->r < a->o ? a->r : a->o, a1 = a->r < a->o ? a->o : a->r;
  int32_t b0 = b->r < b->o ? b->r : b->o, b1 = b->r < b->o ? b->o : b->r;
  if (a0 != b0) return a0 < b0 ? -1 : 1;
  if (a1 != b1) return a1 < b1 ? -1 : 1;
  if (a->k != b->k) return a->k < b->k ? -1 : 1;
  return a->r < b->r ? -1 : a->r > b->r;
}

int diag_grid(sim *s) {
  if (sim_prepare(s)) return -1;
  if (!s->started) sim_begin(s);
  grid_reset(&s->g, 0);
  p2g_plan(s);
  sim_flat(s);
  s->g.moments = s->cfg.normals == NORMALS_PLANE;
  if ((s->nfield > 1 || s->ndriven) && (p2g_mark(s) || contact_prepare(s))) {
    snprintf(s->err, sizeof s->err, "contacts: out of memory for shared nodes");
    return -1;
  }
  p2g(s);
  /* USAVG scatters the forces only after its first half-step's stress
  ** update (usf.c), which a diagnostic may not make: it takes the
  ** forces of the stresses as they stand, the last step's end (the
  ** same at rest, off by that half step's increment in motion).
  ** Without them the walls' and contacts' forces read almost nothing */
  if (s->cfg.update == UPDATE_USAVG) p2g_force(s);
  solve_momentum(s);
  if (s->g.nshared) contact_normals(s);
  if (s->cfg.gap_check) reach(s); /* the walls' too (diag_wall.h) */
  return 0;
}

/* the records of shared node k (as contact.c's node() decides contact,
** bonds aside), appended at rc[*nr] */
static void node_recs(const sim *s, size_t k, rec *rc, size_t *nr) {
  const grid *g = &s->g;
  int32_t n = g->shared[k], sl, q, drv = -1;
  double vref[DIM], M = g->m[n];
  int d;
  if (!(M > s->mcut)) return;
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl])
    /* a slot without mass is no partner, as in contact.c */
    if (s->fdriven[g->sfield[sl]] >= 0 && g->sm[sl] > s->mcut) { drv = sl; break; }
  for (d = 0; d < DIM; d++)
    vref[d] = drv >= 0 ? s->bodies[s->fdriven[g->sfield[drv]]].vdrive[d]
                       : g->q[d][n] / M;
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
    double dn = 0, other = -1e300, mo = -1, mr = g->sm[sl];
    int32_t o = -1;
    rec *e;
    if (s->fdriven[g->sfield[sl]] >= 0 || mr <= s->mcut) continue;
    for (d = 0; d < DIM; d++)
      dn += (g->sq[d][sl] - mr * vref[d]) * g->sn[d][sl];
    for (q = g->head[n]; q >= 0; q = g->snext[q]) {
      if (q == sl || !(g->sm[q] > s->mcut)) continue;
      if (g->sext[q] > other) other = g->sext[q];
      if (g->sm[q] > mo) { mo = g->sm[q]; o = q; }
    }
    if (drv >= 0) o = drv;
    if (o < 0 || !(dn > 0)) continue;
    if (o == drv && sim_drive_far(s, g->sfield[sl], drv)) continue; /* as contact.c */
    if (s->cfg.gap_check && g->sext[sl] + other < 0) continue;
    e = &rc[(*nr)++];
    e->r = g->sfield[sl];
    e->o = g->sfield[o];
    e->k = k;
    e->fn = dn / s->dt;
    for (d = 0; d < DIM; d++) e->f[d] = -dn * g->sn[d][sl] / s->dt;
  }
}

/* the records of shared node k where a patch took it: each free slot's
** normal impulse (sni, the patch's normal part and any deep stop) */
static void patch_recs(const sim *s, size_t k, rec *rc, size_t *nr) {
  const grid *g = &s->g;
  int32_t n = g->shared[k], sl, q;
  int d;
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
    double y2 = 0;
    rec *e;
    if (s->fdriven[g->sfield[sl]] >= 0 || !(g->sm[sl] > s->mcut)) continue;
    for (d = 0; d < DIM; d++) y2 += g->sni[d][sl] * g->sni[d][sl];
    if (!(y2 > 0)) continue;
    for (q = g->head[n]; q >= 0 && q == sl; q = g->snext[q]) {}
    if (q < 0) continue;
    e = &rc[(*nr)++];
    e->r = g->sfield[sl];
    e->o = g->sfield[q];
    e->k = k;
    e->fn = sqrt(y2) / s->dt;
    for (d = 0; d < DIM; d++) e->f[d] = g->sni[d][sl] / s->dt;
  }
}

int diag_contacts(sim *s, contact_pair **out, size_t *n) {
  const grid *g = &s->g;
  rec *rc = NULL;
  contact_pair *cp = NULL;
  int32_t *fbody = NULL;
  size_t nr = 0, np = 0, k, j;
  int d;
  *out = NULL;
  *n = 0;
  if (!s->ps.n) return 0;
  if (diag_grid(s)) return -1;
  if (!g->nshared || !(s->dt > 0)) return 0;
  rc = malloc(g->nslot * sizeof *rc);
  fbody = malloc((size_t)s->nfield * sizeof *fbody);
  if (!rc || !fbody) goto oom;
  for (k = 0; k < (size_t)s->nfield; k++) fbody[k] = -1;
  for (k = (size_t)s->nbody; k-- > 0;) fbody[s->bodies[k].field] = (int32_t)k;
  if (sim_body_patches(s) && s->work.cplab) {
    int32_t *lab = s->work.cplab;
    contact_patches(s, 1);
    for (k = 0; k < g->nshared; k++) {
      if (lab[g->shared[k]] >= 0) patch_recs(s, k, rc, &nr);
      else node_recs(s, k, rc, &nr);
      lab[g->shared[k]] = -1;
    }
  } else
    for (k = 0; k < g->nshared; k++) node_recs(s, k, rc, &nr);
  if (!nr) goto done;
  qsort(rc, nr, sizeof *rc, cmp);
  if (!(cp = malloc(nr * sizeof *cp))) goto oom;
  /* each pair: the mean of what either side receives, the force on a
  ** taken as a's own minus b's (they agree to round-off with two fields;
  ** a driven side receives none and is counted once) */
  for (j = 0; j < nr;) {
    int32_t a = rc[j].r < rc[j].o ? rc[j].r : rc[j].o;
    int32_t b = rc[j].r < rc[j].o ? rc[j].o : rc[j].r;
    double fa = 0, fb = 0, va[DIM] = {0}, vb[DIM] = {0};
    long na = 0, nb = 0, nodes = 0;
    size_t last = (size_t)-1;
    contact_pair *p = &cp[np++];
    for (; j < nr && (rc[j].r < rc[j].o ? rc[j].r : rc[j].o) == a &&
           (rc[j].r < rc[j].o ? rc[j].o : rc[j].r) == b; j++) {
      if (rc[j].k != last) { nodes++; last = rc[j].k; }
      if (rc[j].r == a) {
        fa += rc[j].fn; na++;
        for (d = 0; d < DIM; d++) va[d] += rc[j].f[d];
      } else {
        fb += rc[j].fn; nb++;
        for (d = 0; d < DIM; d++) vb[d] += rc[j].f[d];
      }
    }
    p->a = fbody[a];
    p->b = fbody[b];
    p->nodes = nodes;
    if (na && nb) {
      p->fn = 0.5 * (fa + fb);
      for (d = 0; d < DIM; d++) p->f[d] = 0.5 * (va[d] - vb[d]);
    } else if (na) {
      p->fn = fa;
      for (d = 0; d < DIM; d++) p->f[d] = va[d];
    } else {
      p->fn = fb;
      for (d = 0; d < DIM; d++) p->f[d] = -vb[d];
    }
    if (p->a > p->b) { /* fields numbered out of body order */
      int32_t t = p->a;
      p->a = p->b;
      p->b = t;
      for (d = 0; d < DIM; d++) p->f[d] = -p->f[d];
    }
  }
done:
  free(rc);
  free(fbody);
  *out = cp;
  *n = np;
  return 0;
oom:
  free(rc);
  free(fbody);
  free(cp);
  snprintf(s->err, sizeof s->err, "contacts: out of memory");
  return -1;
}
