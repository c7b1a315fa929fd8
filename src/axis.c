/*
** axis.c - nice numbers for ticks.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "axis.h"

static double nice_step(double range, int n) {
  double raw = range / (n > 1 ? n - 1 : 1), p = pow(10, floor(log10(raw)));
  double f = raw / p;
  return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
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
  s = nice_step(hi - lo, n);
  k0 = (long)ceil(lo / s - 1e-9);
  k1 = (long)floor(hi / s + 1e-9);
  /* too few inside: halve the step (at most twice) */
  while (k1 - k0 < 1 && s > (hi - lo) / 8) {
    s = s / 2;
    k0 = (long)ceil(lo / s - 1e-9);
    k1 = (long)floor(hi / s + 1e-9);
  }
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
  long e, e0 = (long)ceil(a - 1e-9), e1 = (long)floor(b + 1e-9), every;
  int m = 0, j;
  *nminor = 0;
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

void axis_pad(double *lo, double *hi, int log) {
  if (log) {
    double a = log10(*lo), b = log10(*hi);
    if (!(b > a)) { a -= 0.5; b += 0.5; }
    else { double m = 0.04 * (b - a); a -= m; b += m; }
    *lo = pow(10, a);
    *hi = pow(10, b);
    return;
  }
  if (!(*hi > *lo)) {
    double m = *lo != 0 ? 0.1 * fabs(*lo) : 1;
    *lo -= m;
    *hi += m;
    return;
  }
  {
    double m = 0.04 * (*hi - *lo);
    *lo -= m;
    *hi += m;
  }
}
