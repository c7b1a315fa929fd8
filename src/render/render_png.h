/*
** render_png.h - pictures of the particles.
** Each particle is drawn as its deformed square: the square of side
** sqrt(volume0) (the cell over ppc for a seeded body) mapped by the
** particle's F about its position, so stretched, sheared and rotated
** particles look it; on a raster each reaches 0.35 pixel past its edges,
** so that the seams between a turned body's particles do not show as
** pinholes (in an SVG it is exact); a square stretched more than 4 : 1
** is drawn stretched 4 : 1 along the same axes with the same area.
** Particles are drawn in store order over a white background inside
** the domain's outline, y up; the image is width pixels wide and as
** high as the domain's aspect needs, plus a title line and, on the
** right, a colour bar (scalars) or a legend (bodies).
**
** Colouring keys ("by"):
**   body          categorical colour per body, with a legend
**   pressure      -(s_xx + s_yy + s_zz) / 3 (plane strain keeps s_zz)
**   sdiff         in-plane principal stress difference |s1 - s2|
**                 = sqrt((s_xx - s_yy)^2 + 4 s_xy^2)
**   speed         |v|
**   NAME[.COMP]   a field of the store, e.g. mass, velocity.x, stress.xy,
**                 bond; COMP is a component name or its number from 1.
** A field of the store with one of the derived names wins over the
** derivation.  NaN values are drawn grey (CMAP_NAN).
**
** Colour range: as given; else (RENDER_ROBUST) the 1st to 99th
** percentile of the finite values, so that a few outliers do not wash
** out the rest (the true min and max are printed under the bar, and
** the whole extent is used when the percentiles are equal or within
** 1e-9 of the largest |value|); RENDER_FULL takes min and max.  With
** the diverging map the range is +-max|end|.  A component whose values
** are all within RENDER_ROUNDOFF of its field's largest component (e.g.
** stress.xy of a state with stress.xx = 1e5 and stress.xy = 1e-13) is
** round-off: its range is that of the field, so it draws as zero.
** Colormap "auto" picks the diverging map when the range holds both
** signs, else the sequential one.  log: the colour goes with log10 of
** the value; the range must be above zero (data or given), else an
** error says so.
**
** Around the domain: ticks with labels in world units, axis titles
** "x (UNIT)" and "y (UNIT)" (without a unit when unit is NULL; metres
** become mm under 0.1 m of width and μm under 0.1 mm), and a scale bar
** of a 1-2-5 length near a fifth of the width under it; noaxes leaves out the ticks and
** titles.  By body: a categorical colour per body, except that a matrix
** (the body named by matrix; else one whose name begins with "binder"
** or "matrix"; else, among three or more bodies, one holding over a
** quarter of the particles and twice any other's) is drawn in the
** neutral RENDER_MATRIX grey, which no grain colour is.
**
** In 3-D the picture looks along an axis (axis "x", "y" or "z"; z by
** default) with the other two across it, never mirrored: along z, x to
** the right and y up, seen from +z; along x, z right and y up, seen from
** -x; along y, x right and z up, seen from -y.  lo and hi are then the
** window in those two axes (render_view_axes names them).  A slice
** (project 0) draws the particles whose cube (side cbrt(volume0),
** mapped by F) crosses the plane at `at` along the axis, or with
** thick > 0 those whose centre is within thick / 2 of it; `at` is,
** unless given, the middle of the particles' extent along the axis.
** The colour range is taken from all the particles, so that slices of
** one store share it.  A projection (project 1) draws them
** all.  Either way the farthest are drawn first, so the nearest are on
** top, and each is the face of its cube across the axis mapped by the
** block of F in the picture's plane.  sdiff in 3-D is the largest
** principal stress difference s1 - s3.  A 2-D store takes axis NULL or
** "z" and ignores the rest.
**
** Output is a function of the input alone (no clocks, no randomness), so
** the same store gives the same bytes.  A file name ending in ".svg"
** gets the same picture as SVG (render_file): particles as polygons,
** text as text.
*/
#ifndef mvmpm_render_png_h
#define mvmpm_render_png_h

#include <stddef.h>
#include <stdint.h>
#include "canvas.h"
#include "particles.h"

#define RENDER_AUTO (-1)     /* colormap chosen from the data */
#define RENDER_MATRIX 0xBDBDBDu /* a matrix body's colour */
#define RENDER_ROUNDOFF 1e-9 /* relative size of round-off */
enum { RENDER_ROBUST, RENDER_FULL }; /* automatic colour ranges */
#define RENDER_MINW 120      /* narrowest image */

typedef struct render_opts {
  const char *by;            /* colouring key; NULL means "body" */
  int width;                 /* image width in pixels */
  int cmap;                  /* RENDER_AUTO, CMAP_SEQ or CMAP_DIV */
  int has_range;
  double range[2];           /* colour range (range[0] < range[1]) */
  const char *title;         /* NULL or "": no title line */
  double lo[2], hi[2];       /* the window in world coordinates */
  const char *const *names;  /* names of bodies 0.., or NULL */
  const int *driven;         /* per body: driven (noted in the legend), or NULL */
  int nnames;                /* entries of names and driven */
  int autorange;             /* RENDER_ROBUST or RENDER_FULL */
  int log;                   /* log10 colour scale */
  int noaxes;                /* no ticks, labels or axis titles */
  const char *unit;          /* length unit for the axes, or NULL */
  const char *matrix;        /* the matrix body's name, or NULL: guessed */
  unsigned need;             /* fields without all these pfield flags
                                count as absent: a snapshot read back
                                holds only PF_OUTPUT ones */
  /* 3-D (above): zero for all of them is the slice across z through
  ** the middle of the particles */
  const char *axis;          /* "x", "y" or "z" looked along; NULL: "z" */
  int project;               /* 1: all particles; 0: a slice */
  int has_at;
  double at;                 /* the slice's place along the axis */
  double thick;              /* > 0: the slab's thickness; 0: each
                                particle's own cube */
} render_opts;

/* where things went, for tests and callers that annotate */
typedef struct render_layout {
  int w, h, scale;
  int dx0, dy0, dx1, dy1;    /* domain rectangle [dx0, dx1) x [dy0, dy1) */
  int bx0, by0, bx1, by1;    /* colour bar (scalars; zeros for bodies) */
  double sc;                 /* pixels per unit length */
  double vlo, vhi;           /* colour range used */
  double vmin, vmax;         /* the finite values' true extent */
  int roundoff;              /* the values are round-off of their field */
  int cmap;                  /* colormap used (scalars) */
  int matrix;                /* body drawn as the matrix, or -1 */
  double bar;                /* the scale bar's length in the axes' unit */
  size_t drawn;              /* particles drawn (3-D: in the slice) */
  double at;                 /* 3-D slice: its place along the axis */
} render_layout;

/* what a key gives */
enum { RENDER_SCALAR, RENDER_BODY };

/* values of key by for every particle into out (ps->n doubles; out may
** be NULL to only check the key); need as in render_opts.  Returns
** RENDER_SCALAR or RENDER_BODY, or -1 with a message in err that names
** the key and lists the keys there are. */
int render_values(const particles *ps, const char *by, unsigned need,
                  double *out, char *err, size_t errlen);

/* draw into c (initialised here; canvas_free it after); lay may be NULL.
** 0, or -1 with err. */
int render_draw(canvas *c, render_layout *lay, const particles *ps,
                const render_opts *o, char *err, size_t errlen);

/* render_draw then png_write; 0 or -1 with err naming the file */
int render_png(const char *path, const particles *ps, const render_opts *o,
               char *err, size_t errlen);
/* the same picture as an SVG file */
int render_svg(const char *path, const particles *ps, const render_opts *o,
               char *err, size_t errlen);
/* render_svg when path ends in ".svg" (any case), else render_png */
int render_file(const char *path, const particles *ps, const render_opts *o,
                char *err, size_t errlen);
/* the axes of a picture looked along axis (render_opts.axis; NULL is
** "z"): h across to the right, u up, a along (-1 in 2-D).  0, or -1 with
** err for a name that is not an axis of this build. */
int render_view_axes(const char *axis, int *h, int *u, int *a, char *err,
                     size_t errlen);
/* the colour of body b in a picture whose matrix body is matrix */
uint32_t render_body_color(int b, int matrix);
/* the length unit of a scene's units string: "m" for "SI", "cm" for
** "cgs", the string itself if it is a length unit (m, mm, um, cm, km,
** in, ft), else NULL (e.g. "nondimensional") */
const char *render_length_unit(const char *units);

#endif
