/*
** test_out_h5.c - HDF5 snapshots and the XDMF index.
** A store with built-in and run-time fields goes out and comes back bit
** for bit; failures leave neither the file nor its temp; a 3-entry .xmf
** is written beside three snapshots.
**   test_out_h5 [dir]   keep the series in dir (for tests/tools/check_xdmf.py)
*/
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <hdf5.h>

#include "h5sum.h"
#include "hash.h"
#include "out_h5.h"
#include "out_xdmf.h"
#include "particles.h"
#include "unit.h"

#define N 1000

static uint64_t rng = 0x9e3779b97f4a7c15u;

/* xorshift64*: arbitrary bit patterns, NaN payloads and denormals included */
static uint64_t bits(void) {
  rng ^= rng >> 12;
  rng ^= rng << 25;
  rng ^= rng >> 27;
  return rng * 2685821657736338717u;
}

static int exists(const char *p) {
  struct stat st;
  return stat(p, &st) == 0;
}

static void join(char *buf, size_t len, const char *dir, const char *name) {
  if ((size_t)snprintf(buf, len, "%s/%s", dir, name) >= len) {
    fprintf(stderr, "path %s/%s too long\n", dir, name);
    exit(2);
  }
}

/* every component of every field gets its own bits; position stays a
** sane lattice so the series can be looked at */
static void fill(particles *ps, size_t n) {
  size_t i;
  int f, c;
  for (i = 0; i < n; i++) particles_push(ps);
  for (f = 0; f < ps->nfields; f++)
    for (c = 0; c < ps->fields[f].ncomp; c++) {
      size_t sz = ps->fields[f].type == PF_INT32 ? 4 : 8;
      char *a = particles_comp(ps, f, c);
      for (i = 0; i < n; i++) {
        uint64_t b = bits();
        memcpy(a + i * sz, &b, sz);
      }
    }
  for (i = 0; i < n; i++) {
    ps->x[0][i] = 0.01 * (double)(i % 40) + 1e-17 * (double)i;
    ps->x[1][i] = 0.01 * (double)(i / 40);
  }
  if (n > 4) {
    ps->m[0] = -0.0;
    ps->m[1] = INFINITY;
    ps->m[2] = 4.9e-324;
    ps->body[0] = INT32_MIN;
    ps->body[1] = INT32_MAX;
  }
}

/* compare every output field of a with the same-named field of b */
static void same(const particles *a, const particles *b) {
  int f, c;
  UNIT_CHECK(a->n == b->n, "count %zu read back as %zu", a->n, b->n);
  for (f = 0; f < a->nfields; f++) {
    const pfield *pf = &a->fields[f];
    int g = particles_find(b, pf->name);
    if (!(pf->flags & PF_OUTPUT)) continue;
    UNIT_CHECK(g >= 0, "field %s missing after read", pf->name);
    if (g < 0 || a->n != b->n) continue;
    UNIT_CHECK(b->fields[g].ncomp == pf->ncomp && b->fields[g].type ==
               pf->type, "field %s changed shape or type", pf->name);
    UNIT_CHECK(strcmp(b->fields[g].unit, pf->unit) == 0,
               "field %s unit '%s' read as '%s'", pf->name, pf->unit,
               b->fields[g].unit);
    for (c = 0; c < pf->ncomp && c < b->fields[g].ncomp; c++) {
      size_t sz = pf->type == PF_INT32 ? 4 : 8, i, bad = 0;
      const char *x = particles_comp(a, f, c), *y = particles_comp(b, g, c);
      for (i = 0; i < a->n; i++) bad += memcmp(x + i * sz, y + i * sz, sz) != 0;
      UNIT_CHECK(bad == 0, "field %s component %d: %zu values differ",
                 pf->name, c, bad);
    }
  }
}

static char *bigsource(void) {
  size_t len = 100000, i;
  char *s = malloc(len + 1);
  for (i = 0; i < len; i++) s[i] = i % 64 == 63 ? '\n' : "abc =-{}()"[i % 10];
  s[len] = '\0';
  return s;
}

static void roundtrip(const char *dir) {
  particles a, b;
  h5meta m = {.time = 1.25, .step = 12, .cell = 0.01, .units = "nondimensional", .scene = "scene.lua", .source = NULL}, r;
  char path[512], tmp[520], err[512];
  int f;
  particles_init(&a);
  UNIT_CHECK(particles_add_field(&a, "damage", 1, PF_DOUBLE, "1",
                                 PF_OUTPUT) >= 0, "add damage");
  UNIT_CHECK(particles_add_field(&a, "tag", 3, PF_INT32, "", PF_OUTPUT) >= 0,
             "add tag");
  UNIT_CHECK(particles_add_field(&a, "scratchpad", 2, PF_DOUBLE, "",
                                 0) >= 0, "add scratchpad");
  fill(&a, N);
  m.source = bigsource();
  join(path, sizeof path, dir, "rt.h5");
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  UNIT_CHECK(out_h5_write(path, &a, &m, err, sizeof err) == 0, "write: %s",
             err);
  UNIT_CHECK(exists(path) && !exists(tmp), "file there, temp gone");
  particles_init(&b);
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == 0, "read: %s",
             err);
  same(&a, &b);
  UNIT_CHECK(memcmp(&r.time, &m.time, sizeof r.time) == 0 && r.step == 12 &&
             r.cell == 0.01, "meta time %g step %ld cell %g", r.time, r.step,
             r.cell);
  UNIT_CHECK(!r.units && !r.scene && !r.source, "string meta left NULL");
  f = particles_find(&b, "tag");
  UNIT_CHECK(f >= 0 && (b.fields[f].flags & PF_OUTPUT), "tag is an output");
  UNIT_CHECK(particles_find(&b, "scratchpad") < 0, "non-output not written");
  UNIT_CHECK(particles_find(&b, "scene_source") < 0, "source is no field");
  /* a second read into a store that already holds particles is refused */
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
             strstr(err, path), "non-empty store refused: %s", err);
  particles_free(&b);
  free((char *)m.source);
  particles_free(&a);
}

static void empty(const char *dir) {
  particles a, b;
  h5meta m = {.time = 0, .step = 0, .cell = 0.5, .units = "SI", .scene = "empty.lua", .source = ""};
  char path[512], err[512];
  particles_init(&a);
  join(path, sizeof path, dir, "empty.h5");
  UNIT_CHECK(out_h5_write(path, &a, &m, err, sizeof err) == 0, "write n=0: %s",
             err);
  particles_init(&b);
  UNIT_CHECK(out_h5_read(path, &b, &m, err, sizeof err) == 0 && b.n == 0 &&
             m.cell == 0.5, "read n=0: %s", err);
  particles_free(&b);
  particles_free(&a);
  remove(path);
}

/* a failed write returns -1, says which file, and leaves nothing */
static void refused(const char *path, const particles *ps, const char *why) {
  h5meta m = {.time = 0, .step = 0, .cell = 1, .units = "SI", .scene = "s.lua", .source = NULL};
  char err[512] = "", tmp[600];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  UNIT_CHECK(out_h5_write(path, ps, &m, err, sizeof err) == -1,
             "write to %s should fail", path);
  printf("  expected error: %s\n", err);
  UNIT_CHECK(strncmp(err, path, strlen(path)) == 0 && strstr(err, why),
             "message '%s' should name the file and say '%s'", err, why);
  UNIT_CHECK(!exists(tmp), "temp %s left behind", tmp);
}

static void failures(const char *dir) {
  particles a, b;
  h5meta m = {.time = 2, .step = 3, .cell = 1, .units = "SI", .scene = "s.lua", .source = NULL}, r;
  char path[512], err[512];
  struct rlimit old, lim;
  void (*oldsig)(int);
  particles_init(&a);
  fill(&a, N);
  join(path, sizeof path, dir, "nodir/x.h5");
  refused(path, &a, "No such file or directory");
  UNIT_CHECK(!exists(path), "nothing under the final name");
  join(path, sizeof path, dir, "rt.h5/x.h5"); /* parent is a file */
  refused(path, &a, "Not a directory");
  if (geteuid() != 0) { /* root writes anywhere */
    join(path, sizeof path, dir, "ro");
    mkdir(path, 0555);
    join(path, sizeof path, dir, "ro/x.h5");
    refused(path, &a, "Permission denied");
    join(path, sizeof path, dir, "ro");
    rmdir(path);
  }
  /* the disk fills up half way: the previous snapshot must survive */
  join(path, sizeof path, dir, "keep.h5");
  UNIT_CHECK(out_h5_write(path, &a, &m, err, sizeof err) == 0, "%s", err);
  getrlimit(RLIMIT_FSIZE, &old);
  lim = old;
  lim.rlim_cur = 20000;
  oldsig = signal(SIGXFSZ, SIG_IGN); /* write() then fails with EFBIG */
  setrlimit(RLIMIT_FSIZE, &lim);
  refused(path, &a, "File too large");
  setrlimit(RLIMIT_FSIZE, &old);
  signal(SIGXFSZ, oldsig);
  particles_init(&b);
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == 0 && r.time == 2,
             "old snapshot intact: %s", err);
  same(&a, &b);
  particles_free(&b);
  remove(path);
  /* reading what is not there, or not a snapshot */
  particles_init(&b);
  join(path, sizeof path, dir, "missing.h5");
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
             strstr(err, "No such file"), "missing: %s", err);
  printf("  expected error: %s\n", err);
  join(path, sizeof path, dir, "junk.h5");
  {
    FILE *fp = fopen(path, "w");
    fputs("not hdf5\n", fp);
    fclose(fp);
  }
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
             strncmp(err, path, strlen(path)) == 0, "junk: %s", err);
  printf("  expected error: %s\n", err);
  remove(path);
  particles_free(&b);
  particles_free(&a);
}

/* the .xmf holds text exactly count times */
static void xmfhas(const char *path, const char *text, int count) {
  char buf[65536];
  const char *p = buf;
  size_t len;
  int k = 0;
  FILE *fp = fopen(path, "r");
  len = fp ? fread(buf, 1, sizeof buf - 1, fp) : 0;
  if (fp) fclose(fp);
  buf[len] = '\0';
  while ((p = strstr(p, text)) != NULL) k++, p++;
  UNIT_CHECK(k == count, "%s holds '%s' %d times, expected %d", path, text,
             k, count);
}

/* replace (or add) dataset name of a snapshot with zeros of another shape */
static void putds(const char *path, const char *name, int rank,
                  hsize_t rows, hsize_t cols, hid_t type) {
  hsize_t dims[3] = {rows, cols, 2};
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT), sp, d;
  if (H5Lexists(f, name, H5P_DEFAULT) > 0) H5Ldelete(f, name, H5P_DEFAULT);
  sp = H5Screate_simple(rank, dims, NULL);
  d = H5Dcreate2(f, name, type, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dclose(d);
  H5Sclose(sp);
  H5Fclose(f);
}

static void putdim(const char *path, int dim) {
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t a = H5Aopen(f, "dim", H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_INT, &dim);
  H5Aclose(a);
  H5Fclose(f);
}

/*
** An edit through HDF5 leaves the checksum stale: the file is refused
** for that first; sealed again (as tests/tools/h5sum.py does), its
** contents are judged.
*/
static void reseal(const char *path) {
  particles b;
  h5meta r;
  char err[512];
  FILE *fp;
  unsigned char *img;
  long n;
  particles_init(&b);
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
             strstr(err, "checksum mismatch (damaged or edited"),
             "an edited file: got '%s'", err);
  particles_free(&b);
  fp = fopen(path, "r+b");
  if (!fp || fseek(fp, 0, SEEK_END) || (n = ftell(fp)) < 0 ||
      !(img = malloc((size_t)n)) || fseek(fp, 0, SEEK_SET) ||
      fread(img, 1, (size_t)n, fp) != (size_t)n) {
    fprintf(stderr, "cannot read %s back\n", path);
    exit(2);
  }
  h5sum_seal(img, (size_t)n);
  if (fseek(fp, 0, SEEK_SET) || fwrite(img, 1, H5SUM_BLOCK, fp) != H5SUM_BLOCK ||
      fclose(fp)) {
    fprintf(stderr, "cannot seal %s\n", path);
    exit(2);
  }
  free(img);
}

/* a damaged snapshot is refused with a message saying what is wrong */
static void damaged(const char *dir) {
  static const struct {
    const char *name, *want;
    int rank;
    hsize_t rows, cols;
    int isint;
  } bad[] = {
    {"mass", "'mass' has 999 rows but 'F' has 1000", 1, 999, 1, 0},
    {"body", "'body' holds reals, the field holds integers", 1, N, 1, 0},
    {"velocity", "'velocity' has 4 components, the field has", 2, N, 4, 0},
    {"cube", "'cube' has rank 3", 3, N, 2, 0},
    {"wide", "'wide' has 10 components", 2, N, 10, 0},
    {"a_field_name_longer_than_31_chars", "too long", 1, N, 1, 0},
    {"wider_int", "neither floating point nor a 32-bit integer", 1, N, 1, 2},
  };
  particles a, b;
  h5meta m = {.time = 0, .step = 0, .cell = 1, .units = "SI", .scene = "s.lua", .source = NULL}, r;
  char path[512], err[512];
  size_t k;
  particles_init(&a);
  fill(&a, N);
  join(path, sizeof path, dir, "bad.h5");
  for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    out_h5_write(path, &a, &m, err, sizeof err);
    putds(path, bad[k].name, bad[k].rank, bad[k].rows, bad[k].cols,
          bad[k].isint == 2 ? H5T_STD_I64LE
          : bad[k].isint  ? H5T_STD_I32LE : H5T_IEEE_F64LE);
    reseal(path);
    particles_init(&b);
    UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
               strstr(err, bad[k].want) && strstr(err, path) && b.n == 0,
               "damaged %s: got '%s', want '%s'", bad[k].name, err,
               bad[k].want);
    printf("  expected error: %s\n", err);
    particles_free(&b);
  }
  out_h5_write(path, &a, &m, err, sizeof err);
  putdim(path, 3 - (DIM - 2));
  reseal(path);
  particles_init(&b);
  UNIT_CHECK(out_h5_read(path, &b, &r, err, sizeof err) == -1 &&
             strstr(err, "-D but this build is"), "dim: %s", err);
  printf("  expected error: %s\n", err);
  particles_free(&b);
  remove(path);
  particles_free(&a);
}

/* three snapshots, the last one empty, and their index */
static void series(const char *dir) {
  static const size_t n[3] = {N, N / 2, 0};
  xdmf_entry e[3];
  particles a;
  char path[512], tmp[520], err[512];
  int k;
  for (k = 0; k < 3; k++) {
    h5meta m = {.time = 0.1 * k, .step = 10 * k, .cell = 0.01, .units = "nondimensional", .scene = "s.lua", .source = "-- s\n"};
    particles_init(&a);
    particles_add_field(&a, "damage", 1, PF_DOUBLE, "1", PF_OUTPUT);
    fill(&a, n[k]);
    snprintf(e[k].file, sizeof e[k].file, "particles_%06d.h5", 10 * k);
    e[k].time = m.time;
    e[k].n = a.n;
    join(path, sizeof path, dir, e[k].file);
    UNIT_CHECK(out_h5_write(path, &a, &m, err, sizeof err) == 0, "%s", err);
    if (k < 2) particles_free(&a);
  }
  join(path, sizeof path, dir, "series.xmf");
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  UNIT_CHECK(out_xdmf_write(path, e, 3, &a, err, sizeof err) == 0, "xmf: %s",
             err);
  UNIT_CHECK(exists(path) && !exists(tmp), "xmf there, temp gone");
  xmfhas(path, "<Time Value=\"0.1\"/>", 1);
  xmfhas(path, "<Grid Name=\"particles\" GridType=\"Uniform\">", 3);
  xmfhas(path, DIM == 2 ? "Dimensions=\"1000 2\">particles_000000.h5:/position<"
                        : "Dimensions=\"1000 3\">particles_000000.h5:/position<",
         1);
  xmfhas(path, "AttributeType=\"Vector\"", 2); /* velocity, 2 steps */
  /* the stress as one Matrix, every reader sees it; F too in 2-D, and
  ** in 3-D, a full 3 x 3 tensor, as XDMF's Tensor */
  xmfhas(path, "<Attribute Name=\"stress\" AttributeType=\"Matrix\"", 2);
  xmfhas(path, DIM == 2 ? "<Attribute Name=\"F\" AttributeType=\"Matrix\""
                        : "<Attribute Name=\"F\" AttributeType=\"Tensor\"", 2);
  xmfhas(path, DIM == 2 ? "GeometryType=\"XY\"" : "GeometryType=\"XYZ\"", 3);
  xmfhas(path, DIM == 2 ? "Dimensions=\"1 2\">0 0<" : "Dimensions=\"1 3\">0 0 0<",
         1);
  xmfhas(path, "ItemType=\"HyperSlab\"", 0);
  /* the connectivity the Xdmf3 readers need, in each non-empty step */
  xmfhas(path, ":/xdmf/vertex</DataItem>", 2);
  xmfhas(path, "NumberOfElements=\"0\"", 1);
  strcpy(e[1].file, "a:b.h5");
  UNIT_CHECK(out_xdmf_write(path, e, 3, &a, err, sizeof err) == -1 &&
             strstr(err, "':'"), "':' refused: %s", err);
  join(path, sizeof path, dir, "nodir/series.xmf");
  UNIT_CHECK(out_xdmf_write(path, e, 1, &a, err, sizeof err) == -1 &&
             strstr(err, "No such file"), "xmf nodir: %s", err);
  particles_free(&a);
}

static void cleanup(const char *dir) {
  static const char *f[] = {"rt.h5", "particles_000000.h5",
                            "particles_000010.h5", "particles_000020.h5",
                            "series.xmf"};
  char path[512];
  size_t i;
  for (i = 0; i < sizeof f / sizeof f[0]; i++) {
    join(path, sizeof path, dir, f[i]);
    remove(path);
  }
  rmdir(dir);
}

/* BLAKE2b against RFC 7693 appendix A ("abc", 64 bytes) and the
** 32-byte digest of nothing (Python's hashlib.blake2b) */
static void blake2b(void) {
  static const char *const want[2] = {
    "ba80a53f981c4d0d6a2797b69f12f6e94c212f14685ac4b74b12bb6fdbffa2d1"
    "7d87c5392aab792dc252d5de4533cc9518d38aa8dbf1925ab92386edd4009923",
    "0e5751c026e543b2e8ab2eb06099daa1d1e5df47778f7787faab45cdf12fe3a8"};
  unsigned char out[64];
  char hex[129];
  int k, j;
  for (k = 0; k < 2; k++) {
    size_t n = k ? 32 : 64;
    hash_blake2b("abc", k ? 0 : 3, out, n);
    for (j = 0; j < (int)n; j++) sprintf(hex + 2 * j, "%02x", out[j]);
    UNIT_CHECK(strcmp(hex, want[k]) == 0, "blake2b case %d: %s", k, hex);
  }
}

/* the frame (domain, periodic axes, bodies) goes out and comes back
** with DIM entries per vector, and the positions with DIM components */
static void frame(const char *dir) {
  particles a, b;
  h5frame fw, fr;
  h5meta m = {.time = 0.5, .step = 3, .cell = 0.1, .units = "SI",
              .scene = "s.lua", .source = NULL}, r;
  char path[512], err[512], names[2][H5_NAMELEN] = {"grain", "wall"};
  int32_t driven[2] = {0, 1};
  int d, ok = 1, f;
  memset(&fw, 0, sizeof fw);
  for (d = 0; d < DIM; d++) {
    fw.lo[d] = -1.0 - d;
    fw.hi[d] = 2.0 + d;
    fw.periodic[d] = d % 2;
  }
  fw.nbody = 2;
  fw.name = names;
  fw.driven = driven;
  m.frame = &fw;
  particles_init(&a);
  particles_push(&a);
  for (d = 0; d < DIM; d++) a.x[d][0] = 0.25 * (d + 1);
  join(path, sizeof path, dir, "frame.h5");
  UNIT_CHECK(out_h5_write(path, &a, &m, err, sizeof err) == 0, "frame: %s", err);
  particles_init(&b);
  memset(&fr, 0, sizeof fr);
  UNIT_CHECK(out_h5_read_frame(path, NULL, &b, &r, &fr, err, sizeof err) == 0,
             "frame read: %s", err);
  for (d = 0; d < DIM; d++)
    ok = ok && fr.lo[d] == fw.lo[d] && fr.hi[d] == fw.hi[d] &&
         fr.periodic[d] == fw.periodic[d] && b.x[d][0] == a.x[d][0];
  UNIT_CHECK(fr.has_domain && ok, "%d-D domain, periodic axes and position "
             "back", DIM);
  UNIT_CHECK(fr.nbody == 2 && strcmp(fr.name[0], "grain") == 0 &&
             strcmp(fr.name[1], "wall") == 0 && fr.driven[0] == 0 &&
             fr.driven[1] == 1 && strcmp(fr.units, "SI") == 0,
             "bodies' names, drive flags and units back");
  f = particles_find(&b, "position");
  UNIT_CHECK(f >= 0 && b.fields[f].ncomp == DIM, "position has %d components",
             DIM);
  out_h5_frame_free(&fr);
  particles_free(&a);
  particles_free(&b);
  remove(path);
}

int main(int argc, char **argv) {
  setvbuf(stdout, NULL, _IONBF, 0);
  char tmpl[] = "/tmp/test_out_h5.XXXXXX";
  const char *dir = argc > 1 ? argv[1] : mkdtemp(tmpl);
  UNIT_CHECK(dir != NULL, "mkdtemp: %s", strerror(errno));
  if (!dir) UNIT_END("test_out_h5");
  if (argc > 1) mkdir(dir, 0777);
  blake2b();
  roundtrip(dir);
  empty(dir);
  failures(dir);
  damaged(dir);
  series(dir);
  frame(dir);
  if (argc > 1) printf("series kept in %s/series.xmf\n", dir);
  else cleanup(dir);
  UNIT_END("test_out_h5");
}
