/*
** canvas.c - drawing primitives on an RGB raster.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas.h"
#include "font.h"
#include "png.h"

int canvas_init(canvas *c, int w, int h, uint32_t bg) {
  size_t i, n;
  memset(c, 0, sizeof *c);
  if (w < 1 || h < 1 || w > PNG_MAXDIM || h > PNG_MAXDIM) return -1;
  n = (size_t)w * h;
  c->px = malloc(n * 3);
  if (!c->px) return -1;
  c->w = w;
  c->h = h;
  for (i = 0; i < n; i++) {
    c->px[3 * i] = (unsigned char)(bg >> 16);
    c->px[3 * i + 1] = (unsigned char)(bg >> 8);
    c->px[3 * i + 2] = (unsigned char)bg;
  }
  canvas_noclip(c);
  return 0;
}

void canvas_free(canvas *c) {
  free(c->px);
  memset(c, 0, sizeof *c);
}

void canvas_clip(canvas *c, int x0, int y0, int x1, int y1) {
  c->cx0 = x0 < 0 ? 0 : x0;
  c->cy0 = y0 < 0 ? 0 : y0;
  c->cx1 = x1 > c->w ? c->w : x1;
  c->cy1 = y1 > c->h ? c->h : y1;
}

void canvas_noclip(canvas *c) { canvas_clip(c, 0, 0, c->w, c->h); }

uint32_t canvas_get(const canvas *c, int x, int y) {
  const unsigned char *p;
  if (x < 0 || y < 0 || x >= c->w || y >= c->h) return 0;
  p = c->px + 3 * ((size_t)y * c->w + x);
  return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

void canvas_px(canvas *c, int x, int y, uint32_t col) {
  unsigned char *p;
  if (x < c->cx0 || y < c->cy0 || x >= c->cx1 || y >= c->cy1) return;
  p = c->px + 3 * ((size_t)y * c->w + x);
  p[0] = (unsigned char)(col >> 16);
  p[1] = (unsigned char)(col >> 8);
  p[2] = (unsigned char)col;
}

void canvas_rect(canvas *c, int x0, int y0, int x1, int y1, uint32_t col) {
  int x, y;
  if (x0 < c->cx0) x0 = c->cx0;
  if (y0 < c->cy0) y0 = c->cy0;
  if (x1 > c->cx1) x1 = c->cx1;
  if (y1 > c->cy1) y1 = c->cy1;
  for (y = y0; y < y1; y++)
    for (x = x0; x < x1; x++) canvas_px(c, x, y, col);
}

void canvas_frame(canvas *c, int x0, int y0, int x1, int y1, int t,
                  uint32_t col) {
  canvas_rect(c, x0, y0, x1, y0 + t, col);
  canvas_rect(c, x0, y1 - t, x1, y1, col);
  canvas_rect(c, x0, y0, x0 + t, y1, col);
  canvas_rect(c, x1 - t, y0, x1, y1, col);
}

/* clamp a coordinate range to the clip rectangle, in pixel indices */
static int span(double lo, double hi, int c0, int c1, int *i0, int *i1) {
  if (!(lo <= hi)) return 0; /* NaN */
  if (lo < c0) lo = c0;
  if (hi > c1 - 1) hi = c1 - 1;
  if (lo > hi) return 0;
  *i0 = (int)floor(lo);
  *i1 = (int)floor(hi);
  return 1;
}

void canvas_poly(canvas *c, int n, const double *xs, const double *ys,
                 uint32_t col) {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  double area = 0, cxm = 0, cym = 0, sgn;
  int i, j, ix0, ix1, iy0, iy1, x, y, hit = 0;
  if (n < 3 || n > 8) return;
  for (i = 0; i < n; i++) {
    j = (i + 1) % n;
    if (!isfinite(xs[i]) || !isfinite(ys[i])) return;
    if (xs[i] < x0) x0 = xs[i];
    if (xs[i] > x1) x1 = xs[i];
    if (ys[i] < y0) y0 = ys[i];
    if (ys[i] > y1) y1 = ys[i];
    area += xs[i] * ys[j] - xs[j] * ys[i];
    cxm += xs[i];
    cym += ys[i];
  }
  sgn = area < 0 ? -1 : 1;
  /* pixel centres x + 0.5 within [x0, x1] */
  if (span(x0 - 0.5, x1 - 0.5, c->cx0, c->cx1, &ix0, &ix1) &&
      span(y0 - 0.5, y1 - 0.5, c->cy0, c->cy1, &iy0, &iy1)) {
    if (x0 - 0.5 > ix0) ix0++; /* first centre at or right of x0 */
    if (y0 - 0.5 > iy0) iy0++;
    for (y = iy0; y <= iy1; y++)
      for (x = ix0; x <= ix1; x++) {
        double px = x + 0.5, py = y + 0.5;
        for (i = 0; i < n; i++) {
          j = (i + 1) % n;
          if (sgn * ((xs[j] - xs[i]) * (py - ys[i]) -
                     (ys[j] - ys[i]) * (px - xs[i])) < 0)
            break;
        }
        if (i == n) {
          canvas_px(c, x, y, col);
          hit = 1;
        }
      }
  }
  if (!hit) {
    double fx = floor(cxm / n), fy = floor(cym / n);
    if (fx >= c->cx0 && fx < c->cx1 && fy >= c->cy0 && fy < c->cy1)
      canvas_px(c, (int)fx, (int)fy, col);
  }
}

void canvas_disc(canvas *c, double x, double y, double r, uint32_t col) {
  int ix0, ix1, iy0, iy1, i, j;
  if (!(r > 0) || !span(x - r - 0.5, x + r - 0.5, c->cx0, c->cx1, &ix0, &ix1) ||
      !span(y - r - 0.5, y + r - 0.5, c->cy0, c->cy1, &iy0, &iy1))
    return;
  for (j = iy0; j <= iy1 + 1; j++)
    for (i = ix0; i <= ix1 + 1; i++) {
      double dx = i + 0.5 - x, dy = j + 0.5 - y;
      if (dx * dx + dy * dy <= r * r) canvas_px(c, i, j, col);
    }
}

/* a thick line as a filled rectangle around the segment, with square
** caps half the width long so that polylines join without gaps */
void canvas_line(canvas *c, double x0, double y0, double x1, double y1,
                 int t, uint32_t col) {
  double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy), hw;
  double ux, uy, xs[4], ys[4];
  if (!isfinite(len)) return;
  if (t < 1) t = 1;
  hw = 0.5 * t;
  if (len < 1e-9) { ux = 1; uy = 0; }
  else { ux = dx / len; uy = dy / len; }
  x0 -= ux * hw; y0 -= uy * hw;
  x1 += ux * hw; y1 += uy * hw;
  xs[0] = x0 - uy * hw; ys[0] = y0 + ux * hw;
  xs[1] = x1 - uy * hw; ys[1] = y1 + ux * hw;
  xs[2] = x1 + uy * hw; ys[2] = y1 - ux * hw;
  xs[3] = x0 + uy * hw; ys[3] = y0 - ux * hw;
  canvas_poly(c, 4, xs, ys, col);
}

/* the rows of a glyph: a string of r rows is 6 r - 1 characters long */
static int rows(const char *g) { return g[0] ? (int)(strlen(g) + 1) / 6 : 0; }

/*
** Glyph metrics: letters are as wide as their ink plus one column of
** space, so "il" is not spread out; digits keep the full cell, so that
** columns of numbers line up.
*/
static void metrics(unsigned long cp, const char *g, int *left, int *adv) {
  int col, r, n = rows(g), l = FONT_W, rt = -1;
  for (r = 0; r < n; r++)
    for (col = 0; col < FONT_W; col++)
      if (g[r * 6 + col] == '#') {
        if (col < l) l = col;
        if (col > rt) rt = col;
      }
  if ((cp >= '0' && cp <= '9') || rt < 0) {
    *left = 0;
    *adv = rt < 0 ? 3 : FONT_W + 1;
    return;
  }
  *left = l;
  *adv = rt - l + 2;
}

static const char *glyph(unsigned long cp) {
  const char *g = font_glyph(cp);
  return g ? g : font_glyph('?');
}

int canvas_textw(const char *s, int scale) {
  int w = 0, left, adv;
  while (*s) {
    unsigned long cp = font_next(&s);
    metrics(cp, glyph(cp), &left, &adv);
    w += adv;
  }
  return w > 0 ? (w - 1) * scale : 0; /* no trailing space column */
}

int canvas_text(canvas *c, int x, int y, const char *s, int scale,
                uint32_t col, int halign, int valign, int vertical) {
  int w = canvas_textw(s, scale), pen = 0, left, adv, r, k, i, j;
  if (halign == CV_CENTER) pen = -w / 2;
  else if (halign == CV_RIGHT) pen = -w;
  if (valign == CV_MIDDLE) {
    if (vertical) x -= CANVAS_CAP(scale) / 2;
    else y -= CANVAS_CAP(scale) / 2;
  } else if (valign == CV_BOTTOM) {
    if (vertical) x -= CANVAS_CAP(scale);
    else y -= CANVAS_CAP(scale);
  }
  while (*s) {
    unsigned long cp = font_next(&s);
    const char *g = glyph(cp);
    int n = rows(g);
    metrics(cp, g, &left, &adv);
    for (r = 0; r < n && r < FONT_H; r++) {
      const char *row = g + r * 6;
      for (k = 0; k < FONT_W; k++) {
        if (row[k] != '#') continue;
        for (j = 0; j < scale; j++)
          for (i = 0; i < scale; i++) {
            int u = pen + (k - left) * scale + i, v = r * scale + j;
            if (vertical) canvas_px(c, x + v, y - u - 1, col);
            else canvas_px(c, x + u, y + v, col);
          }
      }
    }
    pen += adv * scale;
  }
  return w;
}
