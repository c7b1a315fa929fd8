/*
** material.c - what every material shares: density and elastic moduli.
*/
#include <math.h>
#include <string.h>
#include "material.h"

int material_init(material *m, const mat_model *model, const char *name,
                  double rho, double K, double G) {
  memset(m, 0, sizeof *m);
  m->model = model;
  strncpy(m->name, name ? name : model->name, sizeof m->name - 1);
  if (!(rho > 0) || !(K > 0) || !(G > 0)) return -1;
  m->rho = rho;
  m->K = K;
  m->G = G;
  m->lambda = K - 2.0 * G / 3.0;
  m->c = sqrt((K + 4.0 * G / 3.0) / rho);
  return 0;
}
