/*
** ofile.c - new output files, and links under --sandbox (ofile.h).
*/
#include <errno.h>
#include <fcntl.h>
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
