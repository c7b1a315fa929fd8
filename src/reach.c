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

/* the reach of particle i into the slots of its shared stencil nodes;
** with a plan (blk >= 0), only into the node rows this pass writes */
static void shared(sim *s, size_t i, int blk, int pass) {
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const bands *b = &s->bands;
  const double l = s->lp * g->h;
  int32_t node[STENCIL_MAX];
  double x[DIM];
  int nn, d, k;
  for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
  nn = stencil_nodes(g, s->shape, x, node);
  for (k = 0; k < nn; k++) {
    int32_t n = node[k], sl;
    double e = 0, nrm1 = 0;
    if (g->head[n] < 0) continue;
    if (blk >= 0 && (b->first[n / g->n[0]] == blk) != (pass == 1)) continue;
    sl = grid_slot(g, n, s->bodies[ps->body[i]].field);
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

typedef struct pass_job { sim *s; int pass; } pass_job;

/* Part t of the scatter plan p2g made (the particles have not moved
** since): a maximum does not depend on the order it is taken in, and in
** a pass no two parts write one node row, so no two threads write one
** slot */
static void shared_part(void *arg, int t, int nparts) {
  pass_job *j = arg;
  const bands *b = &j->s->bands;
  stencil_geo geo;
  unsigned char mine[SHAPE_MAXW];
  size_t i;
  stencil_geo_init(&geo, &j->s->g);
  for (i = b->i[t]; i < b->i[t + 1]; i++)
    if (bands_rows(b, &geo, j->s->shape, j->s->ps.x[BANDS_DIM][i], t,
                   j->pass, mine))
      shared(j->s, i, t, j->pass);
}

void reach(sim *s) {
  const particles *ps = &s->ps;
  const bands *b = &s->bands;
  int k, anywall = 0;
  size_t i;
  for (k = 0; k < NSIDES; k++)
    if (s->sides[k].kind == SIDE_WALL) {
      size_t j;
      anywall = 1;
      for (j = 0; j < s->sides[k].next; j++) s->sides[k].ext[j] = -1e300;
    }
  if (anywall)
    for (i = 0; i < ps->n; i++) walls(s, i);
  if (!s->g.nshared) return;
  if (b->nb) {
    pass_job j = {s, 1};
    par_run(s->par, shared_part, &j);
    j.pass = 2;
    par_run(s->par, shared_part, &j);
  } else
    for (i = 0; i < ps->n; i++) shared(s, i, -1, 1);
}
