/*
** contact.c - multi-velocity-field contact at shared nodes.
**
** Normals.  With g_r = sum_p m_p grad S_ip over the particles of field r
** (grad S_ip, taken at the particle, points from the particle toward the
** node, so g_r is minus the gradient of r's nodal mass: outward) and
** G = sum_r g_r, the outward unit normal of body r is
**   n_r = (2 g_r - G) / |2 g_r - G|
** With two fields this is (g_A - g_B)/|.|, so n_B = -n_A exactly: both
** sides see one interface.  That is sim.normals = "mass"; normals()
** below gives the others ("volume", "maxvolume", "plane"), and with
** sim.normal_window takes each from the shared nodes around.  The
** default, "auto", is "mass" but where only flat-faced bodies meet:
** there node by node the corners' normals, turned toward a block's side,
** hold it on a flat body (a / a_ref 0.006 on B-splines), and the flat
** faces take "maxvolume" over NORMAL_FLAT_WINDOW cells and one normal
** per patch (within 1.6 % at 0, 30 and 45 degrees); everywhere, that
** rule made a settled pile of discs creep and two spheres lose their
** head-on symmetry (docs/verification.md, contact: normals).  Where a
** round body meets a flat one, the flat face's normal (face() below).
**
** The rule (after the grid momentum update, on q = p + dt f):
**   v_cm = sum q_r / sum m_r (a driven body's velocity replaces it)
**   dp_r = q_r - m_r v_cm, dn = dp_r . n_r
** Field r is in contact when it approaches (dn > 0: after this step's
** forces, compressive tractions included, it would move into the other
** material) and, with the separation check on, the surfaces touch
** (reach.c), or with sim.contact_gap = "step" would meet within the
** step (closing() below, which also scales the normal part down); where
** a bond was cut, the opening since the cut decides (opening() below).
** Then the normal part of dp_r is removed and the tangential part t is
** reduced by mu dn (Coulomb), or removed if |t| <= mu dn (stick).  The
** corrections are made to sum to zero (mass-weighted residual), so the
** node's total momentum is conserved to round-off;
** with two fields the residual is round-off itself.
**
** What contact dissipates.  Over a step the kinetic energy of the
** particles of field r changes by each impulse times the mean of the
** velocity the step began with (p2g's, v_r^n) and the one the particles
** carry away (v_r^r, MUSL's remap; book.c says why that one and not the
** node's vL).  The part of the contact impulse c_r,
** -c_r . (v_r^n + v_r^r) / 2 summed over the fields (the same in any
** frame, as sum_r c_r = 0; with a driven partner, taken in its frame,
** it is the drive's work on r less what r gains), is what contact
** dissipates: the first half here (contact_lose()), the second in book.c once
** the particles have moved.  Why not the kinetic energy the correction
** itself removes, (|t|^2 - |t'|^2) / (2 m_r): at a node holding a sliver
** of a body (tiny m_r) the forces give a large velocity that the
** correction takes back at once, and the count is of order
** m_r (f_r dt / m_r)^2, large where the motion it stands for is none.
** The tangential part is friction's; the normal part, booked by the same
** rule as e.impact, is the loss of an impact the node makes perfectly
** inelastic: numerical, not friction.
*/
#include <math.h>
#include <stdlib.h>
#include "heat.h"
#include "sim.h"

#define MAXSLOTS 64
/* a node's record in a threaded pass: the driven body's force (DIM) and
** work, the friction work, the bonds cut (a count), the normal
** impulses' loss, the bonded impulses' and the cohesive ones' */
#define CREC (DIM + 6)

/*
** The window.  A node's support sees a body's surface over one or two
** cells; where the surface is tilted to the grid the particles (seeded
** on the grid's lattice) make it a staircase, and two bodies pressed
** together interlock like teeth.  Each node's own estimate then turns
** with the steps, and contact that removes the normal velocity on
** turned normals holds a sliding body (measured: a block on a flat body
** tilted 30 degrees does not slide with any per-node method).  So the
** normal at node n is taken from the sums of every shared node within
** sim.normal_window = R cells of n (a block of (2R+1)^DIM nodes): a smoother density
** gradient, or a plane fitted to the particles of a wider window, which
** sees the true face over several steps.  R = 0 is the node alone.
**
** "plane": the plane that best separates field r's particles near the
** node from the others', by least squares.  With u_p = (x_i - x_p)/h and
** c_p = 1 for r's particles, -1 for the others', (n, b) minimize
**   sum_p w_p (n . u_p + b - c_p)^2,   w_p = V_p sum_j S_jp
** (a linear discriminant: it sees where each side's material lies, not
** how steeply its mass falls off, so a body's corner facing a flat face
** does not turn the face's normal).  The normal equations need only the
** moments p2g gathered at each node j of the window, moved to node i
** (u_i = u_j + (x_i - x_j)/h):
**   [ sum w u u^T  sum w u ] [n]   [ sum c w u ]
**   [ sum w u^T    sum w   ] [b] = [ sum c w   ]
** and n, pointing to where c grows away from r's material, is r's
** outward normal.  The right side is r's moments less the others', so
** with two fields the partner's is the exact negative, and so is its
** normal.  Gaussian elimination with partial pivoting; 0 if singular
** (the particles all on one line through the node, say).
*/
#define NP (DIM + 1)
static int solve(double A[NP][NP], double y[NP], double v[DIM]) {
  int a, b, c;
  for (a = 0; a < NP; a++)
    for (b = 0; b < a; b++) A[a][b] = A[b][a];
  for (c = 0; c < NP; c++) {
    int p = c;
    double t;
    for (a = c + 1; a < NP; a++)
      if (fabs(A[a][c]) > fabs(A[p][c])) p = a;
    if (!(fabs(A[p][c]) > 1e-12 * A[DIM][DIM])) return 0;
    if (p != c) {
      for (b = 0; b < NP; b++) { t = A[c][b]; A[c][b] = A[p][b]; A[p][b] = t; }
      t = y[c]; y[c] = y[p]; y[p] = t;
    }
    for (a = c + 1; a < NP; a++) {
      double f = A[a][c] / A[c][c];
      for (b = c; b < NP; b++) A[a][b] -= f * A[c][b];
      y[a] -= f * y[c];
    }
  }
  for (c = NP - 1; c >= 0; c--) {
    for (b = c + 1; b < NP; b++) y[c] -= A[c][b] * y[b];
    y[c] /= A[c][c];
  }
  for (a = 0; a < DIM; a++) v[a] = y[a];
  return 1;
}

/* node j's moments moved to the node dl (in cells) away, added into the
** normal equations of field f's slot (upper triangle) */
static void moments(const grid *g, int32_t j, int32_t f, const double dl[DIM],
                    double k, double A[NP][NP], double y[NP]) {
  int32_t q;
  int a, b;
  for (q = g->head[j]; q >= 0; q = g->snext[q]) {
    double sgn = g->sfield[q] == f ? 1.0 : -1.0, w = g->sw[q], m[DIM];
    for (a = 0; a < DIM; a++) m[a] = g->sx[a][q] + dl[a] * w;
    for (a = 0; a < DIM; a++) {
      for (b = a; b < DIM; b++)
        A[a][b] += k * (g->sxx[grid_sym(a, b)][q] + dl[a] * g->sx[b][q] +
                        dl[b] * g->sx[a][q] + dl[a] * dl[b] * w);
      A[a][DIM] += k * m[a];
      y[a] += k * sgn * m[a];
    }
    A[DIM][DIM] += k * w;
    y[DIM] += k * sgn * w;
  }
}

/* The window of nodes within R cells of a node, (2R+1)^DIM of them,
** walked with x fastest (then y, then z) as the sums were always taken:
** b holds the offset, starting at (-R, ..., -R); win_next steps it and
** says whether any is left.  win_node is the node at offset b from the
** node at indices i, wrapped across periodic sides, or -1 beyond a side
** that is not */
static void win_first(int b[DIM], int R) {
  int d;
  for (d = 0; d < DIM; d++) b[d] = -R;
}
static int win_next(int b[DIM], int R) {
  int d;
  for (d = 0; d < DIM; d++) {
    if (++b[d] <= R) return 1;
    b[d] = -R;
  }
  return 0;
}
static int32_t win_node(const grid *g, const int i[DIM], const int b[DIM]) {
  int j[DIM], d;
  for (d = 0; d < DIM; d++) {
    j[d] = grid_wrap(g, d, i[d] + b[d]);
    if (j[d] < 0 || j[d] >= g->n[d]) return -1;
  }
  return grid_node(g, j);
}

/* the window's sums for field f at node n: its gradient (own) and the
** others' at the nodes where f has a slot (rest), or, with A, y, the
** plane's normal equations over every shared node of the window.
**
** rr: the plane's window weighted 1 - r^2 / rr by the node's distance r
** from n (in cells): with rr = (R + 1)^2 a round window, with rr
** infinite the square's uniform weights.  Why: the least-squares plane of a flat face seen
** through a square window is turned toward the grid's axes wherever
** the face is neither along them nor diagonal (the band of shared
** nodes, cut by the square, is not symmetric about the face's normal),
** and a patch's mean normal (normal_patch) keeps that turn, however
** many nodes it averages; a round window is symmetric about any line
** through its centre.  Measured, a block on a flat body tilted to the
** grid, plane/4 + patch, B-splines, 16 cells per side, a / a_ref - 1
** square -> round: 15 deg -1.07 -> -0.67 %, with friction -1.93 ->
** -0.49 %; 30 deg -1.18 -> -0.27 %, -1.84 -> -0.28 %; 45 deg unchanged
** (-0.72, -1.17 %).  Node by node a node's own fit needs the wider
** square to see past the staircase (linear hats, plane/4, 30 deg with
** friction, 16 cells: -1.2 % square, -4.3 % round), so there the square
** stays. */
static void window(const grid *g, double *const a[DIM], int32_t n, int32_t f,
                   int R, double rr, double own[DIM], double rest[DIM],
                   double A[NP][NP], double y[NP]) {
  int i[DIM], b[DIM], d;
  for (d = 0; d < DIM; d++) own[d] = rest[d] = 0;
  grid_ijk(g, n, i);
  win_first(b, R);
  do {
    int32_t j = win_node(g, i, b), q;
    if (j < 0 || g->head[j] < 0) continue;
    if (A) {
      double dl[DIM], r2 = 0, k;
      for (d = 0; d < DIM; d++) {
        dl[d] = -b[d];
        r2 += (double)b[d] * b[d];
      }
      k = 1 - r2 / rr;
      if (k > 0) moments(g, j, f, dl, k, A, y);
      continue;
    }
    for (q = g->head[j]; q >= 0 && g->sfield[q] != f; q = g->snext[q]) {}
    if (q < 0) continue;
    for (q = g->head[j]; q >= 0; q = g->snext[q])
      for (d = 0; d < DIM; d++) {
        if (g->sfield[q] == f) own[d] += a[d][q];
        else rest[d] += a[d][q];
      }
  } while (win_next(b, R));
}

/* Normals of the shared nodes [k0, k1): each node reads the window's
** sums and writes only its own slots, so parts cut anywhere give the
** same numbers.  With own and rest field r's and the others' sums:
**   "mass", "volume": (own - rest) / |.| of the mass or volume gradient.
**   "maxvolume": the side with the larger volume gradient is the better
**     sampled surface (the other reaches the node with a sliver of
**     material, or from a stair-step's corner): its own direction is
**     the normal, and the partner takes the opposite one; the
**     difference on an exact tie; so with two fields n_B = -n_A.
**   "plane": the fitted plane, the volume gradients' difference where
**     it has none. */
static int flat_node(const sim *s, int32_t n) {
  const grid *g = &s->g;
  int32_t sl;
  for (sl = g->head[n]; sl >= 0; sl = g->snext[sl])
    if (!s->fflat[g->sfield[sl]]) return 0;
  return 1;
}

/*
** "auto" where a round body meets a flat one (a node of two fields, one
** flat): the flat face's own normal, its mass gradient summed over the
** nodes within NORMAL_FLAT_WINDOW cells that the same two fields share,
** the round body's the negative.  Why not the difference of the two: a
** node off the contact point has the round body's radial gradient, the
** normal leans with it, and along a leaning normal a flat face's reach
** (reach.c) is not the gap: a disc falling onto a driven slab at 16
** cells was taken for touching 0.56 cell before it did, and the
** material a cell inside it was stopped along the leaning normals (the
** report's bounce with driven bodies for walls lost 9 to 19 % per
** impact; a disc sliding frictionless on a slab kept 0.63 / 0.69 of its
** speed at 8 / 16 cells node by node).  Why the window: a node's own
** gradient is the face's only on the face; at a plate's corner it turns
** 45 degrees, and deep in a thin plate it vanishes (the midline of a
** slab two cells thick: the difference then took over and slowed the
** sliding disc 6 % at 8 cells); summed over one cell each way a disc
** pressed on a plate 6.4 cells tall read a normal force 4 % above the
** plate's (the corners' nodes pushing along their diagonals), over four
** cells 0.6 %.  Why only the nodes the two share: the flat body's end
** where it abuts another body (two driven walls meeting in a corner)
** is in its gradient too, and summed in it turned the face's normal 58
** degrees for a disc meeting the wall four cells from the corner.
** Returns 0 where the face has no gradient even so (the difference
** stands).
*/
static int face(sim *s, int32_t n, int32_t first) {
  grid *g = &s->g;
  int32_t second = g->snext[first];
  int32_t fl = s->fflat[g->sfield[first]] ? first : second;
  int32_t ro = fl == first ? second : first;
  const int32_t ff = g->sfield[fl], fr = g->sfield[ro];
  double sum[DIM] = {0}, len = 0;
  int i[DIM], b[DIM], d;
  grid_ijk(g, n, i);
  win_first(b, NORMAL_FLAT_WINDOW);
  do {
    int32_t j = win_node(g, i, b), q, qf = -1;
    int both = 0;
    if (j < 0 || g->head[j] < 0) continue;
    for (q = g->head[j]; q >= 0; q = g->snext[q]) {
      if (g->sfield[q] == ff) qf = q;
      else if (g->sfield[q] == fr) both = 1;
    }
    if (qf < 0 || !both) continue;
    for (d = 0; d < DIM; d++) sum[d] += g->sg[d][qf];
  } while (win_next(b, NORMAL_FLAT_WINDOW));
  for (d = 0; d < DIM; d++) len += sum[d] * sum[d];
  if (!(len > 0)) return 0;
  len = sqrt(len);
  for (d = 0; d < DIM; d++) {
    g->sn[d][fl] = sum[d] / len;
    g->sn[d][ro] = -sum[d] / len;
  }
  return 1;
}

static void normals(sim *s, size_t k0, size_t k1) {
  const sim_cfg *cfg = &s->cfg;
  grid *g = &s->g;
  const int autom = cfg->normals == NORMALS_AUTO, flats = autom && s->flatpair;
  const int faces = autom && s->flatmix;
  double *const *ag = cfg->normals == NORMALS_MASS || autom ? g->sg : g->sv;
  const int maxvg = cfg->normals == NORMALS_MAXVOLUME;
  const int pl0 = cfg->normals == NORMALS_PLANE;
  const int R0 = cfg->normal_window;
  /* the patch's mean normal wants each fit unbiased: window() */
  const double rr = cfg->normal_patch && R0 > 0 ? (R0 + 1.0) * (R0 + 1.0) : INFINITY;
  size_t k;
  for (k = k0; k < k1; k++) {
    int32_t n = g->shared[k], sl, first = g->head[n];
    /* "auto" between flat faces: the larger volume gradient over the
    ** flat window (one normal per patch follows, contact_patch.c) */
    const int flat = flats && flat_node(s, n);
    double *const *a = flat ? g->sv : ag;
    const int maxv = flat || maxvg, pl = !flat && pl0;
    const int R = flat ? NORMAL_FLAT_WINDOW : R0;
    /* the plane's equations are the same for every field of the node
    ** but for the sign of the right side, so with two fields the second
    ** normal is the first's negative, to the bit: taken so, not solved
    ** again (where the first fell back on the gradients it is solved) */
    const int two = first >= 0 && g->snext[first] >= 0 && g->snext[g->snext[first]] < 0;
    int fitted = 0;
    if (faces && two && s->fflat[g->sfield[first]] != s->fflat[g->sfield[g->snext[first]]] &&
        face(s, n, first))
      continue;
    for (sl = first; sl >= 0; sl = g->snext[sl]) {
      double v[DIM], own[DIM], rest[DIM], len = 0, lo = 0, lr = 0;
      int d;
      if (pl) {
        double A[NP][NP] = {{0}}, y[NP] = {0}, u[DIM], l2 = 0;
        if (two && sl != first && fitted) {
          for (d = 0; d < DIM; d++) g->sn[d][sl] = -g->sn[d][first];
          continue;
        }
        window(g, a, n, g->sfield[sl], R, rr, own, rest, A, y);
        if (solve(A, y, u)) {
          for (d = 0; d < DIM; d++) l2 += u[d] * u[d];
          if (l2 > 0) {
            len = sqrt(l2);
            for (d = 0; d < DIM; d++) g->sn[d][sl] = u[d] / len;
            fitted = sl == first;
            continue;
          }
        }
      }
      /* the gradients' sums: the method, or the plane's fallback */
      window(g, a, n, g->sfield[sl], R, INFINITY, own, rest, NULL, NULL);
      for (d = 0; d < DIM; d++) {
        v[d] = own[d] - rest[d];
        len += v[d] * v[d];
        lo += own[d] * own[d];
        lr += rest[d] * rest[d];
      }
      len = sqrt(len);
      if (maxv && lo != lr) {
        const double *w = lo > lr ? own : rest, sg = lo > lr ? 1.0 : -1.0;
        for (d = 0; d < DIM; d++) v[d] = sg * w[d];
        len = sqrt(lo > lr ? lo : lr);
      }
      for (d = 0; d < DIM; d++) g->sn[d][sl] = len > 0 ? v[d] / len : 0.0;
    }
  }
}
#undef NP

static void normals_part(void *arg, int t, int nparts) {
  sim *s = arg;
  size_t k0, k1;
  par_range(s->g.nshared, t, nparts, &k0, &k1);
  normals(s, k0, k1);
}

void contact_normals(sim *s) {
  par_run(s->work.par, normals_part, s);
  if ((s->cfg.normal_patch || sim_flat_patches(s)) && s->work.cplab)
    contact_patch_normals(s);
}

/*
** With a driven partner, the normal traction the bond carries at node n
** for field r (tension positive) is the force the interface must give r
** so that r follows the drive, -f_r, along r's outward normal, over the
** interface area the node stands for: r's own stresses give the node
** f_r = -int_r sigma grad S_i dV, by the divergence theorem minus the
** interface traction weighted by S_i over the interface (the rest of r's
** surface is free); the same weighting of the area is
** A_i = |sum_p V_p grad S_ip| (bond.c).  Between two free fields the test
** uses the particles' stresses instead (normal_stress() below says why).
*/
static double area(const grid *g, int32_t sl) {
  double a = 0;
  int d;
  for (d = 0; d < DIM; d++) a += g->sv[d][sl] * g->sv[d][sl];
  return sqrt(a);
}

/* the normal force the bond gives slot sl at node n (drv: the partner is
** driven, and r must follow its prescribed motion: it needs -f_r) */
static double bondforce(const grid *g, int32_t n, int32_t sl, int drv) {
  double t = 0, w = drv ? 0 : g->sm[sl] / g->m[n];
  int d;
  for (d = 0; d < DIM; d++) t += g->sn[d][sl] * (w * g->f[d][n] - g->sf[d][sl]);
  return t;
}

/* The normal stress across the interface at node j seen from slot q:
** the mixture of every field's particle stress at the node,
**   sigma_j = sum_r sum_p w_p sigma_p / sum_r sum_p w_p,  w_p = V_p S_jp,
** projected on q's normal.  Why the mixture and not q's own particles:
** bonded, the fields share one velocity, so in a cell the interface
** cuts every particle takes the cell's one strain, a volume-weighted mix
** of the two sides' strains; each side's stress there is off by the
** other side's share of the strain jump (measured on the concentric
** cylinders: q's own particles alone put the disc's traction at twice
** the Lame value, onset at 0.46-0.54 of it), and the two errors cancel
** in the volume-weighted mean, which is what continuity of the normal
** traction asks for.  A driven partner has no stresses of its own: its
** slot's particles are left out (drv). */
static double normal_stress(const grid *g, int32_t j, int32_t q, int drv) {
  double S[DIM * (DIM + 1) / 2] = {0}, W = 0, t = 0;
  int32_t o;
  int a, b;
  for (o = g->head[j]; o >= 0; o = g->snext[o])
    if (o == q || !drv) {
      for (a = 0; a < DIM * (DIM + 1) / 2; a++) S[a] += g->sst[a][o];
      W += g->ssw[o];
    }
  if (!(W > 0)) return 0;
  for (a = 0; a < DIM; a++)
    for (b = 0; b < DIM; b++)
      t += g->sn[a][q] * g->sn[b][q] * S[a <= b ? grid_sym(a, b) : grid_sym(b, a)];
  return t / W;
}

/*
** The fitted traction (sim.bond_traction = "fit").  Around node n, the
** nodes only one field reaches (bond.c fit(): their particles lie a cell
** or more from the interface, clear of the cells it cuts) in a strip one
** cell wide along n_r, FIT_PATCH cells each way, give each of the two
** fields a straight line of its normal stress across the interface,
** sigma_k(xi) = A_k + B_k xi (xi: distance from node n along n_r, in
** cells), by weighted least squares (the strip's side nodes weighted
** 1/3).  Normal traction is continuous, so the interface lies where the
** two lines cross, xi* = (A_o - A_r) / (B_r - B_o), clamped to
** FIT_CROSS cells; the traction is the two lines' values there, each
** weighted by 1 / B_k^2 so that the flatter side, whose value depends
** least on where the crossing is, counts most.  0 where either side has
** too few particles to fit a line (the mixture is taken there).
**
** Why.  The mixture (normal_stress()) averages each node's support
** across the interface, over which the annulus's radial stress on the
** concentric cylinders falls by half its value per cell at 25 cells:
** per node it read 0.880 / 0.908 / 0.948 of the Lame value at 25 / 50 /
** 100 cells (mean), with a node-to-node scatter (sd 0.02-0.045) that did
** not shrink.  Fitted: 0.974 / 1.006 / 0.997, scatter 0.003 over a patch
** of 0.08 (docs/verification.md).  Why the strip: over a square window
** the curved interface (5 cells radius at 25 cells) turned the hoop
** stress into the normal one (mean 0.79 at 25 cells).  Why four cells
** each way: the nodes both fields reach span the stencil's reach on
** each side of the interface (1.5 cells for B-splines and GIMP), so
** over three cells a side was often left one node row or none, too few
** for a line, and the node fell back on the mixture.  Measured, the
** concentric onset / Lame at 25 / 35 / 50 cells, three cells against
** four: B-splines 0.959 / 1.047 / 0.995 against 0.963 / 1.006 / 0.995,
** uGIMP 1.055 / 1.006 / 0.999 against 1.005 / 1.004 / 0.999, linear
** hats 1.006 / 0.998 / 0.995 either way.
*/
#define FIT_PATCH 4
#define FIT_CROSS 1.5

/* n . T . n of a symmetric tensor T held as grid_sym's upper triangle,
** its components cs apart from T (the bond fit's sums, bond.c) */
static double symnn(const double *T, size_t cs, const double n[DIM]) {
  double r = 0;
  int a, c;
  for (a = 0; a < DIM; a++)
    for (c = a; c < DIM; c++)
      r += (a == c ? 1 : 2) * T[cs * (size_t)grid_sym(a, c)] * n[a] * n[c];
  return r;
}

static int fitted(const sim *s, int32_t n, int32_t sl, int32_t o, double *t) {
  const sim_work *wk = &s->work;
  const grid *g = &s->g;
  const double *b = wk->bfit;
  size_t N = g->nnodes;
  int32_t fr = g->sfield[sl], fo = g->sfield[o];
  double m[2][5] = {{0}}, nn[DIM], A[2], B[2], xs, e2, w0, w1;
  int a, k, i[DIM], off[DIM];
  for (a = 0; a < DIM; a++) nn[a] = g->sn[a][sl];
  grid_ijk(g, n, i);
  win_first(off, FIT_PATCH);
  /* the strip is, in 3-D, the rod of nodes within 1.5 cells of the line
  ** along n_r through node n, weighted by the same falloff */
  do {
    int32_t j = win_node(g, i, off);
    int sd;
    double dl[DIM], w, W, xi0, tau, u[DIM], snn, sxi, uxi, xx;
    if (j < 0) continue;
    W = b[BF_W * N + j];
    if (g->head[j] >= 0 || !(W > 0)) continue;
    if (wk->bffield[j] == fr) sd = 0;
    else if (wk->bffield[j] == fo) sd = 1;
    else continue;
    for (a = 0; a < DIM; a++) dl[a] = off[a];
    xi0 = vec_dot(dl, nn);
    tau = vec_crossnorm(dl, nn);
    w = 1 - tau / 1.5;
    if (!(w > 0)) continue;
    for (k = 0; k < DIM; k++) u[k] = b[(BF_U + k) * N + j];
    /* about node j: sum w xi_j, sum w xi_j^2, sum w s_nn, sum w s_nn xi_j */
    uxi = vec_dot(u, nn);
    xx = symnn(b + BF_UU * N + j, N, nn);
    snn = symnn(b + BF_S * N + j, N, nn);
    sxi = 0;
    for (k = 0; k < DIM; k++)
      sxi += nn[k] * symnn(b + (BF_SU + k) * N + j, DIM * N, nn);
    /* moved to node n: xi = xi_j + xi0 */
    m[sd][0] += w * W;
    m[sd][1] += w * (uxi + W * xi0);
    m[sd][2] += w * (xx + 2 * xi0 * uxi + W * xi0 * xi0);
    m[sd][3] += w * snn;
    m[sd][4] += w * (sxi + xi0 * snn);
  } while (win_next(off, FIT_PATCH));
  for (k = 0; k < 2; k++) {
    double det = m[k][0] * m[k][2] - m[k][1] * m[k][1];
    /* a line needs weight spread over a cell at least */
    if (!(m[k][0] > 0) || !(det > 0.25 * m[k][0] * m[k][0])) return 0;
    B[k] = (m[k][0] * m[k][4] - m[k][1] * m[k][3]) / det;
    A[k] = (m[k][3] - B[k] * m[k][1]) / m[k][0];
  }
  xs = (A[1] - A[0]) / (B[0] - B[1]);
  if (!(xs >= -FIT_CROSS)) xs = -FIT_CROSS;
  if (!(xs <= FIT_CROSS)) xs = FIT_CROSS;
  e2 = 1e-4 * (A[0] * A[0] + A[1] * A[1]) + 1e-300;
  w0 = 1 / (B[0] * B[0] + e2);
  w1 = 1 / (B[1] * B[1] + e2);
  *t = (w0 * (A[0] + B[0] * xs) + w1 * (A[1] + B[1] * xs)) / (w0 + w1);
  return 1;
}

/* each still-bonded slot's fitted traction, against its heaviest partner
** (a driven partner keeps the force balance): every node writes only its
** own slots */
static void fits_part(void *arg, int t, int nparts) {
  sim *s = arg;
  grid *g = &s->g;
  size_t k, k0, k1;
  par_range(g->nshared, t, nparts, &k0, &k1);
  for (k = k0; k < k1; k++) {
    int32_t n = g->shared[k], sl, q;
    for (sl = g->head[n]; sl >= 0; sl = g->snext[sl]) {
      int32_t o = -1;
      double mo = -1, tr;
      g->sfok[sl] = 0;
      if (!(g->sb[sl] > 0)) continue;
      for (q = g->head[n]; q >= 0; q = g->snext[q])
        if (q != sl && g->sm[q] > mo) {
          mo = g->sm[q];
          o = q;
        }
      if (o < 0 || s->fdriven[g->sfield[o]] >= 0) continue;
      if (fitted(s, n, sl, o, &tr)) {
        g->sft[sl] = tr;
        g->sfok[sl] = 1;
      }
    }
  }
}

/* The traction the bond test sees at node n for slot sl: the
** area-weighted mean of normal_stress() over the nodes within
** BOND_PATCH cells of n where the same field meets the interface, or,
** with a driven partner, the force balance below over the same patch.
**
** Why not the force balance for two free fields.  The force the
** interface must give r, (m_r / M) f - f_r along r's normal, over the
** node's interface area A_ir (bond.c) is exact for a uniform stress and
** sums to the right total over an interface, but node by node it
** partitions the force and the area differently: the 5 x 5 patch's
** largest value was 1.13-1.14 times the Lame value on the concentric
** cylinders and the onset came at 0.914, 0.896, 0.892 of the analytic
** one at 25, 50, 100 cells (linear hats), worse with refinement.  The
** mixture stress gives 1.065, 1.008, 0.964 (docs/verification.md).
** With a driven partner (a grip), m_r / M does not enter and the force
** balance -f_r . n is what the drive transmits; it is kept there.
**
** Why a patch: a single node's mixture still carries the scatter of the
** cut cells' stresses; 5 x 5 nodes (5^3 in 3-D) keep the strength local to two
** cells. */
#define BOND_PATCH 2
#define BOND_PATCH_MAX 16

static double traction(const sim *s, int32_t n, int32_t sl, int drv) {
  const sim_cfg *cfg = &s->cfg;
  const grid *g = &s->g;
  int32_t f = g->sfield[sl];
  double F = 0, A = 0;
  int i[DIM], off[DIM], R = BOND_PATCH, fit = cfg->bond_fit && !drv;
  if (fit && cfg->bond_length * g->inv_h > R)
    R = cfg->bond_length * g->inv_h < BOND_PATCH_MAX
            ? (int)ceil(cfg->bond_length * g->inv_h - 1e-9) : BOND_PATCH_MAX;
  grid_ijk(g, n, i);
  win_first(off, R);
  do {
    int32_t j = win_node(g, i, off), q;
    double aq;
    if (j < 0 || g->head[j] < 0) continue;
    for (q = g->head[j]; q >= 0 && g->sfield[q] != f; q = g->snext[q]) {}
    /* only the interface still bonded: a debonded node's traction is
    ** no load the bond carries, and counting it would pass its
    ** release on to the neighbours at once, two cells per step */
    if (q < 0 || !(g->m[j] > 0) || !(g->sb[q] > 0)) continue;
    aq = area(g, q);
    F += drv ? bondforce(g, j, q, drv)
             : aq * (fit && g->sfok[q] ? g->sft[q] : normal_stress(g, j, q, drv));
    A += aq;
  } while (win_next(off, R));
  return A > 0 ? F / A : 0;
}

double contact_bond_traction(const sim *s, int32_t n, int32_t sl, int odriven) {
  return traction(s, n, sl, odriven);
}

void contact_bond_fits(sim *s) {
  if (s->fbond >= 0 && s->cfg.bond_fit && s->g.nshared)
    par_run(s->work.par, fits_part, s);
}

/* the strength slot sl has left in this pass: none once cut.  A cut is
** only recorded (scut) while the pass runs, and sb is cleared after it
** (bond_sums), so that every node's traction reads its neighbours'
** strengths as the pass began: the nodes do not depend on each other's
** order and are cut among the threads.  (Cleared at once, a cut would
** pass on to the nodes after it in the same sweep, and a debonding could
** run along the sweep's direction within one step.) */
static double left(const grid *g, int32_t sl) {
  return g->scut[sl] > 0 ? 0.0 : g->sb[sl];
}

/*
** Bonds (the report's rule).  Where field r and its partner o both carry
** bond strength and their law lets them bond, the interface is bonded
** while the normal traction t (traction() above) stays
** at or below the strength b = min(b_r, b_o, the law's cap): then r moves
** with the
** reference velocity (perfect bonding, as on one field).  When t > b the
** node's strength on both sides is cut to zero, the cut recorded for
** bond_scatter, and the interface is treated as debonded contact from
** this step on.  Returns 1 if bonded, 0 if not, -1 if cut now.
*/
double contact_bond(const sim *s, int32_t sl, int32_t o, int odriven) {
  const grid *g = &s->g;
  const pairlaw *l;
  double b, cap, bs = left(g, sl), bo = left(g, o);
  if (!(bs > 0) || !(bo > 0 || odriven)) return 0;
  l = sim_law_of(s, g->sfield[sl], g->sfield[o]);
  cap = l ? l->bond : s->cfg.bond_default;
  if (!(cap > 0)) return 0;
  b = odriven || bs < bo ? bs : bo;
  return cap < b ? cap : b;
}

static int bonded(sim *s, int32_t n, int32_t sl, int32_t o, int odriven) {
  grid *g = &s->g;
  double b = contact_bond(s, sl, o, odriven);
  if (!(b > 0)) return 0;
  if (traction(s, n, sl, odriven) <= b) return 1;
  g->scut[sl] += left(g, sl);
  if (!odriven) g->scut[o] += left(g, o);
  return -1;
}

/* the first half of what slot sl's impulse c dissipates (book.c): minus
** its work on half the velocity the step began with, relative to the
** reference velocity vref, -c . (v_r^n / 2 - vref); the impulse is kept
** in a (sfi or sni) for book_finish, which adds -c . v_r^new / 2 */
double contact_lose(const grid *g, int32_t sl, const double vref[DIM],
                    const double c[DIM], double *const a[DIM]) {
  double mr = g->sm[sl], w = 0;
  int d;
  if (!(mr > 0)) return 0;
  for (d = 0; d < DIM; d++) {
    w += (0.5 * g->sp[d][sl] - mr * vref[d]) * c[d];
    a[d][sl] += c[d];
  }
  return -w / mr;
}

/* node k's friction work, bonds cut, normal and bonded impulses' loss:
** recorded (a threaded pass) or added now */
static void booked(sim *s, size_t k, double fric, int cuts, double imp,
                   double bnd, double coh, int rec) {
  sim_work *wk = &s->work;
  if (rec) {
    wk->crec[CREC * k + DIM + 1] = fric;
    wk->crec[CREC * k + DIM + 2] = cuts;
    wk->crec[CREC * k + DIM + 3] = imp;
    wk->crec[CREC * k + DIM + 4] = bnd;
    wk->crec[CREC * k + DIM + 5] = coh;
  } else {
    s->e.friction += fric;
    s->e.impact += imp;
    s->e.bonding += bnd;
    s->e.cohesion += coh;
    s->ncut += (size_t)cuts;
  }
}

/*
** Detection by the gap at the step's end (sim.contact_gap = "step").
** The surfaces are gap = -(e_r + e_o) apart along n_r (reach.c; < 0 when
** they overlap), and close at w = (v_r - v_o) . n_r, the partner's
** velocity taken relative to the reference (zero for a driven partner).
** If they would not meet within the step (w dt <= gap) there is no
** contact; if they would, only the part of the approach that overlaps
** them is taken away, so that they end the step just touching: the
** normal correction is scaled by 1 - gap / (w dt).  Overlapping surfaces
** (gap <= 0) get the whole correction.  Returns that fraction.
*/
static double closing(const sim *s, int32_t sl, int32_t o, int odriven,
                      const double vref[DIM], double *const smom[DIM],
                      double dn, double gap) {
  const grid *g = &s->g;
  double w = dn / g->sm[sl];
  int d;
  if (!(gap > 0)) return 1;
  if (!odriven && g->sm[o] > s->mcut)
    for (d = 0; d < DIM; d++)
      w -= (smom[d][o] / g->sm[o] - vref[d]) * g->sn[d][sl];
  if (!(w * s->dt > gap)) return 0;
  return 1 - gap / (w * s->dt);
}

/*
** Contact where a bond was cut (sim.bond_release = "open").  Released, the
** two sides are where the bond held them: touching, with a gap that then
** opens by the difference of their displacements since the cut, which on
** the concentric cylinders is a tenth of a cell, below what the
** separation check resolves (particles' half-cell squares): each side's
** reach overlaps the other's, contact took every approach of the ringing
** as an impact and rectified it into a squeeze (the disc held at -0.67 of
** its bonded stress, where it should relax to zero).  So where both sides
** at a node hold released particles (bond_scatter records where each
** was), the opening is measured from them,
**   gap = -(u_r - u_o) . n_r,  u_r = sum_p m_p S_ip (x_p - x_p,cut) / sum m_p S_ip
** over r's released particles, and closing() judges the step with it:
** the bodies meet again only once the opening has closed.  Returns 1 and
** the gap where it can be measured, 0 where not (a driven partner, or a
** side with no released particle here: the separation check decides).
** Only while the two sides have moved apart by less than a cell,
** |u_r - u_o| < h: the opening is meant for what the reach cannot
** resolve, and once released particles have slid far along an interface
** that has turned, their displacement since the cut, projected on
** today's normal, reads as an opening where the surfaces press (the
** bonded binder cell at 100 cells buried a grain's particle a cell deep
** in the binder at 72 and 86 % strain; with the bound, none).
*/
static int apart(const sim *s, int32_t sl, int32_t o, double *gap, double *uu) {
  const grid *g = &s->g;
  double u = 0;
  int d;
  if (s->frel < 0 || o < 0 || s->fdriven[g->sfield[o]] >= 0 ||
      !(g->srm[sl] > s->mcut) || !(g->srm[o] > s->mcut))
    return 0;
  *uu = 0;
  for (d = 0; d < DIM; d++) {
    double du = g->sru[d][sl] / g->srm[sl] - g->sru[d][o] / g->srm[o];
    u += du * g->sn[d][sl];
    *uu += du * du;
  }
  *gap = -u;
  return 1;
}

static int opening(const sim *s, int32_t sl, int32_t o, double *gap) {
  double uu;
  /* moved apart a cell or more: the reach */
  return apart(s, sl, o, gap, &uu) && !(uu > s->g.h * s->g.h);
}

/*
** The cohesive law (sim.bond_energy = G_c > 0).  A strength criterion
** alone has no energy: the cut node lets go at once, and how far and how
** fast a debonding runs then depends on the cell (docs/verification.md,
** debond front).  Here a cut interface keeps a normal traction that falls
** linearly with the opening delta (apart() above, from the released
** particles' displacements since the cut),
**   t = sigma_c (1 - delta_max / delta_c),  delta_c = 2 G_c / sigma_c,
** sigma_c the strength the two sides had at the cut (and the law's cap),
** delta_max the largest opening the node has seen (the particles keep
** it: damage does not heal), so that separating a unit area takes G_c
** whatever the grid.  Below delta_max the traction is the secant
** t delta / delta_max.  It only holds the sides back: the impulse
** t A dt along r's normal is given while r moves away from its partner
** (dn < 0) and never more than the -dn that would stop that motion (the
** bonded limit, so the law cannot overshoot however small delta_max),
** and closing sides get none (contact decides), so a reopening pays the
** secant part again.  Returns the impulse along n_r, >= 0.
*/
static double cohere(const sim *s, int32_t sl, int32_t o, double dn) {
  const grid *g = &s->g;
  const pairlaw *l;
  double sc, so, dm, dmo, dc, del, uu, t, cap;
  if (!apart(s, sl, o, &del, &uu)) return 0;
  sc = g->scs[sl] / g->srm[sl];
  so = g->scs[o] / g->srm[o];
  if (so < sc) sc = so;
  l = sim_law_of(s, g->sfield[sl], g->sfield[o]);
  cap = l ? l->bond : s->cfg.bond_default;
  if (cap < sc) sc = cap;
  dm = g->sdm[sl] / g->srm[sl];
  dmo = g->sdm[o] / g->srm[o];
  if (dmo > dm) dm = dmo;
  if (del > dm) dm = del;
  if (dm > g->sdn[sl]) g->sdn[sl] = dm;
  if (!(sc > 0) || !(dn < 0)) return 0;
  dc = 2 * s->cfg.bond_gc / sc;
  if (!(dm < dc)) return 0;
  t = sc * (1 - dm / dc);
  if (del < dm) t *= del > 0 ? del / dm : 0;
  t *= 0.5 * (area(g, sl) + area(g, o)) * s->dt;
  return t < -dn ? t : -dn;
}

/* the correction at shared node k; rec: record the driven body's force
** and work for contact_apply to add up in order (a threaded pass) */
static void node(sim *s, size_t k0, double *const mom[DIM],
                 double *const smom[DIM], int rec) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  int32_t n = g->shared[k0];
  /* each slot's correction, bonded (cb) and by contact (cc) */
  double cb[MAXSLOTS][DIM], cc[MAXSLOTS][DIM];
  double ct[MAXSLOTS][DIM]; /* the tangential part of cc: friction's */
  double cq[MAXSLOTS][DIM]; /* the cohesive law's (cohere()) */
  double sb[DIM] = {0}, sc[DIM] = {0}, st[DIM] = {0}, sq[DIM] = {0}, vref[DIM];
  double M = g->m[n], fric = 0, imp = 0, bnd = 0, coh = 0, cn[DIM];
  int32_t sl, slots[MAXSLOTS], drv = -1;
  int ns = 0, k, d, bonds = s->fbond >= 0, cuts = 0, cohesive = s->fcoh >= 0;
  if (rec) wk->cbody[k0] = -1;
  if (M <= s->mcut) return;
  if (sim_body_patches(s) && wk->cplab && wk->cplab[n] >= 0) {
    booked(s, k0, 0, 0, 0, 0, 0, rec); /* contact_patch.c's */
    return;
  }
  /* a field whose slot holds no mass (the edge of its particles'
  ** supports, where the weights vanish but their gradients need not, so
  ** its normal and reach say nothing) is no partner: a drive there would
  ** stop a body sliding past a cell away (measured: a disc sliding
  ** frictionless above a driven slab lost 4 % of its speed before it
  ** touched, GIMP, 8 cells) */
  for (sl = g->head[n]; sl >= 0 && ns < MAXSLOTS; sl = g->snext[sl]) {
    slots[ns++] = sl;
    if (s->fdriven[g->sfield[sl]] >= 0 && drv < 0 && g->sm[sl] > s->mcut) drv = sl;
  }
  if (drv >= 0) {
    const body *b = &s->bodies[s->fdriven[g->sfield[drv]]];
    for (d = 0; d < DIM; d++) vref[d] = b->vdrive[d];
  } else
    for (d = 0; d < DIM; d++) vref[d] = mom[d][n] / M;
  for (k = 0; k < ns; k++) {
    double dp[DIM], t[DIM], dn = 0, tt = 0, mr, mu, other = -1e300, mo = -1, fn;
    double gap;
    int32_t o = -1;
    int j;
    sl = slots[k];
    mr = g->sm[sl];
    for (d = 0; d < DIM; d++)
      cb[k][d] = cc[k][d] = ct[k][d] = cq[k][d] = 0;
    if (sl == drv || s->fdriven[g->sfield[sl]] >= 0 || mr <= s->mcut) continue;
    for (d = 0; d < DIM; d++) {
      dp[d] = smom[d][sl] - mr * vref[d];
      dn += dp[d] * g->sn[d][sl];
    }
    /* the partner: the driven body, else the heaviest other field here;
    ** the largest reach of the others, for the separation check */
    for (j = 0; j < ns; j++) {
      int32_t q = slots[j];
      if (q == sl || !(g->sm[q] > s->mcut)) continue;
      if (g->sext[q] > other) other = g->sext[q];
      if (g->sm[q] > mo) { mo = g->sm[q]; o = q; }
    }
    if (drv >= 0) o = drv;
    if (o < 0) continue; /* no partner with mass */
    if (bonds) {
      int b = bonded(s, n, sl, o, drv >= 0);
      cuts += b < 0;
      if (b > 0) {
        /* the fields' nodal velocities differ by how their particles
        ** sample the motion; making them one is an inelastic collision
        ** of the fields at the node, whose loss is booked as a contact
        ** impulse's (contact_lose(), e.bonding).  The slot's internal force
        ** impulse, dt f less gravity's, is kept for the work the
        ** stresses do on the common velocity (bond_remap) */
        for (d = 0; d < DIM; d++) {
          cb[k][d] = -dp[d];
          sb[d] += cb[k][d];
          g->sbf[d][sl] = smom[d][sl] - g->sp[d][sl] -
                          mr * cfg->gravity[d] * s->dt;
        }
        g->sbonded[sl] = 1;
        continue;
      }
    }
    if (cohesive) {
      double J = cohere(s, sl, o, dn);
      for (d = 0; d < DIM; d++) {
        cq[k][d] = J * g->sn[d][sl];
        sq[d] += cq[k][d];
      }
    }
    if (!(dn > 0)) continue;
    /* a drive stops a round body only where the drive's material is, as
    ** a wall acts on its line and beyond: past DRIVE_REACH cells it holds
    ** a sliver of its particles' stencils, and its velocity imposed there
    ** stopped the round body's interior a cell inside (a disc on driven
    ** bodies for walls lost 6 % more per impact at 8 cells than on the
    ** grid's walls; with the rule the first impact loses the same where
    ** the driven faces lie on node lines).  A flat body keeps every node:
    ** with the rule a block sliding on a driven slab, aligned or tilted,
    ** tipped and slowed (15 % along the grid at 8 cells, normals "mass"
    ** with one normal per patch), its face's corners a cell above the
    ** slab no longer held */
    if (o == drv && sim_drive_far(s, g->sfield[sl], drv)) continue;
    fn = 1;
    if (cfg->release == RELEASE_OPEN && opening(s, sl, o, &gap)) {
      fn = closing(s, sl, o, o == drv, vref, smom, dn, gap);
      if (!(fn > 0)) continue;
    } else if (cfg->gap_check) {
      gap = -(g->sext[sl] + other);
      if (cfg->gap_step) {
        fn = closing(s, sl, o, o == drv, vref, smom, dn, gap);
        if (!(fn > 0)) continue;
      } else if (gap > 0)
        continue;
    }
    mu = sim_law(s, g->sfield[sl], g->sfield[o]);
    for (d = 0; d < DIM; d++) {
      t[d] = dp[d] - dn * g->sn[d][sl];
      tt += t[d] * t[d];
      cc[k][d] = -fn * dn * g->sn[d][sl];
    }
    dn *= fn;
    tt = sqrt(tt);
    if (tt > mu * dn) { /* slides: friction mu dn against the slip */
      double r = mu * dn / tt;
      for (d = 0; d < DIM; d++) ct[k][d] = -r * t[d];
    } else /* sticks */
      for (d = 0; d < DIM; d++) ct[k][d] = -t[d];
    for (d = 0; d < DIM; d++) {
      cc[k][d] += ct[k][d];
      sc[d] += cc[k][d];
      st[d] += ct[k][d];
    }
  }
  if (drv >= 0) { /* the driven body keeps its velocity and does work */
    int32_t bi = s->fdriven[g->sfield[drv]];
    double cd[DIM], w = 0, *F = s->bodies[bi].force;
    for (d = 0; d < DIM; d++) {
      double sum = sb[d] + sc[d];
      cd[d] = g->sm[drv] * vref[d] - smom[d][drv];
      smom[d][drv] += cd[d];
      mom[d][n] += cd[d];
      w += (cd[d] + sum) * vref[d];
      if (!rec) F[d] += sum / s->dt;
    }
    if (rec) {
      double *r = wk->crec + CREC * k0;
      wk->cbody[k0] = bi;
      for (d = 0; d < DIM; d++) r[d] = (sb[d] + sc[d]) / s->dt;
      r[DIM] = w;
    } else
      s->e.boundary += w;
    for (k = 0; k < ns; k++) {
      sl = slots[k];
      for (d = 0; d < DIM; d++) {
        double c = cb[k][d] + cc[k][d];
        smom[d][sl] += c;
        mom[d][n] += c;
        cn[d] = cc[k][d] - ct[k][d];
      }
      fric += contact_lose(g, sl, vref, ct[k], g->sfi);
      imp += contact_lose(g, sl, vref, cn, g->sni);
      if (bonds) bnd += contact_lose(g, sl, vref, cb[k], g->sbi);
    }
    booked(s, k0, fric, cuts, imp, bnd, 0, rec);
    if (s->heat) heat_contact(s, slots, ns, drv, fric);
    return;
  }
  /* momentum-conserving: remove the residual in proportion to mass */
  for (k = 0; k < ns; k++) {
    double f = g->sm[slots[k]] / M;
    sl = slots[k];
    for (d = 0; d < DIM; d++) {
      double b = cb[k][d] - f * sb[d], c = cc[k][d] - f * sc[d];
      smom[d][sl] += b + c;
      ct[k][d] -= f * st[d];
      cn[d] = c - ct[k][d];
      cb[k][d] = b;
    }
    fric += contact_lose(g, sl, vref, ct[k], g->sfi);
    imp += contact_lose(g, sl, vref, cn, g->sni);
    if (bonds) bnd += contact_lose(g, sl, vref, cb[k], g->sbi);
    if (cohesive) {
      for (d = 0; d < DIM; d++) {
        cq[k][d] -= f * sq[d];
        smom[d][sl] += cq[k][d];
      }
      coh += contact_lose(g, sl, vref, cq[k], g->sci);
    }
  }
  booked(s, k0, fric, cuts, imp, bnd, coh, rec);
  if (s->heat) heat_contact(s, slots, ns, -1, fric);
}

/* Room for the records of a threaded pass, one per slot and per shared
** node, grown (doubling) with the grid's own arrays, so a step does not
** allocate unless the grid did; 0 or -1 (out of memory) */
static int grow(void **p, size_t *cap, size_t need, size_t size) {
  size_t c = *cap ? *cap : 256;
  void *q;
  if (need <= *cap) return 0;
  while (c < need) c *= 2;
  if (!(q = realloc(*p, c * size))) return -1;
  *p = q;
  *cap = c;
  return 0;
}

/* contact's records, and the slots of the particles' stencils p2g finds
** (sim.h, room made by p2g_mark) */
size_t contact_mem(const sim *s) {
  const sim_work *wk = &s->work;
  return wk->pslotcap * sizeof *wk->pslot +
         wk->cnodecap * (CREC * sizeof *wk->crec + sizeof *wk->cbody) +
         wk->cplistcap * sizeof *wk->cplist + (wk->cplab ? s->g.nnodes * sizeof *wk->cplab : 0);
}

int contact_prepare(sim *s) {
  sim_work *wk = &s->work;
  const grid *g = &s->g;
  size_t nc = wk->cnodecap;
  if (grow((void **)&wk->crec, &nc, g->nshared, CREC * sizeof *wk->crec) ||
      grow((void **)&wk->cbody, &wk->cnodecap, g->nshared, sizeof *wk->cbody))
    return -1;
  if (sim_body_patches(s) || s->cfg.normal_patch || sim_flat_patches(s)) {
    /* contact_patch.c: a label per node, -1 between steps, and a list */
    if (!wk->cplab) {
      size_t i;
      if (!(wk->cplab = malloc(g->nnodes * sizeof *wk->cplab))) return -1;
      for (i = 0; i < g->nnodes; i++) wk->cplab[i] = -1;
    }
    if (grow((void **)&wk->cplist, &wk->cplistcap, g->nshared, sizeof *wk->cplist))
      return -1;
  }
  return 0;
}
static void apply_part(void *arg, int t, int nparts) {
  sim *s = arg;
  size_t k, k0, k1;
  par_range(s->g.nshared, t, nparts, &k0, &k1);
  for (k = k0; k < k1; k++) node(s, k, s->g.q, s->g.sq, 1);
}

/* The records of apply_part added up node by node as the sequential
** pass adds them: the sums are the same bits for any count of threads,
** and the same as with none */
static void apply_sums(sim *s) {
  sim_work *wk = &s->work;
  const grid *g = &s->g;
  size_t k;
  for (k = 0; k < g->nshared; k++) {
    const double *r = wk->crec + CREC * k;
    int d;
    if (g->m[g->shared[k]] <= s->mcut) continue;
    s->e.friction += r[DIM + 1];
    s->ncut += (size_t)r[DIM + 2];
    s->e.impact += r[DIM + 3];
    s->e.bonding += r[DIM + 4];
    s->e.cohesion += r[DIM + 5];
    if (wk->cbody[k] >= 0) {
      double *F = s->bodies[wk->cbody[k]].force;
      for (d = 0; d < DIM; d++) F[d] += r[d];
      s->e.boundary += r[DIM];
    }
  }
}

/* After a pass with bonds, node by node and slot by slot in list order:
** the bonded area (each interface counted once: half of each side's),
** and the strengths cut in the pass cleared (see left()) */
static void bond_sums(sim *s) {
  grid *g = &s->g;
  size_t k;
  for (k = 0; k < g->nshared; k++) {
    int32_t sl;
    for (sl = g->head[g->shared[k]]; sl >= 0; sl = g->snext[sl]) {
      if (g->sbonded[sl]) s->bond_area += 0.5 * area(g, sl);
      if (g->scut[sl] > 0) g->sb[sl] = 0;
    }
  }
}

/* Each node's correction writes only its own node and slots, and reads
** other nodes only for the bond traction, which takes their strengths
** as the pass began (left()): the nodes are cut among the threads.  A
** call without contact_prepare's room takes them in order, with the
** same numbers. */
void contact_apply(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  grid *g = &s->g;
  size_t k;
  s->ncut = 0;
  s->bond_area = 0;
  if (s->fbond >= 0 && cfg->bond_fit) par_run(wk->par, fits_part, s);
  /* the patches first (contact_patch.c; their room is contact_prepare's) */
  if (sim_body_patches(s) && wk->cplab) contact_patches(s, 0);
  if (wk->cnodecap >= g->nshared) {
    par_run(wk->par, apply_part, s);
    apply_sums(s);
  } else
    for (k = 0; k < g->nshared; k++) node(s, k, g->q, g->sq, 0);
  if (s->fbond >= 0) bond_sums(s);
  if (sim_body_patches(s) && wk->cplab)
    for (k = 0; k < g->nshared; k++) wk->cplab[g->shared[k]] = -1;
}
