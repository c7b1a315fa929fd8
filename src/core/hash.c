/*
** hash.c - BLAKE2b, as in RFC 7693 (section 3 and appendix C), without
** a key and in one call: the data is always whole in memory here.
*/
#include <stdint.h>
#include <string.h>
#include "hash.h"

static const uint64_t iv[8] = {
  0x6a09e667f3bcc908u, 0xbb67ae8584caa73bu, 0x3c6ef372fe94f82bu,
  0xa54ff53a5f1d36f1u, 0x510e527fade682d1u, 0x9b05688c2b3e6c1fu,
  0x1f83d9abfb41bd6bu, 0x5be0cd19137e2179u};

static const unsigned char sigma[12][16] = {
  {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
  {14, 10, 4, 8, 9, 15, 13, 6, 1, 12, 0, 2, 11, 7, 5, 3},
  {11, 8, 12, 0, 5, 2, 15, 13, 10, 14, 3, 6, 7, 1, 9, 4},
  {7, 9, 3, 1, 13, 12, 11, 14, 2, 6, 5, 10, 4, 0, 15, 8},
  {9, 0, 5, 7, 2, 4, 10, 15, 14, 1, 11, 12, 6, 8, 3, 13},
  {2, 12, 6, 10, 0, 11, 8, 3, 4, 13, 7, 5, 15, 14, 1, 9},
  {12, 5, 1, 15, 14, 13, 4, 10, 0, 7, 6, 3, 9, 2, 8, 11},
  {13, 11, 7, 14, 12, 1, 3, 9, 5, 0, 15, 4, 8, 6, 2, 10},
  {6, 15, 14, 9, 11, 3, 0, 8, 12, 2, 13, 7, 1, 4, 10, 5},
  {10, 2, 8, 4, 7, 6, 1, 5, 15, 11, 9, 14, 3, 12, 13, 0},
  {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
  {14, 10, 4, 8, 9, 15, 13, 6, 1, 12, 0, 2, 11, 7, 5, 3}};

static uint64_t rotr(uint64_t x, int k) { return (x >> k) | (x << (64 - k)); }

/* little-endian whatever the machine */
static uint64_t load64(const unsigned char *p) {
  uint64_t x = 0;
  int k;
  for (k = 7; k >= 0; k--) x = (x << 8) | p[k];
  return x;
}

#define G(a, b, c, d, x, y)        \
  do {                             \
    a = a + b + (x);               \
    d = rotr(d ^ a, 32);           \
    c = c + d;                     \
    b = rotr(b ^ c, 24);           \
    a = a + b + (y);               \
    d = rotr(d ^ a, 16);           \
    c = c + d;                     \
    b = rotr(b ^ c, 63);           \
  } while (0)

/* one 128-byte block; t: the bytes hashed so far, this block's included */
static void compress(uint64_t h[8], const unsigned char *block, uint64_t t,
                     int last) {
  uint64_t v[16], m[16];
  int k, r;
  for (k = 0; k < 16; k++) m[k] = load64(block + 8 * k);
  for (k = 0; k < 8; k++) v[k] = h[k], v[k + 8] = iv[k];
  v[12] ^= t; /* the high word of the counter stays 0 below 2^64 bytes */
  if (last) v[14] = ~v[14];
  for (r = 0; r < 12; r++) {
    const unsigned char *s = sigma[r];
    G(v[0], v[4], v[8], v[12], m[s[0]], m[s[1]]);
    G(v[1], v[5], v[9], v[13], m[s[2]], m[s[3]]);
    G(v[2], v[6], v[10], v[14], m[s[4]], m[s[5]]);
    G(v[3], v[7], v[11], v[15], m[s[6]], m[s[7]]);
    G(v[0], v[5], v[10], v[15], m[s[8]], m[s[9]]);
    G(v[1], v[6], v[11], v[12], m[s[10]], m[s[11]]);
    G(v[2], v[7], v[8], v[13], m[s[12]], m[s[13]]);
    G(v[3], v[4], v[9], v[14], m[s[14]], m[s[15]]);
  }
  for (k = 0; k < 8; k++) h[k] ^= v[k] ^ v[k + 8];
}

void hash_blake2b(const void *p, size_t n, unsigned char *out,
                  size_t outlen) {
  const unsigned char *in = p;
  unsigned char last[128];
  uint64_t h[8], t = 0;
  size_t k;
  if (outlen < 1) return;
  if (outlen > HASH_MAXLEN) outlen = HASH_MAXLEN;
  memcpy(h, iv, sizeof h);
  h[0] ^= 0x01010000u ^ (uint64_t)outlen; /* fanout 1, depth 1, no key */
  /* every full block but the final one (which may be full too) */
  while (n > 128) {
    t += 128;
    compress(h, in, t, 0);
    in += 128;
    n -= 128;
  }
  memset(last, 0, sizeof last);
  if (n) memcpy(last, in, n);
  compress(h, last, t + n, 1);
  for (k = 0; k < outlen; k++) out[k] = (unsigned char)(h[k / 8] >> (8 * (k % 8)));
}
