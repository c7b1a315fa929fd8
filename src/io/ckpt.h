/*
** ckpt.h - checkpoints: the whole state of a run, so that it continues
** bit for bit after a restart.
**
** A checkpoint is an HDF5 file ("mvmpm-checkpoint-2", the snapshot's
** layout and machinery, out_h5.h, with the checksum block of h5sum.h,
** which a checkpoint must carry) holding every PF_RESTART particle
** field and, in the group /state:
**   real, real_names   the simulation's numbers (time, step size rule,
**   int, int_names       energy accumulators, bond counters, temperature,
**                        walls, drives, contact laws) and the run's (next
**                        output, callback and checkpoint times, counters),
**                        each by name, so a file from another version or
**                        another scene is refused by name
**   snap_files, snap_time, snap_n   the XDMF entries so far
**   params             the --set overrides, "name=value" lines, sorted
**                      (int "run.sandbox" says the run was under --sandbox:
**                      a restart of it is too)
**   scene, source      the scene file's path and text
**   lua_state          sim:state's table (lstate.h)
**   fields             the names of the particle fields saved
** Nothing of the grid is kept: every step rebuilds it from the particles.
** Files are DIR/checkpoint_NNNNNN.h5, written under a temp name, synced
** and renamed, the directory synced after; the two newest are kept.
**
** This half knows the simulation (sim.h) and the file; it needs no Lua
** state.  The run's half (the "run." numbers, callbacks' next times, the
** XDMF entries, params, scene, lua_state) is lckpt.h's, in the Lua
** layer: it adds its numbers to the same named lists through ckpt_more
** and its blobs to the file through ckpt_save.
*/
#ifndef mvmpm_ckpt_h
#define mvmpm_ckpt_h

#include <stddef.h>
#include <stdint.h>
#include "out_h5.h"
#include "particles.h"
#include "sim.h"

/* 2: the file carries a checksum (h5sum.h); 1 had none */
#define CKPT_FORMAT "mvmpm-checkpoint-2"

enum { CB_REALN, CB_REAL, CB_INTN, CB_INT, CB_SNAPF, CB_SNAPT, CB_SNAPN,
       CB_PARAMS, CB_SCENE, CB_SOURCE, CB_STATE, CB_FIELDS, CB_N };

/* a checkpoint read back, before it is applied */
typedef struct ckpt {
  char path[1100];
  particles ps;
  h5meta meta;
  h5blob b[CB_N];
} ckpt;

/* named numbers on their way into a checkpoint (gathering) or out of
** one (applying): each call names one number; applying assigns the
** file's value to *p, or fails naming what is missing or out of range.
** After a failure every call is a no-op */
typedef struct ckv ckv;
int ckv_applying(const ckv *v);
int ckv_failed(const ckv *v);
int ckv_fail(ckv *v, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
void ckv_real(ckv *v, const char *name, double *p);  /* finite */
void ckv_int(ckv *v, const char *name, int64_t *p);
/* a count the scene fixes: the checkpoint must agree */
void ckv_same(ckv *v, const char *name, int64_t have, const char *what);
/* x (the value named) must lie in [lo, hi], or (lo, hi] with open */
int ckv_range(ckv *v, const char *name, double x, double lo, double hi,
              int open);

/* the caller's part of the state: visit names its numbers after the
** simulation's, in both directions; check (applying) holds them to their
** ranges after the simulation's were checked.  Either may be NULL */
typedef struct ckpt_more {
  void (*visit)(ckv *v, void *ud);
  void (*check)(ckv *v, void *ud);
  void *ud;
} ckpt_more;

/* write the checkpoint of s to path (under a temp name, synced,
** renamed): the caller gives b[CB_SNAPF .. CB_STATE], meta's units,
** scene and frame, the provenance, and nomem when making them ran out of
** memory; this fills the rest.  0, or -1 with err */
int ckpt_save(const char *path, sim *s, const ckpt_more *more, h5blob *b,
              h5meta *meta, const h5prov *prov, int nomem, char *err,
              size_t errlen);
/* DIR/checkpoint_NNNNNN.h5 of the k-th checkpoint */
void ckpt_name(char *buf, size_t len, const char *dir, int k);
/* fsync a directory (after a rename into it); 0, or -1 with errno */
int ckpt_syncdir(const char *dir);

/* read a checkpoint; 0, or -1 with err naming the file and the reason.
** ckpt_free releases it either way. */
int ckpt_read(ckpt *c, const char *path, char *err, size_t errlen);
void ckpt_free(ckpt *c);
/* a blob as a NUL-terminated string (the bytes are copied) */
char *ckpt_string(const ckpt *c, int which);
/* put the checkpoint's state into s, set up again from the same scene
** with the same parameters, and the caller's numbers through more; 0, or
** -1 with err saying what does not match or lies outside what the engine
** allows: every field this scene saves must be in the file, every
** particle pass pcheck.h against the scene, every number of /state be in
** range.  The particles are copied only when all of that holds */
int ckpt_restore(sim *s, const ckpt *c, const ckpt_more *more, char *err,
                 size_t errlen);
/* 1 if the run was under --sandbox, 0 if not, -1 if the checkpoint does
** not say (written before it was recorded) */
int ckpt_sandboxed(const ckpt *c);
/* the newest DIR/checkpoint_NNNNNN.h5 into out; 0, or -1 with err */
int ckpt_latest(const char *dir, char *out, size_t len, char *err,
                size_t errlen);

/* a growing string: names joined by '\n' for a checkpoint's lists; bad
** once an allocation failed (the caller checks it and frees b) */
typedef struct ckpt_buf { char *b; size_t n, cap; int bad; } ckpt_buf;
void ckpt_buf_add(ckpt_buf *s, const char *p, size_t n);

#endif
