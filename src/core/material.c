/*
** material.c - what every material shares: density and elastic moduli.
*/
#include <math.h>
#include <string.h>
#include "material.h"

int material_init(material *m, const mat_model *model, const char *name,
                  double rho, double K, double G) {
  memset(m, 0, sizeof *m);
  m->fheat = -1;
  m->beta = 0.9;
  m->model = model;
  strncpy(m->name, name ? name : model->name, sizeof m->name - 1);
  if (!(rho > 0) || !(K > 0) || !(G > 0)) return -1;
  m->rho = rho;
  m->K = K;
  m->G = G;
  m->lambda = K - 2.0 * G / 3.0;
  m->c = sqrt((K + 4.0 * G / 3.0) / rho);
  m->beta = 0.9; /* Taylor-Quinney: the common default for metals */
  m->fheat = -1;
  return 0;
}

int material_plastic(material *m, const char *name, double rho, double K,
                     double G, double yield, double hardening) {
  if (material_init(m, &mat_plastic, name, rho, K, G)) return -1;
  if (!(yield > 0) || !(hardening >= 0) || !isfinite(yield) ||
      !isfinite(hardening))
    return -1;
  m->yield = yield;
  m->hardening = hardening;
  return 0;
}

int material_viscoelastic(material *m, const char *name, double rho,
                          double K, double G_inf, int n, const double *G,
                          const double *tau) {
  double Gg = G_inf;
  int k;
  if (n < 0 || n > MAT_MAXPRONY || !(G_inf >= 0)) return -1;
  for (k = 0; k < n; k++) {
    if (!(G[k] > 0) || !(tau[k] > 0) || !isfinite(tau[k])) return -1;
    Gg += G[k];
  }
  /* the glassy modulus sets the wave speed and so the stable step */
  if (material_init(m, &mat_viscoelastic, name, rho, K, Gg)) return -1;
  m->G_inf = G_inf;
  m->nprony = n;
  for (k = 0; k < n; k++) {
    m->prony_G[k] = G[k];
    m->prony_tau[k] = tau[k];
  }
  return 0;
}

double material_elastic_energy(const material *m, const particles *ps,
                               size_t i) {
  double s[NSTRESS];
  mat_get_tau(ps, i, s); /* material.h: the energy of tau */
  return ps->vol0[i] * mat_elastic_density(s, m->K, m->G);
}
