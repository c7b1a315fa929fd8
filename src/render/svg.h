/*
** svg.h - pictures as SVG: the same primitives as canvas.h (rectangles,
** polygons, lines, text) written as vector elements, so a figure scales
** without pixels and its text stays text.  Coordinates are the canvas's
** pixels (y down); text is a monospace font sized so that its advance
** matches the bitmap font's cell, so layouts made with canvas_textw
** hold.  The document is built in memory and written to "<path>.tmp",
** then renamed, as png_write does.
*/
#ifndef mvmpm_svg_h
#define mvmpm_svg_h

#include <stddef.h>
#include <stdint.h>

typedef struct svg {
  char *b;
  size_t n, cap;
  int failed;        /* out of memory: everything after is dropped */
  int clipped;       /* inside a clip group */
  int nclip;         /* clip paths made, for their ids */
} svg;

/* 0, or -1 if out of memory */
int svg_init(svg *g, int w, int h, uint32_t bg);
void svg_free(svg *g);
/* draw into [x0, x1) x [y0, y1) only, until svg_noclip */
void svg_clip(svg *g, int x0, int y0, int x1, int y1);
void svg_noclip(svg *g);
void svg_rect(svg *g, double x0, double y0, double x1, double y1,
              uint32_t col);
/* the outline of a rectangle, t thick, inside it (as canvas_frame) */
void svg_frame(svg *g, double x0, double y0, double x1, double y1, double t,
               uint32_t col);
void svg_poly(svg *g, int n, const double *xs, const double *ys,
              uint32_t col);
void svg_line(svg *g, double x0, double y0, double x1, double y1, double t,
              uint32_t col);
/* text as canvas_text draws it at scale s (alignments of canvas.h) */
void svg_text(svg *g, double x, double y, const char *s, int scale,
              uint32_t col, int halign, int valign, int vertical);
/* close the document and write it; 0 or -1 with err naming path */
int svg_write(svg *g, const char *path, char *err, size_t errlen);

#endif
