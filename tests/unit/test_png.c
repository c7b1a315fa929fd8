/*
** test_png.c - PNG files, the particle renderer and the plot writer.
** Every image is decoded here with zlib alone (chunk CRCs, IHDR,
** inflate, filter bytes) and pixels are checked where the picture's
** geometry says they must be: a particle's colour at its position (y up),
** background beside it, the colour bar's ends, a plotted point.
*/
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "axis.h"
#include "canvas.h"
#include "cmap.h"
#include "font.h"
#include "out_h5.h"
#include "particles.h"
#include "plot_png.h"
#include "png.h"
#include "render_cmd.h"
#include "render_png.h"
#include "unit.h"

#define WHITE 0xFFFFFFu

static char dir[256];

static int exists(const char *p) {
  struct stat st;
  return stat(p, &st) == 0;
}

static uint32_t be32(const unsigned char *p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

typedef struct image {
  int w, h, ch, ok;
  unsigned char *px;
} image;

/* decode what png_write makes: 8-bit RGB or RGBA, filter 0 rows; every
** chunk's CRC must match and IEND must end the file */
static image decode(const char *path) {
  static const unsigned char sig[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};
  image im = {0, 0, 0, 0, NULL};
  FILE *f = fopen(path, "rb");
  unsigned char *buf, *z = NULL;
  size_t n = 0, zn = 0, at = 8;
  long len;
  int crcs = 1, seen_end = 0, y;
  if (!f) { printf("cannot open %s\n", path); return im; }
  fseek(f, 0, SEEK_END);
  len = ftell(f);
  fseek(f, 0, SEEK_SET);
  buf = malloc(len);
  n = fread(buf, 1, len, f);
  fclose(f);
  UNIT_CHECK(n >= 8 && memcmp(buf, sig, 8) == 0, "%s: PNG signature", path);
  while (at + 12 <= n) {
    uint32_t cl = be32(buf + at);
    const unsigned char *type = buf + at + 4, *data = buf + at + 8;
    if (at + 12 + cl > n) break;
    if (crc32(0L, type, cl + 4) != be32(data + cl)) crcs = 0;
    if (memcmp(type, "IHDR", 4) == 0) {
      UNIT_CHECK(at == 8 && cl == 13, "IHDR first, 13 bytes");
      im.w = (int)be32(data);
      im.h = (int)be32(data + 4);
      UNIT_CHECK(data[8] == 8 && (data[9] == 2 || data[9] == 6) && data[10] == 0 &&
                 data[11] == 0 && data[12] == 0, "IHDR: depth 8, RGB(A), no interlace");
      im.ch = data[9] == 2 ? 3 : 4;
    } else if (memcmp(type, "IDAT", 4) == 0) {
      z = realloc(z, zn + cl + 1);
      memcpy(z + zn, data, cl);
      zn += cl;
    } else if (memcmp(type, "IEND", 4) == 0) {
      seen_end = at + 12 == n;
    }
    at += 12 + cl;
  }
  UNIT_CHECK(crcs, "%s: every chunk CRC matches", path);
  UNIT_CHECK(seen_end, "%s: IEND ends the file", path);
  if (im.w > 0 && im.h > 0 && z) {
    uLongf rn = (uLongf)((size_t)im.h * (1 + (size_t)im.w * im.ch));
    unsigned char *raw = malloc(rn);
    int zr = uncompress(raw, &rn, z, (uLong)zn);
    UNIT_CHECK(zr == Z_OK && rn == (uLongf)((size_t)im.h * (1 + (size_t)im.w * im.ch)),
               "%s: IDAT inflates to the image size", path);
    if (zr == Z_OK) {
      int filt = 1;
      im.px = malloc((size_t)im.w * im.h * im.ch);
      for (y = 0; y < im.h; y++) {
        const unsigned char *r = raw + (size_t)y * (1 + (size_t)im.w * im.ch);
        if (r[0] != 0) filt = 0;
        memcpy(im.px + (size_t)y * im.w * im.ch, r + 1, (size_t)im.w * im.ch);
      }
      UNIT_CHECK(filt, "every row has filter 0");
      im.ok = filt;
    }
    free(raw);
  }
  free(z);
  free(buf);
  return im;
}

static uint32_t pix(const image *im, int x, int y) {
  const unsigned char *p;
  if (!im->ok || x < 0 || y < 0 || x >= im->w || y >= im->h) return 0xDEAD;
  p = im->px + ((size_t)y * im->w + x) * im->ch;
  return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

static void path(char *buf, size_t n, const char *name) {
  snprintf(buf, n, "%s/%s", dir, name);
}

static void test_png_roundtrip(void) {
  unsigned char rgb[2 * 3 * 3], rgba[3 * 2 * 4];
  char p[512], err[512];
  image im;
  int k;
  for (k = 0; k < (int)sizeof rgb; k++) rgb[k] = (unsigned char)(k * 37 + 11);
  for (k = 0; k < (int)sizeof rgba; k++) rgba[k] = (unsigned char)(k * 53 + 7);
  path(p, sizeof p, "rgb.png");
  UNIT_CHECK(png_write(p, rgb, 3, 2, 3, err, sizeof err) == 0, "png_write: %s", err);
  im = decode(p);
  UNIT_CHECK(im.w == 3 && im.h == 2 && im.ch == 3, "IHDR 3 x 2 RGB (got %d x %d, %d)",
             im.w, im.h, im.ch);
  UNIT_CHECK(im.ok && memcmp(im.px, rgb, sizeof rgb) == 0, "RGB pixels come back");
  free(im.px);
  path(p, sizeof p, "rgba.png");
  UNIT_CHECK(png_write(p, rgba, 2, 3, 4, err, sizeof err) == 0, "png_write: %s", err);
  im = decode(p);
  UNIT_CHECK(im.w == 2 && im.h == 3 && im.ch == 4, "IHDR 2 x 3 RGBA");
  UNIT_CHECK(im.ok && memcmp(im.px, rgba, sizeof rgba) == 0, "RGBA pixels come back");
  free(im.px);
  strcat(p, ".tmp");
  UNIT_CHECK(!exists(p), "no temporary file left after success");
  UNIT_CHECK(png_write(p, rgb, 0, 2, 3, err, sizeof err) < 0 && strstr(err, "size"),
             "a 0-wide image is refused: %s", err);
  UNIT_CHECK(png_write(p, rgb, 3, 2, 2, err, sizeof err) < 0, "2 channels refused");
}

static void test_png_unwritable(void) {
  unsigned char rgb[12] = {0};
  char file[512], p[600], err[512];
  FILE *f;
  path(file, sizeof file, "plainfile");
  f = fopen(file, "w");
  fclose(f);
  /* a path under a regular file can never be created, even by root */
  snprintf(p, sizeof p, "%s/x.png", file);
  UNIT_CHECK(png_write(p, rgb, 2, 2, 3, err, sizeof err) < 0, "write under a file fails");
  UNIT_CHECK(strstr(err, p) && strstr(err, "Not a directory"),
             "the message names the path and the reason: %s", err);
  UNIT_CHECK(!exists(p), "no file under the final name");
  strcat(p, ".tmp");
  UNIT_CHECK(!exists(p), "no temporary file");
  UNIT_CHECK(png_write("/nonexistent-dir-mvmpm/x.png", rgb, 2, 2, 3, err,
                       sizeof err) < 0 && strstr(err, "No such file"),
             "missing directory: %s", err);
  /* the final name is left alone when a write fails */
  path(p, sizeof p, "keep.png");
  UNIT_CHECK(png_write(p, rgb, 2, 2, 3, err, sizeof err) == 0, "first write");
  UNIT_CHECK(png_write(p, rgb, 0, 2, 3, err, sizeof err) < 0, "failing rewrite");
  {
    image im = decode(p);
    UNIT_CHECK(im.ok && im.w == 2, "the earlier file is intact");
    free(im.px);
  }
}

/* a store of n particles of side a (volume a^2) */
static void store(particles *ps, int n, double a) {
  int i;
  particles_init(ps);
  for (i = 0; i < n; i++) {
    particles_push(ps);
    ps->vol0[i] = a * a;
    ps->m[i] = 1;
  }
}

/* pixel of world point (x, y) by the domain rectangle: y up */
static void at(const render_layout *L, const render_opts *o, double x, double y,
               int *px, int *py) {
  *px = L->dx0 + (int)floor((x - o->lo[0]) / (o->hi[0] - o->lo[0]) * (L->dx1 - L->dx0));
  *py = L->dy0 + (int)floor((o->hi[1] - y) / (o->hi[1] - o->lo[1]) * (L->dy1 - L->dy0));
}

static render_opts unit_square(const char *by, int width) {
  render_opts o;
  memset(&o, 0, sizeof o);
  o.by = by;
  o.width = width;
  o.cmap = RENDER_AUTO;
  o.lo[0] = o.lo[1] = 0;
  o.hi[0] = o.hi[1] = 1;
  o.title = "test";
  return o;
}

static void test_render_body(void) {
  particles ps;
  render_opts o = unit_square("body", 400);
  render_layout L;
  canvas c;
  char p[512], err[512];
  image im;
  int x, y;
  uint32_t c0 = cmap_category(0), c1 = cmap_category(1);
  store(&ps, 2, 0.1);
  ps.x[0][0] = 0.25; ps.x[1][0] = 0.75; ps.body[0] = 0;   /* upper left */
  ps.x[0][1] = 0.75; ps.x[1][1] = 0.25; ps.body[1] = 1;   /* lower right */
  ps.F[0][0] = 2;  /* particle 0 stretched to 0.2 along x */
  UNIT_CHECK(c0 != c1 && c0 != WHITE && c1 != WHITE, "body colours differ");
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw: %s", err);
  canvas_free(&c);
  UNIT_CHECK(L.w == 400 && L.dx1 - L.dx0 == L.dy1 - L.dy0,
             "a square domain is a square (%d x %d)", L.dx1 - L.dx0, L.dy1 - L.dy0);
  path(p, sizeof p, "body.png");
  UNIT_CHECK(render_png(p, &ps, &o, err, sizeof err) == 0, "render_png: %s", err);
  im = decode(p);
  UNIT_CHECK(im.w == L.w && im.h == L.h, "image is %d x %d as laid out", im.w, im.h);
  at(&L, &o, 0.25, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == c0, "body 0 colour at (0.25, 0.75), upper left (got %06x)",
             (unsigned)pix(&im, x, y));
  at(&L, &o, 0.25 + 0.085, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == c0, "F stretches particle 0 to 0.085 right of centre");
  at(&L, &o, 0.25 + 0.12, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "background beyond its stretched edge");
  at(&L, &o, 0.25, 0.75 + 0.07, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "unstretched along y: background 0.07 above");
  at(&L, &o, 0.75, 0.25, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == c1, "body 1 colour at (0.75, 0.25), lower right");
  at(&L, &o, 0.75 + 0.04, 0.25 - 0.04, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == c1, "its square reaches 0.04 from the centre");
  at(&L, &o, 0.75 + 0.07, 0.25, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "background 0.07 beside it");
  at(&L, &o, 0.75, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "background at (0.75, 0.75)");
  at(&L, &o, 0.25, 0.25, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "background at (0.25, 0.25)");
  UNIT_CHECK(pix(&im, L.dx0 - 1, (L.dy0 + L.dy1) / 2) == 0 &&
             pix(&im, (L.dx0 + L.dx1) / 2, L.dy1) == 0, "the domain outline is drawn");
  free(im.px);
  /* a tall domain keeps its aspect */
  o.hi[1] = 2;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "tall: %s", err);
  UNIT_CHECK(abs((L.dy1 - L.dy0) - 2 * (L.dx1 - L.dx0)) <= 1, "1 x 2 domain is twice as high");
  canvas_free(&c);
  particles_free(&ps);
}

/* A particle sheared on: F = [[1, g], [0, 1]].  At g = 1 (stretch 2.6)
** its square is drawn as F maps it (a point only the sheared square
** covers is coloured); at g = 1000 (a sheared PBX bed's particles reached
** stretches of 10^6, drawn as streaks across the grains) it is drawn
** with a stretch of 4 along the same axes and the same area: nothing
** past 2.5 half sides and the seal, and about the square's area. */
static void test_render_stretch(void) {
  const double a = 0.05, gs[2] = {1, 1000};
  int k;
  for (k = 0; k < 2; k++) {
    particles ps;
    render_opts o = unit_square("body", 400);
    render_layout L;
    canvas c;
    char err[512];
    int x, y, px, py, drawn = 0, far = 0;
    double pix, g = gs[k];
    store(&ps, 1, 2 * a);
    ps.x[0][0] = ps.x[1][0] = 0.5;
    ps.F[0][0] = 1; ps.F[1][0] = g; ps.F[2][0] = 0; ps.F[3][0] = 1;
    ps.body[0] = 0;
    UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw: %s", err);
    pix = (L.dx1 - L.dx0) / (o.hi[0] - o.lo[0]); /* pixels per unit */
    for (y = L.dy0; y < L.dy1; y++)
      for (x = L.dx0; x < L.dx1; x++) {
        double wx = o.lo[0] + (x + 0.5 - L.dx0) / pix - 0.5;
        double wy = o.hi[1] - (y + 0.5 - L.dy0) / pix - 0.5;
        if (canvas_get(&c, x, y) != cmap_category(0)) continue;
        drawn++;
        if (hypot(wx, wy) > 2.5 * a + 2 / pix) far++;
      }
    if (k == 0) {
      at(&L, &o, 0.5 + 1.8 * a, 0.5 + 0.9 * a, &px, &py);
      UNIT_CHECK(canvas_get(&c, px, py) == cmap_category(0),
                 "shear 1: the sheared square's corner (1.8, 0.9) half sides out is drawn");
    } else {
      UNIT_CHECK(far == 0, "shear 1000: no pixel past 2.5 half sides (%d)", far);
      UNIT_CHECK(fabs(drawn / (4 * a * a * pix * pix) - 1) < 0.2,
                 "shear 1000: drawn area / the square's = %.3f (within 20 %%)",
                 drawn / (4 * a * a * pix * pix));
    }
    canvas_free(&c);
    particles_free(&ps);
  }
}

/* a turned body whose particles do not abut exactly (each moved a
** little on its own, as a sheared grain's are): no pixel inside it is
** background (before, seams thinner than a pixel left white pinholes
** that read as cracks), and none a few pixels outside it is drawn */
static void test_render_seams(void) {
  enum { N = 12 };
  const double a = 0.04, th = 20 * 3.14159265358979 / 180, cs = cos(th), sn = sin(th);
  particles ps;
  render_opts o = unit_square("body", 400);
  render_layout L;
  canvas c;
  char err[512];
  unsigned lcg = 12345u;
  int i, j, x, y, holes = 0, inside = 0, stray = 0;
  store(&ps, N * N, a);
  for (j = 0; j < N; j++)
    for (i = 0; i < N; i++) {
      int k = j * N + i;
      double u = (i - 0.5 * (N - 1)) * a, v = (j - 0.5 * (N - 1)) * a, d[2];
      for (x = 0; x < 2; x++) { /* +-0.0006: 0.24 pixels at this scale */
        lcg = lcg * 1664525u + 1013904223u;
        d[x] = ((lcg >> 8) / 16777216.0 - 0.5) * 0.0012;
      }
      ps.x[0][k] = 0.5 + cs * u - sn * v + d[0];
      ps.x[1][k] = 0.5 + sn * u + cs * v + d[1];
      ps.F[0][k] = cs; ps.F[1][k] = -sn; ps.F[2][k] = sn; ps.F[3][k] = cs;
      ps.body[k] = 0;
    }
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw: %s", err);
  for (y = L.dy0; y < L.dy1; y++)
    for (x = L.dx0; x < L.dx1; x++) {
      double wx = o.lo[0] + (x + 0.5 - L.dx0) / (L.dx1 - L.dx0) - 0.5;
      double wy = o.hi[1] - (y + 0.5 - L.dy0) / (L.dy1 - L.dy0) - 0.5;
      double u = cs * wx + sn * wy, v = -sn * wx + cs * wy, h = 0.5 * N * a;
      if (fabs(u) < h - a && fabs(v) < h - a) {
        inside++;
        if (canvas_get(&c, x, y) == WHITE) holes++;
      } else if ((fabs(u) > h + 0.008 || fabs(v) > h + 0.008) &&
                 canvas_get(&c, x, y) == cmap_category(0))
        stray++;
    }
  UNIT_CHECK(inside > 5000 && holes == 0, "a turned body with seams: %d of %d pixels inside "
             "it are background", holes, inside);
  UNIT_CHECK(stray == 0, "  and none of its colour 3 pixels past its outline (%d)", stray);
  canvas_free(&c);
  particles_free(&ps);
}

static void test_render_scalar(void) {
  particles ps;
  render_opts o = unit_square("mass", 400);
  render_layout L;
  canvas c;
  char p[512], err[1024];
  image im;
  int x, y, bx;
  uint32_t lo = cmap_color(CMAP_SEQ, 0), hi = cmap_color(CMAP_SEQ, 1);
  store(&ps, 2, 0.1);
  ps.x[0][0] = 0.25; ps.x[1][0] = 0.5; ps.m[0] = 1;
  ps.x[0][1] = 0.75; ps.x[1][1] = 0.5; ps.m[1] = 3;
  path(p, sizeof p, "mass.png");
  UNIT_CHECK(render_png(p, &ps, &o, err, sizeof err) == 0, "render_png: %s", err);
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw");
  canvas_free(&c);
  UNIT_CHECK(L.vlo == 1 && L.vhi == 3 && L.cmap == CMAP_SEQ,
             "positive values: range = min, max on the sequential map");
  im = decode(p);
  at(&L, &o, 0.25, 0.5, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == lo, "the smallest value has the map's first colour");
  at(&L, &o, 0.75, 0.5, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == hi, "the largest has its last colour");
  bx = (L.bx0 + L.bx1) / 2;
  UNIT_CHECK(pix(&im, bx, L.by0) == hi, "colour bar top = last colour (got %06x)",
             (unsigned)pix(&im, bx, L.by0));
  UNIT_CHECK(pix(&im, bx, L.by1 - 1) == lo, "colour bar bottom = first colour");
  UNIT_CHECK(pix(&im, bx, L.by0 - 1) == 0, "the bar has an outline");
  free(im.px);
  /* signed values: the diverging map, symmetric about zero */
  ps.m[0] = -1;
  ps.m[1] = 2;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw");
  UNIT_CHECK(L.cmap == CMAP_DIV && L.vlo == -2 && L.vhi == 2, "both signs: div, +-2");
  at(&L, &o, 0.25, 0.5, &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == cmap_color(CMAP_DIV, 0.25), "-1 sits a quarter up");
  canvas_free(&c);
  /* a given range clamps */
  o.has_range = 1;
  o.range[0] = 0;
  o.range[1] = 1;
  o.cmap = CMAP_SEQ;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "render_draw");
  at(&L, &o, 0.75, 0.5, &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == hi, "above the range: the last colour");
  canvas_free(&c);
  /* bad keys name themselves and list the good ones */
  o.by = "nosuch";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 && strstr(err, "'nosuch'") &&
             strstr(err, "stress.xx|yy|xy|zz") && strstr(err, "sdiff"),
             "unknown key: %s", err);
  o.by = "stress";
  UNIT_CHECK(render_values(&ps, o.by, 0, NULL, err, sizeof err) < 0 &&
             strstr(err, "stress.xx"), "a field needs its component: %s", err);
  o.by = "velocity.q";
  UNIT_CHECK(render_values(&ps, o.by, 0, NULL, err, sizeof err) < 0 &&
             strstr(err, "no component 'q'"), "bad component: %s", err);
  UNIT_CHECK(render_values(&ps, "gradv.xx", PF_OUTPUT, NULL, err, sizeof err) < 0,
             "a field without the needed flags is absent");
  o.by = "mass";
  o.width = 50;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 && strstr(err, "width"),
             "too narrow: %s", err);
  particles_free(&ps);
}

static void test_values(void) {
  particles ps;
  double v[1];
  char err[1024];
  store(&ps, 1, 0.1);
  /* sigma = diag(-3, -6) with s_zz = -3: pressure 4 */
  ps.s[S_XX][0] = -3; ps.s[S_YY][0] = -6; ps.s[S_ZZ][0] = -3; ps.s[S_XY][0] = 0;
  UNIT_CHECK(render_values(&ps, "pressure", 0, v, err, sizeof err) == RENDER_SCALAR, "pressure");
  UNIT_NEAR(v[0], 4.0, 1e-14, "pressure of diag(-3, -6), zz -3");
  /* [[3, sqrt 3], [sqrt 3, 1]] has eigenvalues 4 and 0 */
  ps.s[S_XX][0] = 3; ps.s[S_YY][0] = 1; ps.s[S_XY][0] = sqrt(3.0);
  render_values(&ps, "sdiff", 0, v, err, sizeof err);
  UNIT_NEAR(v[0], 4.0, 1e-14, "sdiff of [[3, sqrt3], [sqrt3, 1]]");
  ps.v[0][0] = 3; ps.v[1][0] = -4;
  render_values(&ps, "speed", 0, v, err, sizeof err);
  UNIT_NEAR(v[0], 5.0, 1e-14, "speed of (3, -4)");
  render_values(&ps, "velocity.y", 0, v, err, sizeof err);
  UNIT_NEAR(v[0], -4.0, 0, "velocity.y");
  render_values(&ps, "velocity.2", 0, v, err, sizeof err);
  UNIT_NEAR(v[0], -4.0, 0, "velocity.2 (component by number)");
  render_values(&ps, "stress.xy", 0, v, err, sizeof err);
  UNIT_NEAR(v[0], sqrt(3.0), 0, "stress.xy");
  ps.body[0] = 3;
  UNIT_CHECK(render_values(&ps, "body", 0, v, err, sizeof err) == RENDER_BODY && v[0] == 3,
             "body is categorical");
  UNIT_CHECK(particles_add_field(&ps, "bond", 1, PF_DOUBLE, "", PF_OUTPUT) >= 0, "add bond");
  ((double *)particles_comp(&ps, particles_find(&ps, "bond"), 0))[0] = 0.5;
  UNIT_CHECK(render_values(&ps, "bond", PF_OUTPUT, v, err, sizeof err) == RENDER_SCALAR &&
             v[0] == 0.5, "a run-time field 'bond'");
  particles_free(&ps);
}

static void test_deterministic(void) {
  particles ps;
  render_opts o = unit_square("sdiff", 300);
  canvas c1, c2;
  unsigned char *b1, *b2;
  size_t n1, n2;
  char err[512];
  int i;
  store(&ps, 50, 0.03);
  for (i = 0; i < 50; i++) {
    ps.x[0][i] = 0.1 + 0.016 * i;
    ps.x[1][i] = 0.5 + 0.3 * sin(i);
    ps.s[S_XY][i] = cos(3.0 * i);
    ps.F[1][i] = 0.3; /* sheared */
  }
  render_draw(&c1, NULL, &ps, &o, err, sizeof err);
  render_draw(&c2, NULL, &ps, &o, err, sizeof err);
  png_encode(c1.px, c1.w, c1.h, 3, &b1, &n1, err, sizeof err);
  png_encode(c2.px, c2.w, c2.h, 3, &b2, &n2, err, sizeof err);
  UNIT_CHECK(n1 == n2 && memcmp(b1, b2, n1) == 0, "same input, same bytes");
  free(b1);
  free(b2);
  canvas_free(&c1);
  canvas_free(&c2);
  particles_free(&ps);
}

/* lightness rises along the sequential map; the diverging one goes from
** blue through grey to red */
static void test_cmaps(void) {
  int k, mono = 1;
  double prev = -1;
  uint32_t m = cmap_color(CMAP_DIV, 0.5), a = cmap_color(CMAP_DIV, 0),
           b = cmap_color(CMAP_DIV, 1);
  for (k = 0; k <= 256; k++) {
    uint32_t c = cmap_color(CMAP_SEQ, k / 256.0);
    double l = 0.2126 * (c >> 16) + 0.7152 * (c >> 8 & 255) + 0.0722 * (c & 255);
    if (l < prev - 0.5) mono = 0; /* 0.5: rounding each channel to 8 bits */
    prev = l;
  }
  UNIT_CHECK(mono, "sequential map: luminance never falls (beyond rounding)");
  {
    uint32_t c0 = cmap_color(CMAP_SEQ, 0), c1 = cmap_color(CMAP_SEQ, 1);
    double l0 = 0.2126 * (c0 >> 16) + 0.7152 * (c0 >> 8 & 255) + 0.0722 * (c0 & 255);
    double l1 = 0.2126 * (c1 >> 16) + 0.7152 * (c1 >> 8 & 255) + 0.0722 * (c1 & 255);
    UNIT_CHECK(l1 - l0 > 150, "sequential map spans dark to light (%.0f to %.0f)", l0, l1);
  }
  UNIT_CHECK((m >> 16) == (m & 255) && (m >> 16) == (m >> 8 & 255) && m != WHITE,
             "diverging middle is a grey that is not the background");
  UNIT_CHECK((a & 255) > (a >> 16) && (b >> 16) > (b & 255), "blue end, red end");
  UNIT_CHECK(cmap_color(CMAP_SEQ, NAN) == CMAP_NAN, "NaN gets its own colour");
  for (k = 0; k < CMAP_NCAT; k++) {
    int j, far = 1;
    for (j = 0; j < k; j++) {
      uint32_t p = cmap_category(j), q = cmap_category(k);
      int dr = (int)(p >> 16) - (int)(q >> 16), dg = (int)(p >> 8 & 255) - (int)(q >> 8 & 255),
          db = (int)(p & 255) - (int)(q & 255);
      if (dr * dr + dg * dg + db * db < 60 * 60) far = 0;
    }
    UNIT_CHECK(far, "categorical colour %d is far from those before it", k);
  }
}

static void test_font(void) {
  unsigned long cp;
  int bad = 0;
  const char *s = "σ";
  for (cp = 32; cp < 127; cp++) {
    const char *g = font_glyph(cp);
    size_t n = g ? strlen(g) : 999, i;
    if (!g || (n && (n + 1) % 6) || n > 9 * 6 - 1) { bad++; continue; }
    for (i = 0; i < n; i++)
      if ((i % 6 == 5) != (g[i] == ' ') || (g[i] != ' ' && g[i] != '#' && g[i] != '.')) bad++;
    if (cp != ' ' && !strchr(g, '#')) bad++;
  }
  UNIT_CHECK(bad == 0, "every ASCII glyph is rows of 5 '#'/'.' (%d bad)", bad);
  UNIT_CHECK(font_next(&s) == 0x3C3 && *s == 0, "UTF-8 sigma decodes");
  UNIT_CHECK(font_glyph(0x3C3) != NULL, "sigma has a glyph");
  {
    canvas c;
    int x, y, in = 0, out = 0;
    canvas_init(&c, 40, 30, WHITE);
    canvas_text(&c, 10, 10, "1", 2, 0, CV_LEFT, CV_TOP, 0);
    for (y = 0; y < 30; y++)
      for (x = 0; x < 40; x++) {
        int inside = x >= 10 && x < 20 && y >= 10 && y < 24;
        if (canvas_get(&c, x, y) == 0) { if (inside) in++; else out++; }
      }
    UNIT_CHECK(in > 10 && out == 0, "'1' at scale 2 inks only its 10 x 14 cell (%d in, %d out)",
               in, out);
    canvas_free(&c);
  }
}

static void test_axis(void) {
  double t[AXIS_MAXTICKS], mn[4 * AXIS_MAXTICKS], step;
  char b[64];
  int n = axis_ticks(0, 1, 6, t, &step), nm;
  UNIT_CHECK(n == 6 && step == 0.2 && t[0] == 0 && fabs(t[5] - 1) < 1e-15,
             "ticks of [0, 1]: 0, 0.2, ..., 1 (n %d, step %g)", n, step);
  n = axis_ticks(-0.095, 0.095, 6, t, &step);
  UNIT_CHECK(n >= 3 && t[0] >= -0.095 && t[n - 1] <= 0.095, "ticks stay inside the range");
  axis_label(0.2, 0.2, b, sizeof b);
  UNIT_CHECK(strcmp(b, "0.2") == 0, "label 0.2 (got %s)", b);
  axis_label(0.25, 0.25, b, sizeof b);
  UNIT_CHECK(strcmp(b, "0.25") == 0, "label 0.25 (got %s)", b);
  axis_label(1.5e-5, 1e-6, b, sizeof b);
  UNIT_CHECK(strcmp(b, "1.5e-5") == 0, "label 1.5e-5 (got %s)", b);
  axis_label(-2e6, 1e6, b, sizeof b);
  UNIT_CHECK(strcmp(b, "-2e6") == 0, "label -2e6 (got %s)", b);
  n = axis_logticks(1, 1000, t, mn, &nm);
  UNIT_CHECK(n == 4 && t[0] == 1 && t[3] == 1000 && nm == 24, "log ticks 1..1000 (%d, %d minor)",
             n, nm);
}

static void test_plot(void) {
  double x1[4] = {0, 1, 2, 3}, y1[4] = {0, 1, 4, 9};
  double x2[3] = {1, NAN, 2}, y2[3] = {5, 5, INFINITY};
  double x3[1] = {7}, y3[1] = {-2};
  double xl[3] = {-1, 10, 100}, yl[3] = {1, 0.1, 0.01};
  plot_series s[3] = {{x1, y1, 4, "squares", PLOT_BOTH},
                      {x2, y2, 3, "broken", PLOT_LINE},
                      {x3, y3, 1, NULL, PLOT_POINTS}};
  plot_opts o;
  plot_layout L;
  canvas c;
  char p[512], err[512];
  double px, py;
  image im;
  memset(&o, 0, sizeof o);
  o.width = 400;
  o.height = 300;
  o.title = "t";
  o.xlabel = "x";
  o.ylabel = "y";
  o.has_xrange = o.has_yrange = 1;
  o.xrange[0] = 0; o.xrange[1] = 10;
  o.yrange[0] = -10; o.yrange[1] = 10;
  UNIT_CHECK(plot_draw(&c, &L, s, 3, &o, err, sizeof err) == 0, "plot_draw: %s", err);
  plot_map(&L, &o, 5, 0, &px, &py);
  UNIT_CHECK(fabs(px - 0.5 * (L.px0 + L.px1)) < 1e-9 && fabs(py - 0.5 * (L.py0 + L.py1)) < 1e-9,
             "the middle of the ranges maps to the middle of the plot");
  plot_map(&L, &o, 2, 4, &px, &py);
  UNIT_CHECK(canvas_get(&c, (int)px, (int)py) == cmap_category(0), "series 1 marker at (2, 4)");
  plot_map(&L, &o, 7, -2, &px, &py);
  UNIT_CHECK(canvas_get(&c, (int)px, (int)py) == cmap_category(2),
             "a single point still shows");
  plot_map(&L, &o, 0.5, 0.5, &px, &py);
  UNIT_CHECK(canvas_get(&c, (int)px, (int)py) == cmap_category(0),
             "the line between (0, 0) and (1, 1)");
  plot_map(&L, &o, 1.5, 5, &px, &py);
  UNIT_CHECK(canvas_get(&c, (int)px, (int)py) != cmap_category(1),
             "no line bridges a NaN point");
  plot_map(&L, &o, 1, NAN, &px, &py);
  UNIT_CHECK(isnan(px), "NaN points do not map");
  canvas_free(&c);
  /* automatic ranges hold every usable point */
  o.has_xrange = o.has_yrange = 0;
  UNIT_CHECK(plot_draw(&c, &L, s, 3, &o, err, sizeof err) == 0, "auto ranges");
  UNIT_CHECK(L.xlo < 0 && L.xhi > 7 && L.ylo < -2 && L.yhi > 9, "auto range [%g, %g] x [%g, %g]",
             L.xlo, L.xhi, L.ylo, L.yhi);
  canvas_free(&c);
  /* one constant point alone */
  UNIT_CHECK(plot_draw(&c, &L, s + 2, 1, &o, err, sizeof err) == 0 && L.xlo < 7 && L.xhi > 7 &&
             L.ylo < -2 && L.yhi > -2, "a single point gets a range around it");
  canvas_free(&c);
  /* a title wider than the image goes on two lines inside it, and its
  ** band has ink (a study's titles ran off both edges) */
  {
    int top1, x, y, edge = 0, ink = 0;
    uint32_t bg;
    UNIT_CHECK(plot_draw(&c, &L, s, 3, &o, err, sizeof err) == 0, "short title");
    top1 = L.py0;
    canvas_free(&c);
    o.title = "a title that names the case, the measure and the scheme, longer "
              "than the four hundred pixels of this image";
    UNIT_CHECK(plot_draw(&c, &L, s, 3, &o, err, sizeof err) == 0, "long title: %s", err);
    bg = canvas_get(&c, 0, 0);
    for (y = 0; y < L.py0 - 2; y++)
      for (x = 0; x < c.w; x++) {
        uint32_t v = canvas_get(&c, x, y);
        if (v != bg && (x < 4 || x >= c.w - 4)) edge++;
        if (v != bg) ink++;
      }
    UNIT_CHECK(L.py0 > top1 && edge == 0 && ink > 0,
               "long title: two lines (plot top %d against %d), %d pixels at the "
               "image's edges, %d inked", L.py0, top1, edge, ink);
    canvas_free(&c);
    o.title = "t";
  }
  /* a legend as wide as most of the plot, over a peak in the middle and a
  ** line along the bottom: every corner hides some of it, so the y axis
  ** is raised above the peak and the legend goes where nothing is (it
  ** used to hide the peak: a shear cell's force against strain) */
  {
    double xp[41], yp[41], xq[1] = {20}, yq[1] = {1};
    long n = 0;
    int k, x, y, hide = 0;
    plot_series w[2] = {{xp, yp, 41, "a legend entry that is wider than half of the plot", PLOT_LINE},
                        {xq, yq, 1, "the peak", PLOT_POINTS}};
    for (k = 0; k <= 40; k++) {
      xp[k] = k;
      yp[k] = k >= 16 && k <= 24 ? 1 - fabs(k - 20.0) / 4.0 : 0;
    }
    UNIT_CHECK(plot_draw(&c, &L, w, 2, &o, err, sizeof err) == 0, "wide legend: %s", err);
    plot_map(&L, &o, 20, 1, &px, &py);
    UNIT_CHECK(canvas_get(&c, (int)px, (int)py) == cmap_category(1),
               "wide legend: the peak's marker shows (y axis to %g)", L.yhi);
    /* the line's pixels between samples, checked along every segment */
    for (k = 0; k < 40; k++) {
      double ax, ay, bx, by;
      int j;
      plot_map(&L, &o, xp[k], yp[k], &ax, &ay);
      plot_map(&L, &o, xp[k + 1], yp[k + 1], &bx, &by);
      for (j = 1; j < 8; j++) {
        x = (int)floor(ax + (bx - ax) * j / 8 + 0.5);
        y = (int)floor(ay + (by - ay) * j / 8 + 0.5);
        n++;
        { /* a one-pixel line: blank if nothing but white around the point */
          int a, b, ink = 0;
          for (a = -1; a <= 1; a++)
            for (b = -1; b <= 1; b++)
              if (canvas_get(&c, x + a, y + b) == cmap_category(0)) ink++;
          if (!ink) hide++;
        }
      }
    }
    UNIT_CHECK(hide == 0, "wide legend: %d of %ld points along the line show no line", hide, n);
    canvas_free(&c);
  }
  /* log axes skip x <= 0, and the file decodes */
  s[0].x = xl; s[0].y = yl; s[0].n = 3;
  o.xlog = o.ylog = 1;
  path(p, sizeof p, "plot.png");
  UNIT_CHECK(plot_png(p, s, 1, &o, err, sizeof err) == 0, "plot_png: %s", err);
  UNIT_CHECK(plot_draw(&c, &L, s, 1, &o, err, sizeof err) == 0 && L.xlo > 0 && L.xlo < 10 &&
             L.ylo < 0.01, "log ranges from the positive points only");
  canvas_free(&c);
  im = decode(p);
  UNIT_CHECK(im.ok && im.w == 400 && im.h == 300, "plot PNG is 400 x 300");
  free(im.px);
  o.has_xrange = 1;
  o.xrange[0] = 0; o.xrange[1] = 1;
  UNIT_CHECK(plot_png(p, s, 1, &o, err, sizeof err) < 0 && strstr(err, "xrange"),
             "log axis with a range from 0 refused: %s", err);
}


/* the colour range: robust against outliers, the true extent kept; a
** field that is round-off of its scale draws as zero; log scales */
static void test_ranges(void) {
  particles ps;
  render_opts o = unit_square("mass", 400);
  render_layout L;
  canvas c;
  char err[1024];
  int i, x, y, n = 200;
  store(&ps, n, 0.01);
  for (i = 0; i < n; i++) {
    ps.x[0][i] = 0.05 + 0.9 * (i % 20) / 19.0;
    ps.x[1][i] = 0.05 + 0.9 * (i / 20) / 9.0;
    ps.m[i] = 1 + i;            /* 1 .. 200 */
  }
  ps.m[n - 1] = 1e6;            /* one outlier */
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "robust: %s", err);
  canvas_free(&c);
  UNIT_CHECK(L.vhi < 250 && L.vmax == 1e6 && L.vmin == 1,
             "robust range ends at the 99th percentile (%g), min/max kept (%g, %g)",
             L.vhi, L.vmin, L.vmax);
  at(&L, &o, ps.x[0][n - 1], ps.x[1][n - 1], &x, &y);
  o.autorange = RENDER_FULL;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.vhi == 1e6 &&
             L.vlo == 1, "range = full: min and max (%g, %g)", L.vlo, L.vhi);
  canvas_free(&c);
  o.autorange = RENDER_ROBUST;
  /* a value spread within round-off is a constant: the middle colour */
  for (i = 0; i < n; i++) ps.m[i] = 0.1414213562373095 * (1 + (i % 3) * 2.2e-16);
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "constant");
  at(&L, &o, ps.x[0][7], ps.x[1][7], &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == cmap_color(L.cmap, 0.5),
             "values 1 ulp apart draw in the middle colour, not the ends");
  canvas_free(&c);
  /* stress of bodies in free flight: 1e-13 against rho v^2 = 100 */
  for (i = 0; i < n; i++) {
    ps.m[i] = 0.01;             /* density 100 */
    ps.v[0][i] = 1;
    ps.s[S_XY][i] = (i % 2 ? 1 : -1) * 1e-13;
    ps.s[S_XX][i] = ps.s[S_YY][i] = ps.s[S_ZZ][i] = 3e-14;
  }
  o.by = "stress.xy";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.roundoff &&
             L.cmap == CMAP_DIV, "round-off stress is recognised (range %g, %g)", L.vlo, L.vhi);
  at(&L, &o, ps.x[0][1], ps.x[1][1], &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == cmap_color(CMAP_DIV, 0.5),
             "1e-13 of stress draws as zero (got %06x)", (unsigned)canvas_get(&c, x, y));
  canvas_free(&c);
  o.by = "pressure";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.roundoff,
             "round-off pressure too");
  canvas_free(&c);
  ps.s[S_XY][0] = 50;           /* a real stress: drawn as it is */
  o.by = "stress.xy";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && !L.roundoff,
             "a stress of 50 is not round-off");
  canvas_free(&c);
  /* log: 1, 10, 100 at a third and two thirds apart */
  o.by = "mass";
  o.log = 1;
  for (i = 0; i < n; i++) ps.m[i] = i < 67 ? 1 : i < 134 ? 10 : 100;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.vlo == 1 &&
             L.vhi == 100, "log range 1..100: %s", err);
  at(&L, &o, ps.x[0][100], ps.x[1][100], &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == cmap_color(L.cmap, 0.5),
             "10 sits in the middle of 1..100 on a log scale");
  canvas_free(&c);
  ps.m[3] = 0;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 &&
             strstr(err, "log scale needs values above zero") && strstr(err, "'mass'"),
             "log over a zero is refused: %s", err);
  o.has_range = 1;
  o.range[0] = 0;
  o.range[1] = 1;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) < 0 &&
             strstr(err, "range above zero"), "log with a range from 0: %s", err);
  o.range[0] = 1;
  o.range[1] = 100;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0,
             "log with a positive range draws a zero at the bottom");
  canvas_free(&c);
  particles_free(&ps);
}

/* body colours: a matrix among grains is grey, the grains never are */
static void test_matrix(void) {
  particles ps;
  render_opts o = unit_square("body", 400);
  render_layout L;
  canvas c;
  char err[512];
  const char *names[4] = {"g1", "g2", "bulk", "g3"};
  int i, x, y, k, n = 40, grey = 0;
  for (k = 0; k < 4 * CMAP_NCAT; k++)
    if (render_body_color(k, -1) == RENDER_MATRIX || render_body_color(k, -1) == CMAP_NAN)
      grey = 1;
  UNIT_CHECK(!grey, "no grain colour is the matrix grey or the NaN grey");
  store(&ps, n, 0.02);
  for (i = 0; i < n; i++) {
    ps.x[0][i] = 0.05 + 0.02 * i;
    ps.x[1][i] = 0.5;
    ps.body[i] = i < 3 ? 0 : i < 6 ? 1 : i < 9 ? 3 : 2;  /* body 2 the bulk */
  }
  o.names = names;
  o.nnames = 4;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.matrix == 2,
             "the body with most of the particles is the matrix (%d)", L.matrix);
  at(&L, &o, ps.x[0][20], 0.5, &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == RENDER_MATRIX, "... drawn grey");
  at(&L, &o, ps.x[0][1], 0.5, &x, &y);
  UNIT_CHECK(canvas_get(&c, x, y) == cmap_category(0), "a grain keeps its colour");
  canvas_free(&c);
  names[0] = "binder";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.matrix == 0,
             "a body named binder is the matrix");
  canvas_free(&c);
  o.matrix = "g3";
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.matrix == 3,
             "the matrix named in the options wins");
  canvas_free(&c);
  o.matrix = NULL;
  names[0] = "g1";
  for (i = 0; i < n; i++) ps.body[i] = i < 20 ? 0 : 1;  /* two bodies: no matrix */
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 && L.matrix == -1,
             "two bodies: none is a matrix");
  canvas_free(&c);
  particles_free(&ps);
}

/* axes, units, SVG */
static void test_axes_svg(void) {
  particles ps;
  render_opts o = unit_square("mass", 400);
  render_layout L;
  canvas c;
  char p[512], err[512], *buf;
  FILE *f;
  long len;
  int x, paths = 0;
  const char *q;
  UNIT_CHECK(render_length_unit("SI") && strcmp(render_length_unit("SI"), "m") == 0 &&
             strcmp(render_length_unit("mm"), "mm") == 0 &&
             render_length_unit("nondimensional") == NULL, "length units of the units");
  store(&ps, 3, 0.1);
  ps.x[0][0] = 0.25; ps.x[1][0] = 0.5; ps.m[0] = 1;
  ps.x[0][1] = 0.5; ps.x[1][1] = 0.5; ps.m[1] = 2;
  ps.x[0][2] = 0.75; ps.x[1][2] = 0.5; ps.m[2] = 3;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0, "axes");
  x = L.dx0 + (int)floor(0.4 * (L.dx1 - L.dx0) + 0.5);
  UNIT_CHECK(canvas_get(&c, x, L.dy1 + L.scale + 1) == 0,
             "a tick mark under the domain at x = 0.4");
  UNIT_CHECK(L.bar == 0.2, "a 1-2-5 scale bar of a fifth of the width (%g)", L.bar);
  canvas_free(&c);
  o.noaxes = 1;
  UNIT_CHECK(render_draw(&c, &L, &ps, &o, err, sizeof err) == 0 &&
             canvas_get(&c, x, L.dy1 + L.scale + 1) == WHITE, "none without axes");
  canvas_free(&c);
  o.noaxes = 0;
  o.unit = "m";
  path(p, sizeof p, "r.svg");
  UNIT_CHECK(render_file(p, &ps, &o, err, sizeof err) == 0, "render_file .svg: %s", err);
  f = fopen(p, "rb");
  UNIT_CHECK(f != NULL, "the SVG is there");
  if (!f) { particles_free(&ps); return; }
  fseek(f, 0, SEEK_END);
  len = ftell(f);
  rewind(f);
  buf = calloc(len + 1, 1);
  UNIT_CHECK(fread(buf, 1, len, f) == (size_t)len, "read the SVG");
  fclose(f);
  for (q = buf; (q = strstr(q, "<path ")); q++) paths++;
  UNIT_CHECK(strncmp(buf, "<?xml", 5) == 0 && strstr(buf, "<svg ") &&
             strstr(buf, "</svg>\n") && paths == 3, "an SVG document, a path a particle (%d)",
             paths);
  UNIT_CHECK(strstr(buf, ">x (m)</text>") && strstr(buf, ">y (m)</text>") &&
             strstr(buf, ">0.2 m</text>") && strstr(buf, ">min 1</text>") &&
             strstr(buf, ">max 3</text>"), "axis titles, scale bar and extent as text");
  free(buf);
  unlink(p);
  particles_free(&ps);
}

/* the render command on a snapshot: same picture as the renderer */
static void test_render_cmd(void) {
  particles ps;
  h5meta meta = {.time = 1.5, .step = 10, .cell = 0.1, .units = "nondimensional", .scene = "t.lua", .source = NULL};
  render_opts o = unit_square("body", 400);
  render_layout L;
  canvas c;
  char snap[512], out[512], err[512];
  image im;
  int x, y;
  store(&ps, 2, 0.1);
  ps.x[0][0] = 0.25; ps.x[1][0] = 0.75; ps.body[0] = 0;
  ps.x[0][1] = 0.75; ps.x[1][1] = 0.25; ps.body[1] = 1;
  path(snap, sizeof snap, "snap.h5");
  path(out, sizeof out, "snap.png");
  UNIT_CHECK(out_h5_write(snap, &ps, &meta, err, sizeof err) == 0, "snapshot: %s", err);
  render_draw(&c, &L, &ps, &o, err, sizeof err);
  canvas_free(&c);
  {
    char *argv[] = {"mvmpm", "render", snap, "--out", out, "--width", "400",
                    "--domain", "0,1,0,1", NULL};
    UNIT_CHECK(render_cmd(9, argv) == 0, "mvmpm render SNAP --out --width --domain");
  }
  im = decode(out);
  UNIT_CHECK(im.w == L.w && im.h == L.h, "command's image %d x %d as laid out", im.w, im.h);
  at(&L, &o, 0.25, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == cmap_category(0), "body 0 upper left from the snapshot");
  at(&L, &o, 0.75, 0.25, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == cmap_category(1), "body 1 lower right from the snapshot");
  at(&L, &o, 0.75, 0.75, &x, &y);
  UNIT_CHECK(pix(&im, x, y) == WHITE, "background between them");
  free(im.px);
  {
    char *a1[] = {"mvmpm", "render", snap, "--by", "gradv.xx", "--out", out, NULL};
    char *a2[] = {"mvmpm", "render", "/nonexistent-dir-mvmpm/s.h5", NULL};
    char *a3[] = {"mvmpm", "render", snap, "--range", "2,1", NULL};
    char *a4[] = {"mvmpm", "render", snap, "--bogus", NULL};
    char *a5[] = {"mvmpm", "render", snap, "--by", "sdiff", "--out", out, NULL};
    UNIT_CHECK(render_cmd(7, a1) == 1, "a field the snapshot lacks: status 1");
    UNIT_CHECK(render_cmd(3, a2) == 1, "a missing snapshot: status 1");
    UNIT_CHECK(render_cmd(5, a3) == 2, "a range with hi < lo: status 2");
    UNIT_CHECK(render_cmd(4, a4) == 2, "an unknown option: status 2");
    UNIT_CHECK(render_cmd(7, a5) == 0, "--by sdiff from a snapshot");
  }
  particles_free(&ps);
}

int main(int argc, char **argv) {
  snprintf(dir, sizeof dir, "%s", argc > 1 ? argv[1] : "/tmp/mvmpm_png_XXXXXX");
  if (argc < 2 && !mkdtemp(dir)) { perror("mkdtemp"); return 2; }
  test_png_roundtrip();
  test_png_unwritable();
  test_render_body();
  test_render_seams();
  test_render_stretch();
  test_render_scalar();
  test_values();
  test_deterministic();
  test_cmaps();
  test_font();
  test_axis();
  test_plot();
  test_render_cmd();
  test_ranges();
  test_matrix();
  test_axes_svg();
  if (argc < 2) {
    const char *names[] = {"rgb.png", "rgba.png", "plainfile", "keep.png", "body.png",
                           "mass.png", "plot.png", "snap.h5", "snap.png", NULL};
    char p[512];
    int k;
    for (k = 0; names[k]; k++) { path(p, sizeof p, names[k]); unlink(p); }
    rmdir(dir);
  }
  UNIT_END("test_png");
}
