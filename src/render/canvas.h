/*
** canvas.h - an RGB raster to draw pictures on: filled rectangles,
** convex polygons, thick lines, discs and text in the bitmap font.
** Colours are 0xRRGGBB.  Every primitive clips to the canvas and to its
** clip rectangle, so callers may draw partly outside either.  Pixel
** (x, y) has its centre at (x + 0.5, y + 0.5); y grows downward.
*/
#ifndef mvmpm_canvas_h
#define mvmpm_canvas_h

#include <stddef.h>
#include <stdint.h>

typedef struct canvas {
  int w, h;
  unsigned char *px;         /* h rows of w pixels, 3 bytes each */
  int cx0, cy0, cx1, cy1;    /* clip rectangle [cx0, cx1) x [cy0, cy1) */
} canvas;

/* text alignment about the anchor point */
enum { CV_LEFT, CV_CENTER, CV_RIGHT };   /* horizontal */
enum { CV_TOP, CV_MIDDLE, CV_BOTTOM };   /* vertical, of the capitals */

/* 0, or -1 if out of memory or the size is not 1 to PNG_MAXDIM */
int canvas_init(canvas *c, int w, int h, uint32_t bg);
void canvas_free(canvas *c);
void canvas_clip(canvas *c, int x0, int y0, int x1, int y1);
void canvas_noclip(canvas *c);
uint32_t canvas_get(const canvas *c, int x, int y);
void canvas_px(canvas *c, int x, int y, uint32_t col);
/* [x0, x1) x [y0, y1) */
void canvas_rect(canvas *c, int x0, int y0, int x1, int y1, uint32_t col);
/* the outline of a rectangle, t pixels thick, drawn inside it */
void canvas_frame(canvas *c, int x0, int y0, int x1, int y1, int t,
                  uint32_t col);
/* a convex polygon of n <= 8 vertices: every pixel whose centre is
** inside; a polygon too small to hold a centre gets the pixel under its
** centroid, so nothing drawn ever vanishes */
void canvas_poly(canvas *c, int n, const double *xs, const double *ys,
                 uint32_t col);
void canvas_disc(canvas *c, double x, double y, double r, uint32_t col);
/* a line of width t pixels between two points */
void canvas_line(canvas *c, double x0, double y0, double x1, double y1,
                 int t, uint32_t col);
/* text at integer scale s; vertical text runs upward (rotated a quarter
** turn anticlockwise).  Returns the advance in pixels. */
int canvas_text(canvas *c, int x, int y, const char *s, int scale,
                uint32_t col, int halign, int valign, int vertical);
int canvas_textw(const char *s, int scale);
/* height of a line of text and of the capitals at scale s */
#define CANVAS_LINE(s) (12 * (s))
#define CANVAS_CAP(s) (7 * (s))

#endif
