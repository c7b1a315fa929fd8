/*
** mark.h - the working room of shared-node marking (mark.c), which runs
** in parallel over the scatter plan (bands.h) and builds the same shared
** list and the same slot lists node by node as one thread would.
**
** Each part of the plan has a region of cap entries.  A mark is one
** field, other than the node's owner, that reaches a node: while marking,
** grid.head holds a node's newest mark and the marks are linked newest
** first.  An event is a node becoming shared, with the place in the
** particles' order where it did (particle index, stencil position), so
** that the parts' events can be put back into that order.
*/
#ifndef mvmpm_mark_h
#define mvmpm_mark_h

#include <stddef.h>
#include <stdint.h>
#include "par.h"

typedef struct marks {
  size_t cap;              /* entries per part */
  size_t alloc;            /* entries allocated */
  int32_t *field, *next;   /* marks: the field, the next older mark */
  uint64_t *key;           /* events: where in the particles' order */
  int32_t *node;           /* events: the node that became shared */
  int nparts;              /* parts of the last marking */
  size_t used[PAR_MAX];    /* marks of each part */
  size_t nev[PAR_MAX];     /* events of each part, both passes */
  size_t nev1[PAR_MAX];    /* ... of which in the first pass */
  int full[PAR_MAX];       /* the part ran out of room */
  size_t at[PAR_MAX];      /* each part's first place in the shared list */
  size_t slots[PAR_MAX];   /* slots of each part's shared nodes, then the
                              first of them */
} marks;

void marks_free(marks *mk);
/* bytes held */
size_t marks_mem(const marks *mk);

#endif
