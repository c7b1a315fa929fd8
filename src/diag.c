/*
** diag.c - per-body diagnostics.  The spin is the rigid-body fit
**   omega = L_c / I_c,  L_c = sum m (r x v),  I_c = sum m (|r|^2 + a^2/6)
** with r relative to the centroid and a the particle's side, so a
** seeded disc's I_c matches the continuum m R^2 / 2 closely.
*/
#include <string.h>
#include "diag.h"

int diag_bodies(const sim *s, bdiag *out) {
  const particles *ps = &s->ps;
  const double a = 2.0 * s->lp * s->g.h;
  size_t i;
  int b, d;
  memset(out, 0, (size_t)s->nbody * sizeof *out);
  for (i = 0; i < ps->n; i++) {
    bdiag *o = &out[ps->body[i]];
    double m = ps->m[i], v2 = 0;
    int32_t mi = s->bmat[ps->body[i]];
    o->n++;
    o->mass += m;
    for (d = 0; d < DIM; d++) {
      o->x[d] += m * ps->x[d][i];
      o->v[d] += m * ps->v[d][i];
      v2 += ps->v[d][i] * ps->v[d][i];
    }
    o->kinetic += 0.5 * m * v2;
    if (mi >= 0) o->strain += s->mats[mi].model->energy(&s->mats[mi], ps, i);
  }
  for (b = 0; b < s->nbody; b++)
    if (out[b].mass > 0)
      for (d = 0; d < DIM; d++) {
        out[b].x[d] /= out[b].mass;
        out[b].v[d] /= out[b].mass;
      }
  for (i = 0; i < ps->n; i++) {
    bdiag *o = &out[ps->body[i]];
    double m = ps->m[i];
    double rx = ps->x[0][i] - o->x[0], ry = ps->x[1][i] - o->x[1];
    double ux = ps->v[0][i] - o->v[0], uy = ps->v[1][i] - o->v[1];
    /* a body across a periodic seam: take the nearest image */
    if (s->g.periodic[0]) {
      double L = s->g.hi[0] - s->g.lo[0];
      if (rx > L / 2) rx -= L; else if (rx < -L / 2) rx += L;
    }
    if (s->g.periodic[1]) {
      double L = s->g.hi[1] - s->g.lo[1];
      if (ry > L / 2) ry -= L; else if (ry < -L / 2) ry += L;
    }
    o->angmom += m * (rx * uy - ry * ux);
    o->inertia += m * (rx * rx + ry * ry + a * a / 6.0);
  }
  for (b = 0; b < s->nbody; b++)
    if (out[b].inertia > 0) out[b].omega = out[b].angmom / out[b].inertia;
  return 0;
}
