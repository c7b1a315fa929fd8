/*
** grid.h - the background grid.
** Every node carries the centre-of-mass field (dense arrays).  Nodes
** touched by particles of more than one velocity field also get one
** slot per field (sparse, linked per node), so memory and time grow with
** the length of interfaces, not with the number of bodies.
**
** During a step the dense and slot arrays hold, in turn:
**   after p2g:    m, p (momentum), f (internal + external force)
**   after solve:  f includes contact and wall impulses / dt, so that the
**                 updated momentum is always p + dt f
**   after finish: p -> vL (updated velocity), f -> dv (velocity change)
*/
#ifndef mvmpm_grid_h
#define mvmpm_grid_h

#include <stddef.h>
#include <stdint.h>
#include "dim.h"

typedef struct grid {
  int cells[DIM];      /* cells per dimension */
  int periodic[DIM];
  int pad;             /* ghost nodes beyond each non-periodic side */
  int n[DIM];          /* stored nodes per dimension */
  size_t nnodes;
  double lo[DIM], hi[DIM];
  double h, inv_h;
  /* dense centre-of-mass field */
  double *m, *p[DIM], *f[DIM];
  double *q[DIM];      /* remapped momentum (MUSL) */
  /* the friction (tangential) impulse the walls gave the node this step,
  ** and, under the lossy transfers, their normal impulse (book.c books
  ** their work on the particles' motion) */
  double *fi[DIM], *ni[DIM];
  int32_t *owner;      /* first field seen at the node, -1 if none */
  int32_t *head;       /* first slot of a shared node, -1 otherwise */
  /* sparse slots, one per (shared node, field) */
  size_t nslot, slotcap;
  int32_t *snext, *sfield, *snode;
  double *sm, *sp[DIM], *sf[DIM], *sq[DIM];
  double *sg[DIM];     /* mass gradient, for normals */
  double *sn[DIM];     /* outward unit normal of the field's body */
  double *sfi[DIM], *sni[DIM]; /* friction impulses (contact and walls,
                                  as fi) and contact's normal ones */
  /* the impulse that gave a bonded slot its node's velocity, and the
  ** slot's dt f less gravity's, the internal force's impulse (contact.c;
  ** book.c and bond_remap book their work) */
  double *sbi[DIM], *sbf[DIM];
  double *sext;        /* reach of the field's material along its normal */
  /* bonds (bond.c), filled only in scenes with bonds: the field's
  ** mass-weighted bond strength, its volume gradient sum_p V_p grad S_ip
  ** (whose length is the interface area the node stands for), and the
  ** strength a debonding removed */
  double *sb, *sv[DIM], *scut;
  double *sbo, *smo;   /* strength x mass, and mass, of the particles whose
                          nearest node this is (bond.c) */
  unsigned char *sbonded; /* bonded this step: moves with the node */
  /* the particles whose bond was cut (bond.c): sum_p m_p S_ip, and
  ** sum_p m_p S_ip (x_p - x_p at the cut), for the opening (contact.c) */
  double *srm, *sru[DIM];
  /* the traction fitted at the slot (contact.c, bond_traction = "fit"),
  ** and whether a fit was found there */
  double *sft;
  unsigned char *sfok;
  /* sum_p w_p sigma_p (in-plane, upper triangle as sxx) and sum_p w_p,
  ** w_p = V_p S_ip, over the field's particles (bond.c): the stress the
  ** bond test projects on the normal */
  double *sst[DIM * (DIM + 1) / 2], *ssw;
  /* the particles' moments about the node, for normals = "plane"
  ** (contact.c), kept only while moments is set: sum_p w_p, sum_p w_p r_p
  ** and sum_p w_p r_p r_p^T (upper triangle, row by row), w_p = V_p S_ip,
  ** r_p = (x_i - x_p) / h */
  int moments;
  size_t momcap;
  double *sw, *sx[DIM], *sxx[DIM * (DIM + 1) / 2];
  /* the cohesive law (bond.c, contact.c; sim.bond_energy > 0), kept only
  ** while cohesive is set: over the released particles, sum_p m_p S_ip
  ** times their strength at the cut and times the largest opening their
  ** node has seen; the largest opening this step (written by contact,
  ** read back by bond_scatter); the cohesive impulses (book.c) */
  int cohesive;
  size_t cohcap;
  double *scs, *sdm, *sdn, *sci[DIM];
  /* list of shared nodes */
  size_t nshared, sharedcap;
  int32_t *shared;
} grid;

/* allocate for the given domain; 0 or -1 (out of memory) */
int grid_init(grid *g, const double lo[DIM], const double hi[DIM], double h,
              const int periodic[DIM], int pad);
void grid_free(grid *g);
/* bytes the grid needs before any slot, for refusing oversize scenes */
double grid_bytes(const double lo[DIM], const double hi[DIM], double h,
                  int pad);
/* bytes the grid holds now: dense arrays, slot pool, shared list */
size_t grid_mem(const grid *g);
/* clear the dense arrays and the slot table for a new step; q only if
** clear_q (the step need not: solve_momentum writes every q) */
void grid_reset(grid *g, int clear_q);
/* the same in two parts: the dense arrays of nodes [i0, i1) (threads
** may clear parts at once), and the slot table */
void grid_clear(grid *g, size_t i0, size_t i1, int clear_q);
void grid_reset_slots(grid *g);
/* room for nslot slots and nshared shared nodes (grown by doubling, so
** that after the first steps no step allocates); 0 or -1 (out of memory).
** Marking (mark.c) fills them: it sets nslot, nshared, the list and the
** links, and clears the sums with grid_slots_clear */
int grid_slots_reserve(grid *g, size_t nslot, size_t nshared);
/* index of (a, b), a <= b, in sxx */
static inline int grid_sym(int a, int b) {
  return a * DIM - a * (a - 1) / 2 + (b - a);
}
/* zero the sums of slots [s0, s1) (threads may clear parts at once) */
void grid_slots_clear(grid *g, size_t s0, size_t s1);
/* the slot of field f at a shared node (must exist) */
static inline int32_t grid_slot(const grid *g, int32_t node, int32_t field) {
  int32_t s = g->head[node];
  while (g->sfield[s] != field) s = g->snext[s];
  return s;
}
/* node index along d of node coordinate i (already including pad),
** wrapped if periodic; assumes i within one period */
static inline int grid_wrap(const grid *g, int d, int i) {
  if (g->periodic[d]) {
    if (i < 0) i += g->n[d];
    else if (i >= g->n[d]) i -= g->n[d];
  }
  return i;
}
/* the stored node at indices i (pad included, wrapped): x runs fastest,
** then y, then z.  Every node number in the core is made here or by
** grid_face_node, so the layout is written once for any DIM */
static inline int32_t grid_node(const grid *g, const int i[DIM]) {
  int32_t n = i[DIM - 1];
  int d;
  for (d = DIM - 2; d >= 0; d--) n = n * g->n[d] + i[d];
  return n;
}
/* the indices of stored node n, as grid_node made them */
static inline void grid_ijk(const grid *g, int32_t n, int i[DIM]) {
  int d;
  /* the last index is what is left: no division for it */
  for (d = 0; d < DIM - 1; d++) { i[d] = n % g->n[d]; n /= g->n[d]; }
  i[DIM - 1] = n;
}
/* the nodes of the plane i_d = line (a line in 2-D): how many, and the
** j-th, with the other indices in grid_node's order */
static inline size_t grid_face_count(const grid *g, int d) {
  size_t c = 1;
  int e;
  for (e = 0; e < DIM; e++) if (e != d) c *= (size_t)g->n[e];
  return c;
}
static inline int32_t grid_face_node(const grid *g, int d, int line,
                                     size_t j) {
  int i[DIM], e;
  for (e = 0; e < DIM; e++) {
    if (e == d) { i[e] = line; continue; }
    i[e] = (int)(j % (size_t)g->n[e]);
    j /= (size_t)g->n[e];
  }
  return grid_node(g, i);
}
/* the column of the node with indices i in its plane i_d: the j that
** grid_face_node(g, d, i[d], j) takes to give it back */
static inline size_t grid_face_index(const grid *g, int d, const int i[DIM]) {
  size_t j = 0;
  int e;
  for (e = DIM - 1; e >= 0; e--)
    if (e != d) j = j * (size_t)g->n[e] + (size_t)i[e];
  return j;
}
/* the node planes side k (2 d low, 2 d + 1 high) of the domain acts on:
** its wall plane and the ghost planes beyond it, [*first, *last] along d */
static inline void grid_wall_lines(const grid *g, int k, int *first, int *last) {
  int d = k / 2;
  if (k & 1) { *first = g->pad + g->cells[d]; *last = g->n[d] - 1; }
  else { *first = 0; *last = g->pad; }
}
/* physical coordinate of stored node index i along d */
static inline double grid_x(const grid *g, int d, int i) {
  return g->lo[d] + (i - (g->periodic[d] ? 0 : g->pad)) * g->h;
}

#endif
