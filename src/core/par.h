/*
** par.h - a small pool of worker threads (POSIX threads).
** The workers start once, with the pool, and wait on a barrier; par_run
** hands each of them, and the calling thread, one part of a job and
** returns when every part is done, so no call allocates or starts a
** thread.  A NULL pool, or a pool of one thread, runs the job in the
** caller: code calls par_run the same way whatever the thread count.
**
** Determinism is the caller's business: a job must give the same
** numbers however many parts it is cut into.  par_chunks cuts index
** ranges on fixed chunk boundaries (PAR_CHUNK indices, independent of
** the thread count) so that sums can be kept per chunk and added up in
** chunk order afterwards.
*/
#ifndef mvmpm_par_h
#define mvmpm_par_h

#include <stddef.h>

/* indices per chunk of a reduction: partial sums are kept per chunk */
#define PAR_CHUNK 4096
/* the most threads a pool may have */
#define PAR_MAX 64

typedef struct par par;
/* one part of a job: part t of nparts */
typedef void (*par_fn)(void *arg, int t, int nparts);

/* a pool of n threads in all (the caller counts as one); NULL if the
** threads cannot be made.  n <= 1 makes a pool that runs in the caller */
par *par_new(int n);
void par_free(par *p);
/* threads in the pool (1 for NULL) */
int par_threads(const par *p);
/* run fn(arg, t, n) for t = 0 .. n - 1 at once, t = 0 in the caller;
** returns when all are done (a barrier: their writes are visible) */
void par_run(par *p, par_fn fn, void *arg);

/* CPU accounting, for the profiler (off by default; one test per job
** when off).  With it on, every job measures each part's thread CPU time
** and adds up, over all pools of the process: work, the CPU time of all
** parts; crit, the longest part of each job (what the job takes on idle
** cores); own, the CPU time the calling thread spent in the job (its
** part and its wait).  A thread's CPU time does not count the time it
** was descheduled, so on a shared machine these say what the code costs
** where the wall clock says what the neighbours did. */
void par_account(int on);
void par_cpu(double *work, double *crit, double *own);
/* the calling thread's CPU time (seconds) */
double par_thread_cpu(void);

/* the chunks of n indices */
static inline size_t par_nchunks(size_t n) {
  return (n + PAR_CHUNK - 1) / PAR_CHUNK;
}
/* part t of nparts of [0, n): whole chunks [*c0, *c1) */
static inline void par_chunks(size_t n, int t, int nparts, size_t *c0,
                              size_t *c1) {
  size_t nc = par_nchunks(n);
  *c0 = nc * (size_t)t / (size_t)nparts;
  *c1 = nc * (size_t)(t + 1) / (size_t)nparts;
}
/* the indices of chunk c of n */
static inline void par_chunk(size_t n, size_t c, size_t *i0, size_t *i1) {
  *i0 = c * PAR_CHUNK;
  *i1 = *i0 + PAR_CHUNK < n ? *i0 + PAR_CHUNK : n;
}
/* part t of nparts of [0, n), cut anywhere (no sums across it) */
static inline void par_range(size_t n, int t, int nparts, size_t *i0,
                             size_t *i1) {
  *i0 = n * (size_t)t / (size_t)nparts;
  *i1 = n * (size_t)(t + 1) / (size_t)nparts;
}

#endif
