/*
** wall_spring.c - walls that push the material by springs on the columns
** of nodes at the wall (sim.wall_contact = "spring").
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
** So the springs act on columns of nodes: a column is the wall plane,
** the ghost planes beyond it and wall_band node planes inside, at one
** node of the wall plane, and every node of a column gets the same normal
** velocity change: a particle whose stencil lies in columns that move
** alike gets that change whole, and the loss above is left only by the
** differences between neighbouring columns.
**
** The springs belong to the material, not to places on the wall.  Kept
** per column, a spring stayed compressed after the material it held had
** slid on, and one the material reached started from nothing: the
** pressure leaned back against the slide and turned a body sliding along
** the wall (the frictionless bounce's disc at 16 cells: -0.05 / -0.10
** rad per time unit after impacts 1 / 2; a disc sliding on a
** frictionless floor under gravity turned -1.9 rad in 10 time units).
** So each spring sits at a column plus an offset (ph, in cells along
** each tangential axis, in [0, 1)), acts on the 2^(DIM-1) columns about
** it with bilinear weights w, and moves with the material: the springs of
** a patch (a connected set of them, boundary.c's patch_find) all move at
** the patch's mean tangential velocity on the wall plane, so that they
** keep their spacing; a spring whose offset passes a column goes on from
** the next one, and a column no spring covers by half or more that the
** material reaches and moves into gets a new one, in step with its
** neighbours.  Two springs meeting at one column are joined as
** sqrt(a^2 + b^2) (their energy kept); one carried off the wall's end or
** over no material is lost, booked as an impact's loss.
**
** A spring's compression delta follows its velocity into the wall, the
** w-weighted mean of its columns' mass-weighted normal velocities (its
** mass 1 / sum w^2 / M_c), and its normal impulse c is the spring force
** at the middle of the step (implicit midpoint):
**   c = k dt (delta + dt (u^n + u^new) / 4),   delta += dt (u^n + u^new) / 2
** so that the work c (u^n + u^new) / 2 is exactly the spring energy
** k delta^2 / 2 gained, at any k, M and dt (no step limit).  Springs
** sharing a column are coupled through it (u^new = u^L - A c, A_ij = sum_c
** w_ic w_jc / M_c): solved one after another, each books its energy on a
** column velocity the later ones change again, and the springs stored
** more than the material gave (measured: +1.9 to +2.4 % of the energy
** over the bounce's three impacts, growing with refinement).  So the
** impulses are solved together, by projected Gauss-Seidel sweeps (c >=
** 0: the wall pushes, never pulls) repeated to round-off: k dt^2 A / 4 is
** of order 1e-3 and a few sweeps do, except where a column holds little
** mass (up to 200 sweeps, the most allowed, in a random 3-D scene).  delta returns to 0 where the material
** moves back.
**
** k = wall_stiffness * max(rho c^2) * h^(DIM - 2) over the scene's
** materials: per wall area h^(DIM-1) the stiffness of a layer of the
** stiffest material h / wall_stiffness thick, which vanishes as the grid
** is refined, so the wall tends to the rigid one.  One k for the scene,
** so that the stored energy is k delta^2 / 2 whatever moves along the
** wall.
**
** A column holding two velocity fields (a shared node in it) is left to
** the node rule (boundary.c), as is a driven body's, which no wall acts
** on.  Frictionless: a spring wall with friction is refused (lua_sim.c;
** docs/algorithm.md section 8c says what was tried).  Serial over the
** columns: the same bits on any thread count.
*/
#include <float.h>
#include <math.h>
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

/* the column off[e] columns from j along each tangential axis e (across a
** periodic seam too), or -1 past the wall's end */
static size_t column_step(const sim *s, int k, size_t j, const int *off) {
  const grid *g = &s->g;
  size_t rest = j, to = 0, stride = 1;
  int e;
  for (e = 0; e < DIM; e++) {
    int t, u;
    if (e == k / 2) continue;
    t = (int)(rest % (size_t)g->n[e]);
    rest /= (size_t)g->n[e];
    u = t + off[e];
    if (u < 0 || u >= g->n[e]) {
      if (!g->periodic[e]) return (size_t)-1;
      u = ((u % g->n[e]) + g->n[e]) % g->n[e];
    }
    to += (size_t)u * stride;
    stride *= (size_t)g->n[e];
  }
  return to;
}

/* corner a (bit b: +1 along the b-th tangential axis) of the springs'
** square: its offsets along each axis, and its bilinear weight for a
** spring at offset ph (with sign -1: the spring a columns behind) */
static double corner(int k, int a, int sign, const double *ph, int *off) {
  double wt = 1;
  int e, bit = 0;
  for (e = 0; e < DIM; e++) {
    int up;
    off[e] = 0;
    if (e == k / 2) continue;
    up = (a >> bit++) & 1;
    off[e] = sign * up;
    wt *= up ? ph[e] : 1 - ph[e];
  }
  return wt;
}

#define NCORNER (1 << (DIM - 1))

/* a spring in contact this step: its index, the columns it acts on
** and their weights, sum w^2 / M, its velocities into the wall at the
** step's start and after the forces, and its impulse */
typedef struct spr {
  size_t j, col[NCORNER];
  int nc;
  double w[NCORNER], a, u0, uL, c;
} spr;

/* the springs take the last 7 + 2 NCORNER doubles of WSPRING_W */
typedef char spr_fits[sizeof(spr) <= (7 + 2 * NCORNER) * sizeof(double) ? 1 : -1];

/* the work arrays of one side (s->work.wcarry, WSPRING_W doubles per
** column) */
typedef struct cols {
  double *M, *u0, *uL, *du; /* per column: mass, normal velocities, change */
  double *T;                /* DIM per column: the wall plane's velocity */
  double *dl, *ph;          /* the springs moved */
  double *pw, *pv;          /* per patch: weight, velocity (DIM) */
  spr *sp;                  /* the springs in contact */
  double k;                 /* wall_spring_k, once a side and step */
  unsigned char *son;       /* s->sides[k].son */
} cols;

/* The springs' columns of side k; where the node rule takes over (two
** fields in the column, or a driven body's), son = 2 and M = 0 */
static void columns_sum(sim *s, int k, int lo, int hi, int wline, cols *c) {
  const grid *g = &s->g;
  side *sd = &s->sides[k];
  const int d = k / 2;
  const double sign = (k & 1) ? 1.0 : -1.0;
  size_t j;
  int line, e;
  for (j = 0; j < sd->next; j++) {
    double M = 0, P0 = 0, PL = 0;
    int32_t nw = grid_face_node(g, d, wline, j);
    c->son[j] = 0;
    for (e = 0; e < DIM; e++)
      c->T[j * DIM + e] = g->m[nw] > s->mcut ? g->p[e][nw] / g->m[nw] : 0;
    for (line = lo; line <= hi; line++) {
      int32_t n = grid_face_node(g, d, line, j);
      if (g->m[n] <= s->mcut) continue;
      if (g->head[n] >= 0 || (s->ndriven && s->fdriven[g->owner[n]] >= 0)) {
        c->son[j] = 2;
        break;
      }
      M += g->m[n];
      P0 += sign * (g->p[d][n] - g->m[n] * sd->v[d]);
      PL += sign * (g->q[d][n] - g->m[n] * sd->v[d]);
    }
    if (c->son[j] == 2) M = 0;
    c->M[j] = M;
    c->u0[j] = M > 0 ? P0 / M : 0;
    c->uL[j] = M > 0 ? PL / M : 0;
  }
}

/* the columns spring j acts on and their weights: the corners with
** material the springs own, their weights scaled to sum to 1 */
static int spring_corners(const sim *s, int k, size_t j, const cols *c,
                          size_t *col, double *w) {
  const double *ph = &s->sides[k].ph[j * DIM];
  int nc = 0, a, off[DIM];
  double sum = 0;
  for (a = 0; a < NCORNER; a++) {
    double wt = corner(k, a, 1, ph, off);
    size_t to = column_step(s, k, j, off);
    if (to == (size_t)-1 || !(wt > 0) || !(c->M[to] > 0)) continue;
    col[nc] = to;
    w[nc++] = wt;
    sum += wt;
  }
  for (a = 0; a < nc; a++) w[a] /= sum;
  return nc;
}

/* Move the springs with their patches' slide over the step, each patch
** at the mean tangential velocity of the wall plane under it, weighted
** by compression and weight (lab: the patch of each spring, np of them) */
static void springs_move(sim *s, int k, const int32_t *lab, int np, cols *c) {
  const grid *g = &s->g;
  side *sd = &s->sides[k];
  const size_t nf = sd->next;
  const double kk = c->k;
  size_t j, col[NCORNER];
  double w[NCORNER];
  int p, e, a;
  for (p = 0; p < np; p++) {
    c->pw[p] = 0;
    for (e = 0; e < DIM; e++) c->pv[p * DIM + e] = 0;
  }
  for (j = 0; j < nf; j++) {
    int nc;
    if (!(sd->dl[j] > 0) || lab[j] < 0) continue;
    nc = spring_corners(s, k, j, c, col, w);
    for (a = 0; a < nc; a++) {
      double wt = sd->dl[j] * w[a];
      c->pw[lab[j]] += wt;
      for (e = 0; e < DIM; e++)
        c->pv[lab[j] * DIM + e] += wt * c->T[col[a] * DIM + e];
    }
  }
  for (j = 0; j < nf; j++) {
    c->dl[j] = 0;
    for (e = 0; e < DIM; e++) c->ph[j * DIM + e] = 0;
  }
  for (j = 0; j < nf; j++) {
    double ph[DIM], a2, b2 = sd->dl[j] * sd->dl[j];
    int off[DIM];
    size_t to;
    if (!(sd->dl[j] > 0)) continue;
    p = lab[j];
    for (e = 0; e < DIM; e++) {
      double v = p >= 0 && c->pw[p] > 0 ? c->pv[p * DIM + e] / c->pw[p] : 0;
      ph[e] = off[e] = 0;
      if (e == k / 2) continue;
      ph[e] = sd->ph[j * DIM + e] + v * s->dt * g->inv_h;
      off[e] = (int)floor(ph[e]);
      ph[e] -= off[e];
    }
    to = column_step(s, k, j, off);
    if (to == (size_t)-1) { /* off the wall's end */
      s->e.impact += 0.5 * kk * b2;
      continue;
    }
    a2 = c->dl[to] * c->dl[to];
    for (e = 0; e < DIM; e++) /* joined: the offset weighted by energy */
      c->ph[to * DIM + e] = (a2 * c->ph[to * DIM + e] + b2 * ph[e]) / (a2 + b2);
    c->dl[to] = sqrt(a2 + b2);
  }
  for (j = 0; j < nf; j++) {
    sd->dl[j] = c->dl[j];
    for (e = 0; e < DIM; e++) sd->ph[j * DIM + e] = c->ph[j * DIM + e];
  }
}

/* whether a spring acts on column j with weight 1/2 or more */
static int spring_covers(const sim *s, int k, size_t j) {
  const side *sd = &s->sides[k];
  int a, off[DIM];
  for (a = 0; a < NCORNER; a++) {
    size_t from;
    corner(k, a, -1, sd->ph, off); /* for the offsets; the weight below */
    from = column_step(s, k, j, off);
    if (from == (size_t)-1 || !(sd->dl[from] > 0)) continue;
    if (corner(k, a, -1, &sd->ph[from * DIM], off) >= 0.5) return 1;
  }
  return 0;
}

/* A new spring for column j, in step with its neighbours: the offset of
** the most compressed spring among the columns next to j (0 if none),
** at the index whose spring then sits nearest j.  Returns the index, or
** -1 if a spring is there already. */
static size_t spring_new(sim *s, int k, size_t j) {
  side *sd = &s->sides[k];
  int a, e, off[DIM], n3 = 1;
  size_t best = (size_t)-1, to;
  for (e = 0; e < DIM - 1; e++) n3 *= 3;
  for (a = 0; a < n3; a++) {
    int r = a;
    size_t from;
    for (e = 0; e < DIM; e++) {
      off[e] = 0;
      if (e == k / 2) continue;
      off[e] = r % 3 - 1;
      r /= 3;
    }
    from = column_step(s, k, j, off);
    if (from == (size_t)-1 || !(sd->dl[from] > 0)) continue;
    if (best == (size_t)-1 || sd->dl[from] > sd->dl[best]) best = from;
  }
  for (e = 0; e < DIM; e++)
    off[e] = e != k / 2 && best != (size_t)-1 && sd->ph[best * DIM + e] >= 0.5 ? -1 : 0;
  to = column_step(s, k, j, off);
  if (to == (size_t)-1 || sd->dl[to] > 0) return (size_t)-1;
  for (e = 0; e < DIM; e++)
    sd->ph[to * DIM + e] = best != (size_t)-1 ? sd->ph[best * DIM + e] : 0;
  sd->dl[to] = DBL_MIN; /* taken; starts from 0 */
  return to;
}

/* the springs in contact: those there are, then new ones; returns how
** many */
static size_t springs_gather(sim *s, int k, cols *c) {
  const sim_cfg *cfg = &s->cfg;
  side *sd = &s->sides[k];
  const size_t nf = sd->next;
  const double kk = c->k;
  size_t ns = 0, j;
  int a;
  for (j = 0; j < 2 * nf; j++) {
    size_t js = j < nf ? j : j - nf;
    spr *q;
    if (j < nf && !(sd->dl[js] > 0)) continue;
    if (j >= nf) { /* a column no spring covers: a new one, once the
                   ** material reaches the wall line there and moves into it */
      size_t col = js;
      if (!(c->M[col] > 0) || (cfg->gap_check && sd->ext[col] < 0) ||
          !(c->uL[col] > 0) || spring_covers(s, k, col))
        continue;
      js = spring_new(s, k, col);
      if (js == (size_t)-1) continue;
    }
    q = &c->sp[ns];
    q->j = js;
    q->nc = spring_corners(s, k, js, c, q->col, q->w);
    if (!q->nc) { /* over no material: lost */
      s->e.impact += 0.5 * kk * sd->dl[js] * sd->dl[js];
      sd->dl[js] = 0;
      continue;
    }
    q->a = q->u0 = q->uL = q->c = 0;
    for (a = 0; a < q->nc; a++) {
      q->a += q->w[a] * q->w[a] / c->M[q->col[a]];
      q->u0 += q->w[a] * c->u0[q->col[a]];
      q->uL += q->w[a] * c->uL[q->col[a]];
      c->son[q->col[a]] = 1;
    }
    ns++;
  }
  return ns;
}

/* the columns' velocity changes du from the springs' impulses */
static void springs_du(const sim *s, int k, cols *c, size_t ns) {
  size_t i, j;
  int a;
  for (j = 0; j < s->sides[k].next; j++) c->du[j] = 0;
  for (i = 0; i < ns; i++)
    for (a = 0; a < c->sp[i].nc; a++)
      c->du[c->sp[i].col[a]] += c->sp[i].w[a] * c->sp[i].c / c->M[c->sp[i].col[a]];
}

/* The impulses together, then the compressions.  Projected Gauss-Seidel
** sweeps, repeated until no impulse moves by more than round-off: the
** system (1 + k dt^2 A / 4) c = b is symmetric positive definite, for
** which the sweeps converge whatever the coupling (Jacobi's did not:
** two springs sharing a column of little mass drove it apart, and a
** spring was left compressed by a third of the domain) */
static void springs_solve(sim *s, int k, cols *c, size_t ns) {
  side *sd = &s->sides[k];
  const double dt = s->dt, kk = c->k;
  size_t i;
  int it, a;
  for (i = 0; i < ns; i++) c->sp[i].c = 0;
  springs_du(s, k, c, ns);
  for (it = 0; it < 200; it++) {
    double most = 0, moved = 0;
    for (i = 0; i < ns; i++) {
      spr *q = &c->sp[i];
      double other = -q->a * q->c, cn;
      for (a = 0; a < q->nc; a++) other += q->w[a] * c->du[q->col[a]];
      cn = kk * dt * (sd->dl[q->j] + 0.25 * dt * (q->u0 + q->uL - other)) /
           (1 + 0.25 * kk * dt * dt * q->a);
      if (!(cn > 0)) cn = 0;
      for (a = 0; a < q->nc; a++)
        c->du[q->col[a]] += q->w[a] * (cn - q->c) / c->M[q->col[a]];
      if (cn > most) most = cn;
      if (fabs(cn - q->c) > moved) moved = fabs(cn - q->c);
      q->c = cn;
    }
    if (!(moved > 1e-14 * most)) break;
  }
  springs_du(s, k, c, ns);
  for (i = 0; i < ns; i++) {
    spr *q = &c->sp[i];
    double u1 = q->uL, *dl = &sd->dl[q->j];
    for (a = 0; a < q->nc; a++) u1 -= q->w[a] * c->du[q->col[a]];
    if (*dl == DBL_MIN) *dl = 0;
    *dl += 0.5 * dt * (q->u0 + u1);
    if (!(*dl > 0)) *dl = 0;
  }
}

/* each column's velocity change on its nodes, by mass */
static void columns_push(sim *s, int k, int lo, int hi, const cols *c) {
  grid *g = &s->g;
  side *sd = &s->sides[k];
  const int d = k / 2;
  const double sign = (k & 1) ? 1.0 : -1.0;
  size_t j;
  int line;
  for (j = 0; j < sd->next; j++) {
    if (c->son[j] != 1 || c->du[j] == 0) continue;
    for (line = lo; line <= hi; line++) {
      int32_t n = grid_face_node(g, d, line, j);
      double imp;
      if (g->m[n] <= s->mcut) continue;
      imp = -sign * g->m[n] * c->du[j];
      g->q[d][n] += imp;
      sd->force[d] += imp / s->dt;
      s->e.boundary += imp * sd->v[d]; /* a moving wall's work */
    }
  }
}

void wall_spring_side(sim *s, int k, int first, int last, const int32_t *lab,
                      int np) {
  side *sd = &s->sides[k];
  const size_t nf = sd->next;
  double *w = s->work.wcarry;
  cols c;
  size_t ns;
  int lo, hi;
  column_lines(s, k, first, last, &lo, &hi);
  c.M = w;
  c.u0 = w + nf;
  c.uL = w + 2 * nf;
  c.du = w + 3 * nf;
  c.T = w + 4 * nf;
  c.dl = c.T + DIM * nf;
  c.ph = c.dl + nf;
  c.pw = c.ph + DIM * nf;
  c.pv = c.pw + nf;
  c.sp = (spr *)(void *)(c.pv + DIM * nf);
  c.son = sd->son;
  c.k = wall_spring_k(s);
  columns_sum(s, k, lo, hi, (k & 1) ? first : last, &c);
  springs_move(s, k, lab, np, &c);
  ns = springs_gather(s, k, &c);
  springs_solve(s, k, &c, ns);
  columns_push(s, k, lo, hi, &c);
}

/* whether the springs own side k's column j (not the node rule's) */
int wall_spring_owns(const sim *s, int k, size_t j) {
  return s->sides[k].son[j] != 2;
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
      if (sd->son[j] != 1) continue;
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

