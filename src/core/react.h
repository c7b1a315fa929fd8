/*
** react.h - single-step Arrhenius reaction on the particles.
**
** Each particle of a reacting material carries its reacted fraction
** lambda (field "reacted", 0 unburnt .. 1 burnt) and its temperature T:
**   d lambda / dt = Z (1 - lambda)^n k(T)
**   c dT / dt     = Q d lambda / dt          (within the reaction phase)
** with k(T) = exp(-Ta / T) (Arrhenius, Ta = E / R) or, for verification
** against Frank-Kamenetskii's theory, the linearised exponent
** k(T) = exp(-Ta / T0) exp(Ta (T - T0) / T0^2) about a chosen T0.
**
** The phase runs once per step after everything else that heats the
** particles (conduction, friction, plastic and viscous heat: heat.h),
** as its own operator, before heat_update: each particle's (T, lambda) is
** advanced over the step by the exact solution at a frozen rate
** constant (exact for constant T, so first-order decay is exact to
** round-off), with the rate constant taken at the midpoint temperature
** of the substep (second order), and with substeps as short as needed
** for the exponent Ta / T to change by at most `tol` over each.  It
** starts from the temperature the step's other heat leads to, T + (q +
** conducted) / (m c); the heat of each substep, Q d lambda, moves T
** exactly, and the step's total m Q d lambda goes to the particle with
** heat_add, so heat_update brings T to where the substeps ended and the
** chemical energy released equals the particles' gain to round-off.  A
** run-away therefore resolves its own time scale whatever the
** mechanical step, and a step costs one rate evaluation per particle
** (two with the midpoint) while nothing runs away.
**
** Nothing is allocated; no material reacting means the phase never runs
** and no field is registered.
*/
#ifndef mvmpm_react_h
#define mvmpm_react_h

#include "sim.h"

/* a material's kinetics are its react_law (material.h) */

/* the defaults every reaction option starts from */
#define REACT_TOL 0.05    /* largest change of Ta / T over a substep */
#define REACT_MAXSUB 4096 /* substeps of one particle in one step */

/* the rate constant of law r at temperature T (without Z (1-l)^n) */
double react_k(const react_law *r, double T);

/*
** Advance one particle over dt: *T and *lam in place; cap is the
** specific heat (Q / cap is the adiabatic temperature rise of a full
** burn).  tol as REACT_TOL.  Returns the reacted fraction gained; *nsub
** gets the substeps taken.  If lam_ign is in (0, 1] and lambda crosses
** it in this step, *t_ign gets the time from the step's start at which
** it did (linear within the substep), else it is left alone.
*/
double react_advance(const react_law *r, double cap, double tol, double dt,
                     double *T, double *lam, double lam_ign, double *t_ign,
                     int *nsub);

/* register the "reacted" field (once) and mark the simulation reacting;
** heat is switched on (heat_enable) if it is not.  0, or -1 with s->err */
int react_enable(sim *s);

/* react(s) (sim.h) is the phase over s->dt, after every other heat
** source; the chemical energy released goes to s->e.chemical, the first
** time any particle's lambda passes s->cfg.react_ign to s->t_ignition */

/* mass-weighted mean reacted fraction of the reacting particles (0 when
** none react) */
double react_mean(const sim *s);

#endif
