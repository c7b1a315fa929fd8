/*
** h5sum.c - the checksum block of mvmpm's HDF5 files (h5sum.h).
*/
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "h5sum.h"
#include "hash.h"

#define LEAD "mvmpm checksum 1: blake2b-256 of the "
#define SUMLEN 32

static const unsigned char hdf5sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n',
                                         0x1a, '\n'};

/* the block a file with these bytes after it must start with */
static void block(unsigned char *blk, const unsigned char *rest, size_t n) {
  unsigned char sum[SUMLEN];
  char *p = (char *)blk;
  int k, len;
  hash_blake2b(rest, n, sum, SUMLEN);
  memset(blk, 0, H5SUM_BLOCK);
  len = snprintf(p, H5SUM_BLOCK, LEAD "%020llu bytes after the first %d:\n",
                 (unsigned long long)n, H5SUM_BLOCK);
  for (k = 0; k < SUMLEN; k++) len += sprintf(p + len, "%02x", sum[k]);
  p[len] = '\n';
}

void h5sum_seal(unsigned char *img, size_t size) {
  if (size >= H5SUM_BLOCK)
    block(img, img + H5SUM_BLOCK, size - H5SUM_BLOCK);
}

/* the whole file; 0 or -1 with errno.  O_NONBLOCK: a FIFO under a
** checkpoint's name would block in open() (with no writer) before fstat
** could refuse it; on a regular file it changes nothing */
static int slurp(const char *path, void **img, size_t *size) {
  struct stat st;
  unsigned char *b;
  size_t n = 0;
  int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK), en;
  if (fd < 0) return -1;
  if (fstat(fd, &st) != 0) goto bad;
  if (!S_ISREG(st.st_mode)) { errno = EINVAL; goto bad; }
  if ((uintmax_t)st.st_size > SIZE_MAX - 1) { errno = EFBIG; goto bad; }
  if (!(b = malloc((size_t)st.st_size + 1))) goto bad;
  while (n < (size_t)st.st_size) {
    ssize_t k = read(fd, b + n, (size_t)st.st_size - n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) {
      en = k ? errno : EIO; /* shrank while read */
      free(b);
      errno = en;
      goto bad;
    }
    n += (size_t)k;
  }
  close(fd);
  *img = b;
  *size = n;
  return 0;
bad:
  en = errno;
  close(fd);
  errno = en;
  return -1;
}

int h5sum_load(const char *path, void **img, size_t *size, char *err,
               size_t errlen) {
  unsigned char want[H5SUM_BLOCK], *b;
  size_t n, lead = strlen(LEAD);
  *img = NULL;
  *size = 0;
  if (slurp(path, (void **)&b, &n)) {
    snprintf(err, errlen, "%s: cannot read file (%s)", path,
             errno == EINVAL ? "not a regular file" : strerror(errno));
    return -1;
  }
  if (n >= sizeof hdf5sig && memcmp(b, hdf5sig, sizeof hdf5sig) == 0) {
    *img = b;
    *size = n;
    return H5SUM_NONE;
  }
  if (n >= lead && memcmp(b, LEAD, lead) == 0) {
    if (n >= H5SUM_BLOCK) {
      block(want, b + H5SUM_BLOCK, n - H5SUM_BLOCK);
      if (memcmp(want, b, H5SUM_BLOCK) == 0) {
        *img = b;
        *size = n;
        return H5SUM_OK;
      }
    }
    /* the length first: it tells a truncated file */
    if (n < H5SUM_BLOCK || memcmp(want, b, lead + 20) != 0) {
      unsigned long long rec = 0;
      size_t k;
      for (k = lead; k < lead + 20 && k < n && b[k] >= '0' && b[k] <= '9'; k++)
        rec = rec * 10 + (unsigned long long)(b[k] - '0');
      snprintf(err, errlen, "%s: cannot open file: checksum mismatch "
               "(damaged or edited; %zu bytes follow its %d-byte header, "
               "which records %llu: truncated or extended)", path,
               n > H5SUM_BLOCK ? n - H5SUM_BLOCK : 0, H5SUM_BLOCK, rec);
    } else
      snprintf(err, errlen, "%s: checksum mismatch (damaged or edited; the "
               "BLAKE2b-256 of its contents is not the one its header "
               "records)", path);
  } else if (n >= H5SUM_BLOCK + sizeof hdf5sig &&
             memcmp(b + H5SUM_BLOCK, hdf5sig, sizeof hdf5sig) == 0)
    snprintf(err, errlen, "%s: checksum mismatch (damaged or edited; its "
             "%d-byte checksum header is unreadable)", path, H5SUM_BLOCK);
  else
    snprintf(err, errlen, "%s: cannot open file (not HDF5, or damaged)", path);
  free(b);
  return -1;
}
