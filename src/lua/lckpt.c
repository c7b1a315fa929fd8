/*
** lckpt.c - the run's half of a checkpoint (lckpt.h): what lives in the
** Lua state and the run's userdata goes through ckpt.h's named lists
** and blobs, beside the simulation's state, which ckpt.c writes and
** reads without Lua.
*/
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "lauxlib.h"
#include "lckpt.h"
#include "lsim.h"
#include "lstate.h"
#include "sandbox.h"

/* the run as ckpt_more's visit and check see it */
typedef struct runpart {
  lua_State *L;
  int simidx;
  lsim *ls;
  int64_t csv_bytes;      /* gathering: the table's length; applying: -1 */
} runpart;

#define VI(v, name, x, type)                      \
  do {                                            \
    int64_t t_ = (int64_t)(x);                    \
    ckv_int(v, name, &t_);                        \
    (x) = (type)t_;                               \
  } while (0)

/* the run's side: output and checkpoint schedule, callbacks' next times */
static void visit_run(ckv *v, void *ud) {
  runpart *rp = ud;
  lua_State *L = rp->L;
  lsim *ls = rp->ls;
  int64_t csv_bytes = rp->csv_bytes;
  lua_Integer k, n;
  char nm[64];
  /* read before the scene loads (ckpt_sandboxed); applying only uses it */
  int64_t sandboxed = sandbox_on(L);
  ckv_int(v, "run.sandbox", &sandboxed);
  ckv_real(v, "run.out_every", &ls->out_every);
  ckv_real(v, "run.out_next", &ls->out_next);
  VI(v, "run.csv_every", ls->csv_every, long);
  VI(v, "run.nsnap", ls->nsnap, int);
  ckv_real(v, "run.ck_every", &ls->ck_every);
  ckv_real(v, "run.ck_next", &ls->ck_next);
  VI(v, "run.ck_count", ls->ck_count, int);
  ckv_int(v, "run.csv_bytes", &csv_bytes);
  if (ckv_applying(v)) ls->csv_resume = (long)csv_bytes;
  lsim_uv(L, rp->simidx, "every");
  n = (lua_Integer)lua_rawlen(L, -1);
  ckv_same(v, "run.nevery", n, "sim:every callbacks");
  for (k = 1; k <= n && !ckv_failed(v); k++) {
    int bytime;
    lua_rawgeti(L, -1, k);
    bytime = lua_getfield(L, -1, "time") != LUA_TNIL;
    lua_pop(L, 1);
    snprintf(nm, sizeof nm, "every%d.bytime", (int)k);
    ckv_same(v, nm, bytime, "as its kind (1 time, 0 steps)");
    snprintf(nm, sizeof nm, "every%d.next", (int)k);
    lua_getfield(L, -1, "next");
    if (bytime) {
      double x = lua_tonumber(L, -1);
      ckv_real(v, nm, &x);
      lua_pushnumber(L, x);
    } else {
      int64_t x = (int64_t)lua_tointeger(L, -1);
      ckv_int(v, nm, &x);
      lua_pushinteger(L, (lua_Integer)x);
    }
    lua_setfield(L, -3, "next");
    lua_pop(L, 2);
  }
  lua_pop(L, 1);
}

/* the run's numbers in the ranges the engine keeps them in */
static void check_run(ckv *v, void *ud) {
  const double big = INFINITY, cnt = (double)INT64_MAX;
  const lsim *ls = ((runpart *)ud)->ls;
  ckv_range(v, "run.out_every", ls->out_every, 0, big, 0);
  ckv_range(v, "run.csv_every", (double)ls->csv_every, 0, big, 0);
  ckv_range(v, "run.nsnap", ls->nsnap, 0, INT32_MAX, 0);
  ckv_range(v, "run.ck_every", ls->ck_every, 0, big, 0);
  ckv_range(v, "run.ck_count", ls->ck_count, 0, 999999, 0);
  ckv_range(v, "run.csv_bytes", (double)ls->csv_resume, -1, cnt, 0);
}

/*
** {======================================================
** Writing
** =======================================================
*/


static int strcmpp(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* the overrides in force, "name=value" lines in name order */
static void params(lua_State *L, ckpt_buf *s);

char *ckpt_overrides(lua_State *L) {
  ckpt_buf s = {0};
  params(L, &s);
  if (s.bad) { free(s.b); return NULL; }
  if (!s.b) return calloc(1, 1);
  return s.b;
}

static void params(lua_State *L, ckpt_buf *s) {
  char *line[256];
  int n = 0, k;
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.overrides");
  if (lua_istable(L, -1)) {
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      if (lua_type(L, -2) == LUA_TSTRING) {
        size_t kl, vl;
        const char *key = lua_tolstring(L, -2, &kl);
        const char *val = luaL_tolstring(L, -1, &vl);
        if (n == 256 || !(line[n] = malloc(kl + vl + 3))) s->bad = 1;
        else snprintf(line[n++], kl + vl + 3, "%s=%s\n", key, val);
        lua_pop(L, 1);
      }
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  qsort(line, (size_t)n, sizeof *line, strcmpp);
  for (k = 0; k < n; k++) {
    ckpt_buf_add(s, line[k], strlen(line[k]));
    free(line[k]);
  }
}


void ckpt_write(lua_State *L, int simidx) {
  lsim *ls = lsim_check(L, simidx);
  sim *s = &ls->s;
  runpart rp;
  ckpt_more more;
  ckpt_buf sf = {0}, pa = {0};
  double *st = NULL;
  int64_t *sn = NULL;
  h5blob b[CB_N];
  h5meta meta;
  h5prov prov;
  h5frame fr;
  char path[1100], old[1100], err[1024], abs_scene[PATH_MAX], scheme[256];
  const char *scene, *source, *state = NULL;
  size_t statelen = 0;
  int k, r, nomem, top = lua_gettop(L);
  long csv = run_sync(L, ls);
  simidx = lua_absindex(L, simidx);
  /* first what may raise an error (a function in the state), before
  ** anything is allocated */
  lsim_uv(L, simidx, "state");
  if (lua_istable(L, -1)) {
    lstate_save(L, -1);
    state = lua_tolstring(L, -1, &statelen);
  }
  ckpt_name(path, sizeof path, ls->outdir, ls->ck_count + 1);
  sandbox_file(L, path, "checkpoint"); /* no link followed (sandbox.h) */
  memset(&fr, 0, sizeof fr);
  ls->ck_count++; /* what a restart continues from */
  rp = (runpart){L, simidx, ls, csv};
  more = (ckpt_more){visit_run, NULL, &rp};
  st = malloc((ls->nsnap + 1) * sizeof *st);
  sn = malloc((ls->nsnap + 1) * sizeof *sn);
  for (k = 0; st && sn && k < ls->nsnap; k++) {
    st[k] = ls->snaps[k].time;
    sn[k] = (int64_t)ls->snaps[k].n;
    ckpt_buf_add(&sf, ls->snaps[k].file, strlen(ls->snaps[k].file));
    ckpt_buf_add(&sf, "\n", 1);
  }
  params(L, &pa);
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.scene");
  scene = lua_isstring(L, -1) ? lua_tostring(L, -1) : ls->scene;
  /* stored absolute, so the run continues from any directory */
  if (scene[0] != '/' && getcwd(abs_scene, sizeof abs_scene) &&
      strlen(abs_scene) + strlen(scene) + 2 <= sizeof abs_scene) {
    strcat(abs_scene, "/");
    strcat(abs_scene, scene);
    scene = abs_scene;
  }
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.source");
  source = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
  nomem = sf.bad || pa.bad || !st || !sn || run_frame(s, &fr);
  b[CB_SNAPF] = (h5blob){"snap_files", H5B_U8, sf.n, sf.b};
  b[CB_SNAPT] = (h5blob){"snap_time", H5B_F64, (size_t)ls->nsnap, st};
  b[CB_SNAPN] = (h5blob){"snap_n", H5B_I64, (size_t)ls->nsnap, sn};
  b[CB_PARAMS] = (h5blob){"params", H5B_U8, pa.n, pa.b};
  b[CB_SCENE] = (h5blob){"scene", H5B_U8, strlen(scene), (void *)scene};
  b[CB_SOURCE] = (h5blob){"source", H5B_U8, strlen(source), (void *)source};
  b[CB_STATE] = (h5blob){"lua_state", H5B_U8, statelen, (void *)state};
  memset(&meta, 0, sizeof meta);
  meta.units = ls->units;
  meta.scene = scene;
  meta.frame = &fr;
  run_provenance(L, &prov);
  sim_scheme(s, scheme, sizeof scheme);
  prov.scheme = scheme;
  r = ckpt_save(path, s, &more, b, &meta, &prov, nomem, err, sizeof err);
  if (r == 0 && ckpt_syncdir(ls->outdir)) {
    snprintf(err, sizeof err, "%s: cannot sync the directory (%s)",
             ls->outdir, strerror(errno));
    r = -1;
  }
  free(sf.b); free(pa.b);
  free(st); free(sn);
  out_h5_frame_free(&fr);
  lua_settop(L, top);
  if (r) {
    ls->ck_count--;
    luaL_error(L, "%s", err);
  }
  snprintf(ls->ck_last, sizeof ls->ck_last, "%s", path);
  /* keep the newest two: the older of them is the fallback if the newest
  ** turns out unreadable */
  if (ls->ck_count > 2) {
    ckpt_name(old, sizeof old, ls->outdir, ls->ck_count - 2);
    remove(old);
  }
}

/* }====================================================== */


/*
** {======================================================
** Applying
** =======================================================
*/

/* the XDMF entries so far; 0, or -1 with why */
static int copy_snaps(lsim *ls, const ckpt *c, char *why, size_t len) {
  char *files = ckpt_string(c, CB_SNAPF), *p, *q;
  int k = 0, n = ls->nsnap;
  if (n < 0 || (size_t)n != c->b[CB_SNAPT].n || (size_t)n != c->b[CB_SNAPN].n) {
    free(files);
    snprintf(why, len, "its XDMF entries are inconsistent");
    return -1;
  }
  if (n > ls->snapcap) {
    xdmf_entry *e = realloc(ls->snaps, (size_t)n * sizeof *e);
    if (!e) { free(files); snprintf(why, len, "out of memory"); return -1; }
    ls->snaps = e;
    ls->snapcap = n;
  }
  for (p = files; p && k < n; p = q + 1, k++) {
    if (!(q = strchr(p, '\n'))) break;
    *q = '\0';
    snprintf(ls->snaps[k].file, sizeof ls->snaps[k].file, "%s", p);
    ls->snaps[k].time = ((const double *)c->b[CB_SNAPT].data)[k];
    ls->snaps[k].n = (size_t)((const int64_t *)c->b[CB_SNAPN].data)[k];
  }
  free(files);
  if (k == n) return 0;
  snprintf(why, len, "its XDMF entries are inconsistent");
  return -1;
}

int ckpt_apply(lua_State *L, int simidx, const ckpt *c, char *err,
               size_t errlen) {
  lsim *ls = lsim_check(L, simidx);
  runpart rp;
  ckpt_more more;
  char why[512];
  int top = lua_gettop(L), failed;
  simidx = lua_absindex(L, simidx);
  rp = (runpart){L, simidx, ls, -1};
  more = (ckpt_more){visit_run, check_run, &rp};
  if (ckpt_restore(&ls->s, c, &more, err, errlen)) {
    lua_settop(L, top);
    return -1;
  }
  failed = copy_snaps(ls, c, why, sizeof why);
  if (!failed) {
    lsim_uv(L, simidx, "state");
    if (c->b[CB_STATE].n > 0 && !lua_istable(L, -1)) {
      snprintf(why, sizeof why, "it holds a sim:state table but the scene "
               "registers none");
      failed = 1;
    } else if (c->b[CB_STATE].n == 0 && lua_istable(L, -1)) {
      snprintf(why, sizeof why, "the scene registers a sim:state table but "
               "the checkpoint holds none");
      failed = 1;
    } else if (c->b[CB_STATE].n > 0 &&
               lstate_load(L, -1, c->b[CB_STATE].data, c->b[CB_STATE].n, why,
                           sizeof why))
      failed = 1;
  }
  lua_settop(L, top);
  if (failed) {
    snprintf(err, errlen, "%s: cannot continue this scene from it: %s",
             c->path, why);
    return -1;
  }
  ls->restarted = 1;
  return 0;
}

/* }====================================================== */
