/*
** png.c - a minimal PNG encoder on zlib's deflate and crc32.
*/
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>
#include "ofile.h"
#include "png.h"

static void put32(unsigned char *p, uint32_t v) {
  p[0] = (unsigned char)(v >> 24);
  p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}

/* a chunk at p: length, type, data (already in place at p + 8), CRC of
** type and data; returns the bytes it took */
static size_t chunk(unsigned char *p, const char *type, size_t len) {
  uLong crc;
  put32(p, (uint32_t)len);
  memcpy(p + 4, type, 4);
  crc = crc32(0L, p + 4, (uInt)(len + 4));
  put32(p + 8 + len, (uint32_t)crc);
  return len + 12;
}

int png_encode(const unsigned char *px, int w, int h, int channels,
               unsigned char **out, size_t *outlen, char *err,
               size_t errlen) {
  static const unsigned char sig[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};
  size_t row, raw_n, zcap, n = 0;
  unsigned char *raw, *buf;
  uLongf zlen;
  int y;
  *out = NULL;
  *outlen = 0;
  if (w < 1 || h < 1 || w > PNG_MAXDIM || h > PNG_MAXDIM ||
      (channels != 3 && channels != 4)) {
    snprintf(err, errlen, "image of %d x %d pixels, %d channels: size must "
             "be 1 to %d and channels 3 or 4", w, h, channels, PNG_MAXDIM);
    return -1;
  }
  row = (size_t)w * channels;
  raw_n = (row + 1) * h;
  raw = malloc(raw_n);
  zcap = compressBound((uLong)raw_n);
  buf = malloc(8 + 25 + 12 + zcap + 12);
  if (!raw || !buf) {
    free(raw);
    free(buf);
    snprintf(err, errlen, "out of memory for a %d x %d image", w, h);
    return -1;
  }
  for (y = 0; y < h; y++) {
    raw[y * (row + 1)] = 0; /* filter: none */
    memcpy(raw + y * (row + 1) + 1, px + y * row, row);
  }
  memcpy(buf, sig, 8);
  n = 8;
  put32(buf + n + 8, (uint32_t)w);
  put32(buf + n + 12, (uint32_t)h);
  buf[n + 16] = 8;                       /* bit depth */
  buf[n + 17] = channels == 3 ? 2 : 6;   /* colour type */
  buf[n + 18] = buf[n + 19] = buf[n + 20] = 0; /* deflate, filter 0, no interlace */
  n += chunk(buf + n, "IHDR", 13);
  zlen = (uLongf)zcap;
  if (compress2(buf + n + 8, &zlen, raw, (uLong)raw_n, 9) != Z_OK) {
    free(raw);
    free(buf);
    snprintf(err, errlen, "deflate failed for a %d x %d image", w, h);
    return -1;
  }
  free(raw);
  n += chunk(buf + n, "IDAT", zlen);
  n += chunk(buf + n, "IEND", 0);
  *out = buf;
  *outlen = n;
  return 0;
}

int png_write(const char *path, const unsigned char *px, int w, int h,
              int channels, char *err, size_t errlen) {
  unsigned char *buf;
  size_t len;
  int r;
  if (png_encode(px, w, h, channels, &buf, &len, err, errlen)) {
    char why[256];
    snprintf(why, sizeof why, "%s", err);
    snprintf(err, errlen, "%s: %s", path, why);
    return -1;
  }
  r = ofile_put(path, buf, len, err, errlen);
  free(buf);
  return r;
}
