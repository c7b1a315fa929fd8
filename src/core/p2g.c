/*
** p2g.c - particles to grid, per velocity field.
**   m_i = sum_p S_ip m_p            p_i = sum_p S_ip m_p v_p
**   f_i = -sum_p V_p sigma_p . grad S_ip + sum_p S_ip m_p g
** Every particle adds to the centre-of-mass field (dense arrays); at
** shared nodes it also adds to its own field's slot, with the gradient
** the contact normals come from: the mass gradient sum_p m_p grad S_ip
** (sg), or with sim.normals "volume" or "maxvolume" the volume gradient
** sum_p V_p grad S_ip (sv, which bonds then need not gather again).  One
** of the two, so a scene pays for the one it uses ("auto" takes both
** only where flat faces meet, sim_vol_grad); "plane" also gathers the
** particles' moments about the node (grid.h).
**
** USAVG (usf.c) splits the scatter in two: mass and momentum first, then
** the forces of the stresses its first half-step update gave (p2g_force).
*/
#include "sim.h"
#include "bands.h"
#include "par.h"
#include "stencil.h"
#include "vec.h"

/* what a scatter adds: everything, or (USAVG) all but the forces, or
** the forces alone */
enum { P2G_ALL, P2G_MASS, P2G_FORCE };

/*
** The scatter of particles [i0, i1) (part blk of the bands plan).
** split: only the node rows this pass writes (bands.h); otherwise all.
*/
STENCIL_INLINE void p2g_kind(sim *s, const int kind, const int shared,
                             const int apic, const int split, const int what,
                             size_t i0, size_t i1, int blk, int pass) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const particles *ps = &s->ps;
  const body *bd = s->bodies;
  const double lp = cfg->lp;
  const int rowlen = stencil_rowlen(kind);
  double grav[DIM];
  /* distinct arrays: restrict lets the compiler keep loads ahead of
  ** stores to the other arrays */
  double *restrict gm = g->m;
  double *restrict gp[DIM], *restrict gf[DIM];
  /* one gradient through one pointer; the volume gradient beside the
  ** mass gradient only where "auto" meets flat faces (both) */
  const int bymass = sim_mass_grad(s), both = bymass && sim_vol_grad(s);
  double *const *sgrad = bymass ? g->sg : g->sv;
  const int plane = what != P2G_FORCE && shared && cfg->normals == NORMALS_PLANE;
  const int mass = what != P2G_FORCE, force = what != P2G_MASS;
  const double *C[NTENS] = {NULL};
  double r[DIM][STENCIL_MAX];
  unsigned char mine[SHAPE_MAXW];
  stencil_geo geo;
  stencil st;
  size_t i;
  int a, b;
  for (a = 0; a < DIM; a++) {
    grav[a] = cfg->gravity[a];
    gp[a] = g->p[a];
    gf[a] = g->f[a];
  }
  stencil_geo_init(&geo, g);
  if (apic)
    for (a = 0; a < NTENS; a++) C[a] = particles_comp(ps, s->faff, a);
  for (i = i0; i < i1; i++) {
    double x[DIM], v0[DIM], F[NTENS], sv[DIM][DIM];
    double mp = ps->m[i], J, V;
    int32_t f = bd[ps->body[i]].field;
    /* restrict: its stores then hold back no load of the grid's int32
    ** lists (head, sfield, snext), 1-2 % of p2g with B-splines */
    int32_t *restrict slot = shared ? wk->pslot + i * stencil_size(kind) : NULL;
    double wg;
    int k;
    for (a = 0; a < DIM; a++) { x[a] = ps->x[a][i]; v0[a] = ps->v[a][i]; }
    for (a = 0; a < NTENS; a++) F[a] = ps->F[a][i];
    J = vec_det(F);
    V = J * ps->vol0[i];
    wg = bymass ? mp : V; /* the normals' weight */
    for (a = 0; a < DIM; a++)
      for (b = 0; b < DIM; b++) sv[a][b] = V * ps->s[vec_sym(a, b)][i];
    if (split &&
        !bands_rows(&wk->bands, &geo, kind, x[BANDS_DIM], blk, pass, mine))
      continue;
    if ((apic && mass) || plane) stencil_eval_r(&geo, kind, x, lp, &st, r);
    else stencil_eval(&geo, kind, x, lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double w = st.w[k], wm = w * mp, v[DIM], fo[DIM];
      if (split && !mine[k / rowlen]) continue;
      for (a = 0; a < DIM; a++) {
        /* from the first product, not from 0: 0 + x is not x for the
        ** compiler (signed zeros), and the add would cost every node */
        double sd = sv[a][0] * st.dw[0][k];
        v[a] = v0[a];
        if (apic && mass) { /* the particle's affine velocity at the node */
          double cr = C[a * DIM][i] * r[0][k];
          for (b = 1; b < DIM; b++) cr += C[a * DIM + b][i] * r[b][k];
          v[a] += cr;
        }
        for (b = 1; b < DIM; b++) sd += sv[a][b] * st.dw[b][k];
        fo[a] = wm * grav[a] - sd;
      }
      if (mass) {
        gm[n] += wm;
        for (a = 0; a < DIM; a++) gp[a][n] += wm * v[a];
      }
      if (force)
        for (a = 0; a < DIM; a++) gf[a][n] += fo[a];
      if (shared) {
        int32_t sl;
        if (mass) /* found here once a step, for the passes after (sim.h) */
          sl = slot[k] = g->head[n] >= 0 ? grid_slot(g, n, f) : -1;
        else
          sl = slot[k];
        if (sl < 0) continue;
        if (force)
          for (a = 0; a < DIM; a++) g->sf[a][sl] += fo[a];
        if (!mass) continue;
        g->sm[sl] += wm;
        for (a = 0; a < DIM; a++) {
          g->sp[a][sl] += wm * v[a];
          sgrad[a][sl] += wg * st.dw[a][k];
          if (both) g->sv[a][sl] += V * st.dw[a][k];
        }
        if (plane) { /* moments of r / h, weighted w V */
          double wv = w * V, u[DIM];
          for (a = 0; a < DIM; a++) u[a] = r[a][k] * g->inv_h;
          g->sw[sl] += wv;
          for (a = 0; a < DIM; a++) {
            g->sx[a][sl] += wv * u[a];
            for (b = a; b < DIM; b++) g->sxx[grid_sym(a, b)][sl] += wv * u[a] * u[b];
          }
        }
      }
    }
  }
}

STENCIL_INLINE void p2g_what(sim *s, const int kind, const int split,
                             const int what, size_t i0, size_t i1, int blk,
                             int pass) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0, apic = sim_affine(cfg);
  if (shared) {
    if (apic) p2g_kind(s, kind, 1, 1, split, what, i0, i1, blk, pass);
    else p2g_kind(s, kind, 1, 0, split, what, i0, i1, blk, pass);
  } else {
    if (apic) p2g_kind(s, kind, 0, 1, split, what, i0, i1, blk, pass);
    else p2g_kind(s, kind, 0, 0, split, what, i0, i1, blk, pass);
  }
}

STENCIL_INLINE void p2g_split(sim *s, const int kind, const int split,
                              size_t i0, size_t i1, int blk, int pass) {
  sim_work *wk = &s->work;
  switch (wk->p2g_what) {
  case P2G_MASS: p2g_what(s, kind, split, P2G_MASS, i0, i1, blk, pass); break;
  case P2G_FORCE: p2g_what(s, kind, split, P2G_FORCE, i0, i1, blk, pass); break;
  default: p2g_what(s, kind, split, P2G_ALL, i0, i1, blk, pass);
  }
}

static void p2g_range(sim *s, int split, size_t i0, size_t i1, int blk,
                      int pass) {
  const sim_cfg *cfg = &s->cfg;
#define P2G(K)                                                         \
  if (split) p2g_split(s, K, 1, i0, i1, blk, pass);                    \
  else p2g_split(s, K, 0, i0, i1, blk, pass);
  switch (cfg->shape) {
  case SHAPE_GIMP: P2G(SHAPE_GIMP); break;
  case SHAPE_BSPLINE2: P2G(SHAPE_BSPLINE2); break;
  default: P2G(SHAPE_LINEAR);
  }
#undef P2G
}

static void p2g_span(void *arg, size_t i0, size_t i1, int t, int pass) {
  p2g_range(arg, 1, i0, i1, t, pass);
}

/* the plan is made from the positions the step starts with, and serves
** the marking, the scatter and the scatters of reach and g2p (the
** particles do not move before g2p's last pass) */
void p2g_plan(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  bands_plan(&wk->bands, wk->par, &s->g, cfg->shape, s->ps.x[BANDS_DIM], s->ps.n);
}

static void p2g_run(sim *s, int what) {
  sim_work *wk = &s->work;
  wk->p2g_what = what;
  if (wk->bands.nb) bands_run(&wk->bands, wk->par, p2g_span, s);
  else
    p2g_range(s, 0, 0, s->ps.n, 0, 1);
}

void p2g(sim *s) { p2g_run(s, s->cfg.update == UPDATE_USAVG ? P2G_MASS : P2G_ALL); }

void p2g_force(sim *s) { p2g_run(s, P2G_FORCE); }
