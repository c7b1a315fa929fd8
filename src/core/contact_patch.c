/*
** contact_patch.c - contact between two bodies per contact patch
** (sim.body_contact = "patch").
**
** Why.  contact.c acts node by node: every shared node whose material
** approaches the other body's is stopped.  A disc turning on a flat body
** has, at the nodes ahead of its contact point, material moving into
** the flat body although its surface there stays put (a circle turned
** about its centre is the same circle); stopping those nodes is a torque
** against the turning, with an arm as wide as the nodes held.  Measured
** on a disc thrown along a driven slab, friction work is 1.10 / 0.94 /
** 0.89 of the rigid disc's at 8 / 16 / 32 cells per diameter and the
** disc ends at 0.62 / 0.83 / 0.91 of its rolling speed.  The walls'
** patch rule (boundary.c) cured the same defect at a wall; this is it
** between bodies.
**
** The rule.  A patch is a connected set (joined along the axes, across
** periodic sides) of shared nodes that hold exactly two fields, the same
** two, a and b, each with mass above mcut and neither bonded nor
** released (those stay with contact.c).  With M_a = sum m_a, P_a = sum
** q_a over the patch (b likewise), the reference velocity v = (P_a +
** P_b) / (M_a + M_b) (the drive's when b is driven), and the patch's
** normal the weighted mean of a's outward normals,
**   n = sum w_i n_ia / |sum w_i n_ia|,  w_i = m_ia m_ib / (m_ia + m_ib)
** (largest where both sides are, at the interface), contact.c's rule is applied once to
** the totals: dp = P_a - M_a v, dn = dp . n; if dn > 0 and the surfaces
** touch somewhere in the patch (max_i e_ia + e_ib >= 0, reach.c; or
** with contact_gap = "step" meet within the step), the normal part is
** removed and the tangential part reduced by mu dn or removed: the
** correction c.  Every slot of a in the patch takes m c / M_a, every
** slot of b -m c / M_b: one velocity change per side, so the normal
** impulse acts through each side's mass centre in the patch (below a
** round body's centre: no torque) and friction at the interface.
** Momentum is conserved over the patch, not node by node.  Where the
** two sides overlap deeply a node's own approach is stopped too
** (pass() below).  Measured (tests/verify/body_patch.lua): the thrown
** disc books 1.080 / 1.018 / 1.002 of the rigid disc's friction work,
** and rolls down a slab at 0.93 / 0.98 / 0.986 of the rigid rate (node
** by node 0.55 / 0.92).  Not the default: head-on impacts lose
** more (6-9 % with mass normals) and a block sliding with friction on a
** flat face rocks (one velocity change cannot move the pressure to its
** leading edge).
**
** A patch whose normals disagree, |sum w n| < 0.8 sum w (a ring of
** interface around a grain in a binder, a body wrapped round a corner),
** is not a plane contact: it is left to contact.c's node rule.
**
** What it dissipates is booked as contact.c books it (contact_lose(): each
** slot's impulse on the mean of its velocities before and after),
** against the patch's one reference velocity, so that the sums over the
** patch are frame-free (the corrections sum to zero over it).
**
** The pass is serial, in shared-node order, before contact.c's threaded
** one, which skips the nodes it took: the numbers do not depend on the
** thread count.
*/
#include <math.h>
#include "heat.h"
#include "sim.h"

/* the coherence below which a patch is no plane (see above) */
#define PATCH_COHERENCE 0.8

/* whether shared node n is a two-field node the patch rule takes; its
** fields then in *a (free) and *b (the other, maybe driven) */
static int pair(const sim *s, int32_t n, int32_t *a, int32_t *b) {
  const grid *g = &s->g;
  int32_t s0 = g->head[n], s1, t;
  if (s0 < 0 || (s1 = g->snext[s0]) < 0 || g->snext[s1] >= 0) return 0;
  if (!(g->m[n] > s->mcut) || !(g->sm[s0] > s->mcut) || !(g->sm[s1] > s->mcut))
    return 0;
  if (s->fdriven[g->sfield[s0]] >= 0) { t = s0; s0 = s1; s1 = t; }
  if (s->fdriven[g->sfield[s0]] >= 0) return 0; /* two drives */
  if (s->fbond >= 0 && (g->sb[s0] > 0 || g->sb[s1] > 0)) return 0;
  if (s->frel >= 0 && (g->srm[s0] > s->mcut || g->srm[s1] > s->mcut)) return 0;
  /* a free pair in field order, so both sides of a patch agree */
  if (s->fdriven[g->sfield[s1]] < 0 && g->sfield[s1] < g->sfield[s0]) {
    t = s0; s0 = s1; s1 = t;
  }
  *a = s0;
  *b = s1;
  return 1;
}

/* Nothing may pass: one velocity change per side stops the patch's mean
** approach, not each node's, so where a body is pressed into another
** (a grain squeezed against the binder along an arc of interface) its
** nodes could go on approaching until one body's particles sit in the
** other's (measured: the unbonded binder cell buried up to 31 particles
** 2 cells deep, with windowed normals).  Where the two sides' particle
** squares overlap by more than 2.6 l (reach.c: the outermost particle
** centres of the two sides have passed each other by 0.6 l), the
** approach left at the node, along a's normal, is removed as the node
** rule would (normal part only: friction stays the patch's): the
** impulse e on a's slot, -e on b's (a drive keeps its velocity and the
** node's momentum takes e).  Returns whether it acted.  Why not less:
** the reach along a node's own normal overstates the overlap where the
** normal is tilted, and at 1.8 l the stops fired under a disc resting
** on a slab (B-splines, 8 cells: a frictionless slide lost 12 % of its
** speed); at 2.6 l they do not. */
static int pass(sim *s, int32_t a, int32_t b, int drv, const double v[DIM],
                double e[DIM]) {
  grid *g = &s->g;
  double u = 0, ma = g->sm[a], mb = g->sm[b], r;
  int d;
  for (d = 0; d < DIM; d++)
    u += (g->sq[d][a] / ma - (drv ? v[d] : g->sq[d][b] / mb)) * g->sn[d][a];
  if (!(u > 0)) return 0;
  r = drv ? ma : ma * mb / (ma + mb);
  for (d = 0; d < DIM; d++) {
    e[d] = -r * u * g->sn[d][a];
    g->sq[d][a] += e[d];
    if (!drv) g->sq[d][b] -= e[d];
  }
  return 1;
}

/* The patch of nodes list[0..len): its fields' slots are found again
** per node (pair() orders them the same way).  Returns 0 if applied (or
** no contact: nothing acts), 1 if left to the node rule.  dry: a
** question between steps (sim:contacts(), diag_contact.c): the impulses
** are applied and kept per slot (sfi, sni) but nothing is booked, heated
** or added to a drive's force. */
static int patch(sim *s, const int32_t *list, size_t len, int dry) {
  const sim_cfg *cfg = &s->cfg;
  grid *g = &s->g;
  double Ma = 0, Mb = 0, Pa[DIM] = {0}, Pb[DIM] = {0}, N[DIM] = {0}, W = 0;
  double v[DIM], dp[DIM], t[DIM], c[DIM], cn[DIM], ct[DIM], nn = 0, dn = 0;
  double tt = 0, touch = -HUGE_VAL, fn = 1, mu, work = 0, Fs[DIM] = {0};
  const double deep = 2.6 * cfg->lp * g->h; /* see pass() */
  int32_t a = -1, b = -1, fb;
  int drv, d;
  size_t i;
  pair(s, list[0], &a, &b);
  fb = g->sfield[b];
  drv = s->fdriven[fb] >= 0;
  for (i = 0; i < len; i++) {
    double ma, mb, w;
    pair(s, list[i], &a, &b);
    ma = g->sm[a];
    mb = g->sm[b];
    w = ma * mb / (ma + mb);
    Ma += ma;
    Mb += mb;
    W += w;
    for (d = 0; d < DIM; d++) {
      Pa[d] += g->sq[d][a];
      Pb[d] += g->sq[d][b];
      N[d] += w * g->sn[d][a];
    }
    if (cfg->gap_check && g->sext[a] + g->sext[b] > touch)
      touch = g->sext[a] + g->sext[b];
  }
  for (d = 0; d < DIM; d++) nn += N[d] * N[d];
  nn = sqrt(nn);
  if (!(nn >= PATCH_COHERENCE * W)) return 1;
  if (drv) {
    const body *bd = &s->bodies[s->fdriven[fb]];
    for (d = 0; d < DIM; d++) v[d] = bd->vdrive[d];
  } else
    for (d = 0; d < DIM; d++) v[d] = (Pa[d] + Pb[d]) / (Ma + Mb);
  for (d = 0; d < DIM; d++) {
    N[d] /= nn;
    dp[d] = Pa[d] - Ma * v[d];
    dn += dp[d] * N[d];
    c[d] = cn[d] = ct[d] = 0;
  }
  if (dn > 0 && cfg->gap_check) {
    if (cfg->gap_step && touch < 0) {
      /* the closing speed of the two sides' mean motions (contact.c
      ** closing(), on the patch) */
      double wv = 0;
      for (d = 0; d < DIM; d++)
        wv += (Pa[d] / Ma - (drv ? v[d] : Pb[d] / Mb)) * N[d];
      fn = wv * s->dt > -touch ? 1 + touch / (wv * s->dt) : 0;
    } else if (touch < 0)
      fn = 0;
  }
  if (dn > 0 && fn > 0) {
    mu = sim_law(s, g->sfield[a], fb);
    for (d = 0; d < DIM; d++) {
      t[d] = dp[d] - dn * N[d];
      tt += t[d] * t[d];
    }
    dn *= fn;
    tt = sqrt(tt);
    for (d = 0; d < DIM; d++) {
      ct[d] = tt > mu * dn ? -mu * dn / tt * t[d] : -t[d];
      cn[d] = -dn * N[d];
      c[d] = cn[d] + ct[d];
    }
  }
  /* one velocity change per side; the drive holds its slots */
  for (i = 0; i < len; i++) {
    int32_t n = list[i], sl[2];
    double ra, rb, fric = 0, imp = 0, x[DIM], y[DIM], e[DIM] = {0};
    int stop;
    pair(s, n, &a, &b);
    ra = g->sm[a] / Ma;
    rb = g->sm[b] / Mb;
    for (d = 0; d < DIM; d++) {
      double ca = ra * c[d];
      g->sq[d][a] += ca;
      g->q[d][n] += ca;
      if (drv) {
        double cd = g->sm[b] * v[d] - g->sq[d][b];
        g->sq[d][b] += cd;
        g->q[d][n] += cd;
        work += (cd + ca) * v[d];
        Fs[d] += ca;
      } else {
        g->sq[d][b] -= rb * c[d];
        g->q[d][n] -= rb * c[d];
      }
    }
    stop = cfg->gap_check && g->sext[a] + g->sext[b] > deep && pass(s, a, b, drv, v, e);
    if (stop && drv)
      for (d = 0; d < DIM; d++) {
        g->q[d][n] += e[d];
        work += e[d] * v[d];
        Fs[d] += e[d];
      }
    if (!(dn > 0 && fn > 0) && !stop) continue;
    for (d = 0; d < DIM; d++) { x[d] = ra * ct[d]; y[d] = ra * cn[d] + e[d]; }
    fric += contact_lose(g, a, v, x, g->sfi);
    imp += contact_lose(g, a, v, y, g->sni);
    if (!drv) {
      for (d = 0; d < DIM; d++) { x[d] = -rb * ct[d]; y[d] = -rb * cn[d] - e[d]; }
      fric += contact_lose(g, b, v, x, g->sfi);
      imp += contact_lose(g, b, v, y, g->sni);
    }
    if (dry) continue;
    s->e.friction += fric;
    s->e.impact += imp;
    sl[0] = a;
    sl[1] = b;
    if (s->heat) heat_contact(s, sl, 2, drv ? b : -1, fric);
  }
  if (drv && !dry) {
    double *F = s->bodies[s->fdriven[fb]].force;
    for (d = 0; d < DIM; d++) F[d] += Fs[d] / s->dt;
    s->e.boundary += work;
  }
  return 0;
}

/* the neighbour of node n along axis d, direction dir, wrapped across a
** periodic side; -1 beyond one that is not */
static int32_t step_to(const grid *g, int32_t n, int d, int dir) {
  int i[DIM];
  grid_ijk(g, n, i);
  i[d] = grid_wrap(g, d, i[d] + dir);
  if (i[d] < 0 || i[d] >= g->n[d]) return -1;
  return grid_node(g, i);
}

/* The patch that holds node n (labelled -2 by the caller, like every
** node pair() takes), flooded breadth first along the axes: its nodes
** into list, each labelled id.  Returns their count. */
static size_t flood(sim *s, int32_t n, int32_t id, int32_t *list) {
  grid *g = &s->g;
  int32_t *lab = s->work.cplab, a, b, fa, fb;
  size_t len = 0, head = 0;
  pair(s, n, &a, &b);
  fa = g->sfield[a];
  fb = g->sfield[b];
  lab[n] = id;
  list[len++] = n;
  while (head < len) {
    int32_t m = list[head++];
    int d, dir;
    for (d = 0; d < DIM; d++)
      for (dir = -1; dir <= 1; dir += 2) {
        int32_t o = step_to(g, m, d, dir), a2, b2;
        if (o < 0 || lab[o] != -2 || !pair(s, o, &a2, &b2)) continue;
        if (g->sfield[a2] != fa || g->sfield[b2] != fb) continue;
        lab[o] = id;
        list[len++] = o;
      }
  }
  return len;
}

/* every shared node labelled: -2 where pair() takes it, -1 elsewhere;
** far: not where a drive's material stays beyond DRIVE_REACH (contact.c
** node() says why; the reach is known once the normals are taken) */
static void label(sim *s, int far) {
  grid *g = &s->g;
  size_t k;
  for (k = 0; k < g->nshared; k++) {
    int32_t n = g->shared[k], a, b;
    int on = pair(s, n, &a, &b);
    if (on && far && s->fdriven[g->sfield[b]] >= 0 && sim_drive_far(s, g->sfield[a], b)) on = 0;
    s->work.cplab[n] = on ? -2 : -1;
  }
}

/* Marks the nodes it takes in s->work.cplab (>= 0: taken, contact.c's
** node() leaves them), -1 elsewhere among the shared nodes.  Under
** body_contact = "auto" only the patches where a flat field meets one
** that is not (sim.fflat: a round body on a flat one) with friction
** between them are taken: two round bodies lose more energy per patch
** head on, a block sliding with friction on a flat body rocks (one
** velocity change cannot move its pressure to the leading edge), and
** without friction the patch buys no torque and its impacts lose more
** than the node rule's (the report's bounce with driven bodies for
** walls: -9.5 / -5.7 / -1.7 % after three impacts at 8 / 16 / 32 cells
** against -7.5 / -3.9 / -1.4 %), as at the walls (boundary.c). */
void contact_patches(sim *s, int dry) {
  grid *g = &s->g;
  int32_t *lab = s->work.cplab, *list = s->work.cplist;
  const int mixed = s->cfg.body_rule != BODY_PATCH;
  size_t k, np = 0, i, len;
  label(s, 1);
  for (k = 0; k < g->nshared; k++) {
    int32_t n = g->shared[k], a, b;
    if (lab[n] != -2) continue;
    len = flood(s, n, (int32_t)np, list);
    pair(s, n, &a, &b);
    if ((mixed && (s->fflat[g->sfield[a]] == s->fflat[g->sfield[b]] ||
                   !(sim_law(s, g->sfield[a], g->sfield[b]) > 0))) ||
        patch(s, list, len, dry)) /* the node rule's */
      for (i = 0; i < len; i++) lab[list[i]] = -1;
    np++;
  }
}

/*
** One normal per patch (sim.normal_patch), for the node rule.  Where a
** face is tilted to the grid, two bodies pressed together are two
** interlocked staircases of particles, and even over a window each
** node's normal turns with the steps: the nodes that press are those
** whose normals lean toward the grid's axis, and the summed normal force
** leans with them (1.5 degrees at 15 degrees and 8 cells per block
** side, measured; with the exact normal at every node the block slides
** at the reference acceleration).  With one normal per patch the normal
** forces of a flat contact are parallel, whichever nodes press: the
** patch's mean, n = sum w_i n_ia / |sum w_i n_ia| with the weights of
** patch() above, written to every slot of a, its negative to b's.  A
** patch whose normals disagree (coherence below PATCH_COHERENCE: a grain
** wrapped in binder, a body round a corner) keeps its nodes' own.  The
** contact decision and the correction stay node by node, so a block's
** pressure can move to its leading edge; a round body still meets the
** node rule's stops ahead of its contact point (it is the patch rule,
** body_contact = "patch", that rolls it).  Serial, in shared-node order:
** the normals do not depend on the thread count. */
void contact_patch_normals(sim *s) {
  grid *g = &s->g;
  int32_t *lab = s->work.cplab, *list = s->work.cplist;
  size_t k, i, len;
  label(s, 0);
  for (k = 0; k < g->nshared; k++) {
    int32_t n = g->shared[k], a, b;
    double N[DIM] = {0}, W = 0, nn = 0;
    int d;
    if (lab[n] != -2) continue;
    len = flood(s, n, 0, list);
    pair(s, n, &a, &b);
    /* under "auto" alone, only where two flat faces meet (sim.fflat) */
    if (!s->cfg.normal_patch &&
        !(s->fflat[g->sfield[a]] && s->fflat[g->sfield[b]]))
      continue;
    for (i = 0; i < len; i++) {
      double w;
      pair(s, list[i], &a, &b);
      w = g->sm[a] * g->sm[b] / (g->sm[a] + g->sm[b]);
      for (d = 0; d < DIM; d++) N[d] += w * g->sn[d][a];
      W += w;
    }
    for (d = 0; d < DIM; d++) nn += N[d] * N[d];
    nn = sqrt(nn);
    if (!(nn >= PATCH_COHERENCE * W) || !(nn > 0)) continue;
    for (i = 0; i < len; i++) {
      pair(s, list[i], &a, &b);
      for (d = 0; d < DIM; d++) {
        g->sn[d][a] = N[d] / nn;
        g->sn[d][b] = -N[d] / nn;
      }
    }
  }
  for (k = 0; k < g->nshared; k++) lab[g->shared[k]] = -1;
}
