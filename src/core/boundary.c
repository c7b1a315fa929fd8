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
** That is the node rule; the patch rule (below) gives all the nodes of a
** contact patch one velocity change, so that friction's torque reaches a
** round body (rolling, spin-up).
**
** A driven body's field is given its prescribed velocity at every node
** it owns alone; at shared nodes contact.c does it.  The impulse needed
** is work done by the drive.
*/
#include <math.h>
#include <string.h>
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

/* the node lines side k acts on: its wall line and the ghost lines
** beyond it, [*first, *last] along the side's normal */
static void wall_lines(const grid *g, int k, int *first, int *last) {
  int d = k / 2;
  if (k & 1) { *first = g->pad + g->cells[d]; *last = g->n[d] - 1; }
  else { *first = 0; *last = g->pad; }
}

/* whether the wall acted at line (counted from the first) of column j */
static int sd_acted(const sim *s, int k, int line, int j) {
  return s->sides[k].acted[(size_t)line * s->g.n[1 - k / 2] + j];
}

static int col_acted(const sim *s, int k, int j, int first, int last) {
  int line;
  for (line = 0; line <= last - first; line++)
    if (sd_acted(s, k, line, j)) return 1;
  return 0;
}

/* The patch rule (sim.wall_contact = "patch").  A run of consecutive
** wall columns with material on the wall lines is one patch: the body's
** whole near-wall band, whose mass follows the body's shape and not the
** orientation of its particle lattice.  It is in contact once the
** material reaches the wall somewhere in it (the separation check).  Per
** velocity field the wall removes the approach of the patch's total
** momentum and Coulomb-limits its tangential part, as for one node, and
** gives every node of the patch the same velocity change, so the impulse
** on each node is its mass times that change: the normal impulse acts
** through the patch's mass centre (a round body feels no torque from
** it), and the friction impulse mu N at the wall line (arm: the body's
** reach to the wall, R for a disc).  The node rule instead stops each
** node that approaches: a spinning round body's nodes on one side of its
** contact point move into the wall (the material does, the surface does
** not), and stopping them alone is a torque against the spin, with the
** arm of the flat of the lowest particle row. */

/* node n of column j on line `line` of side k */
static int32_t wall_nodeid(const grid *g, int d, int line, int j) {
  return d == 0 ? line + g->n[0] * j : j + g->n[0] * line;
}

/* the field of a node no other field shares (the owner is marked only
** in scenes with more than one field) */
static int32_t node_field(const sim *s, int32_t n) {
  return s->nfield > 1 || s->ndriven ? s->g.owner[n] : 0;
}

/* whether field f has mass above the cut at node n; *sl its slot (-1:
** the node's dense entry) */
static int patch_entry(const sim *s, int32_t n, int32_t f, int32_t *sl) {
  const grid *g = &s->g;
  if (g->head[n] < 0) {
    *sl = -1;
    return node_field(s, n) == f && g->m[n] > s->mcut;
  }
  for (*sl = g->head[n]; *sl >= 0; *sl = g->snext[*sl])
    if (g->sfield[*sl] == f) return g->sm[*sl] > s->mcut;
  return 0;
}

/* the smallest field above `after` with mass in columns [j0, j0 + len) */
static int32_t patch_next_field(const sim *s, int k, int j0, int len,
                                int first, int last, int32_t after) {
  const grid *g = &s->g;
  int d = k / 2, o = 1 - d, a, line;
  int32_t best = -1;
  for (a = 0; a < len; a++) {
    int j = (j0 + a) % g->n[o];
    for (line = first; line <= last; line++) {
      int32_t n = wall_nodeid(g, d, line, j), sl;
      if (g->head[n] < 0) {
        int32_t f = node_field(s, n);
        if (g->m[n] > s->mcut && f > after && (best < 0 || f < best)) best = f;
        continue;
      }
      for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
        int32_t f = g->sfield[sl];
        if (g->sm[sl] > s->mcut && f > after && (best < 0 || f < best)) best = f;
      }
    }
  }
  return best;
}

static void patch_field(sim *s, int k, int j0, int len, int first, int last,
                        int32_t f) {
  grid *g = &s->g;
  side *sd = &s->sides[k];
  int d = k / 2, o = 1 - d, a, line, e;
  double sign = (k & 1) ? 1.0 : -1.0, M = 0, P[DIM] = {0}, dv[DIM] = {0};
  double dn, tt = 0, w = 0, loss = 0;
  for (a = 0; a < len; a++) {
    int j = (j0 + a) % g->n[o];
    for (line = first; line <= last; line++) {
      int32_t n = wall_nodeid(g, d, line, j), sl;
      double m;
      if (!patch_entry(s, n, f, &sl)) continue;
      m = sl < 0 ? g->m[n] : g->sm[sl];
      M += m;
      for (e = 0; e < DIM; e++)
        P[e] += (sl < 0 ? g->q[e][n] : g->sq[e][sl]) - m * sd->v[e];
    }
  }
  dn = sign * P[d];
  if (!(M > 0) || !(dn > 0)) return;
  dv[d] = -sign * dn / M;
  for (e = 0; e < DIM; e++)
    if (e != d) tt += P[e] * P[e];
  tt = sqrt(tt);
  for (e = 0; e < DIM; e++) {
    if (e == d) continue;
    dv[e] = (tt > sd->mu * dn ? -sd->mu * dn * P[e] / tt : -P[e]) / M;
  }
  for (a = 0; a < len; a++) {
    int j = (j0 + a) % g->n[o];
    for (line = first; line <= last; line++) {
      int32_t n = wall_nodeid(g, d, line, j), sl;
      double m, imp;
      if (!patch_entry(s, n, f, &sl)) continue;
      m = sl < 0 ? g->m[n] : g->sm[sl];
      for (e = 0; e < DIM; e++) {
        double *q = sl < 0 ? &g->q[e][n] : &g->sq[e][sl];
        double p0 = sl < 0 ? g->p[e][n] : g->sp[e][sl];
        imp = m * dv[e];
        /* dissipated, as wall_node books it */
        if (e != d) loss -= 0.5 * (p0 + *q + imp - 2 * m * sd->v[e]) * dv[e];
        *q += imp;
        if (sl >= 0) g->q[e][n] += imp;
        w += imp * sd->v[e];
        sd->force[e] += imp / s->dt;
      }
      sd->acted[(size_t)(line - first) * g->n[o] + j] = 1;
    }
  }
  s->e.friction += loss;
  s->e.boundary += w;
}

/* whether column j of side k has material on the wall lines */
static int patch_touch(const sim *s, int k, int j, int first, int last) {
  const grid *g = &s->g;
  int d = k / 2, line;
  for (line = first; line <= last; line++)
    if (g->m[wall_nodeid(g, d, line, j)] > s->mcut) return 1;
  return 0;
}

/* whether the material of a patch touches the wall somewhere */
static int patch_gap(const sim *s, int k, int j0, int len) {
  int a;
  if (!s->gap_check) return 1;
  for (a = 0; a < len; a++)
    if (s->sides[k].ext[(j0 + a) % s->g.n[1 - k / 2]] >= 0) return 1;
  return 0;
}

/* The patch rule stops a patch's mean approach, not each node's: where
** the material has passed the wall line by more than half a particle
** (a particle's centre is beyond it), each node that still approaches is
** stopped, as the node rule would, so that nothing goes through a wall
** a body is pressed against (normal part only: friction is the patch's) */
static void patch_deep(sim *s, int k, int first, int last) {
  grid *g = &s->g;
  side *sd = &s->sides[k];
  int d = k / 2, o = 1 - d, j, line;
  double sign = (k & 1) ? 1.0 : -1.0, tol = 0.9 * s->lp * g->h, w = 0;
  for (j = 0; j < g->n[o]; j++) {
    if (!(sd->ext[j] > tol)) continue;
    for (line = first; line <= last; line++) {
      int32_t n = wall_nodeid(g, d, line, j), sl;
      if (g->m[n] <= s->mcut) continue;
      if (g->head[n] < 0) {
        double dn = sign * (g->q[d][n] - g->m[n] * sd->v[d]);
        if (!(dn > 0)) continue;
        g->q[d][n] -= sign * dn;
        sd->force[d] -= sign * dn / s->dt;
        w -= sign * dn * sd->v[d];
        sd->acted[(size_t)(line - first) * g->n[o] + j] = 1;
        continue;
      }
      for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
        double dn;
        if (g->sm[sl] <= s->mcut) continue;
        dn = sign * (g->sq[d][sl] - g->sm[sl] * sd->v[d]);
        if (!(dn > 0)) continue;
        g->sq[d][sl] -= sign * dn;
        g->q[d][n] -= sign * dn;
        sd->force[d] -= sign * dn / s->dt;
        w -= sign * dn * sd->v[d];
        sd->acted[(size_t)(line - first) * g->n[o] + j] = 1;
      }
    }
  }
  s->e.boundary += w;
}

static void wall_patches(sim *s, int k, int first, int last) {
  grid *g = &s->g;
  side *sd = &s->sides[k];
  int d = k / 2, o = 1 - d, nj = g->n[o], j, start = 0, a;
  memset(sd->acted, 0, (size_t)(last - first + 1) * nj);
  /* start the runs after a column without contact, so that a run across
  ** a periodic seam is one patch */
  if (g->periodic[o]) {
    for (start = 0; start < nj && patch_touch(s, k, start, first, last); start++) {}
    if (start == nj) start = 0; /* the whole wall touches: one patch */
  }
  for (a = 0; a < nj;) {
    int len = 0;
    j = (start + a) % nj;
    while (a + len < nj && patch_touch(s, k, (start + a + len) % nj, first, last)) len++;
    if (len && patch_gap(s, k, j, len)) {
      int32_t f = -1;
      while ((f = patch_next_field(s, k, j, len, first, last, f)) >= 0)
        patch_field(s, k, j, len, first, last, f);
      a += len;
    } else a++;
  }
  if (s->gap_check) patch_deep(s, k, first, last);
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

void boundary_apply(sim *s) {
  grid *g = &s->g;
  int k;
  if (s->ndriven) driven(s);
  for (k = 0; k < NSIDES; k++) {
    int line, first, last;
    if (s->sides[k].kind != SIDE_WALL) continue;
    wall_lines(g, k, &first, &last);
    if (s->wall_rule == WALL_PATCH) {
      wall_patches(s, k, first, last);
      continue;
    }
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
/* the patch rule's normal part on the velocities a (sa at slots): per
** field, the mass-weighted mean normal velocity of the patch's nodes is
** brought to the wall's v where it approaches */
static void patch_normal(sim *s, int k, int j0, int len, int first, int last,
                         int32_t f, double *const a[DIM],
                         double *const sa[DIM], double v) {
  grid *g = &s->g;
  int d = k / 2, o = 1 - d, pass, i, line;
  double sign = (k & 1) ? 1.0 : -1.0, M = 0, P = 0, dv = 0;
  for (pass = 0; pass < 2; pass++) {
    if (pass == 1) {
      if (!(M > 0) || !(sign * (P / M - v) > 0)) return;
      dv = v - P / M;
    }
    for (i = 0; i < len; i++) {
      int j = (j0 + i) % g->n[o];
      for (line = first; line <= last; line++) {
        int32_t n = wall_nodeid(g, d, line, j), sl;
        double m;
        if (!sd_acted(s, k, line - first, j) || !patch_entry(s, n, f, &sl)) continue;
        m = sl < 0 ? g->m[n] : g->sm[sl];
        if (pass == 0) {
          M += m;
          P += m * (sl < 0 ? a[d][n] : sa[d][sl]);
        } else if (sl < 0) a[d][n] += dv;
        else {
          sa[d][sl] += dv;
          a[d][n] += dv * m / g->m[n];
        }
      }
    }
  }
}

static void patch_normal_side(sim *s, int k, double *const a[DIM],
                              double *const sa[DIM], double v) {
  const grid *g = &s->g;
  int o = 1 - k / 2, nj = g->n[o], first, last, start = 0, i;
  wall_lines(g, k, &first, &last);
  if (g->periodic[o]) {
    for (start = 0; start < nj && col_acted(s, k, start, first, last); start++) {}
    if (start == nj) start = 0;
  }
  for (i = 0; i < nj;) {
    int len = 0, j = (start + i) % nj;
    while (i + len < nj && col_acted(s, k, (start + i + len) % nj, first, last)) len++;
    if (len) {
      int32_t f = -1;
      while ((f = patch_next_field(s, k, j, len, first, last, f)) >= 0)
        patch_normal(s, k, j, len, first, last, f, a, sa, v);
      i += len;
    } else i++;
  }
}

void boundary_normal_set(sim *s, double *const a[DIM],
                         double *const sa[DIM], int vel) {
  grid *g = &s->g;
  int k;
  if (s->wall_rule == WALL_PATCH) {
    for (k = 0; k < NSIDES; k++)
      if (s->sides[k].kind == SIDE_WALL)
        patch_normal_side(s, k, a, sa, vel ? s->sides[k].v[k / 2] : 0.0);
    return;
  }
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
