/*
** react.c - the reaction phase: single-step Arrhenius kinetics integrated
** per particle with substeps of its own (see react.h for the scheme).
**
** Why the exact solution at a frozen rate: the rate constant is what
** changes by orders of magnitude in a run-away, while at a given rate
** constant the burn of (1 - lambda)^n has a closed form.  Taking that
** form at the substep's midpoint temperature keeps first-order decay at
** constant temperature exact, is second order in the substep when T
** moves, and never overshoots lambda = 1, however stiff the step.
*/
#include <math.h>
#include "heat.h"
#include "par.h"
#include "react.h"

double react_k(const react_law *r, double T) {
  if (r->T_fk > 0) /* Frank-Kamenetskii: exponent linear in T */
    return exp(-r->Ta / r->T_fk + r->Ta * (T - r->T_fk) / (r->T_fk * r->T_fk));
  if (!(T > 0)) return 0;
  return exp(-r->Ta / T);
}

/* lambda after a burn of kh = k h at a constant rate constant */
static double burn(double n, double lam, double kh) {
  double w;
  if (lam >= 1) return 1;
  if (n == 1) return lam - (1 - lam) * expm1(-kh);
  if (n == 0) return lam + kh >= 1 ? 1 : lam + kh;
  /* (1 - lambda)^(1 - n) moves linearly in kh */
  w = pow(1 - lam, 1 - n) - (1 - n) * kh;
  if (n < 1) return w <= 0 ? 1 : 1 - pow(w, 1 / (1 - n));
  return 1 - pow(w, 1 / (1 - n));
}

/* how far the exponent moves between T0 and T1 */
static double swing(const react_law *r, double T0, double T1) {
  if (r->T_fk > 0) return r->Ta * fabs(T1 - T0) / (r->T_fk * r->T_fk);
  if (!(T0 > 0) || !(T1 > 0)) return 0;
  return r->Ta * fabs(T1 - T0) / (T0 * T1);
}

double react_advance(const react_law *r, double cap, double tol, double dt,
                     double *T, double *lam, double lam_ign, double *t_ign,
                     int *nsub) {
  const double B = r->Q / cap, hmin = 1e-12 * dt;
  double t = 0, h = dt, l = *lam, Tp = *T, l0 = *lam;
  int ns = 0;
  while (t < dt && l < 1) {
    double l1, Tm, T1, phi;
    int it;
    if (h > dt - t || ns == REACT_MAXSUB - 1) h = dt - t;
    l1 = burn(r->n, l, r->Z * react_k(r, Tp) * h);
    for (it = 0; it < 2; it++) { /* the midpoint temperature, by Picard */
      Tm = Tp + 0.5 * B * (l1 - l);
      l1 = burn(r->n, l, r->Z * react_k(r, Tm) * h);
    }
    T1 = Tp + B * (l1 - l);
    phi = swing(r, Tp, T1);
    if (phi > tol && h > hmin && ns < REACT_MAXSUB - 1) {
      h *= fmax(0.1, 0.9 * tol / phi); /* refused: shorter */
      continue;
    }
    if (lam_ign > 0 && l < lam_ign && l1 >= lam_ign)
      *t_ign = t + h * (lam_ign - l) / (l1 - l);
    l = l1;
    Tp = T1;
    t += h;
    ns++;
    if (phi < 0.5 * tol) h *= 2;
  }
  *T = Tp;
  *lam = l;
  *nsub = ns;
  return l - l0;
}

int react_enable(sim *s) {
  if (heat_enable(s)) return -1; /* the reaction's heat goes through heat.h */
  if (s->freact < 0) {
    s->freact = particles_add_field(&s->ps, "reacted", 1, PF_DOUBLE, "1",
                                    PF_OUTPUT | PF_RESTART);
    if (s->freact < 0) return -1;
  }
  s->react_on = 1;
  return 0;
}

/* per chunk of particles (par.h): heat released, most substeps, first
** crossing of the ignition fraction */
typedef struct react_sums { double heat, tign; int nsub; } react_sums;
_Static_assert(sizeof(react_sums) <= SIM_RED_BYTES, "react_sums fit");

static void react_part(void *arg, int t, int nparts) {
  sim *s = arg;
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  particles *ps = &s->ps;
  const double *T = particles_comp(ps, s->ftemp, 0);
  const double *q = particles_comp(ps, s->heat->fq, 0);
  const double *Tg = s->heat->conduct ? s->heat->tgrid : NULL;
  double *lam = particles_comp(ps, s->freact, 0);
  react_sums *red = wk->red;
  size_t n = ps->n, c, c0, c1, i, i0, i1;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    react_sums z = {0, INFINITY, 0};
    par_chunk(n, c, &i0, &i1);
    for (i = i0; i < i1; i++) {
      int32_t mi = s->bmat[ps->body[i]];
      const material *m;
      double tig = INFINITY, dl, Ti, qi;
      int ns;
      if (mi < 0) continue;
      m = &s->mats[mi];
      if (m->rx.Z == 0 || lam[i] >= 1) continue;
      /* from the temperature the step's other heat leads to (heat_update
      ** adds it after this phase); a held body keeps its own.  Under
      ** conduction the temperature is the grid's field at the particle
      ** (conduct.c's tgrid): conduction resolves no structure below the
      ** cell, and a particle's own deviation from that field, which
      ** conduction never smooths, would otherwise be amplified by the
      ** rate on the adiabatic time scale (docs/algorithm.md) */
      if (s->bodies[ps->body[i]].hold) Ti = T[i];
      else Ti = (Tg ? Tg[i] : T[i]) + q[i] / (ps->m[i] * m->cv);
      dl = react_advance(&m->rx, m->cv, cfg->react_tol, s->dt, &Ti, &lam[i],
                         cfg->react_ign, &tig, &ns);
      qi = ps->m[i] * m->rx.Q * dl;
      heat_add(s, i, qi); /* T reaches Ti in heat_update */
      z.heat += qi;
      if (tig < z.tign) z.tign = tig;
      if (ns > z.nsub) z.nsub = ns;
    }
    red[c] = z;
  }
}

void react(sim *s) {
  sim_work *wk = &s->work;
  const react_sums *red = wk->red;
  size_t c, nc = par_nchunks(s->ps.n);
  double tign = INFINITY;
  int nsub = 0;
  par_run(wk->par, react_part, s);
  for (c = 0; c < nc; c++) { /* chunk order: any thread count */
    s->e.chemical += red[c].heat;
    s->e.heat_source += red[c].heat;
    if (red[c].tign < tign) tign = red[c].tign;
    if (red[c].nsub > nsub) nsub = red[c].nsub;
  }
  s->react_nsub = nsub;
  if (tign < INFINITY && !(s->t_ignition < INFINITY))
    s->t_ignition = s->t + tign;
}

double react_mean(const sim *s) {
  const particles *ps = &s->ps;
  const double *lam;
  double ml = 0, mt = 0;
  size_t i;
  if (s->freact < 0) return 0;
  lam = particles_comp(ps, s->freact, 0);
  for (i = 0; i < ps->n; i++) {
    int32_t mi = s->bmat[ps->body[i]];
    if (mi < 0 || s->mats[mi].rx.Z == 0) continue;
    ml += ps->m[i] * lam[i];
    mt += ps->m[i];
  }
  return mt > 0 ? ml / mt : 0;
}
