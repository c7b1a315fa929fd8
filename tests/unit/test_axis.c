/*
** test_axis.c - axes, plots and colour bars at the edges of the doubles:
** ranges of denormals, ranges wider than the largest double (1.7e308 -
** -1.7e308 overflows), huge values, infinities.  What must hold: every
** tick is finite and inside its range, padded ranges stay finite with
** lo < hi, positions along an axis are right, and nothing goes through
** an int cast out of range (make test SAN=1 stops at the first one).
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "axis.h"
#include "canvas.h"
#include "cmap.h"
#include "particles.h"
#include "plot_png.h"
#include "render_png.h"
#include "unit.h"

/* every tick finite and inside [lo, hi], and at least two */
static int good_ticks(const double *t, int n, double lo, double hi) {
  int k;
  if (n < 2 || n > AXIS_MAXTICKS) return 0;
  for (k = 0; k < n; k++)
    if (!isfinite(t[k]) || t[k] < lo || t[k] > hi) return 0;
  return 1;
}

static void test_ticks(void) {
  static const double r[][2] = {
      {0, 5e-324},             /* one denormal apart */
      {1e-310, 3e-310},        /* denormals */
      {-1.7e308, 1.7e308},     /* hi - lo overflows */
      {-DBL_MAX, DBL_MAX},
      {1e308, 1.7e308},
      {1, 1 + 2.3e-16},        /* one ulp apart */
      {1e300, 1e300 * (1 + 1e-15)},
      {-1e-300, 1e-300}};
  double t[AXIS_MAXTICKS], step;
  size_t i;
  for (i = 0; i < sizeof r / sizeof r[0]; i++) {
    int n = axis_ticks(r[i][0], r[i][1], 6, t, &step);
    UNIT_CHECK(good_ticks(t, n, r[i][0], r[i][1]) && isfinite(step) && step >= 0,
               "ticks of [%g, %g]: %d, finite and inside (step %g)", r[i][0], r[i][1], n,
               step);
  }
}

static void test_logticks(void) {
  static const double r[][2] = {{5e-324, 1e-320}, {5e-324, DBL_MAX}, {1e-310, 1},
                                {1e300, DBL_MAX}};
  double t[AXIS_MAXTICKS], mn[4 * AXIS_MAXTICKS];
  size_t i;
  for (i = 0; i < sizeof r / sizeof r[0]; i++) {
    int nm, n = axis_logticks(r[i][0], r[i][1], t, mn, &nm);
    UNIT_CHECK(good_ticks(t, n, r[i][0], r[i][1]), "log ticks of [%g, %g]: %d inside",
               r[i][0], r[i][1], n);
  }
}

static void test_pad(void) {
  static const double r[][2] = {{-1.7e308, 1.7e308}, {DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX},
                                {5e-324, 5e-324}, {0, 5e-324}, {1e-310, 1e-310}};
  size_t i;
  for (i = 0; i < sizeof r / sizeof r[0]; i++) {
    double lo = r[i][0], hi = r[i][1];
    axis_pad(&lo, &hi, 0);
    UNIT_CHECK(isfinite(lo) && isfinite(hi) && hi > lo && lo <= r[i][0] && hi >= r[i][1],
               "[%g, %g] padded to [%g, %g]: finite, lo < hi, holding it", r[i][0], r[i][1],
               lo, hi);
  }
  {
    double lo = 5e-324, hi = DBL_MAX;
    axis_pad(&lo, &hi, 1);
    UNIT_CHECK(lo > 0 && isfinite(hi) && hi > lo, "log [5e-324, max] padded to [%g, %g]", lo,
               hi);
    lo = hi = 5e-324;
    axis_pad(&lo, &hi, 1);
    UNIT_CHECK(lo > 0 && isfinite(hi) && hi > lo, "log [5e-324, 5e-324] padded to [%g, %g]",
               lo, hi);
  }
}

static void test_labels(void) {
  char b[64];
  axis_label(1, INFINITY, b, sizeof b);
  UNIT_CHECK(strcmp(b, "1") == 0, "label of 1 with an infinite step (got %s)", b);
  axis_label(1e-310, 5e-324, b, sizeof b);
  UNIT_CHECK(strncmp(b, "1e-310", 6) == 0, "label of a denormal (got %s)", b);
  axis_label(1e308, 1e308, b, sizeof b);
  UNIT_CHECK(strcmp(b, "1e308") == 0, "label of 1e308 (got %s)", b);
}

/* plots of huge and tiny values: finite ranges, points where they belong */
static void test_plot_extremes(void) {
  double xa[2] = {-1.7e308, 1.7e308}, ya[2] = {1.7e308, -1.7e308};
  double xb[3] = {0, 5e-324, 1e-323}, yb[3] = {5e-324, 5e-324, 5e-324};
  double xc[3] = {1, 2, 3}, yc[3] = {NAN, INFINITY, 1e308};
  plot_series s = {xa, ya, 2, "huge", PLOT_BOTH};
  plot_opts o;
  plot_layout L;
  canvas c;
  char err[512];
  double px, py;
  memset(&o, 0, sizeof o);
  o.width = 400;
  o.height = 300;
  UNIT_CHECK(plot_draw(&c, &L, &s, 1, &o, err, sizeof err) == 0, "plot of +-1.7e308: %s", err);
  canvas_free(&c);
  UNIT_CHECK(isfinite(L.xlo) && isfinite(L.xhi) && L.xlo <= xa[0] && L.xhi >= xa[1],
             "+-1.7e308: finite x range [%g, %g] holding the points", L.xlo, L.xhi);
  plot_map(&L, &o, 0, 0, &px, &py);
  UNIT_CHECK(fabs(px - 0.5 * (L.px0 + L.px1)) < 1 && fabs(py - 0.5 * (L.py0 + L.py1)) < 1,
             "+-1.7e308: (0, 0) maps to the middle (%g, %g)", px, py);
  s.x = xb; s.y = yb; s.n = 3;
  UNIT_CHECK(plot_draw(&c, &L, &s, 1, &o, err, sizeof err) == 0, "plot of denormals: %s", err);
  canvas_free(&c);
  UNIT_CHECK(L.xhi > L.xlo && L.yhi > L.ylo && L.ylo < 5e-324 && L.yhi > 5e-324,
             "denormals: ranges [%g, %g] x [%g, %g] with room", L.xlo, L.xhi, L.ylo, L.yhi);
  o.ylog = 1;
  UNIT_CHECK(plot_draw(&c, &L, &s, 1, &o, err, sizeof err) == 0, "log plot of denormals: %s",
             err);
  canvas_free(&c);
  UNIT_CHECK(L.ylo > 0 && L.yhi > L.ylo, "denormals on a log axis: [%g, %g]", L.ylo, L.yhi);
  o.ylog = 0;
  s.x = xc; s.y = yc;
  UNIT_CHECK(plot_draw(&c, &L, &s, 1, &o, err, sizeof err) == 0, "NaN, inf, 1e308: %s", err);
  canvas_free(&c);
  UNIT_CHECK(isfinite(L.ylo) && isfinite(L.yhi) && L.yhi >= 1e308, "y range [%g, %g]", L.ylo,
             L.yhi);
  o.has_yrange = 1;
  o.yrange[0] = 0; o.yrange[1] = INFINITY;
  UNIT_CHECK(plot_draw(&c, &L, &s, 1, &o, err, sizeof err) < 0 && strstr(err, "finite"),
             "an infinite yrange refused: %s", err);
}

/* colour bars over +-1.7e308 and denormals: finite ranges, ticks inside */
static void test_render_extremes(void) {
  static const double r[][2] = {{-1.7e308, 1.7e308}, {0, 5e-324}, {DBL_MAX / 2, DBL_MAX}};
  particles ps;
  render_opts o;
  render_layout L;
  canvas c;
  char err[2048];
  size_t i;
  particles_init(&ps);
  particles_push(&ps);
  ps.vol0[0] = 0.01;
  ps.m[0] = DBL_MAX;
  ps.x[0][0] = ps.x[1][0] = 0.5;
  memset(&o, 0, sizeof o);
  o.by = "mass";
  o.width = 400;
  o.cmap = RENDER_AUTO;
  o.hi[0] = o.hi[1] = 1;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "mass = max double: %s", err);
  canvas_free(&c);
  UNIT_CHECK(isfinite(L.vlo) && isfinite(L.vhi) && L.vhi > L.vlo,
             "a constant max double gets the finite range [%g, %g]", L.vlo, L.vhi);
  o.has_range = 1;
  for (i = 0; i < sizeof r / sizeof r[0]; i++) {
    o.range[0] = r[i][0];
    o.range[1] = r[i][1];
    UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 &&
               canvas_get(&c, (L.bx0 + L.bx1) / 2, (L.by0 + L.by1) / 2) != 0xFFFFFFu,
               "colour range [%g, %g] draws its bar: %s", r[i][0], r[i][1], err);
    canvas_free(&c);
  }
  o.range[0] = -1.7e308; o.range[1] = 1.7e308;
  ps.m[0] = 0;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 &&
             canvas_get(&c, L.dx0 + (L.dx1 - L.dx0) / 2, L.dy0 + (L.dy1 - L.dy0) / 2) ==
                 cmap_color(CMAP_DIV, 0.5),
             "0 in +-1.7e308 has the middle colour");
  canvas_free(&c);
  /* a window 1e6 times as high as wide is refused before its height
  ** becomes an int */
  o.hi[1] = 1e6;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 && strstr(err, "high"),
             "a tall window refused: %s", err);
  o.hi[1] = 1e300;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 && strstr(err, "high"),
             "a 1e300 high window refused: %s", err);
  particles_free(&ps);
}

int main(void) {
  test_ticks();
  test_logticks();
  test_pad();
  test_labels();
  test_plot_extremes();
  test_render_extremes();
  UNIT_END("test_axis");
}
