/*
** cmap.c - colormap stops and the categorical palette.
*/
#include <math.h>
#include "cmap.h"

static const uint32_t seq[5] = {0x2A1E6E, 0x2F5DA8, 0x1E9A96, 0x7CC35A,
                                0xF5E142};
static const uint32_t div_[5] = {0x2B4C9A, 0x86A8D8, 0xDDDDDD, 0xE39B82,
                                 0xA6202E};
/* hues far apart first, so two or three bodies never look alike; no
** grey, which is kept for a matrix (render_png.h) and for NaN */
static const uint32_t cat[CMAP_NCAT] = {0x1F64BE, 0xE8821A, 0x2E9648,
    0xCC2A32, 0x8250B4, 0x8C5A3C, 0xDC64AA, 0x5FC8A0, 0xAAAA28, 0x1EAABE};

static unsigned mix(uint32_t a, uint32_t b, int shift, double f) {
  double x = (a >> shift & 255) + f * ((double)(b >> shift & 255) - (a >> shift & 255));
  return (unsigned)floor(x + 0.5);
}

uint32_t cmap_color(int map, double t) {
  const uint32_t *s = map == CMAP_DIV ? div_ : seq;
  int k;
  double f;
  if (isnan(t)) return CMAP_NAN;
  if (t <= 0) return s[0];
  if (t >= 1) return s[4];
  f = t * 4;
  k = (int)f;
  if (k > 3) k = 3;
  f -= k;
  return mix(s[k], s[k + 1], 16, f) << 16 | mix(s[k], s[k + 1], 8, f) << 8 |
         mix(s[k], s[k + 1], 0, f);
}

uint32_t cmap_category(int k) { return cat[(k < 0 ? -k : k) % CMAP_NCAT]; }
