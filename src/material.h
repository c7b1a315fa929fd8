/*
** material.h - the material interface.
** A material is a model (its update function and the per-particle state
** it needs) plus parameters.  The constitutive phase calls each model's
** update once per step over the particles of each material that uses it:
** one pass per model, no per-particle dispatch.
**
** Stress is updated in rate form with an objective rate: the stress is
** first rotated by the incremental rotation of the step (Hughes-Winget,
** exactly orthogonal), then the model adds its increment from the rate
** of deformation D.  This is the small-strain, objective-rate convention;
** K is the 3-D bulk modulus and the out-of-plane stress follows from
** eps_zz = 0 (plane strain).
*/
#ifndef mvmpm_material_h
#define mvmpm_material_h

#include <stddef.h>
#include <stdint.h>
#include "dim.h"
#include "particles.h"

typedef struct material material;

/* per-step sums the constitutive phase reports */
typedef struct mat_sums {
  double strain;   /* stored elastic energy */
  double power;    /* stress power sum V sigma : D after the update */
  double jmin, jmax;
  size_t nbadj;    /* particles with det F <= 0 */
} mat_sums;

typedef struct mat_model {
  const char *name;
  /* register per-particle state fields; 0 or -1 */
  int (*setup)(material *m, particles *ps);
  /* update the particles whose body uses material id (bmat[body] == id) */
  void (*update)(const material *m, particles *ps, const int32_t *bmat,
                 int32_t id, double dt, mat_sums *sum);
  /* stored energy of particle i (for diagnostics of one body) */
  double (*energy)(const material *m, const particles *ps, size_t i);
} mat_model;

struct material {
  const mat_model *model;
  char name[32];
  int32_t id;
  double rho;       /* reference density */
  double K, G;      /* 3-D bulk and shear moduli */
  double lambda;    /* K - 2G/3 */
  double c;         /* longitudinal wave speed at rest, sqrt((K+4G/3)/rho) */
};

extern const mat_model mat_elastic;

/* the elastic constants every model shares; 0 or -1 if out of range */
int material_init(material *m, const mat_model *model, const char *name,
                  double rho, double K, double G);

/* elastic energy density of a stress state, isotropic K and G */
static inline double mat_elastic_density(const double *s, double K, double G) {
#if DIM == 2
  double p = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3.0;
  double dx = s[S_XX] - p, dy = s[S_YY] - p, dz = s[S_ZZ] - p;
  double ss = dx * dx + dy * dy + dz * dz + 2 * s[S_XY] * s[S_XY];
#else
  double p = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3.0;
  double dx = s[S_XX] - p, dy = s[S_YY] - p, dz = s[S_ZZ] - p;
  double ss = dx * dx + dy * dy + dz * dz +
              2 * (s[S_XY] * s[S_XY] + s[S_YZ] * s[S_YZ] + s[S_XZ] * s[S_XZ]);
#endif
  return p * p / (2 * K) + ss / (4 * G);
}

/*
** The kinematic part every model shares, for particle i: D (symmetric,
** stored as NSTRESS components in stress order, zz = 0 in plane strain),
** the incremental rotation applied to the stress in s[], and F <- (I +
** dt L) F.  Returns det F.
*/
static inline double mat_kinematics(particles *ps, size_t i, double dt,
                                    double *s, double *D) {
#if DIM == 2
  double L00 = ps->L[0][i], L01 = ps->L[1][i];
  double L10 = ps->L[2][i], L11 = ps->L[3][i];
  double w = 0.5 * dt * (L10 - L01); /* dt * W_yx */
  double F00 = ps->F[0][i], F01 = ps->F[1][i];
  double F10 = ps->F[2][i], F11 = ps->F[3][i];
  double a, b, c2, sxx, syy, sxy, cs, sn, cc, ssn;
  D[S_XX] = L00;
  D[S_YY] = L11;
  D[S_XY] = 0.5 * (L01 + L10);
  D[S_ZZ] = 0.0;
  /* Hughes-Winget: R = (I - W dt/2)^-1 (I + W dt/2) is a rotation by an
  ** angle theta with cos = (1 - a^2)/(1 + a^2), sin = 2a/(1 + a^2), a =
  ** w/2 ... written out for 2-D so it stays exactly orthogonal */
  a = 0.5 * w;
  c2 = 1.0 + a * a;
  cs = (1.0 - a * a) / c2;
  sn = 2.0 * a / c2;
  sxx = s[S_XX]; syy = s[S_YY]; sxy = s[S_XY];
  cc = cs * cs; ssn = sn * sn;
  b = 2.0 * cs * sn * sxy;
  s[S_XX] = cc * sxx + ssn * syy - b;
  s[S_YY] = ssn * sxx + cc * syy + b;
  s[S_XY] = cs * sn * (sxx - syy) + (cc - ssn) * sxy;
  ps->F[0][i] = F00 + dt * (L00 * F00 + L01 * F10);
  ps->F[1][i] = F01 + dt * (L00 * F01 + L01 * F11);
  ps->F[2][i] = F10 + dt * (L10 * F00 + L11 * F10);
  ps->F[3][i] = F11 + dt * (L10 * F01 + L11 * F11);
  return ps->F[0][i] * ps->F[3][i] - ps->F[1][i] * ps->F[2][i];
#else
#error "mat_kinematics: 3-D not written yet"
#endif
}

/* gather / scatter the stress of particle i */
static inline void mat_get(const particles *ps, size_t i, double *s) {
  int k;
  for (k = 0; k < NSTRESS; k++) s[k] = ps->s[k][i];
}
static inline void mat_put(particles *ps, size_t i, const double *s) {
  int k;
  for (k = 0; k < NSTRESS; k++) ps->s[k][i] = s[k];
}
/* stress power density sigma : D */
static inline double mat_power(const double *s, const double *D) {
#if DIM == 2
  return s[S_XX] * D[S_XX] + s[S_YY] * D[S_YY] + 2 * s[S_XY] * D[S_XY];
#else
  return s[S_XX] * D[S_XX] + s[S_YY] * D[S_YY] + s[S_ZZ] * D[S_ZZ] +
         2 * (s[S_XY] * D[S_XY] + s[S_YZ] * D[S_YZ] + s[S_XZ] * D[S_XZ]);
#endif
}
static inline void mat_sum_j(mat_sums *sum, double J) {
  if (J < sum->jmin) sum->jmin = J;
  if (J > sum->jmax) sum->jmax = J;
  if (!(J > 0)) sum->nbadj++;
}

#endif
