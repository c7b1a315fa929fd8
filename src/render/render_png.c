/*
** render_png.c - the particle renderer: values, layout, drawing.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "axis.h"
#include "cmap.h"
#include "png.h"
#include "render_png.h"
#include "svg.h"
#include "vec.h"

#define INK 0x000000u
#define BG 0xFFFFFFu

/* the list of keys, for messages: derived ones, then each field with its
** components */
static void keylist(const particles *ps, unsigned need, char *buf, size_t n) {
  size_t len;
  int f, c;
  snprintf(buf, n, "pressure, sdiff, speed");
  for (f = 0; f < ps->nfields; f++) {
    const pfield *pf = &ps->fields[f];
    if ((pf->flags & need) != need) continue;
    len = strlen(buf);
    if (len + 40 >= n) break;
    snprintf(buf + len, n - len, ", %s", pf->name);
    for (c = 0; pf->ncomp > 1 && c < pf->ncomp; c++) {
      len = strlen(buf);
      if (pf->comp_names[c])
        snprintf(buf + len, n - len, "%c%s", c ? '|' : '.', pf->comp_names[c]);
      else
        snprintf(buf + len, n - len, "%c%d", c ? '|' : '.', c + 1);
    }
  }
}

static double get(const particles *ps, int f, int c, size_t i) {
  if (ps->fields[f].type == PF_INT32)
    return ((const int32_t *)particles_comp(ps, f, c))[i];
  return ((const double *)particles_comp(ps, f, c))[i];
}

/* field f's component named comp: by name, or its number from 1 */
static int component(const pfield *pf, const char *comp) {
  int c;
  char *end;
  long k;
  for (c = 0; c < pf->ncomp; c++)
    if (pf->comp_names[c] && strcmp(pf->comp_names[c], comp) == 0) return c;
  k = strtol(comp, &end, 10);
  if (end != comp && !*end && k >= 1 && k <= pf->ncomp) return (int)k - 1;
  return -1;
}

/* field by name, if it has the flags */
static int find(const particles *ps, const char *name, unsigned need) {
  int f = particles_find(ps, name);
  return f >= 0 && (ps->fields[f].flags & need) == need ? f : -1;
}

/*
** s1 - s3 of the 3-D stress of particle i: the eigenvalues of a
** symmetric 3 x 3 tensor are q + 2 p cos(phi + 2 pi k / 3) with q its
** mean and p, phi from the invariants of its deviator, so the largest
** less the smallest is 2 p (cos(phi) - cos(phi + 2 pi / 3)) =
** 2 sqrt(3) p sin(phi + pi / 3).  (Not called in 2-D.)
*/
static double spread3(const particles *ps, size_t i) {
  double s[3][3], q, p2 = 0, p, r = 0, phi;
  int a, b;
  for (a = 0; a < 3; a++)
    for (b = 0; b < 3; b++) s[a][b] = ps->s[vec_sym(a % DIM, b % DIM)][i];
  q = (s[0][0] + s[1][1] + s[2][2]) / 3;
  for (a = 0; a < 3; a++) s[a][a] -= q;
  for (a = 0; a < 3; a++)
    for (b = 0; b < 3; b++) p2 += s[a][b] * s[a][b];
  p = sqrt(p2 / 6);
  if (!(p > 0)) return p == 0 ? 0 : NAN;
  /* det(s / p) / 2 = cos(3 phi), clamped against round-off */
  r = (s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) -
       s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
       s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0])) / (2 * p * p * p);
  r = r < -1 ? -1 : r > 1 ? 1 : r;
  phi = acos(r) / 3;
  return 2 * sqrt(3.0) * p * sin(phi + M_PI / 3);
}

int render_values(const particles *ps, const char *by, unsigned need,
                  double *out, char *err, size_t errlen) {
  char name[64], keys[1536];
  const char *dot;
  int f, c = 0;
  size_t i;
  if (!by) by = "body";
  f = find(ps, by, need);
  if (f < 0) {
    if (strcmp(by, "pressure") == 0) {
      /* s_zz is the out-of-plane stress in 2-D (plane strain) */
      for (i = 0; out && i < ps->n; i++)
        out[i] = -(ps->s[S_XX][i] + ps->s[S_YY][i] + ps->s[S_ZZ][i]) / 3;
      return RENDER_SCALAR;
    }
    if (strcmp(by, "sdiff") == 0) {
      for (i = 0; out && i < ps->n; i++) {
        double d = ps->s[S_XX][i] - ps->s[S_YY][i], t = ps->s[S_XY][i];
        out[i] = DIM == 3 ? spread3(ps, i) : sqrt(d * d + 4 * t * t);
      }
      return RENDER_SCALAR;
    }
    if (strcmp(by, "speed") == 0) {
      for (i = 0; out && i < ps->n; i++) {
        double s2 = 0;
        int d;
        for (d = 0; d < DIM; d++) s2 += ps->v[d][i] * ps->v[d][i];
        out[i] = sqrt(s2);
      }
      return RENDER_SCALAR;
    }
  }
  if (f < 0 && (dot = strrchr(by, '.')) && (size_t)(dot - by) < sizeof name) {
    memcpy(name, by, dot - by);
    name[dot - by] = 0;
    f = find(ps, name, need);
    if (f >= 0 && (ps->fields[f].ncomp == 1 ||
                   (c = component(&ps->fields[f], dot + 1)) < 0)) {
      keylist(ps, need, keys, sizeof keys);
      snprintf(err, errlen, "'%s': field '%s' has no component '%s' (keys: %s)",
               by, name, dot + 1, keys);
      return -1;
    }
  } else if (f >= 0 && ps->fields[f].ncomp > 1) {
    keylist(ps, need, keys, sizeof keys);
    snprintf(err, errlen, "'%s' has %d components: name one, e.g. '%s.%s' "
             "(keys: %s)", by, ps->fields[f].ncomp, by,
             ps->fields[f].comp_names[0] ? ps->fields[f].comp_names[0] : "1",
             keys);
    return -1;
  }
  if (f < 0) {
    keylist(ps, need, keys, sizeof keys);
    snprintf(err, errlen, "no particle field or derived quantity '%s' "
             "(keys: %s)", by, keys);
    return -1;
  }
  for (i = 0; out && i < ps->n; i++) out[i] = get(ps, f, c, i);
  return strcmp(ps->fields[f].name, "body") == 0 ? RENDER_BODY : RENDER_SCALAR;
}

/*
** {======================================================
** Pens: the same drawing on a canvas or into an SVG document
** =======================================================
*/

typedef struct pen {
  canvas *c;   /* raster, or NULL */
  svg *g;      /* vector, or NULL */
} pen;

static void p_rect(pen *p, int x0, int y0, int x1, int y1, uint32_t col) {
  if (p->c) canvas_rect(p->c, x0, y0, x1, y1, col);
  if (p->g) svg_rect(p->g, x0, y0, x1, y1, col);
}

static void p_frame(pen *p, int x0, int y0, int x1, int y1, int t,
                    uint32_t col) {
  if (p->c) canvas_frame(p->c, x0, y0, x1, y1, t, col);
  if (p->g) svg_frame(p->g, x0, y0, x1, y1, t, col);
}

static void p_poly(pen *p, int n, const double *xs, const double *ys,
                   uint32_t col) {
  if (p->c) canvas_poly(p->c, n, xs, ys, col);
  if (p->g) svg_poly(p->g, n, xs, ys, col);
}

static void p_text(pen *p, int x, int y, const char *s, int scale,
                   uint32_t col, int ha, int va, int vertical) {
  if (p->c) canvas_text(p->c, x, y, s, scale, col, ha, va, vertical);
  if (p->g) svg_text(p->g, x, y, s, scale, col, ha, va, vertical);
}

static void p_clip(pen *p, int x0, int y0, int x1, int y1) {
  if (p->c) canvas_clip(p->c, x0, y0, x1, y1);
  if (p->g) svg_clip(p->g, x0, y0, x1, y1);
}

static void p_noclip(pen *p) {
  if (p->c) canvas_noclip(p->c);
  if (p->g) svg_noclip(p->g);
}

/* }====================================================== */

static int cmpd(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/*
** The scale against which round-off is judged: the largest |value|
** among the components of the field the key takes one component of;
** for a stress (pressure, sdiff, stress.*) also the largest dynamic
** pressure rho |v|^2 = m / V0 |v|^2, so that the stress of bodies in
** free flight, which is round-off, is not drawn as if it were load.
** 0 when neither applies.
*/
static double field_scale(const particles *ps, const char *by, unsigned need) {
  char name[64];
  const char *dot = by ? strrchr(by, '.') : NULL;
  int f = -1, c, d, stress = 0;
  size_t i;
  double m = 0;
  if (!by || find(ps, by, need) >= 0) return 0;
  if (strcmp(by, "pressure") == 0 || strcmp(by, "sdiff") == 0) {
    f = particles_find(ps, "stress");
    stress = 1;
  } else if (dot && (size_t)(dot - by) < sizeof name) {
    memcpy(name, by, dot - by);
    name[dot - by] = 0;
    f = find(ps, name, need);
    stress = strcmp(name, "stress") == 0;
  }
  for (c = 0; f >= 0 && ps->fields[f].ncomp > 1 && c < ps->fields[f].ncomp; c++)
    for (i = 0; i < ps->n; i++) {
      double a = fabs(get(ps, f, c, i));
      if (isfinite(a) && a > m) m = a;
    }
  for (i = 0; stress && i < ps->n; i++) {
    double v2 = 0, q;
    for (d = 0; d < DIM; d++) v2 += ps->v[d][i] * ps->v[d][i];
    q = ps->vol0[i] > 0 ? ps->m[i] / ps->vol0[i] * v2 : 0;
    if (isfinite(q) && q > m) m = q;
  }
  return m;
}

/* the colour range and map for the values; -1 with err for a log scale
** that cannot be */
static int crange(const render_opts *o, const particles *ps, const double *v,
                  render_layout *L, char *err, size_t errlen) {
  double a = HUGE_VAL, b = -HUGE_VAL, *w, amax, ref;
  size_t i, nf = 0;
  const char *key = o->by ? o->by : "body";
  w = malloc((ps->n ? ps->n : 1) * sizeof *w);
  if (!w) {
    snprintf(err, errlen, "out of memory for %zu values", ps->n);
    return -1;
  }
  for (i = 0; i < ps->n; i++)
    if (isfinite(v[i])) w[nf++] = v[i];
  qsort(w, nf, sizeof *w, cmpd);
  if (nf > 0) {
    L->vmin = w[0];
    L->vmax = w[nf - 1];
  } else L->vmin = L->vmax = NAN;
  if (o->has_range) {
    a = o->range[0];
    b = o->range[1];
  } else if (nf > 0) {
    a = w[0];
    b = w[nf - 1];
    amax = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    if (o->autorange == RENDER_ROBUST) {
      double pa = w[(size_t)floor(0.01 * (double)(nf - 1))];
      double pb = w[(size_t)ceil(0.99 * (double)(nf - 1))];
      double pm = fabs(pa) > fabs(pb) ? fabs(pa) : fabs(pb);
      if (pb > pa && pm > RENDER_ROUNDOFF * amax) {
        a = pa;
        b = pb;
      }
    }
    /* a spread within round-off of the values is no spread: constant */
    if (b - a <= RENDER_ROUNDOFF * (fabs(a) > fabs(b) ? fabs(a) : fabs(b)))
      a = b = a + (b - a) / 2;
    ref = field_scale(ps, o->by, o->need);
    if (ref > 0 && amax <= RENDER_ROUNDOFF * ref) {
      L->roundoff = 1;  /* draws as the zero it is */
      a = -ref;
      b = ref;
    }
  } else {
    a = o->log ? 1 : 0;  /* nothing finite */
    b = o->log ? 10 : 1;
  }
  free(w);
  if (o->log) {
    if (o->has_range && !(a > 0)) {
      snprintf(err, errlen, "a log scale needs a range above zero (got {%g, %g})",
               a, b);
      return -1;
    }
    if (!o->has_range && !(a > 0 && L->vmin > 0)) {
      snprintf(err, errlen, "a log scale needs values above zero: '%s' "
               "ranges over [%g, %g]; give a range {lo, hi} with lo > 0",
               key, L->vmin, L->vmax);
      return -1;
    }
    if (!(b > a)) { a /= 1.25; b *= 1.25; }
    if (!isfinite(b)) b = a * 10 > a ? a * 10 : a;
    L->cmap = o->cmap != RENDER_AUTO ? o->cmap : CMAP_SEQ;
    L->vlo = a;
    L->vhi = b;
    return 0;
  }
  L->cmap = o->cmap != RENDER_AUTO ? o->cmap : (a < 0 && b > 0) ? CMAP_DIV : CMAP_SEQ;
  if (L->cmap == CMAP_DIV && !o->has_range) {
    double m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    a = -m;
    b = m;
  }
  if (!(b > a)) axis_widen(&a, &b); /* constant: a range around it */
  L->vlo = a;
  L->vhi = b;
  return 0;
}

/* where v falls in the colour range */
static double cfrac(const render_opts *o, const render_layout *L, double v) {
  if (!o->log) return axis_frac(v, L->vlo, L->vhi);
  if (!(v > 0)) return 0;
  return (log10(v) - log10(L->vlo)) / (log10(L->vhi) - log10(L->vlo));
}

/* the bodies present, in order, up to cap; returns the count; counts
** (maxb + 1 entries, malloc'ed) the particles of each */
static int bodies_present(const particles *ps, int *list, int cap, int *more,
                          size_t **counts, int *nb) {
  int n = 0, b, maxb = -1;
  size_t i, *cnt;
  *more = 0;
  *counts = NULL;
  *nb = 0;
  for (i = 0; i < ps->n; i++)
    if (ps->body[i] > maxb) maxb = ps->body[i];
  if (maxb < 0) return 0;
  cnt = calloc((size_t)maxb + 1, sizeof *cnt);
  if (!cnt) return 0;
  for (i = 0; i < ps->n; i++)
    if (ps->body[i] >= 0) cnt[ps->body[i]]++;
  for (b = 0; b <= maxb; b++)
    if (cnt[b]) {
      if (n < cap) list[n++] = b;
      else (*more)++;
    }
  *counts = cnt;
  *nb = maxb + 1;
  return n;
}

static const char *body_name(const render_opts *o, int b) {
  if (o->names && b < o->nnames && o->names[b] && o->names[b][0])
    return o->names[b];
  return NULL;
}

/* the matrix body (render_png.h), or -1 */
static int find_matrix(const render_opts *o, const size_t *cnt, int nb,
                       size_t n) {
  int b, big = -1, present = 0;
  size_t second = 0;
  for (b = 0; b < nb; b++) {
    const char *nm = body_name(o, b);
    if (cnt[b] && nm && o->matrix && strcmp(nm, o->matrix) == 0) return b;
  }
  if (o->matrix) return -1;
  for (b = 0; b < nb; b++) {
    const char *nm = body_name(o, b);
    if (cnt[b] && nm && (strncmp(nm, "binder", 6) == 0 ||
                         strncmp(nm, "matrix", 6) == 0))
      return b;
  }
  for (b = 0; b < nb; b++) {
    if (!cnt[b]) continue;
    present++;
    if (big < 0 || cnt[b] > cnt[big]) {
      if (big >= 0 && cnt[big] > second) second = cnt[big];
      big = b;
    } else if (cnt[b] > second)
      second = cnt[b];
  }
  if (present >= 3 && 4 * cnt[big] > n && cnt[big] >= 2 * second) return big;
  return -1;
}

uint32_t render_body_color(int b, int matrix) {
  if (b == matrix) return RENDER_MATRIX;
  /* the grains keep their colours whichever body is the matrix */
  return cmap_category(b);
}

static void body_label(const render_opts *o, int b, char *buf, size_t n) {
  const char *nm = body_name(o, b);
  int drv = o->driven && b < o->nnames && o->driven[b];
  if (nm) snprintf(buf, n, "%s%s", nm, drv ? " (driven)" : "");
  else snprintf(buf, n, "body %d%s", b + 1, drv ? " (driven)" : "");
}

const char *render_length_unit(const char *units) {
  static const char *const len[] = {"m", "mm", "um", "µm", "cm", "km", "in",
                                    "ft", NULL};
  int k;
  if (!units) return NULL;
  if (strcmp(units, "SI") == 0 || strcmp(units, "si") == 0) return "m";
  if (strcmp(units, "cgs") == 0 || strcmp(units, "CGS") == 0) return "cm";
  for (k = 0; len[k]; k++)
    if (strcmp(units, len[k]) == 0) return len[k];
  return NULL;
}

/* the picture's axes (render_view_axes) */
typedef struct view {
  int h, u, a;     /* right, up, along (-1 in 2-D) */
  double toward;   /* +1 or -1: the viewer's side along a */
} view;

int render_view_axes(const char *axis, int *h, int *u, int *a, char *err,
                     size_t errlen) {
  /* h x u points at the viewer, so no picture is mirrored */
  static const int hs[] = {2, 0, 0}, us[] = {1, 2, 1};
  int k = !axis ? 2 : !strcmp(axis, "x") ? 0 : !strcmp(axis, "y") ? 1
          : !strcmp(axis, "z") ? 2 : -1;
  if (k < 0 || (DIM == 2 && k != 2)) {
    snprintf(err, errlen, "axis must be %s (got '%s')",
             DIM == 2 ? "z in 2-D" : "x, y or z", axis);
    return -1;
  }
  *h = DIM == 2 ? 0 : hs[k];
  *u = DIM == 2 ? 1 : us[k];
  *a = DIM == 2 ? -1 : k;
  return 0;
}

/* det F of particle i */
static double det_at(const particles *ps, size_t i) {
  double T[NTENS];
  int c;
  for (c = 0; c < NTENS; c++) T[c] = ps->F[c][i];
  return vec_det(T);
}

/* how far, in pixels, a particle's square is drawn past its edges in a
** raster picture (particle(): the seams between particles) */
#define RENDER_SEAL 0.35

/* The stretch a particle's square is drawn with at most (the larger of
** its image's singular values over the smaller).  Sheared on, F maps
** the square to a needle that reaches far past the particles about it,
** which stay near: at strain 1 a sheared PBX bed's binder particles
** reached stretches of 10^6 and its grains' of 4,000, and drawn so (the
** seal below gives a needle a pixel's width) they streaked across the
** grains.  Beyond this, the square is drawn with its stretch limited to
** this ratio, along the same axes and with the same area. */
#define RENDER_STRETCH 4.0

/* the half edges e (columns: e[k] is edge k's image) with their stretch
** limited to RENDER_STRETCH: e <- e V diag(t_1 / s_1, t_2 / s_2) V^T,
** where e = U diag(s_1, s_2) V^T and t_1 t_2 = s_1 s_2 (the area) */
static void limit_stretch(double e[2][2]) {
  double a = e[0][0], b = e[1][0], c = e[0][1], d = e[1][1]; /* [[a b] [c d]] */
  double A = a * a + c * c, B = b * b + d * d, P = a * b + c * d;
  double q = A + B, det = fabs(a * d - b * c);
  double disc = sqrt(fmax(q * q - 4 * det * det, 0));
  double s1 = sqrt(0.5 * (q + disc)), s2 = det / s1, v[2], n, f1, f2;
  double m[2][2];
  int k, r;
  if (!(s2 > 0) || s1 <= RENDER_STRETCH * s2) return;
  /* v: e^T e's eigenvector of s1^2, the stretched axis in the square */
  if (A >= B) { v[0] = s1 * s1 - B; v[1] = P; }
  else { v[0] = P; v[1] = s1 * s1 - A; }
  n = hypot(v[0], v[1]);
  v[0] /= n;
  v[1] /= n;
  f1 = sqrt(det * RENDER_STRETCH) / s1;
  f2 = sqrt(det / RENDER_STRETCH) / s2;
  /* m = f1 v v^T + f2 w w^T (w the normal to v), then e <- e m */
  m[0][0] = f1 * v[0] * v[0] + f2 * v[1] * v[1];
  m[1][1] = f1 * v[1] * v[1] + f2 * v[0] * v[0];
  m[0][1] = m[1][0] = (f1 - f2) * v[0] * v[1];
  for (r = 0; r < 2; r++) { /* component r of each column */
    double x0 = e[0][r], x1 = e[1][r];
    for (k = 0; k < 2; k++) e[k][r] = x0 * m[0][k] + x1 * m[1][k];
  }
}

/* half the side of particle i's cube (square in 2-D) */
static double halfside(const particles *ps, size_t i) {
  double v = ps->vol0[i] > 0 ? ps->vol0[i] : 0;
  return 0.5 * (DIM == 2 ? sqrt(v) : cbrt(v));
}

/* one particle: its square of side sqrt(volume0) (in 3-D the face of its
** cube across the view) mapped by F's block in the picture's plane */
static void particle(pen *p, const render_layout *L, const particles *ps,
                     size_t i, const render_opts *o, const view *w,
                     uint32_t col) {
  double a, e[2][2], xs[4], ys[4], cx, cy;
  int k, h = w->h, u = w->u;
  a = halfside(ps, i);
  /* the columns of F (in-plane part) are the images of the edges */
  e[0][0] = ps->F[h * DIM + h][i];  e[0][1] = ps->F[u * DIM + h][i];
  e[1][0] = ps->F[h * DIM + u][i];  e[1][1] = ps->F[u * DIM + u][i];
  if (!(isfinite(e[0][0] + e[0][1] + e[1][0] + e[1][1])) ||
      e[0][0] * e[1][1] - e[0][1] * e[1][0] <= 0) {
    e[0][0] = e[1][1] = 1;     /* inverted or broken F: the initial square */
    e[0][1] = e[1][0] = 0;
  }
  cx = L->dx0 + (ps->x[h][i] - o->lo[0]) * L->sc;
  cy = L->dy0 + (o->hi[1] - ps->x[u][i]) * L->sc;
  limit_stretch(e);
  for (k = 0; k < 2; k++) { /* the half edges, in pixels */
    e[k][0] *= a * L->sc;
    e[k][1] *= a * L->sc;
  }
  if (p->c) {
    /* Raster only: each edge moved out by RENDER_SEAL pixels.  A body's
    ** particles, moved and stretched each by its own F, do not abut
    ** exactly once it turns or shears; a seam thinner than a pixel that
    ** crosses a pixel's centre left a white pinhole inside a grain, which
    ** reads as a crack.  The half edge e0 goes out by the seal over the
    ** centre's distance to the edges it spans, |e0 x e1| / |e1|. */
    double cr = fabs(e[0][0] * e[1][1] - e[0][1] * e[1][0]);
    double l0 = hypot(e[0][0], e[0][1]), l1 = hypot(e[1][0], e[1][1]);
    if (cr > 0) {
      double g0 = 1 + RENDER_SEAL * l1 / cr, g1 = 1 + RENDER_SEAL * l0 / cr;
      e[0][0] *= g0; e[0][1] *= g0;
      e[1][0] *= g1; e[1][1] *= g1;
    }
  }
  for (k = 0; k < 4; k++) {
    double s = (k == 0 || k == 3) ? -1 : 1, t = k < 2 ? -1 : 1;
    xs[k] = cx + e[0][0] * s + e[1][0] * t;
    ys[k] = cy - (e[0][1] * s + e[1][1] * t);
  }
  p_poly(p, 4, xs, ys, col);
}

/*
** 3-D: the particles drawn, farthest first (qsort is not stable, so
** equal depths go in store order by the index).  A particle with a
** position that is not finite is left out.
*/
typedef struct deep {
  double z;
  size_t i;
} deep;

static int cmpdeep(const void *x, const void *y) {
  const deep *a = x, *b = y;
  if (a->z != b->z) return a->z < b->z ? -1 : 1;
  return (a->i > b->i) - (a->i < b->i);
}

/* how far particle i's cube, mapped by F, reaches along axis a from its
** centre: half its side times the sum of |F_ab| over b (the initial half
** side when F is broken) */
static double reach(const particles *ps, size_t i, int a) {
  double r = 0;
  int b;
  for (b = 0; b < DIM; b++) r += fabs(ps->F[a * DIM + b][i]);
  if (!isfinite(r) || !(det_at(ps, i) > 0)) r = 1;
  return halfside(ps, i) * r;
}

/* the slice's place: as given, else the middle of the particles */
static double slice_at(const particles *ps, const render_opts *o, int a) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  size_t i;
  if (o->has_at) return o->at;
  for (i = 0; i < ps->n; i++)
    if (isfinite(ps->x[a][i])) {
      if (ps->x[a][i] < lo) lo = ps->x[a][i];
      if (ps->x[a][i] > hi) hi = ps->x[a][i];
    }
  return lo <= hi ? lo / 2 + hi / 2 : 0;
}

/* the order of drawing into *out (malloc'ed; NULL in 2-D: store order);
** the count; -1 when out of memory */
static long depth_order(const particles *ps, const render_opts *o,
                        const view *w, double at, size_t **out) {
  deep *d;
  size_t i, n = 0, *idx;
  *out = NULL;
  if (w->a < 0) return (long)ps->n;
  d = malloc((ps->n ? ps->n : 1) * sizeof *d);
  if (!d) return -1;
  for (i = 0; i < ps->n; i++) {
    double z = ps->x[w->a][i];
    double half = o->thick > 0 ? o->thick / 2 : reach(ps, i, w->a);
    if (!isfinite(z)) continue;
    /* the cube's extent along the axis, half-open: a plane on the face
    ** between two particles' cubes (the default, the middle of a
    ** lattice, often is) takes exactly one of them, not neither */
    if (!o->project && !(z - half <= at && at < z + half)) continue;
    d[n].z = w->toward * z;
    d[n++].i = i;
  }
  qsort(d, n, sizeof *d, cmpdeep);
  idx = malloc((n ? n : 1) * sizeof *idx);
  if (!idx) {
    free(d);
    return -1;
  }
  for (i = 0; i < n; i++) idx[i] = d[i].i;
  free(d);
  *out = idx;
  return (long)n;
}

#define MAXLEG 24

/* ticks over [lo, hi] with labels */
typedef struct ticks {
  int n;
  double t[AXIS_MAXTICKS], step;
  char lab[AXIS_MAXTICKS][48];
  int maxw;                  /* widest label, pixels */
} ticks;

/*
** One style along an axis: when some labels are in exponent form and
** others not ("5e-4" beside "0.0010"), all but zero take the exponent
** form, with the digits the step needs.
*/
static void uniform(ticks *T) {
  int k, ex = 0, fx = 0;
  for (k = 0; k < T->n; k++) {
    if (strchr(T->lab[k], 'e')) ex = 1;
    else if (T->t[k] != 0) fx = 1;
  }
  if (!ex || !fx || !(T->step > 0)) return;
  for (k = 0; k < T->n; k++) {
    double v = T->t[k];
    int e, d;
    char *p;
    if (v == 0 || !isfinite(v)) continue;
    e = (int)floor(log10(fabs(v)));
    d = e - (int)floor(log10(T->step) + 1e-9);
    d = d < 0 ? 0 : d > 15 ? 15 : d;
    snprintf(T->lab[k], sizeof T->lab[k], "%.*f", d, v / pow(10, e));
    if (strchr(T->lab[k], '.')) {   /* no trailing zeros */
      p = T->lab[k] + strlen(T->lab[k]) - 1;
      while (*p == '0') *p-- = 0;
      if (*p == '.') *p = 0;
    }
    snprintf(T->lab[k] + strlen(T->lab[k]), sizeof T->lab[k] - strlen(T->lab[k]),
             "e%d", e);
  }
}

static void mkticks(ticks *T, double lo, double hi, int want, int s, int log) {
  double minor[4 * AXIS_MAXTICKS];
  int k, nm;
  if (log) {
    T->n = axis_logticks(lo, hi, T->t, minor, &nm);
    T->step = T->n > 1 ? T->t[1] - T->t[0] : 0;
  } else
    T->n = axis_ticks(lo, hi, want < 2 ? 2 : want, T->t, &T->step);
  T->maxw = 0;
  for (k = 0; k < T->n; k++) {
    if (log && T->t[k] > 0 && fabs(log10(T->t[k]) - floor(log10(T->t[k]) + 0.5)) < 1e-9)
      axis_label(T->t[k], T->t[k], T->lab[k], sizeof T->lab[k]);
    else axis_label(T->t[k], T->step, T->lab[k], sizeof T->lab[k]);
  }
  if (!log) uniform(T);
  for (k = 0; k < T->n; k++) {
    int w = canvas_textw(T->lab[k], s);
    if (w > T->maxw) T->maxw = w;
  }
}

/* a 1-2-5 length near a fifth of len */
static double bar_length(double len) {
  double e = pow(10, floor(log10(len / 5))), f = len / 5 / e;
  return (f >= 5 ? 5 : f >= 2 ? 2 : 1) * e;
}

/* the scalar panel's text lines under the bar */
static void extent_lines(const render_layout *L, char (*line)[64], int *n) {
  *n = 0;
  if (!isfinite(L->vmin)) {
    snprintf(line[(*n)++], 64, "no finite value");
    return;
  }
  if (L->roundoff) {
    double m = fabs(L->vmin) > fabs(L->vmax) ? fabs(L->vmin) : fabs(L->vmax);
    snprintf(line[(*n)++], 64, "|v| <= %.3g:", m);
    snprintf(line[(*n)++], 64, "round-off");
    return;
  }
  snprintf(line[(*n)++], 64, "min %.4g", L->vmin);
  snprintf(line[(*n)++], 64, "max %.4g", L->vmax);
}

/*
** Lay out and draw.  The layout, left to right: margin, y-axis title and
** tick labels, the domain, the panel (colour bar or legend), margin; top
** to bottom: margin, title, the domain, x tick labels, x-axis title,
** scale bar, margin.  init makes the pen's surface once the size is
** known.
*/
static int draw(pen *P, int (*init)(pen *, int, int), render_layout *lay,
                const particles *ps, const render_opts *o, char *err,
                size_t errlen) {
  render_layout L;
  double *v = NULL, lx, ly;
  char buf[128], ext[4][64], xt[80], yt[80], barlab[64];
  int kind, s, m, lh, top, panel, dw, dh, k, y, labw = 0, x, left, bottom;
  int barpx, barw, barrow;
  int legend[MAXLEG], nleg = 0, more = 0, nb = 0, next = 0, tick;
  size_t i, *cnt = NULL;
  ticks cb, tx, ty;
  const char *u = o->unit && o->unit[0] ? o->unit : NULL;
  double us = 1;  /* world length to the axes' unit */
  view W;
  size_t *ord = NULL;
  long nd;
  memset(&L, 0, sizeof L);
  L.matrix = -1;
  if (render_view_axes(o->axis, &W.h, &W.u, &W.a, err, errlen)) return -1;
  W.toward = W.a == 2 ? 1 : -1;
  lx = o->hi[0] - o->lo[0];
  ly = o->hi[1] - o->lo[1];
  if (!(lx > 0) || !(ly > 0) || !isfinite(lx) || !isfinite(ly)) {
    snprintf(err, errlen, "the window [%g, %g] x [%g, %g] is empty", o->lo[0],
             o->hi[0], o->lo[1], o->hi[1]);
    return -1;
  }
  if (o->width < RENDER_MINW || o->width > PNG_MAXDIM) {
    snprintf(err, errlen, "width must be in [%d, %d] (got %d)", RENDER_MINW,
             PNG_MAXDIM, o->width);
    return -1;
  }
  if (o->has_range && !(o->range[1] > o->range[0] && isfinite(o->range[0]) &&
                        isfinite(o->range[1]))) {
    snprintf(err, errlen, "range {%g, %g} must be finite with hi > lo", o->range[0],
             o->range[1]);
    return -1;
  }
  kind = render_values(ps, o->by, o->need, NULL, err, errlen);
  if (kind < 0) return -1;
  v = malloc((ps->n ? ps->n : 1) * sizeof *v);
  if (!v) {
    snprintf(err, errlen, "out of memory for %zu particles", ps->n);
    return -1;
  }
  render_values(ps, o->by, o->need, v, err, errlen);

  /* layout: margins, title line, domain, then the panel on the right */
  s = o->width / 400;
  s = s < 1 ? 1 : s > 4 ? 4 : s;
  m = 10 * s;
  lh = CANVAS_LINE(s);
  tick = 4 * s;
  top = m + (o->title && o->title[0] ? lh + 4 * s : 0);
  if (kind == RENDER_SCALAR) {
    if (crange(o, ps, v, &L, err, errlen)) {
      free(v);
      return -1;
    }
    mkticks(&cb, L.vlo, L.vhi, 6, s, o->log);
    extent_lines(&L, ext, &next);
    labw = cb.maxw;
    panel = 14 * s + 14 * s + 7 * s + labw;        /* gap, bar, tick, labels */
    snprintf(buf, sizeof buf, "%s%s", o->by ? o->by : "body", o->log ? " (log)" : "");
    k = canvas_textw(buf, s);  /* key over the bar */
    if (14 * s + k > panel) panel = 14 * s + k;
    for (k = 0; k < next; k++)
      if (14 * s + canvas_textw(ext[k], s) > panel)
        panel = 14 * s + canvas_textw(ext[k], s);
  } else {
    nleg = bodies_present(ps, legend, MAXLEG, &more, &cnt, &nb);
    if (cnt) L.matrix = find_matrix(o, cnt, nb, ps->n);
    for (k = 0; k < nleg; k++) {
      int w;
      body_label(o, legend[k], buf, sizeof buf);
      w = canvas_textw(buf, s);
      if (w > labw) labw = w;
    }
    panel = 14 * s + 10 * s + 5 * s + labw;
    if (more) {
      snprintf(buf, sizeof buf, "+%d more", more);
      if (14 * s + canvas_textw(buf, s) > panel) panel = 14 * s + canvas_textw(buf, s);
      if (L.matrix >= 0) {
        body_label(o, L.matrix, buf, sizeof buf);
        if (14 * s + 15 * s + canvas_textw(buf, s) > panel)
          panel = 14 * s + 15 * s + canvas_textw(buf, s);
      }
    }
  }
  /* the axes: y labels fix the left gutter, then the x ticks fit the
  ** width left */
  /* metres for a small domain read better as mm or μm */
  if (u && strcmp(u, "m") == 0 && lx < 1e-4) { us = 1e6; u = "μm"; }
  else if (u && strcmp(u, "m") == 0 && lx < 0.1) { us = 1e3; u = "mm"; }
  snprintf(xt, sizeof xt, u ? "%c (%s)" : "%c", "xyz"[W.h], u);
  snprintf(yt, sizeof yt, u ? "%c (%s)" : "%c", "xyz"[W.u], u);
  memset(&ty, 0, sizeof ty);
  memset(&tx, 0, sizeof tx);
  left = m;
  if (!o->noaxes) {
    mkticks(&ty, o->lo[1] * us, o->hi[1] * us, ly > lx ? 8 : 5, s, 0);
    left = m + lh + 2 * s + ty.maxw + 3 * s + tick;
  }
  dw = o->width - left - m - panel;
  if (dw < 40) {
    free(v);
    free(cnt);
    snprintf(err, errlen, "width %d leaves no room for the domain beside the "
             "%s (use a width of %d or more)", o->width,
             kind == RENDER_SCALAR ? "colour bar" : "legend",
             left + m + panel + 40);
    return -1;
  }
  if (!o->noaxes) {
    mkticks(&tx, o->lo[0] * us, o->hi[0] * us, 6, s, 0);
    k = dw / (tx.maxw + 12 * s);
    if (k < tx.n) mkticks(&tx, o->lo[0] * us, o->hi[0] * us, k < 2 ? 2 : k, s, 0);
  }
  L.sc = dw / lx;
  /* the scale bar goes at the left of the x-axis title's row when it
  ** fits beside the title, else in a row of its own */
  L.bar = bar_length(lx * us);
  axis_label(L.bar, L.bar, barlab, sizeof barlab);
  if (u) snprintf(barlab + strlen(barlab), sizeof barlab - strlen(barlab), " %s", u);
  barpx = (int)floor(L.bar / us * L.sc + 0.5);
  if (barpx < 2 * s) barpx = 2 * s;
  barw = barpx + 5 * s + canvas_textw(barlab, s);
  barrow = o->noaxes || left + barw + 8 * s > left + dw / 2 - canvas_textw(xt, s) / 2;
  bottom = s + m + (o->noaxes ? 0 : tick + 3 * s + 2 * lh) + (barrow ? 10 * s : 0);
  /* checked before it becomes an int (the image's limit below says
  ** the same); by the aspect, as dw / lx overflows for a tiny window */
  if (!(ly / lx * dw <= PNG_MAXDIM)) {
    free(v);
    free(cnt);
    snprintf(err, errlen, "the domain is %g times as high as wide: the image "
             "would be more than %d pixels high; use a smaller width",
             ly / lx, PNG_MAXDIM);
    return -1;
  }
  dh = (int)floor(ly / lx * dw + 0.5);
  if (dh < 1) dh = 1;
  L.scale = s;
  L.w = o->width;
  L.dx0 = left;
  L.dy0 = top;
  L.dx1 = left + dw;
  L.dy1 = top + dh;
  L.h = top + dh + bottom;
  if (kind == RENDER_SCALAR) {
    L.bx0 = L.dx1 + 14 * s;
    L.bx1 = L.bx0 + 14 * s;
    L.by0 = top + lh + 4 * s;  /* room for the key and the top label */
    /* the bar spans the domain, less what the extent's lines under it
    ** need beyond the rows below the domain, and is 40 s at least */
    L.by1 = L.h - m - lh / 2 - next * lh;
    if (L.by1 > L.dy1) L.by1 = L.dy1;
    if (L.by1 < L.by0 + 40 * s) L.by1 = L.by0 + 40 * s;
    if (L.by1 + lh / 2 + next * lh + m > L.h) L.h = L.by1 + lh / 2 + next * lh + m;
  } else if (top + lh * (nleg + 2 * (more > 0)) + m > L.h)
    L.h = top + lh * (nleg + 2 * (more > 0)) + m;
  if (L.h > PNG_MAXDIM) {
    free(v);
    free(cnt);
    snprintf(err, errlen, "the domain is %g times as high as wide: the image "
             "would be %d pixels high (at most %d); use a smaller width",
             ly / lx, L.h, PNG_MAXDIM);
    return -1;
  }
  if (init(P, L.w, L.h)) {
    free(v);
    free(cnt);
    snprintf(err, errlen, "out of memory for a %d x %d image", L.w, L.h);
    return -1;
  }

  /* particles, clipped to the domain, then its outline just outside */
  L.at = W.a >= 0 ? slice_at(ps, o, W.a) : 0;
  nd = depth_order(ps, o, &W, L.at, &ord);
  if (nd < 0) {
    free(v);
    free(cnt);
    snprintf(err, errlen, "out of memory for %zu particles", ps->n);
    return -1;
  }
  L.drawn = (size_t)nd;
  p_clip(P, L.dx0, L.dy0, L.dx1, L.dy1);
  for (k = 0; k < nd; k++) {
    uint32_t col;
    i = ord ? ord[k] : (size_t)k;
    if (kind == RENDER_BODY) col = render_body_color((int)v[i], L.matrix);
    else if (isnan(v[i])) col = CMAP_NAN;
    else col = cmap_color(L.cmap, cfrac(o, &L, v[i]));
    particle(P, &L, ps, i, o, &W, col);
  }
  free(ord);
  p_noclip(P);
  p_frame(P, L.dx0 - s, L.dy0 - s, L.dx1 + s, L.dy1 + s, s, INK);
  if (o->title && o->title[0])
    p_text(P, (L.dx0 + L.dx1) / 2, m, o->title, s, INK, CV_CENTER,
           CV_TOP, 0);

  /* ticks outside the frame, labels, axis titles */
  y = L.dy1 + s;
  if (!o->noaxes) {
    for (k = 0; k < tx.n; k++) {
      int px = L.dx0 + (int)floor(axis_frac(tx.t[k], o->lo[0] * us, o->hi[0] * us) * dw + 0.5);
      if (px >= L.dx1) px = L.dx1 - 1;
      p_rect(P, px - s / 2, L.dy1 + s, px - s / 2 + s, L.dy1 + s + tick, INK);
      p_text(P, px, L.dy1 + s + tick + 3 * s, tx.lab[k], s, INK, CV_CENTER,
             CV_TOP, 0);
    }
    for (k = 0; k < ty.n; k++) {
      int py = L.dy1 - 1 - (int)floor(axis_frac(ty.t[k], o->lo[1] * us, o->hi[1] * us) * (dh - 1) + 0.5);
      p_rect(P, L.dx0 - s - tick, py - s / 2, L.dx0 - s, py - s / 2 + s, INK);
      p_text(P, L.dx0 - s - tick - 3 * s, py, ty.lab[k], s, INK, CV_RIGHT,
             CV_MIDDLE, 0);
    }
    p_text(P, (L.dx0 + L.dx1) / 2, L.dy1 + s + tick + 3 * s + lh, xt, s, INK,
           CV_CENTER, CV_TOP, 0);
    p_text(P, m, (L.dy0 + L.dy1) / 2, yt, s, INK, CV_CENTER, CV_TOP, 1);
    y = L.dy1 + s + tick + 3 * s + 2 * lh;
  }
  /* the scale bar, under the domain's left end: its centre line on the
  ** axis title's, or in the middle of its own row */
  {
    int cy = barrow ? y + 5 * s : y - lh + CANVAS_CAP(s) / 2;
    p_rect(P, L.dx0, cy - s, L.dx0 + barpx, cy + s, INK);
    p_rect(P, L.dx0, cy - 3 * s, L.dx0 + s, cy + 3 * s, INK);
    p_rect(P, L.dx0 + barpx - s, cy - 3 * s, L.dx0 + barpx, cy + 3 * s, INK);
    p_text(P, L.dx0 + barpx + 5 * s, cy, barlab, s, INK, CV_LEFT, CV_MIDDLE, 0);
  }

  if (kind == RENDER_SCALAR) {
    int bh = L.by1 - L.by0;
    /* top row is the top of the range, bottom row the bottom, exactly */
    for (y = L.by0; y < L.by1; y++)
      p_rect(P, L.bx0, y, L.bx1, y + 1,
             cmap_color(L.cmap, bh > 1 ? (double)(L.by1 - 1 - y) / (bh - 1) : 0.5));
    p_frame(P, L.bx0 - 1, L.by0 - 1, L.bx1 + 1, L.by1 + 1, 1, INK);
    snprintf(buf, sizeof buf, "%s%s", o->by ? o->by : "body", o->log ? " (log)" : "");
    p_text(P, L.bx0, top, buf, s, INK, CV_LEFT, CV_TOP, 0);
    for (k = 0; k < cb.n; k++) {
      double f = cfrac(o, &L, cb.t[k]);
      int ty0 = L.by1 - 1 - (int)floor(f * (bh - 1) + 0.5);
      p_rect(P, L.bx1 + 1, ty0 - s / 2, L.bx1 + 1 + 3 * s, ty0 - s / 2 + s, INK);
      p_text(P, L.bx1 + 1 + 6 * s, ty0, cb.lab[k], s, INK, CV_LEFT,
             CV_MIDDLE, 0);
    }
    for (k = 0; k < next; k++)
      p_text(P, L.bx0, L.by1 + lh / 2 + k * lh, ext[k], s, INK, CV_LEFT,
             CV_TOP, 0);
  } else {
    x = L.dx1 + 14 * s;
    for (k = 0; k < nleg; k++) {
      int ty0 = top + k * lh;
      p_rect(P, x, ty0, x + 10 * s, ty0 + CANVAS_CAP(s),
             render_body_color(legend[k], L.matrix));
      body_label(o, legend[k], buf, sizeof buf);
      p_text(P, x + 15 * s, ty0, buf, s, INK, CV_LEFT, CV_TOP, 0);
    }
    if (more) {
      int ty0 = top + nleg * lh;
      snprintf(buf, sizeof buf, "+%d more", more);
      p_text(P, x, ty0, buf, s, INK, CV_LEFT, CV_TOP, 0);
      /* a matrix past the list still gets its swatch */
      if (L.matrix >= 0 && L.matrix > legend[nleg - 1]) {
        p_rect(P, x, ty0 + lh, x + 10 * s, ty0 + lh + CANVAS_CAP(s), RENDER_MATRIX);
        body_label(o, L.matrix, buf, sizeof buf);
        p_text(P, x + 15 * s, ty0 + lh, buf, s, INK, CV_LEFT, CV_TOP, 0);
      }
    }
  }
  free(v);
  free(cnt);
  if (lay) *lay = L;
  return 0;
}

static int init_canvas(pen *p, int w, int h) {
  return canvas_init(p->c, w, h, BG);
}

static int init_svg(pen *p, int w, int h) {
  return svg_init(p->g, w, h, BG);
}

int render_draw(canvas *c, render_layout *lay, const particles *ps,
                const render_opts *o, char *err, size_t errlen) {
  pen p = {c, NULL};
  memset(c, 0, sizeof *c);
  return draw(&p, init_canvas, lay, ps, o, err, errlen);
}

/* err prefixed with the file's name */
static void named(const char *path, char *err, size_t errlen) {
  char why[1800];
  snprintf(why, sizeof why, "%s", err);
  snprintf(err, errlen, "%s: %s", path, why);
}

int render_png(const char *path, const particles *ps, const render_opts *o,
               char *err, size_t errlen) {
  canvas c;
  int r;
  if (render_draw(&c, NULL, ps, o, err, errlen)) {
    canvas_free(&c);
    named(path, err, errlen);
    return -1;
  }
  r = png_write(path, c.px, c.w, c.h, 3, err, errlen);
  canvas_free(&c);
  return r;
}

int render_svg(const char *path, const particles *ps, const render_opts *o,
               char *err, size_t errlen) {
  svg g;
  pen p = {NULL, &g};
  int r;
  memset(&g, 0, sizeof g);
  if (draw(&p, init_svg, NULL, ps, o, err, errlen)) {
    svg_free(&g);
    named(path, err, errlen);
    return -1;
  }
  r = svg_write(&g, path, err, errlen);
  svg_free(&g);
  return r;
}

int render_file(const char *path, const particles *ps, const render_opts *o,
                char *err, size_t errlen) {
  size_t n = strlen(path);
  if (n >= 4 && path[n - 4] == '.' && (path[n - 3] | 32) == 's' &&
      (path[n - 2] | 32) == 'v' && (path[n - 1] | 32) == 'g')
    return render_svg(path, ps, o, err, errlen);
  return render_png(path, ps, o, err, errlen);
}
