/*
** out_csv.h - the diagnostics table of a run: a header row, then one row
** per recorded step.  Written under "<path>.part" while the run goes and
** renamed to path when it closes, so a file under the final name is
** always complete; rows are flushed as they come so a run can be watched.
*/
#ifndef mvmpm_out_csv_h
#define mvmpm_out_csv_h

#include <stddef.h>
#include <stdio.h>

typedef struct csvout {
  FILE *f;
  char path[1024];
  int ncol;
} csvout;

int out_csv_open(csvout *c, const char *path, const char *const *cols,
                 int ncol, char *err, size_t errlen);
int out_csv_row(csvout *c, const double *vals, char *err, size_t errlen);
/* flush and rename into place; 0 or -1 */
int out_csv_close(csvout *c, char *err, size_t errlen);

#endif
