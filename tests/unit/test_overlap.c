/*
** test_overlap.c - the interpenetration diagnostic (diag_overlap.c) on
** hand-made particle sets whose answer is known by construction.
*/
#include "diag_overlap.h"
#include "shape.h"
#include "unit.h"

/* a 16 x 16 cell domain of cell 1, 2 x 2 particles per cell */
static void domain(sim *s, int periodic_y) {
  double lo[2] = {0, 0}, hi[2] = {16, 16};
  int per[2] = {0, periodic_y};
  material m;
  sim_init(s, lo, hi, 1.0, per, SHAPE_LINEAR, 2);
  material_init(&m, &mat_elastic, "m", 1, 1, 0.5);
  sim_add_material(s, &m);
  sim_add_body(s, "a", 0, -1);
  sim_add_body(s, "b", 0, -1);
}

/* fill cells [i0, i1) x [j0, j1) (wrapped in y) with body b */
static void fill(sim *s, int b, int i0, int i1, int j0, int j1) {
  int i, j, a, c;
  for (i = i0; i < i1; i++)
    for (j = j0; j < j1; j++)
      for (a = 0; a < 2; a++)
        for (c = 0; c < 2; c++) {
          double x[2] = {i + 0.25 + 0.5 * a, ((j % 16) + 16) % 16 + 0.25 + 0.5 * c};
          double v[2] = {0, 0};
          sim_add_particle(s, b, x, v, 0.25);
        }
}

static void one(sim *s, int b, double x, double y) {
  double p[2] = {x, y}, v[2] = {0, 0};
  sim_add_particle(s, b, p, v, 0.25);
}

int main(void) {
  sim s;
  overlap_info o;

  /* two blocks side by side: touching, nothing buried */
  domain(&s, 0);
  fill(&s, 0, 2, 8, 2, 10);
  fill(&s, 1, 8, 14, 2, 10);
  UNIT_CHECK(diag_overlap(&s, 8, &o) == 0, "runs");
  UNIT_NEAR((double)o.n, 0, 0, "blocks side by side: particles buried");
  UNIT_NEAR(o.depth, 0, 0, "blocks side by side: depth");
  /* a particle of b just inside a's surface (its cell a's, a neighbour
  ** cell b's): contact, not burial */
  one(&s, 1, 7.6, 5.5);
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 0, 0, "particle in a's surface cell: buried");
  sim_free(&s);

  /* a particle of b at the centre of a 7 x 7 block of a: buried 3 cells */
  domain(&s, 0);
  fill(&s, 0, 4, 11, 4, 11);
  one(&s, 1, 7.5, 7.5);
  one(&s, 1, 5.5, 7.5);   /* one cell inside the block's edge: depth 1 */
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 2, 0, "particles of b inside a's block");
  UNIT_NEAR(o.depth, 3, 0, "deepest: centre of a 7 x 7 block");
  UNIT_CHECK(o.body == 1 && o.host == 0, "deepest is b's, inside a (%d in %d)",
             (int)o.body, (int)o.host);
  diag_overlap(&s, 2, &o);
  UNIT_NEAR(o.depth, 2, 0, "depth sought only to maxdepth");
  sim_free(&s);

  /* a cell shared 2 : 2 is held by neither body, so a's particle there
  ** is not counted even though b holds every neighbour */
  domain(&s, 0);
  fill(&s, 1, 3, 12, 3, 12);
  {
    size_t i;   /* give two of b's particles in cell (7, 7) to a */
    int k = 0;
    for (i = 0; i < s.ps.n && k < 2; i++)
      if ((int)s.ps.x[0][i] == 7 && (int)s.ps.x[1][i] == 7) { s.ps.body[i] = 0; k++; }
  }
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 0, 0, "tied cell: no holder, nothing buried");
  sim_free(&s);

  /* across a periodic side: a block spanning the seam buries a particle
  ** that sits next to the seam; without periodicity it is not buried */
  domain(&s, 1);
  fill(&s, 0, 5, 12, -3, 4);
  one(&s, 1, 8.5, 0.5);
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 1, 0, "periodic: buried across the seam");
  UNIT_NEAR(o.depth, 3, 0, "periodic: depth across the seam");
  sim_free(&s);
  domain(&s, 0);
  fill(&s, 0, 5, 12, 0, 4);
  one(&s, 1, 8.5, 0.5);
  diag_overlap(&s, 8, &o);
  UNIT_NEAR((double)o.n, 0, 0, "wall side: the cells beyond it hold nothing");
  sim_free(&s);
  UNIT_END("test_overlap");
}
