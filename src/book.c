/*
** book.c - the work of the friction and normal impulses, booked on the
** motion the particles are given.
**
** Contact (contact.c) and the walls (boundary.c) change a node's (or a
** field's slot's) momentum by an impulse c.  What c dissipates is minus
** its work on the material over the step, -c . (v^n + v^new) / 2, with
** v^n the velocity the step began with (p2g's) and v^new the velocity
** the impulse leaves.  Which v^new: FLIP gives each particle
** v_p + sum_i S_ip dv_i, so the work the node's impulse does on the
** particles is
**   sum_p m_p (v_p + sum_j S_jp dv_j / 2) . S_ip c_i / m_i
**     = c_i . (v_i^n + v_i^r) / 2,
** v_i^r = sum_p m_p S_ip v_p^new / m_i being MUSL's remapped velocity.
** The nodal velocity vL = v^n + dv takes the place of v^r only where the
** particles move with it; at a node holding a sliver of a field (small
** m_i) the force gives a large dv that reaches its particles with small
** weights, and c_i . vL / 2 books far more than the particles lose.
** Measured on a column of 50 frictional discs collapsing (linear hats,
** FLIP, 6 cells per diameter): friction booked at vL 0.71 of the energy
** put in, on the particles 0.37; the budget left -32 % of it.
**
** So the impulse's work is booked in two halves: -c . (v^n / 2 - v_ref)
** when it is applied (v_ref the wall's or drive's velocity; contact
** between free fields sums to zero impulse, where v_ref drops out), and
** -c . v^r / 2 here, after MUSL's remap, from the impulses kept in fi,
** ni (sfi, sni at shared nodes).  Under APIC the particle's candidate
** velocity field is v_p + C_p r + dv at its nodes, whose energy changes
** by exactly the nodal c . (v^n + vL) / 2, and under USL there is no
** remap: there vL is used.  For XPIC and the FLIP/PIC blend the remap
** is of the velocities the particles get, not FLIP's: the difference is
** the transfer's own, booked in e.transfer.
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
  const grid *g = &s->g;
  /* after solve_remap p holds v^r; q holds vL throughout */
  const int remap = s->update != UPDATE_USL && s->transfer == TRANSFER_FLIP;
  double *const *v = remap ? g->p : g->q, *const *sv = remap ? g->sp : g->sq;
  int k, walls = 0;
  for (k = 0; k < NSIDES; k++) walls |= s->sides[k].kind == SIDE_WALL;
  /* the dense tables carry the walls' impulses only (contact acts at
  ** shared nodes, on slots), and entries at shared nodes are zero */
  if (walls) {
    s->e.friction += half(g->nnodes, g->m, s->mcut, v, g->fi);
    s->e.impact += half(g->nnodes, g->m, s->mcut, v, g->ni);
  }
  s->e.friction += half(g->nslot, g->sm, s->mcut, sv, g->sfi);
  s->e.impact += half(g->nslot, g->sm, s->mcut, sv, g->sni);
}
