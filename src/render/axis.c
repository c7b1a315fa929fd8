/*
** axis.c - nice numbers for ticks.
*/
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "axis.h"

/* 1, 2 or 5 times a power of ten near the range over n - 1 intervals,
** or 0 when that would be below AXIS_TINY (ticks so close could not be
** told apart, and their powers of ten are no longer exact).  The range
** is taken in halves: hi - lo can exceed the largest double. */
static double nice_step(double lo, double hi, int n) {
  double raw = (hi / 2 - lo / 2) / (n > 1 ? n - 1 : 1) * 2, p, f, s;
  if (!(raw >= AXIS_TINY)) return 0;
  if (raw > DBL_MAX) raw = DBL_MAX;
  p = pow(10, floor(log10(raw)));
  f = raw / p;
  s = (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
  return s <= DBL_MAX ? s : 1e308;
}

/* the multiples of s in [lo, hi] are k0 * s .. k1 * s; 0 if their
** numbers are too large for a long (a step far below the values) */
static int multiples(double lo, double hi, double s, long *k0, long *k1) {
  double a = ceil(lo / s - 1e-9), b = floor(hi / s + 1e-9);
  if (!(fabs(a) < 0x1p62 && fabs(b) < 0x1p62)) return 0;
  *k0 = (long)a;
  *k1 = (long)b;
  return 1;
}

int axis_ticks(double lo, double hi, int n, double *t, double *step) {
  double s, v;
  long k, k0, k1;
  int m = 0;
  *step = 0;
  if (!(hi > lo) || !isfinite(lo) || !isfinite(hi)) {
    if (isfinite(lo)) t[m++] = lo;
    return m;
  }
  s = nice_step(lo, hi, n);
  /* no 1-2-5 steps that doubles can hold (a step of a few ulps of the
  ** values gives ticks that round together): the two ends */
  if (s < 64 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)) ||
      !multiples(lo, hi, s, &k0, &k1)) {
    t[m++] = lo;
    t[m++] = hi;
    return m;
  }
  /* too few inside: halve the step (at most twice) */
  while (k1 - k0 < 1 && s > hi / 8 - lo / 8 && s / 2 >= AXIS_TINY &&
         multiples(lo, hi, s / 2, &k0, &k1))
    s = s / 2;
  for (k = k0; k <= k1 && m < AXIS_MAXTICKS; k++) {
    v = k * s;
    if (fabs(v) < 1e-9 * s) v = 0; /* no "-0" or 1e-17 */
    t[m++] = v;
  }
  *step = s;
  return m;
}

int axis_logticks(double lo, double hi, double *t, double *minor,
                  int *nminor) {
  double a = log10(lo), b = log10(hi);
  long e, e0, e1, every;
  int m = 0, j;
  *nminor = 0;
  if (!(lo > 0) || !(hi > lo) || !isfinite(hi)) {
    double step;
    return axis_ticks(lo, hi, 5, t, &step);
  }
  /* lo and hi are positive doubles: a and b lie in [-324, 309] */
  e0 = (long)ceil(a - 1e-9);
  e1 = (long)floor(b + 1e-9);
  if (e1 - e0 < 1) { /* under two powers of ten inside: 1-2-5 ticks */
    double step;
    return axis_ticks(lo, hi, 5, t, &step);
  }
  every = (e1 - e0) / 8 + 1;
  for (e = e0; e <= e1 && m < AXIS_MAXTICKS; e++)
    if ((e - e0) % every == 0) t[m++] = pow(10, (double)e);
  if (every == 1)
    for (e = e0 - 1; e <= e1; e++)
      for (j = 2; j <= 9 && *nminor < 4 * AXIS_MAXTICKS; j++) {
        double v = j * pow(10, (double)e);
        if (v >= lo && v <= hi) minor[(*nminor)++] = v;
      }
  return m;
}

void axis_label(double v, double step, char *buf, size_t n) {
  double a = fabs(v);
  if (v == 0) { snprintf(buf, n, "0"); return; }
  if (!isfinite(v)) { snprintf(buf, n, "%g", v); return; }
  if (!(step > 0)) step = 0;
  else if (step > DBL_MAX) step = DBL_MAX; /* as few decimals as can be */
  if (a >= 1e5 || a < 1e-3) {
    /* exponent form with the digits the step needs */
    int e = (int)floor(log10(a)), d = 0;
    char tmp[64], *p;
    if (step > 0) d = e - (int)floor(log10(step) + 1e-9);
    if (d < 0) d = 0;
    if (d > 6) d = 6;
    snprintf(tmp, sizeof tmp, "%.*e", d, v);
    /* 1.50e-05 -> 1.5e-5: drop trailing zeros, the '+' and leading zeros */
    p = strchr(tmp, 'e');
    if (p) {
      char mant[64], *q;
      int ex = 0;
      sscanf(p + 1, "%d", &ex);
      *p = 0;
      snprintf(mant, sizeof mant, "%s", tmp);
      if (strchr(mant, '.')) {
        q = mant + strlen(mant) - 1;
        while (*q == '0') *q-- = 0;
        if (*q == '.') *q = 0;
      }
      snprintf(buf, n, "%se%d", mant, ex);
    } else snprintf(buf, n, "%s", tmp);
    return;
  }
  {
    int d = step > 0 ? (int)ceil(-log10(step) - 1e-9) : 3;
    if (step > 0) {
      /* a step of 0.25 needs two decimals, not one */
      double r = step * pow(10, d);
      if (fabs(r - floor(r + 0.5)) > 1e-6) d++;
    }
    if (d < 0) d = 0;
    if (d > 8) d = 8;
    snprintf(buf, n, "%.*f", d, v);
  }
}

/* v within [-DBL_MAX, DBL_MAX]: a range with room must stay finite */
static double finite(double v) {
  return v > DBL_MAX ? DBL_MAX : v < -DBL_MAX ? -DBL_MAX : v;
}

void axis_widen(double *lo, double *hi) {
  double m = 0.1 * fabs(*lo);
  if (!(m >= AXIS_TINY)) m = *lo != 0 ? AXIS_TINY : 1;
  *lo = finite(*lo - m);
  *hi = finite(*hi + m);
}

double axis_frac(double v, double lo, double hi) {
  /* halves only when needed: they lose the last bit of a denormal */
  if (isfinite(hi - lo)) return (v - lo) / (hi - lo);
  return (v / 2 - lo / 2) / (hi / 2 - lo / 2);
}

void axis_pad(double *lo, double *hi, int log) {
  if (log) {
    double a = log10(*lo), b = log10(*hi);
    if (!(b > a)) { a -= 0.5; b += 0.5; }
    else { double m = 0.04 * (b - a); a -= m; b += m; }
    /* inside the positive doubles, denormals included */
    *lo = fmax(pow(10, a), DBL_TRUE_MIN);
    *hi = fmin(pow(10, b), DBL_MAX);
    return;
  }
  if (!(*hi > *lo)) {
    axis_widen(lo, hi);
    return;
  }
  {
    double m = 0.04 * (*hi / 2 - *lo / 2) * 2;
    *lo = finite(*lo - m);
    *hi = finite(*hi + m);
  }
}
