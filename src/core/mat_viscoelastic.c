/*
** mat_viscoelastic.c - generalized Maxwell solid (Prony series in shear)
** for the binder:
**   G(t) = G_inf + sum_k G_k exp(-t / tau_k),   elastic bulk modulus K.
** The stress is p I + s_inf + sum_k s_k: the pressure and the long-term
** deviator s_inf grow hypoelastically (p' = K tr D, s_inf' = 2 G_inf d),
** and each element follows s_k' = 2 G_k d - s_k / tau_k, d the deviator
** of D (in plane strain d_zz = -tr D / 3).  Only the s_k are stored; s_inf
** is what the total stress leaves over.
**
** Over a step the deviatoric rate d is taken constant, so each element
** integrates exactly:
**   s_k <- e s_k + 2 G_k tau_k (1 - e) d,   e = exp(-dt / tau_k)
** which stays stable and accurate for dt >> tau_k (the element simply
** sits at its steady state 2 G_k tau_k d).  The element stresses rotate
** with the same objective rotation as the stress, before the update.
**
** Dissipation of element k over the step is the exact integral of
** s_k : s_k / (2 G_k tau_k) along that same exponential path,
** s(t) = x E + 2 G tau d (1 - E), E = exp(-t / tau), x the start value:
**   int |s|^2 dt / (2 G tau) = |x|^2 tau (1 - e^2) / (4 G tau)
**                            + x:d tau (1 - e)^2 + |d|^2 2 G tau^2 f(dt/tau)
** with f(u) = u - 2 (1 - e^-u) + (1 - e^-2u) / 2 = u^3/3 - u^4/4 + ...,
** summed as its series for small u where the closed form cancels.
** It is kept per unit reference volume in "viscous_work" (like the
** stored energy) and summed into the energy budget.  Stored energy:
** p^2/(2K) + |s_inf|^2/(4 G_inf) + sum |s_k|^2/(4 G_k).
**
** All of it is written for the Kirchhoff stress tau = J sigma
** (material.h): p, s_inf and the s_k are parts of tau, the element
** stresses stored as such, and the stored energy and the dissipation are
** per reference volume, exact against the grid's work at any strain.
**
** Element stresses are deviatoric, so each is stored without its zz
** (= -(xx + yy)): xx, yy, xy in 2-D, xx, yy, xy, yz, xz in 3-D, in the fields "maxwell1" .. "maxwellN", one per element
** the material has; materials share them by name.
*/
#include <math.h>
#include <stdio.h>
#include "material.h"

#define F_VW MAT_MAXPRONY   /* field slot of viscous_work */

static const char *const slot_names[NSTRESS] = DIM_STRESS_NAMES;

static int setup(material *m, particles *ps) {
  int k, c;
  for (k = 0; k < m->nprony; k++) {
    char name[16];
    int f;
    snprintf(name, sizeof name, "maxwell%d", k + 1);
    f = particles_add_field(ps, name, MAT_NDEV, PF_DOUBLE, "M/(L T^2)",
                            PF_OUTPUT | PF_RESTART);
    if (f < 0) return -1;
    for (c = 0; c < MAT_NDEV; c++)
      ps->fields[f].comp_names[c] = slot_names[mat_dev_slot(c)];
    m->field[k] = f;
  }
  m->field[F_VW] = particles_add_field(ps, "viscous_work", 1, PF_DOUBLE,
                                       "M/(L T^2)", PF_OUTPUT | PF_RESTART);
  return m->field[F_VW] < 0 ? -1 : 0;
}

#define ddot mat_ddot

/* element k's stored deviator of particle i, zz restored */
static inline void dev_get(double *const *ak, size_t i, double *x) {
  int c;
  for (c = 0; c < MAT_NDEV; c++) x[mat_dev_slot(c)] = ak[c][i];
  x[S_ZZ] = -(x[S_XX] + x[S_YY]);
}

static void update(const material *m, particles *ps, const int32_t *bmat,
                   int32_t id, double dt, size_t i0, size_t i1,
                   mat_sums *sum) {
  const int n = m->nprony;
  const double K = m->K, g2 = 2.0 * m->G_inf;
  double e[MAT_MAXPRONY], B[MAT_MAXPRONY], k1[MAT_MAXPRONY], k2[MAT_MAXPRONY],
      k3[MAT_MAXPRONY];
  double *a[MAT_MAXPRONY][MAT_NDEV];
  double *vw = particles_comp(ps, m->field[F_VW], 0);
  double *hq = m->fheat >= 0 ? particles_comp(ps, m->fheat, 0) : NULL;
  double s[NSTRESS], D[NSTRESS], d[NSTRESS], strain = 0, power = 0, visc = 0;
  size_t i;
  int k, c;
  /* per-step constants: no exp() per particle */
  for (k = 0; k < n; k++) {
    double tau = m->prony_tau[k], G = m->prony_G[k], u = dt / tau;
    double om = -expm1(-u), f;
    if (u < 1e-3) /* the closed form loses (1e-16 / u) of the work here */
      f = u * u * u * (1.0 / 3 + u * (-1.0 / 4 + u * (7.0 / 60 - u / 24)));
    else
      f = u - 2.0 * om + 0.5 * om * (2.0 - om);
    e[k] = 1.0 - om;
    B[k] = 2.0 * G * tau * om;      /* approach to the steady state 2 G tau d */
    k1[k] = om * (2.0 - om) / (4.0 * G);      /* tau (1 - e^2) / (4 G tau) */
    k2[k] = tau * om * om;
    k3[k] = 2.0 * G * tau * tau * f;
    for (c = 0; c < MAT_NDEV; c++) a[k][c] = particles_comp(ps, m->field[k], c);
  }
  for (i = i0; i < i1; i++) {
    double J, tr, dd, w = 0, en;
    mat_rot rot;
    if (bmat[ps->body[i]] != id) continue;
    mat_get_tau(ps, i, s);
    J = mat_kinematics(ps, i, dt, s, D, &rot);
    /* plane strain: D_zz = 0, so d_zz = -tr D / 3 */
    tr = D[S_XX] + D[S_YY] + D[S_ZZ];
    for (c = 0; c < NSTRESS; c++) d[c] = D[c];
    d[S_XX] = D[S_XX] - tr / 3.0;
    d[S_YY] = D[S_YY] - tr / 3.0;
    d[S_ZZ] = D[S_ZZ] - tr / 3.0;
    dd = ddot(d, d);
    /* pressure and long-term part */
    for (c = 0; c < NSTRESS; c++) s[c] += g2 * dt * d[c];
    s[S_XX] += K * tr * dt; s[S_YY] += K * tr * dt; s[S_ZZ] += K * tr * dt;
    en = 0;
    for (k = 0; k < n; k++) {
      double x[NSTRESS], y[NSTRESS];
      dev_get(a[k], i, x);
      mat_rotate(&rot, x);
      x[S_ZZ] = -(x[S_XX] + x[S_YY]);
      for (c = 0; c < NSTRESS; c++) {
        y[c] = e[k] * x[c] + B[k] * d[c];
        s[c] += y[c] - x[c];
      }
      w += k1[k] * ddot(x, x) + k2[k] * ddot(x, d) + k3[k] * dd;
      en += ddot(y, y) / (4.0 * m->prony_G[k]);
      for (c = 0; c < MAT_NDEV; c++) a[k][c][i] = y[mat_dev_slot(c)];
    }
    vw[i] += w;
    visc += ps->vol0[i] * w;
    if (hq) hq[i] += ps->vol0[i] * w; /* heat.h: all of it is heat */
    mat_put_tau(ps, i, s, J);
    mat_sum_j(sum, J);
    {
      double p, dv[NSTRESS], r;
      (void)mat_deviator(s, &p, dv);
      en += p * p / (2.0 * K);
      if (m->G_inf > 0) {
        for (k = 0; k < n; k++) {
          for (c = 0; c < MAT_NDEV; c++) dv[mat_dev_slot(c)] -= a[k][c][i];
          dv[S_ZZ] += a[k][0][i] + a[k][1][i];
        }
        r = ddot(dv, dv);
        en += r / (4.0 * m->G_inf);
      }
    }
    strain += ps->vol0[i] * en;
    power += ps->vol0[i] * mat_power(s, D);
  }
  sum->strain += strain;
  sum->power += power;
  sum->viscous += visc;
}

static double energy(const material *m, const particles *ps, size_t i) {
  double s[NSTRESS], dv[NSTRESS], p, en = 0;
  int k;
  mat_get_tau(ps, i, s); /* as update() works */
  (void)mat_deviator(s, &p, dv);
  for (k = 0; k < m->nprony; k++) {
    double *ak[MAT_NDEV], x[NSTRESS];
    int c;
    for (c = 0; c < MAT_NDEV; c++) ak[c] = particles_comp(ps, m->field[k], c);
    dev_get(ak, i, x);
    en += ddot(x, x) / (4.0 * m->prony_G[k]);
    for (c = 0; c < NSTRESS; c++) dv[c] -= x[c];
  }
  en += p * p / (2.0 * m->K);
  if (m->G_inf > 0) en += ddot(dv, dv) / (4.0 * m->G_inf);
  return ps->vol0[i] * en;
}

const mat_model mat_viscoelastic = {"viscoelastic", setup, update, energy};
