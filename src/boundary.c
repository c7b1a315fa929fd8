/*
** boundary.c - domain sides and driven bodies, on the updated momentum.
**
** A wall side acts on the nodes of its grid line (and any ghost nodes
** beyond it) with the exact normal of the side.  With v_w the wall's
** velocity and n the side's outward normal, a node of mass m and momentum
** q approaches the wall when dn = (q - m v_w).n > 0; the normal part is
** then removed and the tangential part reduced by mu dn (Coulomb; removed
** if smaller).  With the separation check the wall acts only once the
** material reaches the wall line (reach.c).  The wall's impulse c does
** work c.v_w on the material, and dissipates minus its work on the
** node's mean velocity over the step in the wall's frame (contact.c).
**
** A driven body's field is given its prescribed velocity at every node
** it owns alone; at shared nodes contact.c does it.  The impulse needed
** is work done by the drive.
*/
#include <math.h>
#include "sim.h"

/* one node (or slot) of mass m against side k; returns the impulse */
static int wall_node(sim *s, side *sd, int d, double sign, double m,
                     double *const p0[DIM], double *const mom[DIM], size_t i,
                     double *imp) {
  double dp[DIM], dn, tt = 0, w = 0, loss = 0;
  int e;
  for (e = 0; e < DIM; e++) {
    dp[e] = mom[e][i] - m * sd->v[e];
    imp[e] = 0;
  }
  dn = sign * dp[d];
  if (!(dn > 0)) return 0;
  imp[d] = -sign * dn;
  for (e = 0; e < DIM; e++)
    if (e != d) tt += dp[e] * dp[e];
  tt = sqrt(tt);
  for (e = 0; e < DIM; e++) {
    if (e == d) continue;
    if (tt > sd->mu * dn) imp[e] = -sd->mu * dn * dp[e] / tt;
    else imp[e] = -dp[e];
  }
  /* dissipated: minus the impulse's work on the mean of the velocity the
  ** step began with and the one it ends with, in the wall's frame (see
  ** contact.c) */
  for (e = 0; e < DIM; e++)
    if (e != d)
      loss -= 0.5 * (p0[e][i] + mom[e][i] + imp[e] - 2 * m * sd->v[e]) * imp[e];
  s->e.friction += loss / m;
  /* the normal impulse's likewise: an impact's loss at the node */
  s->e.impact -= 0.5 * (p0[d][i] + mom[d][i] + imp[d] - 2 * m * sd->v[d]) *
                 imp[d] / m;
  for (e = 0; e < DIM; e++) {
    mom[e][i] += imp[e];
    w += imp[e] * sd->v[e];
  }
  for (e = 0; e < DIM; e++) sd->force[e] += imp[e] / s->dt;
  s->e.boundary += w;
  return 1;
}

static void wall_line(sim *s, int k, int line, int first) {
  grid *g = &s->g;
  side *sd = &s->sides[k];
  int d = k / 2, o = 1 - d, j;
  double sign = (k & 1) ? 1.0 : -1.0;
  double *const *mom = g->q, *const *smom = g->sq;
  for (j = 0; j < g->n[o]; j++) {
    int32_t n = d == 0 ? line + g->n[0] * j : j + g->n[0] * line, sl;
    double imp[DIM];
    int e;
    unsigned char *act = sd->acted + (size_t)(line - first) * g->n[o] + j;
    *act = 0;
    if (g->m[n] <= s->mcut) continue;
    if (s->gap_check && sd->ext[j] < 0) continue;
    if (g->head[n] < 0) {
      int a = wall_node(s, sd, d, sign, g->m[n], g->p, mom, (size_t)n, imp);
      *act = (unsigned char)a;
      continue;
    }
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
      if (g->sm[sl] <= s->mcut) continue;
      if (wall_node(s, sd, d, sign, g->sm[sl], g->sp, smom, (size_t)sl, imp) && act)
        *act = 1;
      for (e = 0; e < DIM; e++) mom[e][n] += imp[e];
    }
  }
}

static void driven(sim *s) {
  grid *g = &s->g;
  double *const *mom = g->q;
  double w = 0;
  size_t n;
  int d;
  for (n = 0; n < g->nnodes; n++) {
    int32_t f = g->owner[n], b;
    if (f < 0 || g->head[n] >= 0 || (b = s->fdriven[f]) < 0) continue;
    for (d = 0; d < DIM; d++) {
      double c = g->m[n] * s->bodies[b].vdrive[d] - mom[d][n];
      mom[d][n] += c;
      w += c * s->bodies[b].vdrive[d];
    }
  }
  s->e.boundary += w;
}

/* the node lines side k acts on: its wall line and the ghost lines
** beyond it, [*first, *last] along the side's normal */
static void wall_lines(const grid *g, int k, int *first, int *last) {
  int d = k / 2;
  if (k & 1) { *first = g->pad + g->cells[d]; *last = g->n[d] - 1; }
  else { *first = 0; *last = g->pad; }
}

void boundary_apply(sim *s) {
  grid *g = &s->g;
  int k;
  if (s->ndriven) driven(s);
  for (k = 0; k < NSIDES; k++) {
    int line, first, last;
    if (s->sides[k].kind != SIDE_WALL) continue;
    wall_lines(g, k, &first, &last);
    for (line = first; line <= last; line++) wall_line(s, k, line, first);
  }
}

/*
** MUSL with the walls held (sim.wall_remap): the walls again, on the
** remapped velocities (p after solve_remap), at the nodes where they
** acted this step, so that the velocity gradient sees the motion the
** particles made.  Without it the remap gives a wall node the mean
** velocity of the particles beside it, which under FLIP keeps some of
** the motion into the wall the wall took away: the layer at the wall
** strains less than it moved, and a body resting on a wall under a
** steady load (gravity) is pumped (measured: a block with K = 100 on a
** floor, kinetic energy 2e-8 -> 2e-3 over 8 time units; held, it stays
** at 1e-5).  Held, impacts lose more at the grid: the frictionless
** bouncing cylinder at 8 cells loses 6 % instead of 2.6 % over three
** impacts.  So "auto" holds the walls only in scenes with gravity.  The
** normal component only: the tangential one follows friction's rule.
*/
void boundary_normal_set(sim *s, double *const a[DIM],
                         double *const sa[DIM], int vel) {
  grid *g = &s->g;
  int k;
  for (k = 0; k < NSIDES; k++) {
    const side *sd = &s->sides[k];
    int d = k / 2, o = 1 - d, line, first, last, j;
    double v = vel ? sd->v[d] : 0.0;
    if (sd->kind != SIDE_WALL) continue;
    wall_lines(g, k, &first, &last);
    for (line = first; line <= last; line++)
      for (j = 0; j < g->n[o]; j++) {
        int32_t n = d == 0 ? line + g->n[0] * j : j + g->n[0] * line, sl;
        if (!sd->acted[(size_t)(line - first) * g->n[o] + j]) continue;
        a[d][n] = v;
        for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) sa[d][sl] = v;
      }
  }
}

void boundary_remap(sim *s) { boundary_normal_set(s, s->g.p, s->g.sp, 1); }
