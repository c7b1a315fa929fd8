/*
** lckpt.h - checkpoints of a run driven from Lua: the simulation's state
** through ckpt.h (the io layer, which needs no Lua state), and the run's
** own numbers beside it: the output and checkpoint schedule, the
** sim:every callbacks' next times, the XDMF entries so far, the --set
** overrides, the scene's path and text, and sim:state's table (lstate.h).
** The file is described in ckpt.h.
*/
#ifndef mvmpm_lckpt_h
#define mvmpm_lckpt_h

#include "ckpt.h"
#include "lua.h"

/* write the next checkpoint of the simulation at simidx into its output
** directory (between steps only); raises a Lua error naming the file
** and the reason when it cannot.  ls->ck_last names it afterwards. */
void ckpt_write(lua_State *L, int simidx);

/* put the checkpoint's state into the simulation at simidx, loaded again
** from the same scene with the same parameters: ckpt_restore, then the
** run's numbers, XDMF entries and sim:state; 0, or -1 with err saying
** what does not match or lies outside what the engine allows */
int ckpt_apply(lua_State *L, int simidx, const ckpt *c, char *err,
               size_t errlen);
/* the --set overrides in force as a checkpoint stores them (malloc'ed;
** NULL when out of memory) */
char *ckpt_overrides(lua_State *L);

#endif
