/*
** prof.h - wall time per phase of the step, for `mvmpm run --profile`.
** sim_step and run.c mark the end of each phase; the time since the
** last mark goes to that phase.  With profiling off (s->prof NULL) a
** mark is one test; with it on, one clock_gettime per phase per step.
*/
#ifndef mvmpm_prof_h
#define mvmpm_prof_h

#include <stdio.h>
#include <time.h>

enum prof_phase {
  PROF_P2G,      /* grid reset, shared-node marking, particles to grid */
  PROF_SOLVE,    /* grid momentum and velocity loops */
  PROF_CONTACT,  /* normals, reach, bonds, contact correction */
  PROF_SIDES,    /* walls and driven bodies */
  PROF_G2P,      /* grid to particles */
  PROF_REMAP,    /* MUSL remap and second pass */
  PROF_CONST,    /* constitutive update, thermal phase */
  PROF_HOUSE,    /* time step, removal of lost particles, sort */
  PROF_DIAG,     /* Lua drives, CSV row, callbacks */
  PROF_OUTPUT,   /* snapshots, progress, checkpoints */
  PROF_N
};

typedef struct sim_prof {
  double t[PROF_N]; /* seconds per phase */
  double last;      /* clock at the last mark */
  long steps;
} sim_prof;

extern const char *const prof_names[PROF_N];

struct sim;
/* the effects the engine derived from the scene, one per line */
void prof_effects(FILE *f, const struct sim *s);
/* seconds and shares per phase (nothing without s->prof) */
void prof_report(FILE *f, const struct sim *s);

static inline double prof_clock(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
/* start timing from now */
static inline void prof_start(struct sim_prof *p) {
  if (p) p->last = prof_clock();
}
/* the time since the last mark was spent in phase k */
static inline void prof_mark(struct sim_prof *p, int k) {
  if (p) {
    double now = prof_clock();
    p->t[k] += now - p->last;
    p->last = now;
  }
}

#endif
