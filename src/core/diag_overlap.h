/*
** diag_overlap.h - interpenetration of bodies, measured on the grid's
** cells (a diagnostic between steps, never part of one).
**
** A cell is held by the body with the most particles in it (a tie: by
** none).  A particle of body a lies inside body b by k cells when every
** cell within k cells of its own (the (2k+1)^DIM block, across periodic
** sides) is held by b != a.  Contact on the grid acts once two bodies
** share nodes, so surfaces a cell apart already touch: depth 0 is
** ordinary contact, depth >= 1 is a particle buried in another body
** beyond the reach of the contact rule.
*/
#ifndef mvmpm_diag_overlap_h
#define mvmpm_diag_overlap_h

#include "sim.h"

typedef struct overlap_info {
  size_t n;       /* particles inside another body by >= 1 cell */
  int depth;      /* the deepest, in cells (0 when n == 0) */
  int32_t body;   /* body of a deepest particle, -1 if none */
  int32_t host;   /* the body it lies in, -1 if none */
} overlap_info;

/* measures the particles as they are; depth is sought up to maxdepth
** cells.  0, or -1 when out of memory */
int diag_overlap(const sim *s, int maxdepth, overlap_info *out);

#endif
