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
** of deformation D.  K is the 3-D bulk modulus and the out-of-plane
** stress follows from eps_zz = 0 (plane strain).
**
** The rate form is written for the Kirchhoff stress tau = J sigma, not
** the Cauchy stress the particles store: the models read tau
** (mat_get_tau) and store tau / J (mat_put_tau).  Why: the grid's forces
** do the work J V0 sigma : D = V0 tau : D, and an isotropic law's
** rotation leaves tau : C^-1 : tau unchanged, so the stored energy
** V0 (tau : C^-1 : tau) / 2 per reference volume changes by exactly that
** work at any strain.  Written for sigma, the energy read V0 J times too
** little work (a strip stretched 50 % left 9 % of the work unbooked).
** Its volume part is Hencky's, tau_m = K ln J.
*/
#ifndef mvmpm_material_h
#define mvmpm_material_h

#include <stddef.h>
#include <stdint.h>
#include "dim.h"
#include "particles.h"
#include "vec.h"

typedef struct material material;

/* single-step Arrhenius kinetics (react.h); Z = 0: the material does not
** react */
typedef struct react_law {
  double Z;      /* pre-exponential factor, 1/T */
  double Ta;     /* activation temperature E / R, K */
  double Q;      /* heat of reaction per unit mass (> 0 exothermic) */
  double n;      /* order in (1 - lambda), 0 .. 3 */
  double T_fk;   /* > 0: Frank-Kamenetskii's exponent about this T */
} react_law;

#define MAT_MAXPRONY 8             /* Maxwell elements of one material */
#define MAT_MAXFIELDS (MAT_MAXPRONY + 2)

/* per-step sums the constitutive phase reports */
typedef struct mat_sums {
  double strain;   /* stored elastic energy */
  double power;    /* stress power sum V sigma : D after the update */
  double jmin, jmax;
  size_t nbadj;    /* particles with det F <= 0 */
  double plastic;  /* plastic work of this step */
  double viscous;  /* viscous dissipation of this step */
  double heat;     /* plastic work of this step turned to heat (beta W_p;
                      scenes with heat only, heat.h) */
} mat_sums;

typedef struct mat_model {
  const char *name;
  /* register per-particle state fields; 0 or -1 */
  int (*setup)(material *m, particles *ps);
  /* update the particles i0 .. i1 - 1 whose body uses material id
  ** (bmat[body] == id), adding to sum (threads update disjoint ranges) */
  void (*update)(const material *m, particles *ps, const int32_t *bmat,
                 int32_t id, double dt, size_t i0, size_t i1, mat_sums *sum);
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
  /* thermal expansion (thermal.c): linear coefficient of the 3-D
  ** material and the temperature at which the seeded shape is stress
  ** free; alpha = 0 keeps the material out of the thermal phase */
  double alpha, T_ref;
  /* reaction (react.c) */
  react_law rx;
  /* > 0: friction heat does not raise T above it (melt.h) */
  double T_melt;
  /* elastic-plastic (mat_plastic.c): initial yield stress (von Mises,
  ** equivalent stress) and linear isotropic hardening modulus */
  double yield, hardening;
  /* viscoelastic (mat_viscoelastic.c): long-term shear modulus and the
  ** Maxwell elements; G above is the glassy G_inf + sum G_i */
  double G_inf;
  int nprony;
  double prony_G[MAT_MAXPRONY], prony_tau[MAT_MAXPRONY];
  /* heat (heat.h, conduct.h): specific heat per unit mass (0: not
  ** given; a scene with heat needs it > 0), thermal conductivity, and the
  ** Taylor-Quinney fraction of plastic work that becomes heat */
  double cv, kcond, beta;
  /* the particle field the models add each step's heat to (J): set by
  ** the simulation, -1 in a scene without heat */
  int fheat;
  /* per-particle state fields the model registered (indices into the
  ** particle field table, set by setup) */
  int field[MAT_MAXFIELDS];
};

extern const mat_model mat_elastic;
extern const mat_model mat_plastic;
extern const mat_model mat_viscoelastic;

/* the elastic constants every model shares; 0 or -1 if out of range */
int material_init(material *m, const mat_model *model, const char *name,
                  double rho, double K, double G);
/* J2 plasticity: yield > 0, hardening >= 0; 0 or -1 */
int material_plastic(material *m, const char *name, double rho, double K,
                     double G, double yield, double hardening);
/* generalized Maxwell: G_inf >= 0, n <= MAT_MAXPRONY elements with G > 0
** and tau > 0, glassy G_inf + sum G > 0; 0 or -1 */
int material_viscoelastic(material *m, const char *name, double rho,
                          double K, double G_inf, int n, const double *G,
                          const double *tau);

/* the stored energy of particle i whose stress is elastic in K and G
** (the elastic and plastic models' energy()) */
double material_elastic_energy(const material *m, const particles *ps,
                               size_t i);

/* elastic energy density of a stress state, isotropic K and G */
static inline double mat_elastic_density(const double *s, double K, double G) {
#if DIM == 2
  double p = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3.0;
  double dx = s[S_XX] - p, dy = s[S_YY] - p, dz = s[S_ZZ] - p;
  double ss = dx * dx + dy * dy + dz * dz + 2 * s[S_XY] * s[S_XY];
#elif DIM == 3
  double p = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3.0;
  double dx = s[S_XX] - p, dy = s[S_YY] - p, dz = s[S_ZZ] - p;
  double ss = dx * dx + dy * dy + dz * dz +
              2 * (s[S_XY] * s[S_XY] + s[S_YZ] * s[S_YZ] + s[S_XZ] * s[S_XZ]);
#else
#error "mat_elastic_density: DIM must be 2 or 3"
#endif
  return p * p / (2 * K) + ss / (4 * G);
}

/*
** The incremental rotation of particle i over the step: Hughes-Winget,
** R = (I - A)^-1 (I + A), A = dt W / 2, W the spin.  For a skew A with
** axial vector a this is R = I + 2 (A + A^2) / (1 + |a|^2), exactly
** orthogonal however large the step; in 2-D it is a rotation by theta
** with cos = (1 - a^2)/(1 + a^2), sin = 2a/(1 + a^2), a = dt W_yx / 2,
** written out so.  Models with stress-like state besides the stress
** rotate it with the same R.
*/
typedef struct mat_rot {
#if DIM == 2
  double cs, sn;
#elif DIM == 3
  double R[9];
#else
#error "mat_rot: DIM must be 2 or 3"
#endif
} mat_rot;

static inline void mat_rotation(const particles *ps, size_t i, double dt,
                                mat_rot *r) {
#if DIM == 2
  double a = 0.25 * dt * (ps->L[2][i] - ps->L[1][i]);
  double c2 = 1.0 + a * a;
  r->cs = (1.0 - a * a) / c2;
  r->sn = 2.0 * a / c2;
#elif DIM == 3
  double a[3], q;
  int p, k;
  a[0] = 0.25 * dt * (ps->L[7][i] - ps->L[5][i]);
  a[1] = 0.25 * dt * (ps->L[2][i] - ps->L[6][i]);
  a[2] = 0.25 * dt * (ps->L[3][i] - ps->L[1][i]);
  q = 2.0 / (1.0 + a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  /* A + A^2 = A + a a^T - |a|^2 I */
  for (p = 0; p < 3; p++)
    for (k = 0; k < 3; k++)
      r->R[3 * p + k] = (p == k) + q * (a[p] * a[k] - (p == k) *
                        (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
  r->R[1] -= q * a[2]; r->R[3] += q * a[2];
  r->R[2] += q * a[1]; r->R[6] -= q * a[1];
  r->R[5] -= q * a[0]; r->R[7] += q * a[0];
#else
#error "mat_rotation: DIM must be 2 or 3"
#endif
}

/* s <- R s R^T for a symmetric tensor in stress order (in 2-D the
** in-plane part: zz is the rotation's axis) */
static inline void mat_rotate(const mat_rot *r, double *s) {
#if DIM == 2
  double cs = r->cs, sn = r->sn;
  double sxx = s[S_XX], syy = s[S_YY], sxy = s[S_XY];
  double cc = cs * cs, ssn = sn * sn, b = 2.0 * cs * sn * sxy;
  s[S_XX] = cc * sxx + ssn * syy - b;
  s[S_YY] = ssn * sxx + cc * syy + b;
  s[S_XY] = cs * sn * (sxx - syy) + (cc - ssn) * sxy;
#elif DIM == 3
  const double *R = r->R;
  double S[9], T[9];
  int p, k, m;
  for (p = 0; p < 3; p++)
    for (k = 0; k < 3; k++) S[3 * p + k] = s[vec_sym(p, k)];
  for (p = 0; p < 3; p++) /* T = R S */
    for (k = 0; k < 3; k++)
      T[3 * p + k] = R[3 * p] * S[k] + R[3 * p + 1] * S[3 + k] +
                     R[3 * p + 2] * S[6 + k];
  for (p = 0; p < 3; p++) /* (T R^T)_pk, upper triangle */
    for (k = p; k < 3; k++) {
      double v = 0;
      for (m = 0; m < 3; m++) v += T[3 * p + m] * R[3 * k + m];
      s[vec_sym(p, k)] = v;
    }
#else
#error "mat_rotate: DIM must be 2 or 3"
#endif
}

/* det F of particle i */
static inline double mat_jacobian(const particles *ps, size_t i) {
  double F[NTENS];
  int k;
  for (k = 0; k < NTENS; k++) F[k] = ps->F[k][i];
  return vec_det(F);
}

/*
** The kinematic part every model shares, for particle i: D (symmetric,
** stored as NSTRESS components in stress order, zz = 0 in plane strain),
** the stress in s[] (the Kirchhoff stress, from mat_get_tau) rotated by
** the incremental rotation (returned in r for the models' other state),
** and F <- (I + dt L) F.  Returns the new det F, by which mat_put_tau
** divides.
*/
static inline double mat_kinematics(particles *ps, size_t i, double dt,
                                    double *s, double *D, mat_rot *r) {
#if DIM == 2
  double L00 = ps->L[0][i], L01 = ps->L[1][i];
  double L10 = ps->L[2][i], L11 = ps->L[3][i];
  double F00 = ps->F[0][i], F01 = ps->F[1][i];
  double F10 = ps->F[2][i], F11 = ps->F[3][i];
  D[S_XX] = L00;
  D[S_YY] = L11;
  D[S_XY] = 0.5 * (L01 + L10);
  D[S_ZZ] = 0.0;
  mat_rotation(ps, i, dt, r);
  mat_rotate(r, s);
  ps->F[0][i] = F00 + dt * (L00 * F00 + L01 * F10);
  ps->F[1][i] = F01 + dt * (L00 * F01 + L01 * F11);
  ps->F[2][i] = F10 + dt * (L10 * F00 + L11 * F10);
  ps->F[3][i] = F11 + dt * (L10 * F01 + L11 * F11);
  return ps->F[0][i] * ps->F[3][i] - ps->F[1][i] * ps->F[2][i];
#elif DIM == 3
  double L[9], F[9], G[9];
  int p, k;
  for (k = 0; k < 9; k++) { L[k] = ps->L[k][i]; F[k] = ps->F[k][i]; }
  for (p = 0; p < 3; p++)
    for (k = p; k < 3; k++) D[vec_sym(p, k)] = 0.5 * (L[3 * p + k] + L[3 * k + p]);
  mat_rotation(ps, i, dt, r);
  mat_rotate(r, s);
  for (p = 0; p < 3; p++)
    for (k = 0; k < 3; k++)
      G[3 * p + k] = F[3 * p + k] + dt * (L[3 * p] * F[k] + L[3 * p + 1] * F[3 + k] +
                                          L[3 * p + 2] * F[6 + k]);
  for (k = 0; k < 9; k++) ps->F[k][i] = G[k];
  return vec_det(G);
#else
#error "mat_kinematics: DIM must be 2 or 3"
#endif
}

/* split a stress into its mean p and deviator d (all NSTRESS components,
** zz included); returns |d|^2 with the shear counted twice (d : d) */
static inline double mat_deviator(const double *s, double *p, double *d) {
  double m = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3.0, dd = 0;
  int c;
  for (c = 0; c < NSTRESS; c++) d[c] = s[c];
  d[S_XX] = s[S_XX] - m;
  d[S_YY] = s[S_YY] - m;
  d[S_ZZ] = s[S_ZZ] - m;
  *p = m;
  /* the normal parts once, the shears twice: 2-D's order of sums kept */
  dd = d[S_XX] * d[S_XX] + d[S_YY] * d[S_YY] + d[S_ZZ] * d[S_ZZ];
  for (c = 0; c < NSTRESS; c++)
    if (c != S_XX && c != S_YY && c != S_ZZ) dd += 2.0 * d[c] * d[c];
  return dd;
}

/* the isotropic elastic increment over dt, s += lambda tr(D) dt I +
** 2 G D dt (plane strain: D_zz = 0, so zz grows with lambda tr D only);
** g2 = 2 G */
static inline void mat_hooke(double *s, const double *D, double dt,
                             double lam, double g2) {
#if DIM == 2
  double tr = dt * (D[S_XX] + D[S_YY]);
  s[S_XX] += lam * tr + g2 * dt * D[S_XX];
  s[S_YY] += lam * tr + g2 * dt * D[S_YY];
  s[S_XY] += g2 * dt * D[S_XY];
  s[S_ZZ] += lam * tr;
#elif DIM == 3
  double tr = dt * (D[S_XX] + D[S_YY] + D[S_ZZ]);
  int c;
  for (c = 0; c < NSTRESS; c++) s[c] += g2 * dt * D[c];
  s[S_XX] += lam * tr;
  s[S_YY] += lam * tr;
  s[S_ZZ] += lam * tr;
#else
#error "mat_hooke: DIM must be 2 or 3"
#endif
}

/* a deviator stored without its zz, which is -(xx + yy): MAT_NDEV
** components, the c-th in stress slot mat_dev_slot(c) */
#define MAT_NDEV (NSTRESS - 1)
static inline int mat_dev_slot(int c) { return c < S_ZZ ? c : c + 1; }

/* a : b of two symmetric tensors in stress order (zz included, each
** shear twice): the normal parts first, then the shears */
static inline double mat_ddot(const double *a, const double *b) {
  double r = a[S_XX] * b[S_XX] + a[S_YY] * b[S_YY] + a[S_ZZ] * b[S_ZZ];
  int c;
  for (c = 0; c < NSTRESS; c++)
    if (c != S_XX && c != S_YY && c != S_ZZ) r += 2.0 * a[c] * b[c];
  return r;
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
/* the Kirchhoff stress tau = J sigma of particle i, J = det F now */
static inline void mat_get_tau(const particles *ps, size_t i, double *tau) {
  const double J = mat_jacobian(ps, i);
  int k;
  for (k = 0; k < NSTRESS; k++) tau[k] = J * ps->s[k][i];
}
/* store the Kirchhoff stress tau of particle i as Cauchy's, tau / J */
static inline void mat_put_tau(particles *ps, size_t i, const double *tau,
                               double J) {
  double r = 1.0 / J;
  int k;
  for (k = 0; k < NSTRESS; k++) ps->s[k][i] = tau[k] * r;
}
/* stress power density tau : D (per reference volume) */
static inline double mat_power(const double *s, const double *D) {
#if DIM == 2
  return s[S_XX] * D[S_XX] + s[S_YY] * D[S_YY] + 2 * s[S_XY] * D[S_XY];
#elif DIM == 3
  return s[S_XX] * D[S_XX] + s[S_YY] * D[S_YY] + s[S_ZZ] * D[S_ZZ] +
         2 * (s[S_XY] * D[S_XY] + s[S_YZ] * D[S_YZ] + s[S_XZ] * D[S_XZ]);
#else
#error "mat_power: DIM must be 2 or 3"
#endif
}
static inline void mat_sum_j(mat_sums *sum, double J) {
  if (J < sum->jmin) sum->jmin = J;
  if (J > sum->jmax) sum->jmax = J;
  if (!(J > 0)) sum->nbadj++;
}

#endif
