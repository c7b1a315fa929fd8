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

/* Per column of a wall the largest reach, the field it is of, and the
** largest reach of the other fields: two bodies side by side on a wall
** share the columns between them, and the one a cell above the wall
** must not be stopped because its neighbour touches (a disc held a cell
** above the floor in a pile, under the patch rule).  Three arrays per
** side: r1, f1, r2. */
typedef struct wreach {
  double *r1[NSIDES], *r2[NSIDES];
  int32_t *f1[NSIDES];
} wreach;

/* the reach r of field f at column j */
static void wreach_put(const wreach *w, int k, size_t j, int32_t f, double r) {
  if (f == w->f1[k][j]) {
    if (r > w->r1[k][j]) w->r1[k][j] = r;
  } else if (r > w->r1[k][j]) { /* a new top: the old one is the others' */
    w->r2[k][j] = w->r1[k][j];
    w->r1[k][j] = r;
    w->f1[k][j] = f;
  } else if (r > w->r2[k][j])
    w->r2[k][j] = r;
}

double sim_wall_reach(const side *sd, size_t j, int32_t f) {
  return f == sd->efld[j] ? sd->ext[j] : sd->ext2[j];
}

/* particle i's reach toward the walls, into w (one array per side,
** per column of the wall plane): every column whose node the particle's
** stencil reaches along the plane's axes */
static void walls(const sim *s, size_t i, const wreach *w) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const double l = cfg->lp * g->h;
  const int nw = shape_width(cfg->shape);
  int32_t f = -1;
  int k;
  for (k = 0; k < NSIDES; k++) {
    const side *sd = &s->sides[k];
    int d = k / 2, hi = k & 1, e, a, i0[DIM], t[DIM], cnt = 1;
    double xw, r;
    if (sd->kind != SIDE_WALL) continue;
    xw = hi ? g->hi[d] : g->lo[d];
    r = (hi ? ps->x[d][i] - xw : xw - ps->x[d][i]) + l;
    if (r < -1.5 * g->h) continue; /* not near this wall */
    if (f < 0) f = s->bodies[ps->body[i]].field;
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
        wreach_put(w, k, grid_face_index(g, d, ix), f, r);
      }
    }
  }
}

/* The reach of particle i into the slots of its shared stencil nodes
** (the slots p2g found, sim.h); with a plan (mine != NULL), only into
** the node rows this pass writes.  Compiled per shape kind, with the
** offsets to the particle taken along each axis once. */
STENCIL_INLINE void shared_kind(sim *s, const int kind,
                                const stencil_geo *geo, size_t i,
                                const unsigned char *mine) {
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  const int32_t *slot = s->work.pslot + i * stencil_size(kind);
  const double l = s->cfg.lp * g->h;
  const int nw = shape_width(kind);
  double dx[DIM][SHAPE_MAXW];
  int t[DIM], nn = 1, d, a, k;
  for (d = 0; d < DIM; d++) {
    double x = ps->x[d][i];
    int i0 = stencil_first(geo, kind, d, x);
    for (a = 0; a < nw; a++) {
      /* node position on the particle's side of any periodic seam */
      int ia = stencil_wrap(geo, d, i0 + a);
      double r = x - grid_x(g, d, ia);
      if (g->periodic[d]) {
        double L = g->hi[d] - g->lo[d];
        if (r > 0.5 * L) r -= L;
        else if (r < -0.5 * L) r += L;
      }
      dx[d][a] = r;
    }
    t[d] = 0;
    nn *= nw;
  }
  /* an odometer over the DIM indices, x fastest */
  for (k = 0; k < nn; k++) {
    const int32_t sl = slot[k];
    if (sl >= 0 && (!mine || mine[t[BANDS_DIM]])) {
      double e = 0, nrm1 = 0;
      for (d = 0; d < DIM; d++) {
        e += dx[d][t[d]] * g->sn[d][sl];
        nrm1 += fabs(g->sn[d][sl]);
      }
      e += l * nrm1;
      if (e > g->sext[sl]) g->sext[sl] = e;
    }
    for (d = 0; d < DIM && ++t[d] == nw; d++) t[d] = 0;
  }
}

/* particles [i0, i1): part t of the scatter plan p2g made in pass pass
** (the particles have not moved since), or all (t < 0) */
STENCIL_INLINE void shared_range(sim *s, const int kind, size_t i0,
                                 size_t i1, int t, int pass) {
  sim_work *wk = &s->work;
  stencil_geo geo;
  unsigned char mine[SHAPE_MAXW];
  size_t i;
  stencil_geo_init(&geo, &s->g);
  for (i = i0; i < i1; i++) {
    if (t < 0) shared_kind(s, kind, &geo, i, NULL);
    else if (bands_rows(&wk->bands, &geo, kind, s->ps.x[BANDS_DIM][i], t,
                        pass, mine))
      shared_kind(s, kind, &geo, i, mine);
  }
}

/* A maximum does not depend on the order it is taken in, and in a pass
** no two parts write one node row, so no two threads write one slot */
static void shared_span(void *arg, size_t i0, size_t i1, int t, int pass) {
  sim *s = arg;
  switch (s->cfg.shape) {
  case SHAPE_GIMP: shared_range(s, SHAPE_GIMP, i0, i1, t, pass); break;
  case SHAPE_BSPLINE2: shared_range(s, SHAPE_BSPLINE2, i0, i1, t, pass); break;
  default: shared_range(s, SHAPE_LINEAR, i0, i1, t, pass);
  }
}

/* The walls, part t of the particles: part 0 into the sides' own
** arrays, the others each into a copy of its own (s->work.wext, wefld),
** merged after: a maximum does not depend on the order it is taken in */
static void walls_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  double *w = t > 0 ? wk->wext + (size_t)(t - 1) * 2 * wk->wextn : NULL;
  int32_t *wf = t > 0 ? wk->wefld + (size_t)(t - 1) * wk->wextn : NULL;
  wreach r;
  size_t i, i0, i1, j;
  int k;
  for (k = 0; k < NSIDES; k++) {
    side *sd = &s->sides[k];
    r.r1[k] = sd->ext;
    r.r2[k] = sd->ext2;
    r.f1[k] = sd->efld;
    if (t > 0) {
      r.r1[k] = w;
      r.r2[k] = w + sd->next;
      r.f1[k] = wf;
      w += 2 * sd->next;
      wf += sd->next;
    }
    if (sd->kind == SIDE_WALL)
      for (j = 0; j < sd->next; j++) {
        r.r1[k][j] = r.r2[k][j] = -1e300;
        r.f1[k][j] = -1;
      }
  }
  par_range(s->ps.n, t, nparts, &i0, &i1);
  for (i = i0; i < i1; i++) walls(s, i, &r);
}

/* two columns' summaries: the larger top, and the others' largest (the
** smaller top's field differs from the larger's, or they are one) */
static void walls_merge(sim *s) {
  sim_work *wk = &s->work;
  const double *w = wk->wext;
  const int32_t *wf = wk->wefld;
  int t, k;
  for (t = 1; t < par_threads(wk->par); t++)
    for (k = 0; k < NSIDES; k++) {
      side *sd = &s->sides[k];
      const double *r1 = w, *r2 = w + sd->next;
      size_t j;
      if (sd->kind == SIDE_WALL)
        for (j = 0; j < sd->next; j++) {
          if (wf[j] == sd->efld[j]) {
            if (r1[j] > sd->ext[j]) sd->ext[j] = r1[j];
            if (r2[j] > sd->ext2[j]) sd->ext2[j] = r2[j];
          } else if (r1[j] > sd->ext[j]) {
            sd->ext2[j] = sd->ext[j] > r2[j] ? sd->ext[j] : r2[j];
            sd->ext[j] = r1[j];
            sd->efld[j] = wf[j];
          } else if (r1[j] > sd->ext2[j])
            sd->ext2[j] = r1[j];
        }
      w += 2 * sd->next;
      wf += sd->next;
    }
}

void reach(sim *s) {
  sim_work *wk = &s->work;
  const particles *ps = &s->ps;
  const bands *b = &wk->bands;
  int k, anywall = 0;
  for (k = 0; k < NSIDES; k++) anywall |= s->sides[k].kind == SIDE_WALL;
  if (anywall) {
    par_run(wk->par, walls_part, s);
    walls_merge(s);
  }
  if (!s->g.nshared) return;
  if (b->nb) bands_run(b, wk->par, shared_span, s);
  else
    shared_span(s, 0, ps->n, -1, 1);
}
