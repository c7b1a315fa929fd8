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
  int bad;        /* a write failed: the file may end in a torn row */
} csvout;

/* preamble (may be NULL): lines of "# " comments written before the
** header row (the run's provenance) */
int out_csv_open(csvout *c, const char *path, const char *preamble,
                 const char *const *cols, int ncol, char *err,
                 size_t errlen);
/* continue a table a checkpoint recorded at `length` bytes: the rows a
** killed run wrote after it are cut off, and rows are appended.  The
** table is "<path>.part", or path itself when the run had finished
** (renamed back to .part).  Its header row must name cols (the table
** of another version has other columns: appending to it would mix
** them).  0, or -1 with err (missing, shorter, other columns), the files
** left as they were. */
int out_csv_resume(csvout *c, const char *path, long length,
                   const char *const *cols, int ncol, char *err,
                   size_t errlen);
int out_csv_row(csvout *c, const double *vals, char *err, size_t errlen);
/* flush to disk (fsync); the length in bytes, -1 when no table is open,
** -2 with err when it fails */
long out_csv_sync(csvout *c, char *err, size_t errlen);
/* flush and rename into place; 0 or -1.  After a failed write the file
** stays "<path>.part" (it may end in a torn row) and -1 says so. */
int out_csv_close(csvout *c, char *err, size_t errlen);
/* close, leaving the table "<path>.part": the run is not finished */
void out_csv_leave(csvout *c);

#endif
