/*
** wall_spring.c - walls that push each column of nodes by a spring
** (sim.wall_contact = "spring").
**
** Why not stop the nodes.  The node rule (boundary.c) takes a node's
** approach away in one step: a perfectly inelastic impact of all the
** material the node carries, up to a stencil's reach from the wall, and
** FLIP hands the particles only part of that velocity change (S_ip of
** it), which loses more (the frictionless bounce, quadratic B-splines:
** -7.4 / -3.8 / -1.4 % over three impacts at 8 / 16 / 32 cells per
** diameter).  A spring stores what an impact takes and gives it back.
** Springs on the particles (wall_penalty.c) act through each particle's
** nodes, where FLIP again hands the particles only part of the nodes'
** change: an impulse c on a node of mass m gives the grid c^2 / 2m of
** kinetic energy and the particles c^2 sum_p m_p S_ip^2 / 2m^2, less;
** the difference is lost at every step of contact.
**
** So the spring acts on a column of nodes: the wall plane, the ghost
** planes beyond it and wall_band node planes inside, at one wall column
** (a node of the wall plane).  It gives every node of the column the same
** normal velocity change: a particle whose stencil lies in columns that
** move alike gets that change whole, and the loss above is left only by
** the differences between neighbouring columns.  The column's
** compression delta follows its mass-weighted normal velocity U into the
** wall (reach.c's separation
** check starts it once the material reaches the wall line), and the
** normal impulse c is the spring's force at the middle of the step
** (implicit midpoint, per column of mass M):
**   c = k dt (delta + dt (U^n + U^new) / 4),   U^new = U^L - c / M
**   delta += dt (U^n + U^new) / 2
** so that the work c (U^n + U^new) / 2 is exactly the spring energy
** k delta^2 / 2 gained, at any k, M and dt (no step limit), and no
** energy is booked as lost.  c >= 0: the wall pushes, never pulls; the
** column lets go where delta returns to 0.  Frictionless: a spring wall
** with friction is refused (lua_sim.c; docs/algorithm.md section 8c says
** what was tried).
**
** k = wall_stiffness * max(rho c^2) * h^(DIM - 2) over the scene's
** materials: per wall area h^(DIM-1) the stiffness of a layer of the
** stiffest material h / wall_stiffness thick, which vanishes as the grid
** is refined, so the wall tends to the rigid one.  One k for the scene,
** so that the stored energy is k delta^2 / 2 whatever moves across the
** columns.
**
** A column holding two velocity fields (a shared node in it) is left to
** the node rule (boundary.c): its compression is per column, not per
** field; so is a driven body's, which no wall acts on.  Serial over the columns: the same bits on any thread count.
**
** The defect (warned of at load, sim_wall_advice): the compression is
** kept per column, a place on the wall, while the material it belongs to
** slides along it.  A column stays compressed after the material has
** moved on, the pressure leans back against the slide, and a body
** sliding along the wall is turned (the frictionless bounce's disc at 16
** cells: -0.05 and -0.10 rad per time unit after impacts 1 and 2; the
** node rule 0.0006).  Carried along with the column's tangential velocity
** by an upwind step, it was worse (0.06 / 0.16): the contact is a few
** columns wide; carried by the particles, three ways, it was smaller but
** grew with refinement or lost energy (docs/algorithm.md section 8c).
*/
#include "sim.h"

/* the spring constant per column (over the bodies: once per side and
** step, not per column) */
double wall_spring_k(const sim *s) {
  double best = 0, k;
  int32_t i;
  int d;
  for (i = 0; i < s->nbody; i++) {
    const material *m;
    if (s->bmat[i] < 0) continue; /* a driven body */
    m = &s->mats[s->bmat[i]];
    if (m->rho * m->c * m->c > best) best = m->rho * m->c * m->c;
  }
  k = s->cfg.wall_stiffness * best;
  for (d = 2; d < DIM; d++) k *= s->g.h;
  return k;
}

/* the node planes of side k's columns: the wall and ghost planes
** [first, last] and wall_band planes inside, no further than the grid
** (a domain fewer cells across than the band: the whole grid) */
static void column_lines(const sim *s, int k, int first, int last, int *lo,
                         int *hi) {
  int nb = s->cfg.wall_band;
  if (k & 1) { *lo = first - nb < 0 ? 0 : first - nb; *hi = last; }
  else {
    int top = s->g.n[k / 2] - 1;
    *lo = first;
    *hi = last + nb > top ? top : last + nb;
  }
}

int wall_spring_column(sim *s, int k, int first, int last, size_t j, double kk) {
  const sim_cfg *cfg = &s->cfg;
  grid *g = &s->g;
  side *sd = &s->sides[k];
  const int d = k / 2;
  const double sign = (k & 1) ? 1.0 : -1.0, dt = s->dt;
  double M = 0, P0 = 0, PL = 0, u0, uL, u1, c, *dl = &sd->dl[j];
  int lo, hi, line;
  column_lines(s, k, first, last, &lo, &hi);
  for (line = lo; line <= hi; line++) {
    int32_t n = grid_face_node(g, d, line, j);
    if (g->m[n] <= s->mcut) continue;
    if (g->head[n] >= 0) { *dl = 0; return 0; } /* two fields: the node rule */
    /* a driven body's: the node rule, which leaves it to its drive */
    if (s->ndriven && s->fdriven[g->owner[n]] >= 0) { *dl = 0; return 0; }
    M += g->m[n];
    P0 += sign * (g->p[d][n] - g->m[n] * sd->v[d]);
    PL += sign * (g->q[d][n] - g->m[n] * sd->v[d]);
  }
  if (!(M > 0)) { *dl = 0; return 1; }
  u0 = P0 / M;
  uL = PL / M;
  /* not yet in contact: the material has not reached the wall line, or
  ** the column does not move into it */
  if (!(*dl > 0) && ((cfg->gap_check && sd->ext[j] < 0) || !(uL > 0))) {
    *dl = 0;
    return 1;
  }
  c = kk * dt * (*dl + 0.25 * dt * (u0 + uL)) / (1 + 0.25 * kk * dt * dt / M);
  if (!(c > 0)) c = 0;
  u1 = uL - c / M;
  *dl += 0.5 * dt * (u0 + u1);
  if (!(*dl > 0)) *dl = 0;
  if (c == 0) return 1;
  for (line = lo; line <= hi; line++) {
    int32_t n = grid_face_node(g, d, line, j);
    double imp;
    if (g->m[n] <= s->mcut) continue;
    imp = -sign * c * g->m[n] / M;
    g->q[d][n] += imp;
    sd->force[d] += imp / dt;
    s->e.boundary += imp * sd->v[d]; /* a moving wall's work */
  }
  return 1;
}

/*
** MUSL with the walls held (sim.wall_remap; "auto": with gravity): in the
** columns the springs push, the remapped normal velocity is set back to
** the one the springs left (q, vL), so that the particles strain as the
** springs drove them.  Left to the remap, a block resting on a floor
** under gravity is pumped, as the node rule's is (boundary.c): measured
** on the block of tests/verify/wall_spring.lua, its largest kinetic
** energy over t = 9 .. 12 was 1.13 times that over t = 3 .. 6.
*/
void wall_spring_hold(sim *s) {
  grid *g = &s->g;
  int k, line;
  for (k = 0; k < NSIDES; k++) {
    side *sd = &s->sides[k];
    int d = k / 2, first, last, lo, hi;
    size_t j;
    if (!sim_spring_side(s, k)) continue;
    grid_wall_lines(g, k, &first, &last);
    column_lines(s, k, first, last, &lo, &hi);
    for (j = 0; j < sd->next; j++) {
      if (!(sd->dl[j] > 0)) continue;
      for (line = lo; line <= hi; line++) {
        int32_t n = grid_face_node(g, d, line, j);
        if (g->m[n] > s->mcut) g->p[d][n] = g->q[d][n];
      }
    }
  }
}

double wall_spring_energy(const sim *s) {
  double e = 0, kk;
  size_t j;
  int k;
  if (s->cfg.wall_rule != WALL_SPRING || s->nmat == 0) return 0;
  kk = wall_spring_k(s);
  for (k = 0; k < NSIDES; k++) {
    const side *sd = &s->sides[k];
    if (sd->kind != SIDE_WALL || sd->mirror) continue;
    for (j = 0; j < sd->next; j++) e += 0.5 * kk * sd->dl[j] * sd->dl[j];
  }
  return e;
}
