/*
** render_png.h - pictures of the particles.
** Each particle is drawn as its deformed square: the square of side
** sqrt(volume0) (the cell over ppc for a seeded body) mapped by the
** particle's F about its position, so stretched, sheared and rotated
** particles look it.  Particles are drawn in store order over a white
** background inside the domain's outline, y up; the image is width
** pixels wide and as high as the domain's aspect needs, plus a title
** line and, on the right, a colour bar (scalars) or a legend (bodies).
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
** Colour range: as given, else the values' min and max, or +-max|v| with
** the diverging map.  Colormap "auto" picks the diverging map when the
** range holds both signs, else the sequential one.
**
** Output is a function of the input alone (no clocks, no randomness), so
** the same store gives the same bytes.
*/
#ifndef mvmpm_render_png_h
#define mvmpm_render_png_h

#include <stddef.h>
#include "canvas.h"
#include "particles.h"

#define RENDER_AUTO (-1)     /* colormap chosen from the data */
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
  int nnames;
  unsigned need;             /* fields without all these pfield flags
                                count as absent: a snapshot read back
                                holds only PF_OUTPUT ones */
} render_opts;

/* where things went, for tests and callers that annotate */
typedef struct render_layout {
  int w, h, scale;
  int dx0, dy0, dx1, dy1;    /* domain rectangle [dx0, dx1) x [dy0, dy1) */
  int bx0, by0, bx1, by1;    /* colour bar (scalars; zeros for bodies) */
  double sc;                 /* pixels per unit length */
  double vlo, vhi;           /* colour range used */
  int cmap;                  /* colormap used (scalars) */
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

#endif
