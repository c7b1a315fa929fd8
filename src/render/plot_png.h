/*
** plot_png.h - line plots as PNG: several (x, y) series on linear or
** log10 axes, drawn as lines, markers or both, with ticks, tick labels,
** axis titles, a plot title and a legend.
**
** Points that are NaN or infinite, or not > 0 on a log axis, are
** skipped, and a line breaks there instead of bridging the gap.  Ranges
** are the usable points' extent with 4% room (in decades on log axes);
** a single point or a constant series gets a range around its value, and
** a plot with no usable point still draws its axes.  Series k gets
** colour k of the categorical palette and marker shape k (disc, square,
** triangle, diamond, inverted triangle, cross, then again).  The legend
** (series with a label) goes in the corner of the plot that covers the
** fewest points.
*/
#ifndef mvmpm_plot_png_h
#define mvmpm_plot_png_h

#include <stddef.h>
#include "canvas.h"

enum { PLOT_LINE, PLOT_POINTS, PLOT_BOTH };
#define PLOT_MINW 200
#define PLOT_MINH 150

typedef struct plot_series {
  const double *x, *y;
  size_t n;
  const char *label;           /* NULL or "": not in the legend */
  int style;                   /* PLOT_LINE, PLOT_POINTS or PLOT_BOTH */
} plot_series;

typedef struct plot_opts {
  int width, height;           /* pixels */
  const char *title, *xlabel, *ylabel;  /* each may be NULL */
  int xlog, ylog;
  int has_xrange, has_yrange;  /* fixed ranges instead of automatic */
  double xrange[2], yrange[2];
} plot_opts;

typedef struct plot_layout {
  int w, h, scale;
  int px0, py0, px1, py1;      /* plot area [px0, px1) x [py0, py1) */
  double xlo, xhi, ylo, yhi;   /* the ranges shown */
} plot_layout;

/* pixel coordinates of a data point (NaN if it is not usable) */
void plot_map(const plot_layout *L, const plot_opts *o, double x, double y,
              double *px, double *py);
/* draw into c (initialised here; canvas_free it after); lay may be NULL.
** 0, or -1 with err */
int plot_draw(canvas *c, plot_layout *lay, const plot_series *s, int ns,
              const plot_opts *o, char *err, size_t errlen);
/* plot_draw then png_write; 0 or -1 with err naming the file */
int plot_png(const char *path, const plot_series *s, int ns,
             const plot_opts *o, char *err, size_t errlen);

#endif
