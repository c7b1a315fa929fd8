/*
** heat.c - heat sources and the temperature update (see heat.h for the
** sources and their booking; conduct.c for conduction).
**
** Friction heat is made at grid nodes: contact.c and boundary.c put each
** node's (or slot's) friction work on hn / hs, and heat_grid hands it to
** the particles by their mass share of the field's nodal mass,
** N_ip m_p / m_i.  p2g summed m_i = sum_p N_ip m_p with the same weights
** and positions, so the particles' shares add up to 1 and their heat to
** the booked work, to round-off.  It must run before g2p moves them.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conduct.h"
#include "heat.h"
#include "stencil.h"
#include "thermal.h"

int heat_enable(sim *s) {
  heat_state *h;
  particles *ps = &s->ps;
  int k;
  if (s->heat) return 0;
  if (s->started) {
    snprintf(s->err, sizeof s->err, "heat: switch heat on before the first step");
    return -1;
  }
  if (thermal_enable(s) || !(h = calloc(1, sizeof *h))) goto oom;
  s->heat = h;
  h->fq = particles_add_field(ps, "heat_step", 1, PF_DOUBLE, "M L^2/T^2", 0);
  h->fheat = particles_add_field(ps, "heat", 1, PF_DOUBLE, "M L^2/T^2",
                                 PF_OUTPUT | PF_RESTART);
  h->ffric = particles_add_field(ps, "heat_friction", 1, PF_DOUBLE,
                                 "M L^2/T^2", PF_OUTPUT | PF_RESTART);
  if (h->fq < 0 || h->fheat < 0 || h->ffric < 0) goto oom;
  h->split = HEAT_SPLIT_SHARE;
  h->share = 0.5;
  h->wall_share = 1;
  h->contact = HEAT_PERFECT;
  for (k = 0; k < NSIDES; k++) h->walls[k].kind = HEAT_INSULATED;
  for (k = 0; k < s->nmat; k++) s->mats[k].fheat = h->fq;
  return 0;
oom:
  snprintf(s->err, sizeof s->err, "heat: out of memory");
  return -1;
}

void heat_free(sim *s) {
  heat_state *h = s->heat;
  int d;
  if (!h) return;
  conduct_free(s);
  free(h->feff);
  free(h->hn);
  free(h->hs);
  for (d = 0; d < DIM; d++) free(h->swi[d]);
  free(h);
  s->heat = NULL;
}

double heat_energy(const sim *s) {
  const particles *ps = &s->ps;
  const double *T = particles_comp(ps, s->ftemp, 0);
  double E = 0;
  size_t i;
  for (i = 0; i < ps->n; i++) {
    int32_t mi = s->bmat[ps->body[i]];
    if (mi >= 0) E += ps->m[i] * s->mats[mi].cv * T[i];
  }
  return E - s->heat->E0;
}

double heat_booked(const sim *s) {
  const sim_energy *e = &s->e;
  return e->heat_friction + e->heat_plastic + e->heat_viscous +
         e->heat_source + e->heat_boundary - e->latent;
}

int heat_start(sim *s) {
  heat_state *h = s->heat;
  int b, f;
  s->temp_on = 0; /* sim:temperature(T) gave the initial temperature only */
  for (b = 0; b < s->nbody; b++) {
    const material *m;
    if (s->bmat[b] < 0) {
      if (s->bodies[b].hold) {
        snprintf(s->err, sizeof s->err, "body '%s': hold_temperature needs a "
                 "body with a material (a driven body has no heat capacity)",
                 s->bodies[b].name);
        return -1;
      }
      continue;
    }
    m = &s->mats[s->bmat[b]];
    if (!(m->cv > 0)) {
      snprintf(s->err, sizeof s->err, "heat: material '%s' (body '%s') has "
               "no specific heat: give cv > 0 (per unit mass) in its constructor",
               m->name, s->bodies[b].name);
      return -1;
    }
  }
  if (!(h->feff = calloc((size_t)s->nfield + 1, sizeof *h->feff))) goto oom;
  for (f = 0; f < s->nfield; f++) h->feff[f] = 1;
  for (b = s->nbody - 1; b >= 0; b--) /* the first body of each field */
    if (s->bmat[b] >= 0) {
      const material *m = &s->mats[s->bmat[b]];
      h->feff[s->bodies[b].field] = sqrt(m->kcond * m->rho * m->cv);
    }
  if (!(h->hn = calloc(s->g.nnodes, sizeof *h->hn))) goto oom;
  if (conduct_start(s)) return -1;
  h->ready = 1;
  if (!s->started) {
    const particles *ps = &s->ps;
    double *T = particles_comp(ps, s->ftemp, 0);
    size_t i;
    for (i = 0; i < ps->n; i++) { /* held bodies start at their temperature */
      const body *bd = &s->bodies[ps->body[i]];
      if (bd->hold) T[i] = bd->T_hold;
    }
    h->E0 = 0;
    h->E0 = heat_energy(s);
  }
  return 0;
oom:
  snprintf(s->err, sizeof s->err, "heat: out of memory");
  return -1;
}

int heat_prepare(sim *s) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  int d;
  if (g->slotcap > h->hscap) {
    double *p = realloc(h->hs, g->slotcap * sizeof *p);
    if (!p) goto oom;
    h->hs = p;
    for (d = 0; d < DIM; d++) {
      if (!(p = realloc(h->swi[d], g->slotcap * sizeof *p))) goto oom;
      h->swi[d] = p;
    }
    h->hscap = g->slotcap;
  }
  memset(h->hn, 0, g->nnodes * sizeof *h->hn);
  if (g->nslot) {
    memset(h->hs, 0, g->nslot * sizeof *h->hs);
    for (d = 0; d < DIM; d++) memset(h->swi[d], 0, g->nslot * sizeof *h->swi[d]);
  }
  if (h->conduct && conduct_prepare(s)) return -1;
  return 0;
oom:
  snprintf(s->err, sizeof s->err, "heat: out of memory for the grid's heat");
  return -1;
}

void heat_contact(sim *s, const int32_t *slots, int ns, int32_t drv,
                  double fric) {
  heat_state *h = s->heat;
  const grid *g = &s->g;
  double w[64], sum = 0; /* contact.c gathers at most 64 slots */
  int k, n = 0, lo = -1;
  if (fric == 0) return;
  for (k = 0; k < ns && k < 64; k++) {
    int32_t sl = slots[k], f = g->sfield[sl];
    w[k] = 0;
    if (sl == drv || s->fdriven[f] >= 0 || !(g->sm[sl] > s->mcut)) continue;
    w[k] = h->split == HEAT_SPLIT_EFFUSIVITY ? h->feff[f] : 1;
    n++;
    if (lo < 0 || f < g->sfield[slots[lo]]) lo = k;
  }
  /* two sides: the first field takes share, the other the rest */
  if (n == 2 && h->split == HEAT_SPLIT_SHARE)
    for (k = 0; k < ns && k < 64; k++)
      if (w[k] > 0) w[k] = k == lo ? h->share : 1 - h->share;
  for (k = 0; k < ns && k < 64; k++) sum += w[k];
  if (!(sum > 0)) { /* no side takes heat: equal among the material */
    for (k = 0; k < ns && k < 64; k++)
      w[k] = s->fdriven[g->sfield[slots[k]]] < 0 && g->sm[slots[k]] > 0;
    for (sum = 0, k = 0; k < ns && k < 64; k++) sum += w[k];
    if (!(sum > 0)) return;
  }
  for (k = 0; k < ns && k < 64; k++)
    if (w[k] > 0) h->hs[slots[k]] += fric * (w[k] / sum);
}

void heat_wall_friction(sim *s, int32_t n, int32_t sl, double loss) {
  heat_state *h = s->heat;
  double in = h->wall_share * loss;
  if (sl >= 0) h->hs[sl] += in;
  else h->hn[n] += in;
  s->e.heat_wall += loss - in;
}

/* the nodes' friction heat to the particles, per stencil kind */
STENCIL_INLINE double gather_kind(sim *s, const int kind) {
  const sim_cfg *cfg = &s->cfg;
  heat_state *h = s->heat;
  const grid *g = &s->g;
  particles *ps = &s->ps;
  double *q = particles_comp(ps, h->fq, 0);
  double *qf = particles_comp(ps, h->ffric, 0);
  double total = 0;
  stencil_geo geo;
  stencil st;
  size_t i;
  stencil_geo_init(&geo, g);
  for (i = 0; i < ps->n; i++) {
    double x[DIM], mp = ps->m[i], sum = 0;
    int32_t f = s->bodies[ps->body[i]].field;
    int k, d;
    if (s->bmat[ps->body[i]] < 0) continue;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    stencil_eval(&geo, kind, x, cfg->lp, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      if (g->head[n] >= 0) {
        int32_t sl = grid_slot(g, n, f);
        if (h->hs[sl] != 0) sum += st.w[k] * mp * (h->hs[sl] / g->sm[sl]);
      } else if (h->hn[n] != 0)
        sum += st.w[k] * mp * (h->hn[n] / g->m[n]);
    }
    if (sum != 0) {
      q[i] += sum;
      qf[i] += sum;
      total += sum;
    }
  }
  return total;
}

/* the nodes' friction heat to the particles, booked as friction heat */
static void gather(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  double fr;
  switch (cfg->shape) {
  case SHAPE_GIMP: fr = gather_kind(s, SHAPE_GIMP); break;
  case SHAPE_BSPLINE2: fr = gather_kind(s, SHAPE_BSPLINE2); break;
  default: fr = gather_kind(s, SHAPE_LINEAR);
  }
  s->e.heat_friction += fr;
}

int heat_grid(sim *s) {
  gather(s);
  if (s->heat->conduct) return conduct(s);
  return 0;
}

/* -c . v / 2 of one entry: the second half of an impulse's work (book.c) */
static double half_work(double *const c[DIM], double *const v[DIM], size_t i) {
  double w = 0;
  int d;
  for (d = 0; d < DIM; d++) w += c[d][i] * v[d][i];
  return -0.5 * w;
}

void heat_finish(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  heat_state *h = s->heat;
  const grid *g = &s->g;
  const int remap = cfg->update != UPDATE_USL;
  double *const *v = remap ? g->p : g->q, *const *sv = remap ? g->sp : g->sq;
  size_t n;
  memset(h->hn, 0, g->nnodes * sizeof *h->hn);
  if (g->nslot) memset(h->hs, 0, g->nslot * sizeof *h->hs);
  for (n = 0; n < g->nnodes; n++) {
    int32_t slots[64], sl;
    double wc = 0;
    int ns = 0;
    if (!(g->m[n] > s->mcut)) continue;
    if (g->head[n] < 0) { /* the dense table: the walls' friction only */
      double w = half_work(g->fi, v, n);
      if (w != 0) heat_wall_friction(s, (int32_t)n, -1, w);
      continue;
    }
    /* at a shared node, what the walls did to each slot is the walls';
    ** the rest of the slots' friction is contact's, split as contact.c
    ** split the first half (drv -1: heat_contact passes over driven
    ** fields itself) */
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
      double w, ww;
      if (ns < 64) slots[ns++] = sl;
      if (!(g->sm[sl] > s->mcut)) continue;
      w = half_work(g->sfi, sv, (size_t)sl);
      ww = half_work(h->swi, sv, (size_t)sl);
      if (ww != 0) heat_wall_friction(s, (int32_t)n, sl, ww);
      wc += w - ww;
    }
    if (wc != 0) heat_contact(s, slots, ns, -1, wc);
  }
  gather(s);
}

void heat_update(sim *s) {
  heat_state *h = s->heat;
  particles *ps = &s->ps;
  double *q = particles_comp(ps, h->fq, 0);
  double *qh = particles_comp(ps, h->fheat, 0);
  double *T = particles_comp(ps, s->ftemp, 0);
  const double *qc = h->conduct ? h->hcond : NULL;
  double work = 0, held = 0, E = 0;
  size_t i;
  for (i = 0; i < ps->n; i++) {
    const body *bd = &s->bodies[ps->body[i]];
    int32_t mi = s->bmat[ps->body[i]];
    const material *m;
    double qs = q[i], dT;
    q[i] = 0;
    if (mi < 0) continue;
    m = &s->mats[mi];
    qh[i] += qs;
    if (bd->hold) { /* the reservoir takes it */
      held += qs;
      E += ps->m[i] * m->cv * T[i];
      continue;
    }
    dT = (qs + (qc ? qc[i] : 0)) / (ps->m[i] * m->cv);
    T[i] += dT;
    E += ps->m[i] * m->cv * T[i];
    if (m->alpha != 0 && dT != 0) work += thermal_strain(m, ps, i, dT);
  }
  s->e.heat_boundary -= held;
  s->e.thermal += work;
  s->e.heat_thermal = E - h->E0;
}

double sim_heat_residual(const sim *s) {
  if (!s->heat) return 0;
  return heat_booked(s) - s->e.heat_thermal;
}

double sim_residual_all(const sim *s) {
  const sim_energy *e = &s->e;
  if (!s->heat) return sim_residual(s);
  return sim_residual(s) + e->friction + e->plastic + e->viscous +
         e->heat_source + e->heat_boundary - e->heat_thermal - e->cold -
         e->heat_wall - e->latent;
}
