/*
** mat_elastic.c - isotropic linear elasticity in rate form:
**   tau' = lambda tr(D) I + 2 G D    (tau = J sigma, objective: material.h)
** In plane strain D_zz = 0, so tau_zz grows with lambda tr(D) only.
*/
#include "material.h"

static int setup(material *m, particles *ps) { return 0; }

static void update(const material *m, particles *ps, const int32_t *bmat,
                   int32_t id, double dt, size_t i0, size_t i1,
                   mat_sums *sum) {
  const double lam = m->lambda, g2 = 2.0 * m->G, K = m->K, G = m->G;
  double s[NSTRESS], D[NSTRESS], strain = 0, power = 0;
  size_t i;
  for (i = i0; i < i1; i++) {
    double J;
    mat_rot rot;
    if (bmat[ps->body[i]] != id) continue;
    mat_get_tau(ps, i, s);
    J = mat_kinematics(ps, i, dt, s, D, &rot);
    mat_hooke(s, D, dt, lam, g2);
    mat_put_tau(ps, i, s, J);
    mat_sum_j(sum, J);
    strain += ps->vol0[i] * mat_elastic_density(s, K, G);
    power += ps->vol0[i] * mat_power(s, D);
  }
  sum->strain += strain;
  sum->power += power;
}

const mat_model mat_elastic = {"elastic", setup, update, material_elastic_energy};
