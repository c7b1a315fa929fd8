/*
** ofile.c - new output files, and links under --sandbox (ofile.h).
*/
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>
#include "ofile.h"

static int strict;  /* the process's: mvmpm run makes one Lua state */

void ofile_strict(void) {
  strict = 1;
}

int ofile_nofollow(void) {
  return strict ? O_NOFOLLOW : 0;
}

int ofile_create(const char *path) {
  if (!strict)
    return open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  /* unlink removes a link itself, not what it points to */
  if (unlink(path) != 0 && errno != ENOENT) return -1;
  return open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
              0666);
}

FILE *ofile_fcreate(const char *path, const char *mode) {
  int fd = ofile_create(path), e;
  FILE *f;
  if (fd < 0) return NULL;
  if (!(f = fdopen(fd, mode))) {
    e = errno;
    close(fd);
    unlink(path);
    errno = e;
  }
  return f;
}

int ofile_put(const char *path, const void *buf, size_t len, char *err,
              size_t errlen) {
  char tmp[4096];
  FILE *f;
  int ok;
  if ((size_t)snprintf(tmp, sizeof tmp, "%s.tmp", path) >= sizeof tmp) {
    snprintf(err, errlen, "%s: path too long", path);
    return -1;
  }
  f = ofile_fcreate(tmp, "wb"); /* never through a link when strict */
  if (!f) {
    snprintf(err, errlen, "%s: cannot create the file (%s)", path,
             strerror(errno));
    return -1;
  }
  ok = fwrite(buf, 1, len, f) == len;
  ok = fflush(f) == 0 && ok;
  if (!ok) snprintf(err, errlen, "%s: cannot write (%s)", path, strerror(errno));
  if (fclose(f) != 0 && ok) {
    snprintf(err, errlen, "%s: cannot write (%s)", path, strerror(errno));
    ok = 0;
  }
  if (ok && rename(tmp, path) != 0) {
    snprintf(err, errlen, "%s: cannot rename the finished file into place (%s)",
             path, strerror(errno));
    ok = 0;
  }
  if (!ok) unlink(tmp);
  return ok ? 0 : -1;
}
