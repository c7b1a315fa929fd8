/*
** diag_wall.h - where a wall presses on the material, node by node (a
** diagnostic between steps, never part of one).
**
** sim:wall_force gives a wall's total force; a contact patch's size and
** pressure profile (Hertz's radius, say) need the force per node.  The
** grid is rebuilt from the particles as the next step would begin (as
** diag_contact.h does it) and the node rule of the wall (boundary.c) is
** asked, without applying it, what normal impulse dn it would give each
** node of the wall's planes: dn = sign (q - m v_w)_d where the node
** approaches, and with the separation check only where the material
** reaches the wall line (under contact_gap = "step", only the part of
** the approach that would overlap).  dn / dt is the node's compressive
** normal force.  Under wall_contact = "patch" or "couple" the step
** spreads a patch's impulse by mass; this reports the node rule's share,
** which has the same sum on a patch at rest.
*/
#ifndef mvmpm_diag_wall_h
#define mvmpm_diag_wall_h

#include "sim.h"

typedef struct wall_press {
  double x[DIM];    /* the node's position */
  double fn;        /* its compressive normal force (> 0) */
} wall_press;

/* The nodes side k presses on now, in node order, into *out (malloc'd,
** the caller frees; NULL when none) and their count into *n.  Rebuilds
** the grid (the next step rebuilds it again: the run's numbers do not
** change).  A side that is not a wall, or a mirror plane, presses
** nowhere.  0, or -1 with s->err (out of memory) */
int diag_wall(sim *s, int k, wall_press **out, size_t *n);

#endif
