/*
** out_h5.c - particle snapshots in HDF5 (the layout is described in
** out_h5.h).  HDF5's own error printing is switched off for the length
** of each call, so the one message a user sees is ours: the file name,
** what failed, and why (the system's reason when there is one, else the
** innermost line of HDF5's error stack).
*/
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <hdf5.h>

#include "ofile.h"
#include "h5sum.h"
#include "out_h5.h"

#define FORMAT "mvmpm-snapshot-1"
#define SOURCE "scene_source" /* dataset holding the scene's text */
#define CHUNKROWS 65536
#define DEFLATE 4
#define MSGLEN 256 /* each part of a message: what failed, and why */

/* one write or read: where the message goes and what to release */
typedef struct h5s {
  const char *path; /* the name the user knows (never the temp name) */
  char *err;
  size_t errlen;
  int failed;       /* only the first failure is reported */
  hid_t file;
  unsigned flags;   /* the fields written: PF_OUTPUT or PF_RESTART */
  const char *format; /* the "format" attribute written */
  const h5prov *prov; /* provenance attributes written, or NULL */
  void *buf;        /* row-major staging for (n, ncomp) datasets */
  size_t bufsz;
  H5E_auto2_t efunc; /* HDF5's error printer, restored on the way out */
  void *edata;
} h5s;

/*
** {======================================================
** Errors
** =======================================================
*/

static herr_t innermost(unsigned k, const H5E_error2_t *e, void *ud) {
  char *why = ud;
  if (k == 0 && e->desc && e->desc[0]) snprintf(why, MSGLEN, "%s", e->desc);
  return 0;
}

/*
** Called right after the failing call, so errno and HDF5's error stack
** still describe it (every HDF5 API call clears the stack on entry).
** errno is trusted only because each step clears it before starting.
*/
static int fail(h5s *S, const char *fmt, ...) {
  int en = errno;
  char what[MSGLEN], why[MSGLEN] = "";
  va_list ap;
  if (S->failed) return -1;
  S->failed = 1;
  if (en) snprintf(why, sizeof why, "%s", strerror(en));
  else H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, why);
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  if (S->err && S->errlen) {
    if (why[0]) snprintf(S->err, S->errlen, "%s: %s (%s)", S->path, what, why);
    else snprintf(S->err, S->errlen, "%s: %s", S->path, what);
  }
  return -1;
}

static void begin(h5s *S, const char *path, char *err, size_t errlen) {
  memset(S, 0, sizeof *S);
  S->path = path;
  S->err = err;
  S->errlen = errlen;
  S->file = -1;
  if (err && errlen) err[0] = '\0';
  H5Eget_auto2(H5E_DEFAULT, &S->efunc, &S->edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

static void end(h5s *S) {
  if (S->file >= 0) H5Fclose(S->file);
  S->file = -1;
  free(S->buf);
  S->buf = NULL;
  H5Eset_auto2(H5E_DEFAULT, S->efunc, S->edata);
}

/* make sure the staging buffer holds at least sz bytes */
static int room(h5s *S, size_t sz) {
  void *p;
  if (sz <= S->bufsz) return 0;
  p = realloc(S->buf, sz);
  if (!p) return -1;
  S->buf = p;
  S->bufsz = sz;
  return 0;
}

/* variable-length UTF-8 strings: h5py reads them back as str */
static hid_t strtype(void) {
  hid_t t = H5Tcopy(H5T_C_S1);
  if (t >= 0 && (H5Tset_size(t, H5T_VARIABLE) < 0 ||
                 H5Tset_cset(t, H5T_CSET_UTF8) < 0)) {
    H5Tclose(t);
    return -1;
  }
  return t;
}

/* }====================================================== */


/*
** {======================================================
** Writing
** =======================================================
*/

/* a scalar attribute; where names the object for the message */
static int putattr(h5s *S, hid_t obj, const char *where, const char *name,
                   hid_t ftype, hid_t mtype, const void *v) {
  hid_t sp, a = -1;
  int r = 0;
  errno = 0;
  sp = H5Screate(H5S_SCALAR);
  if (sp >= 0) a = H5Acreate2(obj, name, ftype, sp, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0 || H5Awrite(a, mtype, v) < 0)
    r = fail(S, "cannot write attribute '%s' of '%s'", name, where);
  if (a >= 0) H5Aclose(a);
  if (sp >= 0) H5Sclose(sp);
  return r;
}

static int putstr(h5s *S, hid_t obj, const char *where, const char *name,
                  const char *s) {
  hid_t t = strtype();
  int r;
  if (!s) s = "";
  if (t < 0) return fail(S, "cannot make a string type");
  r = putattr(S, obj, where, name, t, t, &s);
  H5Tclose(t);
  return r;
}

static int putmeta(h5s *S, const h5meta *meta) {
  int64_t step = meta->step;
  int dim = DIM;
  hid_t f = S->file;
  if (putstr(S, f, "/", "format", S->format) ||
      putattr(S, f, "/", "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
              &meta->time) ||
      putattr(S, f, "/", "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &step) ||
      putattr(S, f, "/", "cell", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
              &meta->cell) ||
      putattr(S, f, "/", "dim", H5T_STD_I32LE, H5T_NATIVE_INT, &dim) ||
      putstr(S, f, "/", "units", meta->units) ||
      putstr(S, f, "/", "scene", meta->scene))
    return -1;
  return 0;
}

/* provenance: what made the file */
static int putprov(h5s *S, const h5prov *p) {
  hid_t f = S->file;
  if (!p) return 0;
  if ((p->version && putstr(S, f, "/", "version", p->version)) ||
      (p->build && putstr(S, f, "/", "build", p->build)) ||
      (p->command && putstr(S, f, "/", "command", p->command)) ||
      (p->params && putstr(S, f, "/", "params", p->params)) ||
      (p->restarted && putstr(S, f, "/", "restarted_from", p->restarted)) ||
      (p->scheme && putstr(S, f, "/", "scheme", p->scheme)))
    return -1;
  return 0;
}

/*
** The scene's text goes in a scalar string dataset, not an attribute:
** attributes are limited to 64 KiB in the default object header, and a
** scene with an inline table of points can be larger than that.
*/
static int putsource(h5s *S, const char *src) {
  hid_t t, sp = -1, d = -1;
  int r = 0;
  if (!src) return 0;
  errno = 0;
  t = strtype();
  if (t >= 0) sp = H5Screate(H5S_SCALAR);
  if (sp >= 0)
    d = H5Dcreate2(S->file, SOURCE, t, sp, H5P_DEFAULT, H5P_DEFAULT,
                   H5P_DEFAULT);
  if (d < 0 || H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &src) < 0)
    r = fail(S, "cannot write dataset '%s'", SOURCE);
  if (d >= 0) H5Dclose(d);
  if (sp >= 0) H5Sclose(sp);
  if (t >= 0) H5Tclose(t);
  return r;
}

/*
** The data of field f as one row-major (n, ncomp) block.  A single
** component is already that, so it is written straight from the store.
*/
static const void *gather(h5s *S, const particles *ps, const pfield *f) {
  size_t i, n = ps->n, nc = (size_t)f->ncomp;
  int c;
  if (nc == 1) return *f->slot[0];
  for (c = 0; c < f->ncomp; c++) {
    if (f->type == PF_INT32) {
      const int32_t *a = *f->slot[c];
      int32_t *b = S->buf;
      for (i = 0; i < n; i++) b[i * nc + c] = a[i];
    } else {
      const double *a = *f->slot[c];
      double *b = S->buf;
      for (i = 0; i < n; i++) b[i * nc + c] = a[i];
    }
  }
  return S->buf;
}

/* "xx,xy,yx,yy", or nothing when the field has no component names */
static void compnames(const pfield *f, char *buf, size_t len) {
  size_t k = 0;
  int c;
  buf[0] = '\0';
  for (c = 0; c < f->ncomp && f->comp_names[c] && k < len; c++)
    k += (size_t)snprintf(buf + k, len - k, "%s%s", c ? "," : "",
                          f->comp_names[c]);
}

/*
** The dataset creation properties.  An empty dataset stays contiguous:
** a chunk must have at least one row, and there is nothing to compress.
*/
static hid_t dcpl(const pfield *f, size_t n) {
  hsize_t chunk[2];
  hid_t p = H5Pcreate(H5P_DATASET_CREATE);
  if (p < 0 || n == 0) return p;
  chunk[0] = n < CHUNKROWS ? n : CHUNKROWS;
  chunk[1] = (hsize_t)f->ncomp;
  if (H5Pset_chunk(p, f->ncomp == 1 ? 1 : 2, chunk) < 0 ||
      H5Pset_shuffle(p) < 0 || H5Pset_deflate(p, DEFLATE) < 0) {
    H5Pclose(p);
    return -1;
  }
  return p;
}

static int putfield(h5s *S, const particles *ps, const pfield *f) {
  hsize_t dims[2];
  int isint = f->type == PF_INT32;
  hid_t sp = -1, pl = -1, d = -1;
  char names[PF_MAXCOMP * 32];
  int r = -1;
  errno = 0;
  dims[0] = ps->n;
  dims[1] = (hsize_t)f->ncomp;
  sp = H5Screate_simple(f->ncomp == 1 ? 1 : 2, dims, NULL);
  pl = dcpl(f, ps->n);
  if (sp < 0 || pl < 0) {
    fail(S, "cannot set up dataset '%s'", f->name);
    goto out;
  }
  d = H5Dcreate2(S->file, f->name, isint ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                 sp, H5P_DEFAULT, pl, H5P_DEFAULT);
  if (d < 0) {
    fail(S, "cannot create dataset '%s'", f->name);
    goto out;
  }
  if (ps->n > 0 &&
      H5Dwrite(d, isint ? H5T_NATIVE_INT32 : H5T_NATIVE_DOUBLE, H5S_ALL,
               H5S_ALL, H5P_DEFAULT, gather(S, ps, f)) < 0) {
    fail(S, "cannot write dataset '%s'", f->name);
    goto out;
  }
  if (putstr(S, d, f->name, "unit", f->unit)) goto out;
  compnames(f, names, sizeof names);
  if (names[0] && putstr(S, d, f->name, "components", names)) goto out;
  r = 0;
out:
  if (d >= 0) H5Dclose(d);
  if (pl >= 0) H5Pclose(pl);
  if (sp >= 0) H5Sclose(sp);
  return r;
}

/* the staging buffer, sized once for the widest output field */
static int stage(h5s *S, const particles *ps) {
  int f, w = 1;
  for (f = 0; f < ps->nfields; f++)
    if ((ps->fields[f].flags & S->flags) && ps->fields[f].ncomp > w)
      w = ps->fields[f].ncomp;
  if (ps->n == 0 || w == 1) return 0;
  errno = 0;
  if (ps->n > SIZE_MAX / 8 / (size_t)w || room(S, ps->n * 8 * (size_t)w))
    return fail(S, "cannot allocate the output buffer");
  return 0;
}

static int deflate_ok(h5s *S) {
  unsigned cfg = 0;
  errno = 0;
  if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0 ||
      H5Zget_filter_info(H5Z_FILTER_DEFLATE, &cfg) < 0 ||
      !(cfg & H5Z_FILTER_CONFIG_ENCODE_ENABLED))
    return fail(S, "this HDF5 library has no deflate (zlib) compression");
  return 0;
}

/*
** The file is built in memory (the core driver, no backing store) and
** written out by us.  HDF5 1.10 does not survive a failed H5Fclose: the
** half-closed file stays registered and the library crashes when it
** shuts down at exit.  A full disk must not crash a long run, so HDF5
** never touches the disk here; the price is holding the compressed file
** in memory twice at the end (the driver's copy and the image).
** Closing strongly closes whatever a failed step left open.  The name
** given to HDF5 is the (empty) temp file: H5Fcreate probes that name on
** disk first, and probing the old snapshot would read it all in.
*/
static int create(h5s *S, const char *tmp, const particles *ps) {
  size_t raw = 0, grow;
  int f;
  hid_t fapl;
  for (f = 0; f < ps->nfields; f++)
    if (ps->fields[f].flags & S->flags) raw += (size_t)ps->fields[f].ncomp;
  /* grow in a few large steps: a quarter of the raw data at a time */
  grow = raw > SIZE_MAX / 2 / (ps->n + 1) ? SIZE_MAX / 4 : raw * 2 * ps->n;
  if (grow < ((size_t)1 << 16)) grow = (size_t)1 << 16;
  errno = 0;
  fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0 || H5Pset_fapl_core(fapl, grow, 0) < 0 ||
      H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0) {
    if (fapl >= 0) H5Pclose(fapl);
    return fail(S, "cannot set up file access");
  }
  S->file = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (S->file < 0) fail(S, "cannot create the file in memory");
  H5Pclose(fapl);
  return S->file < 0 ? -1 : 0;
}

/*
** The finished file as bytes, behind the checksum block (h5sum.h); then
** closing it frees the driver's copy.  The block is a user block put in
** front of a file made without one, as h5jam does: HDF5 finds the
** superblock at 512 and takes its addresses from there, and
** H5Fget_file_image of a file made with a user block leaves the block
** out of the image but counts it in the length.
*/
static int image(h5s *S, void **img, size_t *size) {
  ssize_t len;
  unsigned char *b;
  int r;
  free(S->buf); /* staging is done: lower the peak */
  S->buf = NULL;
  S->bufsz = 0;
  errno = 0;
  /* H5Fget_file_image takes the bytes as they are: flush the cache first */
  if (H5Fflush(S->file, H5F_SCOPE_GLOBAL) < 0)
    return fail(S, "cannot flush the file in memory");
  len = H5Fget_file_image(S->file, NULL, 0);
  if (len < 0) return fail(S, "cannot finish the file in memory");
  *img = b = malloc(H5SUM_BLOCK + (size_t)len);
  if (!b) return fail(S, "out of memory for the file image");
  if (H5Fget_file_image(S->file, b + H5SUM_BLOCK, (size_t)len) != len)
    return fail(S, "cannot copy the file image");
  *size = H5SUM_BLOCK + (size_t)len;
  h5sum_seal(b, *size);
  r = H5Fclose(S->file);
  S->file = -1;
  return r < 0 ? fail(S, "cannot close the file in memory") : 0;
}

/* the file type (file != 0) or memory type of a blob; HDF5's type ids
** are variables set when the library opens, not constants */
static hid_t blobtype(int type, int file) {
  switch (type) {
    case H5B_F64: return file ? H5T_IEEE_F64LE : H5T_NATIVE_DOUBLE;
    case H5B_I64: return file ? H5T_STD_I64LE : H5T_NATIVE_INT64;
    default: return file ? H5T_STD_U8LE : H5T_NATIVE_UINT8;
  }
}

/* the blobs, each a 1-D contiguous dataset in the group "state" */
static int putblobs(h5s *S, const h5blob *b, int nb) {
  hid_t g;
  int k, r = 0;
  if (nb == 0) return 0;
  errno = 0;
  g = H5Gcreate2(S->file, "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) return fail(S, "cannot create group 'state'");
  for (k = 0; k < nb && r == 0; k++) {
    hsize_t n = b[k].n;
    hid_t sp = H5Screate_simple(1, &n, NULL), d = -1;
    if (sp >= 0)
      d = H5Dcreate2(g, b[k].name, blobtype(b[k].type, 1), sp, H5P_DEFAULT,
                     H5P_DEFAULT, H5P_DEFAULT);
    if (d < 0 || (n > 0 && H5Dwrite(d, blobtype(b[k].type, 0), H5S_ALL,
                                    H5S_ALL, H5P_DEFAULT, b[k].data) < 0))
      r = fail(S, "cannot write dataset 'state/%s'", b[k].name);
    if (d >= 0) H5Dclose(d);
    if (sp >= 0) H5Sclose(sp);
  }
  H5Gclose(g);
  return r;
}

/*
** The scene's frame: the domain as root attributes of shape (dim), the
** bodies in the group "bodies" (a group, so readers that take every
** root dataset for a particle field pass over it).
*/
static int putvec(h5s *S, const char *name, hid_t ftype, hid_t mtype,
                  const void *v) {
  hsize_t n = DIM;
  hid_t sp, a = -1;
  int r = 0;
  errno = 0;
  sp = H5Screate_simple(1, &n, NULL);
  if (sp >= 0)
    a = H5Acreate2(S->file, name, ftype, sp, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0 || H5Awrite(a, mtype, v) < 0)
    r = fail(S, "cannot write attribute '%s' of '/'", name);
  if (a >= 0) H5Aclose(a);
  if (sp >= 0) H5Sclose(sp);
  return r;
}

/* a 1-D dataset of n entries in g */
static int put1d(h5s *S, hid_t g, const char *name, hid_t ftype, hid_t mtype,
                 size_t n, const void *v) {
  hsize_t dn = n;
  hid_t sp, d = -1;
  int r = 0;
  errno = 0;
  sp = H5Screate_simple(1, &dn, NULL);
  if (sp >= 0)
    d = H5Dcreate2(g, name, ftype, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (d < 0 || (n > 0 && H5Dwrite(d, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0))
    r = fail(S, "cannot write dataset 'bodies/%s'", name);
  if (d >= 0) H5Dclose(d);
  if (sp >= 0) H5Sclose(sp);
  return r;
}

static int putframe(h5s *S, const h5frame *fr) {
  int per[DIM], d, b, r;
  const char **names;
  hid_t g, t;
  if (!fr) return 0;
  for (d = 0; d < DIM; d++) per[d] = fr->periodic[d] != 0;
  if (putvec(S, "domain_lo", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, fr->lo) ||
      putvec(S, "domain_hi", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, fr->hi) ||
      putvec(S, "periodic", H5T_STD_I32LE, H5T_NATIVE_INT, per))
    return -1;
  errno = 0;
  names = malloc((fr->nbody ? fr->nbody : 1) * sizeof *names);
  if (!names) return fail(S, "out of memory");
  for (b = 0; b < fr->nbody; b++) names[b] = fr->name[b];
  g = H5Gcreate2(S->file, "bodies", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  t = strtype();
  if (g < 0 || t < 0) r = fail(S, "cannot create group 'bodies'");
  else
    r = (put1d(S, g, "name", t, t, (size_t)fr->nbody, names) ||
         put1d(S, g, "driven", H5T_STD_I32LE, H5T_NATIVE_INT32,
               (size_t)fr->nbody, fr->driven)) ? -1 : 0;
  if (t >= 0) H5Tclose(t);
  if (g >= 0) H5Gclose(g);
  free(names);
  return r;
}

/*
** /xdmf/vertex: 0 ... n-1, the connectivity of the XDMF index's
** polyvertex grid (out_xdmf.c).  ParaView's XDMF 2 reader makes one
** vertex per point from the counts alone; its Xdmf3 readers make none
** without this list, and show the points with no cells.  Shuffled and
** deflated, it costs a few bytes per thousand particles.  In a group, so
** that readers of the fields (getfields) pass it over.
*/
static int putvertex(h5s *S, size_t n) {
  pfield one;
  hsize_t dim = n;
  hid_t g, sp = -1, pl = -1, d = -1;
  int32_t *v;
  size_t i;
  int r = -1;
  errno = 0;
  if (n > (size_t)INT32_MAX) return fail(S, "too many particles for the "
                                            "XDMF connectivity (%zu)", n);
  if (room(S, (n ? n : 1) * sizeof *v)) return fail(S, "out of memory");
  v = S->buf;
  for (i = 0; i < n; i++) v[i] = (int32_t)i;
  memset(&one, 0, sizeof one);
  one.ncomp = 1;
  g = H5Gcreate2(S->file, "xdmf", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) return fail(S, "cannot create group 'xdmf'");
  sp = H5Screate_simple(1, &dim, NULL);
  pl = dcpl(&one, n);
  if (sp >= 0 && pl >= 0)
    d = H5Dcreate2(g, "vertex", H5T_STD_I32LE, sp, H5P_DEFAULT, pl,
                   H5P_DEFAULT);
  if (d >= 0 && (n == 0 || H5Dwrite(d, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL,
                                    H5P_DEFAULT, v) >= 0))
    r = 0;
  else
    fail(S, "cannot write dataset 'xdmf/vertex'");
  if (d >= 0) H5Dclose(d);
  if (pl >= 0) H5Pclose(pl);
  if (sp >= 0) H5Sclose(sp);
  H5Gclose(g);
  return r;
}

static int build(h5s *S, const char *tmp, const particles *ps,
                 const h5meta *meta, const h5blob *b, int nb, void **img,
                 size_t *size) {
  int f;
  if (deflate_ok(S) || stage(S, ps) || create(S, tmp, ps) ||
      putmeta(S, meta) || putprov(S, S->prov) ||
      putframe(S, meta->frame))
    return -1;
  for (f = 0; f < ps->nfields; f++)
    if ((ps->fields[f].flags & S->flags) && putfield(S, ps, &ps->fields[f]))
      return -1;
  if (putsource(S, meta->source) || putblobs(S, b, nb)) return -1;
  /* a snapshot (not a checkpoint) is what the XDMF index points at */
  if (!(S->flags & PF_RESTART) && putvertex(S, ps->n)) return -1;
  return image(S, img, size);
}

/*
** Write the image to the temp file and make it durable before the
** rename, so after a system crash the final name holds either the
** previous snapshot or the new one, never a torn file.
*/
static int commit(h5s *S, int fd, const char *tmp, const char *img,
                  size_t size) {
  int r;
  errno = 0;
  while (size > 0) {
    ssize_t k = write(fd, img, size);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) {
      if (k == 0) errno = EIO;
      close(fd);
      return fail(S, "cannot write file");
    }
    img += k;
    size -= (size_t)k;
  }
  if (fsync(fd) != 0) {
    close(fd);
    return fail(S, "cannot sync file");
  }
  r = close(fd);
  if (r != 0) return fail(S, "cannot close file");
  errno = 0;
  if (rename(tmp, S->path) != 0)
    return fail(S, "cannot rename the temp file %s", tmp);
  return 0;
}

/* the temp file is opened first, so a bad directory fails before work */
int out_h5_write_state(const char *path, const char *format,
                       const particles *ps, unsigned flags,
                       const h5meta *meta, const h5prov *prov,
                       const h5blob *b, int nb, char *err, size_t errlen) {
  h5s S;
  char *tmp;
  void *img = NULL;
  size_t size = 0;
  int fd = -1, r = -1;
  begin(&S, path, err, errlen);
  S.flags = flags;
  S.format = format ? format : FORMAT;
  S.prov = prov;
  errno = 0;
  tmp = malloc(strlen(path) + 5);
  if (!tmp) {
    fail(&S, "out of memory");
    goto out;
  }
  sprintf(tmp, "%s.tmp", path);
  fd = ofile_create(tmp); /* never through a link */
  if (fd < 0) {
    fail(&S, "cannot create file");
    goto out;
  }
  if (build(&S, tmp, ps, meta, b, nb, &img, &size) == 0) {
    r = commit(&S, fd, tmp, img, size);
    fd = -1; /* commit closed it */
  }
out:
  end(&S);
  if (fd >= 0) close(fd);
  if (r != 0 && tmp) remove(tmp);
  free(img);
  free(tmp);
  return r;
}

int out_h5_write(const char *path, const particles *ps, const h5meta *meta,
                 char *err, size_t errlen) {
  return out_h5_write_state(path, NULL, ps, PF_OUTPUT, meta, NULL, NULL, 0,
                            err, errlen);
}

int out_h5_write_prov(const char *path, const particles *ps,
                      const h5meta *meta, const h5prov *prov, char *err,
                      size_t errlen) {
  return out_h5_write_state(path, NULL, ps, PF_OUTPUT, meta, prov, NULL, 0,
                            err, errlen);
}

/* }====================================================== */


/*
** {======================================================
** Reading
** =======================================================
*/

/* a scalar attribute of any numeric type, converted to mtype */
static int getattr(h5s *S, const char *name, hid_t mtype, void *v) {
  hid_t a;
  herr_t e = -1;
  errno = 0;
  a = H5Aopen(S->file, name, H5P_DEFAULT);
  if (a >= 0) e = H5Aread(a, mtype, v);
  if (e < 0) fail(S, "cannot read attribute '%s'", name);
  if (a >= 0) H5Aclose(a);
  return e < 0 ? -1 : 0;
}

/*
** A string attribute, fixed or variable length, into buf (truncated to
** len - 1).  Absent is not an error here: buf is left "" and 1 returned.
*/
static int getstr(h5s *S, hid_t obj, const char *where, const char *name,
                  char *buf, size_t len) {
  hid_t a, ft = -1, mt = -1;
  int r = -1;
  buf[0] = '\0';
  errno = 0;
  if (H5Aexists(obj, name) == 0) return 1;
  a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a >= 0) ft = H5Aget_type(a);
  if (ft >= 0 && H5Tget_class(ft) != H5T_STRING) {
    errno = 0;
    fail(S, "attribute '%s' of '%s' is not a string", name, where);
    goto out;
  }
  if (ft >= 0 && H5Tis_variable_str(ft) > 0) {
    char *s = NULL;
    mt = strtype();
    if (mt >= 0 && H5Aread(a, mt, &s) >= 0) {
      snprintf(buf, len, "%s", s ? s : "");
      H5free_memory(s);
      r = 0;
    }
  } else if (ft >= 0) {
    mt = H5Tcopy(H5T_C_S1); /* HDF5 converts to our size, NUL-terminated */
    if (mt >= 0 && H5Tset_size(mt, len) >= 0 && H5Aread(a, mt, buf) >= 0)
      r = 0;
  }
  if (r < 0) fail(S, "cannot read attribute '%s' of '%s'", name, where);
out:
  if (mt >= 0) H5Tclose(mt);
  if (ft >= 0) H5Tclose(ft);
  if (a >= 0) H5Aclose(a);
  return r;
}

static int getmeta(h5s *S, h5meta *meta, const char *want) {
  char fmt[64];
  int64_t step;
  int dim;
  int r = getstr(S, S->file, "/", "format", fmt, sizeof fmt);
  if (r < 0) return -1;
  errno = 0;
  if (r > 0 || strcmp(fmt, want) != 0)
    return fail(S, "not an mvmpm %s (format '%s', expected '%s')",
                strcmp(want, FORMAT) == 0 ? "snapshot" : "checkpoint", fmt,
                want);
  if (getattr(S, "dim", H5T_NATIVE_INT, &dim)) return -1;
  if (dim != DIM)
    return fail(S, "the snapshot is %d-D but this build is %d-D", dim, DIM);
  if (getattr(S, "time", H5T_NATIVE_DOUBLE, &meta->time) ||
      getattr(S, "step", H5T_NATIVE_INT64, &step) ||
      getattr(S, "cell", H5T_NATIVE_DOUBLE, &meta->cell))
    return -1;
  meta->step = (long)step;
  return 0;
}

/* a root attribute of shape (dim), converted to mtype; 1 if absent */
static int getvec(h5s *S, const char *name, hid_t mtype, void *v) {
  hid_t a, sp = -1;
  hsize_t n = 0;
  int r = -1;
  errno = 0;
  if (H5Aexists(S->file, name) <= 0) return 1;
  a = H5Aopen(S->file, name, H5P_DEFAULT);
  if (a >= 0) sp = H5Aget_space(a);
  if (sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 &&
      H5Sget_simple_extent_dims(sp, &n, NULL) == 1 && n == DIM &&
      H5Aread(a, mtype, v) >= 0)
    r = 0;
  else {
    errno = 0;
    fail(S, "attribute '%s' must hold %d numbers", name, DIM);
  }
  if (sp >= 0) H5Sclose(sp);
  if (a >= 0) H5Aclose(a);
  return r;
}

/* bodies/NAME: rank 1 with n entries (n set by the first one read) */
static hid_t open1d(h5s *S, hid_t g, const char *name, hsize_t *n) {
  hid_t d, sp = -1;
  hsize_t k = 0;
  int ok = 0;
  errno = 0;
  if (H5Lexists(g, name, H5P_DEFAULT) <= 0) {
    fail(S, "group 'bodies' has no dataset '%s'", name);
    return -1;
  }
  d = H5Dopen2(g, name, H5P_DEFAULT);
  if (d >= 0) sp = H5Dget_space(d);
  if (sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 &&
      H5Sget_simple_extent_dims(sp, &k, NULL) == 1 && k <= H5_MAXBODY &&
      (*n == (hsize_t)-1 || k == *n))
    ok = 1;
  if (sp >= 0) H5Sclose(sp);
  if (!ok) {
    errno = 0;
    fail(S, "dataset 'bodies/%s' must be 1-D with at most %d entries, as "
         "many as the other", name, H5_MAXBODY);
    if (d >= 0) H5Dclose(d);
    return -1;
  }
  *n = k;
  return d;
}

/* the bodies' names: strings of any kind, cut to H5_NAMELEN - 1 bytes */
static int getnames(h5s *S, hid_t d, h5frame *fr, size_t n) {
  hid_t ft = H5Dget_type(d), mt = -1;
  int r = -1;
  size_t b;
  errno = 0;
  if (ft < 0 || H5Tget_class(ft) != H5T_STRING) {
    if (ft >= 0) H5Tclose(ft);
    return fail(S, "dataset 'bodies/name' does not hold strings");
  }
  if (H5Tis_variable_str(ft) > 0) {
    char **s = calloc(n ? n : 1, sizeof *s);
    mt = strtype();
    if (s && mt >= 0 &&
        (n == 0 || H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, s) >= 0)) {
      for (b = 0; b < n; b++) {
        snprintf(fr->name[b], H5_NAMELEN, "%s", s[b] ? s[b] : "");
        H5free_memory(s[b]);
      }
      r = 0;
    }
    free(s);
  } else {
    mt = H5Tcopy(H5T_C_S1); /* converted to our size, NUL-terminated */
    if (mt >= 0 && H5Tset_size(mt, H5_NAMELEN) >= 0 &&
        (n == 0 || H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, fr->name) >= 0))
      r = 0;
  }
  if (mt >= 0) H5Tclose(mt);
  H5Tclose(ft);
  if (r < 0) fail(S, "cannot read dataset 'bodies/name'");
  return r;
}

/*
** The frame, if the file has one (older files have none: has_domain and
** nbody stay 0).  Only what is there is read; whoever draws with it
** judges the numbers.
*/
static int getframe(h5s *S, h5frame *fr) {
  int per[DIM], d, k;
  hsize_t n = (hsize_t)-1;
  hid_t g, dn = -1, dd = -1;
  if (!fr) return 0;
  memset(fr, 0, sizeof *fr);
  if (getstr(S, S->file, "/", "units", fr->units, sizeof fr->units) < 0)
    return -1;
  k = getvec(S, "domain_lo", H5T_NATIVE_DOUBLE, fr->lo);
  if (k < 0) return -1;
  if (k == 0) {
    if (getvec(S, "domain_hi", H5T_NATIVE_DOUBLE, fr->hi) ||
        getvec(S, "periodic", H5T_NATIVE_INT, per))
      return S->failed ? -1 : fail(S, "attribute 'domain_lo' without "
                                   "'domain_hi' and 'periodic'");
    for (d = 0; d < DIM; d++) fr->periodic[d] = per[d] != 0;
    fr->has_domain = 1;
  }
  errno = 0;
  if (H5Lexists(S->file, "bodies", H5P_DEFAULT) <= 0) return 0;
  g = H5Gopen2(S->file, "bodies", H5P_DEFAULT);
  if (g < 0) return fail(S, "cannot open group 'bodies'");
  dn = open1d(S, g, "name", &n);
  if (dn >= 0) dd = open1d(S, g, "driven", &n);
  if (dd >= 0) {
    fr->name = calloc(n ? n : 1, sizeof *fr->name);
    fr->driven = calloc(n ? n : 1, sizeof *fr->driven);
    errno = 0;
    if (!fr->name || !fr->driven) fail(S, "out of memory");
    else if (getnames(S, dn, fr, (size_t)n) == 0) {
      errno = 0;
      if (n > 0 && H5Dread(dd, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL,
                           H5P_DEFAULT, fr->driven) < 0)
        fail(S, "cannot read dataset 'bodies/driven'");
      else fr->nbody = (int)n;
    }
  }
  if (dd >= 0) H5Dclose(dd);
  if (dn >= 0) H5Dclose(dn);
  H5Gclose(g);
  return S->failed ? -1 : 0;
}

void out_h5_frame_free(h5frame *f) {
  if (!f) return;
  free(f->name);
  free(f->driven);
  f->name = NULL;
  f->driven = NULL;
  f->nbody = 0;
}

/* shape and type of a field dataset, checked against what a field can be */
static int shape(h5s *S, hid_t d, const char *name, hsize_t *n, int *ncomp,
                 int *type) {
  hsize_t dims[2] = {0, 1};
  hid_t sp, t;
  int rank = -1;
  H5T_class_t cl = H5T_NO_CLASS;
  size_t size = 0;
  errno = 0;
  sp = H5Dget_space(d);
  if (sp >= 0) rank = H5Sget_simple_extent_ndims(sp);
  if (rank >= 1 && rank <= 2) H5Sget_simple_extent_dims(sp, dims, NULL);
  if (sp >= 0) H5Sclose(sp);
  t = H5Dget_type(d);
  if (t >= 0) {
    cl = H5Tget_class(t);
    size = H5Tget_size(t);
    H5Tclose(t);
  }
  if (sp < 0 || t < 0) return fail(S, "cannot inspect dataset '%s'", name);
  errno = 0;
  if (rank < 1 || rank > 2)
    return fail(S, "dataset '%s' has rank %d, a field has 1 or 2", name, rank);
  if (dims[1] < 1 || dims[1] > PF_MAXCOMP)
    return fail(S, "dataset '%s' has %llu components, at most %d allowed",
                name, (unsigned long long)dims[1], PF_MAXCOMP);
  if (cl == H5T_FLOAT) *type = PF_DOUBLE;
  else if (cl == H5T_INTEGER && size <= 4) *type = PF_INT32;
  else
    return fail(S, "dataset '%s' is neither floating point nor a 32-bit "
                "integer", name);
  *n = dims[0];
  *ncomp = (int)dims[1];
  return 0;
}

/* the store's field for a dataset: the built-in one, or a new one */
static int field(h5s *S, particles *ps, hid_t d, const char *name,
                 int ncomp, int type) {
  char unit[sizeof ps->fields[0].unit];
  int f = particles_find(ps, name);
  errno = 0;
  if (f >= 0) {
    if (ps->fields[f].type != type)
      return fail(S, "dataset '%s' holds %s, the field holds %s", name,
                  type == PF_INT32 ? "integers" : "reals",
                  ps->fields[f].type == PF_INT32 ? "integers" : "reals");
    if (ps->fields[f].ncomp != ncomp)
      return fail(S, "dataset '%s' has %d components, the field has %d",
                  name, ncomp, ps->fields[f].ncomp);
    return f;
  }
  if (strlen(name) >= sizeof ps->fields[0].name)
    return fail(S, "dataset name '%s' is too long for a field", name);
  if (getstr(S, d, name, "unit", unit, sizeof unit) < 0) return -1;
  f = particles_add_field(ps, name, ncomp, type, unit, PF_OUTPUT);
  errno = 0;
  if (f < 0)
    return fail(S, "cannot add field '%s' (more than %d fields or out of "
                "memory)", name, PF_MAXFIELDS);
  { /* its components by name (affine.xy), as the writer named them */
    char comps[128];
    if (getstr(S, d, name, "components", comps, sizeof comps) < 0) return -1;
    if (comps[0]) particles_name_comps(&ps->fields[f], comps);
  }
  return f;
}

/* read the whole dataset and scatter its columns into the store */
static int fill(h5s *S, particles *ps, hid_t d, int f, size_t n) {
  const pfield *pf = &ps->fields[f];
  size_t i, nc = (size_t)pf->ncomp;
  hid_t mt = pf->type == PF_INT32 ? H5T_NATIVE_INT32 : H5T_NATIVE_DOUBLE;
  void *dst = nc == 1 ? *pf->slot[0] : NULL;
  int c;
  if (n == 0) return 0;
  errno = 0;
  if (!dst) {
    if (room(S, n * nc * 8)) return fail(S, "out of memory");
    dst = S->buf;
  }
  if (H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, dst) < 0)
    return fail(S, "cannot read dataset '%s'", pf->name);
  for (c = 0; nc > 1 && c < pf->ncomp; c++) {
    if (pf->type == PF_INT32) {
      const int32_t *a = S->buf;
      int32_t *b = *pf->slot[c];
      for (i = 0; i < n; i++) b[i] = a[i * nc + c];
    } else {
      const double *a = S->buf;
      double *b = *pf->slot[c];
      for (i = 0; i < n; i++) b[i] = a[i * nc + c];
    }
  }
  return 0;
}

/*
** One dataset.  The first (first[0] still empty) fixes the particle
** count and sizes the store, so fields added afterwards are allocated at
** that capacity; its name is kept for the message when counts differ.
*/
static int getfield(h5s *S, particles *ps, hid_t d, const char *name,
                    hsize_t *n, char *first, size_t firstlen) {
  hsize_t rows = 0;
  int ncomp = 1, type = PF_DOUBLE, f;
  if (shape(S, d, name, &rows, &ncomp, &type)) return -1;
  errno = 0;
  if (!first[0]) {
    if (rows > SIZE_MAX / 8 / PF_MAXCOMP || particles_reserve(ps, rows))
      return fail(S, "cannot make room for %llu particles",
                  (unsigned long long)rows);
    *n = rows;
    snprintf(first, firstlen, "%s", name);
  } else if (rows != *n)
    return fail(S, "dataset '%s' has %llu rows but '%s' has %llu", name,
                (unsigned long long)rows, first, (unsigned long long)*n);
  f = field(S, ps, d, name, ncomp, type);
  if (f < 0) return -1;
  ps->fields[f].flags |= PF_READ;
  return fill(S, ps, d, f, (size_t)rows);
}

/*
** Every dataset in the root group except the scene's text is a field;
** other objects (groups a later version may add) are passed over.
*/
static int getfields(h5s *S, particles *ps) {
  H5G_info_t gi;
  hsize_t k, n = 0;
  char name[256], first[256] = "";
  errno = 0;
  if (H5Gget_info(S->file, &gi) < 0)
    return fail(S, "cannot list the root group");
  for (k = 0; k < gi.nlinks; k++) {
    ssize_t len;
    hid_t obj;
    int r = 0;
    errno = 0;
    len = H5Lget_name_by_idx(S->file, ".", H5_INDEX_NAME, H5_ITER_INC, k,
                             name, sizeof name, H5P_DEFAULT);
    if (len < 0) return fail(S, "cannot list the root group");
    if ((size_t)len >= sizeof name)
      return fail(S, "object name '%s...' is too long", name);
    if (strcmp(name, SOURCE) == 0) continue;
    obj = H5Oopen(S->file, name, H5P_DEFAULT);
    if (obj < 0) return fail(S, "cannot open '%s'", name);
    if (H5Iget_type(obj) == H5I_DATASET)
      r = getfield(S, ps, obj, name, &n, first, sizeof first);
    H5Oclose(obj);
    if (r) return -1;
  }
  ps->n = (size_t)n;
  return 0;
}

/* one blob of "state": rank 1, the type class it was written with */
static int getblob(h5s *S, hid_t g, h5blob *b) {
  hsize_t n = 0;
  hid_t d, sp = -1, t = -1;
  int rank = -1, r = -1;
  H5T_class_t cl = H5T_NO_CLASS;
  H5T_class_t want = b->type == H5B_F64 ? H5T_FLOAT : H5T_INTEGER;
  size_t esz = b->type == H5B_U8 ? 1 : 8;
  errno = 0;
  if (H5Lexists(g, b->name, H5P_DEFAULT) <= 0)
    return fail(S, "no dataset 'state/%s' (written by another version?)",
                b->name);
  d = H5Dopen2(g, b->name, H5P_DEFAULT);
  if (d >= 0) sp = H5Dget_space(d);
  if (sp >= 0) rank = H5Sget_simple_extent_ndims(sp);
  if (rank == 1) H5Sget_simple_extent_dims(sp, &n, NULL);
  if (d >= 0) t = H5Dget_type(d);
  if (t >= 0) cl = H5Tget_class(t);
  if (d < 0 || sp < 0 || t < 0) fail(S, "cannot open dataset 'state/%s'", b->name);
  else if (rank != 1 || cl != want || n > SIZE_MAX / 8)
    fail(S, "dataset 'state/%s' has the wrong shape or type", b->name);
  else if (!(b->data = malloc(n ? (size_t)n * esz : 1)))
    fail(S, "out of memory for dataset 'state/%s'", b->name);
  else if (n > 0 && H5Dread(d, blobtype(b->type, 0), H5S_ALL, H5S_ALL,
                            H5P_DEFAULT, b->data) < 0)
    fail(S, "cannot read dataset 'state/%s'", b->name);
  else {
    b->n = (size_t)n;
    r = 0;
  }
  if (t >= 0) H5Tclose(t);
  if (sp >= 0) H5Sclose(sp);
  if (d >= 0) H5Dclose(d);
  return r;
}

static int getblobs(h5s *S, h5blob *b, int nb) {
  hid_t g;
  int k, r = 0;
  if (nb == 0) return 0;
  errno = 0;
  if (H5Lexists(S->file, "state", H5P_DEFAULT) <= 0)
    return fail(S, "no group 'state'");
  g = H5Gopen2(S->file, "state", H5P_DEFAULT);
  if (g < 0) return fail(S, "cannot open group 'state'");
  for (k = 0; k < nb && r == 0; k++) r = getblob(S, g, &b[k]);
  H5Gclose(g);
  return r;
}

/*
** The file is read whole and its checksum checked before HDF5 sees a
** byte of it (a damaged chunk index can crash HDF5 1.10); HDF5 then
** opens those checked bytes from memory.  A checkpoint must carry the
** checksum; a snapshot from before it existed is read unchecked (its
** fields are still checked by whoever uses them, pcheck.h).
*/
/* the core driver refuses an image whose name exists on disk: this
** name never does (/dev/null is not a directory) */
#define IMAGE_NAME "/dev/null/mvmpm-image"

static int openimage(h5s *S, const char *sealed) {
  void *img;
  size_t size;
  hid_t fapl;
  int k = h5sum_load(S->path, &img, &size, S->err, S->errlen);
  if (k < 0) return S->failed = 1, -1;
  errno = 0;
  if (k == H5SUM_NONE && sealed) {
    free(img);
    return fail(S, "it has no checksum (written by an mvmpm older than "
                "the format %s, or rewritten by another tool); this "
                "version continues only checkpoints that carry one",
                sealed);
  }
  fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl >= 0 && H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0 &&
      H5Pset_file_image(fapl, img, size) >= 0)
    S->file = H5Fopen(IMAGE_NAME, H5F_ACC_RDONLY, fapl);
  free(img); /* HDF5 holds its own copy */
  if (fapl >= 0) H5Pclose(fapl);
  return S->file < 0 ? fail(S, "cannot open file (not HDF5, or damaged)") : 0;
}

/* the readers' work; fr may be NULL */
static int readall(const char *path, const char *format, particles *ps,
                   h5meta *meta, h5frame *fr, h5blob *b, int nb, char *err,
                   size_t errlen) {
  h5s S;
  h5meta dummy;
  const char *want = format ? format : FORMAT;
  int r, k;
  if (!meta) {
    memset(&dummy, 0, sizeof dummy);
    meta = &dummy;
  }
  for (k = 0; k < nb; k++) b[k].data = NULL, b[k].n = 0;
  begin(&S, path, err, errlen);
  meta->units = meta->scene = meta->source = NULL;
  meta->frame = NULL;
  errno = 0;
  if (ps->n != 0) {
    r = fail(&S, "cannot read into a store that already holds particles");
  } else {
    r = openimage(&S, format);
    if (r == 0)
      r = (getmeta(&S, meta, want) || getframe(&S, fr) ||
           getfields(&S, ps) || getblobs(&S, b, nb)) ? -1 : 0;
  }
  end(&S);
  if (r != 0) {
    ps->n = 0;
    out_h5_frame_free(fr);
  }
  return r;
}

int out_h5_read_state(const char *path, const char *format, particles *ps,
                      h5meta *meta, h5blob *b, int nb, char *err,
                      size_t errlen) {
  return readall(path, format, ps, meta, NULL, b, nb, err, errlen);
}

int out_h5_read(const char *path, particles *ps, h5meta *meta, char *err,
                size_t errlen) {
  return readall(path, NULL, ps, meta, NULL, NULL, 0, err, errlen);
}

int out_h5_read_frame(const char *path, const char *format, particles *ps,
                      h5meta *meta, h5frame *fr, char *err, size_t errlen) {
  return readall(path, format, ps, meta, fr, NULL, 0, err, errlen);
}

/* }====================================================== */

int out_h5_file_dim(const char *path) {
  H5E_auto2_t efunc;
  void *edata;
  hid_t f, a;
  int dim = -1;
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f >= 0) {
    if (H5Aexists(f, "dim") > 0 && (a = H5Aopen(f, "dim", H5P_DEFAULT)) >= 0) {
      if (H5Aread(a, H5T_NATIVE_INT, &dim) < 0) dim = -1;
      H5Aclose(a);
    }
    H5Fclose(f);
  }
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  return dim;
}
