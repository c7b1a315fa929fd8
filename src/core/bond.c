/*
** bond.c - interfacial bond strength between the grid and the particles.
**
** Each particle of a bonding body carries a bond strength b_p (field
** "bond", a stress): its share of the interface's strength belongs to the
** grid node nearest to it.  Before contact, every shared slot of field r
** gets the strength of the particles of r it owns (mass-weighted), and
** r's volume gradient
**   a_r = sum_p V_p grad S_ip
** whose length is the area of r's surface the node stands for (by the
** divergence theorem, the integral of S_i over r's surface); contact.c
** compares the traction the bond carries with the smaller strength of
** the two sides.  The slot also sums its particles' in-plane stresses
** weighted by w_p = V_p S_ip, and the weights: contact.c projects the
** mixture of the fields' stresses at a node on the normal.  A node that owns none of r's particles (a sliver of the
** body reaching it) takes the weighted mean of those that reach it.
**
** Where contact cut a node's strength (the traction exceeded it), the
** particles the node owns lose all their strength: damage shows on the
** particles, and a node that has let go cannot bond again, so nothing
** heals.  Removing the whole of it at once is deliberate: a strength
** criterion without a softening law has no length or energy scale by
** which to spread the loss over steps.  Why ownership rather than
** interpolation with the weights S_ip: a particle reaches two or more
** interface nodes, and taking from it in proportion to a cut neighbour's
** weight weakened the next node's strength at once, so debonding ran
** along the interface a node per step (four times c_L at cfl 0.25),
** whatever the load; with ownership a node's strength changes only when
** it is cut itself.
*/
#include <math.h>
#include <string.h>
#include "bands.h"
#include "par.h"
#include "sim.h"
#include "stencil.h"
#include "vec.h"

/* the stencil with the shape kind a constant in each branch (which also
** lets the compiler see every weight written) */
static void eval(const sim *s, const stencil_geo *geo, const double *x,
                 stencil *st) {
  const sim_cfg *cfg = &s->cfg;
  switch (cfg->shape) {
  case SHAPE_GIMP: stencil_eval(geo, SHAPE_GIMP, x, cfg->lp, st); break;
  case SHAPE_BSPLINE2: stencil_eval(geo, SHAPE_BSPLINE2, x, cfg->lp, st); break;
  default: stencil_eval(geo, SHAPE_LINEAR, x, cfg->lp, st);
  }
}

/* the node nearest to x: the one whose share of the interface the
** particle's bond is */
static int32_t nearest(const grid *g, const double *x) {
  int i[DIM], d;
  for (d = 0; d < DIM; d++)
    i[d] = grid_wrap(g, d, (int)floor((x[d] - g->lo[d]) * g->inv_h + 0.5) +
                               (g->periodic[d] ? 0 : g->pad));
  return grid_node(g, i);
}

/* the current volume of particle i, vol0 det F (2-D: the in-plane
** determinant, an area times the unit depth of plane strain) */
static double volume(const particles *ps, size_t i) {
  double F[NTENS];
  int k;
  for (k = 0; k < NTENS; k++) F[k] = ps->F[k][i];
  return ps->vol0[i] * vec_det(F);
}

/* particle i's displacement since its bond was cut (the nearest image
** across a periodic side) */
static void released(const grid *g, const particles *ps, int frel, size_t i,
                     double u[DIM]) {
  int d;
  for (d = 0; d < DIM; d++) {
    const double *x0 = particles_comp(ps, frel, 1 + d);
    double L = g->hi[d] - g->lo[d];
    u[d] = ps->x[d][i] - x0[i];
    if (g->periodic[d]) u[d] -= L * floor(u[d] / L + 0.5);
  }
}

/* particle i's share w of node n's fit sums (sim.h BF_*), node n one
** that only field f reaches: its offset from the node u (in cells), its
** stress and their products */
static void fit(sim *s, int32_t n, int32_t f, const double x[DIM], double w,
                size_t i) {
  sim_work *wk = &s->work;
  const grid *g = &s->g;
  const particles *ps = &s->ps;
  double u[DIM], sg[DIM * (DIM + 1) / 2], *b = wk->bfit;
  size_t N = g->nnodes;
  int id[DIM], d, a, c = 0;
  grid_ijk(g, n, id);
  for (d = 0; d < DIM; d++) {
    u[d] = (x[d] - grid_x(g, d, id[d])) * g->inv_h;
    if (g->periodic[d]) u[d] -= g->n[d] * floor(u[d] / g->n[d] + 0.5);
  }
  /* the stress in the order of the sums, grid_sym's */
  for (d = 0; d < DIM; d++)
    for (a = d; a < DIM; a++) sg[grid_sym(d, a)] = ps->s[vec_sym(d, a)][i];
  wk->bffield[n] = f;
  b[BF_W * N + n] += w;
  for (d = 0; d < DIM; d++) {
    b[(BF_U + d) * N + n] += w * u[d];
    for (a = d; a < DIM; a++) b[(BF_UU + c++) * N + n] += w * u[d] * u[a];
  }
  for (a = 0; a < DIM * (DIM + 1) / 2; a++) {
    b[(BF_S + a) * N + n] += w * sg[a];
    for (d = 0; d < DIM; d++) b[(BF_SU + a * DIM + d) * N + n] += w * sg[a] * u[d];
  }
}

/* Particles [i0, i1) into the slots of their shared nodes: strength,
** volume gradient, and the strength and mass each nearest node owns.
** With a plan (blk >= 0) only into the node rows this pass writes
** (bands.h): the sums then come in the particles' order whatever the
** thread count.  The nearest node is one of the stencil's, in its row
** first + (nearest row - first row). */
static void gather(sim *s, size_t i0, size_t i1, int blk, int pass) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  const particles *ps = &s->ps;
  const body *bd = s->bodies;
  const double *bp = particles_comp(ps, s->fbond, 0);
  const double *rel = particles_comp(ps, s->frel, 0);
  const double *coh = s->fcoh >= 0 ? particles_comp(ps, s->fcoh, 0) : NULL;
  const double *dmax = s->fopen >= 0 ? particles_comp(ps, s->fopen, 0) : NULL;
  /* a node's row along BANDS_DIM in the stencil: k / rowlen (nw in 2-D,
  ** nw^2 in 3-D) */
  const int rowlen = stencil_rowlen(cfg->shape), fitting = cfg->bond_fit;
  /* the normals took the volume gradient in p2g already (the same sums
  ** in the same order) */
  const int byvol = sim_vol_grad(s);
  unsigned char mine[SHAPE_MAXW];
  stencil st;
  size_t i, k;
  stencil_geo geo;
  stencil_geo_init(&geo, g);
  for (i = i0; i < i1; i++) {
    double x[DIM], mp = ps->m[i], V, u[DIM] = {0};
    int32_t node[STENCIL_MAX], f = bd[ps->body[i]].field, own;
    int nn, d, any = 0;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    nn = stencil_nodes(g, cfg->shape, x, node);
    for (k = 0; k < (size_t)nn && !any; k++) any = g->head[node[k]] >= 0;
    if (!any && !(fitting && bp[i] > 0)) continue;
    if (blk >= 0 &&
        !bands_rows(&wk->bands, &geo, cfg->shape, x[BANDS_DIM], blk, pass, mine))
      continue;
    eval(s, &geo, x, &st);
    if (rel[i] > 0) released(g, ps, s->frel, i, u);
    V = volume(ps, i);
    for (k = 0; k < (size_t)st.n; k++) {
      int32_t n = st.node[k], sl;
      if (blk >= 0 && !mine[k / rowlen]) continue;
      if (g->head[n] < 0) {
        if (fitting && bp[i] > 0 && st.w[k] > 0) fit(s, n, f, x, V * st.w[k], i);
        continue;
      }
      sl = grid_slot(g, n, f);
      g->sb[sl] += st.w[k] * mp * bp[i];
      g->ssw[sl] += V * st.w[k];
      for (d = 0; d < DIM; d++) {
        int a;
        for (a = d; a < DIM; a++)
          g->sst[grid_sym(d, a)][sl] += V * st.w[k] * ps->s[vec_sym(d, a)][i];
      }
      if (!byvol)
        for (d = 0; d < DIM; d++) g->sv[d][sl] += V * st.dw[d][k];
      if (rel[i] > 0) {
        g->srm[sl] += st.w[k] * mp;
        for (d = 0; d < DIM; d++) g->sru[d][sl] += st.w[k] * mp * u[d];
        if (coh) {
          g->scs[sl] += st.w[k] * mp * coh[i];
          g->sdm[sl] += st.w[k] * mp * dmax[i];
        }
      }
    }
    if (!any) continue;
    own = nearest(g, x);
    if (blk >= 0) {
      int r = (int)floor((x[BANDS_DIM] - g->lo[BANDS_DIM]) * g->inv_h + 0.5) +
              (g->periodic[BANDS_DIM] ? 0 : g->pad);
      if (!mine[r - stencil_first(&geo, cfg->shape, BANDS_DIM, x[BANDS_DIM])])
        continue;
    }
    if (g->head[own] >= 0) {
      int32_t sl = grid_slot(g, own, f);
      g->sbo[sl] += mp * bp[i];
      g->smo[sl] += mp;
    }
  }
}

static void gather_span(void *arg, size_t i0, size_t i1, int t, int pass) {
  gather(arg, i0, i1, t, pass);
}

/* a node's strength is that of the particles it owns; a node owning
** none of the field (a sliver of the body reaching it) takes the
** weighted mean of the particles that reach it */
static void strength_part(void *arg, int t, int nparts) {
  grid *g = arg;
  size_t k, k0, k1;
  par_range(g->nslot, t, nparts, &k0, &k1);
  for (k = k0; k < k1; k++)
    g->sb[k] = g->smo[k] > 0 ? g->sbo[k] / g->smo[k]
               : g->sm[k] > 0 ? g->sb[k] / g->sm[k] : 0.0;
}

/* over the plan p2g made: the particles have not moved since */
void bond_gather(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  if (cfg->bond_fit) memset(wk->bfit, 0, BF_N * s->g.nnodes * sizeof *wk->bfit);
  if (wk->bands.nb) bands_run(&wk->bands, wk->par, gather_span, s);
  else
    gather(s, 0, s->ps.n, -1, 1);
  par_run(wk->par, strength_part, &s->g);
}

/* particles whose nearest node was cut lose their strength: each
** particle writes only its own.  Under the cohesive law the particle keeps
** the strength it had as its cut strength, and a released particle takes
** the largest opening its nearest node has seen (the law's memory: the
** traction does not come back when the opening closes again) */
static void scatter_part(void *arg, int t, int nparts) {
  sim *s = arg;
  const grid *g = &s->g;
  particles *ps = &s->ps;
  const body *bd = s->bodies;
  double *bp = particles_comp(ps, s->fbond, 0);
  double *rel = particles_comp(ps, s->frel, 0);
  double *coh = s->fcoh >= 0 ? particles_comp(ps, s->fcoh, 0) : NULL;
  double *dmax = s->fopen >= 0 ? particles_comp(ps, s->fopen, 0) : NULL;
  size_t i, i0, i1;
  par_range(ps->n, t, nparts, &i0, &i1);
  for (i = i0; i < i1; i++) {
    double x[DIM];
    int32_t own, sl;
    int d;
    if (!(bp[i] > 0) && !(coh && rel[i] > 0)) continue;
    /* called before g2p: the particles sit where they were gathered */
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    own = nearest(g, x);
    if (g->head[own] < 0) continue;
    sl = grid_slot(g, own, bd[ps->body[i]].field);
    if (rel[i] > 0) {
      if (g->sdn[sl] > dmax[i]) dmax[i] = g->sdn[sl];
    } else if (g->scut[sl] > 0) {
      if (coh) {
        coh[i] = bp[i];
        dmax[i] = 0.0;
      }
      bp[i] = 0.0;
      rel[i] = 1.0;
      for (d = 0; d < DIM; d++)
        ((double *)particles_comp(ps, s->frel, 1 + d))[i] = x[d];
    }
  }
}

void bond_scatter(sim *s) { par_run(s->work.par, scatter_part, s); }

/* A bonded interface is one body for the step: under MUSL the velocity
** gradient comes from the particles' remapped velocities, and a bonded
** slot must give its particles the node's common velocity there too.
** Left to its own particles, a slot holding a sliver of its body at the
** stair-stepped surface extrapolates a velocity of its own, and the
** particles beside a perfectly bonded interface strain as if it slipped
** (measured on the concentric cylinders: radial stresses up to 3.6 times
** the Lame value within a cell of the interface).
**
** The stresses then work on the node's velocity v^r while the
** particles' motion is their own slot's v_r^r: over the step the strain
** energy gains sum_r dt f_r . v^r where the particles' kinetic energy
** paid dt f_r . v_r^r (book.c's derivation, f_r the slot's internal
** force, kept by contact.c in sbf).  The difference is booked with the
** bonded impulses' loss in e.bonding, so that the budget closes
** (measured on scenarios/pbx3d.lua, 140 steps: the bonded impulses took
** 14.4 % of the work put in, the remap gave back 3.1 %, and unbooked
** they left the residual at +11.1 %).
**
** Where the partner is a driven body the common velocity is the drive's,
** as in contact.c's step (vref), not the node's remapped mean: that
** mean mixes the body's ringing into the rigid body's motion, and the
** stresses worked on it returned more than the bonded impulses took
** (measured: an elastic bar bonded to a grip at rest, ringing in its
** first mode, gained 2.5 % / 0.56 % of its energy in 40 time units at
** 16 / 32 cells, booked as negative bonding loss; with the drive's
** velocity it keeps it within 0.5 %, tests/verify/bonds.lua). */
int32_t bond_driven(const sim *s, int32_t n) {
  const grid *g = &s->g;
  int32_t q;
  for (q = g->head[n]; q >= 0; q = g->snext[q])
    if (s->fdriven[g->sfield[q]] >= 0 && g->sm[q] > s->mcut) return q;
  return -1;
}

void bond_remap(sim *s) {
  grid *g = &s->g;
  double w = 0;
  size_t k;
  int d;
  for (k = 0; k < g->nslot; k++) {
    int32_t n = g->snode[k], q;
    const double *vd = NULL;
    if (!g->sbonded[k]) continue;
    if ((q = bond_driven(s, n)) >= 0) vd = s->bodies[s->fdriven[g->sfield[q]]].vdrive;
    for (d = 0; d < DIM; d++) {
      double v = vd ? vd[d] : g->p[d][n];
      if (g->sm[k] > s->mcut) w += g->sbf[d][k] * (v - g->sp[d][k]);
      g->sp[d][k] = v;
    }
  }
  /* under USAVG the remapped velocity strains the particles over half
  ** the step only (the first half's hold, usf.c, books its own): booked
  ** whole, the debond front's budget was left 3.9 % of the work open
  ** (brittle, 24 cells), with half 0.22 % */
  s->e.bonding += s->cfg.update == UPDATE_USAVG ? 0.5 * w : w;
}
