/*
** out_csv.c - diagnostics CSV.  Integral columns (the first, "step") are
** printed as integers, the rest with 17 significant digits so a table
** read back reproduces the doubles exactly.
*/
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ofile.h"
#include "out_csv.h"

int out_csv_open(csvout *c, const char *path, const char *preamble,
                 const char *const *cols, int ncol, char *err,
                 size_t errlen) {
  char part[1040];
  int k;
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  snprintf(part, sizeof part, "%s.part", path);
  c->f = ofile_fcreate(part, "w"); /* never through a link */
  if (!c->f) {
    snprintf(err, errlen, "%s: cannot create (%s)", part, strerror(errno));
    return -1;
  }
  c->ncol = ncol;
  if (preamble) fputs(preamble, c->f);
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
    c->bad = 1;
    snprintf(err, errlen, "%s.part: write failed (%s)", c->path,
             strerror(errno));
    return -1;
  }
  return 0;
}

/* whether the header row of file (its first line that is not a "# "
** comment) names cols; -1 when the file cannot be read (the caller's
** own checks then say why), else 1 or 0 with the file's column count */
static int header_is(const char *file, const char *const *cols, int ncol,
                     int *have) {
  FILE *f = fopen(file, "r");
  int ch, k = 0, same = 1, at_start = 1, comment = 0;
  const char *want = ncol > 0 ? cols[0] : "";
  if (!f) return -1;
  *have = 1;
  while ((ch = fgetc(f)) != EOF) {
    if (at_start) comment = ch == '#';
    at_start = ch == '\n';
    if (comment) continue;
    if (ch == '\n') break;
    if (ch == ',') { /* the next name */
      (*have)++;
      if (*want || ++k >= ncol) same = 0;
      else want = cols[k];
    } else if (same && *want == ch) want++;
    else same = 0;
  }
  fclose(f);
  return same && !*want && k == ncol - 1;
}

int out_csv_resume(csvout *c, const char *path, long length,
                   const char *const *cols, int ncol, char *err,
                   size_t errlen) {
  char part[1040];
  const char *table;
  struct stat st;
  int fd, have = 0;
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  snprintf(part, sizeof part, "%s.part", path);
  c->ncol = ncol;
  /* before anything is renamed or cut */
  table = lstat(part, &st) == 0 ? part : path;
  if (header_is(table, cols, ncol, &have) == 0) {
    snprintf(err, errlen, "%s: the diagnostics table has other columns "
             "than this version writes (%d in its header, %d written): it "
             "was made by another version, and rows appended to it would "
             "not match its header; continue the run with the version that "
             "made it, or run it again", table, have, ncol);
    return -1;
  }
  if (lstat(part, &st) != 0) {
    if (errno != ENOENT || lstat(path, &st) != 0 || rename(path, part) != 0) {
      snprintf(err, errlen, "%s: cannot continue the diagnostics table: "
               "neither it nor %s can be used (%s)", path, part,
               strerror(errno));
      return -1;
    }
  }
  /* under --sandbox never through a link (ofile.h) */
  fd = open(part, O_WRONLY | O_APPEND | O_CLOEXEC | ofile_nofollow());
  if (fd < 0 || fstat(fd, &st) != 0) {
    snprintf(err, errlen, "%s: cannot continue (%s)", part, strerror(errno));
    if (fd >= 0) close(fd);
    return -1;
  }
  if (st.st_size < length) {
    snprintf(err, errlen, "%s: the diagnostics table is shorter (%lld bytes) "
             "than at the checkpoint (%ld bytes)", part,
             (long long)st.st_size, length);
    close(fd);
    return -1;
  }
  /* where "a" puts the position before the first write is the C
  ** library's choice: seek, so out_csv_sync's ftell is the length */
  if (ftruncate(fd, length) != 0 || !(c->f = fdopen(fd, "a")) ||
      fseek(c->f, 0, SEEK_END) != 0) {
    snprintf(err, errlen, "%s: cannot continue (%s)", part, strerror(errno));
    if (c->f) fclose(c->f);
    else close(fd);
    c->f = NULL;
    return -1;
  }
  return 0;
}

long out_csv_sync(csvout *c, char *err, size_t errlen) {
  long n;
  if (!c->f) return -1;
  if (fflush(c->f) || fsync(fileno(c->f)) || (n = ftell(c->f)) < 0) {
    c->bad = 1;
    snprintf(err, errlen, "%s.part: cannot sync (%s)", c->path, strerror(errno));
    return -2;
  }
  return n;
}

int out_csv_close(csvout *c, char *err, size_t errlen) {
  char part[1040];
  int bad;
  if (!c->f) return 0;
  snprintf(part, sizeof part, "%s.part", c->path);
  bad = fclose(c->f) != 0;
  c->f = NULL;
  if (c->bad && !bad) {
    snprintf(err, errlen, "%s: a write failed, so the table stays %s and "
             "may end in a torn row", c->path, part);
    return -1;
  }
  if (bad || rename(part, c->path)) {
    snprintf(err, errlen, "%s: cannot finish (%s)", c->path, strerror(errno));
    return -1;
  }
  return 0;
}

void out_csv_leave(csvout *c) {
  if (c->f) fclose(c->f);
  c->f = NULL;
}
