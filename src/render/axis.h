/*
** axis.h - ranges, tick positions and tick labels for axes and colour
** bars.
*/
#ifndef mvmpm_axis_h
#define mvmpm_axis_h

#include <stddef.h>

#define AXIS_MAXTICKS 32
/* the smallest step of 1-2-5 ticks: below it (near the denormals) an
** axis gets its two ends as ticks */
#define AXIS_TINY 1e-300

/* ticks at multiples of 1, 2 or 5 times a power of ten inside [lo, hi],
** about n of them (at least 2 when the range allows); returns the count
** and the step in *step.  Any finite lo < hi works, a range wider than
** the largest double or narrower than AXIS_TINY too (the latter gets
** lo and hi with *step 0); otherwise the ticks are lo alone, if finite */
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
** lo == hi; log: in powers of ten (lo, hi > 0).  Finite input gives a
** finite range with lo < hi (on log axes inside the positive doubles) */
void axis_pad(double *lo, double *hi, int log);
/* a range around the single finite value lo == hi: +-10 %, or +-1 for
** zero, clamped to the finite doubles */
void axis_widen(double *lo, double *hi);
/* the position of v in [lo, hi] as a fraction (0 at lo, 1 at hi), with
** no overflow when hi - lo exceeds the largest double */
double axis_frac(double v, double lo, double hi);

#endif
