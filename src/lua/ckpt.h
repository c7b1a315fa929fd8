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
*/
#ifndef mvmpm_ckpt_h
#define mvmpm_ckpt_h

#include <stddef.h>
#include "lua.h"
#include "out_h5.h"
#include "particles.h"

/* 2: the file carries a checksum (h5sum.h); 1 had none */
#define CKPT_FORMAT "mvmpm-checkpoint-2"

/* write the next checkpoint of the simulation at simidx into its output
** directory (between steps only); raises a Lua error naming the file
** and the reason when it cannot.  ls->ck_last names it afterwards. */
void ckpt_write(lua_State *L, int simidx);

enum { CB_REALN, CB_REAL, CB_INTN, CB_INT, CB_SNAPF, CB_SNAPT, CB_SNAPN,
       CB_PARAMS, CB_SCENE, CB_SOURCE, CB_STATE, CB_FIELDS, CB_N };

/* a checkpoint read back, before it is applied */
typedef struct ckpt {
  char path[1100];
  particles ps;
  h5meta meta;
  h5blob b[CB_N];
} ckpt;

/* read a checkpoint; 0, or -1 with err naming the file and the reason.
** ckpt_free releases it either way. */
int ckpt_read(ckpt *c, const char *path, char *err, size_t errlen);
void ckpt_free(ckpt *c);
/* a blob as a NUL-terminated string (the bytes are copied) */
char *ckpt_string(const ckpt *c, int which);
/* put the checkpoint's state into the simulation at simidx, loaded again
** from the same scene with the same parameters; 0, or -1 with err saying
** what does not match or lies outside what the engine allows: every
** field this scene saves must be in the file, every particle pass
** pcheck.h against the scene, every number of /state be in range */
int ckpt_apply(lua_State *L, int simidx, const ckpt *c, char *err,
               size_t errlen);
/* 1 if the run was under --sandbox, 0 if not, -1 if the checkpoint does
** not say (written before it was recorded) */
int ckpt_sandboxed(const ckpt *c);
/* the --set overrides in force as a checkpoint stores them (malloc'ed;
** NULL when out of memory) */
char *ckpt_overrides(lua_State *L);
/* the newest DIR/checkpoint_NNNNNN.h5 into out; 0, or -1 with err */
int ckpt_latest(const char *dir, char *out, size_t len, char *err,
                size_t errlen);

#endif
