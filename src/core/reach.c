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

/* particle i's reach toward the walls, into ext (one array per side,
** per column of the wall plane): every column whose node the particle's
** stencil reaches along the plane's axes */
static void walls(const sim *s, size_t i, double *const ext[NSIDES]) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const double l = cfg->lp * g->h;
  const int nw = shape_width(cfg->shape);
  int k;
  for (k = 0; k < NSIDES; k++) {
    const side *sd = &s->sides[k];
    int d = k / 2, hi = k & 1, e, a, i0[DIM], t[DIM], cnt = 1;
    double xw, r;
    if (sd->kind != SIDE_WALL) continue;
    xw = hi ? g->hi[d] : g->lo[d];
    r = (hi ? ps->x[d][i] - xw : xw - ps->x[d][i]) + l;
    if (r < -1.5 * g->h) continue; /* not near this wall */
    /* the first stencil node along each axis of the plane */
    for (e = 0; e < DIM; e++) {
      double xi;
      t[e] = 0;
      i0[e] = 0;
      if (e == d) continue;
      xi = (ps->x[e][i] - g->lo[e]) * g->inv_h + (g->periodic[e] ? 0 : g->pad);
      i0[e] = cfg->shape == SHAPE_LINEAR ? (int)floor(xi)
              : cfg->shape == SHAPE_GIMP ? (int)floor(xi + 0.5) - 1
                                       : (int)floor(xi - 0.5);
      cnt *= nw;
    }
    for (a = 0; a < cnt; a++) { /* the nw^(DIM-1) columns, x fastest */
      int ix[DIM], in = 1, c = a;
      for (e = 0; e < DIM; e++) {
        ix[e] = 0;
        if (e == d) continue;
        t[e] = c % nw;
        c /= nw;
        ix[e] = grid_wrap(g, e, i0[e] + t[e]);
        in &= ix[e] >= 0 && ix[e] < g->n[e];
      }
      if (in) {
        size_t j = grid_face_index(g, d, ix);
        if (r > ext[k][j]) ext[k][j] = r;
      }
    }
  }
}

/* the reach of particle i into the slots of its shared stencil nodes;
** with a plan (blk >= 0), only into the node rows this pass writes */
static void shared(sim *s, size_t i, int blk, int pass) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const bands *b = &wk->bands;
  const double l = cfg->lp * g->h;
  int32_t node[STENCIL_MAX];
  double x[DIM];
  int nn, d, k;
  for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
  nn = stencil_nodes(g, cfg->shape, x, node);
  for (k = 0; k < nn; k++) {
    int32_t n = node[k], sl;
    double e = 0, nrm1 = 0;
    int ix[DIM];
    if (g->head[n] < 0) continue;
    grid_ijk(g, n, ix);
    if (blk >= 0 && (b->first[ix[BANDS_DIM]] == blk) != (pass == 1)) continue;
    sl = grid_slot(g, n, s->bodies[ps->body[i]].field);
    for (d = 0; d < DIM; d++) {
      /* node position on the particle's side of any periodic seam */
      double xn = grid_x(g, d, ix[d]);
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

/* Part t of the scatter plan p2g made (the particles have not moved
** since): a maximum does not depend on the order it is taken in, and in
** a pass no two parts write one node row, so no two threads write one
** slot */
static void shared_span(void *arg, size_t i0, size_t i1, int t, int pass) {
  sim *s = arg;
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  stencil_geo geo;
  unsigned char mine[SHAPE_MAXW];
  size_t i;
  stencil_geo_init(&geo, &s->g);
  for (i = i0; i < i1; i++)
    if (bands_rows(&wk->bands, &geo, cfg->shape, s->ps.x[BANDS_DIM][i], t, pass, mine))
      shared(s, i, t, pass);
}

/* The walls, part t of the particles: part 0 into the sides' own
** arrays, the others each into a copy of its own (s->work.wext), merged after:
** a maximum does not depend on the order it is taken in */
static void walls_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  double *ext[NSIDES], *w = t > 0 ? wk->wext + (size_t)(t - 1) * wk->wextn : NULL;
  size_t i, i0, i1, j;
  int k;
  for (k = 0; k < NSIDES; k++) {
    side *sd = &s->sides[k];
    ext[k] = sd->ext;
    if (t > 0) {
      ext[k] = w;
      w += sd->next;
    }
    if (sd->kind == SIDE_WALL)
      for (j = 0; j < sd->next; j++) ext[k][j] = -1e300;
  }
  par_range(s->ps.n, t, nparts, &i0, &i1);
  for (i = i0; i < i1; i++) walls(s, i, ext);
}

static void walls_merge(sim *s) {
  sim_work *wk = &s->work;
  const double *w = wk->wext;
  int t, k;
  for (t = 1; t < par_threads(wk->par); t++)
    for (k = 0; k < NSIDES; k++) {
      side *sd = &s->sides[k];
      size_t j;
      if (sd->kind == SIDE_WALL)
        for (j = 0; j < sd->next; j++)
          if (w[j] > sd->ext[j]) sd->ext[j] = w[j];
      w += sd->next;
    }
}

void reach(sim *s) {
  sim_work *wk = &s->work;
  const particles *ps = &s->ps;
  const bands *b = &wk->bands;
  int k, anywall = 0;
  size_t i;
  for (k = 0; k < NSIDES; k++) anywall |= s->sides[k].kind == SIDE_WALL;
  if (anywall) {
    par_run(wk->par, walls_part, s);
    walls_merge(s);
  }
  if (!s->g.nshared) return;
  if (b->nb) bands_run(b, wk->par, shared_span, s);
  else
    for (i = 0; i < ps->n; i++) shared(s, i, -1, 1);
}
