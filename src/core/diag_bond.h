/*
** diag_bond.h - how close each bonded interface node is to letting go (a
** diagnostic between steps, never part of one).
**
** The grid is rebuilt as the next step would begin (diag_grid), the
** bonds' sums gathered, and at every shared node where a field and its
** partner (chosen as contact.c chooses it: a driven body, else the
** heaviest other field) are still bonded, the bond test is asked what it
** reads: the normal traction it compares with the strength (tension > 0,
** per sim.bond_traction) and that strength.  Nothing is cut: a node
** whose traction exceeds its strength would let go at the next step.
*/
#ifndef mvmpm_diag_bond_h
#define mvmpm_diag_bond_h

#include "sim.h"

typedef struct bond_node {
  double x[DIM];     /* the node */
  int32_t body;      /* the bonded body (the first body of its field) */
  int32_t partner;   /* the body it is bonded to */
  double traction;   /* what the bond test reads (tension > 0) */
  double strength;   /* what it is compared with */
} bond_node;

/* The bonded interface nodes, one record per bonded field at each (a
** node between two bodies gives two), in the shared nodes' order, into
** *out (malloc'd, the caller frees; NULL when none) and their count into
** *n.  Rebuilds the grid (the next step rebuilds it again: the run's
** numbers do not change).  0, or -1 with s->err (out of memory) */
int diag_bonds(sim *s, bond_node **out, size_t *n);

#endif
