/*
** out_csv.c - diagnostics CSV.  Integral columns (the first, "step") are
** printed as integers, the rest with 17 significant digits so a table
** read back reproduces the doubles exactly.
*/
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "out_csv.h"

int out_csv_open(csvout *c, const char *path, const char *const *cols,
                 int ncol, char *err, size_t errlen) {
  char part[1040];
  int k;
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  snprintf(part, sizeof part, "%s.part", path);
  c->f = fopen(part, "w");
  if (!c->f) {
    snprintf(err, errlen, "%s: cannot create (%s)", part, strerror(errno));
    return -1;
  }
  c->ncol = ncol;
  for (k = 0; k < ncol; k++) fprintf(c->f, "%s%s", k ? "," : "", cols[k]);
  fputc('\n', c->f);
  return 0;
}

int out_csv_row(csvout *c, const double *vals, char *err, size_t errlen) {
  int k;
  if (!c->f) return 0;
  fprintf(c->f, "%.0f", vals[0]);
  for (k = 1; k < c->ncol; k++) fprintf(c->f, ",%.17g", vals[k]);
  fputc('\n', c->f);
  if (fflush(c->f) || ferror(c->f)) {
    snprintf(err, errlen, "%s.part: write failed (%s)", c->path,
             strerror(errno));
    return -1;
  }
  return 0;
}

int out_csv_close(csvout *c, char *err, size_t errlen) {
  char part[1040];
  int bad;
  if (!c->f) return 0;
  snprintf(part, sizeof part, "%s.part", c->path);
  bad = fclose(c->f) != 0;
  c->f = NULL;
  if (bad || rename(part, c->path)) {
    snprintf(err, errlen, "%s: cannot finish (%s)", c->path, strerror(errno));
    return -1;
  }
  return 0;
}
