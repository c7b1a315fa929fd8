/*
** ofile.h - creating the files the engine writes.  Every output is
** written under a temp name and renamed into place; rename replaces a
** link at the final name and never writes through it.  The temp file is
** made here.  Normally whatever is at its name is truncated and written,
** links followed (the fault tests point a temp name at /dev/full).
** Strict, once ofile_strict was called (mvmpm run --sandbox), the
** process never writes through a link: what stands at the temp name is
** removed first, never followed, and O_EXCL | O_NOFOLLOW turn a link put
** there in between into an error.  Strict cannot be turned off.
*/
#ifndef mvmpm_ofile_h
#define mvmpm_ofile_h

#include <stdio.h>

void ofile_strict(void);
/* O_NOFOLLOW when strict, else 0: for opening an existing output */
int ofile_nofollow(void);
/* a new, empty file at path open for writing: the descriptor, or -1 with
** errno set */
int ofile_create(const char *path);
/* the same as a stdio stream (mode "w" or "wb"), or NULL with errno */
FILE *ofile_fcreate(const char *path, const char *mode);

/* len bytes to path, whole or not at all: written to path.tmp (made by
** ofile_create), flushed and renamed into place; the temp file removed
** on a failure.  0, or -1 with a message naming path in err */
int ofile_put(const char *path, const void *buf, size_t len, char *err,
              size_t errlen);

#endif
