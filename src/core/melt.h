/*
** melt.h - the melting cap of friction heating.
**
** A material with T_melt > 0 does not heat above T_melt by friction: a
** sliding surface that reaches its melting point melts, and the work
** goes to the latent heat instead of the temperature.  Each step, the
** friction heat a particle received (heat.h's "heat_friction" since the
** last step) is cut so that the temperature the step's heat leads to,
** T + (q + conducted) / (m c), does not pass T_melt; the part cut is
** taken back from the step's heat and booked as latent heat (e.latent),
** which the heat budget counts as heat that left the particles, so it
** still closes.  Other heat (plastic, viscous, conduction, reaction) is
** not capped.  The latent heat is not stored as a melt fraction: there
** is no solidification.
*/
#ifndef mvmpm_melt_h
#define mvmpm_melt_h

#include "sim.h"

/* some material has T_melt: register the particle field that remembers
** the friction heat already seen (checkpointed, not output), and switch
** the phase on; heat must be on.  0, or -1 with s->err */
int melt_enable(sim *s);

#endif
