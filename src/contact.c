/*
** contact.c - multi-velocity-field contact at shared nodes.
**
** Normals.  With g_r = sum_p m_p grad S_ip over the particles of field r
** (grad S_ip, taken at the particle, points from the particle toward the
** node, so g_r is minus the gradient of r's nodal mass: outward) and
** G = sum_r g_r, the outward unit normal of body r is
**   n_r = (2 g_r - G) / |2 g_r - G|
** With two fields this is (g_A - g_B)/|.|, so n_B = -n_A exactly: both
** sides see one interface.
**
** The rule (after the grid momentum update, on q = p + dt f):
**   v_cm = sum q_r / sum m_r (a driven body's velocity replaces it)
**   dp_r = q_r - m_r v_cm, dn = dp_r . n_r
** Field r is in contact when it approaches (dn > 0: after this step's
** forces, compressive tractions included, it would move into the other
** material) and, with the separation check on, the surfaces touch
** (reach.c).  Then the normal part of dp_r is removed and the tangential
** part t is reduced by mu dn (Coulomb), or removed if |t| <= mu dn
** (stick).  The corrections are made to sum to zero (mass-weighted
** residual), so the node's total momentum is conserved to round-off;
** with two fields the residual is round-off itself.
**
** Friction work: the kinetic energy of tangential relative motion removed,
** (|t|^2 - |t'|^2) / (2 m_r), summed over fields.
*/
#include <math.h>
#include "sim.h"

#define MAXSLOTS 64

void contact_normals(sim *s) {
  grid *g = &s->g;
  size_t k;
  for (k = 0; k < g->nshared; k++) {
    int32_t n = g->shared[k], sl;
    double G[DIM] = {0};
    int d;
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl])
      for (d = 0; d < DIM; d++) G[d] += g->sg[d][sl];
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
      double v[DIM], len = 0;
      for (d = 0; d < DIM; d++) {
        v[d] = 2.0 * g->sg[d][sl] - G[d];
        len += v[d] * v[d];
      }
      len = sqrt(len);
      for (d = 0; d < DIM; d++) g->sn[d][sl] = len > 0 ? v[d] / len : 0.0;
    }
  }
}

/* normal traction n.sigma.n of slot sl (tension positive) */
static double traction(const grid *g, int32_t sl) {
  double nx = g->sn[0][sl], ny = g->sn[1][sl];
#if DIM == 2
  return nx * nx * g->ss[0][sl] + ny * ny * g->ss[1][sl] +
         2 * nx * ny * g->ss[2][sl];
#else
#error "contact traction: 3-D not written yet"
#endif
}

/*
** Bonds (the report's rule).  Where field r and its partner o both carry
** bond strength and their law lets them bond, the interface is bonded
** while the normal traction t (mass-weighted over the two sides) stays
** at or below the strength b = min(b_r, b_o, the law's cap): then r moves
** with the
** reference velocity (perfect bonding, as on one field).  When t > b the
** node's strength on both sides is cut to zero, the cut recorded for
** bond_scatter, and the interface is treated as debonded contact from
** this step on.  Returns 1 if bonded.
*/
static int bonded(sim *s, int32_t sl, int32_t o, int odriven) {
  grid *g = &s->g;
  const pairlaw *l;
  double b, t, cap;
  if (!(g->sb[sl] > 0) || !(g->sb[o] > 0 || odriven)) return 0;
  l = sim_law_of(s, g->sfield[sl], g->sfield[o]);
  cap = l ? l->bond : s->bond_default;
  if (!(cap > 0)) return 0;
  if (odriven) { b = g->sb[sl]; t = traction(g, sl); }
  else {
    b = g->sb[sl] < g->sb[o] ? g->sb[sl] : g->sb[o];
    t = (g->sm[sl] * traction(g, sl) + g->sm[o] * traction(g, o)) /
        (g->sm[sl] + g->sm[o]);
  }
  if (cap < b) b = cap;
  if (t <= b) return 1;
  g->scut[sl] += g->sb[sl];
  g->sb[sl] = 0;
  if (!odriven) {
    g->scut[o] += g->sb[o];
    g->sb[o] = 0;
  }
  s->ncut++;
  return 0;
}

static void node(sim *s, int32_t n, double *const mom[DIM],
                 double *const smom[DIM]) {
  grid *g = &s->g;
  double c[MAXSLOTS][DIM], csum[DIM] = {0}, vref[DIM], M = g->m[n];
  int32_t sl, slots[MAXSLOTS], drv = -1;
  int ns = 0, k, d, bonds = s->fbond >= 0;
  if (M <= s->mcut) return;
  for (sl = g->head[n]; sl >= 0 && ns < MAXSLOTS; sl = g->snext[sl]) {
    slots[ns++] = sl;
    if (s->fdriven[g->sfield[sl]] >= 0 && drv < 0) drv = sl;
  }
  if (drv >= 0) {
    const body *b = &s->bodies[s->fdriven[g->sfield[drv]]];
    for (d = 0; d < DIM; d++) vref[d] = b->vdrive[d];
  } else
    for (d = 0; d < DIM; d++) vref[d] = mom[d][n] / M;
  for (k = 0; k < ns; k++) {
    double dp[DIM], t[DIM], dn = 0, tt = 0, mr, mu, other = -1e300, mo = -1;
    int32_t o = -1;
    int j;
    sl = slots[k];
    mr = g->sm[sl];
    for (d = 0; d < DIM; d++) c[k][d] = 0;
    if (sl == drv || s->fdriven[g->sfield[sl]] >= 0 || mr <= s->mcut) continue;
    for (d = 0; d < DIM; d++) {
      dp[d] = smom[d][sl] - mr * vref[d];
      dn += dp[d] * g->sn[d][sl];
    }
    /* the partner: the driven body, else the heaviest other field here;
    ** the largest reach of the others, for the separation check */
    for (j = 0; j < ns; j++) {
      int32_t q = slots[j];
      if (q == sl) continue;
      if (g->sext[q] > other) other = g->sext[q];
      if (g->sm[q] > mo) { mo = g->sm[q]; o = q; }
    }
    if (drv >= 0) o = drv;
    if (bonds && bonded(s, sl, o, drv >= 0)) {
      /* no energy is booked here: the fields' nodal velocities differ
      ** only by how the particles sample them, as on one shared field,
      ** and FLIP keeps each particle's own motion (measured: booking
      ** sum |dp|^2 / 2m as lost left the budget short by exactly that) */
      for (d = 0; d < DIM; d++) {
        c[k][d] = -dp[d];
        csum[d] += c[k][d];
      }
      continue;
    }
    if (!(dn > 0)) continue;
    if (s->gap_check && g->sext[sl] + other < 0) continue;
    mu = sim_law(s, g->sfield[sl], g->sfield[o]);
    for (d = 0; d < DIM; d++) {
      t[d] = dp[d] - dn * g->sn[d][sl];
      tt += t[d] * t[d];
      c[k][d] = -dn * g->sn[d][sl];
    }
    tt = sqrt(tt);
    if (tt > mu * dn) { /* slides: friction mu dn against the slip */
      double r = mu * dn / tt;
      for (d = 0; d < DIM; d++) c[k][d] -= r * t[d];
      s->e.friction += (tt * tt - (tt - mu * dn) * (tt - mu * dn)) / (2 * mr);
    } else { /* sticks */
      for (d = 0; d < DIM; d++) c[k][d] -= t[d];
      s->e.friction += tt * tt / (2 * mr);
    }
    for (d = 0; d < DIM; d++) csum[d] += c[k][d];
  }
  if (drv >= 0) { /* the driven body keeps its velocity and does work */
    double cd[DIM], w = 0;
    for (d = 0; d < DIM; d++) {
      cd[d] = g->sm[drv] * vref[d] - smom[d][drv];
      smom[d][drv] += cd[d];
      mom[d][n] += cd[d];
      w += (cd[d] + csum[d]) * vref[d];
    }
    s->e.boundary += w;
    for (k = 0; k < ns; k++)
      for (d = 0; d < DIM; d++) {
        smom[d][slots[k]] += c[k][d];
        mom[d][n] += c[k][d];
      }
    return;
  }
  /* momentum-conserving: remove the residual in proportion to mass */
  for (k = 0; k < ns; k++) {
    double f = g->sm[slots[k]] / M;
    for (d = 0; d < DIM; d++) smom[d][slots[k]] += c[k][d] - f * csum[d];
  }
}

void contact_apply(sim *s) {
  grid *g = &s->g;
  size_t k;
  s->ncut = 0;
  for (k = 0; k < g->nshared; k++) node(s, g->shared[k], g->q, g->sq);
}
