/*
** thermal.c - the thermal phase: temperature changes become hydrostatic
** stress increments (see thermal.h for the plane-strain convention).
**
** Energy: the strain energy changes by the work of the stress on the
** thermal strain, -V alpha dT tr(sigma) (3-D trace), taken at the mean
** stress of the increment, which is exact for the p^2 / (2K) part every
** model stores.  It is summed as e.thermal, an input to the budget
** like boundary work.
*/
#include "par.h"
#include "thermal.h"

int thermal_enable(sim *s) {
  if (s->ftemp >= 0) return 0;
  s->ftemp = particles_add_field(&s->ps, "temperature", 1, PF_DOUBLE, "T",
                                 PF_OUTPUT | PF_RESTART);
  if (s->ftemp < 0) return -1;
  thermal_seed(s, 0, s->ps.n, NULL);
  return 0;
}

void thermal_seed(sim *s, size_t from, size_t to, const double *T0) {
  particles *ps = &s->ps;
  double *T;
  size_t i;
  if (s->ftemp < 0) return;
  T = particles_comp(ps, s->ftemp, 0);
  for (i = from; i < to; i++) {
    int32_t mi = s->bmat[ps->body[i]];
    T[i] = T0 ? *T0 : s->temp_on ? s->temp : mi >= 0 ? s->mats[mi].T_ref : 0;
  }
}

int thermal_uniform(sim *s, double T) {
  if (thermal_enable(s)) return -1;
  s->temp_on = 1;
  s->temp = T;
  if (!s->started) thermal_seed(s, 0, s->ps.n, &T);
  return 0;
}

/* add -3 K alpha dT to the normal Kirchhoff stresses of particle i
** (material.h: the models' stress is tau = J sigma); the work of the
** increment at its mean stress, per reference volume as the models'
** stored energy */
double thermal_strain(const material *m, particles *ps, size_t i, double dT) {
  const double J = mat_jacobian(ps, i), ds = -3.0 * m->K * m->alpha * dT;
  const double tr = J * (ps->s[S_XX][i] + ps->s[S_YY][i] + ps->s[S_ZZ][i]);
  const double dsig = ds / J; /* the Cauchy stress's share */
  ps->s[S_XX][i] += dsig;
  ps->s[S_YY][i] += dsig;
  ps->s[S_ZZ][i] += dsig;
  return -ps->vol0[i] * m->alpha * dT * (tr + 1.5 * ds);
}

void thermal_prestress(sim *s) {
  particles *ps = &s->ps;
  const double *T = particles_comp(ps, s->ftemp, 0);
  size_t i;
  for (i = 0; i < ps->n; i++) {
    int32_t mi = s->bmat[ps->body[i]];
    if (mi < 0 || s->mats[mi].alpha == 0 || T[i] == s->mats[mi].T_ref) continue;
    thermal_strain(&s->mats[mi], ps, i, T[i] - s->mats[mi].T_ref);
  }
}

/* whole chunks of particles (par.h), the work summed per chunk */
static void thermal_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  particles *ps = &s->ps;
  double *T = particles_comp(ps, s->ftemp, 0), *red = wk->red;
  const double Tn = s->temp;
  size_t n = ps->n, c, c0, c1, i, i0, i1;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    double work = 0;
    par_chunk(n, c, &i0, &i1);
    for (i = i0; i < i1; i++) {
      int32_t mi = s->bmat[ps->body[i]];
      double dT = Tn - T[i];
      T[i] = Tn;
      if (mi < 0 || s->mats[mi].alpha == 0 || dT == 0) continue;
      work += thermal_strain(&s->mats[mi], ps, i, dT);
    }
    red[c] = work;
  }
}

/* the chunks' work added in chunk order: the same for any thread count */
void thermal(sim *s) {
  sim_work *wk = &s->work;
  const double *red = wk->red;
  size_t c, nc = par_nchunks(s->ps.n);
  par_run(wk->par, thermal_part, s);
  for (c = 0; c < nc; c++) s->e.thermal += red[c];
}
