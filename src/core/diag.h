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
  /* rotation about the centroid, as vectors of 3 (2-D: only z, [2]) */
  double omega[3];      /* angular velocity, I omega = angmom */
  double inertia[3][3]; /* inertia tensor, the particles' own squares
                           (cubes) included; 2-D: [2][2] is the polar
                           moment (the in-plane rows a lamina's) */
  double angmom[3];     /* angular momentum */
  double kinetic, strain;
} bdiag;

/* fills out[0 .. nbody-1]; 0 or -1 (out of memory) */
int diag_bodies(const sim *s, bdiag *out);

#endif
