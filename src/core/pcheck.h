/*
** pcheck.h - particles read from a file, judged before anything uses
** them: a checkpoint to continue from, a snapshot to render.  One pass,
** at load; never in a step.
**
** Every field read (PF_READ) is checked: no NaN anywhere, no infinity
** but in "bond" (a strength with no cap); mass, volume0 and det F above
** 0; halfsize in (0, 0.5] cells; body in [0, nbody); id in [1, nmade]
** and no two alike; plastic_strain, bond, plastic_work and viscous_work
** at least 0; position inside the domain by the engine's own rule (lo <=
** x < hi and in a cell: a particle that leaves is removed at once, and
** a periodic side wraps it back, so none outside is ever stored).  The
** message names the file, the dataset, its row (from 0, as h5py and
** h5dump count) and the allowed range.
*/
#ifndef mvmpm_pcheck_h
#define mvmpm_pcheck_h

#include <stddef.h>
#include "particles.h"

/* bodies a snapshot may number when nothing else says how many */
#define PCHECK_MAXBODY (1 << 20)

typedef struct pcheck_lim {
  int nbody;              /* body index in [0, nbody) */
  size_t nmade;           /* ids in [1, nmade]; 0: up to INT32_MAX */
  int domain;             /* 1: lo, hi, h and cells hold the domain */
  double lo[DIM], hi[DIM], h;
  int cells[DIM];
} pcheck_lim;

/* 0, or -1 with err ("PATH: dataset 'mass', row 3: 0 is not in (0,
** inf)") */
int pcheck_particles(const char *path, const particles *ps,
                     const pcheck_lim *lim, char *err, size_t errlen);

#endif
