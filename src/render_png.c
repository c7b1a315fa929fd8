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
        out[i] = sqrt(d * d + 4 * t * t);
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

/* the colour range and map for the values */
static void crange(const render_opts *o, const double *v, size_t n,
                   double *lo, double *hi, int *map) {
  double a = HUGE_VAL, b = -HUGE_VAL;
  size_t i;
  for (i = 0; i < n; i++)
    if (isfinite(v[i])) {
      if (v[i] < a) a = v[i];
      if (v[i] > b) b = v[i];
    }
  if (a > b) { a = 0; b = 1; } /* nothing finite */
  if (o->has_range) { a = o->range[0]; b = o->range[1]; }
  *map = o->cmap != RENDER_AUTO ? o->cmap : (a < 0 && b > 0) ? CMAP_DIV : CMAP_SEQ;
  if (*map == CMAP_DIV && !o->has_range) {
    double m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    a = -m;
    b = m;
  }
  if (!(b > a)) axis_widen(&a, &b); /* constant: a range around it */
  *lo = a;
  *hi = b;
}

/* the bodies present, in order, up to cap; returns the count */
static int bodies_present(const particles *ps, int *list, int cap, int *more) {
  int n = 0, b, maxb = -1;
  size_t i;
  unsigned char *seen;
  *more = 0;
  for (i = 0; i < ps->n; i++)
    if (ps->body[i] > maxb) maxb = ps->body[i];
  if (maxb < 0) return 0;
  seen = calloc((size_t)maxb + 1, 1);
  if (!seen) return 0;
  for (i = 0; i < ps->n; i++)
    if (ps->body[i] >= 0) seen[ps->body[i]] = 1;
  for (b = 0; b <= maxb; b++)
    if (seen[b]) {
      if (n < cap) list[n++] = b;
      else (*more)++;
    }
  free(seen);
  return n;
}

static void body_label(const render_opts *o, int b, char *buf, size_t n) {
  if (o->names && b < o->nnames && o->names[b] && o->names[b][0])
    snprintf(buf, n, "%s", o->names[b]);
  else snprintf(buf, n, "body %d", b + 1);
}

/* one particle: its square of side sqrt(volume0) mapped by F */
static void particle(canvas *c, const render_layout *L, const particles *ps,
                     size_t i, const render_opts *o, uint32_t col) {
  double a, e[2][2], xs[4], ys[4], cx, cy;
  int k;
#if DIM == 2
  a = 0.5 * sqrt(ps->vol0[i] > 0 ? ps->vol0[i] : 0);
#else
  a = 0.5 * cbrt(ps->vol0[i] > 0 ? ps->vol0[i] : 0);
#endif
  /* the columns of F (in-plane part) are the images of the edges */
  e[0][0] = ps->F[0][i];       e[0][1] = ps->F[DIM][i];
  e[1][0] = ps->F[1][i];       e[1][1] = ps->F[DIM + 1][i];
  if (!(isfinite(e[0][0] + e[0][1] + e[1][0] + e[1][1])) ||
      e[0][0] * e[1][1] - e[0][1] * e[1][0] <= 0) {
    e[0][0] = e[1][1] = 1;     /* inverted or broken F: the initial square */
    e[0][1] = e[1][0] = 0;
  }
  cx = L->dx0 + (ps->x[0][i] - o->lo[0]) * L->sc;
  cy = L->dy0 + (o->hi[1] - ps->x[1][i]) * L->sc;
  for (k = 0; k < 4; k++) {
    double u = (k == 0 || k == 3) ? -a : a, w = k < 2 ? -a : a;
    xs[k] = cx + (e[0][0] * u + e[1][0] * w) * L->sc;
    ys[k] = cy - (e[0][1] * u + e[1][1] * w) * L->sc;
  }
  canvas_poly(c, 4, xs, ys, col);
}

#define MAXLEG 24

int render_draw(canvas *c, render_layout *lay, const particles *ps,
                const render_opts *o, char *err, size_t errlen) {
  render_layout L;
  double *v = NULL, ticks[AXIS_MAXTICKS], step = 0, lx, ly;
  char lab[AXIS_MAXTICKS][48], buf[96];
  int kind, s, m, lh, top, panel, dw, dh, nt = 0, k, y, labw = 0, x;
  int legend[MAXLEG], nleg = 0, more = 0;
  size_t i;
  memset(c, 0, sizeof *c);
  memset(&L, 0, sizeof L);
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
  top = m + (o->title && o->title[0] ? lh + 4 * s : 0);
  if (kind == RENDER_SCALAR) {
    crange(o, v, ps->n, &L.vlo, &L.vhi, &L.cmap);
    nt = axis_ticks(L.vlo, L.vhi, 6, ticks, &step);
    for (k = 0; k < nt; k++) {
      int w;
      axis_label(ticks[k], step, lab[k], sizeof lab[k]);
      w = canvas_textw(lab[k], s);
      if (w > labw) labw = w;
    }
    panel = 14 * s + 14 * s + 7 * s + labw;        /* gap, bar, tick, labels */
    k = canvas_textw(o->by ? o->by : "body", s);  /* key over the bar */
    if (14 * s + k > panel) panel = 14 * s + k;
  } else {
    nleg = bodies_present(ps, legend, MAXLEG, &more);
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
    }
  }
  dw = o->width - 2 * m - panel;
  if (dw < 40) {
    free(v);
    snprintf(err, errlen, "width %d leaves no room for the domain beside the "
             "%s (use a width of %d or more)", o->width,
             kind == RENDER_SCALAR ? "colour bar" : "legend",
             2 * m + panel + 40);
    return -1;
  }
  L.sc = dw / lx;
  /* checked before it becomes an int (the image's limit below says
  ** the same); by the aspect, as dw / lx overflows for a tiny window */
  if (!(ly / lx * dw <= PNG_MAXDIM)) {
    free(v);
    snprintf(err, errlen, "the domain is %g times as high as wide: the image "
             "would be more than %d pixels high; use a smaller width",
             ly / lx, PNG_MAXDIM);
    return -1;
  }
  dh = (int)floor(ly / lx * dw + 0.5);
  if (dh < 1) dh = 1;
  L.scale = s;
  L.w = o->width;
  L.dx0 = m;
  L.dy0 = top;
  L.dx1 = m + dw;
  L.dy1 = top + dh;
  L.h = top + dh + m;
  if (kind == RENDER_SCALAR) {
    L.bx0 = L.dx1 + 14 * s;
    L.bx1 = L.bx0 + 14 * s;
    L.by0 = top + lh + 4 * s;  /* room for the key and the top label */
    L.by1 = L.dy1 > L.by0 + 60 * s ? L.dy1 : L.by0 + 60 * s;
    if (L.by1 + m > L.h) L.h = L.by1 + m;
  } else if (top + lh * (nleg + (more > 0)) + m > L.h)
    L.h = top + lh * (nleg + (more > 0)) + m;
  if (L.h > PNG_MAXDIM) {
    free(v);
    snprintf(err, errlen, "the domain is %g times as high as wide: the image "
             "would be %d pixels high (at most %d); use a smaller width",
             ly / lx, L.h, PNG_MAXDIM);
    return -1;
  }
  if (canvas_init(c, L.w, L.h, BG)) {
    free(v);
    snprintf(err, errlen, "out of memory for a %d x %d image", L.w, L.h);
    return -1;
  }

  /* particles, clipped to the domain, then its outline just outside */
  canvas_clip(c, L.dx0, L.dy0, L.dx1, L.dy1);
  for (i = 0; i < ps->n; i++) {
    uint32_t col;
    if (kind == RENDER_BODY) col = cmap_category((int)v[i]);
    else if (isnan(v[i])) col = CMAP_NAN;
    else col = cmap_color(L.cmap, axis_frac(v[i], L.vlo, L.vhi));
    particle(c, &L, ps, i, o, col);
  }
  canvas_noclip(c);
  canvas_frame(c, L.dx0 - s, L.dy0 - s, L.dx1 + s, L.dy1 + s, s, INK);
  if (o->title && o->title[0])
    canvas_text(c, (L.dx0 + L.dx1) / 2, m, o->title, s, INK, CV_CENTER,
                CV_TOP, 0);

  if (kind == RENDER_SCALAR) {
    int bh = L.by1 - L.by0;
    /* top row is the top of the range, bottom row the bottom, exactly */
    for (y = L.by0; y < L.by1; y++)
      canvas_rect(c, L.bx0, y, L.bx1, y + 1,
                  cmap_color(L.cmap, bh > 1 ? (double)(L.by1 - 1 - y) / (bh - 1) : 0.5));
    canvas_frame(c, L.bx0 - 1, L.by0 - 1, L.bx1 + 1, L.by1 + 1, 1, INK);
    canvas_text(c, L.bx0, top, o->by ? o->by : "body", s, INK, CV_LEFT,
                CV_TOP, 0);
    for (k = 0; k < nt; k++) {
      double f = axis_frac(ticks[k], L.vlo, L.vhi);
      int ty = L.by1 - 1 - (int)floor(f * (bh - 1) + 0.5);
      canvas_rect(c, L.bx1 + 1, ty - s / 2, L.bx1 + 1 + 3 * s, ty - s / 2 + s, INK);
      canvas_text(c, L.bx1 + 1 + 6 * s, ty, lab[k], s, INK, CV_LEFT,
                  CV_MIDDLE, 0);
    }
  } else {
    x = L.dx1 + 14 * s;
    for (k = 0; k < nleg; k++) {
      int ty = top + k * lh;
      canvas_rect(c, x, ty, x + 10 * s, ty + CANVAS_CAP(s),
                  cmap_category(legend[k]));
      body_label(o, legend[k], buf, sizeof buf);
      canvas_text(c, x + 15 * s, ty, buf, s, INK, CV_LEFT, CV_TOP, 0);
    }
    if (more) {
      snprintf(buf, sizeof buf, "+%d more", more);
      canvas_text(c, x, top + nleg * lh, buf, s, INK, CV_LEFT, CV_TOP, 0);
    }
  }
  free(v);
  if (lay) *lay = L;
  return 0;
}

int render_png(const char *path, const particles *ps, const render_opts *o,
               char *err, size_t errlen) {
  canvas c;
  int r;
  if (render_draw(&c, NULL, ps, o, err, errlen)) {
    char why[1800];
    snprintf(why, sizeof why, "%s", err);
    snprintf(err, errlen, "%s: %s", path, why);
    return -1;
  }
  r = png_write(path, c.px, c.w, c.h, 3, err, errlen);
  canvas_free(&c);
  return r;
}
