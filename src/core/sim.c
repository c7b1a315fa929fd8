/*
** sim.c - the simulation object, set-up, and the step as a sequence of
** phases (each phase lives in the file named after it).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "heat.h"
#include "prof.h"
#include "react.h"
#include "shape.h"
#include "sim.h"
#include "vec.h"
#include "thermal.h"

int sim_init(sim *s, const double lo[DIM], const double hi[DIM], double h,
             const int periodic[DIM], int shape, int ppc) {
  int k, d;
  size_t most = 0;
  memset(s, 0, sizeof *s);
  s->cfg.shape = shape;
  s->cfg.update = UPDATE_MUSL;
  s->cfg.flip = 1.0;
  s->cfg.xpic = 2;
  s->cfg.cfl = 0.25;
  s->t_end = 1.0;
  s->cfg.gap_check = 1;
  s->cfg.normals = NORMALS_AUTO;
  s->cfg.body_rule = BODY_AUTO;
  s->cfg.normal_window = 0;
  s->cfg.normal_patch = 0;
  s->cfg.bond_default = INFINITY;
  s->faff = -1;
  s->t_stop = INFINITY;
  s->fbond = -1;
  s->frel = -1;
  s->fcoh = -1;
  s->fopen = -1;
  s->cfg.mcut_rel = 1e-9;
  s->cfg.wall_stiffness = 2;
  s->cfg.wall_band = 2;
  s->cfg.sort_every = 20;
  s->cfg.ppc = ppc;
  s->cfg.lp = 0.5 / ppc;
  s->ftemp = -1;
  s->freact = -1;
  s->fmelt = -1;
  s->cfg.react_tol = REACT_TOL;
  s->cfg.react_ign = 0.5;
  s->t_ignition = INFINITY;
  s->cfg.threads = 1;
  particles_init(&s->ps);
  if (grid_init(&s->g, lo, hi, h, periodic, shape_pad(shape)) ||
      bands_init(&s->work.bands, s->g.n[BANDS_DIM])) {
    snprintf(s->err, sizeof s->err, "out of memory for the grid");
    return -1;
  }
  for (k = 0; k < NSIDES; k++) {
    d = k / 2;
    s->sides[k].kind = periodic[d] ? SIDE_PERIODIC : SIDE_WALL;
    s->sides[k].next = grid_face_count(&s->g, d);
    if (s->sides[k].next > most) most = s->sides[k].next;
    s->sides[k].ext = malloc(s->sides[k].next * sizeof(double));
    s->sides[k].ext2 = malloc(s->sides[k].next * sizeof(double));
    s->sides[k].efld = malloc(s->sides[k].next * sizeof(int32_t));
    /* the wall plane and the ghost planes beyond it */
    s->sides[k].acted = calloc((size_t)(s->g.pad + 1) * s->sides[k].next, 1);
    s->sides[k].hm = calloc((size_t)(s->g.pad + 2) * s->sides[k].next, sizeof(double));
    s->sides[k].dl = calloc(s->sides[k].next, sizeof(double));
    s->sides[k].ph = calloc(s->sides[k].next * DIM, sizeof(double));
    s->sides[k].son = calloc(s->sides[k].next, 1);
    if (!s->sides[k].ext || !s->sides[k].ext2 || !s->sides[k].efld ||
        !s->sides[k].acted || !s->sides[k].hm ||
        !s->sides[k].dl || !s->sides[k].ph || !s->sides[k].son)
      return -1;
  }
  s->work.wpatch = malloc((4 * most + 1) * sizeof *s->work.wpatch);
  s->work.wcarry = malloc(WSPRING_W * most * sizeof *s->work.wcarry);
  if (!s->work.wpatch || !s->work.wcarry) return -1;
  return 0;
}

void sim_free(sim *s) {
  int k;
  grid_free(&s->g);
  particles_free(&s->ps);
  for (k = 0; k < NSIDES; k++) {
    free(s->sides[k].ext);
    free(s->sides[k].ext2);
    free(s->sides[k].efld);
    free(s->sides[k].acted);
    free(s->sides[k].dl);
    free(s->sides[k].ph);
    free(s->sides[k].son);
    free(s->sides[k].hm);
  }
  free(s->mats);
  free(s->bodies);
  free(s->bmat);
  free(s->fdriven);
  free(s->fflat);
  free(s->laws);
  free(s->flaw);
  par_free(s->work.par);
  bands_free(&s->work.bands);
  marks_free(&s->work.marks);
  free(s->work.red);
  free(s->work.wext);
  free(s->work.wefld);
  free(s->work.pflag);
  free(s->work.wpatch);
  free(s->work.wcarry);
  free(s->work.crec);
  free(s->work.cbody);
  free(s->work.cplab);
  free(s->work.cplist);
  free(s->work.bfit);
  free(s->work.bffield);
  free(s->work.pslot);
  free(s->work.prof);
  heat_free(s);
  memset(s, 0, sizeof *s);
}

void sim_set_threads(sim *s, int n) {
  if (n < 1) n = 1;
  if (n > PAR_MAX) n = PAR_MAX;
  if (n == s->cfg.threads && s->work.par) return;
  par_free(s->work.par);
  s->work.par = NULL;
  free(s->work.wext); /* sized by the thread count */
  free(s->work.wefld);
  s->work.wext = NULL;
  s->work.wefld = NULL;
  s->cfg.threads = n;
}

/* the pool, and room for the partial sums of every chunk of particles:
** made at the first step and grown (doubling) only if particles were
** added since, so steps do not allocate */
int sim_prepare(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  size_t need = par_nchunks(s->ps.n) * SIM_RED_BYTES;
  if (!wk->par && !(wk->par = par_new(cfg->threads))) {
    snprintf(s->err, sizeof s->err, "cannot start %d threads", cfg->threads);
    return -1;
  }
  if (!wk->pflag && cfg->wall_rule == WALL_PENALTY) {
    if (!(wk->pflag = calloc(s->g.nnodes, 1))) {
      snprintf(s->err, sizeof s->err, "out of memory for the penalty walls");
      return -1;
    }
  }
  if ((!wk->wext || !wk->wefld) && par_threads(wk->par) > 1) { /* reach.c */
    int k;
    free(wk->wext);
    free(wk->wefld);
    wk->wextn = 0;
    for (k = 0; k < NSIDES; k++) wk->wextn += s->sides[k].next;
    wk->wext = malloc((size_t)(par_threads(wk->par) - 1) * 2 * wk->wextn *
                     sizeof *wk->wext);
    wk->wefld = malloc((size_t)(par_threads(wk->par) - 1) * wk->wextn *
                       sizeof *wk->wefld);
    if (!wk->wext || !wk->wefld) {
      snprintf(s->err, sizeof s->err, "out of memory for partial sums");
      return -1;
    }
  }
  if (need > wk->redcap) {
    size_t cap = wk->redcap ? 2 * wk->redcap : SIM_RED_BYTES * 64;
    void *r;
    while (cap < need) cap *= 2;
    if (!(r = realloc(wk->red, cap))) {
      snprintf(s->err, sizeof s->err, "out of memory for partial sums");
      return -1;
    }
    wk->red = r;
    wk->redcap = cap;
  }
  return 0;
}

int sim_add_material(sim *s, const material *m) {
  if (s->nmat == s->matcap) {
    int cap = s->matcap ? 2 * s->matcap : 8;
    material *p = realloc(s->mats, cap * sizeof *p);
    if (!p) return -1;
    s->mats = p;
    s->matcap = cap;
  }
  s->mats[s->nmat] = *m;
  s->mats[s->nmat].id = s->nmat;
  s->mats[s->nmat].fheat = s->heat ? s->heat->fq : -1;
  if (m->model->setup && m->model->setup(&s->mats[s->nmat], &s->ps)) {
    snprintf(s->err, sizeof s->err, "material %s: cannot set up its state",
             m->name);
    return -1;
  }
  return s->nmat++;
}

static int grow_fields(sim *s, int nfield) {
  int32_t *fd;
  unsigned char *fl;
  int k;
  if (nfield <= s->nfield) return 0;
  fd = realloc(s->fdriven, nfield * sizeof *fd);
  if (!fd) return -1;
  s->fdriven = fd;
  fl = realloc(s->flaw, nfield);
  if (!fl) return -1;
  s->flaw = fl;
  for (k = s->nfield; k < nfield; k++) { fd[k] = -1; fl[k] = 0; }
  fl = realloc(s->fflat, nfield);
  if (!fl) return -1;
  s->fflat = fl;
  for (k = s->nfield; k < nfield; k++) fl[k] = 0;
  s->nfield = nfield;
  return 0;
}

int sim_add_body(sim *s, const char *name, int32_t mat, int32_t field) {
  body *b;
  if (s->nbody == s->bodycap) {
    int cap = s->bodycap ? 2 * s->bodycap : 16;
    body *p = realloc(s->bodies, cap * sizeof *p);
    int32_t *q = realloc(s->bmat, cap * sizeof *q);
    if (!p || !q) { free(p == s->bodies ? NULL : p); return -1; }
    s->bodies = p;
    s->bmat = q;
    s->bodycap = cap;
  }
  if (field < 0) field = s->nfield;
  if (grow_fields(s, field + 1)) return -1;
  b = &s->bodies[s->nbody];
  memset(b, 0, sizeof *b);
  snprintf(b->name, sizeof b->name, "%s", name);
  b->material = mat;
  b->field = field;
  s->bmat[s->nbody] = mat;
  return s->nbody++;
}

const char *const update_names[] = {"usl", "musl", "usavg", NULL};
const char *const transfer_names[] = {"flip", "apic", "xpic", "spin", NULL};

void sim_scheme(const sim *s, char *buf, size_t n) {
  const sim_cfg *c = &s->cfg;
  char xpic[24] = "";
  if (c->transfer == TRANSFER_XPIC) snprintf(xpic, sizeof xpic, ", xpic = %d", c->xpic);
  snprintf(buf, n, "shape = \"%s\", update = \"%s\", transfer = \"%s\"%s, "
           "flip = %.17g, ppc = %d, cfl = %.17g", shape_names[c->shape],
           update_names[c->update], transfer_names[c->transfer], xpic, c->flip, c->ppc, c->cfl);
}

/* linear hats under USL: a node that a particle barely reaches has a
** tiny mass and the full slope of the hat, so the velocity the stresses
** give it there, read back through that slope, crushes the particles
** beside it as they cross cells (MUSL's remap reads mass-weighted
** particle velocities instead; GIMP and B-splines flatten at the edge).
** Measured: a free disc (K = 1, G = 0.5) translating at 0.18 c and
** spinning in a periodic box, 6.4 / 12.8 / 25.6 cells across it: det F
** <= 0 at steps 184 / 214 / 877 under pure FLIP, 281 / 340 / 973 under
** XPIC; against walls also under PIC (32 and 64 cells); in 3-D (a ball,
** 5 cells across) det F down to 0.02 */
static int usl_linear_hats(const sim_cfg *c) {
  return c->shape == SHAPE_LINEAR && c->update == UPDATE_USL;
}

static const char usl_linear[] =
    "linear hats under USL (shape = \"linear\", update = \"usl\") crush "
    "particles that cross cells: a free disc translating and spinning "
    "stopped with det F <= 0 within 900 steps at 6, 13 and 26 cells "
    "across it, under FLIP, XPIC and, against walls, PIC; update = "
    "\"musl\" or \"usavg\", or GIMP or B-splines under USL, hold "
    "(docs/stability.md)";

const char *sim_advice(const sim *s) {
  int k, walls = 0;
  if (usl_linear_hats(&s->cfg)) return usl_linear;
  for (k = 0; k < NSIDES; k++)
    if (s->sides[k].kind == SIDE_WALL && !s->g.periodic[k / 2]) walls = 1;
  if (s->cfg.transfer != TRANSFER_FLIP || s->cfg.flip < 1 || !(walls || s->nfield > 1))
    return NULL;
  /* the 3-D sphere's bounce (docs/accuracy.md): linear hats under MUSL
  ** lose 2.8 % at 8 cells, 0.7 % at 16, then gain 0.2 % at 24 and
  ** 1.1 % at 32; GIMP under USAVG
  ** at cfl 0.4, with the longer step an impact takes fewer steps, at
  ** each of which the walls' impact loss is taken: 1.8 % at 8 cells,
  ** 0.8 % at 12, 0.13 % at 16 */
  if (DIM == 3 && s->cfg.shape == SHAPE_LINEAR)
    return "linear hats with pure FLIP (shape = \"linear\", flip = 1) gain "
           "energy after impacts on walls or between bodies at fine grids "
           "(the 3-D sphere's bounce under MUSL: -2.8 %, -0.7 %, +0.2 %, "
           "+1.1 % after three impacts at 8, 16, 24, 32 cells per "
           "diameter); the default shape (B-splines) falls (-5.6 %, -4.7 % "
           "at 8, 12); for 3-D impacts shape = \"gimp\", update = \"usavg\", "
           "cfl = 0.4 gives -1.8 %, -0.8 %, +0.13 % at 8, 12, 16 "
           "(docs/accuracy.md)";
  /* measured on the frictionless bouncing disc (docs/accuracy.md): the
  ** energy change after three impacts at 8, 16, 32, 48 cells across it.
  ** Linear hats gain per cell crossed under MUSL; GIMP under MUSL too,
  ** less.  B-splines (the default) fall to -0.5 % at 48 and 64 cells,
  ** GIMP and linear hats under USAVG to -0.5 and -0.25 % at 48, so none
  ** of those is warned of.  (Before the stress rate was written for the
  ** Kirchhoff stress, linear hats under USAVG read +1.4 / +3.3 % at 32 /
  ** 48 cells: energy the material made at the impacts.) */
  if (s->cfg.shape == SHAPE_LINEAR && s->cfg.update == UPDATE_USAVG)
    return NULL;
  if (s->cfg.shape == SHAPE_LINEAR)
    return "linear hats with pure FLIP (shape = \"linear\", flip = 1) gain "
           "energy after impacts on walls or between bodies, more as the grid "
           "is refined (under MUSL +23 % after three bounces at 32 cells per "
           "diameter), and a free bar crossing cells diverges; the default "
           "shape (B-splines: -7.4 %, -3.8 %, -1.4 %, -0.5 % at 8, 16, 32, "
           "48) does not (docs/accuracy.md, the default shape)";
  if (s->cfg.shape == SHAPE_GIMP && s->cfg.update == UPDATE_MUSL)
    return "GIMP with pure FLIP under MUSL gains energy after impacts on "
           "walls or between bodies as the grid is refined (-1.3 %, +1.6 %, "
           "+2.9 % after three bounces at 16, 32, 48 cells per diameter); "
           "update = \"usavg\" does not (docs/accuracy.md, the bounce's "
           "convergence)";
  return NULL;
}

/* whether some wall side (not a mirror plane) has friction */
static int frictional_walls(const sim *s) {
  int k;
  for (k = 0; k < NSIDES; k++) {
    const side *sd = &s->sides[k];
    if (sd->kind == SIDE_WALL && !sd->mirror && sd->mu > 0) return 1;
  }
  return 0;
}

/* measured (tests/verify/friction_work.lua): a disc thrown without spin
** along a floor with mu = 0.3, friction work over the rigid disc's (it
** slides until it rolls) at 8, 16, 32 cells per diameter: node rule
** 2.28 / 1.32 / 1.13, patch rule 1.079 / 1.017 / 1.001.  Under the node
** rule the nodes ahead of the contact point, stopped one by one, turn
** the disc back, and it slides where it would roll. */
const char *sim_wall_advice(const sim *s) {
  /* spring walls are frictionless (a spring wall with friction is
  ** refused), and no longer turn bodies that slide along them: their
  ** springs move with the material (wall_spring.c) */
  if (s->cfg.wall_rule == WALL_SPRING) return NULL;
  if (!frictional_walls(s)) return NULL;
  /* measured (tests/verify/rolling.lua, last case): a disc (K = 10)
  ** thrown spinning into a box of walls with friction 0.3 under gravity,
  ** total energy above the work put in at its peak, 9.6 / 12.8 / 19.2
  ** cells per diameter: B-splines 9.3 / 15.4 / 14.9 %, linear hats 6.7 /
  ** 9.8 / 9.7 %; friction's booked work negative.  The couple's two
  ** impulses move the slip at the wall line several times as much as the
  ** patch's mean velocity, on which mu N and the slide test are judged,
  ** so mu N can reverse that slip within a step (boundary.c) */
  if (s->cfg.wall_rule == WALL_COUPLE)
    return "friction at the wall line (wall_contact = \"couple\") can "
           "make energy where a spinning body slides and rolls on a "
           "wall: a disc thrown spinning into a box of walls with "
           "friction under gravity rises 9 to 15 % above the work put in "
           "at 10 to 19 cells per diameter, friction booking negative "
           "work; \"patch\" does not (docs/verification.md, contact: "
           "rolling and spin-up)";
  /* "auto" is the node rule under the schemes sim_auto_patch() leaves
  ** out (sim.h), and the patch rule for round bodies elsewhere */
  if (s->cfg.wall_rule != WALL_NODE &&
      (s->cfg.wall_rule != WALL_AUTO || sim_auto_patch(&s->cfg)))
    return NULL; /* patch, auto per patch, penalty */
  return "walls with friction under the node rule (wall_contact = "
         "\"node\", or \"auto\" under linear hats or a transfer other "
         "than pure FLIP) hardly turn round bodies: a disc thrown along a "
         "floor slides where it would roll, and friction takes 2.3, 1.3, "
         "1.13 times the rigid disc's work at 8, 16, 32 cells per diameter; "
         "wall_contact = \"patch\" 1.08, 1.02, 1.001, but its impacts make "
         "energy under APIC and linear FLIP (docs/verification.md, friction "
         "work against the rigid disc)";
}

/* measured (tests/verify/normals.lua): a frictionless block on a flat
** body along the grid, gravity turned 30 degrees, contact node by node:
** a / a_ref 0.006 / 0.021 / 0.008 at 8 / 16 / 32 cells per side on
** B-splines, 0.85 on linear hats; at the block's bottom corners the
** normals turn toward the side, and stopping the approach along them
** stops the slide.  One normal per patch over a window of 4 cells:
** within 1.6 % along the grid, at 30 and 45 degrees.  Round bodies are
** not warned of: as the default that window and patch made a settled pile
** of discs creep and broke the symmetry of two spheres head on. */
const char *sim_normals_advice(const sim *s) {
  const sim_cfg *cfg = &s->cfg;
  int32_t i, j;
  if (cfg->normals == NORMALS_AUTO || cfg->normal_window > 0 ||
      cfg->normal_patch || cfg->body_rule == BODY_PATCH || s->nfield < 2)
    return NULL;
  for (i = 0; i < s->nbody; i++) {
    const body *a = &s->bodies[i];
    if (!a->flat || a->driven) continue;
    for (j = 0; j < s->nbody; j++) {
      const body *b = &s->bodies[j];
      if (j != i && b->flat && b->field != a->field)
        return "two bodies with flat faces meet with contact normals taken "
               "node by node (normal_window = 0, normal_patch = false): at "
               "a block's corners the normals turn toward its side, and "
               "stopping the approach along them holds it: a block on a "
               "flat body slides at 0.6-2 % of the analytic acceleration "
               "at 8-32 cells per side on B-splines, 85 % on linear hats; "
               "normals = \"maxvolume\", normal_window = 4, normal_patch = "
               "true is within 1.6 % along the grid, at 30 and 45 degrees, "
               "and the default, normals = \"auto\", takes it where flat "
               "faces meet (docs/verification.md, contact: normals)";
    }
  }
  return NULL;
}

/* A field is flat when every body on it is (body.flat: seeded from a
** shape with flat faces, no bond); the flat faces' normals (NORMALS_AUTO,
** contact.c) are wanted where two flat fields meet and one is free. */
void sim_flat(sim *s) {
  int32_t i;
  int nflat = 0, nfree = 0, nround = 0;
  for (i = 0; i < s->nfield; i++) s->fflat[i] = 1;
  for (i = 0; i < s->nbody; i++)
    if (!s->bodies[i].flat) s->fflat[s->bodies[i].field] = 0;
  for (i = 0; i < s->nbody; i++) { /* each flat field counted once */
    int32_t f = s->bodies[i].field;
    if (s->fflat[f] != 1) continue;
    s->fflat[f] = 2;
    nflat++;
    nfree += s->fdriven[f] < 0;
  }
  for (i = 0; i < s->nbody; i++) nround += !s->fflat[s->bodies[i].field];
  for (i = 0; i < s->nfield; i++) s->fflat[i] = s->fflat[i] == 2;
  s->flatpair = nflat >= 2 && nfree >= 1;
  s->flatmix = nflat >= 1 && nround >= 1;
}

/* what the numerics took (the transfer's smoothing and the nodes'
** inelastic impacts) beside what friction took: a scene whose friction
** work is read as physics should know when the numerical part is of the
** same size (measured in grain packs: tests/verify/friction_budget.lua,
** studies/grain_budget.lua) */
const char *sim_budget_advice(const sim *s) {
  const sim_energy *e = &s->e;
  double num = e->transfer + e->impact + e->bonding;
  double put = e->initial + e->boundary;
  if (!(e->friction > 0) || !(put > 0) || num < 0.02 * put ||
      num < 0.5 * e->friction)
    return NULL;
  return "the numerical losses (sim:energy().numerical) are more "
         "than half the friction work: friction work differs between "
         "transfer schemes and resolutions by as much (docs/verification.md, "
         "energy budget with friction)";
}

int sim_enable_apic(sim *s) {
  if (s->faff < 0) {
    int c;
    /* in snapshots too: the affine field is half the particle's velocity
    ** state under APIC */
    s->faff = particles_add_field(&s->ps, "affine", NTENS, PF_DOUBLE, "1/T",
                                  PF_OUTPUT | PF_RESTART);
    if (s->faff < 0) return -1;
    for (c = 0; c < NTENS; c++)
      s->ps.fields[s->faff].comp_names[c] = particles_tens_name(c);
  }
  return 0;
}

int sim_enable_bonds(sim *s) {
  if (s->fbond < 0)
    s->fbond = particles_add_field(&s->ps, "bond", 1, PF_DOUBLE, "M/(L T^2)",
                                   PF_OUTPUT | PF_RESTART);
  if (s->fbond >= 0 && s->frel < 0)
    s->frel = particles_add_field(&s->ps, "release", DIM + 1, PF_DOUBLE, "L",
                                  PF_RESTART);
  if (s->frel >= 0 && s->cfg.bond_gc > 0 && s->fcoh < 0) {
    s->fcoh = particles_add_field(&s->ps, "cut_strength", 1, PF_DOUBLE,
                                  "M/(L T^2)", PF_OUTPUT | PF_RESTART);
    s->fopen = particles_add_field(&s->ps, "opening", 1, PF_DOUBLE, "L",
                                   PF_OUTPUT | PF_RESTART);
    if (s->fcoh < 0 || s->fopen < 0) return -1;
  }
  if (s->frel >= 0 && s->cfg.bond_fit && !s->work.bfit) { /* only for bond_traction = "fit" */
    s->work.bfit = malloc(BF_N * s->g.nnodes * sizeof *s->work.bfit);
    s->work.bffield = malloc(s->g.nnodes * sizeof *s->work.bffield);
    if (!s->work.bfit || !s->work.bffield) return -1;
  }
  return s->frel < 0 ? -1 : s->fbond;
}

long sim_add_particle(sim *s, int32_t b, const double x[DIM],
                      const double v[DIM], double vol) {
  particles *ps = &s->ps;
  size_t i = particles_push(ps);
  const material *m;
  int d;
  if (i == (size_t)-1) return -1;
  for (d = 0; d < DIM; d++) {
    ps->x[d][i] = x[d];
    ps->v[d][i] = v[d];
  }
  ps->body[i] = b;
  ps->vol0[i] = vol;
  ps->lp[i] = s->cfg.lp;
  m = &s->mats[s->bodies[b].material];
  ps->m[i] = m->rho * vol;
  return (long)i;
}

double sim_stable_dt(const sim *s) {
  const sim_cfg *cfg = &s->cfg;
  double c = 0;
  int k;
  for (k = 0; k < s->nmat; k++)
    if (s->mats[k].c > c) c = s->mats[k].c;
  /* the wave speed grows as the material is stretched: c ~ sqrt(J) */
  if (s->e.jmax > 1) c *= sqrt(s->e.jmax);
  return cfg->cfl * s->g.h / (c + s->vmax);
}

void sim_measure(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  const particles *ps = &s->ps;
  size_t i;
  int d;
  double ke = 0, se = 0, am[3] = {0, 0, 0}, v2max = 0, pe = 0;
  for (d = 0; d < DIM; d++) s->e.mom[d] = 0;
  for (i = 0; i < ps->n; i++) {
    double v2 = 0;
    int32_t mi = s->bmat[ps->body[i]];
    for (d = 0; d < DIM; d++) {
      v2 += ps->v[d][i] * ps->v[d][i];
      s->e.mom[d] += ps->m[i] * ps->v[d][i];
      pe -= ps->m[i] * cfg->gravity[d] * ps->x[d][i];
    }
    if (v2 > v2max) v2max = v2;
    ke += 0.5 * ps->m[i] * v2;
    if (mi >= 0) se += s->mats[mi].model->energy(&s->mats[mi], ps, i);
    {
      double x[DIM], v[DIM];
      for (d = 0; d < DIM; d++) { x[d] = ps->x[d][i]; v[d] = ps->v[d][i]; }
      vec_moment(am, ps->m[i], x, v);
    }
  }
  s->e.kinetic = ke + g2p_affine_energy(s);
  s->e.strain = se;
  s->e.potential = sim_potential(s, pe);
  s->e.wall_spring = wall_penalty_energy(s) + wall_spring_energy(s);
  for (d = 0; d < 3; d++) s->e.angmom[d] = am[d];
  s->vmax = sqrt(v2max);
}

double sim_next_dt(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  double dt;
  if (!s->started) sim_measure(s);
  dt = cfg->dt_fixed > 0 ? cfg->dt_fixed : sim_stable_dt(s);
  /* land on the end of a run rather than overshoot it; a sliver shorter
  ** than a thousandth of a step is absorbed by the step before */
  if (s->t_stop > s->t && s->t + dt * 1.001 > s->t_stop) dt = s->t_stop - s->t;
  return dt;
}

int sim_wall_hold(const sim *s) {
  const sim_cfg *cfg = &s->cfg;
  int d;
  if (cfg->wall_remap != WALL_REMAP_AUTO) return cfg->wall_remap == WALL_REMAP_HOLD;
  for (d = 0; d < DIM; d++)
    if (cfg->gravity[d] != 0) return 1;
  return 0;
}

double sim_potential(const sim *s, double pe) {
  int d;
  for (d = 0; d < DIM; d++) pe -= s->cfg.gravity[d] * s->e.wrap[d];
  return pe;
}

double sim_total(const sim *s) {
  return s->e.kinetic + s->e.strain + s->e.potential + s->e.lag + s->e.wall_spring;
}

double sim_residual(const sim *s) {
  const sim_energy *e = &s->e;
  return e->initial + e->boundary + e->thermal - e->friction - e->plastic -
         e->viscous - e->settled - e->transfer - e->impact - e->bonding -
         e->cohesion - e->removed - sim_total(s);
}

double sim_scale(const sim *s) {
  const sim_energy *e = &s->e;
  return (e->initial - e->potential0) + fabs(e->boundary) + fabs(e->thermal) +
         fabs(e->potential - e->potential0) + e->settled + fabs(e->removed);
}

double sim_stop(sim *s) {
  particles *ps = &s->ps;
  double before, after;
  size_t i;
  int d;
  if (!s->started) sim_begin(s);
  sim_measure(s);
  before = s->e.kinetic;
  for (i = 0; i < ps->n; i++) {
    if (s->bmat[ps->body[i]] < 0) continue; /* driven: keeps its drive */
    for (d = 0; d < DIM; d++) ps->v[d][i] = 0;
    if (s->faff >= 0) {
      const pfield *f = &ps->fields[s->faff];
      int c;
      for (c = 0; c < f->ncomp; c++) ((double *)*f->slot[c])[i] = 0;
    }
  }
  sim_measure(s);
  after = s->e.kinetic;
  s->e.settled += before - after;
  return before - after;
}

/* each material's update over whole chunks of particles, the sums kept
** per chunk */
typedef struct cjob { sim *s; double dt; } cjob;

static void constitutive_part(void *arg, int t, int nparts) {
  const cjob *j = arg;
  sim *s = j->s;
  sim_work *wk = &s->work;
  mat_sums *red = wk->red;
  size_t n = s->ps.n, c, c0, c1, i0, i1;
  int k;
  par_chunks(n, t, nparts, &c0, &c1);
  for (c = c0; c < c1; c++) {
    mat_sums z = {0, 0, 1e300, -1e300, 0, 0, 0, 0};
    red[c] = z;
    par_chunk(n, c, &i0, &i1);
    for (k = 0; k < s->nmat; k++)
      s->mats[k].model->update(&s->mats[k], &s->ps, s->bmat, k, j->dt, i0,
                               i1, &red[c]);
  }
}

_Static_assert(sizeof(mat_sums) <= SIM_RED_BYTES, "mat_sums fit SIM_RED_BYTES");

int constitutive(sim *s, double dt) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  mat_sums sum = {0, 0, 1e300, -1e300, 0, 0, 0, 0};
  const mat_sums *red = wk->red;
  size_t c, nc = par_nchunks(s->ps.n);
  cjob j = {s, dt};
  par_run(wk->par, constitutive_part, &j);
  /* in chunk order: the same for any thread count */
  for (c = 0; c < nc; c++) {
    sum.strain += red[c].strain;
    sum.power += red[c].power;
    sum.plastic += red[c].plastic;
    sum.viscous += red[c].viscous;
    sum.heat += red[c].heat;
    sum.nbadj += red[c].nbadj;
    if (red[c].jmin < sum.jmin) sum.jmin = red[c].jmin;
    if (red[c].jmax > sum.jmax) sum.jmax = red[c].jmax;
  }
  s->e.strain = sum.strain;
  s->e.plastic += sum.plastic;
  s->e.viscous += sum.viscous;
  if (s->heat) {
    s->e.heat_plastic += sum.heat;
    s->e.cold += sum.plastic - sum.heat;
    s->e.heat_viscous += sum.viscous;
  }
  /* USAVG's stresses are those of the step's end, as the velocities */
  s->e.lag = cfg->update == UPDATE_USAVG ? 0 : -0.5 * dt * sum.power;
  if (sum.jmin <= sum.jmax) { s->e.jmin = sum.jmin; s->e.jmax = sum.jmax; }
  s->e.nbadj = sum.nbadj;
  if (sum.nbadj) {
    snprintf(s->err, sizeof s->err,
             "step %ld: %zu particle(s) with det F <= 0 (min %.3g): the "
             "material was crushed; %s",
             s->step, sum.nbadj, sum.jmin,
             usl_linear_hats(cfg)
                 ? "linear hats under USL do this where particles cross "
                   "cells: use update = \"musl\" or \"usavg\", or another "
                   "shape"
                 : "reduce the time step (cfl) or refine");
    return -1;
  }
  return 0;
}

/* What particle i takes with it as it leaves: its kinetic, strain and
** potential energy, taken out of the step's sums (which g2p and the
** constitutive pass made with it) and booked as removed; with heat, its
** thermal energy as heat that left through the boundary.  The potential
** is over its wrapped position, as the sums took it (the wraps' sum
** e.wrap keeps its part, a constant from then on). */
static void leave(sim *s, size_t i) {
  const particles *ps = &s->ps;
  int32_t mi = s->bmat[ps->body[i]];
  double m = ps->m[i], ke = 0, pe = 0, se = 0;
  int d;
  for (d = 0; d < DIM; d++) {
    ke += 0.5 * m * ps->v[d][i] * ps->v[d][i];
    pe -= m * s->cfg.gravity[d] * ps->x[d][i];
  }
  if (mi >= 0) {
    se = s->mats[mi].model->energy(&s->mats[mi], ps, i);
    if (s->heat && s->ftemp >= 0) {
      const double *T = particles_comp(ps, s->ftemp, 0);
      double q = m * s->mats[mi].cv * T[i];
      s->e.heat_boundary -= q;
      s->e.heat_thermal -= q;
    }
  }
  s->e.kinetic -= ke;
  s->e.potential -= pe;
  s->e.strain -= se;
  s->e.removed += ke + pe + se;
}

/* particles that left the domain are dropped (documented behaviour) */
static void housekeeping(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  particles *ps = &s->ps;
  if (s->nout) {
    unsigned char *keep = ps->scratch; /* cap bytes are enough */
    size_t i;
    for (i = 0; i < ps->n; i++)
      if (!(keep[i] = ps->cell[i] >= 0)) leave(s, i);
    /* compact works array by array; keep must not be one of them */
    s->nremoved += ps->n - particles_compact(ps, keep);
    s->nout = 0;
  }
  /* also after the first step: bodies are seeded one after the other,
  ** so until the first sort each body's particles span every node row,
  ** and the scatter plan (bands.h) of two bodies side by side gives one
  ** part every row in pass 1 and the other every row in pass 2: the
  ** threads took turns for the first sort_every steps */
  if (cfg->sort_every > 0 && (s->step % cfg->sort_every == 0 || s->step == 1)) {
    size_t ncell = 1;
    int d;
    for (d = 0; d < DIM; d++) ncell *= (size_t)s->g.cells[d];
    particles_sort(ps, ps->cell, ncell, wk->par);
  }
}

void sim_begin(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  const particles *ps = &s->ps;
  double mmin = 1e300;
  size_t i;
  for (i = 0; i < ps->n; i++)
    if (ps->m[i] < mmin) mmin = ps->m[i];
  s->mcut = ps->n ? cfg->mcut_rel * mmin : 0;
  sim_measure(s);
  s->e.initial = s->e.kinetic + s->e.strain + s->e.potential;
  s->e.potential0 = s->e.potential;
  s->e.jmin = s->e.jmax = 1;
  s->dt = cfg->dt_fixed > 0 ? cfg->dt_fixed : sim_stable_dt(s);
}

/* the forces walls and driven bodies report are those of this step */
static void forces_clear(sim *s) {
  int k, d;
  for (k = 0; k < NSIDES; k++)
    for (d = 0; d < DIM; d++) s->sides[k].force[d] = 0;
  if (s->ndriven)
    for (k = 0; k < s->nbody; k++)
      if (s->bodies[k].driven)
        for (d = 0; d < DIM; d++) s->bodies[k].force[d] = 0;
}

static void reset_part(void *arg, int t, int nparts) {
  grid *g = arg;
  size_t i0, i1;
  par_range(g->nnodes, t, nparts, &i0, &i1);
  grid_clear(g, i0, i1, 0);
}

int sim_step(sim *s) {
  const sim_cfg *cfg = &s->cfg;
  sim_work *wk = &s->work;
  int musl = cfg->update != UPDATE_USL, usavg = cfg->update == UPDATE_USAVG;
  if (sim_prepare(s)) return -1;
  if (s->heat && !s->heat->ready && heat_start(s)) return -1;
  if (!s->started) {
    /* once, at the first step: bodies are all added */
    if (s->ftemp >= 0) thermal_prestress(s);
    particles_fit(&s->ps); /* drop the seeding slack */
    sim_begin(s);
    s->started = 1;
  }
  s->dt = sim_next_dt(s);
  prof_mark(wk->prof, PROF_HOUSE);
  par_run(wk->par, reset_part, &s->g);
  grid_reset_slots(&s->g);
  p2g_plan(s);
  sim_flat(s);
  s->g.moments = cfg->normals == NORMALS_PLANE;
  s->g.cohesive = s->fcoh >= 0;
  if ((s->nfield > 1 || s->ndriven) && (p2g_mark(s) || contact_prepare(s))) {
    snprintf(s->err, sizeof s->err, "out of memory for shared nodes");
    return -1;
  }
  if (s->heat && heat_prepare(s)) return -1;
  p2g(s);
  /* USAVG with bonds: the strengths before the first half-step, which
  ** holds the bonded slots beside driven bodies (usf.c); the traction
  ** the bond test reads is then the stresses' at the step's start, as
  ** under MUSL */
  if (usavg && s->g.nshared && s->fbond >= 0) bond_gather(s);
  if (usavg && usf(s)) return -1;
  prof_mark(wk->prof, PROF_P2G);
  solve_momentum(s);
  prof_mark(wk->prof, PROF_SOLVE);
  if (s->g.nshared) contact_normals(s);
  if (cfg->gap_check) reach(s);
  forces_clear(s);
  if (!usavg && s->g.nshared && s->fbond >= 0) bond_gather(s);
  if (s->g.nshared) contact_apply(s);
  if (s->ncut || (s->fcoh >= 0 && s->g.nshared)) {
    bond_scatter(s);
    s->ncut_total += s->ncut;
  }
  prof_mark(wk->prof, PROF_CONTACT);
  boundary_apply(s);
  prof_mark(wk->prof, PROF_SIDES);
  if (s->heat) {
    if (heat_grid(s)) return -1;
    prof_mark(wk->prof, PROF_HEAT);
  }
  solve_velocity(s);
  if (cfg->transfer == TRANSFER_XPIC) xpic(s);
  prof_mark(wk->prof, PROF_SOLVE);
  if (!musl && s->heat) heat_finish(s); /* book_finish's velocities (vL) */
  g2p(s);
  prof_mark(wk->prof, PROF_G2P);
  if (musl) {
    /* the remap is not constrained again by contact: the velocity
    ** gradient follows what the particles do; the walls only where the
    ** scene holds them (boundary_remap says why and what it costs) */
    solve_remap(s); /* g2p mapped the updated momenta back */
    if (sim_wall_hold(s)) {
      boundary_remap(s);
      if (cfg->wall_rule == WALL_PENALTY) wall_penalty_hold(s);
      if (cfg->wall_rule == WALL_SPRING) wall_spring_hold(s);
    }
    book_finish(s); /* on the remapped motion (book.c) */
    if (s->heat) heat_finish(s); /* ... and its heat, before the move */
    if (s->fbond >= 0 && s->g.nshared) bond_remap(s);
    g2p_remap(s);
    prof_mark(wk->prof, PROF_REMAP);
  }
  if (!musl) book_finish(s); /* no remap: on vL */
  if (s->temp_on) thermal(s);
  if (constitutive(s, usavg ? 0.5 * s->dt : s->dt)) return -1;
  /* after every other source of heat of the step */
  if (s->fmelt >= 0) melt(s);
  if (s->react_on) react(s);
  prof_mark(wk->prof, PROF_CONST);
  if (s->heat) {
    heat_update(s);
    prof_mark(wk->prof, PROF_HEAT);
  }
  s->t += s->dt;
  s->step++;
  housekeeping(s);
  if (wk->prof) wk->prof->steps++;
  prof_mark(wk->prof, PROF_HOUSE);
  return 0;
}
