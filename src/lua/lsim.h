/*
** lsim.h - what the Lua bindings share: the simulation userdata and its
** run state (callbacks, drives, output).  Lua objects the simulation
** holds on to live in the userdata's user value, a table with fields
**   mats    material userdata -> material index
**   bodies  array of body userdata
**   every   array of {fn=, time=|steps=, next=}
**   drives  body index -> function(t) returning the velocity
**   sidefn  side index -> function(t) returning the wall velocity
**   temperature  function(t) returning the uniform temperature, or nil
*/
#ifndef mvmpm_lsim_h
#define mvmpm_lsim_h

#include "lua.h"
#include "lauxlib.h"
#include "out_csv.h"
#include "diag_hotspot.h"
#include "out_xdmf.h"
#include "sim.h"

/*
** One binary holds both dimensions (Makefile: the 3-D objects' names
** carry _3d, all but DIMKEEP's).  Each dimension's Lua objects have
** metatables of their own, and the few entry points one dimension calls
** in the other have a name per dimension: N = this one's, O = the other's.
*/
#if DIM == 2
#define LSIM_TAG ""
#define LSIM_OTHER_TAG "3"
#define LSIM_OTHER_DIM 3
#define lmvmpm_enter lmvmpm_enter2
#define lmvmpm_enter_other lmvmpm_enter3
#define lmvmpm_loaded lmvmpm_loaded2
#define lmvmpm_loaded_other lmvmpm_loaded3
#elif DIM == 3
#define LSIM_TAG "3"
#define LSIM_OTHER_TAG ""
#define LSIM_OTHER_DIM 2
#define lmvmpm_enter lmvmpm_enter3
#define lmvmpm_enter_other lmvmpm_enter2
#define lmvmpm_loaded lmvmpm_loaded3
#define lmvmpm_loaded_other lmvmpm_loaded2
#else
#error "lsim.h: DIM must be 2 or 3"
#endif
#define LSIM_MT "mvmpm.sim" LSIM_TAG
#define LBODY_MT "mvmpm.body" LSIM_TAG
#define LMAT_MT "mvmpm.material" LSIM_TAG
#define LSHAPE_MT "mvmpm.shape" LSIM_TAG
#define LSIM_OTHER_MT "mvmpm.sim" LSIM_OTHER_TAG

/* mvmpm.sim{dim = ...} of the other dimension: the module table (the
** registry's "mvmpm.module") takes that dimension's functions, then its
** sim constructor runs on the same arguments (with none, only the module
** changes: mvmpm.load's fresh start).  Weak: a build without the other
** dimension (the stock interpreter's module) has none, and says so */
int lmvmpm_enter2(lua_State *L) __attribute__((weak));
int lmvmpm_enter3(lua_State *L) __attribute__((weak));
/* what loading a scene does to the simulation it made (lmvmpm_load's
** end), for a simulation of this dimension at index idx */
int lmvmpm_loaded2(lua_State *L, int idx, const char *path) __attribute__((weak));
int lmvmpm_loaded3(lua_State *L, int idx, const char *path) __attribute__((weak));

typedef struct lsim {
  sim s;
  int ok;                 /* set-up succeeded, and not closed since */
  int closed;             /* __gc ran: s is released; methods refuse */
  int busy;               /* methods under way that call back into Lua
                          ** holding pointers into s: closing waits */
  /* lattice of seeding points: which body holds each (-1 none) */
  int32_t *occ;
  size_t nocc;
  double *claim;          /* per point: the measure earlier bodies' cut
                          ** volumes took of its sub-cell (lua_body.c) */
  int ncut;               /* bodies seeded with volume = "cut" */
  int fields_single;      /* every body on one field */
  /* output */
  char outdir[1024];
  double out_every, out_next;
  int out_enabled;
  long csv_every;
  csvout csv;
  int csv_open;
  xdmf_entry *snaps;
  int nsnap, snapcap;
  int progress;           /* live progress line (a terminal) */
  char scene[512];        /* scene file, for messages and snapshots */
  char units[32];
  int drives, sidefns, nevery;
  int nat_end;            /* sim:at_end functions */
  double ended;           /* the end time they last ran at (NaN: never) */
  int tempfn;             /* uv.temperature is a function of time */
  /* checkpoints (ckpt.c) */
  double ck_every, ck_next; /* simulated time between them; 0: none */
  int ck_count;           /* written so far (the next is ck_count + 1) */
  int ck_on_interrupt;    /* Ctrl-C: checkpoint, then stop (mvmpm run) */
  int interrupted;        /* the run stopped on Ctrl-C */
  int restarted;          /* the output continues a checkpoint's */
  long csv_resume;        /* restarted: the table's length then, or -1 */
  char ck_last[1100];     /* the newest checkpoint written */
  int advised;            /* sim_advice was printed (once, at the first run) */
  /* the energy budget's residual: warned once when it passes
  ** warn_residual (a fraction of the energy scale; 0: never) */
  double warn_residual;
  int warn_given;         /* sim:output{warn_residual = } was given */
  int warned;
  double e_peak;          /* the largest kinetic + strain seen */
  char failed[1100];      /* the state written when a guard stopped the run */
  /* sim:output{hotspots = }: the threshold and link of the per-snapshot
  ** table and the diagnostics columns (lua_hotspot.c) */
  int hs_on;
  double hs_threshold, hs_link;
  hotspots hs;            /* the regions of the last search, reused */
  int budgeted;           /* sim_budget_advice was printed */
} lsim;

typedef struct lbody {
  lsim *ls;
  int idx;
} lbody;

/* What a run may need before it is refused as one that would not end.
** A run to an end time (mvmpm run, sim:run) may take LSIM_MAX_STEPS
** steps.  A value as it enters (a material, a velocity, a fixed dt) is
** held to LSIM_MAX_SPAN: a scene may set a t_end it never means to reach
** and step by hand (sim:step), so the entry check refuses only a step so
** small against t_end that time itself stops advancing in doubles (near
** 2^52 steps t + dt rounds to t); the run's own check comes when it runs */
#define LSIM_MAX_STEPS 1e12   /* steps of a run to its end */
#define LSIM_MAX_SPAN 1e15    /* steps across t_end, where a value enters */
#define LSIM_MAX_EVENTS 1e9   /* outputs, checkpoints, calls of a callback */

/* lua_sim.c */
/* push a rotation vector q[3] (angular momentum, spin): in 2-D the
** number q[2] (its z component, the only one), in 3-D a table {x, y, z}
** (as_table) or the three numbers; returns how many values it pushed */
int lsim_push_rot(lua_State *L, const double *q, int as_table);
extern const char *const lsim_side_names[];  /* "left", "right", ... */
/* refuse a velocity v (DIM components) that the step cannot follow: its
** CFL step would need more than LSIM_MAX_SPAN steps to t_end.  fnidx: the
** scene function that gave it (the error names where it was defined), or
** 0 (the calling scene line); what names it, formatted only on failure */
void lsim_check_speed(lua_State *L, lsim *ls, const double *v, int fnidx,
                      const char *fmt, ...) __attribute__((format(printf, 5, 6)));
/* refuse an interval every (> 0) that makes more than LSIM_MAX_EVENTS
** events in a span of simulated time; what names it for the message */
/* a bond strength (field 'field' of 'what') that the cohesive law
** (sim.bond_energy) would open by more than half a cell before it gives
** out is refused (lua_sim.c says why) */
void lsim_check_cohesion(lua_State *L, const sim *s, double strength,
                         const char *what, const char *field);
void lsim_check_every(lua_State *L, const char *what, double every,
                      double span);
/* the simulation at idx, set up and not closed, else a Lua error */
lsim *lsim_check(lua_State *L, int idx);
/* mark ls busy until the calling C function returns or raises: pushes a
** to-be-closed value, so call it where the stack above it is free */
void lsim_hold(lua_State *L, lsim *ls);
/* every engine metatable: getmetatable gives this, not the table */
void lsim_lock(lua_State *L, int mtidx);
int lsim_new(lua_State *L);
/* sim{dim = N} at idx: N (absent: DIM) must be this build's DIM, else a
** Lua error naming the build's dimension; returns DIM */
int lsim_dim_check(lua_State *L, int idx);
int lsim_env_threads(void);                  /* $MVMPM_THREADS or 1 */                 /* mvmpm.sim{...} */
void lsim_open(lua_State *L);
void lsim_uv(lua_State *L, int idx, const char *field); /* push uv.field */
/* lua_body.c */
int lbody_new(lua_State *L);                /* sim:body{...} */
void lbody_open(lua_State *L);
int lbody_push(lua_State *L, int simidx, int b);
/* the body at idx, of the simulation ls (what names the caller in the
** message): a body of another simulation, or of a closed one, raises */
lbody *lbody_check(lua_State *L, int idx, const lsim *ls, const char *what);
/* lua_material.c */
void lmat_open(lua_State *L, int modidx);
material *lmat_check(lua_State *L, int idx);
/* lua_shape.c: regions bodies are seeded from.  disk is a ball in 3-D,
** annulus a spherical shell, rect a box; cylinder runs from a base point
** to an end point; extrude (3-D) is a polygon swept along an axis */
enum { SH_DISK, SH_ANNULUS, SH_RECT, SH_POLYGON, SH_REST, SH_FUNC,
       SH_CYLINDER, SH_EXTRUDE };
typedef struct lshape {
  int kind;
  double c[DIM], r, r0;      /* disk / annulus: centre, outer, inner radius;
                             ** cylinder: base point, radius */
  double ax[DIM], len;       /* cylinder: unit axis, length */
  int axis, p0, p1;          /* extrude: the axis, the polygon's two axes */
  double lo[DIM], hi[DIM];   /* bounding box (rect: the rectangle) */
  int npts;                  /* polygon vertices, stored after the struct */
  double pts[];
} lshape;
void lshape_open(lua_State *L, int modidx);
lshape *lshape_check(lua_State *L, int idx);
/* is (x) inside the shape at idx?  SH_FUNC calls the Lua function */
int lshape_inside(lua_State *L, int idx, const lshape *sh, const double *x);
/* the shape's area (2-D) or volume (3-D); < 0 if not known */
double lshape_area(const lshape *sh);
/* lua_thermal.c: sim:temperature(T | function(t)) */
int lsim_temperature(lua_State *L);
/* lua_hotspot.c: sim:hotspots{...}; the options table {threshold, link};
** the diagnostics columns; the file beside snapshot k */
int lsim_hotspots(lua_State *L);
void lsim_hotspot_opts(lua_State *L, int idx, const char *what, double *T,
                       double *link);
void lsim_hotspot_row(lua_State *L, lsim *ls, double *count, double *frac);
void lsim_hotspot_file(lua_State *L, lsim *ls, int k);
double lsim_temperature_at(lua_State *L, int simidx, double t);
/* lua_heat.c: sim:heat{...} */
int lsim_heat(lua_State *L);
/* lua_render.c: sim:render{...} and mvmpm.plot{...} */
int lrender_sim(lua_State *L);
void lrender_open(lua_State *L, int modidx);
/* run.c */
int run_until(lua_State *L, int simidx, double t_end, long max_steps);
/* refuse a run to t_end that would need more than LSIM_MAX_STEPS steps
** of the step it would start with (fixed, or the CFL step) */
void run_check_steps(lua_State *L, lsim *ls, double t_end);
/* a new run's directory: one holding another run's outputs (snapshots,
** particles.xmf, diagnostics.csv, checkpoints, failed states) is refused
** unless overwrite, which removes those files and no other; 0, or -1
** with err */
int run_claim_outdir(const char *dir, int overwrite, char *err,
                     size_t errlen);
/* mkdir -p; 0, or -1 with err naming the directory and the reason */
int run_mkdirs(const char *path, char *err, size_t errlen);
/* flush the diagnostics table to disk; its length in bytes, -1 if none */
long run_sync(lua_State *L, lsim *ls);
int run_snapshot(lua_State *L, lsim *ls, const char *path);
/* fill prov (version, build, command, params, restarted
** from); pushes 3 values that hold the strings: pop them after writing */
struct h5prov;
void run_provenance(lua_State *L, struct h5prov *prov);
/* the domain and the bodies' names and driven flags for a snapshot or a
** checkpoint (out_h5.h); 0, or -1 if out of memory.  Release with
** out_h5_frame_free (also after a failure). */
struct h5frame;
int run_frame(const sim *s, struct h5frame *fr);

#endif
