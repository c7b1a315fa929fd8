/*
** particles.h - the particle store: structure of arrays plus a field
** table (name, components, unit, flags) that drives HDF5 output,
** restart and the Lua views without any of them knowing the fields.
*/
#ifndef mvmpm_particles_h
#define mvmpm_particles_h

#include <stddef.h>
#include <stdint.h>
#include "dim.h"

#define PF_MAXCOMP 9
#define PF_MAXFIELDS 48

enum pf_type { PF_DOUBLE, PF_INT32 };
enum pf_flags {
  PF_OUTPUT = 1, /* written to snapshots */
  PF_RESTART = 2, /* part of a checkpoint */
  PF_READ = 4     /* filled from a file's dataset (out_h5_read): a field
                     the file lacks is left zero without it */
};

typedef struct pfield {
  char name[32];
  char unit[16];
  int ncomp;
  int type;
  unsigned flags;
  const char *comp_names[PF_MAXCOMP]; /* optional, e.g. "xx","yy" */
  void **slot[PF_MAXCOMP]; /* where each component's array pointer lives */
  void *own[PF_MAXCOMP];   /* storage of fields registered at run time */
} pfield;

/*
** Every array is allocated with cap * 8 bytes whatever its type, so the
** sort can swap any array with the one scratch buffer.
*/
typedef struct particles {
  size_t n, cap;
  size_t nmade;        /* particles ever made (the next id) */
  double *x[DIM];      /* position */
  double *v[DIM];      /* velocity */
  double *m;           /* mass */
  double *vol0;        /* initial volume */
  double *F[NTENS];    /* deformation gradient, row major */
  double *L[NTENS];    /* velocity gradient of the last step */
  double *s[NSTRESS];  /* Cauchy stress (tension positive) */
  double *lp;          /* half particle size in cell units (GIMP) */
  int32_t *body;       /* body index */
  int32_t *cell;       /* cell index of the last sort */
  int32_t *id;         /* creation order, 1-based: the sort by cell moves
                          particles, the id follows each one */
  pfield fields[PF_MAXFIELDS];
  int nfields;
  void *scratch;       /* cap * 8 bytes, for sorting */
  size_t *perm;        /* cap sources, for sorting */
  size_t *count;       /* per-cell counts for the sort, ncell + 1 */
  size_t ncount;
} particles;

void particles_init(particles *ps);
void particles_free(particles *ps);
/* make room for at least cap particles; 0 on success, -1 out of memory */
int particles_reserve(particles *ps, size_t cap);
/* give back the capacity beyond n (seeding grows it by doubling) */
void particles_fit(particles *ps);
/* register a run-time field (zero filled); returns its index or -1 */
int particles_add_field(particles *ps, const char *name, int ncomp,
                        int type, const char *unit, unsigned flags);
/* find a field by name; -1 if absent */
/* a field read back from a file: its component names from the file's
** comma-joined list, when it is one of the engine's sets (x,y / xx,xy,..
** / the stress's); 1 if named, 0 if not */
int particles_name_comps(pfield *f, const char *joined);
/* the name of component c of a full tensor (F, gradv): "xx", "xy", ... */
const char *particles_tens_name(int c);
int particles_find(const particles *ps, const char *name);
/* pointer to component c of field f */
static inline void *particles_comp(const particles *ps, int f, int c) {
  return *ps->fields[f].slot[c];
}
/* append one particle with zeroed state and F = I; returns its index */
size_t particles_push(particles *ps);
/* stable counting sort by cell index (key[i] in [0, ncell)); the arrays
** are moved by the threads of p (NULL: the caller), each taking a
** stretch of destinations, so the result does not depend on how many */
struct par;
int particles_sort(particles *ps, const int32_t *key, size_t ncell,
                   struct par *p);
/* bytes the store holds: every array at capacity, and the sort buffers */
size_t particles_mem(const particles *ps);
/* drop particles with keep[i] == 0, keeping order */
size_t particles_compact(particles *ps, const unsigned char *keep);

#endif
