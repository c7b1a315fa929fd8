/*
** book.c - the work of the friction and normal impulses, booked on the
** motion the particles carry away.
**
** Contact (contact.c) and the walls (boundary.c) change a node's (or a
** field's slot's) momentum by an impulse c.  What c dissipates is minus
** its work on the material over the step, -c . (v^n + v^new) / 2, with
** v^n the velocity the step began with (p2g's) and v^new the velocity
** the impulse leaves.  Which v^new: FLIP gives each particle
** v_p + sum_i S_ip dv_i, so the work node i's impulse does on the
** particles is
**   sum_p m_p (v_p + sum_j S_jp dv_j / 2) . S_ip c_i / m_i
**     = c_i . (v_i^n + v_i^r) / 2,
** with v_i^r = sum_p m_p S_ip v_p^new / m_i, MUSL's remapped velocity.
** The nodal velocity vL = v^n + dv stands for v^r only where the
** particles move with it.  At a node holding a sliver of a field (small
** m_i) the forces give a large dv that reaches the particles with small
** weights, and c_i . vL / 2 books far more than the particles lose:
** measured on a column of 50 frictional discs collapsing under gravity
** (linear hats, FLIP, 6 cells per diameter), friction booked on vL was
** 0.71 of the energy put in, on the particles 0.37, and the budget was
** left 32 % short; booked here, the residual is +0.4 %.
**
** So the work is booked in two halves: -c . (v^n / 2 - v_ref) when the
** impulse is applied (v_ref the wall's or the drive's velocity; between
** free fields the impulses at a node sum to zero and v_ref drops out),
** and -c . v^r / 2 here, after MUSL's remap, from the impulses kept in
** fi (sfi, sni at shared nodes).  The walls' normal impulses are booked
** whole where they act (boundary.c says why).  Where the walls are held on the
** remap (sim_wall_hold) the held velocity is taken: it is the motion the
** stresses see next (measured on the sliding disc, GIMP at 12 cells:
** residual -2.9 % before the hold, -0.7 % after).  For APIC, XPIC and
** the FLIP/PIC blend v^r is the remap of the velocities the particles
** are given, not FLIP's: the rest of their change is the transfer's,
** which g2p.c books with the same rule on each particle's mean
** velocity, and the walls' normal impulses are booked here too
** (boundary.c, sim_lossy), so that the kinetic energy's change is
** accounted exactly.  Under USL there is no remap and vL is used.
*/
#include "sim.h"

/* -c . v / 2 over entries [0, n) of one table whose mass is above the
** cut (lighter ones got no impulse) */
static double half(size_t n, const double *m, double mcut,
                   double *const v[DIM], double *const c[DIM]) {
  double w = 0;
  size_t i;
  int d;
  for (i = 0; i < n; i++)
    if (m[i] > mcut)
      for (d = 0; d < DIM; d++) w += c[d][i] * v[d][i];
  return -0.5 * w;
}

void book_finish(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  /* after solve_remap (and the walls' hold) p holds v^r; q holds vL */
  const int remap = cfg->update != UPDATE_USL;
  double *const *v = remap ? g->p : g->q, *const *sv = remap ? g->sp : g->sq;
  int k, walls = 0;
  for (k = 0; k < NSIDES; k++) walls |= s->sides[k].kind == SIDE_WALL;
  /* the dense table carries the walls' friction only (contact acts at
  ** shared nodes, on slots), and its entries at shared nodes are zero */
  /* the walls' normal impulses are split only under the lossy transfers
  ** (contact's, in sni, always), the bonded nodes' only in scenes with
  ** bonds: elsewhere those tables stay zero and are not summed */
  const int split = sim_lossy(cfg);
  if (walls) {
    s->e.friction += half(g->nnodes, g->m, s->mcut, v, g->fi);
    if (split || s->wsplit) s->e.impact += half(g->nnodes, g->m, s->mcut, v, g->ni);
    s->wsplit = 0;
  }
  s->e.friction += half(g->nslot, g->sm, s->mcut, sv, g->sfi);
  s->e.impact += half(g->nslot, g->sm, s->mcut, sv, g->sni);
  if (s->fbond >= 0) s->e.bonding += half(g->nslot, g->sm, s->mcut, sv, g->sbi);
  if (g->cohesive) {
    s->e.cohesion += half(g->nslot, g->sm, s->mcut, sv, g->sci);
  }
}
