/*
** diag_hotspot.h - hot spots: the connected sets of particles hotter
** than a threshold, and their size, temperature and burn.
**
** Connectivity rule: two hot particles belong to one hot spot when their
** centres are at most `link` apart; link is given in particle spacings
** of the seeding (h / ppc) and is 1.5 by default, so on the seeded
** lattice a particle links to its 8 neighbours (side 1, diagonal 1.41)
** and a one-particle gap of cold material (distance 2) separates two hot
** spots (in 3-D: its 18 face and edge neighbours, not the corners at
** 1.73).  The search bins the hot particles in squares (3-D: cubes) of
** side link and
** looks at the neighbouring bins: O(hot particles).  Links do not cross
** periodic sides (a hot spot cut by one is counted as two).
**
** Diagnostics only: reads the particles between steps, allocates its own
** memory, never runs inside a step.
*/
#ifndef mvmpm_diag_hotspot_h
#define mvmpm_diag_hotspot_h

#include <stddef.h>
#include "sim.h"

typedef struct hotspot {
  size_t n;        /* particles */
  double area;     /* sum of the particles' current volumes (2-D: an
                      area, 3-D: a volume) */
  double mass;
  double Tmax, Tmean; /* peak and mass-weighted mean temperature */
  double x[DIM];   /* mass centroid */
  double reacted;  /* mass-weighted mean reacted fraction (0 if none) */
  int32_t first;   /* smallest particle id in it (orders equal areas) */
} hotspot;

typedef struct hotspots {
  hotspot *r;      /* regions, largest area first */
  size_t n, cap;
  double area_hot;   /* total area of the hot particles */
  double area_all;   /* ... of every material particle */
} hotspots;

#define HOTSPOT_LINK 1.5 /* default link, in particle spacings */

/* find the hot spots above threshold (strictly hotter) with link in
** particle spacings (> 0); 0, or -1 with s->err (no temperature field,
** out of memory).  out is reused between calls */
int diag_hotspots(sim *s, double threshold, double link, hotspots *out);
void hotspots_free(hotspots *h);

#endif
