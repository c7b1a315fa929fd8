/*
** heat.h - temperature as a computed field: heat sources and the
** temperature update.  Conduction is conduct.h's.
**
** A scene without heat has s->heat == NULL and pays nothing: no arrays,
** no passes.  With heat on, every particle has a temperature T, its
** material's specific heat c (per unit mass) and a per-step heat
** accumulator q (J).  What the energy budget books as dissipated becomes
** heat, each joule once:
**   plastic work      beta W_p to the particle that did it (the model
**                     adds it as it books W_p); (1 - beta) W_p is cold
**                     work, stored in the material (e.cold)
**   viscous           all of it, to the particle that did it
**   contact friction  the node's friction work, split between the fields
**                     at the node (heat_state.split), each field's share
**                     to its particles by their mass share N_ip m_p / m_i
**                     of the field's nodal mass, so it sums exactly to the
**                     booked work
**   wall friction     a fraction wall_share to the material at the node,
**                     the rest leaves through the wall (e.heat_wall)
**   anything else     heat_add (e.g. a reaction), booked by its caller
** At the step's end each particle takes T += q / (m c) (heat_update),
** and the thermal expansion phase (thermal.h) takes that change.
**
** The order in the step: contact and walls put friction heat on the
** nodes; before g2p (the particles still where p2g saw them) heat_grid
** gives it to the particles and runs conduction; the constitutive update
** adds plastic and viscous heat; heat_update then updates T.  A phase
** that adds heat between the constitutive update and heat_update (a
** reaction) calls heat_add.
*/
#ifndef mvmpm_heat_h
#define mvmpm_heat_h

#include "sim.h"

/* the thermal condition of a domain side (conduct.c) */
enum heat_wall_kind { HEAT_INSULATED, HEAT_FIXED, HEAT_FILM };
/* thermal contact between fields at shared nodes (conduct.c) */
enum heat_contact_kind { HEAT_PERFECT, HEAT_CONDUCTANCE };
/* how a contact node's friction heat is split between its fields */
enum heat_split_kind { HEAT_SPLIT_SHARE, HEAT_SPLIT_EFFUSIVITY };

typedef struct heat_wall {
  int kind;        /* enum heat_wall_kind */
  double T;        /* HEAT_FIXED: the wall's; HEAT_FILM: the ambient */
  double h;        /* HEAT_FILM: heat-transfer coefficient (W/(m^2 K)) */
} heat_wall;

typedef struct heat_state {
  int fq;          /* particle field "heat_step": J added this step (no
                      output: zero between steps) */
  int fheat;       /* "heat": J deposited by the sources, cumulative */
  int ffric;       /* "heat_friction": the friction part of it */
  int split;       /* enum heat_split_kind */
  double share;    /* HEAT_SPLIT_SHARE: the share of the first field (the
                      lower index) at a two-field node; 0.5 by default */
  double wall_share; /* fraction of wall friction heat to the material */
  int contact;     /* enum heat_contact_kind */
  double hc;       /* HEAT_CONDUCTANCE: interface conductance W/(m^2 K) */
  heat_wall walls[NSIDES];
  int conduct;     /* some material conducts (k > 0) or a side or body
                      exchanges heat: conduction runs */
  double *feff;    /* per field: its friction weight (effusivity) */
  /* friction heat on the grid this step (J): per node (dense, nodes no
  ** other field shares) and per slot */
  double *hn, *hs;
  size_t hscap;
  /* the walls' friction impulses at slots this step (book.c keeps them
  ** mixed with contact's in sfi): heat_finish tells the two apart */
  double *swi[DIM];
  /* conduct.c's nodal arrays (dense and per slot), made at the start */
  double *nC, *nT, *nQ, *nT0, *nH, *nHT, *nA[DIM];
  double *sC, *sT, *sQ, *sT0, *sH, *sHT, *sA[DIM];
  size_t hscap_c;  /* ... the slots' room */
  double *hcond;   /* per particle: conduction's J this step */
  double *tgrid;   /* per particle: the temperature field conduction
                      resolves, sum_i N_ip T_i after this step's
                      conduction (the reaction's temperature) */
  size_t pgcap;    /* ... their room */
  size_t nsub;     /* conduction substeps of the last step */
  double dtc;      /* conduction's stable step of the last step */
  double E0;       /* sum m c T at the start (thermal energy origin) */
  int ready;       /* heat_start ran (at the first step, or the first
                      after a restart) */
} heat_state;

/* switch heat on (before the first step): registers the particle fields
** "temperature" (if not yet), "heat", "heat_friction" and the
** accumulator, and the defaults (split 0.5, walls insulated, perfect
** contact, wall friction all to the material).  0, or -1 with s->err */
int heat_enable(sim *s);
/* checks at the first step of this process (every material with c > 0,
** the grid's and conduction's arrays); before the simulation's first
** step also the held bodies' temperatures and the thermal energy's
** origin E0 (a restart reads E0 back); 0, or -1 with s->err */
int heat_start(sim *s);
void heat_free(sim *s);

/* add q joules to particle i in this step (any thread, each particle
** from one thread only).  The caller books the sum in the budget as
** s->e.heat_source (added in a fixed order, for determinism) */
static inline void heat_add(sim *s, size_t i, double q) {
  ((double *)particles_comp(&s->ps, s->heat->fq, 0))[i] += q;
}

/* before contact: room for and zero the nodal friction heat; 0 or -1 */
int heat_prepare(sim *s);
/* contact.c: the friction work fric of shared node n (slots[0..ns),
** drv: the driven body's slot or -1) onto its fields' slots */
void heat_contact(sim *s, const int32_t *slots, int ns, int32_t drv,
                  double fric);
/* boundary.c: a wall's friction work at node n (sl < 0) or slot sl */
void heat_wall_friction(sim *s, int32_t n, int32_t sl, double loss);
/* boundary.c: a wall's friction impulse c at slot sl, kept for
** heat_finish */
static inline void heat_wall_impulse(sim *s, int32_t sl, int d, double c) {
  s->heat->swi[d][sl] += c;
}
/* before g2p: the nodes' friction heat to the particles, and conduction */
int heat_grid(sim *s);
/* the second half of the friction impulses' work (book.c), split and
** given to the particles as the first: after book_finish under MUSL
** (before the remap pass moves the particles), just before g2p under
** USL, from the same velocities book_finish reads */
void heat_finish(sim *s);
/* after the constitutive update: T += q / (m c), thermal strain, sums */
void heat_update(sim *s);
/* sum m c (T - T0) over the particles: the thermal energy */
double heat_energy(const sim *s);
/* the heat the budget says the particles hold: sources + what came in
** through walls and held bodies */
double heat_booked(const sim *s);

#endif
