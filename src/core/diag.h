/*
** diag.h - per-body diagnostics: mass, centroid, velocity, spin, energy.
** One pass over the particles for all bodies at once, so the cost is
** flat in the number of bodies.
*/
#ifndef mvmpm_diag_h
#define mvmpm_diag_h

#include "sim.h"

typedef struct bdiag {
  size_t n;
  double mass;
  double x[DIM];   /* centroid */
  double v[DIM];   /* centre-of-mass velocity */
  double omega;    /* angular velocity about the centroid (2-D) */
  double inertia;  /* polar moment about the centroid, particle squares
                      included */
  double angmom;   /* about the centroid */
  double kinetic, strain;
} bdiag;

/* fills out[0 .. nbody-1]; 0 or -1 (out of memory) */
int diag_bodies(const sim *s, bdiag *out);

#endif
