/*
** test_render_view.c - the renderer's view of a store of either
** dimension.  A lattice of 4 particles a side fills the unit square
** (cube); in 3-D it is drawn looking along each axis, as slices (which
** particles a slice takes) and projections (the nearest particle on
** top, the picture not mirrored), and the 3-D sdiff is checked against
** principal stresses known by hand.  In 2-D only the view along z
** exists and every particle is drawn.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "canvas.h"
#include "cmap.h"
#include "particles.h"
#include "render_png.h"
#include "unit.h"

#define K 4           /* particles a side */
#define H (1.0 / K)   /* their spacing */

/* particle number of lattice point (i[0], i[1] (, i[2])), x fastest */
static size_t lat(const int *i) {
  size_t n = 0;
  int d;
  for (d = DIM - 1; d >= 0; d--) n = n * K + (size_t)i[d];
  return n;
}

/* K^DIM particles at the cell centres; body = the layer along the last
** axis, mass = the index along axis `mark` (so a colour tells depth) */
static void lattice(particles *ps, int mark) {
  size_t n = 1, p;
  int d;
  particles_init(ps);
  for (d = 0; d < DIM; d++) n *= K;
  for (p = 0; p < n; p++) {
    size_t q = p;
    int c;
    particles_push(ps);
    for (d = 0; d < DIM; d++) {
      ps->x[d][p] = (double)(q % K + 0.5) * H;
      if (d == mark) ps->m[p] = (double)(q % K);
      if (d == DIM - 1) ps->body[p] = (int32_t)(q % K);
      q /= K;
    }
    ps->vol0[p] = pow(H, DIM);
    for (c = 0; c < NTENS; c++) ps->F[c][p] = c % (DIM + 1) == 0;
  }
  if (mark < 0 || mark >= DIM)
    for (p = 0; p < n; p++) ps->m[p] = 1;
}

static render_opts unit_window(const char *by) {
  render_opts o;
  memset(&o, 0, sizeof o);
  o.by = by;
  o.width = 400;
  o.cmap = CMAP_SEQ;
  o.hi[0] = o.hi[1] = 1;
  o.title = "view";
  return o;
}

/* the pixel of picture point (h, u) */
static uint32_t px(const canvas *c, const render_layout *L,
                   const render_opts *o, double h, double u) {
  int x = L->dx0 + (int)floor((h - o->lo[0]) / (o->hi[0] - o->lo[0]) *
                              (L->dx1 - L->dx0));
  int y = L->dy0 + (int)floor((o->hi[1] - u) / (o->hi[1] - o->lo[1]) *
                              (L->dy1 - L->dy0));
  return canvas_get(c, x, y);
}

static int draw(canvas *c, render_layout *L, const particles *ps,
                const render_opts *o, const char *what) {
  char err[512];
  int r = render_draw(c, L, ps, o, err, sizeof err);
  UNIT_CHECK(r == 0, "%s: %s", what, err);
  return r;
}

static void test_axes(void) {
  int h, u, a;
  char err[256];
  UNIT_CHECK(render_view_axes(NULL, &h, &u, &a, err, sizeof err) == 0 &&
             h == 0 && u == 1 && a == (DIM == 2 ? -1 : 2),
             "default view: x right, y up (got %d %d %d)", h, u, a);
  UNIT_CHECK(render_view_axes("w", &h, &u, &a, err, sizeof err) < 0 &&
             strstr(err, "'w'"), "axis 'w' refused: %s", err);
  if (DIM == 2) {
    UNIT_CHECK(render_view_axes("x", &h, &u, &a, err, sizeof err) < 0 &&
               strstr(err, "2-D"), "2-D: axis x refused: %s", err);
    return;
  }
  UNIT_CHECK(render_view_axes("x", &h, &u, &a, err, sizeof err) == 0 &&
             h == 2 && u == 1 && a == 0, "along x: z right, y up");
  UNIT_CHECK(render_view_axes("y", &h, &u, &a, err, sizeof err) == 0 &&
             h == 0 && u == 2 && a == 1, "along y: x right, z up");
}

/* 2-D: every particle, in its body's colour */
static void test_plane(void) {
  particles ps;
  render_opts o = unit_window("body");
  render_layout L;
  canvas c;
  int i[DIM] = {0}, j;
  if (DIM != 2) return;
  lattice(&ps, -1);
  o.project = 1;  /* no meaning in 2-D */
  if (draw(&c, &L, &ps, &o, "2-D") == 0) {
    UNIT_CHECK(L.drawn == K * K, "2-D: all %d drawn (got %zu)", K * K, L.drawn);
    for (j = 0; j < K; j++) {
      i[DIM - 1] = j;
      UNIT_CHECK(px(&c, &L, &o, 0.5 * H, (j + 0.5) * H) ==
                     render_body_color(ps.body[lat(i)], L.matrix),
                 "2-D: row %d in its body's colour", j);
    }
  }
  canvas_free(&c);
  particles_free(&ps);
}

/* 3-D slices across z: one layer of particles, or a slab of two */
static void test_slices(void) {
  particles ps;
  render_opts o = unit_window("body");
  render_layout L;
  canvas c;
  if (DIM != 3) return;
  lattice(&ps, -1);
  o.has_at = 1;
  o.at = 0.49;  /* in layer 1 (0.25, 0.5) only */
  if (draw(&c, &L, &ps, &o, "slice") == 0) {
    UNIT_CHECK(L.drawn == K * K && L.at == 0.49,
               "slice z = 0.49: one layer, %d particles (got %zu)", K * K, L.drawn);
    UNIT_CHECK(px(&c, &L, &o, 0.6, 0.3) == render_body_color(1, L.matrix),
               "slice z = 0.49 shows layer 1");
  }
  canvas_free(&c);
  {
    /* layer 0 stretched 3 times along z reaches 0.375 from z = 0.125 */
    size_t p;
    for (p = 0; p < ps.n; p++)
      if (ps.body[p] == 0) ps.F[8][p] = 3;
    o.at = 0.45;
    if (draw(&c, &L, &ps, &o, "stretched") == 0)
      UNIT_CHECK(L.drawn == 2 * K * K, "slice z = 0.45 meets layer 1 and the "
                 "stretched layer 0 (got %zu)", L.drawn);
    canvas_free(&c);
    for (p = 0; p < ps.n; p++) ps.F[8][p] = 1;
  }
  o.at = 1.2;  /* beyond the particles */
  if (draw(&c, &L, &ps, &o, "empty slice") == 0)
    UNIT_CHECK(L.drawn == 0, "slice z = 1.2: none (got %zu)", L.drawn);
  canvas_free(&c);
  o.at = 0.5;
  o.thick = 0.6;  /* layers 1 and 2, centres 0.125 away; 0 and 3 are 0.375 */
  if (draw(&c, &L, &ps, &o, "slab") == 0) {
    UNIT_CHECK(L.drawn == 2 * K * K, "slab 0.6 at 0.5: two layers (got %zu)",
               L.drawn);
    UNIT_CHECK(px(&c, &L, &o, 0.6, 0.3) == render_body_color(2, L.matrix),
               "slab seen from +z: layer 2, the nearer, on top");
  }
  canvas_free(&c);
  o.has_at = 0;
  o.thick = 0;  /* the middle of the particles, z = 0.5: a face, no layer */
  if (draw(&c, &L, &ps, &o, "middle") == 0)
    UNIT_CHECK(L.at == 0.5, "default slice at the particles' middle (got %g)",
               L.at);
  canvas_free(&c);
  particles_free(&ps);
}

/*
** 3-D projections along each axis: every particle is drawn; mass is the
** index along the axis looked along, so the colour seen is the nearest
** layer's: the largest index seen from +z, the smallest from -x and -y.
** Body (the z layer) places the picture: along x, z runs to the right;
** along y, z runs up.
*/
static void test_projections(void) {
  static const char *const name[] = {"x", "y", "z"};
  static const int nearest[] = {0, 0, K - 1};
  particles ps;
  render_layout L;
  canvas c;
  int a;
  if (DIM != 3) return;
  for (a = 0; a < DIM; a++) {
    render_opts o = unit_window("mass");
    uint32_t want;
    lattice(&ps, a);
    o.axis = name[a];
    o.project = 1;
    o.has_range = 1;
    o.range[0] = 0;
    o.range[1] = K - 1;
    want = cmap_color(CMAP_SEQ, (double)nearest[a] / (K - 1));
    if (draw(&c, &L, &ps, &o, name[a]) == 0) {
      UNIT_CHECK(L.drawn == K * K * K, "along %s: all %d drawn (got %zu)",
                 name[a], K * K * K, L.drawn);
      UNIT_CHECK(px(&c, &L, &o, 0.3, 0.6) == want && px(&c, &L, &o, 0.9, 0.1) == want,
                 "along %s: the nearest layer (index %d) on top", name[a],
                 nearest[a]);
    }
    canvas_free(&c);
    particles_free(&ps);
  }
  /* placement: body = z layer */
  lattice(&ps, -1);
  for (a = 0; a < 2; a++) {
    render_opts o = unit_window("body");
    o.axis = name[a];
    o.project = 1;
    if (draw(&c, &L, &ps, &o, "placement") == 0) {
      double z0 = a == 0 ? 0.1 : 0.5, u0 = a == 0 ? 0.5 : 0.1;
      double z3 = a == 0 ? 0.9 : 0.5, u3 = a == 0 ? 0.5 : 0.9;
      UNIT_CHECK(px(&c, &L, &o, z0, u0) == render_body_color(0, L.matrix) &&
                 px(&c, &L, &o, z3, u3) == render_body_color(K - 1, L.matrix),
                 "along %s: z runs %s", name[a], a == 0 ? "right" : "up");
    }
    canvas_free(&c);
  }
  particles_free(&ps);
}

/* 3-D sdiff = s1 - s3 for stresses whose principal values are known */
static void test_sdiff(void) {
  /* xx, yy, zz, xy, yz, xz and the largest principal difference */
  static const double cases[][7] = {
      {3, 1, -2, 0, 0, 0, 5},      /* already principal */
      {0, 0, 0, 2, 0, 0, 4},       /* shear: +-2 and 0 */
      {0, 0, 0, 1, 1, 1, 3},       /* eigenvalues 2, -1, -1 */
      {5, 5, 5, 0, 0, 0, 0},       /* isotropic */
      {1, 2, 2, 0, 0.5, 0, 1.5},   /* yz block: 2.5 and 1.5; and 1 */
  };
  particles ps;
  double v[5];
  char err[512];
  int k, c;
  if (DIM != 3) return;
  particles_init(&ps);
  for (k = 0; k < 5; k++) {
    particles_push(&ps);
    for (c = 0; c < NSTRESS; c++) ps.s[c][k] = cases[k][c];
  }
  /* slots by name: S_XX.. S_XZ as dim.h orders them */
  UNIT_CHECK(render_values(&ps, "sdiff", 0, v, err, sizeof err) == RENDER_SCALAR,
             "sdiff: %s", err);
  for (k = 0; k < 5; k++) {
    double want = cases[k][6];
    char nm[64];
    snprintf(nm, sizeof nm, "sdiff 3-D case %d", k + 1);
    UNIT_NEAR(v[k], want, 1e-12 * (1 + want), nm);
  }
  particles_free(&ps);
}

int main(void) {
  test_axes();
  test_plane();
  test_slices();
  test_projections();
  test_sdiff();
  UNIT_END(DIM == 2 ? "test_render_view" : "test_render_view (3-D)");
}
