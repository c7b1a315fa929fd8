/*
** mat_plastic.c - J2 (von Mises) elastic-plastic solid with linear
** isotropic hardening, for the grains.
**
** Elastic predictor: the objective rate form of mat_elastic.c, in the
** Kirchhoff stress tau = J sigma (material.h).  Plastic corrector:
** radial return of the trial deviator onto the yield surface
**   q = sqrt(3/2 s:s) = yield + hardening * ep
** where s is the full 3-D deviator of tau (in plane strain tau_zz is part
** of it) and ep the equivalent plastic strain.  With linear hardening the
** return is closed form: dep = (q_trial - q_y) / (3G + H), and along a
** path of fixed deviatoric direction it reproduces the exact solution
** for any step size (including the step that crosses the yield point).
**
** Plastic work of a step is the flow stress integrated over the plastic
** strain increment, exact for linear hardening:
**   dW = dep (q_y(ep) + H dep / 2)
** It is kept per unit reference volume in the field "plastic_work" and
** summed into the energy budget; like the stored energy (the elastic
** energy of tau, so the elastic part only) it is reckoned per reference
** volume: it is tau : D_p, the work the grid's forces do per reference
** volume on the plastic part of D, at any strain.
*/
#include <math.h>
#include "material.h"

enum { F_EP, F_WP };

static int setup(material *m, particles *ps) {
  m->field[F_EP] = particles_add_field(ps, "plastic_strain", 1, PF_DOUBLE, "1",
                                       PF_OUTPUT | PF_RESTART);
  m->field[F_WP] = particles_add_field(ps, "plastic_work", 1, PF_DOUBLE,
                                       "M/(L T^2)", PF_OUTPUT | PF_RESTART);
  return m->field[F_EP] < 0 || m->field[F_WP] < 0 ? -1 : 0;
}

static void update(const material *m, particles *ps, const int32_t *bmat,
                   int32_t id, double dt, size_t i0, size_t i1,
                   mat_sums *sum) {
  const double lam = m->lambda, g2 = 2.0 * m->G, K = m->K, G = m->G;
  const double y0 = m->yield, H = m->hardening, g3h = 3.0 * G + H;
  double *ep = particles_comp(ps, m->field[F_EP], 0);
  double *wp = particles_comp(ps, m->field[F_WP], 0);
  double *hq = m->fheat >= 0 ? particles_comp(ps, m->fheat, 0) : NULL;
  double s[NSTRESS], D[NSTRESS], d[NSTRESS], strain = 0, power = 0, plastic = 0;
  double heat = 0;
  size_t i;
  for (i = i0; i < i1; i++) {
    double J, p, q, qy;
    mat_rot rot;
    if (bmat[ps->body[i]] != id) continue;
    mat_get_tau(ps, i, s);
    J = mat_kinematics(ps, i, dt, s, D, &rot);
    mat_hooke(s, D, dt, lam, g2); /* the elastic trial stress */
    q = sqrt(1.5 * mat_deviator(s, &p, d));
    qy = y0 + H * ep[i];
    if (q > qy) {
      double dep = (q - qy) / g3h, f = 1.0 - 3.0 * G * dep / q, w;
      int k;
      for (k = 0; k < NSTRESS; k++) s[k] = f * d[k];
      s[S_XX] += p; s[S_YY] += p; s[S_ZZ] += p;
      w = dep * (qy + 0.5 * H * dep);
      ep[i] += dep;
      wp[i] += w;
      plastic += ps->vol0[i] * w;
      if (hq) { /* heat.h: beta of the work heats the particle */
        double hw = m->beta * ps->vol0[i] * w;
        hq[i] += hw;
        heat += hw;
      }
    }
    mat_put_tau(ps, i, s, J);
    mat_sum_j(sum, J);
    strain += ps->vol0[i] * mat_elastic_density(s, K, G);
    power += ps->vol0[i] * mat_power(s, D);
  }
  sum->strain += strain;
  sum->power += power;
  sum->plastic += plastic;
  sum->heat += heat;
}

/* the stored energy is the elastic part of the stress only */
const mat_model mat_plastic = {"plastic", setup, update, material_elastic_energy};
