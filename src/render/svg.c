/*
** svg.c - the SVG writer: elements appended to a growing buffer.
*/
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "canvas.h"
#include "ofile.h"
#include "svg.h"

static void add(svg *g, const char *fmt, ...) {
  va_list ap;
  int k;
  if (g->failed) return;
  for (;;) {
    size_t room = g->cap - g->n;
    va_start(ap, fmt);
    k = vsnprintf(g->b + g->n, room, fmt, ap);
    va_end(ap);
    if (k < 0) { g->failed = 1; return; }
    if ((size_t)k < room) break;
    {
      size_t cap = 2 * g->cap + (size_t)k + 1;
      char *p = realloc(g->b, cap);
      if (!p) { g->failed = 1; return; }
      g->b = p;
      g->cap = cap;
    }
  }
  g->n += (size_t)k;
}

/* text with XML's special characters escaped and control bytes dropped */
static void addtext(svg *g, const char *s) {
  for (; *s; s++) {
    unsigned char c = (unsigned char)*s;
    if (c == '&') add(g, "&amp;");
    else if (c == '<') add(g, "&lt;");
    else if (c == '>') add(g, "&gt;");
    else if (c == '"') add(g, "&quot;");
    else if (c < 32 || c == 127) continue;
    else add(g, "%c", c);
  }
}

int svg_init(svg *g, int w, int h, uint32_t bg) {
  memset(g, 0, sizeof *g);
  g->cap = 1 << 16;
  g->b = malloc(g->cap);
  if (!g->b) return -1;
  add(g, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
      "viewBox=\"0 0 %d %d\" font-family=\"DejaVu Sans Mono, Menlo, "
      "Consolas, monospace\" shape-rendering=\"crispEdges\">\n"
      "<rect width=\"%d\" height=\"%d\" fill=\"#%06X\"/>\n", w, h, w, h, w, h,
      (unsigned)bg);
  return g->failed ? -1 : 0;
}

void svg_free(svg *g) {
  free(g->b);
  memset(g, 0, sizeof *g);
}

void svg_clip(svg *g, int x0, int y0, int x1, int y1) {
  svg_noclip(g);
  g->nclip++;
  add(g, "<clipPath id=\"c%d\"><rect x=\"%d\" y=\"%d\" width=\"%d\" "
      "height=\"%d\"/></clipPath>\n<g clip-path=\"url(#c%d)\">\n", g->nclip,
      x0, y0, x1 - x0, y1 - y0, g->nclip);
  g->clipped = 1;
}

void svg_noclip(svg *g) {
  if (g->clipped) add(g, "</g>\n");
  g->clipped = 0;
}

void svg_rect(svg *g, double x0, double y0, double x1, double y1,
              uint32_t col) {
  if (!(x1 > x0) || !(y1 > y0)) return;
  add(g, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.6g\" height=\"%.6g\" "
      "fill=\"#%06X\"/>\n", x0, y0, x1 - x0, y1 - y0, (unsigned)col);
}

void svg_frame(svg *g, double x0, double y0, double x1, double y1, double t,
               uint32_t col) {
  add(g, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.6g\" height=\"%.6g\" "
      "fill=\"none\" stroke=\"#%06X\" stroke-width=\"%.6g\"/>\n", x0 + t / 2,
      y0 + t / 2, x1 - x0 - t, y1 - y0 - t, (unsigned)col, t);
}

void svg_poly(svg *g, int n, const double *xs, const double *ys,
              uint32_t col) {
  int k;
  add(g, "<path d=\"");
  for (k = 0; k < n; k++)
    add(g, "%c%.2f %.2f", k ? 'L' : 'M', xs[k], ys[k]);
  add(g, "Z\" fill=\"#%06X\"/>\n", (unsigned)col);
}

void svg_line(svg *g, double x0, double y0, double x1, double y1, double t,
              uint32_t col) {
  add(g, "<line x1=\"%.6g\" y1=\"%.6g\" x2=\"%.6g\" y2=\"%.6g\" "
      "stroke=\"#%06X\" stroke-width=\"%.6g\"/>\n", x0, y0, x1, y1,
      (unsigned)col, t);
}

/*
** The bitmap font's cell is 6 units wide with capitals 7 high; a
** monospace face at 10 units has an advance of about 6 and capitals of
** about 7, so the anchor points of canvas_text carry over: the baseline
** sits a capital's height below a top anchor.
*/
void svg_text(svg *g, double x, double y, const char *s, int scale,
              uint32_t col, int halign, int valign, int vertical) {
  static const char *const anchor[] = {"start", "middle", "end"};
  double cap = CANVAS_CAP(scale), base;
  if (!s[0]) return;
  base = valign == CV_TOP ? cap : valign == CV_MIDDLE ? cap / 2 : 0;
  if (vertical)
    add(g, "<text transform=\"translate(%.6g %.6g) rotate(-90)\" x=\"0\" "
        "y=\"%.6g\"", x + base, y, 0.0);
  else add(g, "<text x=\"%.6g\" y=\"%.6g\"", x, y + base);
  add(g, " font-size=\"%d\" text-anchor=\"%s\" fill=\"#%06X\">", 10 * scale,
      anchor[halign < 0 || halign > 2 ? 0 : halign], (unsigned)col);
  addtext(g, s);
  add(g, "</text>\n");
}

int svg_write(svg *g, const char *path, char *err, size_t errlen) {
  svg_noclip(g);
  add(g, "</svg>\n");
  if (g->failed) {
    snprintf(err, errlen, "%s: out of memory for the picture", path);
    return -1;
  }
  return ofile_put(path, g->b, g->n, err, errlen);
}
