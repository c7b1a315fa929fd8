/*
** out_xdmf.h - the XDMF index of a snapshot series, so ParaView (or any
** XDMF reader) opens the time series directly.  Rewritten whole (temp
** name + rename) after every snapshot.
**
** XDMF 2.0: one temporal collection, one Polyvertex grid per entry whose
** connectivity is "file:/xdmf/vertex" and whose Geometry (XY, or XYZ in
** 3-D) is "file:/position".  Each other PF_OUTPUT field becomes: a
** Scalar (one component); a Vector (components x, y (, z), padded to 3
** by the XDMF 2 reader); a Tensor (a 3-D full tensor row by row, F); or
** else a Matrix, one array of the (n, ncomp) dataset in the snapshot's
** order (the stress: xx,yy,xy,zz in 2-D, xx,yy,zz,xy,yz,xz in 3-D, which
** is VTK's order for a symmetric tensor).  An entry with n == 0 gets one
** placeholder point and no cells or attributes, as ParaView's XDMF 2
** reader cannot read empty arrays.
** Read by ParaView's XDMFReader, Xdmf3ReaderS and Xdmf3ReaderT alike;
** tests/tools/check_xdmf.py checks a series in ParaView with each.
*/
#ifndef mvmpm_out_xdmf_h
#define mvmpm_out_xdmf_h

#include <stddef.h>
#include "particles.h"

typedef struct xdmf_entry {
  char file[256]; /* snapshot file name, relative to the .xmf */
  double time;
  size_t n;       /* particles in that snapshot */
} xdmf_entry;

/* the field list (PF_OUTPUT fields of ps) is the same for every entry.
** 0, or -1 with a message naming path in err: no 2-D/3-D "position"
** output in ps, an entry file name that is empty, unterminated or holds
** ':' (XDMF's file/dataset separator), or a failed write (nothing is
** left under path or its temp name then). */
int out_xdmf_write(const char *path, const xdmf_entry *e, int ne,
                   const particles *ps, char *err, size_t errlen);

#endif
