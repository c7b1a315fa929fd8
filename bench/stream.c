/*
** stream.c - memory bandwidth of one core, for reading the bench figures
** against: the copy b = a and the triad a = b + s c over arrays far
** larger than the caches, best of several passes, counting the bytes
** read and written as the STREAM benchmark does (16 and 24 per element;
** the write-allocate read the cache may add is not counted).
** Built and run by bench/run.sh.
*/
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define N (1 << 24) /* 16 M doubles, 128 MB per array */
#define PASSES 5

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(void) {
  double *a = malloc(N * sizeof *a), *b = malloc(N * sizeof *b);
  double *c = malloc(N * sizeof *c), best_copy = 1e30, best_triad = 1e30, sum = 0;
  size_t i;
  int p;
  if (!a || !b || !c) return 1;
  for (i = 0; i < N; i++) { a[i] = 1.0; b[i] = 2.0; c[i] = 0.5; }
  for (p = 0; p < PASSES; p++) {
    double t = now();
    for (i = 0; i < N; i++) b[i] = a[i];
    t = now() - t;
    if (t < best_copy) best_copy = t;
    t = now();
    for (i = 0; i < N; i++) a[i] = b[i] + 3.0 * c[i];
    t = now() - t;
    if (t < best_triad) best_triad = t;
  }
  for (i = 0; i < N; i += 4096) sum += a[i] + b[i]; /* keep the loops */
  printf("%-9s %-46s %10.3f %-10s %s\n", "machine", "memory bandwidth, copy (1 core)",
         16.0 * N / best_copy / 1e9, "GB/s", sum > 0 ? "best of 5, 128 MB arrays" : "");
  printf("%-9s %-46s %10.3f %-10s %s\n", "machine", "memory bandwidth, triad (1 core)",
         24.0 * N / best_triad / 1e9, "GB/s", "");
  free(a); free(b); free(c);
  return 0;
}
