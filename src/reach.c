/*
** reach.c - how far each body's material reaches toward its contact
** partner, for the separation check.  Particles are squares of half
** size l = lp h.  At a shared node, for the slot of field r with outward
** normal n_r, the reach is
**   e_r = max over particles p of r near the node of (x_p - x_i).n_r + l |n_r|_1
** i.e. the position of r's outermost material surface along n_r.  Two
** fields touch when e_A + e_B >= 0 (their surfaces meet or overlap).
** For a wall the reach is the distance the material passes the wall
** line, max (x_p - x_w).n_out + l, per wall node.
*/
#include <math.h>
#include "sim.h"
#include "stencil.h"

static void walls(sim *s, size_t i) {
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const double l = s->lp * g->h;
  int k;
  for (k = 0; k < NSIDES; k++) {
    side *sd = &s->sides[k];
    int d = k / 2, hi = k & 1, o = 1 - d; /* o: the other dimension (2-D) */
    double xw, r, xi;
    int i0, a, nw;
    if (sd->kind != SIDE_WALL) continue;
    xw = hi ? g->hi[d] : g->lo[d];
    r = (hi ? ps->x[d][i] - xw : xw - ps->x[d][i]) + l;
    if (r < -1.5 * g->h) continue; /* not near this wall */
    /* wall nodes along the other dimension this particle touches */
    xi = (ps->x[o][i] - g->lo[o]) * g->inv_h + (g->periodic[o] ? 0 : g->pad);
    nw = shape_width(s->shape);
    i0 = s->shape == SHAPE_LINEAR ? (int)floor(xi)
         : s->shape == SHAPE_GIMP ? (int)floor(xi + 0.5) - 1
                                  : (int)floor(xi - 0.5);
    for (a = 0; a < nw; a++) {
      int j = grid_wrap(g, o, i0 + a);
      if (j >= 0 && (size_t)j < sd->next && r > sd->ext[j]) sd->ext[j] = r;
    }
  }
}

void reach(sim *s) {
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const body *bd = s->bodies;
  const double l = s->lp * g->h;
  int32_t node[STENCIL_MAX];
  int k, anywall = 0;
  size_t i;
  for (k = 0; k < NSIDES; k++)
    if (s->sides[k].kind == SIDE_WALL) {
      size_t j;
      anywall = 1;
      for (j = 0; j < s->sides[k].next; j++) s->sides[k].ext[j] = -1e300;
    }
  for (i = 0; i < ps->n; i++) {
    double x[DIM];
    int nn, d;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    if (anywall) walls(s, i);
    if (!g->nshared) continue;
    nn = stencil_nodes(g, s->shape, x, node);
    for (k = 0; k < nn; k++) {
      int32_t n = node[k], sl;
      double e = 0, nrm1 = 0;
      if (g->head[n] < 0) continue;
      sl = grid_slot(g, n, bd[ps->body[i]].field);
      for (d = 0; d < DIM; d++) {
        /* node position on the particle's side of any periodic seam */
        int id = d == 0 ? n % g->n[0] : n / g->n[0];
        double xn = grid_x(g, d, id);
        double dx = x[d] - xn;
        if (g->periodic[d]) {
          double L = g->hi[d] - g->lo[d];
          if (dx > 0.5 * L) dx -= L;
          else if (dx < -0.5 * L) dx += L;
        }
        e += dx * g->sn[d][sl];
        nrm1 += fabs(g->sn[d][sl]);
      }
      e += l * nrm1;
      if (e > g->sext[sl]) g->sext[sl] = e;
    }
  }
}
