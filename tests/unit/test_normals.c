/*
** test_normals.c - contact normals (contact.c) on hand-made shared nodes,
** in whichever dimension the build has.
**   The window: every slot's normal from the sums over the shared nodes
**   within R cells, against the same sums taken by brute force over all
**   nodes (Chebyshev distance, wrapped across a periodic side), for
**   "volume" and "maxvolume".
**   The plane: two bodies of particles on the seeding lattice meeting on
**   a tilted plane; the fitted normal against the plane's, and the
**   partner's normal its exact negative.
*/
#include <stdlib.h>
#include <string.h>
#include "sim.h"
#include "unit.h"

static void link_slot(grid *g, int32_t n, int32_t f, size_t *nsl) {
  size_t s = (*nsl)++;
  g->sfield[s] = f;
  g->snode[s] = n;
  g->snext[s] = g->head[n];
  g->head[n] = (int32_t)s;
  g->sm[s] = 1;
}

/* a smooth, irregular value per field, component and node */
static double val(int f, int d, const int *i) {
  double a = f + 0.5 * d;
  int e;
  for (e = 0; e < DIM; e++) a += (1.3 + 0.7 * e * (d + 1)) * i[e] + 0.11 * e * i[e] * i[e];
  return sin(a);
}

static void window_case(int maxv) {
  sim s;
  grid *g = &s.g;
  double lo[DIM], hi[DIM];
  int per[DIM], R, d;
  for (d = 0; d < DIM; d++) {
    lo[d] = 0;
    hi[d] = 10 - d;
    per[d] = d == 1; /* y periodic */
  }
  for (R = 0; R <= 2; R++) {
    size_t n, k, ns = 0, nsl = 0;
    double worst = 0;
    memset(&s, 0, sizeof s);
    grid_init(g, lo, hi, 1.0, per, 1);
    grid_slots_reserve(g, 2 * g->nnodes, g->nnodes);
    for (n = 0; n < g->nnodes; n++) g->head[n] = -1;
    /* shared where the index sum is not a multiple of 3; field 1 left
    ** out at some of them */
    for (n = 0; n < g->nnodes; n++) {
      int i[DIM], sum = 0, f;
      grid_ijk(g, (int32_t)n, i);
      for (d = 0; d < DIM; d++) sum += (d + 1) * i[d];
      if (sum % 3 == 0) continue;
      g->shared[ns++] = (int32_t)n;
      for (f = 1; f >= 0; f--) {
        if (f == 1 && (i[0] * i[DIM - 1]) % 5 == 1) continue;
        link_slot(g, (int32_t)n, f, &nsl);
        for (d = 0; d < DIM; d++) g->sv[d][nsl - 1] = val(f, d, i);
      }
    }
    g->nshared = ns;
    g->nslot = nsl;
    s.cfg.normals = maxv ? NORMALS_MAXVOLUME : NORMALS_VOLUME;
    s.cfg.normal_window = R;
    contact_normals(&s);
    for (k = 0; k < ns; k++) {
      int32_t nd = g->shared[k], sl;
      int c[DIM];
      grid_ijk(g, nd, c);
      for (sl = g->head[nd]; sl >= 0; sl = g->snext[sl]) {
        double own[DIM] = {0}, rest[DIM] = {0}, v[DIM], l = 0, lo2 = 0, lr2 = 0;
        size_t j;
        for (j = 0; j < g->nnodes; j++) {
          int i[DIM], in = 1, has = 0;
          int32_t q;
          grid_ijk(g, (int32_t)j, i);
          for (d = 0; d < DIM; d++) {
            int dd = abs(i[d] - c[d]);
            if (per[d] && g->n[d] - dd < dd) dd = g->n[d] - dd;
            in = in && dd <= R;
          }
          if (!in || g->head[j] < 0) continue;
          for (q = g->head[j]; q >= 0; q = g->snext[q]) has |= g->sfield[q] == g->sfield[sl];
          if (!has) continue;
          for (q = g->head[j]; q >= 0; q = g->snext[q])
            for (d = 0; d < DIM; d++) {
              if (g->sfield[q] == g->sfield[sl]) own[d] += g->sv[d][q];
              else rest[d] += g->sv[d][q];
            }
        }
        for (d = 0; d < DIM; d++) {
          v[d] = own[d] - rest[d];
          l += v[d] * v[d];
          lo2 += own[d] * own[d];
          lr2 += rest[d] * rest[d];
        }
        if (maxv && lo2 != lr2) {
          for (d = 0; d < DIM; d++) v[d] = lo2 > lr2 ? own[d] : -rest[d];
          l = lo2 > lr2 ? lo2 : lr2;
        }
        l = sqrt(l);
        for (d = 0; d < DIM; d++) {
          double e = fabs((l > 0 ? v[d] / l : 0) - g->sn[d][sl]);
          if (e > worst) worst = e;
        }
      }
    }
    UNIT_NEAR(worst, 0, 1e-12, maxv ? "maxvolume window: |n - brute force|"
                                     : "volume window: |n - brute force|");
    grid_free(g);
  }
}

/* two bodies on the lattice of 2 particles per cell and direction,
** meeting on the plane through c with normal nv; linear hats */
static double plane_case(int R, double tol) {
  sim s;
  grid *g = &s.g;
  const double raw[3] = {0.37, 0.81, 0.45};
  double lo[DIM], hi[DIM], nv[DIM], c0[DIM], worst = 0, anti = 0;
  int per[DIM] = {0}, d, e, p[DIM], cnt = 0;
  size_t n, nsl = 0, ns = 0;
  const double V = pow(0.5, DIM);
  for (d = 0; d < DIM; d++) {
    lo[d] = 0;
    hi[d] = 12;
    nv[d] = raw[d];
    c0[d] = 6.05 + 0.05 * d;
  }
  vec_unit(nv);
  memset(&s, 0, sizeof s);
  grid_init(g, lo, hi, 1.0, per, 1);
  g->moments = 1;
  grid_slots_reserve(g, 2 * g->nnodes, g->nnodes);
  for (n = 0; n < g->nnodes; n++) {
    g->head[n] = -1;
    link_slot(g, (int32_t)n, 1, &nsl);
    link_slot(g, (int32_t)n, 0, &nsl);
  }
  g->nslot = nsl;
  grid_slots_clear(g, 0, nsl);
  for (d = 0; d < DIM; d++) p[d] = 0;
  for (;;) {
    double x[DIM], sd = 0;
    int base[DIM], f, corner;
    for (d = 0; d < DIM; d++) {
      x[d] = 0.25 + 0.5 * p[d];
      base[d] = (int)floor(x[d]);
      sd += (x[d] - c0[d]) * nv[d];
    }
    f = sd < 0 ? 0 : 1;
    for (corner = 0; corner < 1 << DIM; corner++) {
      int id[DIM];
      double w = V, r[DIM];
      int32_t sl;
      for (d = 0; d < DIM; d++) {
        int o = (corner >> d) & 1;
        double t = x[d] - base[d];
        id[d] = base[d] + o + g->pad;
        w *= o ? t : 1 - t;
      }
      sl = grid_slot(g, grid_node(g, id), f);
      for (d = 0; d < DIM; d++) r[d] = grid_x(g, d, id[d]) - x[d];
      g->sw[sl] += w;
      for (d = 0; d < DIM; d++) {
        g->sx[d][sl] += w * r[d];
        for (e = d; e < DIM; e++) g->sxx[grid_sym(d, e)][sl] += w * r[d] * r[e];
      }
    }
    for (d = 0; d < DIM && ++p[d] >= 24; d++) p[d] = 0;
    if (d == DIM) break;
  }
  for (n = 0; n < g->nnodes; n++) {
    if (g->sw[grid_slot(g, (int32_t)n, 0)] > 0 && g->sw[grid_slot(g, (int32_t)n, 1)] > 0)
      g->shared[ns++] = (int32_t)n;
    else
      g->head[n] = -1;
  }
  g->nshared = ns;
  s.cfg.normals = NORMALS_PLANE;
  s.cfg.normal_window = R;
  contact_normals(&s);
  for (n = 0; n < ns; n++) {
    int32_t nd = g->shared[n], s0 = grid_slot(g, nd, 0), s1 = grid_slot(g, nd, 1);
    int id[DIM], inner = 1;
    double dot = 0;
    grid_ijk(g, nd, id);
    /* away from the domain's sides, where the lattice ends */
    for (d = 0; d < DIM; d++) inner = inner && id[d] >= 3 + R && id[d] <= g->n[d] - 4 - R;
    if (!inner) continue;
    cnt++;
    for (d = 0; d < DIM; d++) {
      dot += g->sn[d][s0] * nv[d];
      if (fabs(g->sn[d][s0] + g->sn[d][s1]) > anti) anti = fabs(g->sn[d][s0] + g->sn[d][s1]);
    }
    if (acos(fmin(1, dot)) * 180 / M_PI > worst) worst = acos(fmin(1, dot)) * 180 / M_PI;
  }
  UNIT_CHECK(cnt > 10, "plane: %d interface nodes inside", cnt);
  UNIT_NEAR(worst, 0, tol, R ? "plane over a window of 2: worst angle (deg)"
                             : "plane, node alone: worst angle (deg)");
  UNIT_NEAR(anti, 0, 1e-14, "plane: |n_A + n_B|");
  grid_free(g);
  return worst;
}

int main(void) {
  window_case(0);
  window_case(1);
  /* node by node the staircase turns the plane by up to 20 degrees
  ** (measured 20.4 in 2-D, 19.4 in 3-D); the window must take most of
  ** that away (1.57 and 0.93) */
  {
    double w0 = plane_case(0, 25), w2 = plane_case(2, 2);
    UNIT_CHECK(w2 < 0.15 * w0, "plane: the window's worst angle %.3g below "
               "0.15 of the node's own %.3g", w2, w0);
  }
  UNIT_END("test_normals");
}
