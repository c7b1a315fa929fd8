/*
** out_h5.h - particle snapshots in HDF5.
** One file per snapshot; every field flagged PF_OUTPUT is written as a
** chunked, deflate-compressed dataset; attributes carry time, step,
** units and the scene's source.  Written to "<path>.tmp" and renamed,
** so a crash never leaves a corrupt file under the final name.
**
** Layout ("mvmpm-snapshot-1"), all in the root group:
**   dataset NAME per PF_OUTPUT field: shape (n) for one component, else
**     (n, ncomp), row i = particle i; IEEE F64LE or STD I32LE; chunks of
**     min(n, 65536) rows, shuffle + deflate level 4 (n == 0: contiguous,
**     unfiltered).  Attributes "unit" (string) and, when the field names
**     its components, "components" (e.g. "xx,yy,xy,zz").
**   dataset "scene_source": the scene's text, a scalar string; absent
**     when meta->source is NULL.  A dataset, not an attribute, because a
**     scene can exceed the 64 KiB an attribute may hold.
**   root attributes: "format" = "mvmpm-snapshot-1", "time" (F64),
**     "step" (I64), "cell" (F64), "dim" (I32), "units", "scene"; and the
**     provenance strings given: "version", "build", "command", "params"
**     (one "name = value" line per scene parameter in force), and in a
**     continued run "restarted_from" (the checkpoint).
**   the scene's frame, when meta->frame is given (files from before it
**     lack them; readers fall back on the particles' extent):
**     root attributes "domain_lo", "domain_hi" (F64, shape (dim)) and
**     "periodic" (I32, shape (dim), 1 = periodic); group "bodies" with
**     datasets "name" (strings, shape (nbody)) and "driven" (I32,
**     shape (nbody)), entry b for the particles whose "body" is b.  A
**     group, so that readers that take every root dataset for a field
**     pass over it.
** Strings are variable-length UTF-8 (h5py reads them as str).
** In front of it all: the 512-byte checksum block of h5sum.h (an HDF5
** user block); reading checks it before HDF5 sees the file.
**
** The file is built in memory and written with write/fsync/rename: HDF5
** 1.10 crashes at exit after a failed H5Fclose, so it never does the
** disk I/O.  The cost is about twice the compressed file in memory for
** a moment.  HDF5's error printing is off during both calls; the message
** in err names the file, what failed and why ("No space left on device").
*/
#ifndef mvmpm_out_h5_h
#define mvmpm_out_h5_h

#include <stddef.h>
#include <stdint.h>
#include "particles.h"

/* the domain and the bodies' names (out_h5.h's layout) */
#define H5_NAMELEN 32
#define H5_MAXBODY (1 << 20)  /* most bodies a file may name */
typedef struct h5frame {
  int has_domain;         /* reading: the file holds lo, hi, periodic */
  double lo[DIM], hi[DIM];
  int periodic[DIM];
  int nbody;              /* entries of name and driven; 0: none stored */
  char (*name)[H5_NAMELEN];
  int32_t *driven;
  char units[32];         /* reading: the "units" attribute ("" if none) */
} h5frame;
/* release what out_h5_read_frame allocated in f */
void out_h5_frame_free(h5frame *f);

typedef struct h5meta {
  double time;
  long step;
  double cell;            /* grid spacing */
  const char *units;      /* e.g. "nondimensional" or "SI" */
  const char *scene;      /* scene file name */
  const char *source;     /* the scene's source text (may be NULL) */
  const h5frame *frame;   /* writing: stored when not NULL (reading sets
                             it NULL; see out_h5_read_frame) */
} h5meta;
/* what made a file, each written as a root string attribute when not
** NULL (out_h5_write_prov, out_h5_write_state) */
typedef struct h5prov {
  const char *version;    /* the engine's version (git describe) */
  const char *build;      /* compiler and flags */
  const char *command;    /* the command line of the run */
  const char *params;     /* "name = value" lines: the parameters used */
  const char *restarted;  /* the checkpoint the run continued from */
  const char *scheme;     /* the scheme as run (sim_scheme): defaults change,
                             and "default" in params does not say which */
} h5prov;

/* 0 on success; -1 with a message naming the file in err */
int out_h5_write(const char *path, const particles *ps, const h5meta *meta,
                 char *err, size_t errlen);
/* the same with the provenance attributes (prov may be NULL) */
int out_h5_write_prov(const char *path, const particles *ps,
                      const h5meta *meta, const h5prov *prov, char *err,
                      size_t errlen);

/*
** Checkpoints (ckpt.c) use the same file with other fields and more:
** the fields whose flags meet `flags` (PF_RESTART), and 1-D datasets in
** the group "/state", one per blob.  On reading, each blob named is
** looked up, its type must match, and data is malloc'ed (the caller
** frees it, also after a failure); a missing one is an error.
*/
enum { H5B_F64, H5B_I64, H5B_U8 };
typedef struct h5blob {
  const char *name;
  int type;               /* H5B_F64 (double), H5B_I64 (int64_t), H5B_U8 */
  size_t n;               /* entries */
  void *data;
} h5blob;
/* format: the root's "format" attribute (NULL: "mvmpm-snapshot-1");
** prov: the provenance attributes (may be NULL) */
int out_h5_write_state(const char *path, const char *format,
                       const particles *ps, unsigned flags,
                       const h5meta *meta, const h5prov *prov,
                       const h5blob *b, int nb, char *err, size_t errlen);
/* as out_h5_read, but the file's "format" must be format (NULL: a
** snapshot), and the blobs are read too */
int out_h5_read_state(const char *path, const char *format, particles *ps,
                      h5meta *meta, h5blob *b, int nb, char *err,
                      size_t errlen);

/* Read a snapshot into an initialised, empty store: the built-in fields
** are filled, other datasets become run-time fields.  meta->time/step/cell
** are filled; string members are left NULL.  0 or -1 with err.
** Every dataset must have the same number of rows, and one matching a
** field already in the store must have its type and component count.
** New fields are flagged PF_OUTPUT, with the stored unit but no
** component names (pfield only points to names, it cannot own them).
** Fields of the store the file lacks are left zero (F included) and
** without PF_READ, which those read get (pcheck.h judges them), and
** the file's "dim" must be this build's DIM.  On failure ps->n is 0 and
** fields may have been added; particles_free releases it as usual. */
int out_h5_read(const char *path, particles *ps, h5meta *meta, char *err,
                size_t errlen);
/* out_h5_read (format NULL) or, for a checkpoint's particles,
** out_h5_read_state without blobs, filling fr with the file's frame
** and units: a file from before they were stored leaves has_domain and
** nbody 0 (release fr with out_h5_frame_free, also after a failure) */
int out_h5_read_frame(const char *path, const char *format, particles *ps,
                      h5meta *meta, h5frame *fr, char *err, size_t errlen);

/* the dimension a snapshot or checkpoint was written in (its root
** attribute "dim"), or -1 when the file cannot be read or has none: the
** application starts again in the file's dimension */
int out_h5_file_dim(const char *path);

#endif
