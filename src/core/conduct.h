/*
** conduct.h - heat conduction on the grid, per velocity field, as the
** momentum equation is solved (docs/algorithm.md, conduction):
**   C_i = sum_p N_ip m_p c_p         (nodal heat capacity)
**   T_i = sum_p N_ip m_p c_p T_p / C_i
**   Q_i = -sum_p V_p k_p grad N_ip . grad T_p,
**         grad T_p = sum_j grad N_jp T_j
**   T_i += dt Q_i / C_i,  then each particle takes the increment
**   dT_p = sum_i N_ip (T_i - T_i^0), i.e. m_p c_p dT_p joules.
** sum_i grad N_ip = 0, so the heat flows only between nodes, and the
** particles' increments add up to sum_i C_i (T_i - T_i^0): conduction
** conserves heat except what walls and held bodies exchange, which is
** booked (e.heat_boundary).
**
** Thermal contact between fields at shared nodes is perfect (one
** temperature: the fields share the node, conduction runs on the centre
** of mass arrays) or through an interface conductance h (each field has
** its own temperature at the node; the pair exchanges h A (T_b - T_a),
** A the mean of the two fields' |sum_p V_p grad N_ip|, the interface
** area the node stands for, integrated exactly over the substep).
** Walls are insulated, at a fixed temperature (their nodes held at it),
** or exchange h A (T_amb - T_i) with A the material's outward volume
** gradient at the wall nodes.  A held body's particles keep their
** temperature; at each node their share of the capacity is reset to it
** every substep (a reservoir).
**
** Explicit conduction is stable for dt <= h^2 rho c / (2 DIM k): the
** step is cut into substeps within 0.9 of that (conduct_dt); the
** exchanges at interfaces and walls are exact exponentials.
*/
#ifndef mvmpm_conduct_h
#define mvmpm_conduct_h

#include "sim.h"

/* at the first step: the dense nodal arrays; 0 or -1 with s->err */
int conduct_start(sim *s);
/* each step: room for the slots' and particles' arrays; 0 or -1 */
int conduct_prepare(sim *s);
void conduct_free(sim *s);
/* the stable conduction step now (INFINITY if nothing conducts) */
double conduct_dt(const sim *s);
/* one step of conduction: each particle's joules in heat->hcond; 0, or
** -1 with s->err */
int conduct(sim *s);

#endif
