/*
** melt.c - the melting cap of friction heating (melt.h): between the
** constitutive update and the reaction, before heat_update.
*/
#include <math.h>
#include <stdio.h>
#include "heat.h"
#include "melt.h"
#include "par.h"

int melt_enable(sim *s) {
  if (!s->heat) {
    snprintf(s->err, sizeof s->err, "T_melt needs heat on (sim:heat{})");
    return -1;
  }
  if (s->fmelt < 0) {
    s->fmelt = particles_add_field(&s->ps, "heat_friction_seen", 1, PF_DOUBLE,
                                   "M L^2/T^2", PF_RESTART);
    if (s->fmelt < 0) {
      snprintf(s->err, sizeof s->err, "out of memory");
      return -1;
    }
  }
  return 0;
}

static void melt_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  particles *ps = &s->ps;
  const double *T = particles_comp(ps, s->ftemp, 0);
  const double *qf = particles_comp(ps, s->heat->ffric, 0);
  const double *qc = s->heat->conduct ? s->heat->hcond : NULL;
  double *q = particles_comp(ps, s->heat->fq, 0);
  double *seen = particles_comp(ps, s->fmelt, 0);
  double *red = wk->red;
  size_t n = ps->n, c, c0, c1, i, i0, i1;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    double latent = 0;
    par_chunk(n, c, &i0, &i1);
    for (i = i0; i < i1; i++) {
      int32_t mi = s->bmat[ps->body[i]];
      const material *m;
      double fr = qf[i] - seen[i], mc, over, cut;
      seen[i] = qf[i];
      if (mi < 0 || !(fr > 0) || s->bodies[ps->body[i]].hold) continue;
      m = &s->mats[mi];
      if (!(m->T_melt > 0)) continue;
      mc = ps->m[i] * m->cv;
      over = T[i] + (q[i] + (qc ? qc[i] : 0)) / mc - m->T_melt;
      if (!(over > 0)) continue;
      cut = fmin(fr, over * mc);
      q[i] -= cut;
      latent += cut;
    }
    red[c] = latent;
  }
}

void melt(sim *s) {
  sim_work *wk = &s->work;
  const double *red = wk->red;
  size_t c, nc = par_nchunks(s->ps.n);
  par_run(wk->par, melt_part, s);
  for (c = 0; c < nc; c++) s->e.latent += red[c]; /* chunk order */
}
