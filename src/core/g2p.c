/*
** g2p.c - grid to particles, each particle reading its own field.
**   v_p <- flip (v_p + sum_i S_ip dv_i) + (1 - flip) sum_i S_ip vL_i
**   x_p <- x_p + dt sum_i S_ip vL_i
**   L_p  = sum_i v_i (x) grad S_ip
** with v_i = vL_i (USL) or, for MUSL, the velocities of the particles'
** updated momenta mapped back to the grid (the first pass), which are
** mass-weighted averages of particle velocities and so bounded even at
** nearly empty nodes.  The pass that moves the particles also sums the
** kinetic energy and momenta, wraps periodic positions, marks particles
** that left the domain, and records each particle's cell for the sort.
*/
#include <math.h>
#include "sim.h"
#include "bands.h"
#include "par.h"
#include "stencil.h"
#include "vec.h"

/*
** What the transfer itself dissipates.  FLIP's new velocity v + S dv
** carries the grid's increment, and with it the work of every force,
** contact and wall impulse the grid booked; PIC's part of a blend
** (flip < 1), XPIC and APIC replace v by the grid's smoother velocity
** and drop what the grid cannot see.  Their change of the particle's
** velocity beyond FLIP's, d = v' - v - S dv, is booked as an impulse's
** is (book.c): as minus its work on the particle's mean velocity over
** the step, e.transfer += -1/2 m d . (v + v').  With the grid's
** impulses booked on (v^n + v^r) / 2 (v^r the remap of the new
** velocities) the change of kinetic energy is then accounted exactly:
**   sum_p 1/2 m (|v'|^2 - |v|^2) = sum_p m (S dv + d) . (v + v') / 2
**     = sum_i m_i dv_i . (v^n_i + v^r_i) / 2 + sum_p m d . (v + v') / 2.
** (Taken instead as the kinetic energy lost against FLIP's,
** 1/2 m (|v + S dv|^2 - |v'|^2), it missed 1/2 m d . S dv, the cross term
** with the grid's increment: the piston pack of lua/mvmpm/piston.lua
** left +3.4 % (GIMP APIC) and -2.6 % (linear XPIC) of the piston's work
** unbooked, a disc spinning in free space -16 % under XPIC.)
** APIC's particle carries the field u_i = v + C r_i at its nodes
** (r = x_i - x_p), whose kinetic energy 1/2 m sum_i S_ip |u_i|^2 =
** 1/2 m (|v|^2 + sum_i S_ip |C r_i|^2) (the weights reproduce linear
** fields) is what p2g hands the grid and what the kinetic energy counts;
** there d_i = u'_i - u_i - dv_i per node, booked on (u_i + u'_i) / 2.
** XPIC's f holds its correction, not dv: there S dv = S vL - S v, with
** S v kept by xpic.c in the particle's L.  Under MUSL the gather keeps
** each particle's loss in L[0] until the remap pass, whose sums run in
** chunk order, adds it up: the same at any thread count.
*/

/* APIC: the affine field's kinetic energy, sum_p 1/2 m_p sum_i S_ip
** |C_p r_ip|^2, at the particles' present positions (the state before
** the first step: sim_measure) */
double g2p_affine_energy(const sim *s) {
  const sim_cfg *cfg = &s->cfg;
  const particles *ps = &s->ps;
  const double *C[NTENS];
  double r[DIM][STENCIL_MAX], e = 0;
  stencil_geo geo;
  stencil st;
  size_t i;
  int a, b;
  if (!sim_affine(cfg) || s->faff < 0) return 0;
  for (a = 0; a < NTENS; a++) C[a] = particles_comp(ps, s->faff, a);
  stencil_geo_init(&geo, &s->g);
  for (i = 0; i < ps->n; i++) {
    double x[DIM], en = 0;
    int k, zero = 1;
    for (a = 0; a < NTENS; a++) zero &= C[a][i] == 0;
    if (zero) continue;
    for (a = 0; a < DIM; a++) x[a] = ps->x[a][i];
    stencil_eval_r(&geo, cfg->shape, x, cfg->lp, &st, r);
    for (k = 0; k < st.n; k++) {
      double t = 0;
      for (a = 0; a < DIM; a++) {
        double u = 0;
        for (b = 0; b < DIM; b++) u += C[a * DIM + b][i] * r[b][k];
        t += u * u;
      }
      en += st.w[k] * t;
    }
    e += 0.5 * ps->m[i] * en;
  }
  return e;
}

/* the sums of one chunk of particles (par.h), kept in s->work.red */
typedef struct sums {
  double ke, mom[DIM], am[3], v2max, pe, loss, wrap[DIM];
  size_t out, held;
} sums;
_Static_assert(sizeof(sums) <= SIM_RED_BYTES, "sums fit SIM_RED_BYTES");

/* the domain as settle needs it, copied into a local like stencil_geo */
typedef struct box {
  double lo[DIM], hi[DIM], inv_h, grav[DIM];
  double in[DIM];    /* how far inside a held particle is put */
  int32_t cells[DIM];
  int periodic[DIM];
  int hold[NSIDES];  /* a penalty wall: particles are held inside */
  int anyhold;
} box;

STENCIL_INLINE void box_init(box *bx, const sim *s) {
  const grid *g = &s->g;
  int d, k;
  bx->inv_h = g->inv_h;
  for (d = 0; d < DIM; d++) {
    bx->grav[d] = s->cfg.gravity[d];
    bx->lo[d] = g->lo[d];
    bx->hi[d] = g->hi[d];
    bx->in[d] = 1e-9 * g->h;
    bx->cells[d] = g->cells[d];
    bx->periodic[d] = g->periodic[d];
  }
  bx->anyhold = 0;
  for (k = 0; k < NSIDES; k++) {
    bx->hold[k] = sim_spring_side(s, k);
    bx->anyhold |= bx->hold[k];
  }
}

/* after the move: wrap, domain check, cell, sums */
STENCIL_INLINE void settle(const box *bx, particles *ps, size_t i, sums *u) {
  double m = ps->m[i], v2 = 0;
  int32_t cell = 0, stride = 1;
  int d;
  for (d = 0; d < DIM; d++) {
    double x = ps->x[d][i], r;
    if (bx->periodic[d]) {
      double L = bx->hi[d] - bx->lo[d];
      if (x >= bx->hi[d]) {
        x -= L;
        u->wrap[d] += m * L;
      } else if (x < bx->lo[d]) {
        x += L;
        u->wrap[d] -= m * L;
      }
      ps->x[d][i] = x;
    } else if (bx->anyhold) {
      /* a penalty wall's spring too soft for the impact: the particle
      ** would leave the domain (and be dropped); it is held at the wall
      ** line instead, and counted (wall_penalty.c) */
      if (bx->hold[2 * d + 1] && x >= bx->hi[d] - bx->in[d]) {
        x = ps->x[d][i] = bx->hi[d] - bx->in[d];
        u->held++;
      } else if (bx->hold[2 * d] && x < bx->lo[d]) {
        x = ps->x[d][i] = bx->lo[d];
        u->held++;
      }
    }
    /* r >= 0 once x >= lo, so the cell is (int) r; r < cells also
    ** catches x just below hi rounding up to the next cell */
    r = (x - bx->lo[d]) * bx->inv_h;
    if (!(x >= bx->lo[d] && x < bx->hi[d] && r < bx->cells[d])) cell = -1;
    else if (cell >= 0) cell += stride * (int32_t)r;
    stride *= bx->cells[d];
    v2 += ps->v[d][i] * ps->v[d][i];
    u->mom[d] += m * ps->v[d][i];
    u->pe -= m * bx->grav[d] * x;
  }
  if (cell < 0) u->out++;
  ps->cell[i] = cell;
  u->ke += 0.5 * m * v2;
  if (v2 > u->v2max) u->v2max = v2;
  {
    double x[DIM], v[DIM];
    for (d = 0; d < DIM; d++) { x[d] = ps->x[d][i]; v[d] = ps->v[d][i]; }
    vec_moment(u->am, m, x, v);
  }
}

/* what a g2p pass does besides the gather: move the particles (USL),
** or map their momenta back to the grid at every node row, at the rows
** of pass 1 of the bands plan, or at none (a second pass does) */
enum { G2P_MOVE, G2P_SCATTER, G2P_SCATTER1, G2P_GATHER };

/*
** USL: velocities, move and gradient in one pass.  MUSL pass 1:
** velocities, and at once the particles' updated momenta mapped back to
** the grid (into p, which solve_velocity cleared) with the same weights,
** so the stencil is evaluated once for both; the sums into p run in the
** particles' order either way (bands.h).  Particles [i0, i1), part blk.
*/
STENCIL_INLINE void g2p_kind(sim *s, const int kind, const int shared,
                             const int mode, const int apic, size_t i0,
                             size_t i1, int blk, sums *u) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  particles *ps = &s->ps;
  const body *bd = s->bodies;
  const double dt = s->dt, flip = cfg->flip, pic = 1.0 - flip, lp = cfg->lp;
  const int full = mode == G2P_MOVE, rowlen = stencil_rowlen(kind);
  const int scatter = mode == G2P_SCATTER || mode == G2P_SCATTER1;
  const int xp = cfg->transfer == TRANSFER_XPIC, lossy = sim_lossy(cfg);
  /* apic: 0 none, 1 APIC, 2 the spin transfer (B-splines only), a
  ** constant in each instantiation (g2p_shape), so no branch on it is
  ** left in the loops */
  const int spin = apic == 2;
  /* the dense grid only through these: loads need not wait for stores */
  const double *restrict gq[DIM], *restrict gf[DIM];
  double *restrict gp[DIM];
  /* APIC: the affine matrix C; B-splines give it exactly from the
  ** weights, C = 4 / h^2 sum_i S_ip v_i r_i^T, the hats and GIMP as the
  ** velocity gradient sum_i v_i grad S_ip^T */
  const double Dinv = 4.0 * g->inv_h * g->inv_h;
  double *C[NTENS] = {NULL};
  double r[DIM][STENCIL_MAX];
  unsigned char mine[SHAPE_MAXW];
  stencil_geo geo;
  box bx;
  stencil st;
  size_t i;
  int a, c;
  for (a = 0; a < DIM; a++) { gq[a] = g->q[a]; gf[a] = g->f[a]; gp[a] = g->p[a]; }
  stencil_geo_init(&geo, g);
  box_init(&bx, s);
  if (apic)
    for (a = 0; a < NTENS; a++) C[a] = particles_comp(ps, s->faff, a);
  for (i = i0; i < i1; i++) {
    double x[DIM], vp[DIM], v[DIM] = {0}, ac[DIM] = {0}, nv[DIM];
    double l[NTENS] = {0}, bm[NTENS] = {0}, dvr[NTENS] = {0}, bmd[NTENS] = {0};
    double aref = 0, aff = 0;
    const body *b = &bd[ps->body[i]];
    const int32_t *slot = shared ? wk->pslot + i * stencil_size(kind) : NULL;
    int k;
    for (a = 0; a < DIM; a++) { x[a] = ps->x[a][i]; vp[a] = ps->v[a][i]; }
    if (apic) stencil_eval_r(&geo, kind, x, lp, &st, r);
    else stencil_eval(&geo, kind, x, lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double w = st.w[k], q[DIM], fo[DIM];
      if (shared && slot[k] >= 0) {
        int32_t sl = slot[k];
        for (a = 0; a < DIM; a++) { q[a] = g->sq[a][sl]; fo[a] = g->sf[a][sl]; }
      } else {
        for (a = 0; a < DIM; a++) { q[a] = gq[a][n]; fo[a] = gf[a][n]; }
      }
      for (a = 0; a < DIM; a++) { v[a] += w * q[a]; ac[a] += w * fo[a]; }
      if (apic && !spin && lossy) { /* the old affine part C r, and dv against r */
        double t = 0, cr[DIM];
        for (a = 0; a < DIM; a++) {
          cr[a] = 0;
          for (c = 0; c < DIM; c++) cr[a] += C[a * DIM + c][i] * r[c][k];
          t += cr[a] * (cr[a] + fo[a]);
          for (c = 0; c < DIM; c++) dvr[a * DIM + c] += w * fo[a] * r[c][k];
        }
        aref += w * t;
      }
      if (full || (apic && kind != SHAPE_BSPLINE2))
        for (a = 0; a < DIM; a++)
          for (c = 0; c < DIM; c++) l[a * DIM + c] += q[a] * st.dw[c][k];
      if (spin) /* the increment's moment: W moves by its skew part */
        for (a = 0; a < DIM; a++)
          for (c = 0; c < DIM; c++) bmd[a * DIM + c] += fo[a] * (w * r[c][k]);
      else if (apic && kind == SHAPE_BSPLINE2)
        for (a = 0; a < DIM; a++)
          for (c = 0; c < DIM; c++) bm[a * DIM + c] += q[a] * (w * r[c][k]);
    }
    if (apic) {
      if (spin) /* the spin moved by the increment's, as v is by dv */
        for (a = 0; a < DIM; a++)
          for (c = 0; c < DIM; c++)
            bm[a * DIM + c] = a == c ? 0
                : C[a * DIM + c][i] + 0.5 * Dinv * (bmd[a * DIM + c] - bmd[c * DIM + a]);
      else
        for (a = 0; a < NTENS; a++)
          bm[a] = kind == SHAPE_BSPLINE2 ? bm[a] * Dinv : l[a];
      if (b->driven)
        for (a = 0; a < NTENS; a++) bm[a] = 0;
      for (a = 0; a < NTENS; a++) C[a][i] = bm[a];
      for (k = 0; k < st.n; k++) { /* the new affine field's energy */
        double t = 0;
        for (a = 0; a < DIM; a++) {
          double ua = 0;
          for (c = 0; c < DIM; c++) ua += bm[a * DIM + c] * r[c][k];
          t += ua * ua;
        }
        aff += st.w[k] * t;
      }
      aff *= 0.5 * ps->m[i];
    }
    for (a = 0; a < DIM; a++) {
      if (b->driven) nv[a] = b->vdrive[a];
      else if (apic && !spin) nv[a] = v[a];
      else if (xp) nv[a] = v[a] + ac[a]; /* f holds XPIC's correction c (xpic.c) */
      else nv[a] = flip * (vp[a] + ac[a]) + pic * v[a];
    }
    if (lossy) { /* the transfer's change of velocity, booked as work */
      double loss = 0, t = 0;
      if (b->driven) {
      } else if (apic && !spin) {
        /* sum_i S_ip d_i . (u_i + u'_i), d_i = u'_i - u_i - dv_i, with
        ** u_i = v + C r_i, u'_i = v' + C' r_i: |u'|^2 - |u|^2 summed
        ** (the cross terms drop: sum_i S_ip r_i = 0) less dv . (u + u') */
        for (a = 0; a < DIM; a++) {
          t += nv[a] * nv[a] - vp[a] * vp[a] - ac[a] * (vp[a] + nv[a]);
          for (c = 0; c < DIM; c++) t -= bm[a * DIM + c] * dvr[a * DIM + c];
        }
        t += aff * 2.0 / ps->m[i] - aref;
        loss = -0.5 * ps->m[i] * t;
      } else {
        /* d = v' - v - S dv on the mean (v + v') / 2; XPIC: S dv =
        ** S vL - S v, S v kept by xpic.c in L.  Spin: the affine terms
        ** of APIC's sum above cancel exactly for W' = W + skew(D^-1
        ** sum_i S_ip dv_i r_i^T) (with D = h^2/4, W and W' skew), so
        ** only the velocity's part is left, FLIP's or the blend's */
        for (a = 0; a < DIM; a++) {
          double sdv = xp ? v[a] - ps->L[a][i] : ac[a];
          t += (nv[a] - vp[a] - sdv) * (vp[a] + nv[a]);
        }
        loss = -0.5 * ps->m[i] * t;
      }
      if (full) { u->loss += loss; u->ke += aff; }
      else { /* kept for remap_kind, which sums them */
        ps->L[0][i] = loss;
        ps->L[1][i] = aff;
      }
    }
    for (a = 0; a < DIM; a++) ps->v[a][i] = nv[a];
    if (full) {
      for (a = 0; a < NTENS; a++) ps->L[a][i] = l[a];
      for (a = 0; a < DIM; a++) ps->x[a][i] = x[a] + dt * v[a];
      settle(&bx, ps, i, u);
    } else if (scatter) {
      const double mp = ps->m[i];
      if (mode == G2P_SCATTER1 &&
          !bands_rows(&wk->bands, &geo, kind, x[BANDS_DIM], blk, 1, mine))
        continue;
      for (k = 0; k < st.n; k++) {
        int32_t n = st.node[k];
        double wm = st.w[k] * mp, uu[DIM];
        if (mode == G2P_SCATTER1 && !mine[k / rowlen]) continue;
        for (a = 0; a < DIM; a++) {
          uu[a] = nv[a];
          if (apic) {
            double cr = bm[a * DIM] * r[0][k];
            for (c = 1; c < DIM; c++) cr += bm[a * DIM + c] * r[c][k];
            uu[a] += cr;
          }
          gp[a][n] += wm * uu[a];
        }
        if (shared && slot[k] >= 0)
          for (a = 0; a < DIM; a++) g->sp[a][slot[k]] += wm * uu[a];
      }
    }
  }
}

/*
** MUSL: the momenta of particles [i0, i1) back to the grid, from the
** velocities (and affine matrices) the gather stored; the same numbers
** as the scatter in g2p_kind.  split: only the node rows of pass 2 of
** part blk; otherwise every row.
*/
STENCIL_INLINE void scatter_kind(sim *s, const int kind, const int shared,
                                 const int apic, const int split, size_t i0,
                                 size_t i1, int blk) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const particles *ps = &s->ps;
  const double lp = cfg->lp;
  const int rowlen = stencil_rowlen(kind);
  double *restrict gp[DIM];
  const double *C[NTENS] = {NULL};
  double r[DIM][STENCIL_MAX];
  unsigned char mine[SHAPE_MAXW];
  stencil_geo geo;
  stencil st;
  size_t i;
  int a, c;
  for (a = 0; a < DIM; a++) gp[a] = g->p[a];
  stencil_geo_init(&geo, g);
  if (apic)
    for (a = 0; a < NTENS; a++) C[a] = particles_comp(ps, s->faff, a);
  for (i = i0; i < i1; i++) {
    double x[DIM], nv[DIM];
    const double mp = ps->m[i];
    const int32_t *slot = shared ? wk->pslot + i * stencil_size(kind) : NULL;
    int k;
    for (a = 0; a < DIM; a++) { x[a] = ps->x[a][i]; nv[a] = ps->v[a][i]; }
    if (split &&
        !bands_rows(&wk->bands, &geo, kind, x[BANDS_DIM], blk, 2, mine))
      continue;
    if (apic) stencil_eval_r(&geo, kind, x, lp, &st, r);
    else stencil_eval(&geo, kind, x, lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double wm = st.w[k] * mp, uu[DIM];
      if (split && !mine[k / rowlen]) continue;
      for (a = 0; a < DIM; a++) {
        uu[a] = nv[a];
        if (apic) {
          double cr = C[a * DIM][i] * r[0][k];
          for (c = 1; c < DIM; c++) cr += C[a * DIM + c][i] * r[c][k];
          uu[a] += cr;
        }
        gp[a][n] += wm * uu[a];
      }
      if (shared && slot[k] >= 0)
        for (a = 0; a < DIM; a++) g->sp[a][slot[k]] += wm * uu[a];
    }
  }
}

STENCIL_INLINE void g2p_shape(sim *s, const int kind, int mode, size_t i0,
                              size_t i1, int blk, sums *u) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0, apic = sim_affine(cfg);
  /* kind is a constant here: off B-splines the spin's instance is dead */
  const int spin = kind == SHAPE_BSPLINE2 && cfg->transfer == TRANSFER_SPIN;
#define G2PA(SH, MO)                                                     \
  if (spin) g2p_kind(s, kind, SH, MO, 2, i0, i1, blk, u);                \
  else if (apic) g2p_kind(s, kind, SH, MO, 1, i0, i1, blk, u);           \
  else g2p_kind(s, kind, SH, MO, 0, i0, i1, blk, u);
#define G2PM(SH)                                                         \
  switch (mode) {                                                        \
  case G2P_MOVE: G2PA(SH, G2P_MOVE) break;                               \
  case G2P_SCATTER: G2PA(SH, G2P_SCATTER) break;                         \
  case G2P_SCATTER1: G2PA(SH, G2P_SCATTER1) break;                       \
  default: G2PA(SH, G2P_GATHER)                                          \
  }
  if (shared) { G2PM(1) } else { G2PM(0) }
#undef G2PM
#undef G2PA
}

static void g2p_range(sim *s, int mode, size_t i0, size_t i1, int blk,
                      sums *u) {
  const sim_cfg *cfg = &s->cfg;
  switch (cfg->shape) {
  case SHAPE_GIMP: g2p_shape(s, SHAPE_GIMP, mode, i0, i1, blk, u); break;
  case SHAPE_BSPLINE2:
    g2p_shape(s, SHAPE_BSPLINE2, mode, i0, i1, blk, u);
    break;
  default: g2p_shape(s, SHAPE_LINEAR, mode, i0, i1, blk, u);
  }
}

STENCIL_INLINE void scatter_shape(sim *s, const int kind, int split,
                                  size_t i0, size_t i1, int blk) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0, apic = sim_affine(cfg);
#define SCA(SH, AP)                                                      \
  if (split) scatter_kind(s, kind, SH, AP, 1, i0, i1, blk);              \
  else scatter_kind(s, kind, SH, AP, 0, i0, i1, blk);
  if (shared) { if (apic) { SCA(1, 1) } else { SCA(1, 0) } }
  else { if (apic) { SCA(0, 1) } else { SCA(0, 0) } }
#undef SCA
}

static void scatter_range(sim *s, int split, size_t i0, size_t i1, int blk) {
  const sim_cfg *cfg = &s->cfg;
  switch (cfg->shape) {
  case SHAPE_GIMP: scatter_shape(s, SHAPE_GIMP, split, i0, i1, blk); break;
  case SHAPE_BSPLINE2:
    scatter_shape(s, SHAPE_BSPLINE2, split, i0, i1, blk);
    break;
  default: scatter_shape(s, SHAPE_LINEAR, split, i0, i1, blk);
  }
}

/* the sums of every chunk, added in chunk order: the same for any
** thread count */
static void finish(sim *s) {
  sim_work *wk = &s->work;
  const sums *red = wk->red;
  sums u = {0};
  size_t c, nc = par_nchunks(s->ps.n);
  int d;
  for (c = 0; c < nc; c++) {
    u.ke += red[c].ke;
    for (d = 0; d < DIM; d++) u.mom[d] += red[c].mom[d];
    for (d = 0; d < 3; d++) u.am[d] += red[c].am[d];
    u.pe += red[c].pe;
    for (d = 0; d < DIM; d++) u.wrap[d] += red[c].wrap[d];
    u.out += red[c].out;
    u.held += red[c].held;
    u.loss += red[c].loss;
    if (red[c].v2max > u.v2max) u.v2max = red[c].v2max;
  }
  s->e.kinetic = u.ke;
  for (d = 0; d < DIM; d++) s->e.wrap[d] += u.wrap[d];
  s->e.potential = sim_potential(s, u.pe);
  s->e.wall_spring = wall_penalty_energy(s) + wall_spring_energy(s); /* at the moved positions */
  for (d = 0; d < DIM; d++) s->e.mom[d] = u.mom[d];
  for (d = 0; d < 3; d++) s->e.angmom[d] = u.am[d];
  s->vmax = sqrt(u.v2max);
  s->nout = u.out;
  s->nheld += u.held;
  s->e.transfer += u.loss;
}

typedef struct g2p_job { sim *s; int mode; } g2p_job;

/* USL: whole chunks, each with its own sums */
static void move_part(void *arg, int t, int nparts) {
  g2p_job *j = arg;
  sums *red = j->s->work.red;
  size_t n = j->s->ps.n, c, c0, c1, i0, i1;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    sums z = {0};
    red[c] = z;
    par_chunk(n, c, &i0, &i1);
    g2p_range(j->s, G2P_MOVE, i0, i1, t, &red[c]);
  }
}

/* MUSL pass 1 with a plan: part t gathers and maps back at its rows,
** then (the plan's pass 2) at the rows of the part before */
static void split_part(void *arg, int t, int nparts) {
  g2p_job *j = arg;
  size_t i0, i1;
  bands_span(&j->s->work.bands, t, j->mode == G2P_SCATTER1 ? 1 : 2, &i0, &i1);
  if (j->mode == G2P_SCATTER1)
    g2p_range(j->s, G2P_SCATTER1, i0, i1, t, NULL);
  else
    scatter_range(j->s, 1, i0, i1, t);
}

/* MUSL pass 1 without a plan: the gather only, cut anywhere */
static void gather_part(void *arg, int t, int nparts) {
  g2p_job *j = arg;
  size_t i0, i1;
  par_range(j->s->ps.n, t, nparts, &i0, &i1);
  g2p_range(j->s, G2P_GATHER, i0, i1, t, NULL);
}

void g2p(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  g2p_job j = {s, G2P_MOVE};
  if (cfg->update == UPDATE_USL) {
    par_run(wk->par, move_part, &j);
    finish(s);
  } else if (wk->bands.nb) { /* the plan p2g made */
    j.mode = G2P_SCATTER1;
    par_run(wk->par, split_part, &j);
    j.mode = G2P_SCATTER;
    par_run(wk->par, split_part, &j);
  } else if (par_threads(wk->par) > 1) {
    par_run(wk->par, gather_part, &j);
    scatter_range(s, 0, 0, s->ps.n, 0);
  } else
    g2p_range(s, G2P_SCATTER, 0, s->ps.n, 0, NULL);
}

/* MUSL pass 2: gradient from the remapped velocities (in p), move with vL */
STENCIL_INLINE void remap_kind(sim *s, const int kind, const int shared,
                               size_t i0, size_t i1, sums *u) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  particles *ps = &s->ps;
  const double dt = s->dt, lp = cfg->lp;
  const int lossy = sim_lossy(cfg), apic = sim_affine(cfg);
  const double *restrict gp[DIM], *restrict gq[DIM];
  stencil_geo geo;
  box bx;
  stencil st;
  size_t i;
  int a, c;
  for (a = 0; a < DIM; a++) { gp[a] = g->p[a]; gq[a] = g->q[a]; }
  stencil_geo_init(&geo, g);
  box_init(&bx, s);
  for (i = i0; i < i1; i++) {
    double x[DIM], v[DIM] = {0}, l[NTENS] = {0};
    const int32_t *slot = shared ? s->work.pslot + i * stencil_size(kind) : NULL;
    int k;
    for (a = 0; a < DIM; a++) x[a] = ps->x[a][i];
    stencil_eval(&geo, kind, x, lp, &st);
    /* the velocity and the gradient in two loops over the nodes: each
    ** sum in the same order as in one, with fewer sums live at once (one
    ** loop over 9 or 27 nodes, unrolled, ran out of registers) */
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double q[DIM];
      if (shared && slot[k] >= 0) {
        for (a = 0; a < DIM; a++) q[a] = g->sq[a][slot[k]];
      } else {
        for (a = 0; a < DIM; a++) q[a] = gq[a][n];
      }
      for (a = 0; a < DIM; a++) v[a] += st.w[k] * q[a];
    }
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      double uu[DIM];
      if (shared && slot[k] >= 0) {
        for (a = 0; a < DIM; a++) uu[a] = g->sp[a][slot[k]];
      } else {
        for (a = 0; a < DIM; a++) uu[a] = gp[a][n];
      }
      for (a = 0; a < DIM; a++)
        for (c = 0; c < DIM; c++) l[a * DIM + c] += uu[a] * st.dw[c][k];
    }
    if (lossy) { /* g2p_kind's, before L is set */
      u->loss += ps->L[0][i];
      if (apic) u->ke += ps->L[1][i];
    }
    for (a = 0; a < NTENS; a++) ps->L[a][i] = l[a];
    for (a = 0; a < DIM; a++) ps->x[a][i] = x[a] + dt * v[a];
    settle(&bx, ps, i, u);
  }
}

static void remap_range(sim *s, size_t i0, size_t i1, sums *u) {
  const sim_cfg *cfg = &s->cfg;
  int shared = s->g.nshared > 0;
  switch (cfg->shape) {
  case SHAPE_GIMP:
    if (shared) remap_kind(s, SHAPE_GIMP, 1, i0, i1, u);
    else remap_kind(s, SHAPE_GIMP, 0, i0, i1, u);
    break;
  case SHAPE_BSPLINE2:
    if (shared) remap_kind(s, SHAPE_BSPLINE2, 1, i0, i1, u);
    else remap_kind(s, SHAPE_BSPLINE2, 0, i0, i1, u);
    break;
  default:
    if (shared) remap_kind(s, SHAPE_LINEAR, 1, i0, i1, u);
    else remap_kind(s, SHAPE_LINEAR, 0, i0, i1, u);
  }
}

static void remap_part(void *arg, int t, int nparts) {
  sim *s = arg;
  sim_work *wk = &s->work;
  sums *red = wk->red;
  size_t n = s->ps.n, c, c0, c1, i0, i1;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    sums z = {0};
    red[c] = z;
    par_chunk(n, c, &i0, &i1);
    remap_range(s, i0, i1, &red[c]);
  }
}

void g2p_remap(sim *s) {
  sim_work *wk = &s->work;
  par_run(wk->par, remap_part, s);
  finish(s);
}
