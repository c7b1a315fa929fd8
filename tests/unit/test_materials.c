/*
** test_materials.c - the constitutive models against closed forms, one
** homogeneous particle driven by a prescribed velocity gradient L (the
** model's update called directly), and the thermal phase.
**
** Paths: pure shear L = [[0, g], [g, 0]] (no spin, D_xy = g, engineering
** shear strain gamma = 2 g t) and plane-strain uniaxial strain
** L = diag(r, 0).  Along both the deviatoric direction is fixed, where
** radial return is exact for any step size, so stresses are checked to
** round-off; integrals the test forms itself by the trapezoid rule carry
** its error, bounded in each check's comment.
*/
#include <math.h>
#include <string.h>
#include "sim.h"
#include "thermal.h"
#include "unit.h"

typedef struct one {
  particles ps;
  material m;
  int32_t bmat[1];
  mat_sums sum;      /* summed over every step */
} one;

static void one_init(one *o, const material *m) {
  memset(o, 0, sizeof *o);
  particles_init(&o->ps);
  o->m = *m;
  o->m.model->setup(&o->m, &o->ps);
  particles_push(&o->ps);
  o->ps.body[0] = 0;
  o->ps.vol0[0] = 1.0;
  o->ps.m[0] = m->rho;
}

/* one step with velocity gradient (L00, L01, L10, L11) */
static void one_step(one *o, double L00, double L01, double L10, double L11,
                     double dt) {
  mat_sums s = {0, 0, 1e300, -1e300, 0, 0, 0, 0};
  o->ps.L[0][0] = L00; o->ps.L[1][0] = L01;
  o->ps.L[2][0] = L10; o->ps.L[3][0] = L11;
  o->m.model->update(&o->m, &o->ps, o->bmat, 0, dt, 0, o->ps.n, &s);
  o->sum.plastic += s.plastic;
  o->sum.viscous += s.viscous;
  o->sum.strain = s.strain;
}

/* the models' stress: Kirchhoff's, tau = J sigma (material.h), which is
** what the rate forms and their closed forms are written for; the
** particle stores sigma */
static double sig(const one *o, int k) {
  return mat_jacobian(&o->ps, 0) * o->ps.s[k][0];
}
static double field(const one *o, const char *name) {
  return ((double *)particles_comp(&o->ps, particles_find(&o->ps, name), 0))[0];
}

/* --- J2 plasticity ------------------------------------------------- */

/* pure shear: tau = G gamma up to tau_y = yield / sqrt 3, then
** d tau / d gamma = G H / (3G + H); gamma_p = gamma - tau / G and
** ep = gamma_p / sqrt 3; plastic work = yield ep + H ep^2 / 2 */
static void j2_shear(double H) {
  const double K = 5.0 / 3.0, G = 1.0, y = 0.01, g = 1.0;
  const double ty = y / sqrt(3.0), gy = ty / G, Gt = G * H / (3 * G + H);
  const int nel = 40;               /* steps to the yield point */
  const double dt = gy / (2 * g * nel), dgam = 2 * g * dt;
  material m;
  one o;
  double gam = 0, work = 0, wpd = 0, t1 = 0, g1 = 0, ty_meas = 0;
  char name[80];
  int n;
  material_plastic(&m, "j2", 1.0, K, G, y, H);
  one_init(&o, &m);
  for (n = 1; n <= 4 * nel; n++) {
    double s0 = sig(&o, S_XY), s1;
    one_step(&o, 0, g, g, 0, dt);
    s1 = sig(&o, S_XY);
    gam = n * dgam;
    /* work of the prescribed deformation, and sigma : D_p with D_p dt =
    ** d eps - C^-1 d sigma, both by the trapezoid rule */
    work += 0.5 * (s0 + s1) * dgam;
    wpd += 0.5 * (s0 + s1) * (dgam - (s1 - s0) / G);
    if (n == nel) ty_meas = s1;
    if (n == 2 * nel) { t1 = s1; g1 = gam; }
  }
  snprintf(name, sizeof name, "J2 shear H=%g: tau at gamma_y / tau_y", H);
  UNIT_NEAR(ty_meas / ty, 1, 1e-12, name);
  snprintf(name, sizeof name, "J2 shear H=%g: tau at 4 gamma_y", H);
  UNIT_NEAR(sig(&o, S_XY), ty + Gt * (gam - gy), 1e-12 * ty, name);
  snprintf(name, sizeof name, "J2 shear H=%g: slope after yield / G", H);
  UNIT_NEAR((sig(&o, S_XY) - t1) / (gam - g1) / G, Gt / G, 1e-9, name);
  {
    double ep = (gam - sig(&o, S_XY) / G) / sqrt(3.0);
    double wp = y * ep + 0.5 * H * ep * ep;
    snprintf(name, sizeof name, "J2 shear H=%g: plastic strain / analytic", H);
    UNIT_NEAR(field(&o, "plastic_strain") / ep, 1, 1e-10, name);
    snprintf(name, sizeof name, "J2 shear H=%g: plastic work / analytic", H);
    UNIT_NEAR(o.sum.plastic / wp, 1, 1e-10, name);
    /* the trapezoid is exact on the linear pieces; the one step with the
    ** kink at yield errs by less than G dgam^2 / 8 */
    snprintf(name, sizeof name, "J2 shear H=%g: plastic work - int sigma:Dp", H);
    UNIT_NEAR(o.sum.plastic - wpd, 0, G * dgam * dgam / 8 + 1e-15, name);
    snprintf(name, sizeof name, "J2 shear H=%g: field plastic_work - sum", H);
    UNIT_NEAR(field(&o, "plastic_work") - o.sum.plastic, 0, 1e-18, name);
    snprintf(name, sizeof name, "J2 shear H=%g: work - stored - plastic", H);
    UNIT_NEAR(work - o.sum.strain - o.sum.plastic, 0,
              G * dgam * dgam / 8 + 1e-6 * work, name);
    snprintf(name, sizeof name, "J2 shear H=%g: sigma_zz stays 0", H);
    UNIT_NEAR(sig(&o, S_ZZ), 0, 1e-18, name);
  }
  particles_free(&o.ps);
}

/* plane-strain uniaxial compression eps = r t < 0: elastic sigma_xx =
** (K + 4G/3) eps, sigma_yy = sigma_zz = (K - 2G/3) eps; yield at |eps| =
** yield / (2G); after it d sigma_xx / d eps = K + 4 G H / (3 (3G + H)) */
static void j2_uniaxial(double H) {
  const double K = 5.0 / 3.0, G = 1.0, y = 0.01, r = -1.0;
  const double ey = y / (2 * G), M = K + 4 * G / 3, Mt = K + 4 * G * H / (3 * (3 * G + H));
  const int nel = 50;
  const double dt = ey / (-r * nel);
  material m;
  one o;
  double s1 = 0, e1 = 0, eps = 0;
  char name[80];
  int n;
  material_plastic(&m, "j2", 1.0, K, G, y, H);
  one_init(&o, &m);
  for (n = 1; n <= 3 * nel; n++) {
    one_step(&o, r, 0, 0, 0, dt);
    eps = n * r * dt;
    if (n == nel) {
      snprintf(name, sizeof name, "J2 uniaxial H=%g: sxx at yield / analytic", H);
      UNIT_NEAR(sig(&o, S_XX) / (M * eps), 1, 1e-12, name);
      snprintf(name, sizeof name, "J2 uniaxial H=%g: syy - sxx at yield / yield", H);
      UNIT_NEAR((sig(&o, S_YY) - sig(&o, S_XX)) / y, 1, 1e-12, name);
    }
    if (n == 2 * nel) { s1 = sig(&o, S_XX); e1 = eps; }
  }
  snprintf(name, sizeof name, "J2 uniaxial H=%g: slope after yield / K", H);
  UNIT_NEAR((sig(&o, S_XX) - s1) / (eps - e1) / K, Mt / K, 1e-9, name);
  snprintf(name, sizeof name, "J2 uniaxial H=%g: sxx at 3 eps_y / analytic", H);
  UNIT_NEAR(sig(&o, S_XX) / (-M * ey + Mt * (eps + ey)), 1, 1e-12, name);
  snprintf(name, sizeof name, "J2 uniaxial H=%g: syy - szz (equal)", H);
  UNIT_NEAR(sig(&o, S_YY) - sig(&o, S_ZZ), 0, 1e-15, name);
  {
    /* on the yield surface: q = syy - sxx = yield + H ep */
    double ep = field(&o, "plastic_strain");
    snprintf(name, sizeof name, "J2 uniaxial H=%g: q / (yield + H ep)", H);
    UNIT_NEAR((sig(&o, S_YY) - sig(&o, S_XX)) / (y + H * ep), 1, 1e-12, name);
    /* deviatoric strain 2/3 |eps| beyond yield splits elastic/plastic:
    ** ep = 3G (2/3)(|eps| - ey) / (3G + H) */
    snprintf(name, sizeof name, "J2 uniaxial H=%g: ep / analytic", H);
    UNIT_NEAR(ep / (2 * G * (-eps - ey) / (3 * G + H)), 1, 1e-10, name);
  }
  particles_free(&o.ps);
}

/* --- generalized Maxwell ------------------------------------------- */

static const double pK = 2.0, pGinf = 0.1;
static const double pG[3] = {0.5, 0.3, 0.2}, ptau[3] = {1e-3, 1e-2, 1e-1};

/* u - (1 - e^-u), by its series where the difference cancels */
static double ramp(double u) {
  if (u < 1e-3) return u * u * (0.5 + u * (-1.0 / 6 + u * (1.0 / 24 - u / 120)));
  return u + expm1(-u);
}

static double Gt(double t) {
  double g = pGinf;
  int k;
  for (k = 0; k < 3; k++) g += pG[k] * exp(-t / ptau[k]);
  return g;
}

/* step strain gamma0 in pure shear, then relaxation at steps dt larger
** than tau_min: sigma_xy = G(t) gamma0.  The step is a ramp of length t0
** = 1e-9, which changes G by t0 / tau_min = 1e-6 at most */
static void prony_relax(void) {
  const double g0 = 1e-3, t0 = 1e-9, dt = 5e-3;
  const double when[] = {5e-3, 2e-2, 1e-1, 0.5};
  material m;
  one o;
  double t = 0, work = 0, rate = g0 / t0;
  int n, w = 0, k;
  char name[80];
  material_viscoelastic(&m, "ve", 1.0, pK, pGinf, 3, pG, ptau);
  UNIT_NEAR(m.G, pGinf + 0.5 + 0.3 + 0.2, 1e-15, "Prony: glassy G sets the wave speed");
  one_init(&o, &m);
  one_step(&o, 0, 0.5 * rate, 0.5 * rate, 0, t0);
  /* work of the ramp, closed form: rate^2 (sum G tau (t0 - tau (1 -
  ** e^(-t0/tau))) + G_inf t0^2 / 2) */
  work = pGinf * t0 * t0 / 2;
  for (k = 0; k < 3; k++) work += pG[k] * ptau[k] * ptau[k] * ramp(t0 / ptau[k]);
  work *= rate * rate;
  UNIT_NEAR(sig(&o, S_XY) / (Gt(0) * g0), 1, 2e-6, "Prony: sigma_xy after the step / G(0) g0");
  for (n = 1; t < 0.5 - 1e-12; n++) {
    one_step(&o, 0, 0, 0, 0, dt);
    t = n * dt;
    if (fabs(t - when[w]) < 1e-12) {
      snprintf(name, sizeof name, "Prony: sigma_xy / G(t) g0 at t = %g", t);
      UNIT_NEAR(sig(&o, S_XY) / (Gt(t) * g0), 1, 2e-6, name);
      /* every bit of work is either stored or dissipated, exactly */
      snprintf(name, sizeof name, "Prony: (stored + viscous) / work at t = %g", t);
      UNIT_NEAR((o.sum.strain + o.sum.viscous) / work - 1, 0, 1e-12, name);
      w++;
    }
  }
  UNIT_NEAR(sig(&o, S_XX) + sig(&o, S_YY) + sig(&o, S_ZZ), 0, 1e-18,
            "Prony: pure shear leaves no pressure");
  /* stored: (G_inf + sum G e^(-2t/tau)) g0^2 / 2, each element holding
  ** G e^(-t/tau) g0 */
  {
    double st = pGinf;
    for (k = 0; k < 3; k++) st += pG[k] * exp(-2 * t / ptau[k]);
    UNIT_NEAR(o.sum.strain / (0.5 * st * g0 * g0), 1, 4e-6,
              "Prony: stored at t = 0.5 / closed form");
  }
  UNIT_NEAR(field(&o, "viscous_work") - o.sum.viscous, 0, 1e-20,
            "Prony: field viscous_work - sum");
  particles_free(&o.ps);
}

/* constant shear rate at steps 20 tau_min: the exponential update is the
** exact solution sigma_xy = rate (G_inf t + sum G tau (1 - e^(-t/tau)))
** whatever the step */
static void prony_rate(void) {
  const double g = 0.5, dt = 2e-2, rate = 2 * g;
  material m;
  one o;
  double t, ref = 0, work = 0;
  int n, k;
  material_viscoelastic(&m, "ve", 1.0, pK, pGinf, 3, pG, ptau);
  one_init(&o, &m);
  for (n = 1; n <= 10; n++) one_step(&o, 0, g, g, 0, dt);
  t = 10 * dt;
  ref = pGinf * t;
  for (k = 0; k < 3; k++) ref += pG[k] * ptau[k] * -expm1(-t / ptau[k]);
  ref *= rate;
  UNIT_NEAR(sig(&o, S_XY) / ref, 1, 1e-12, "Prony: constant rate, dt = 20 tau_min");
  /* work: rate^2 (G_inf t^2/2 + sum G tau (t - tau (1 - e^(-t/tau)))) */
  work = pGinf * t * t / 2;
  for (k = 0; k < 3; k++) work += pG[k] * ptau[k] * ptau[k] * ramp(t / ptau[k]);
  work *= rate * rate;
  UNIT_NEAR((o.sum.strain + o.sum.viscous) / work - 1, 0, 1e-12,
            "Prony: constant rate (stored + viscous) / work");
  particles_free(&o.ps);
}

/* oscillating shear with dt << tau: the trapezoid work of the test
** against stored + dissipated, error O(dt^2) */
static void prony_cycle(void) {
  const double A = 1e-3, om = 2 * M_PI / 2e-2, dt = 1e-5;
  material m;
  one o;
  double work = 0;
  int n;
  material_viscoelastic(&m, "ve", 1.0, pK, pGinf, 3, pG, ptau);
  one_init(&o, &m);
  for (n = 0; n < 4000; n++) {
    double t = (n + 0.5) * dt, g = 0.5 * A * om * cos(om * t);
    double s0 = sig(&o, S_XY);
    one_step(&o, 0, g, g, 0, dt);
    work += 0.5 * (s0 + sig(&o, S_XY)) * 2 * g * dt;
  }
  UNIT_CHECK(o.sum.viscous > 0, "oscillating shear dissipates");
  /* (om dt)^2 / 12 = 8e-6 of the work per cycle for the trapezoid */
  UNIT_NEAR((o.sum.strain + o.sum.viscous) / work, 1, 1e-4,
            "Prony: oscillating shear (stored + viscous) / work");
  particles_free(&o.ps);
}

/* --- large strain: the stored energy against the work done ---------- */

/*
** A path far from small strain: stretch, shear and spin at once, L
** constant, to det F = 1.65 and a shear of order one.  The work the grid
** does on a particle is its current volume times sigma : D, J V0 sigma : D
** with sigma the Cauchy stress it stores; summed by the trapezoid rule
** over the steps, it must equal what the model stores plus what it
** dissipates.  The stored energy is the models' own sum (the energy
** budget's strain), and material.c's energy() must read the same.  Read
** with sigma in place of tau (J sigma), the energy would miss the work by
** tens of percent here: printed, and checked to be far off, so that this
** case tells the two apart.
*/
static void large_path(const material *m, const char *what) {
  const double a = 0.5, b = 0.3, c = -0.2, d = 0.0, T = 1.0;
  const int nsteps = 4000;
  const double dt = T / nsteps;
  const double D[3] = {a, d, 0.5 * (b + c)}; /* xx, yy, xy */
  one o;
  double work = 0, J = 1, wsig, stored;
  char name[96];
  int n;
  one_init(&o, m);
  for (n = 0; n < nsteps; n++) {
    double t0[3] = {sig(&o, S_XX), sig(&o, S_YY), sig(&o, S_XY)}, t1[3];
    one_step(&o, a, b, c, d, dt);
    t1[0] = sig(&o, S_XX); t1[1] = sig(&o, S_YY); t1[2] = sig(&o, S_XY);
    work += 0.5 * dt * ((t0[0] + t1[0]) * D[0] + (t0[1] + t1[1]) * D[1] +
                        2 * (t0[2] + t1[2]) * D[2]);
  }
  J = mat_jacobian(&o.ps, 0);
  stored = o.sum.strain;
  snprintf(name, sizeof name, "%s, large strain: det F (info %.4f) > 1.6", what, J);
  UNIT_CHECK(J > 1.6, name);
  /* the trapezoid on a rotating stress: O((|L| dt)^2) = 1e-8 per unit */
  snprintf(name, sizeof name, "%s, large strain: (stored + dissipated) / work", what);
  UNIT_NEAR((stored + o.sum.plastic + o.sum.viscous) / work, 1, 1e-5, name);
  snprintf(name, sizeof name, "%s, large strain: energy() / the update's stored energy", what);
  UNIT_NEAR(o.m.model->energy(&o.m, &o.ps, 0) / stored, 1, 1e-12, name);
  {
    /* the same energy read from sigma: the model's energy() with F
    ** set to I for the call (then tau = sigma) */
    double F[NTENS];
    int k;
    for (k = 0; k < NTENS; k++) {
      F[k] = o.ps.F[k][0];
      o.ps.F[k][0] = k % (DIM + 1) == 0;
    }
    wsig = o.m.model->energy(&o.m, &o.ps, 0);
    for (k = 0; k < NTENS; k++) o.ps.F[k][0] = F[k];
  }
  printf("  %s: work %.6g, stored %.6g, dissipated %.6g; read from sigma %.6g (%.1f %% off)\n",
         what, work, stored, o.sum.plastic + o.sum.viscous, wsig,
         100 * (wsig + o.sum.plastic + o.sum.viscous - work) / work);
  snprintf(name, sizeof name, "%s, large strain: sigma's energy misses the work by > 10 %%", what);
  UNIT_CHECK(fabs(wsig + o.sum.plastic + o.sum.viscous - work) > 0.1 * work, name);
  particles_free(&o.ps);
}

static void large_paths(void) {
  material m;
  material_init(&m, &mat_elastic, "el", 1.0, 5.0 / 3.0, 1.0);
  large_path(&m, "elastic");
  material_plastic(&m, "j2", 1.0, 5.0 / 3.0, 1.0, 0.1, 0.5);
  large_path(&m, "J2");
  material_viscoelastic(&m, "ve", 1.0, pK, pGinf, 3, pG, ptau);
  large_path(&m, "Maxwell");
}

/* --- thermal expansion --------------------------------------------- */

static void thermal_confined(void) {
  const double K = 5.0 / 3.0, G = 1.0, alpha = 1e-3, dT = 10;
  double lo[2] = {0, 0}, hi[2] = {1, 1}, x[2] = {0.5, 0.5}, v[2] = {0, 0};
  int per[2] = {0, 0};
  material m;
  sim s;
  int k;
  for (k = 0; k < 2; k++) {
    double p = -3 * K * alpha * dT;
    sim_init(&s, lo, hi, 0.25, per, 0, 2);
    if (k == 0) material_init(&m, &mat_elastic, "e", 1, K, G);
    else material_plastic(&m, "p", 1, K, G, 1e-3, 0);
    m.alpha = alpha;
    sim_add_material(&s, &m);
    sim_add_body(&s, "b", 0, -1);
    sim_add_particle(&s, 0, x, v, 1.0);
    thermal_enable(&s);
    s.started = 1;  /* heat the held particle: no grid, L = 0 */
    thermal_uniform(&s, dT);
    s.dt = 1e-3;
    sim_prepare(&s); /* the phases' buffers, before any phase */
    thermal(&s);
    constitutive(&s, s.dt);
    UNIT_NEAR(s.ps.s[S_XX][0] / p, 1, 1e-14, k ? "confined heating (plastic): sxx / -3K alpha dT"
                                               : "confined heating: sxx / -3K alpha dT");
    UNIT_NEAR(s.ps.s[S_YY][0] / p, 1, 1e-14, "confined heating: syy / -3K alpha dT");
    UNIT_NEAR(s.ps.s[S_ZZ][0] / p, 1, 1e-14, "confined heating: szz / -3K alpha dT");
    UNIT_NEAR(s.ps.s[S_XY][0], 0, 1e-18, "confined heating: no shear");
    /* the heating supplies the strain energy p^2 / (2K) */
    UNIT_NEAR(s.e.thermal / (p * p / (2 * K)), 1, 1e-14,
              "confined heating: thermal work / stored");
    UNIT_NEAR(s.e.strain / (p * p / (2 * K)), 1, 1e-14,
              "confined heating: strain energy / p^2/(2K)");
    if (k) UNIT_NEAR(s.e.plastic, 0, 0, "confined heating: hydrostatic, no yield");
    sim_free(&s);
  }
}

/* a held particle heated then held free in plane by the stress-free
** strain: drive it with L = diag(r, r) while heating, r dt = (1+nu)
** alpha dT per step; then sxx = syy = 0 and szz = -E alpha dT */
static void thermal_free_strain(void) {
  const double K = 5.0 / 3.0, G = 1.0, alpha = 1e-3;
  const double nu = (3 * K - 2 * G) / (2 * (3 * K + G)), E = 9 * K * G / (3 * K + G);
  double lo[2] = {0, 0}, hi[2] = {1, 1}, x[2] = {0.5, 0.5}, v[2] = {0, 0};
  int per[2] = {0, 0}, n;
  material m;
  sim s;
  sim_init(&s, lo, hi, 0.25, per, 0, 2);
  material_init(&m, &mat_elastic, "e", 1, K, G);
  m.alpha = alpha;
  sim_add_material(&s, &m);
  sim_add_body(&s, "b", 0, -1);
  sim_add_particle(&s, 0, x, v, 1.0);
  thermal_enable(&s);
  s.started = 1;
  s.dt = 1e-3;
  sim_prepare(&s);
  for (n = 1; n <= 10; n++) {
    double r = (1 + nu) * alpha * 1.0 / s.dt;  /* 1 degree per step */
    thermal_uniform(&s, n);
    thermal(&s);
    s.ps.L[0][0] = r; s.ps.L[3][0] = r;
    constitutive(&s, s.dt);
  }
  UNIT_NEAR(s.ps.s[S_XX][0], 0, 1e-15, "free in-plane strain (1+nu) alpha dT: sxx");
  UNIT_NEAR(s.ps.s[S_YY][0], 0, 1e-15, "free in-plane strain (1+nu) alpha dT: syy");
  /* the closed form is the Kirchhoff stress's (material.h): the particle
  ** has grown by J = 1.026 and stores tau / J */
  UNIT_NEAR(mat_jacobian(&s.ps, 0) * s.ps.s[S_ZZ][0] / (-E * alpha * 10), 1, 1e-12,
            "free in-plane: tau_zz / (-E alpha dT)");
  sim_free(&s);
}

int main(void) {
  j2_shear(0);
  j2_shear(0.5);
  j2_uniaxial(0);
  j2_uniaxial(0.5);
  prony_relax();
  prony_rate();
  prony_cycle();
  large_paths();
  thermal_confined();
  thermal_free_strain();
  UNIT_END("test_materials");
}
