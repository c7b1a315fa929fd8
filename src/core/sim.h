/*
** sim.h - the simulation object and the step.
** sim_step runs the phases in the order of the method, nothing else:
**   reset grid -> p2g (per field) -> grid momentum update -> contact ->
**   sides and driven bodies -> grid velocities -> g2p -> [MUSL remap] ->
**   constitutive update -> particle housekeeping.
** Lua, callbacks and output run only between steps.
*/
#ifndef mvmpm_sim_h
#define mvmpm_sim_h

#include <stddef.h>
#include <stdint.h>
#include "bands.h"
#include "dim.h"
#include "grid.h"
#include "mark.h"
#include "material.h"
#include "particles.h"
#include "par.h"
#include "shape.h"
#include "vec.h"

enum side_kind { SIDE_FREE, SIDE_WALL, SIDE_PERIODIC };
/* the velocity gradient the stresses are updated with: the updated grid
** velocity (USL), the updated particle velocities mapped back (MUSL), or
** half of the step with the grid velocity at its start and half with
** MUSL's at its end (USAVG, usf.c) */
enum update_kind { UPDATE_USL, UPDATE_MUSL, UPDATE_USAVG };
/* their names in mvmpm.sim, in enum order, NULL-terminated (sim.c) */
extern const char *const update_names[];
/* MUSL's remap at the walls (boundary_remap): auto holds them with
** gravity on */
enum wall_remap { WALL_REMAP_AUTO, WALL_REMAP_HOLD, WALL_REMAP_FREE };
/* how a wall acts on the nodes where material touches it (boundary.c) */
/* ... WALL_COUPLE: the patch rule with sliding friction put at the wall
** line by a couple on the first node line inside (boundary.c);
** WALL_PENALTY: a spring on each particle that passes the wall line,
** frictionless walls only (wall_penalty.c); WALL_SPRING: a spring on each
** column of nodes at the wall (wall_spring.c); WALL_AUTO: the patch rule
** for the fields that are not flat (sim.fflat) at a wall with friction,
** the node rule elsewhere (boundary.c) */
enum wall_rule { WALL_NODE, WALL_PATCH, WALL_COUPLE, WALL_PENALTY, WALL_SPRING,
                 WALL_AUTO };
/* how contact between two bodies acts: node by node (contact.c) or one
** velocity change per side over each contact patch (contact_patch.c);
** BODY_AUTO (the default): per patch where a flat-faced body meets one
** that is not (sim.fflat), node by node elsewhere */
enum body_rule { BODY_NODE, BODY_PATCH, BODY_AUTO };
/* FLIP: the velocity increment blended with PIC by flip; APIC: the
** grid velocity and an affine velocity field per particle; SPIN: FLIP
** whose particles also carry a spin, the skew part of APIC's affine
** field, mapped to the grid as APIC's is and moved by FLIP's increments
** as the velocity is (g2p.c) */
enum transfer_kind { TRANSFER_FLIP, TRANSFER_APIC, TRANSFER_XPIC, TRANSFER_SPIN };
/* their names in mvmpm.sim, in enum order, NULL-terminated (sim.c) */
extern const char *const transfer_names[];
/* how contact normals are taken (contact.c): each field's mass or volume
** gradient against the others', the larger volume gradient's direction
** for both sides, or the least-squares plane between the particles;
** NORMALS_AUTO (the default): the mass gradient, but where only fields
** of flat-faced bodies meet (sim.fflat) the larger volume gradient over
** NORMAL_FLAT_WINDOW cells with one normal per contact patch, and where
** a round body meets a flat one the flat face's own mass gradient over
** as many */
enum normals_kind { NORMALS_MASS, NORMALS_VOLUME, NORMALS_MAXVOLUME,
                    NORMALS_PLANE, NORMALS_AUTO };
/* contact where a bond was cut (contact.c): only once the opening measured
** from the sides' displacements since the cut closes, or by the separation
** check like any contact */
enum release_kind { RELEASE_OPEN, RELEASE_CONTACT };
/* the widest window the normals may take (cells each way) */
#define NORMAL_WINDOW_MAX 8
/* NORMALS_AUTO's window between flat faces (contact.c says why 4) */
#define NORMAL_FLAT_WINDOW 4
/* A driven body acts on a round one at a shared node only where its
** material reaches within this many cells of the node (reach.c), as a
** wall acts on its line and beyond (contact.c, driven partners) */
#define DRIVE_REACH 0.75
#define NSIDES (2 * DIM)
/* doubles per wall column wall_spring.c works in: the columns' sums,
** the springs moved, the patches' slides and the springs (struct spr) */
#define WSPRING_W (13 + 3 * DIM + 2 * (1 << (DIM - 1)))
/* side index: 2 d for the low side of dimension d, 2 d + 1 for the high */

typedef struct side {
  int kind;
  int mirror;        /* a wall of kind "symmetry": the normal velocity is
                     ** held at 0 both ways (the material may not leave
                     ** the plane either), no friction: the mirror plane of
                     ** a symmetric scene */
  double mu;         /* Coulomb friction; INFINITY sticks */
  double v[DIM];     /* wall velocity (tangential part moves the wall) */
  double *ext;       /* reach of material toward the wall per column (node
                     ** of the wall plane, grid_face_node's order) */
  int32_t *efld;     /* ... the field that reach is of, and ext2 the reach */
  double *ext2;      /* of the other fields there (sim_wall_reach) */
  size_t next;       /* columns: grid_face_count of the side's axis */
  unsigned char *acted; /* per column of the wall plane and the ghost
                        ** planes: the wall acted there this step */
  double *hm;        /* patch rule with friction: per column of those planes
                     ** and the first plane inside, sum S m (distance of the
                     ** particle from the wall plane) (boundary.c) */
  double force[DIM]; /* force the wall put on the material, last step */
  /* WALL_SPRING (wall_spring.c): per column index, the compression of
  ** the spring there (0: none) and its offset from the column along each
  ** tangential axis, in cells, in [0, 1) (DIM entries, the normal one
  ** 0); and per column, whether the springs acted on it this step (1)
  ** or left it to the node rule (2) */
  double *dl, *ph;
  unsigned char *son;
} side;

typedef struct body {
  char name[32];
  int32_t material;  /* index into mats; -1 for a driven (rigid) body */
  int32_t field;     /* velocity field */
  int driven;
  double vdrive[DIM];
  double force[DIM]; /* driven: force it put on the other bodies, last step */
  int hold;          /* heat (heat.h): its particles are held at T_hold, a
                        reservoir */
  double T_hold;
  int flat;          /* set by the binding: seeded from a shape with flat
                        faces (rect, polygon, box, extrude) and given no
                        bond; sim_normals_advice looks for two of them */
} body;

/* a contact law between two fields: friction, and the most their
** interface's bond may hold (bond.c): 0 never bonds, INFINITY bonds up
** to the particles' own strengths */
typedef struct pairlaw { int32_t a, b; double mu, bond; } pairlaw;

/* energy and momentum, updated every step */
typedef struct sim_energy {
  double kinetic, strain;
  double potential;  /* of gravity, -sum m g.x: zero without gravity; x
                     ** unwrapped (wrap below) */
  double wrap[DIM];  /* sum m (x - x_wrapped) over every periodic wrap of
                     ** a particle (g2p.c): what the potential adds back, so
                     ** that with gravity along a periodic axis it stays
                     ** gravity's work and material falling through the
                     ** seam does not jump it by m g L */
  double lag;        /* -dt/2 sum V sigma:D: see sim_total */
  double wall_spring; /* stored in the walls' springs (wall_penalty.c) */
  double friction;   /* work dissipated by friction (walls + contacts) */
  double boundary;   /* work done on the material by walls / driven bodies */
  double plastic;    /* plastic work (mat_plastic.c) */
  double viscous;    /* viscous dissipation (mat_viscoelastic.c) */
  double thermal;    /* work of the thermal strain on the stress (thermal.c):
                     ** what heating or cooling adds to the strain energy */
  double settled;    /* kinetic energy taken out by sim_stop (settling) */
  double removed;    /* kinetic + strain + potential of the particles that
                     ** left through free sides, as they left (sim.c
                     ** housekeeping): an outflow, so that the budget of
                     ** an open scene (a hopper, a chute's outlet) closes */
  double chemical;   /* heat the reaction released, sum m Q d lambda
                     ** (react.c): an input to the heat, not to the
                     ** mechanical budget */
  double transfer;   /* what the transfer itself took from the particles:
                     ** its change of their velocities beyond FLIP's
                     ** increment, booked as an impulse's work on their
                     ** mean velocity (g2p.c) */
  double impact;     /* what the normal impulses of contact and walls
                     ** dissipate: impacts are inelastic at a node */
  double bonding;    /* what bonded nodes take: the impulses that give
                     ** the bonded fields one velocity (inelastic at the
                     ** node) less the stress work bond_remap adds
                     ** (contact.c, bond.c) */
  double cohesion;   /* the work of separation: what the cohesive law's
                     ** impulses took from cut interfaces opening
                     ** (sim.bond_energy > 0; contact.c cohere()) */
  /* heat (heat.h), in scenes with heat only: what the sources put into
  ** the particles (friction, beta x plastic, viscous, heat_add's), what
  ** wall friction gave the walls, the cold work (1 - beta) x plastic,
  ** what came in through walls and held bodies (conduct.c), and the
  ** thermal energy sum m c (T - T0) the particles hold */
  double heat_friction, heat_plastic, heat_viscous, heat_source;
  double heat_wall, cold, heat_boundary, heat_thermal;
  double latent;     /* friction heat the melting cap took (melt.h): heat
                     ** that left the particles' temperature */
  double initial;    /* kinetic + strain + potential before the first step */
  double potential0; /* potential before the first step */
  double mom[DIM];
  double angmom[3];  /* about the origin, sum m x × v (2-D: only the z
                     ** component, angmom[2]; the others stay 0) */
  double jmin, jmax;
  size_t nbadj;
} sim_energy;

/*
** The settings of a simulation: set (and checked) between steps by
** sim_init and the scene's setters, read by the phases of a step, which
** never write them.  A checkpoint keeps the ones a restart needs.
*/
typedef struct sim_cfg {
  int shape;         /* enum shape_kind */
  int update;        /* enum update_kind */
  double flip;       /* FLIP fraction of the velocity update, 0 = PIC */
  int transfer;      /* enum transfer_kind */
  int xpic;          /* XPIC: its order m, 2 or 3 (xpic.c) */
  double cfl;        /* Courant number for the automatic step */
  double dt_fixed;   /* > 0: fixed step */
  double gravity[DIM];
  double mu_default; /* default contact friction between fields */
  double bond_default; /* bond cap where no law says otherwise (INFINITY) */
  int release;       /* enum release_kind: contact across a released bond */
  int bond_fit;      /* bond traction from the sides' fitted profiles */
  double bond_length; /* ... averaged over this length along the interface */
  double bond_gc;    /* > 0: a cut interface holds a cohesive traction that
                     ** falls with the opening and gives out once this
                     ** energy per area is spent (contact.c); 0: brittle */
  int gap_check;     /* contact only once material surfaces meet */
  int gap_step;      /* ... judged at the step's end (contact.c closing) */
  int wall_remap;    /* enum wall_remap: MUSL's remap at the walls */
  int wall_rule;     /* enum wall_rule: node by node or per contact patch */
  double wall_stiffness; /* WALL_PENALTY: the spring over the particle
                     ** material's P-wave modulus per particle size;
                     ** WALL_SPRING: the column's, per cell (wall_spring.c) */
  int wall_band;     /* WALL_SPRING: node planes inside in a column */
  int body_rule;     /* enum body_rule: the same between bodies */
  int normals;       /* enum normals_kind: how contact normals are taken */
  int normal_window; /* ... from the shared nodes within this many cells */
  int normal_patch;  /* 1: then one normal per contact patch (their mean) */
  double mcut_rel;   /* mcut as a fraction of the lightest particle */
  int sort_every;    /* steps between sorts by cell */
  int ppc;
  double lp;         /* particle half size in cells (1 / (2 ppc)) */
  double react_tol;  /* largest change of Ta / T over a substep (react.h) */
  double react_ign;  /* the reacted fraction that counts as ignition */
  /* threads (par.h): the pool is made at the first step, or the first
  ** after sim_set_threads; results do not depend on the count */
  int threads;
} sim_cfg;

/* whether the transfer replaces FLIP's increment by a smoother velocity
** (a PIC share, APIC, XPIC): its change is then booked as e.transfer
** (g2p.c) and the walls' normal impulses in two halves (boundary.c,
** book.c) */
static inline int sim_lossy(const sim_cfg *cfg) {
  return cfg->transfer != TRANSFER_FLIP || cfg->flip < 1;
}

/* whether the particles carry an affine field (APIC) or its spin part
** (SPIN): mapped to the grid as v_p + C_p (x_i - x_p) (p2g.c, g2p.c) */
static inline int sim_affine(const sim_cfg *cfg) {
  return cfg->transfer == TRANSFER_APIC || cfg->transfer == TRANSFER_SPIN;
}

/* whether wall_contact = "auto" takes the patch rule for round bodies at
** walls with friction: under pure FLIP on GIMP and B-splines, and under
** "spin" with flip 1 (FLIP's velocities, the spin kept).  Elsewhere
** it is the node rule: the patch's normal impulses made energy there (a
** disc dropped on a frictional floor, residual -2.5 to -2.8 % of the
** energy put in at 8 to 32 cells under B-spline APIC, node by node
** within 0.3 %; linear FLIP -1.1 / -2.6 / -5.8 / -9.6 % at 8 / 16 / 24
** / 32 cells), and XPIC and the FLIP/PIC blend stop a body's spin in
** the transfer, so that the patch's torque buys little (boundary.c) */
static inline int sim_auto_patch(const sim_cfg *cfg) {
  const int flip = !sim_lossy(cfg) || (cfg->transfer == TRANSFER_SPIN && cfg->flip == 1);
  return flip && cfg->shape != SHAPE_LINEAR;
}

/*
** The scratch of a step: the thread pool, the scatter plan and the
** rooms the threaded phases sum and record into.  Made or grown by
** sim_prepare (and the phases' own prepare calls), overwritten by every
** step, never read across steps and never kept by a checkpoint.
*/
typedef struct sim_work {
  par *par;
  bands bands;       /* the plan of this step's scatters (bands.h) */
  marks marks;       /* shared-node marking's room (mark.h) */
  int p2g_what;      /* p2g.c: what its scatter now adds */
  void *red;         /* per-chunk partial sums of the threaded phases */
  size_t redcap;     /* ... its bytes */
  unsigned char *pflag; /* wall_penalty.c: per node, bit d set where a
                     ** spring pushed along axis d this step */
  double *wext;      /* reach.c: each thread but the first's copy of the
                        sides' reach arrays, 2 wextn doubles each (ext,
                        ext2), and in wefld wextn fields (efld) */
  int32_t *wefld;
  size_t wextn;
  double *wcarry;    /* wall_spring.c: WSPRING_W per column of a side */
  int32_t *wpatch;   /* boundary.c: room to find a wall's contact patches
                        in, 4 x the most columns of a side + 1 */
  /* contact.c's records of a threaded pass, added up in node order after
  ** it: per shared node the driven body's force and work (cbody -1:
  ** none) */
  double *crec;
  int32_t *cbody;
  size_t cnodecap;
  /* contact_patch.c: per node its patch (-1: none, and between steps),
  ** and the nodes of the patch being flooded */
  int32_t *cplab, *cplist;
  size_t cplistcap;
  /* per node, the bond traction's sums over the particles near, not at,
  ** an interface (bond.c: BF_* arrays of nnodes each), and the field they
  ** belong to */
  double *bfit;
  int32_t *bffield;
  /* p2g.c: per particle the slot of each node of its stencil, in
  ** stencil_eval's order (-1: the node is not shared), stencil_size
  ** per particle; found once a step by p2g's scatter, read by the passes
  ** after it (reach, g2p, the remap, USAVG's gradient, XPIC) until the
  ** particles move.  Made by p2g_mark, only where nodes are shared. */
  int32_t *pslot;
  size_t pslotcap;   /* ... entries */
  struct sim_prof *prof; /* time per phase, when profiling (prof.h) */
} sim_work;

/*
** The simulation object: its settings (cfg), the state a step advances
** (the members between them: grid, particles, time, the registries of
** materials, bodies, laws and particle fields, energies and counters)
** and the step's scratch (work).  A phase names at its top which of the
** three it reads and writes (docs/architecture.md has the table).
*/
typedef struct sim {
  sim_cfg cfg;       /* the settings */
  /* the state */
  grid g;
  particles ps;
  int faff;          /* APIC: particle field "affine" (C, row major) */
  double dt, t, t_end;
  double t_stop;     /* a step ends here at the latest (run_until's end) */
  long step;
  side sides[NSIDES];
  material *mats;
  int nmat, matcap;
  body *bodies;
  int nbody, bodycap;
  int32_t *bmat;     /* per body: material index, -1 for driven */
  int nfield;
  int ndriven;       /* driven bodies (set with their drive) */
  int32_t *fdriven;  /* per field: driving body or -1 */
  pairlaw *laws;     /* overrides per field pair, sorted (a < b) */
  int nlaw, lawcap;
  unsigned char *flaw; /* per field: 1 if some override names it */
  unsigned char *fflat; /* per field: 1 if all its bodies are flat
                           (body.flat), set at each step (sim_flat) */
  int flatpair;      /* two flat fields, one of them free: NORMALS_AUTO
                        then takes the flat faces' normals (sim_flat) */
  int wsplit;        /* boundary.c: the patch rule kept normal impulses in
                     ** g.ni this step, for book.c's second half */
  int flatmix;       /* a flat field and one that is not: BODY_AUTO then
                        takes their patches (sim_flat) */
  int fbond;         /* particle field "bond" (strength), -1: no bonds */
  int fcoh, fopen;   /* particle fields "cut_strength" and "opening"
                        (bond_gc > 0): the strength the particle's bond had
                        when cut, the largest opening its node has seen
                        since (bond.c); -1 without */
  int frel;          /* particle field "release": 1 once the particle's bond
                        was cut, then its position then (bond.c) */
  size_t ncut;       /* interface slots debonded in the last step */
  size_t ncut_total; /* ... since the start */
  double bond_area;  /* bonded interface area in the last step (length in
                        2-D), each interface counted once */
  double mcut;       /* nodal masses below this are empty (cfg.mcut_rel
                        times the lightest particle, sim_begin) */
  size_t nremoved;   /* particles that left the domain */
  size_t nheld;      /* particle moves held inside at a penalty wall
                     ** (wall_penalty.c: its spring too soft) */
  sim_energy e;
  int ftemp;         /* particle field "temperature", -1 if no scene uses it */
  int temp_on;       /* a uniform temperature is imposed (thermal.c) */
  struct heat_state *heat; /* heat.h: NULL in a scene without heat */
  double temp;       /* ... its value at the end of the next step */
  int freact;        /* particle field "reacted", -1 if nothing reacts */
  int react_on;      /* some material reacts: the reaction phase runs */
  double t_ignition; /* when a particle first passed it; INFINITY before */
  int react_nsub;    /* most substeps one particle took, last step */
  int fmelt;         /* melt.h: friction heat already seen, -1 if no
                     ** material caps friction heating at T_melt */
  double vmax;       /* fastest particle of the last step */
  size_t nout;       /* particles outside the domain after the last move */
  int started;
  sim_work work;     /* the step's scratch */
  char err[256];
} sim;

/* whether side k pushes particles by springs (wall_contact "penalty"):
** every wall but a mirror plane, which keeps the node rule */
static inline int sim_penalty_side(const sim *s, int k) {
  return s->cfg.wall_rule == WALL_PENALTY && s->sides[k].kind == SIDE_WALL &&
         !s->sides[k].mirror;
}

/* whether side k's wall acts by springs, on the particles ("penalty") or
** on the columns of nodes ("spring"): frictionless walls only */
static inline int sim_spring_side(const sim *s, int k) {
  return (s->cfg.wall_rule == WALL_PENALTY || s->cfg.wall_rule == WALL_SPRING) &&
         s->sides[k].kind == SIDE_WALL && !s->sides[k].mirror;
}

/* bytes of partial sums per chunk of particles (par.h) a phase may use */
#define SIM_RED_BYTES 128

/* defaults: MUSL, flip 1.0, cfl 0.25; 0 or -1 */
int sim_init(sim *s, const double lo[DIM], const double hi[DIM], double h,
             const int periodic[DIM], int shape, int ppc);
void sim_free(sim *s);
/* the threads the steps use (>= 1; the pool is made at the next step) */
void sim_set_threads(sim *s, int n);
/* materials and bodies; index or -1 with s->err set */
int sim_add_material(sim *s, const material *m);
int sim_add_body(sim *s, const char *name, int32_t mat, int32_t field);
/* a contact law between two fields (a != b), mu may be INFINITY; bond:
** the most the interface's bond holds (0 never, INFINITY no cap) */
int sim_set_law(sim *s, int32_t a, int32_t b, double mu, double bond);
/* the law of two fields (b < 0: none, the default) */
const pairlaw *sim_law_of(const sim *s, int32_t a, int32_t b);
double sim_law(const sim *s, int32_t a, int32_t b);
/* give the particles a bond strength field ("bond"); its index or -1 */
int sim_enable_bonds(sim *s);
/* the affine transfers (APIC, SPIN; the caller sets cfg.transfer):
** registers the particles' "affine" field; 0 or -1 */
int sim_enable_apic(sim *s);
/* append a particle of body b at x with volume vol; index or -1 */
long sim_add_particle(sim *s, int32_t b, const double x[DIM],
                      const double v[DIM], double vol);
/* the state before the first step: energies, momenta, the initial energy
** of the budget and the first dt; the first step calls it, and anything
** that reports the state before then may (bodies can still be added) */
void sim_begin(sim *s);
/* the thread pool and the buffers of the threaded phases, made or grown
** if need be; sim_step calls it first, as must code that calls the
** phases below itself.  0, or -1 with s->err */
int sim_prepare(sim *s);
/* one explicit step; 0, or -1 with s->err (e.g. det F <= 0) */
int sim_step(sim *s);
/* the step the CFL rule gives now */
double sim_stable_dt(const sim *s);
/* the scheme as it runs, as mvmpm.sim's fields ("shape = \"bspline2\",
** update = \"musl\", ..."), into buf (n bytes, truncated to fit): what a
** snapshot records, since a scene that leaves a field to the engine gets
** whatever the engine's default was when it ran */
void sim_scheme(const sim *s, char *buf, size_t n);
/* a warning about the scheme the scene chose, or NULL: linear hats under
** pure FLIP (any update), or GIMP under pure FLIP and MUSL, with walls or
** contact, whose energy error on impacts grows as the grid is refined
** (docs/accuracy.md) */
const char *sim_advice(const sim *s);
/* a warning when a wall with friction acts by the node rule, under which
** friction hardly turns a round body (docs/verification.md), or NULL */
const char *sim_wall_advice(const sim *s);
/* a warning when two bodies with flat faces, one of them free, meet with
** contact normals taken node by node, which hold a block sliding on a
** flat body at its corners (docs/verification.md), or NULL */
const char *sim_normals_advice(const sim *s);
/* the slot gradients p2g gathers for the normals: the mass gradient
** (sg) and the volume gradient (sv), which bonds need too (bond.c
** gathers it when p2g did not) */
static inline int sim_mass_grad(const sim *s) {
  return s->cfg.normals == NORMALS_MASS || s->cfg.normals == NORMALS_AUTO;
}
static inline int sim_vol_grad(const sim *s) {
  return s->cfg.normals == NORMALS_AUTO ? s->flatpair
                                        : s->cfg.normals != NORMALS_MASS;
}
/* whether contact_patch.c takes patches this step: body_contact =
** "patch", or "auto" where a flat field meets another */
static inline int sim_body_patches(const sim *s) {
  return s->cfg.body_rule == BODY_PATCH ||
         (s->cfg.body_rule == BODY_AUTO && s->flatmix);
}
/* whether driven slot sl's material stays beyond DRIVE_REACH cells of
** its node (the reach, reach.c, so only with the separation check) where
** it meets field f of a round body: the drive then stops no partner
** there.  Flat bodies keep every node (contact.c says why) */
static inline int sim_drive_far(const sim *s, int32_t f, int32_t sl) {
  return s->cfg.gap_check && !s->fflat[f] && s->g.sext[sl] < -DRIVE_REACH * s->g.h;
}
/* NORMALS_AUTO takes one normal per patch where flat fields meet */
static inline int sim_flat_patches(const sim *s) {
  return s->cfg.normals == NORMALS_AUTO && s->flatpair;
}
/* fflat and flatpair from the bodies as they stand (each step, and
** before a question that maps the particles) */
void sim_flat(sim *s);
/* the step the next sim_step will take (fixed or CFL) */
double sim_next_dt(sim *s);
/* gravity's potential from pe = -sum m g.x over the wrapped positions:
** plus what the periodic wraps took from it (sim_energy.wrap) */
double sim_potential(const sim *s, double pe);
/* total energy, kinetic + strain + lag.  Velocities and stresses are a
** half step apart in the explicit update (as in symplectic Euler), so
** kinetic + strain oscillates by O(omega dt) even when nothing is lost;
** the lag term -dt/2 sum V sigma:D removes that first-order error (it
** is exact for a linear oscillator) */
double sim_total(const sim *s);
/* energy budget residual: initial + boundary + thermal - friction -
** plastic - viscous - settled - transfer - impact - bonding - cohesion -
** removed - total; zero up to the error of the
** step */
double sim_residual(const sim *s);
/* with heat (heat.h): the heat the budget booked into the particles
** (sources + walls and held bodies) less the thermal energy they hold,
** sum m c (T - T0); zero up to round-off when conduction conserves */
double sim_heat_residual(const sim *s);
/* the budget of mechanical and thermal energy together: initial +
** boundary + thermal work + heat_source + heat_boundary - total -
** thermal energy - cold work - heat_wall - settled - transfer - impact
** - removed;
** sim_residual when heat is off */
double sim_residual_all(const sim *s);
/* the budget's scale, which no choice of origin changes (the potential's
** own value does): the kinetic and strain energy at the start plus the
** size of every flow since, |boundary| + |thermal| + |potential change|
** (+ what was settled away); > 0 whenever anything moved */
double sim_scale(const sim *s);
/* stop every particle of a body that is not driven: velocities (and
** APIC's affine field) to zero, the kinetic energy taken out booked as
** e.settled so the budget still closes; returns that energy.  Between
** steps only (a settling step, sim:settle) */
double sim_stop(sim *s);
/* recompute kinetic energy, momenta and strain energy from particles */
void sim_measure(sim *s);

/* phases (one file each) */
void p2g_plan(sim *s);         /* p2g.c: the scatter plan of the step
                                  (bands.h), before marking and p2g */
int p2g_mark(sim *s);          /* mark.c: shared nodes and their slots,
                                  room for the particles' (work.pslot);
                                  0 or -1 (out of memory) */
void p2g(sim *s);              /* p2g.c: mass, momentum, force (USAVG:
                                  mass and momentum) */
void p2g_force(sim *s);        /* p2g.c: the forces alone (USAVG) */
int usf(sim *s);               /* usf.c: USAVG's first half update; 0 or
                                  -1 with s->err */
void solve_momentum(sim *s);   /* solve.c: q = p + dt f */
void solve_velocity(sim *s);   /* solve.c: q -> vL, f -> dv */
void xpic(sim *s);             /* xpic.c: f -> the XPIC(m) correction c */
void solve_remap(sim *s);      /* solve.c: p -> remapped velocity */
void contact_normals(sim *s);  /* contact.c: normals at shared nodes */
void reach(sim *s);            /* reach.c: surfaces, for the gap check */
/* how far field f's material passes side sd's wall line at column j (an
** upper bound where a third field reaches the column) */
double sim_wall_reach(const side *sd, size_t j, int32_t f);
int contact_prepare(sim *s);   /* contact.c: room for its records */
size_t contact_mem(const sim *s); /* ... their bytes, and the slots p2g found */
void contact_apply(sim *s);    /* contact.c: corrects q at shared nodes */
void contact_patches(sim *s, int dry); /* contact_patch.c: ... per
                                  contact patch (body_contact = "patch",
                                  or "auto" where a flat body meets one
                                  that is not), first; dry: kept per slot,
                                  not booked (sim:contacts()) */
void contact_patch_normals(sim *s); /* contact_patch.c: each patch's nodes
                                  given its mean normal (normal_patch) */
/* contact.c: the first half of what slot sl's impulse c dissipates,
** relative to vref; c kept in a for book_finish */
double contact_lose(const grid *g, int32_t sl, const double vref[DIM],
                    const double c[DIM], double *const a[DIM]);
/* bond fit sums: weight, first and second moments of the offset from
** the node, stress (xx, xy, yy), stress times offset (a * DIM + c) */
enum { BF_W, BF_U = 1, BF_UU = 1 + DIM, BF_S = 1 + DIM + DIM * (DIM + 1) / 2,
       BF_SU = BF_S + DIM * (DIM + 1) / 2,
       BF_N = BF_SU + DIM * DIM * (DIM + 1) / 2 };
void bond_gather(sim *s);      /* bond.c: strength, stress at shared slots */
void bond_scatter(sim *s);     /* bond.c: debonding back to particles */
void bond_remap(sim *s);       /* bond.c: bonded slots take the node's
                                  remapped velocity (MUSL), or beside a
                                  driven body the drive's */
/* bond.c: the slot of a driven body with mass at node n, or -1 (the
** partner contact.c gives every other slot there) */
int32_t bond_driven(const sim *s, int32_t n);
/* contact.c: the strength of the bond between slot sl and its partner o
** (odriven: o is a driven body's) as the bond test reads it, the least
** of both sides' (a drive's: the slot's) and their law's cap; 0 where
** either side has none left or the law does not bond them */
double contact_bond(const sim *s, int32_t sl, int32_t o, int odriven);
/* contact.c: the normal traction the bond test reads for slot sl at
** shared node n (odriven: its partner is a driven body's), and the fits
** it reads under bond_traction = "fit" (after bond_gather; the step
** makes them in contact_apply) */
double contact_bond_traction(const sim *s, int32_t n, int32_t sl, int odriven);
void contact_bond_fits(sim *s);
void book_finish(sim *s);     /* book.c: impulses' work, second half */
void boundary_apply(sim *s);   /* boundary.c: sides, drives, on q */
/* wall_penalty.c: the penalty walls' forces on the particles, onto q;
** the energy stored in their springs */
void wall_penalty(sim *s);
void wall_penalty_hold(sim *s); /* MUSL, walls held (sim_wall_hold) */
double wall_penalty_energy(const sim *s);
/* wall_spring.c: side k's springs on q (first..last its wall and ghost
** planes; lab: patch_find's labels of the columns with a spring, np
** patches); then wall_spring_owns: 0 where the node rule acts instead
** (a column with two fields, or a driven body's) */
double wall_spring_k(const sim *s);
void wall_spring_side(sim *s, int k, int first, int last, const int32_t *lab,
                      int np);
int wall_spring_owns(const sim *s, int k, size_t j);
double wall_spring_energy(const sim *s);
void wall_spring_hold(sim *s); /* MUSL, walls held (sim_wall_hold) */
void boundary_remap(sim *s);   /* boundary.c: MUSL remap at the walls */
/* boundary.c: at every node where a wall acted this step, the normal
** component of the node array a and of its slots' array sa set to the
** wall's normal velocity (vel = 1) or to 0 (vel = 0) */
void boundary_normal_set(sim *s, double *const a[DIM],
                         double *const sa[DIM], int vel);
/* whether MUSL's remap holds the walls (boundary_remap) */
int sim_wall_hold(const sim *s);
void g2p(sim *s);              /* g2p.c: velocities; USL: positions, grad v;
                                  MUSL: momenta back to the grid */
void g2p_remap(sim *s);        /* g2p.c: MUSL grad v from remap */
double g2p_affine_energy(const sim *s); /* g2p.c: APIC's affine field's
                                  kinetic energy */
int constitutive(sim *s, double dt); /* sim.c: each material's update
                                  over dt */
void thermal(sim *s);          /* thermal.c: temperature -> eigenstress */
void react(sim *s);            /* react.c: reaction and its heat */
void melt(sim *s);             /* melt.c: friction heat capped at T_melt */
/* a warning when the transfer's losses are large against the friction
** work booked, or NULL (sim.c) */
const char *sim_budget_advice(const sim *s);

#endif
