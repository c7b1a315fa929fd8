/*
** diag.c - per-body diagnostics.  The spin is the rigid-body fit
**   I_c omega = L_c,  L_c = sum m (r x v),
**   I_c = sum m ((|r|^2 + a^2/6) 1 - r r^T)
** with r relative to the centroid and a the particle's side (a^2/6 is a
** square's polar moment per mass, and a cube's about each axis), so a
** seeded disc's I_c matches the continuum m R^2 / 2 closely.  In 2-D
** only the z components exist: omega_z = L_z / I_zz.
*/
#include <stdlib.h>
#include <string.h>
#include "diag.h"

/* x - ref along d, the nearest image where d is periodic */
static double rel(const sim *s, int d, double x, double ref) {
  double r = x - ref;
  if (s->g.periodic[d]) {
    double L = s->g.hi[d] - s->g.lo[d];
    if (r > L / 2) r -= L;
    else if (r < -L / 2) r += L;
  }
  return r;
}

int diag_bodies(const sim *s, bdiag *out) {
  const particles *ps = &s->ps;
  const double a = 2.0 * s->cfg.lp * s->g.h;
  double *ref = malloc((size_t)s->nbody * DIM * sizeof *ref);
  size_t i;
  int b, d;
  if (!ref) return -1;
  memset(out, 0, (size_t)s->nbody * sizeof *out);
  /* positions are taken relative to each body's first particle, so that
  ** a body across a periodic seam has its centroid where it is, not
  ** halfway between its two halves */
  for (i = 0; i < ps->n; i++) {
    bdiag *o = &out[ps->body[i]];
    double m = ps->m[i], v2 = 0;
    int32_t mi = s->bmat[ps->body[i]];
    if (o->n++ == 0)
      for (d = 0; d < DIM; d++) ref[DIM * ps->body[i] + d] = ps->x[d][i];
    o->mass += m;
    for (d = 0; d < DIM; d++) {
      o->x[d] += m * rel(s, d, ps->x[d][i], ref[DIM * ps->body[i] + d]);
      o->v[d] += m * ps->v[d][i];
      v2 += ps->v[d][i] * ps->v[d][i];
    }
    o->kinetic += 0.5 * m * v2;
    if (mi >= 0) o->strain += s->mats[mi].model->energy(&s->mats[mi], ps, i);
  }
  for (b = 0; b < s->nbody; b++)
    if (out[b].mass > 0)
      for (d = 0; d < DIM; d++) {
        double x = ref[DIM * b + d] + out[b].x[d] / out[b].mass;
        if (s->g.periodic[d]) { /* back into the domain */
          double L = s->g.hi[d] - s->g.lo[d];
          if (x >= s->g.hi[d]) x -= L;
          else if (x < s->g.lo[d]) x += L;
        }
        out[b].x[d] = x;
        out[b].v[d] /= out[b].mass;
      }
  free(ref);
  for (i = 0; i < ps->n; i++) {
    bdiag *o = &out[ps->body[i]];
    double m = ps->m[i], r[3] = {0, 0, 0}, u[DIM], r2;
    int e;
    for (d = 0; d < DIM; d++) {
      r[d] = rel(s, d, ps->x[d][i], o->x[d]);
      u[d] = ps->v[d][i] - o->v[d];
    }
    vec_moment(o->angmom, m, r, u);
    r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (d = 0; d < 3; d++)
      for (e = 0; e < 3; e++)
        o->inertia[d][e] += m * ((d == e ? r2 + a * a / 6.0 : 0.0) - r[d] * r[e]);
  }
  for (b = 0; b < s->nbody; b++) vec_spin(out[b].inertia, out[b].angmom, out[b].omega);
  return 0;
}
