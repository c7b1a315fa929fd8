/*
** out_xdmf.c - the XDMF index of a snapshot series (see out_xdmf.h).
** XDMF 2: a temporal collection of polyvertex grids whose arrays live in
** the HDF5 snapshots.  A field of one component is a Scalar attribute; a
** field whose components are x, y (, z) is a Vector (ParaView's XDMF 2
** reader pads a 2-D vector with z = 0, which glyphs need); a full 3 x 3
** tensor stored row by row (F in 3-D: xx,xy,xz,yx,..,zz) is a Tensor,
** XDMF's own layout; any other field of several components is a Matrix
** of its (n, ncomp) dataset, one array of ncomp components in the
** snapshot's order (its "components" attribute: stress xx,yy,xy,zz in
** 2-D, xx,yy,zz,xy,yz,xz in 3-D; F xx,xy,yx,yy in 2-D).
** The 3-D stress is not a Tensor6: ParaView's XDMF 2 reader takes a
** Tensor6 as xx,xy,xz,yy,yz,zz and expands it to 9 components, while its
** Xdmf3 readers pass the 6 values on as they are, which VTK reads as
** xx,yy,zz,xy,yz,xz; no one order is right for all three.  The snapshot's
** order is VTK's own, so as a Matrix every reader shows it right.  A
** HyperSlab per component (the other way to name them) is dropped by
** ParaView's Xdmf3 readers; a Matrix is read by all three.
*/
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ofile.h"
#include "out_xdmf.h"

/* XDMF's name for DIM coordinates per point */
static const char *const geometry[] = {"X", "XY", "XYZ"};
#define GEOMETRY (geometry[DIM - 1])

/* text with the five XML special characters escaped */
static void xml(FILE *fp, const char *s) {
  for (; *s; s++) {
    switch (*s) {
      case '&': fputs("&amp;", fp); break;
      case '<': fputs("&lt;", fp); break;
      case '>': fputs("&gt;", fp); break;
      case '"': fputs("&quot;", fp); break;
      case '\'': fputs("&apos;", fp); break;
      default: fputc(*s, fp);
    }
  }
}

/* the HDF5 reference "file:/dataset" with its number type */
static void heavy(FILE *fp, const xdmf_entry *e, const pfield *f,
                  const char *indent) {
  fprintf(fp, "%s<DataItem Format=\"HDF\" NumberType=\"%s\" Precision=\"%d\""
          " Dimensions=\"%zu", indent, f->type == PF_INT32 ? "Int" : "Float",
          f->type == PF_INT32 ? 4 : 8, e->n);
  if (f->ncomp > 1) fprintf(fp, " %d", f->ncomp);
  fputs("\">", fp);
  xml(fp, e->file);
  fputs(":/", fp);
  xml(fp, f->name);
  fputs("</DataItem>\n", fp);
}

/* the whole dataset as one attribute: "Scalar", "Vector", "Tensor" or
** "Matrix" */
static void whole(FILE *fp, const xdmf_entry *e, const pfield *f,
                  const char *type) {
  fputs("    <Attribute Name=\"", fp);
  xml(fp, f->name);
  fprintf(fp, "\" AttributeType=\"%s\" Center=\"Node\">\n", type);
  heavy(fp, e, f, "     ");
  fputs("    </Attribute>\n", fp);
}

/* a spatial vector: DIM components named x, y (, z) */
static int isvector(const pfield *f) {
  static const char *const xyz[] = {"x", "y", "z"};
  int c;
  if (f->ncomp != DIM) return 0;
  for (c = 0; c < DIM; c++)
    if (!f->comp_names[c] || strcmp(f->comp_names[c], xyz[c]) != 0) return 0;
  return 1;
}

/* a full 3 x 3 tensor row by row (xx, xy, xz, yx, .., zz): XDMF's Tensor */
static int istensor(const pfield *f) {
  int c;
  if (f->ncomp != 9 || NTENS != 9) return 0;
  for (c = 0; c < 9; c++)
    if (!f->comp_names[c] || !particles_tens_name(c) ||
        strcmp(f->comp_names[c], particles_tens_name(c)) != 0)
      return 0;
  return 1;
}

/* the shortest decimal that reads back as x: 0.05, not 0.05000000000000000277 */
static void number(FILE *fp, double x) {
  char buf[32];
  int p;
  for (p = 15; p < 17; p++) {
    snprintf(buf, sizeof buf, "%.*g", p, x);
    if (strtod(buf, NULL) == x) break;
  }
  if (p == 17) snprintf(buf, sizeof buf, "%.17g", x);
  fputs(buf, fp);
}

/*
** A step without particles.  ParaView's XDMF 2 reader fails on arrays of
** size 0 and crashes on a grid without geometry, so the grid gets one
** placeholder point at the origin, no cells and no attributes: nothing
** is drawn, and the cell count is still the particle count.
*/
static void nogrid(FILE *fp) {
  int d;
  fprintf(fp, "    <Topology TopologyType=\"Polyvertex\" NumberOfElements="
          "\"0\" NodesPerElement=\"1\"/>\n"
          "    <Geometry GeometryType=\"%s\">\n"
          "     <DataItem Format=\"XML\" NumberType=\"Float\" Precision=\"8\""
          " Dimensions=\"1 %d\">", GEOMETRY, DIM);
  for (d = 0; d < DIM; d++) fputs(d ? " 0" : "0", fp);
  fputs("</DataItem>\n"
        "    </Geometry>\n", fp);
}

static void grid(FILE *fp, const xdmf_entry *e, const particles *ps,
                 const pfield *pos) {
  int f;
  fputs("   <Grid Name=\"particles\" GridType=\"Uniform\">\n"
        "    <Time Value=\"", fp);
  number(fp, e->time);
  fputs("\"/>\n", fp);
  if (e->n == 0) {
    nogrid(fp);
    fputs("   </Grid>\n", fp);
    return;
  }
  /* the connectivity is given (the snapshot's /xdmf/vertex): ParaView's
  ** Xdmf3 readers make no cells from the counts alone */
  fprintf(fp, "    <Topology TopologyType=\"Polyvertex\" NumberOfElements="
          "\"%zu\" NodesPerElement=\"1\">\n"
          "     <DataItem Format=\"HDF\" NumberType=\"Int\" Precision=\"4\""
          " Dimensions=\"%zu\">", e->n, e->n);
  xml(fp, e->file);
  fprintf(fp, ":/xdmf/vertex</DataItem>\n"
          "    </Topology>\n"
          "    <Geometry GeometryType=\"%s\">\n", GEOMETRY);
  heavy(fp, e, pos, "     ");
  fputs("    </Geometry>\n", fp);
  for (f = 0; f < ps->nfields; f++) {
    const pfield *pf = &ps->fields[f];
    if (!(pf->flags & PF_OUTPUT) || pf == pos) continue;
    if (pf->ncomp == 1) whole(fp, e, pf, "Scalar");
    else if (isvector(pf)) whole(fp, e, pf, "Vector");
    else if (istensor(pf)) whole(fp, e, pf, "Tensor");
    else whole(fp, e, pf, "Matrix");
  }
  fputs("   </Grid>\n", fp);
}

/*
** What a reader would choke on is refused here, where the message can
** say why: an unterminated name, or a ':' that XDMF would take for the
** file/dataset separator.
*/
static const char *badentry(const xdmf_entry *e) {
  if (!memchr(e->file, '\0', sizeof e->file))
    return "file name is not terminated";
  if (!e->file[0]) return "file name is empty";
  if (strchr(e->file, ':')) return "file name contains ':'";
  return NULL;
}

static int check(const char *path, const xdmf_entry *e, int ne,
                 const particles *ps, char *err, size_t errlen) {
  int i, f = particles_find(ps, "position");
  if (f < 0 || !(ps->fields[f].flags & PF_OUTPUT) ||
      ps->fields[f].ncomp != DIM || ps->fields[f].type != PF_DOUBLE) {
    snprintf(err, errlen, "%s: the store has no %d-D position output", path,
             DIM);
    return -1;
  }
  for (i = 0; i < ne; i++) {
    const char *why = badentry(&e[i]);
    if (why) {
      snprintf(err, errlen, "%s: entry %d: %s", path, i, why);
      return -1;
    }
  }
  return f;
}

static void document(FILE *fp, const xdmf_entry *e, int ne,
                     const particles *ps, const pfield *pos) {
  int i;
  fputs("<?xml version=\"1.0\" ?>\n"
        "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        "<Xdmf Version=\"2.0\">\n"
        " <Domain>\n"
        "  <Grid Name=\"series\" GridType=\"Collection\""
        " CollectionType=\"Temporal\">\n", fp);
  for (i = 0; i < ne; i++) grid(fp, &e[i], ps, pos);
  fputs("  </Grid>\n </Domain>\n</Xdmf>\n", fp);
}

int out_xdmf_write(const char *path, const xdmf_entry *e, int ne,
                   const particles *ps, char *err, size_t errlen) {
  char dummy[1], *tmp;
  FILE *fp;
  int f, bad, r = -1;
  if (!err || !errlen) err = dummy, errlen = sizeof dummy;
  err[0] = '\0';
  f = check(path, e, ne, ps, err, errlen);
  if (f < 0) return -1;
  tmp = malloc(strlen(path) + 5);
  if (!tmp) {
    snprintf(err, errlen, "%s: out of memory", path);
    return -1;
  }
  sprintf(tmp, "%s.tmp", path);
  errno = 0;
  fp = ofile_fcreate(tmp, "w"); /* never through a link */
  if (!fp) {
    snprintf(err, errlen, "%s: cannot create file (%s)", path,
             strerror(errno));
    free(tmp);
    return -1;
  }
  errno = 0; /* a failed write leaves its reason for ferror/fclose */
  document(fp, e, ne, ps, &ps->fields[f]);
  bad = ferror(fp);
  if (fclose(fp) != 0 || bad)
    snprintf(err, errlen, "%s: cannot write file (%s)", path,
             errno ? strerror(errno) : "I/O error");
  else if (rename(tmp, path) != 0)
    snprintf(err, errlen, "%s: cannot rename the temp file %s (%s)", path,
             tmp, strerror(errno));
  else
    r = 0;
  if (r != 0) remove(tmp);
  free(tmp);
  return r;
}
