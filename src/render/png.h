/*
** png.h - writing an image as a PNG file.
** Colour type 2 (RGB) or 6 (RGBA), 8 bits a sample, no interlace; every
** row is filtered with "none" (flat-coloured pictures compress well
** without prediction) and the rows are deflated with zlib in one IDAT
** chunk.  The file is written to "<path>.tmp" and renamed, so a failed
** or interrupted write never leaves a half-written file under path.
*/
#ifndef mvmpm_png_h
#define mvmpm_png_h

#include <stddef.h>

/* largest width or height accepted (keeps w * h * 4 far from overflow) */
#define PNG_MAXDIM 16384

/* px: h rows of w pixels, top row first, channels (3 or 4) bytes each.
** 0 on success; -1 with a message naming path and the reason in err. */
int png_write(const char *path, const unsigned char *px, int w, int h,
              int channels, char *err, size_t errlen);

/* the same bytes in memory: *out is malloc'ed, *outlen its size */
int png_encode(const unsigned char *px, int w, int h, int channels,
               unsigned char **out, size_t *outlen, char *err,
               size_t errlen);

#endif
