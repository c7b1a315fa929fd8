/*
** diag_contact.h - which bodies press on which, and how hard (a
** diagnostic between steps, never part of one).
**
** The grid is rebuilt from the particles as they are, as the next step
** would begin (p2g, the momentum update, the normals and, with the
** separation check, the reach), and at every shared node the contact
** rule is asked, without applying it, what normal impulse it would give
** each field: dn = (q_r - m_r v_ref) . n_r where the field approaches
** (dn > 0) and the surfaces touch.  dn / dt is the compressive normal
** force the node passes to field r.  Summed per pair of fields (r and
** its partner at the node, the partner chosen as contact_apply chooses
** it), it is the force one body puts on the other.  Bonds are not asked:
** a bonded interface is reported where it is in compression.
*/
#ifndef mvmpm_diag_contact_h
#define mvmpm_diag_contact_h

#include "sim.h"

typedef struct contact_pair {
  int32_t a, b;     /* bodies, a < b (the first body of each field) */
  double fn;        /* compressive normal force between them (> 0) */
  double f[DIM];    /* the normal force on a from b (vector) */
  long nodes;       /* shared nodes where they press */
} contact_pair;

/* The grid as the next step begins: p2g, the momentum update, the
** normals and, with the separation check, the reach (walls and shared
** nodes), for the diagnostics that ask the step's rules without applying
** them.  0, or -1 with s->err (out of memory) */
int diag_grid(sim *s);

/* The pairs in contact now, sorted by (a, b), into *out (malloc'd, the
** caller frees; NULL when none) and their count into *n.  Rebuilds the
** grid (the next step rebuilds it again: the run's numbers do not
** change).  0, or -1 with s->err (out of memory) */
int diag_contacts(sim *s, contact_pair **out, size_t *n);

#endif
