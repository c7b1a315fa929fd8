/*
** mark.c - shared nodes and their slots (p2g_mark), in parallel.
**
** A node is shared when particles of two fields reach it.  The first
** field in the particles' order owns the node; each other field gets a
** slot, and the owner one too.  Done one particle after the other, the
** order of the shared list (nodes in the order they became shared) and
** of each node's slots (newest field first, the owner last) follow the
** particles' order, and contact sums over both in that order.  The
** threads keep it in three steps:
**
**   1. Marking, over the scatter plan (bands.h): in each of its two
**      passes no two parts touch one node row, and a row's particles
**      come part by part, each part's in its stored order.  So a node's
**      owner and its marks (the other fields, linked newest first) are
**      those of one thread.  Marks go into the part's own region; a node
**      becoming shared is an event, kept with its place in the
**      particles' order.
**   2. Order: each part merges the events of its two passes by that
**      place (each pass's are in order already) into its stretch of the
**      shared list, the parts one after the other, and counts its slots.
**   3. Slots: each part numbers the slots of its nodes from its first
**      (the counts added up part by part), a node's slots consecutive in
**      list order, and clears them.
**
** The shared list and every node's slot list are then those of one
** thread, and a slot's number is fixed by the list: nothing depends on
** the thread count.  A part that runs out of room stops; the marking is
** undone and made again with twice the room (only in the first steps of
** a run: the room is also doubled ahead once a part fills half of it).
*/
#include <stdlib.h>
#include <string.h>
#include "sim.h"
#include "stencil.h"

void marks_free(marks *mk) {
  free(mk->field);
  free(mk->next);
  free(mk->key);
  free(mk->node);
  memset(mk, 0, sizeof *mk);
}

size_t marks_mem(const marks *mk) {
  return mk->alloc * (2 * sizeof(int32_t) + sizeof(uint64_t) + sizeof(int32_t));
}

#define GROW(ptr, n)                                          \
  do {                                                        \
    void *np_ = realloc(ptr, (n) * sizeof *(ptr));            \
    if (!np_) return -1;                                      \
    ptr = np_;                                                \
  } while (0)

/* regions of cap entries for np parts; 0 or -1 (out of memory) */
static int room(marks *mk, int np) {
  size_t need;
  if (!mk->cap) mk->cap = 1024;
  need = (size_t)np * mk->cap;
  if (need <= mk->alloc) return 0;
  GROW(mk->field, need);
  GROW(mk->next, need);
  GROW(mk->key, need);
  GROW(mk->node, need);
  mk->alloc = need;
  return 0;
}

/* Part t's marks of the particles [i0, i1) in one pass (split: only the
** node rows this pass writes).  A stencil marked once for a field is
** marked: marking it again is a no-op, so the last MARK_SEEN stencils
** (first node and field) are remembered and skipped.  Particles sorted
** by cell repeat them closely: with linear hats a cell's particles share
** one stencil; with 3-node stencils (which start at the node below the
** particle's half cell) a cell's 2 x 2 particles have four, and the next
** cell's repeat two of them. */
#define MARK_SEEN 4
STENCIL_INLINE void mark_kind(sim *s, const int kind, int split, int t,
                              int pass, size_t i0, size_t i1) {
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const particles *ps = &s->ps;
  const body *bd = s->bodies;
  marks *mk = &wk->marks;
  const size_t base = (size_t)t * mk->cap, cap = mk->cap;
  const int nw = shape_width(kind);
  int32_t *owner = g->owner, *head = g->head, *mf = mk->field, *mn = mk->next;
  size_t used = mk->used[t], nev = mk->nev[t], i;
  int32_t seen[MARK_SEEN], seenf[MARK_SEEN]; /* a ring; -1: none */
  int oldest = 0;
  unsigned char mine[SHAPE_MAXW];
  stencil_geo geo;
  stencil_geo_init(&geo, g);
  for (i = 0; i < MARK_SEEN; i++) seen[i] = seenf[i] = -1;
  for (i = i0; i < i1; i++) {
    int32_t f = bd[ps->body[i]].field, ix[DIM][SHAPE_MAXW], n0;
    int first[DIM], c, d;
    /* the stencil's node indices along each axis, wrapped */
    for (d = 0; d < DIM; d++) {
      int a;
      first[d] = stencil_first(&geo, kind, d, ps->x[d][i]);
      for (a = 0; a < nw; a++) ix[d][a] = stencil_wrap(&geo, d, first[d] + a);
    }
    {
      int i0n[DIM];
      for (d = 0; d < DIM; d++) i0n[d] = ix[d][0];
      n0 = grid_node(g, i0n);
    }
    {
      int q;
      for (q = 0; q < MARK_SEEN && (seen[q] != n0 || seenf[q] != f); q++) {}
      if (q < MARK_SEEN) continue;
      seen[oldest] = n0;
      seenf[oldest] = f;
      oldest = (oldest + 1) % MARK_SEEN;
    }
    if (split && !bands_rows(&wk->bands, &geo, kind, ps->x[BANDS_DIM][i], t,
                             pass, mine))
      continue;
    /* rows along BANDS_DIM (the last axis) outermost, x innermost: k
    ** counts the stencil's nodes in this order */
    for (c = 0; c < nw; c++) {
      int r, nmid = 1, in[DIM];
      if (split && !mine[c]) continue;
      for (d = 1; d < DIM - 1; d++) nmid *= nw;
      in[DIM - 1] = ix[DIM - 1][c];
      for (r = 0; r < nmid; r++) {
        int a, rr = r;
        for (d = 1; d < DIM - 1; d++) {
          in[d] = ix[d][rr % nw];
          rr /= nw;
        }
        for (a = 0; a < nw; a++) {
          int32_t n, o, m;
          in[0] = ix[0][a];
          n = grid_node(g, in);
          o = owner[n];
          if (o == f) continue;
          if (o < 0) { owner[n] = f; continue; }
          for (m = head[n]; m >= 0 && mf[m] != f; m = mn[m]) {}
          if (m >= 0) continue;
          if (used == cap) { mk->full[t] = 1; goto out; }
          m = (int32_t)(base + used++);
          mf[m] = f;
          if (head[n] < 0) { /* the node becomes shared here */
            mk->key[base + nev] =
                (uint64_t)i * STENCIL_MAX + (uint64_t)((c * nmid + r) * nw + a);
            mk->node[base + nev] = n;
            nev++;
          }
          mn[m] = head[n];
          head[n] = m;
        }
      }
    }
  }
out:
  mk->used[t] = used;
  mk->nev[t] = nev;
}

typedef struct mark_job { sim *s; int split, pass; } mark_job;

static void mark_part(void *arg, int t, int nparts) {
  mark_job *j = arg;
  sim *s = j->s;
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  size_t i0 = 0, i1 = s->ps.n;
  if (j->split) bands_span(&wk->bands, t, j->pass, &i0, &i1);
  switch (cfg->shape) {
  case SHAPE_GIMP: mark_kind(s, SHAPE_GIMP, j->split, t, j->pass, i0, i1); break;
  case SHAPE_BSPLINE2:
    mark_kind(s, SHAPE_BSPLINE2, j->split, t, j->pass, i0, i1);
    break;
  default: mark_kind(s, SHAPE_LINEAR, j->split, t, j->pass, i0, i1);
  }
}

/* fn over the parts of the marking: the pool's threads, or the caller */
static void run(const sim_work *wk, par_fn fn, void *arg) {
  if (wk->marks.nparts > 1) par_run(wk->par, fn, arg);
  else fn(arg, 0, 1);
}

/* Step 2, part t: its events in the particles' order into its stretch of
** the shared list, and the count of their slots */
static void order_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const marks *mk = &wk->marks;
  size_t base = (size_t)t * mk->cap, a = base, ae = base + mk->nev1[t];
  size_t b = ae, be = base + mk->nev[t], at = mk->at[t], nsl = 0;
  while (a < ae || b < be) {
    size_t e = b >= be || (a < ae && mk->key[a] < mk->key[b]) ? a++ : b++;
    int32_t n = mk->node[e], m;
    g->shared[at++] = n;
    for (m = g->head[n], nsl++; m >= 0; m = mk->next[m]) nsl++;
  }
  wk->marks.slots[t] = nsl;
}

/* Step 3, part t: the slots of its shared nodes, from its first, each
** node's in list order (its marks newest first, then the owner) */
static void slots_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const marks *mk = &wk->marks;
  size_t k, s0 = mk->slots[t], sl = s0;
  for (k = mk->at[t]; k < mk->at[t] + mk->nev[t]; k++) {
    int32_t n = g->shared[k], m = g->head[n];
    g->head[n] = (int32_t)sl;
    for (; m >= 0; m = mk->next[m], sl++) {
      g->sfield[sl] = mk->field[m];
      g->snode[sl] = n;
      g->snext[sl] = (int32_t)sl + 1;
    }
    g->sfield[sl] = g->owner[n];
    g->snode[sl] = n;
    g->snext[sl++] = -1;
  }
  grid_slots_clear(g, s0, sl);
}

/* room for the slots p2g finds for each particle's stencil (sim.h), as
** many particles as the store has room for: it grows only when bodies
** are added */
static int pslot_room(sim *s) {
  sim_work *wk = &s->work;
  size_t need = s->ps.cap * (size_t)stencil_size(s->cfg.shape);
  if (need <= wk->pslotcap) return 0;
  GROW(wk->pslot, need);
  wk->pslotcap = need;
  return 0;
}

/* a marking that ran out of room, undone: every node it touched is
** unowned again and no node has marks */
static void undo(grid *g, const marks *mk) {
  int t;
  size_t e;
  memset(g->owner, 0xff, g->nnodes * sizeof *g->owner);
  for (t = 0; t < mk->nparts; t++)
    for (e = (size_t)t * mk->cap; e < (size_t)t * mk->cap + mk->nev[t]; e++)
      g->head[mk->node[e]] = -1;
}

/* step 1, in as many parts as the plan has (one without a plan); 0, or
** -1 if some part ran out of room */
static int mark_all(sim *s) {
  sim_work *wk = &s->work;
  marks *mk = &wk->marks;
  int split = wk->bands.nb > 0, t;
  mark_job j = {s, split, 1};
  mk->nparts = split ? wk->bands.nb : 1;
  for (t = 0; t < mk->nparts; t++) mk->used[t] = mk->nev[t] = mk->full[t] = 0;
  run(wk, mark_part, &j);
  for (t = 0; t < mk->nparts; t++) mk->nev1[t] = mk->nev[t];
  if (split) {
    j.pass = 2;
    run(wk, mark_part, &j);
  }
  for (t = 0; t < mk->nparts; t++)
    if (mk->full[t]) return -1;
  return 0;
}

int p2g_mark(sim *s) {
  sim_work *wk = &s->work;
  grid *g = &s->g;
  marks *mk = &wk->marks;
  size_t nshared = 0, nslot = 0, most = 0;
  int t;
  for (;;) {
    if (room(mk, wk->bands.nb > 0 ? wk->bands.nb : 1)) return -1;
    if (!mark_all(s)) break;
    undo(g, mk);
    mk->cap *= 2;
  }
  for (t = 0; t < mk->nparts; t++) {
    mk->at[t] = nshared;
    nshared += mk->nev[t];
    if (mk->used[t] > most) most = mk->used[t];
  }
  if (nshared) {
    if (pslot_room(s)) return -1;
    if (grid_slots_reserve(g, g->slotcap, nshared)) return -1;
    run(wk, order_part, s);
    for (t = 0; t < mk->nparts; t++) { /* each part's first slot */
      size_t c = mk->slots[t];
      mk->slots[t] = nslot;
      nslot += c;
    }
    if (grid_slots_reserve(g, nslot, nshared)) return -1;
    run(wk, slots_part, s);
  }
  g->nshared = nshared;
  g->nslot = nslot;
  /* room ahead, taken at the next step: regions are laid out by cap */
  if (2 * most > mk->cap) mk->cap *= 2;
  return 0;
}
