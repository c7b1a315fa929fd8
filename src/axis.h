/*
** axis.h - ranges, tick positions and tick labels for axes and colour
** bars.
*/
#ifndef mvmpm_axis_h
#define mvmpm_axis_h

#include <stddef.h>

#define AXIS_MAXTICKS 32

/* ticks at multiples of 1, 2 or 5 times a power of ten inside [lo, hi],
** about n of them (at least 2 when the range allows); returns the count
** and the step in *step */
int axis_ticks(double lo, double hi, int n, double *t, double *step);
/* log10 axis over [lo, hi] (both > 0): majors at powers of ten (every
** k-th decade when there are many), else 1-2-5 ticks; minors (2..9 x
** each decade) when decades are few.  Returns the number of majors;
** *nminor the minors */
int axis_logticks(double lo, double hi, double *t, double *minor,
                  int *nminor);
/* a short label for v on an axis whose ticks are step apart: fixed
** point with the decimals the step needs, or exponent form (1.5e-05 ->
** "1.5e-5") for very large or small magnitudes; "0" for zero */
void axis_label(double v, double step, char *buf, size_t n);
/* a range that shows [lo, hi] with a little room, and something when
** lo == hi; log: in powers of ten (lo, hi > 0) */
void axis_pad(double *lo, double *hi, int log);

#endif
