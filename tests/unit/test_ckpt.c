/*
** test_ckpt.c - a checkpoint of the simulation's state written and read
** by the io layer alone (io/ckpt.h): this file is compiled with the core's
** and io's include paths only, no Lua.  Two discs meet under a contact
** law; the run is checkpointed half way, a fresh simulation set up the
** same way restores it, and both go on: every particle number and every
** energy must agree bit for bit.  A file of another scene is refused by
** name.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "ckpt.h"
#include "sim.h"
#include "unit.h"

/* two discs of one material moving at each other, on two fields */
static void scene(sim *s, int nbody) {
  double lo[2] = {0, 0}, hi[2] = {2, 1}, c[2][2] = {{0.72, 0.42}, {1.28, 0.58}};
  int per[2] = {0, 0}, b, i, j;
  material m;
  sim_init(s, lo, hi, 0.05, per, SHAPE_GIMP, 2);
  s->t_end = 1;
  material_init(&m, &mat_elastic, "m", 1, 100, 40);
  sim_add_material(s, &m);
  for (b = 0; b < nbody; b++) {
    sim_add_body(s, b ? "right" : "left", 0, -1);
    for (i = 0; i < 40; i++)
      for (j = 0; j < 40; j++) {
        double x[2] = {c[b][0] - 0.5 + (i + 0.5) * 0.025,
                       c[b][1] - 0.5 + (j + 0.5) * 0.025};
        double v[2] = {b ? -1 : 1, 0};
        if (hypot(x[0] - c[b][0], x[1] - c[b][1]) < 0.25)
          sim_add_particle(s, b, x, v, 0.025 * 0.025);
      }
  }
  if (nbody > 1) sim_set_law(s, 0, 1, 0.3, 0);
}

static int steps(sim *s, int n) {
  int k;
  for (k = 0; k < n; k++)
    if (sim_step(s)) return -1;
  return 0;
}

/* the particles' arrays and the energies, compared as bits */
static int same(const sim *a, const sim *b) {
  int k, c;
  if (a->ps.n != b->ps.n || a->step != b->step ||
      memcmp(&a->t, &b->t, sizeof a->t) || memcmp(&a->e, &b->e, sizeof a->e))
    return 0;
  for (k = 0; k < a->ps.nfields; k++) {
    const pfield *f = &a->ps.fields[k];
    size_t esz = f->type == PF_INT32 ? 4 : 8;
    for (c = 0; c < f->ncomp; c++)
      if (memcmp(particles_comp(&a->ps, k, c), particles_comp(&b->ps, k, c),
                 a->ps.n * esz))
        return 0;
  }
  return 1;
}

int main(void) {
  sim a, b, other;
  ckpt c;
  h5blob blob[CB_N];
  h5meta meta;
  h5prov prov;
  char dir[] = "/tmp/mvmpm_ckpt_XXXXXX", path[1100], err[1024];
  int k, r;
  if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
  ckpt_name(path, sizeof path, dir, 1);
  scene(&a, 2);
  UNIT_CHECK(steps(&a, 40) == 0, "first 40 steps: %s", a.err);
  memset(blob, 0, sizeof blob);
  for (k = CB_SNAPF; k <= CB_STATE; k++) blob[k].type = H5B_U8;
  blob[CB_SNAPT].type = H5B_F64;
  blob[CB_SNAPN].type = H5B_I64;
  blob[CB_SNAPF].name = "snap_files";
  blob[CB_SNAPT].name = "snap_time";
  blob[CB_SNAPN].name = "snap_n";
  blob[CB_PARAMS].name = "params";
  blob[CB_SCENE].name = "scene";
  blob[CB_SOURCE].name = "source";
  blob[CB_STATE].name = "lua_state";
  memset(&meta, 0, sizeof meta);
  meta.units = "nondimensional";
  meta.scene = "test_ckpt.c";
  memset(&prov, 0, sizeof prov);
  r = ckpt_save(path, &a, NULL, blob, &meta, &prov, 0, err, sizeof err);
  UNIT_CHECK(r == 0, "ckpt_save: %s", err);
  UNIT_CHECK(steps(&a, 60) == 0, "60 steps more: %s", a.err);

  r = ckpt_read(&c, path, err, sizeof err);
  UNIT_CHECK(r == 0, "ckpt_read: %s", err);
  scene(&b, 2);
  r = r ? r : ckpt_restore(&b, &c, NULL, err, sizeof err);
  UNIT_CHECK(r == 0, "ckpt_restore: %s", err);
  UNIT_CHECK(b.step == 40 && b.nlaw == 1 && b.laws[0].mu == 0.3,
             "restored: step %ld, %d laws", b.step, b.nlaw);
  UNIT_CHECK(steps(&b, 60) == 0, "60 steps after the restore: %s", b.err);
  printf("restored run after 100 steps: t = %.17g, kinetic %.17g, friction "
         "work %.17g\n", b.t, b.e.kinetic, b.e.friction);
  UNIT_CHECK(b.e.friction > 0, "the discs met and slid (friction work %g)",
             b.e.friction);
  UNIT_CHECK(same(&a, &b), "the restored run continues bit for bit");

  /* a scene with one body is not the scene of this checkpoint */
  scene(&other, 1);
  r = ckpt_restore(&other, &c, NULL, err, sizeof err);
  printf("%s\n", err);
  UNIT_CHECK(r != 0 && strstr(err, "bodies"), "another scene refused by "
             "name: %s", err);
  ckpt_free(&c);
  sim_free(&a);
  sim_free(&b);
  sim_free(&other);
  remove(path);
  rmdir(dir);
  UNIT_END("test_ckpt");
}
