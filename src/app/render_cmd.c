/*
** render_cmd.c - the render command: read a snapshot or a checkpoint,
** draw it.  The picture is framed by the domain the file records and
** its legend names the bodies; files from before those were stored are
** framed by the particles' extent and say "body N".  A 3-D file is drawn
** looking along --axis (z by default): a slice at --at (the middle of
** the stored domain by default) or, with --project, all the particles
** (render_png.h); --domain is then the window in the picture's axes.
*/
#include <math.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ckpt.h"
#include "cmap.h"
#include "out_h5.h"
#include "pcheck.h"
#include "png.h"
#include "render_cmd.h"
#include "app.h"
#include "lsim.h"
#include "render_png.h"

static const char *prog = "mvmpm render";

/* n comma-separated finite numbers */
static int numlist(const char *s, double *v, int n) {
  int k;
  char *end;
  for (k = 0; k < n; k++) {
    v[k] = strtod(s, &end);
    if (end == s || !isfinite(v[k])) return -1;
    s = end;
    if (k < n - 1) {
      if (*s != ',') return -1;
      s++;
    }
  }
  return *s ? -1 : 0;
}

static int usage_error(const char *msg, const char *arg) {
  fprintf(stderr, "%s: %s%s%s\n"
          "usage: mvmpm render SNAPSHOT.h5|CHECKPOINT.h5 [--by KEY] "
          "[--out FILE.png|FILE.svg] [--width N]\n"
          "                    [--range LO,HI|robust|full] [--log] "
          "[--colormap auto|seq|div] [--title TEXT]\n"
          "                    [--domain X0,X1,Y0,Y1] [--no-axes] "
          "[--matrix BODY]\n"
          "                    3-D: [--axis x|y|z] [--at POS] [--thick T] "
          "[--project]\n", prog, msg, arg ? " " : "", arg ? arg : "");
  return 2;
}

/* a snapshot, else a checkpoint (its particle fields; the run's state
** is not read) */
static int readfile(const char *snap, particles *ps, h5meta *meta,
                    h5frame *fr, int *ck, char *err, size_t errlen) {
  *ck = 0;
  if (out_h5_read_frame(snap, NULL, ps, meta, fr, err, errlen) == 0) return 0;
  if (!strstr(err, "format '" CKPT_FORMAT "'")) return -1;
  particles_free(ps);
  particles_init(ps);
  *ck = 1;
  return out_h5_read_frame(snap, CKPT_FORMAT, ps, meta, fr, err, errlen);
}

int render_cmd(int argc, char **argv) {
  const char *snap = NULL, *out = NULL, *title = NULL;
  char outbuf[4096], titlebuf[160], err[2048];
  const char **names = NULL;
  int *driven = NULL;
  render_opts o;
  pcheck_lim lim = {0};
  particles ps;
  h5meta meta;
  h5frame fr;
  double dom[4];
  int i, has_domain = 0, rc = 0, d, ck = 0, h, u, along;
  memset(&o, 0, sizeof o);
  o.by = "body";
  o.width = 800;
  o.cmap = RENDER_AUTO;
  for (i = 2; i < argc; i++) {
    const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
    int takes = strcmp(a, "--by") == 0 || strcmp(a, "--out") == 0 ||
                strcmp(a, "--width") == 0 || strcmp(a, "--range") == 0 ||
                strcmp(a, "--colormap") == 0 || strcmp(a, "--title") == 0 ||
                strcmp(a, "--domain") == 0 || strcmp(a, "--matrix") == 0 ||
                strcmp(a, "--axis") == 0 || strcmp(a, "--at") == 0 ||
                strcmp(a, "--thick") == 0;
    if (takes && !val) return usage_error("missing value after", a);
    if (strcmp(a, "--by") == 0) o.by = val;
    else if (strcmp(a, "--out") == 0) out = val;
    else if (strcmp(a, "--title") == 0) title = val;
    else if (strcmp(a, "--matrix") == 0) o.matrix = val;
    else if (strcmp(a, "--log") == 0) o.log = 1;
    else if (strcmp(a, "--no-axes") == 0) o.noaxes = 1;
    else if (strcmp(a, "--project") == 0) o.project = 1;
    else if (strcmp(a, "--axis") == 0) o.axis = val;
    else if (strcmp(a, "--at") == 0) {
      if (numlist(val, &o.at, 1)) {
        fprintf(stderr, "%s: --at must be a finite number (got '%s')\n", prog,
                val);
        return 2;
      }
      o.has_at = 1;
    } else if (strcmp(a, "--thick") == 0) {
      if (numlist(val, &o.thick, 1) || !(o.thick > 0)) {
        fprintf(stderr, "%s: --thick must be a number above 0 (got '%s')\n",
                prog, val);
        return 2;
      }
    }
    else if (strcmp(a, "--width") == 0) {
      char *end;
      long w = strtol(val, &end, 10);
      if (end == val || *end || w < RENDER_MINW || w > PNG_MAXDIM) {
        fprintf(stderr, "%s: --width must be a whole number in [%d, %d] (got '%s')\n",
                prog, RENDER_MINW, PNG_MAXDIM, val);
        return 2;
      }
      o.width = (int)w;
    } else if (strcmp(a, "--range") == 0) {
      if (strcmp(val, "robust") == 0) o.autorange = RENDER_ROBUST;
      else if (strcmp(val, "full") == 0) o.autorange = RENDER_FULL;
      else if (numlist(val, o.range, 2) || !(o.range[1] > o.range[0])) {
        fprintf(stderr, "%s: --range must be LO,HI with LO < HI, robust or "
                "full (got '%s')\n", prog, val);
        return 2;
      } else o.has_range = 1;
    } else if (strcmp(a, "--colormap") == 0) {
      if (strcmp(val, "auto") == 0) o.cmap = RENDER_AUTO;
      else if (strcmp(val, "seq") == 0) o.cmap = CMAP_SEQ;
      else if (strcmp(val, "div") == 0) o.cmap = CMAP_DIV;
      else {
        fprintf(stderr, "%s: --colormap must be auto, seq or div (got '%s')\n",
                prog, val);
        return 2;
      }
    } else if (strcmp(a, "--domain") == 0) {
      if (numlist(val, dom, 4) || !(dom[1] > dom[0]) || !(dom[3] > dom[2])) {
        fprintf(stderr, "%s: --domain must be X0,X1,Y0,Y1 with X0 < X1 and "
                "Y0 < Y1 (got '%s')\n", prog, val);
        return 2;
      }
      has_domain = 1;
    } else if (a[0] == '-' && a[1]) return usage_error("unknown option", a);
    else if (!snap) snap = a;
    else return usage_error("unexpected argument", a);
    if (takes) i++;
  }
  if (!snap) return usage_error("no snapshot given", NULL);
  /* a snapshot of the other dimension is drawn by that dimension's code */
  {
    struct stat st; /* a regular file only: a FIFO would block */
    if (stat(snap, &st) == 0 && S_ISREG(st.st_mode) &&
        out_h5_file_dim(snap) == LSIM_OTHER_DIM)
      return APP_REDO;
  }
  if (render_view_axes(o.axis, &h, &u, &along, err, sizeof err)) {
    fprintf(stderr, "%s: --axis: %s\n", prog, err);
    return 2;
  }
  if (!out) {
    size_t n = strlen(snap);
    if (n > 3 && strcmp(snap + n - 3, ".h5") == 0) n -= 3;
    if ((size_t)snprintf(outbuf, sizeof outbuf, "%.*s_%s.png", (int)n, snap,
                         o.by) >= sizeof outbuf)
      return usage_error("output path too long; give --out", NULL);
    out = outbuf;
  }

  particles_init(&ps);
  memset(&meta, 0, sizeof meta);
  memset(&fr, 0, sizeof fr);
  if (readfile(snap, &ps, &meta, &fr, &ck, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", prog, err);
    particles_free(&ps);
    return 1;
  }
  /* what is drawn is judged first: a body index sizes the legend's
  ** table, a position the picture */
  lim.nbody = PCHECK_MAXBODY;
  if (!(ps.fields[particles_find(&ps, "position")].flags & PF_READ)) {
    fprintf(stderr, "%s: %s: no dataset 'position'\n", prog, snap);
    rc = 1;
    goto done;
  }
  if (pcheck_particles(snap, &ps, &lim, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", prog, err);
    rc = 1;
    goto done;
  }
  /* a checkpoint's fields are those it was written with (PF_RESTART) */
  o.need = ck ? PF_READ : PF_OUTPUT;
  if (render_values(&ps, o.by, o.need, NULL, err, sizeof err) < 0) {
    fprintf(stderr, "%s: %s: %s\n", prog, snap, err);
    rc = 1;
    goto done;
  }
  for (d = 0; fr.has_domain && d < DIM; d++)
    if (!(isfinite(fr.lo[d]) && isfinite(fr.hi[d]) && fr.hi[d] > fr.lo[d])) {
      fprintf(stderr, "%s: %s: the stored domain [%g, %g] x [%g, %g] is not "
              "a finite box (give --domain X0,X1,Y0,Y1)\n", prog, snap,
              fr.lo[0], fr.hi[0], fr.lo[1], fr.hi[1]);
      rc = 1;
      goto done;
    }
  if (fr.nbody > 0) {
    names = malloc(fr.nbody * sizeof *names);
    driven = malloc(fr.nbody * sizeof *driven);
    if (!names || !driven) {
      fprintf(stderr, "%s: out of memory\n", prog);
      rc = 1;
      goto done;
    }
    for (i = 0; i < fr.nbody; i++) {
      names[i] = fr.name[i];
      driven[i] = fr.driven[i] != 0;
    }
    o.names = names;
    o.driven = driven;
    o.nnames = fr.nbody;
  }
  if (o.matrix) {
    for (i = 0; i < fr.nbody && strcmp(fr.name[i], o.matrix) != 0; i++) {}
    if (i == fr.nbody) {
      fprintf(stderr, "%s: %s: --matrix: no body named '%s'%s\n", prog, snap,
              o.matrix, fr.nbody ? "" : " (the file names none)");
      rc = 1;
      goto done;
    }
  }
  o.unit = render_length_unit(fr.units);
  /* the window in the picture's axes: h across, u up */
  if (has_domain) {
    o.lo[0] = dom[0]; o.hi[0] = dom[1];
    o.lo[1] = dom[2]; o.hi[1] = dom[3];
  } else if (fr.has_domain) {
    for (d = 0; d < 2; d++) {
      o.lo[d] = fr.lo[d ? u : h];
      o.hi[d] = fr.hi[d ? u : h];
    }
  } else {
    size_t k;
    double pad = meta.cell > 0 ? meta.cell : 0;
    for (d = 0; d < 2; d++) {
      const double *x = ps.x[d ? u : h];
      o.lo[d] = HUGE_VAL;
      o.hi[d] = -HUGE_VAL;
      for (k = 0; k < ps.n; k++)
        if (isfinite(x[k])) {
          if (x[k] < o.lo[d]) o.lo[d] = x[k];
          if (x[k] > o.hi[d]) o.hi[d] = x[k];
        }
      if (o.lo[d] > o.hi[d]) { o.lo[d] = 0; o.hi[d] = 1; } /* no particles */
      if (pad <= 0) pad = 0.05 * (o.hi[d] - o.lo[d]);
      if (pad <= 0) pad = 0.5;
      o.lo[d] -= pad;
      o.hi[d] += pad;
    }
  }
  /* a 3-D slice goes through the middle of the stored domain */
  if (along >= 0 && !o.has_at && fr.has_domain) {
    o.at = fr.lo[along] / 2 + fr.hi[along] / 2;
    o.has_at = 1;
  }
  if (!title && along < 0)
    snprintf(titlebuf, sizeof titlebuf, "%s   t = %.6g", o.by, meta.time);
  else if (!title && o.project)
    snprintf(titlebuf, sizeof titlebuf, "%s   t = %.6g   along %c", o.by,
             meta.time, "xyz"[along]);
  else if (!title && o.has_at)
    snprintf(titlebuf, sizeof titlebuf, "%s   t = %.6g   %c = %.6g", o.by,
             meta.time, "xyz"[along], o.at);
  else if (!title)
    snprintf(titlebuf, sizeof titlebuf, "%s   t = %.6g   %c slice", o.by,
             meta.time, "xyz"[along]);
  if (!title) title = titlebuf;
  o.title = title;
  if (render_file(out, &ps, &o, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", prog, err);
    rc = 1;
  } else
    printf("%s: %zu particles, t = %g -> %s\n", snap, ps.n, meta.time, out);
done:
  free(names);
  free(driven);
  out_h5_frame_free(&fr);
  particles_free(&ps);
  return rc;
}
