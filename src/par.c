/*
** par.c - the worker pool.  One mutex and two condition variables: a job
** is published under the mutex with a new generation number and the
** workers woken; each runs its part, and the last to finish wakes the
** caller.  The mutex orders memory both ways, so the job's fields are
** seen by every worker and every part's writes are seen by the caller
** after par_run.  POSIX threads from the C library rather than OpenMP:
** see docs/performance.md (licence of the OpenMP runtime).
*/
#include <pthread.h>
#include <stdlib.h>
#include "par.h"

struct worker { struct par *p; int t; };

struct par {
  int n;             /* threads, the caller included */
  int started;       /* workers made (1 .. started - 1) */
  int quit;
  int sync;          /* mutex and conditions made */
  unsigned long gen; /* job number */
  int pending;       /* workers still running the current job */
  par_fn fn;
  void *arg;
  pthread_mutex_t mu;
  pthread_cond_t wake, idle;
  pthread_t tid[PAR_MAX];
  struct worker w[PAR_MAX];
};

static void *worker_main(void *a) {
  struct worker *w = a;
  par *p = w->p;
  unsigned long seen = 0;
  for (;;) {
    par_fn fn;
    void *arg;
    int n;
    pthread_mutex_lock(&p->mu);
    while (p->gen == seen && !p->quit) pthread_cond_wait(&p->wake, &p->mu);
    if (p->quit) { pthread_mutex_unlock(&p->mu); break; }
    seen = p->gen;
    fn = p->fn; arg = p->arg; n = p->n;
    pthread_mutex_unlock(&p->mu);
    fn(arg, w->t, n);
    pthread_mutex_lock(&p->mu);
    if (--p->pending == 0) pthread_cond_signal(&p->idle);
    pthread_mutex_unlock(&p->mu);
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
  pthread_mutex_lock(&p->mu);
  p->n = p->started = t;
  pthread_mutex_unlock(&p->mu);
  return p;
}

void par_free(par *p) {
  int t;
  if (!p) return;
  if (p->started > 1) {
    pthread_mutex_lock(&p->mu);
    p->quit = 1;
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

void par_run(par *p, par_fn fn, void *arg) {
  if (!p || p->n == 1) { fn(arg, 0, 1); return; }
  pthread_mutex_lock(&p->mu);
  p->fn = fn;
  p->arg = arg;
  p->pending = p->n - 1;
  p->gen++;
  pthread_cond_broadcast(&p->wake);
  pthread_mutex_unlock(&p->mu);
  fn(arg, 0, p->n);
  pthread_mutex_lock(&p->mu);
  while (p->pending > 0) pthread_cond_wait(&p->idle, &p->mu);
  pthread_mutex_unlock(&p->mu);
}
