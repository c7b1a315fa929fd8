/*
** diag_wall.c - a wall's normal force node by node (diag_wall.h).
**
** Cost: one p2g and one pass over the wall's planes, only when asked
** (between steps); the step is untouched, so a run that never asks pays
** nothing.  The nodes are visited in node order and a shared node's
** fields in slot order, so the forces do not depend on the thread count.
*/
#include <stdio.h>
#include <stdlib.h>
#include "diag_contact.h"
#include "diag_wall.h"

/* the normal impulse the node rule would give mass m of momentum q (the
** component along the side's axis) against a wall of velocity vw with
** the gap still open to it (boundary.c's wall_node, its normal part) */
static double press(const sim *s, double m, double q, double vw, double sign,
                    double gap) {
  double dn = sign * (q - m * vw);
  if (!(m > s->mcut) || !(dn > 0)) return 0;
  if (gap > 0 && !s->cfg.gap_step) return 0;
  if (gap > 0) {
    double reach = dn / m * s->dt;
    if (!(reach > gap)) return 0;
    dn *= 1 - gap / reach;
  }
  return dn;
}

/* the gap between field f's material and the wall at column j */
static double gap_of(const sim *s, const side *sd, size_t j, int32_t f) {
  return s->cfg.gap_check ? -sim_wall_reach(sd, j, f) : 0;
}

int diag_wall(sim *s, int k, wall_press **out, size_t *n) {
  const grid *g = &s->g;
  const side *sd = &s->sides[k];
  int d = k / 2, line, first, last, e;
  double sign = (k & 1) ? 1.0 : -1.0;
  size_t j, nr = 0;
  wall_press *w;
  *out = NULL;
  *n = 0;
  if (sd->kind != SIDE_WALL || sd->mirror || !s->ps.n) return 0;
  if (diag_grid(s)) return -1;
  if (!(s->dt > 0)) return 0;
  /* the wall's plane and the ghost planes beyond it, as boundary.c */
  if (k & 1) { first = g->pad + g->cells[d]; last = g->n[d] - 1; }
  else { first = 0; last = g->pad; }
  w = malloc((size_t)(last - first + 1) * sd->next * sizeof *w);
  if (!w) {
    snprintf(s->err, sizeof s->err, "wall forces: out of memory");
    return -1;
  }
  for (line = first; line <= last; line++)
    for (j = 0; j < sd->next; j++) {
      int32_t nd = grid_face_node(g, d, line, j), sl;
      double dn = 0;
      int i[DIM];
      if (!(g->m[nd] > s->mcut)) continue;
      if (g->head[nd] < 0)
        dn = press(s, g->m[nd], g->q[d][nd], sd->v[d], sign,
                   gap_of(s, sd, j, s->nfield > 1 || s->ndriven ? g->owner[nd] : 0));
      else /* each field by its own reach, as boundary.c */
        for (sl = g->head[nd]; sl >= 0; sl = g->snext[sl])
          dn += press(s, g->sm[sl], g->sq[d][sl], sd->v[d], sign,
                      gap_of(s, sd, j, g->sfield[sl]));
      if (!(dn > 0)) continue;
      grid_ijk(g, nd, i);
      for (e = 0; e < DIM; e++)
        w[nr].x[e] = g->lo[e] + (i[e] - (g->periodic[e] ? 0 : g->pad)) * g->h;
      w[nr++].fn = dn / s->dt;
    }
  if (!nr) {
    free(w);
    return 0;
  }
  *out = w;
  *n = nr;
  return 0;
}
