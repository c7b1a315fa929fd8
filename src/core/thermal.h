/*
** thermal.h - temperature and thermal expansion.
**
** Plane strain convention (3-D bulk modulus K, eps_zz = 0): a material
** with linear expansion coefficient alpha has the eigenstrain
** alpha (T - T_ref) I in 3-D terms, so the mechanical strain rate is
** D - alpha T' I with D_zz = 0.  For an isotropic model the stress
** response to a temperature change dT over a step is therefore
**   d sigma = -3 K alpha dT I    (xx, yy and zz alike),
** purely hydrostatic.  It commutes with the objective rotation and
** leaves the deviator alone, so it is applied by its own phase before
** the constitutive update and no model needs to know about temperature
** (J2 yield and the Maxwell elements depend on the deviator only).  A
** free body then expands in plane by (1 + nu) alpha dT; a fully held
** one is stressed by -3 K alpha dT.  In 3-D (DIM = 3, no eps_zz = 0)
** the increment is the same and a free body expands by alpha dT along
** every axis.
**
** The seeded shape is the stress-free shape at T_ref: a particle that
** starts at another temperature T0 starts with the stress of a fully
** held body, -3 K alpha (T0 - T_ref) I, applied before the first step.
**
** The particle field "temperature" exists only in scenes that use
** temperature; the phase runs only while a uniform temperature is
** imposed (sim.temp_on).  Each step brings every particle to sim.temp,
** the temperature at the end of the step, so the change of the step is
** well defined: dT = temp - T(particle).
*/
#ifndef mvmpm_thermal_h
#define mvmpm_thermal_h

#include "sim.h"

/* register the temperature field (once); particles present get their
** material's T_ref.  0, or -1 out of memory */
int thermal_enable(sim *s);
/* temperature of particles [from, to): *T0, or if T0 is NULL the
** uniform temperature if one is imposed, else their material's T_ref */
void thermal_seed(sim *s, size_t from, size_t to, const double *T0);
/* impose a uniform temperature from now on; before the first step it is
** also every particle's initial temperature */
int thermal_uniform(sim *s, double T);
/* the thermal strain of a change dT of particle i (material m): the
** stress increment -3 K alpha dT I; returns the work it adds to the
** strain energy (heat.c's temperature update) */
double thermal_strain(const material *m, particles *ps, size_t i, double dT);
/* before the first step: the stress of particles not at T_ref */
void thermal_prestress(sim *s);

#endif
