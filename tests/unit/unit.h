/*
** unit.h - a tiny test harness: each test program counts its checks and
** closes with "NAME: N passed, M failed"; the exit status says whether
** all passed.
*/
#ifndef mvmpm_unit_h
#define mvmpm_unit_h

#include <math.h>
#include <stdio.h>

static int unit_pass, unit_fail;

#define UNIT_CHECK(cond, ...)                                        \
  do {                                                               \
    if (cond) unit_pass++;                                           \
    else {                                                           \
      unit_fail++;                                                   \
      printf("FAIL %s:%d: ", __FILE__, __LINE__);                    \
      printf(__VA_ARGS__);                                           \
      printf("\n");                                                  \
    }                                                                \
  } while (0)

/* a measured value beside its reference, printed either way */
#define UNIT_NEAR(a, b, tol, name)                                   \
  do {                                                               \
    double ua_ = (a), ub_ = (b), ut_ = (tol);                        \
    int ok_ = fabs(ua_ - ub_) <= ut_;                                \
    printf("%s %-44s measured %-13.6g reference %-13.6g tol %.2g\n", \
           ok_ ? "ok  " : "FAIL", name, ua_, ub_, ut_);              \
    if (ok_) unit_pass++;                                            \
    else unit_fail++;                                                \
  } while (0)

#define UNIT_END(name)                                               \
  do {                                                               \
    printf("%s: %d passed, %d failed\n", name, unit_pass, unit_fail); \
    return unit_fail != 0;                                           \
  } while (0)

#endif
