/*
** plot_png.c - the line-plot writer.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "axis.h"
#include "cmap.h"
#include "plot_png.h"
#include "png.h"

#define INK 0x000000u
#define GRID 0xE4E4E4u
#define BG 0xFFFFFFu

static int usable(double x, double y, int xlog, int ylog) {
  return isfinite(x) && isfinite(y) && (!xlog || x > 0) && (!ylog || y > 0);
}

/* position along an axis as a fraction of its length */
static double frac(double v, double lo, double hi, int log) {
  if (log) return (log10(v) - log10(lo)) / (log10(hi) - log10(lo));
  return axis_frac(v, lo, hi);
}

void plot_map(const plot_layout *L, const plot_opts *o, double x, double y,
              double *px, double *py) {
  if (!usable(x, y, o->xlog, o->ylog)) { *px = *py = NAN; return; }
  *px = L->px0 + frac(x, L->xlo, L->xhi, o->xlog) * (L->px1 - L->px0);
  *py = L->py1 - frac(y, L->ylo, L->yhi, o->ylog) * (L->py1 - L->py0);
}

static void marker(canvas *c, int shape, double x, double y, double r,
                   uint32_t col, int s) {
  double xs[4], ys[4];
  switch (shape % 6) {
  case 0: canvas_disc(c, x, y, r, col); break;
  case 1:
    xs[0] = xs[3] = x - 0.85 * r; xs[1] = xs[2] = x + 0.85 * r;
    ys[0] = ys[1] = y - 0.85 * r; ys[2] = ys[3] = y + 0.85 * r;
    canvas_poly(c, 4, xs, ys, col);
    break;
  case 2: case 4: {
    double d = shape % 6 == 2 ? 1 : -1;
    xs[0] = x; ys[0] = y - d * 1.15 * r;
    xs[1] = x + r; ys[1] = y + d * 0.75 * r;
    xs[2] = x - r; ys[2] = y + d * 0.75 * r;
    canvas_poly(c, 3, xs, ys, col);
    break;
  }
  case 3:
    xs[0] = x; ys[0] = y - 1.2 * r;
    xs[1] = x + 1.2 * r; ys[1] = y;
    xs[2] = x; ys[2] = y + 1.2 * r;
    xs[3] = x - 1.2 * r; ys[3] = y;
    canvas_poly(c, 4, xs, ys, col);
    break;
  default:
    canvas_line(c, x - r, y - r, x + r, y + r, s, col);
    canvas_line(c, x - r, y + r, x + r, y - r, s, col);
  }
}

/* the range of the usable values of one axis */
static void extent(const plot_series *s, int ns, const plot_opts *o, int ax,
                   double *lo, double *hi) {
  double a = HUGE_VAL, b = -HUGE_VAL;
  int k;
  size_t i;
  for (k = 0; k < ns; k++)
    for (i = 0; i < s[k].n; i++)
      if (usable(s[k].x[i], s[k].y[i], o->xlog, o->ylog)) {
        double v = ax ? s[k].y[i] : s[k].x[i];
        if (v < a) a = v;
        if (v > b) b = v;
      }
  if (a > b) { /* nothing to show */
    int log = ax ? o->ylog : o->xlog;
    a = log ? 1 : 0;
    b = log ? 10 : 1;
  }
  *lo = a;
  *hi = b;
  axis_pad(lo, hi, ax ? o->ylog : o->xlog);
}

/* what a legend box (x0, y0, bw, bh, in pixels) hides: the points of the
** series' lines sampled every two pixels along each segment, and the
** markers (radius r) that reach into it */
static long hidden(const plot_layout *L, const plot_opts *o,
                   const plot_series *s, int ns, int x0, int y0, int bw,
                   int bh, double r) {
  long n = 0;
  int k;
  size_t i;
  for (k = 0; k < ns; k++) {
    double qx = NAN, qy = NAN, px, py;
    for (i = 0; i < s[k].n; i++) {
      plot_map(L, o, s[k].x[i], s[k].y[i], &px, &py);
      if (isnan(px)) { qx = NAN; continue; }
      if (s[k].style != PLOT_LINE &&
          px + r >= x0 && px - r < x0 + bw && py + r >= y0 && py - r < y0 + bh)
        n++;
      if (s[k].style != PLOT_POINTS && !isnan(qx)) {
        double d = fmax(fabs(px - qx), fabs(py - qy));
        int j, m = d > 2 ? (int)fmin(ceil(d / 2), 4096) : 1;
        for (j = 1; j <= m; j++) {
          double u = (double)j / m, x = qx + u * (px - qx), y = qy + u * (py - qy);
          if (x >= x0 && x < x0 + bw && y >= y0 && y < y0 + bh) n++;
        }
      }
      qx = px;
      qy = py;
    }
  }
  return n;
}

typedef struct ticks {
  double t[AXIS_MAXTICKS], minor[4 * AXIS_MAXTICKS], step;
  int n, nminor, maxw;
  char lab[AXIS_MAXTICKS][40];
} ticks;

static void maketicks(ticks *T, double lo, double hi, int log, int n, int s) {
  int k, expo = 0;
  T->nminor = 0;
  T->maxw = 0;
  T->step = 0;
  if (log) {
    T->n = axis_logticks(lo, hi, T->t, T->minor, &T->nminor);
    if (T->nminor == 0 && T->n > 1 && T->t[1] / T->t[0] < 9.99)
      T->step = T->t[1] - T->t[0];  /* 1-2-5 ticks within a decade */
  } else
    T->n = axis_ticks(lo, hi, n, T->t, &T->step);
  /* decades beyond 0.01 to 10^4 all read as 1e-3, 1e5, ... alike */
  if (log && T->step == 0 && T->n > 0 && (T->t[0] < 0.01 || T->t[T->n - 1] > 1e4))
    expo = 1;
  for (k = 0; k < T->n; k++) {
    int w;
    if (expo) snprintf(T->lab[k], sizeof T->lab[k], "1e%d", (int)floor(log10(T->t[k]) + 0.5));
    else axis_label(T->t[k], T->step > 0 ? T->step : T->t[k], T->lab[k],
                    sizeof T->lab[k]);
    w = canvas_textw(T->lab[k], s);
    if (w > T->maxw) T->maxw = w;
  }
}

/* A title wider than the image goes on two lines, split at the space
** nearest its middle, and is drawn smaller (down to scale 1) only if the
** longer line is still too wide (a study's titles name the case and the
** measure, and ran off both edges of the image).  Returns the number of
** lines; *ts the scale, first[] the first line when there are two
** (*second the rest). */
static int title_fit(const char *t, int width, int m, int sc, int *ts,
                     char *first, size_t cap, const char **second) {
  size_t n = strlen(t), i, best = 0;
  int room = width - 2 * m, w;
  *ts = sc;
  if (canvas_textw(t, sc) <= room || n >= cap) {
    while (*ts > 1 && canvas_textw(t, *ts) > room) (*ts)--;
    return 1;
  }
  for (i = 1; i < n; i++)
    if (t[i] == ' ' && (best == 0 || (i > n / 2 ? i - n / 2 : n / 2 - i) <
                                      (best > n / 2 ? best - n / 2 : n / 2 - best)))
      best = i;
  if (best == 0) {
    while (*ts > 1 && canvas_textw(t, *ts) > room) (*ts)--;
    return 1;
  }
  memcpy(first, t, best);
  first[best] = 0;
  *second = t + best + 1;
  for (;;) {
    w = canvas_textw(first, *ts);
    if (canvas_textw(*second, *ts) > w) w = canvas_textw(*second, *ts);
    if (w <= room || *ts == 1) return 2;
    (*ts)--;
  }
}

int plot_draw(canvas *c, plot_layout *lay, const plot_series *s, int ns,
              const plot_opts *o, char *err, size_t errlen) {
  plot_layout L;
  ticks X, Y;
  int sc, m, lh, top, left, bottom, right, k, nlab = 0, legw = 0, bw, bh;
  int tl, best = 0, corner, tlines = 0, ts = 1, pass;
  long bestn = -1;
  char tfirst[256];
  const char *tsecond = NULL;
  size_t i;
  memset(c, 0, sizeof *c);
  memset(&L, 0, sizeof L);
  if (o->width < PLOT_MINW || o->height < PLOT_MINH || o->width > PNG_MAXDIM ||
      o->height > PNG_MAXDIM) {
    snprintf(err, errlen, "size %d x %d: width must be in [%d, %d] and height "
             "in [%d, %d]", o->width, o->height, PLOT_MINW, PNG_MAXDIM,
             PLOT_MINH, PNG_MAXDIM);
    return -1;
  }
  if (o->has_xrange && !(o->xrange[1] > o->xrange[0] && isfinite(o->xrange[0]) &&
                          isfinite(o->xrange[1]) && (!o->xlog || o->xrange[0] > 0))) {
    snprintf(err, errlen, "xrange {%g, %g} must be finite with hi > lo%s", o->xrange[0],
             o->xrange[1], o->xlog ? " > 0 (log axis)" : "");
    return -1;
  }
  if (o->has_yrange && !(o->yrange[1] > o->yrange[0] && isfinite(o->yrange[0]) &&
                          isfinite(o->yrange[1]) && (!o->ylog || o->yrange[0] > 0))) {
    snprintf(err, errlen, "yrange {%g, %g} must be finite with hi > lo%s", o->yrange[0],
             o->yrange[1], o->ylog ? " > 0 (log axis)" : "");
    return -1;
  }
  sc = o->width / 400;
  sc = sc < 1 ? 1 : sc > 4 ? 4 : sc;
  m = 10 * sc;
  lh = CANVAS_LINE(sc);
  tl = 4 * sc; /* tick length */
  if (o->has_xrange) { L.xlo = o->xrange[0]; L.xhi = o->xrange[1]; }
  else extent(s, ns, o, 0, &L.xlo, &L.xhi);
  if (o->has_yrange) { L.ylo = o->yrange[0]; L.yhi = o->yrange[1]; }
  else extent(s, ns, o, 1, &L.ylo, &L.yhi);
  maketicks(&X, L.xlo, L.xhi, o->xlog, 7, sc);
  maketicks(&Y, L.ylo, L.yhi, o->ylog, 6, sc);

  if (o->title && o->title[0])
    tlines = title_fit(o->title, o->width, m, sc, &ts, tfirst, sizeof tfirst, &tsecond);
  top = m + (tlines ? tlines * CANVAS_LINE(ts) + 6 * sc : 0) + CANVAS_CAP(sc) / 2;
  bottom = m + tl + 3 * sc + lh + (o->xlabel && o->xlabel[0] ? lh + 2 * sc : 0);
  right = m + X.maxw / 2;
  L.scale = sc;
  L.w = o->width;
  L.h = o->height;
  L.px1 = o->width - right;
  L.py0 = top;
  L.py1 = o->height - bottom;
  for (k = 0; k < ns; k++)
    if (s[k].label && s[k].label[0]) {
      int w = canvas_textw(s[k].label, sc);
      if (w > legw) legw = w;
      nlab++;
    }
  bw = legw + 30 * sc;
  bh = nlab * lh + 6 * sc;
  /* the legend goes in the corner that hides the least of the series;
  ** where every corner hides some, the y axis is raised (unless its range
  ** is given) so that the series pass below the legend's height, and the
  ** corners are tried again */
  for (pass = 0; pass < 2; pass++) {
    left = m + (o->ylabel && o->ylabel[0] ? lh + 4 * sc : 0) + Y.maxw + 3 * sc + tl;
    L.px0 = left;
    if (L.px1 - L.px0 < 40 || L.py1 - L.py0 < 40) {
      snprintf(err, errlen, "size %d x %d leaves no room for the plot inside "
               "its labels; make it larger", o->width, o->height);
      return -1;
    }
    if (!nlab) break;
    bestn = -1;
    for (corner = 0; corner < 4; corner++) {
      int x0 = corner == 1 || corner == 3 ? L.px0 + 6 * sc : L.px1 - 6 * sc - bw;
      int y0 = corner < 2 ? L.py0 + 6 * sc : L.py1 - 6 * sc - bh;
      long n = hidden(&L, o, s, ns, x0, y0, bw, bh, 3.0 * sc);
      if (bestn < 0 || n < bestn) { bestn = n; best = corner; }
    }
    if (pass || bestn == 0 || o->has_yrange) break;
    {
      /* the part of the plot's height the legend and its margins take */
      double f = (double)(bh + 12 * sc) / (L.py1 - L.py0);
      if (!(f < 0.6)) break; /* no room to make: keep the best corner */
      if (o->ylog)
        L.yhi = pow(10, log10(L.ylo) + (log10(L.yhi) - log10(L.ylo)) / (1 - f));
      else
        L.yhi = L.ylo + (L.yhi - L.ylo) / (1 - f);
      maketicks(&Y, L.ylo, L.yhi, o->ylog, 6, sc);
    }
  }
  if (canvas_init(c, L.w, L.h, BG)) {
    snprintf(err, errlen, "out of memory for a %d x %d image", L.w, L.h);
    return -1;
  }

  /* grid, then the series clipped to the plot area, then the frame */
  for (k = 0; k < X.n; k++) {
    int x = L.px0 + (int)floor(frac(X.t[k], L.xlo, L.xhi, o->xlog) * (L.px1 - L.px0) + 0.5);
    canvas_rect(c, x, L.py0, x + 1, L.py1, GRID);
  }
  for (k = 0; k < Y.n; k++) {
    int y = L.py1 - (int)floor(frac(Y.t[k], L.ylo, L.yhi, o->ylog) * (L.py1 - L.py0) + 0.5);
    canvas_rect(c, L.px0, y, L.px1, y + 1, GRID);
  }
  canvas_clip(c, L.px0, L.py0, L.px1, L.py1);
  for (k = 0; k < ns; k++) {
    uint32_t col = cmap_category(k);
    double px, py, qx = NAN, qy = NAN;
    if (s[k].style != PLOT_POINTS)
      for (i = 0; i < s[k].n; i++) {
        plot_map(&L, o, s[k].x[i], s[k].y[i], &px, &py);
        if (!isnan(px) && !isnan(qx)) canvas_line(c, qx, qy, px, py, sc, col);
        qx = px;
        qy = py;
      }
    if (s[k].style != PLOT_LINE || s[k].n == 1)
      for (i = 0; i < s[k].n; i++) {
        plot_map(&L, o, s[k].x[i], s[k].y[i], &px, &py);
        if (!isnan(px)) marker(c, k, px, py, 3.0 * sc, col, sc);
      }
  }
  canvas_noclip(c);
  canvas_frame(c, L.px0 - sc, L.py0 - sc, L.px1 + sc, L.py1 + sc, sc, INK);

  /* ticks and their labels */
  for (k = 0; k < X.n; k++) {
    int x = L.px0 + (int)floor(frac(X.t[k], L.xlo, L.xhi, o->xlog) * (L.px1 - L.px0) + 0.5);
    canvas_rect(c, x - sc / 2, L.py1 + sc, x - sc / 2 + sc, L.py1 + sc + tl, INK);
    canvas_text(c, x, L.py1 + sc + tl + 3 * sc, X.lab[k], sc, INK, CV_CENTER,
                CV_TOP, 0);
  }
  for (k = 0; k < X.nminor; k++) {
    int x = L.px0 + (int)floor(frac(X.minor[k], L.xlo, L.xhi, 1) * (L.px1 - L.px0) + 0.5);
    canvas_rect(c, x - sc / 2, L.py1 + sc, x - sc / 2 + sc, L.py1 + sc + tl / 2, INK);
  }
  for (k = 0; k < Y.n; k++) {
    int y = L.py1 - (int)floor(frac(Y.t[k], L.ylo, L.yhi, o->ylog) * (L.py1 - L.py0) + 0.5);
    canvas_rect(c, L.px0 - sc - tl, y - sc / 2, L.px0 - sc, y - sc / 2 + sc, INK);
    canvas_text(c, L.px0 - sc - tl - 3 * sc, y, Y.lab[k], sc, INK, CV_RIGHT,
                CV_MIDDLE, 0);
  }
  for (k = 0; k < Y.nminor; k++) {
    int y = L.py1 - (int)floor(frac(Y.minor[k], L.ylo, L.yhi, 1) * (L.py1 - L.py0) + 0.5);
    canvas_rect(c, L.px0 - sc - tl / 2, y - sc / 2, L.px0 - sc, y - sc / 2 + sc, INK);
  }
  if (tlines) {
    const char *l1 = tlines == 2 ? tfirst : o->title;
    int w = canvas_textw(l1, ts), cx = (L.px0 + L.px1) / 2;
    if (tlines == 2 && canvas_textw(tsecond, ts) > w) w = canvas_textw(tsecond, ts);
    if (cx - w / 2 < m || cx + w / 2 > o->width - m) cx = o->width / 2;
    canvas_text(c, cx, m, l1, ts, INK, CV_CENTER, CV_TOP, 0);
    if (tlines == 2)
      canvas_text(c, cx, m + CANVAS_LINE(ts), tsecond, ts, INK, CV_CENTER, CV_TOP, 0);
  }
  if (o->xlabel && o->xlabel[0])
    canvas_text(c, (L.px0 + L.px1) / 2, L.py1 + sc + tl + 3 * sc + lh + 2 * sc,
                o->xlabel, sc, INK, CV_CENTER, CV_TOP, 0);
  if (o->ylabel && o->ylabel[0])
    canvas_text(c, m, (L.py0 + L.py1) / 2, o->ylabel, sc, INK, CV_CENTER,
                CV_TOP, 1);

  /* the legend, in the corner chosen above */
  if (nlab) {
    int x0, y0, y;
    x0 = best == 1 || best == 3 ? L.px0 + 6 * sc : L.px1 - 6 * sc - bw;
    y0 = best < 2 ? L.py0 + 6 * sc : L.py1 - 6 * sc - bh;
    canvas_rect(c, x0, y0, x0 + bw, y0 + bh, BG);
    canvas_frame(c, x0, y0, x0 + bw, y0 + bh, 1, 0x909090u);
    y = y0 + 3 * sc + CANVAS_CAP(sc) / 2 + sc;
    for (k = 0; k < ns; k++) {
      uint32_t col = cmap_category(k);
      if (!s[k].label || !s[k].label[0]) continue;
      if (s[k].style != PLOT_POINTS)
        canvas_line(c, x0 + 5 * sc, y, x0 + 23 * sc, y, sc, col);
      if (s[k].style != PLOT_LINE)
        marker(c, k, x0 + 14 * sc, y, 3.0 * sc, col, sc);
      canvas_text(c, x0 + 27 * sc, y, s[k].label, sc, INK, CV_LEFT, CV_MIDDLE, 0);
      y += lh;
    }
  }
  if (lay) *lay = L;
  return 0;
}

int plot_png(const char *path, const plot_series *s, int ns,
             const plot_opts *o, char *err, size_t errlen) {
  canvas c;
  int r;
  if (plot_draw(&c, NULL, s, ns, o, err, errlen)) {
    char why[512];
    snprintf(why, sizeof why, "%s", err);
    snprintf(err, errlen, "%s: %s", path, why);
    return -1;
  }
  r = png_write(path, c.px, c.w, c.h, 3, err, errlen);
  canvas_free(&c);
  return r;
}
