/*
** bond.c - interfacial bond strength between the grid and the particles.
**
** Each particle of a bonding body carries a bond strength b_p (field
** "bond", a stress).  Before contact, every shared slot of field r gets
** the mass-weighted strength of r's particles around it and their
** volume gradient,
**   b_r = sum_p S_ip m_p b_p / m_r,   a_r = sum_p V_p grad S_ip
** where |a_r| is the area of r's surface the node stands for (by the
** divergence theorem, the integral of S_i over r's surface); contact.c
** compares the traction the bond carries with the smaller strength of
** the two sides.  Where contact cut a node's strength to zero (the normal
** traction exceeded it), the cut is interpolated back to the particles
** over the interface nodes they touch:
**   b_p <- b_p (1 - sum_{i cut} S_ip / sum_{i shared} S_ip)
** so a particle whose interface nodes have all debonded has no strength
** left, damage shows on the particles, and no node it reaches can bond
** again.  (Interpolating the nodal value itself, b_p -= sum S_ip b_i,
** would leave a particle with a small weight on the interface most of
** its strength, the next step's nodal strength would be positive again,
** and an interface that has let go could bond again as soon as its
** traction fell: healing and chatter.)
**
** Removing the whole nodal strength at once is deliberate: a strength
** criterion without a softening law has no length or energy scale by
** which to spread the loss over steps; cutting it at once makes the
** interface let go where it is overloaded, and the debond front then
** moves as fast as the elastic waves carry the load to the next node.
** Only particles beside shared nodes are visited.
*/
#include "sim.h"
#include "stencil.h"

/* the stencil with the shape kind a constant in each branch (which also
** lets the compiler see every weight written) */
static void eval(const sim *s, const double *x, stencil *st) {
  switch (s->shape) {
  case SHAPE_GIMP: stencil_eval(&s->g, SHAPE_GIMP, x, s->lp, st); break;
  case SHAPE_BSPLINE2: stencil_eval(&s->g, SHAPE_BSPLINE2, x, s->lp, st); break;
  default: stencil_eval(&s->g, SHAPE_LINEAR, x, s->lp, st);
  }
}

void bond_gather(sim *s) {
  grid *g = &s->g;
  const particles *ps = &s->ps;
  const body *bd = s->bodies;
  const double *bp = particles_comp(ps, s->fbond, 0);
  stencil st;
  size_t i, k;
  for (i = 0; i < ps->n; i++) {
    double x[DIM], mp = ps->m[i], V;
    int32_t node[STENCIL_MAX], f = bd[ps->body[i]].field;
    int nn, d, any = 0;
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    nn = stencil_nodes(g, s->shape, x, node);
    for (k = 0; k < (size_t)nn && !any; k++) any = g->head[node[k]] >= 0;
    if (!any) continue;
    eval(s, x, &st);
#if DIM == 2
    V = ps->vol0[i] * (ps->F[0][i] * ps->F[3][i] - ps->F[1][i] * ps->F[2][i]);
#endif
    for (k = 0; k < (size_t)st.n; k++) {
      int32_t n = st.node[k], sl;
      if (g->head[n] < 0) continue;
      sl = grid_slot(g, n, f);
      g->sb[sl] += st.w[k] * mp * bp[i];
      for (d = 0; d < DIM; d++) g->sv[d][sl] += V * st.dw[d][k];
    }
  }
  for (k = 0; k < g->nslot; k++) g->sb[k] *= g->sm[k] > 0 ? 1.0 / g->sm[k] : 0.0;
}

void bond_scatter(sim *s) {
  const grid *g = &s->g;
  particles *ps = &s->ps;
  const body *bd = s->bodies;
  double *bp = particles_comp(ps, s->fbond, 0);
  stencil st;
  size_t i;
  for (i = 0; i < ps->n; i++) {
    double x[DIM], wsh = 0, wcut = 0;
    int32_t f = bd[ps->body[i]].field;
    int k, d;
    if (!(bp[i] > 0)) continue;
    /* called before g2p: the particles sit where they were gathered */
    for (d = 0; d < DIM; d++) x[d] = ps->x[d][i];
    eval(s, x, &st);
    for (k = 0; k < st.n; k++) {
      int32_t n = st.node[k];
      if (g->head[n] < 0) continue;
      wsh += st.w[k];
      if (g->scut[grid_slot(g, n, f)] > 0) wcut += st.w[k];
    }
    if (wcut > 0) bp[i] = wcut >= wsh ? 0.0 : bp[i] * (1.0 - wcut / wsh);
  }
}

/* A bonded interface is one body for the step: under MUSL the velocity
** gradient comes from the particles' remapped velocities, and a bonded
** slot must give its particles the node's common velocity there too.
** Left to its own particles, a slot holding a sliver of its body at the
** stair-stepped surface extrapolates a velocity of its own, and the
** particles beside a perfectly bonded interface strain as if it slipped
** (measured on the concentric cylinders: radial stresses up to 3.6 times
** the Lame value within a cell of the interface). */
void bond_remap(sim *s) {
  grid *g = &s->g;
  size_t k;
  int d;
  for (k = 0; k < g->nslot; k++)
    if (g->sbonded[k])
      for (d = 0; d < DIM; d++) g->sp[d][k] = g->p[d][g->snode[k]];
}
