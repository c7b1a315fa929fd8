/*
** par.c - the worker pool.  A job is published with a new generation
** number; each worker runs its part, and the last to finish tells the
** caller.
**
** Both waits (a worker's for the next job, the caller's for the last
** part) first poll for PAR_SPIN_NS, yielding the core between polls, and
** only then sleep on a condition variable.  The jobs of a step follow
** each other within microseconds, and on this virtual machine a thread
** asleep on a condition variable took 27 us to wake (an empty job cost
** 27 us with sleeping waits, 1.9 us with polling ones, 2 idle cores): a
** step's twenty-odd jobs paid that each time, some 5 % of a grain bed's
** step.  Yielding, not a busy loop, lets a descheduled partner run on a
** busy machine (the empty job cost 10 us sleeping, 4 us polling there).
**
** The generation and the count of running workers are atomics: the
** release on publishing a job and on finishing a part, and the acquire
** on seeing either, order the job's fields and every part's writes.  A
** job is published under the mutex, so a worker between its last poll
** and its sleep cannot miss it; the last part signals under the mutex,
** likewise for the caller.  POSIX threads from the C library rather than
** OpenMP: see docs/performance.md (licence of the OpenMP runtime).
*/
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#include "par.h"

/* CPU accounting (par_account): on or off, and the sums; the parts of
** the current job write their own entries of part[] */
static int acct;
static double acct_work, acct_crit, acct_own;

/* how long a wait polls before it sleeps (nanoseconds) */
#define PAR_SPIN_NS 50000

struct worker { struct par *p; int t; };

struct par {
  int n;               /* threads, the caller included */
  int started;         /* workers made (1 .. started - 1) */
  int sync;            /* mutex and conditions made */
  atomic_int quit;
  atomic_ulong gen;    /* job number */
  atomic_int pending;  /* workers still running the current job */
  par_fn fn;
  void *arg;
  int acct;            /* this job is accounted: parts time themselves */
  double part[PAR_MAX]; /* each part's thread CPU time (accounting) */
  pthread_mutex_t mu;
  pthread_cond_t wake, idle;
  pthread_t tid[PAR_MAX];
  struct worker w[PAR_MAX];
};

double par_thread_cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

void par_account(int on) { acct = on != 0; }

void par_cpu(double *work, double *crit, double *own) {
  *work = acct_work;
  *crit = acct_crit;
  *own = acct_own;
}

static long long now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* the number of the job after seen, or 0 to quit */
static unsigned long next_job(par *p, unsigned long seen) {
  long long t0 = now_ns();
  unsigned long g;
  do {
    g = atomic_load_explicit(&p->gen, memory_order_acquire);
    if (g != seen) return g;
    if (atomic_load_explicit(&p->quit, memory_order_relaxed)) return 0;
    sched_yield();
  } while (now_ns() - t0 < PAR_SPIN_NS);
  pthread_mutex_lock(&p->mu);
  while ((g = atomic_load_explicit(&p->gen, memory_order_acquire)) == seen &&
         !atomic_load_explicit(&p->quit, memory_order_relaxed))
    pthread_cond_wait(&p->wake, &p->mu);
  pthread_mutex_unlock(&p->mu);
  return g != seen ? g : 0;
}

static void *worker_main(void *a) {
  struct worker *w = a;
  par *p = w->p;
  unsigned long seen = 0;
  while ((seen = next_job(p, seen)) != 0) {
    if (p->acct) {
      double c0 = par_thread_cpu();
      p->fn(p->arg, w->t, p->n);
      p->part[w->t] = par_thread_cpu() - c0;
    } else
      p->fn(p->arg, w->t, p->n);
    if (atomic_fetch_sub_explicit(&p->pending, 1, memory_order_acq_rel) == 1) {
      pthread_mutex_lock(&p->mu); /* the last part: the caller may sleep */
      pthread_cond_signal(&p->idle);
      pthread_mutex_unlock(&p->mu);
    }
  }
  return NULL;
}

par *par_new(int n) {
  par *p = calloc(1, sizeof *p);
  int t;
  if (!p) return NULL;
  if (n < 1) n = 1;
  if (n > PAR_MAX) n = PAR_MAX;
  p->n = p->started = 1;
  atomic_init(&p->quit, 0);
  atomic_init(&p->gen, 0);
  atomic_init(&p->pending, 0);
  if (n == 1) return p;
  if (pthread_mutex_init(&p->mu, NULL)) { free(p); return NULL; }
  if (pthread_cond_init(&p->wake, NULL) || pthread_cond_init(&p->idle, NULL)) {
    pthread_mutex_destroy(&p->mu);
    free(p);
    return NULL;
  }
  p->sync = 1;
  /* a thread that cannot be made leaves the pool smaller, not broken:
  ** the result does not depend on the thread count */
  for (t = 1; t < n; t++) {
    p->w[t].p = p;
    p->w[t].t = t;
    if (pthread_create(&p->tid[t], NULL, worker_main, &p->w[t])) break;
  }
  /* the workers read n only in a job, which is published after this */
  p->n = p->started = t;
  return p;
}

void par_free(par *p) {
  int t;
  if (!p) return;
  if (p->started > 1) {
    pthread_mutex_lock(&p->mu);
    atomic_store_explicit(&p->quit, 1, memory_order_relaxed);
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->mu);
    for (t = 1; t < p->started; t++) pthread_join(p->tid[t], NULL);
  }
  if (p->sync) {
    pthread_cond_destroy(&p->wake);
    pthread_cond_destroy(&p->idle);
    pthread_mutex_destroy(&p->mu);
  }
  free(p);
}

int par_threads(const par *p) { return p ? p->n : 1; }

/* the job's sums, after its parts (accounting on) */
static void account(par *p, double c0) {
  double most = p->part[0], all = 0;
  int t;
  for (t = 0; t < p->n; t++) {
    all += p->part[t];
    if (p->part[t] > most) most = p->part[t];
  }
  acct_work += all;
  acct_crit += most;
  acct_own += par_thread_cpu() - c0;
}

/* the caller's wait for the workers' parts */
static void wait_parts(par *p) {
  long long t0 = now_ns();
  do {
    if (atomic_load_explicit(&p->pending, memory_order_acquire) == 0) return;
    sched_yield();
  } while (now_ns() - t0 < PAR_SPIN_NS);
  pthread_mutex_lock(&p->mu);
  while (atomic_load_explicit(&p->pending, memory_order_acquire) > 0)
    pthread_cond_wait(&p->idle, &p->mu);
  pthread_mutex_unlock(&p->mu);
}

void par_run(par *p, par_fn fn, void *arg) {
  double c0 = acct ? par_thread_cpu() : 0;
  if (!p || p->n == 1) {
    fn(arg, 0, 1);
    if (acct) {
      double c = par_thread_cpu() - c0;
      acct_work += c;
      acct_crit += c;
      acct_own += c;
    }
    return;
  }
  /* every worker has finished the last job (pending 0, seen with an
  ** acquire): none reads these fields now */
  p->fn = fn;
  p->arg = arg;
  p->acct = acct;
  atomic_store_explicit(&p->pending, p->n - 1, memory_order_relaxed);
  pthread_mutex_lock(&p->mu);
  atomic_fetch_add_explicit(&p->gen, 1, memory_order_release);
  pthread_cond_broadcast(&p->wake);
  pthread_mutex_unlock(&p->mu);
  fn(arg, 0, p->n);
  if (acct) p->part[0] = par_thread_cpu() - c0;
  wait_parts(p);
  if (acct) account(p, c0);
}
