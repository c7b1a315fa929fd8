/*
** prof.h - wall time per phase of the step, for `mvmpm run --profile`.
** sim_step and run.c mark the end of each phase; the time since the
** last mark goes to that phase.  With profiling off (s->work.prof NULL) a
** mark is one test; with it on, one clock_gettime per phase per step.
*/
#ifndef mvmpm_prof_h
#define mvmpm_prof_h

#include <stdio.h>
#include <time.h>
#include "par.h"

enum prof_phase {
  PROF_P2G,      /* grid reset, shared-node marking, particles to grid */
  PROF_SOLVE,    /* grid momentum and velocity loops */
  PROF_CONTACT,  /* normals, reach, bonds, contact correction */
  PROF_SIDES,    /* walls and driven bodies */
  PROF_G2P,      /* grid to particles */
  PROF_REMAP,    /* MUSL remap and second pass */
  PROF_CONST,    /* constitutive update, thermal phase */
  PROF_HEAT,     /* heat: friction heat, conduction, temperature update */
  PROF_HOUSE,    /* time step, removal of lost particles, sort */
  PROF_DIAG,     /* Lua drives, CSV row, callbacks */
  PROF_OUTPUT,   /* snapshots, progress, checkpoints */
  PROF_N
};

/* Besides the wall time, per phase the CPU time the threads spent in it
** (cpu) and the time it would take on idle cores (crit: the serial code
** plus, for each threaded job, its longest part), from the pool's
** accounting (par_account) and the calling thread's CPU clock.  The
** ratio of a one-thread run's crit to a two-thread run's is the speed-up
** the code allows, whatever else the machine runs. */
typedef struct sim_prof {
  double t[PROF_N]; /* seconds per phase */
  double cpu[PROF_N], crit[PROF_N];
  double last;      /* clock at the last mark */
  double tc, work, cr, own; /* the CPU clocks at the last mark */
  long steps;
} sim_prof;

extern const char *const prof_names[PROF_N];

struct sim;
/* the effects the engine derived from the scene, one per line */
void prof_effects(FILE *f, const struct sim *s);
/* seconds and shares per phase (nothing without s->work.prof) */
void prof_report(FILE *f, const struct sim *s);

static inline double prof_clock(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
/* start timing from now */
static inline void prof_start(struct sim_prof *p) {
  if (p) {
    p->last = prof_clock();
    p->tc = par_thread_cpu();
    par_cpu(&p->work, &p->cr, &p->own);
  }
}
/* the time since the last mark was spent in phase k */
static inline void prof_mark(struct sim_prof *p, int k) {
  if (p) {
    double now = prof_clock(), tc = par_thread_cpu(), w, c, o, serial;
    par_cpu(&w, &c, &o);
    serial = (tc - p->tc) - (o - p->own);
    p->t[k] += now - p->last;
    p->cpu[k] += serial + (w - p->work);
    p->crit[k] += serial + (c - p->cr);
    p->last = now;
    p->tc = tc;
    p->work = w;
    p->cr = c;
    p->own = o;
  }
}

#endif
