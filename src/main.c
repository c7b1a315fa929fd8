/*
** main.c - the mvmpm command: run a scene, step it at a prompt, or run
** verification scripts.
*/
#include <glob.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "interrupt.h"
#include "lauxlib.h"
#include "lmvmpm.h"
#include "lsim.h"
#include "lualib.h"
#include "render_cmd.h"
#include "repl.h"

static const char *progname = "mvmpm";

static void usage(FILE *f) {
  fprintf(f,
"usage: %s run SCENE.lua [--set name=value ...] [--out DIR] [--quiet]\n"
"       %s repl [SCENE.lua] [--set name=value ...] [--out DIR]\n"
"       %s test [FILE.lua ...]        (default: tests/verify/*.lua)\n"
"       %s render SNAPSHOT.h5 [--by KEY] [--out FILE.png] [--width N]\n"
"                [--range LO,HI] [--colormap auto|seq|div] [--title TEXT]\n"
"                [--domain X0,X1,Y0,Y1]\n"
"       %s --help | --version\n"
"\n"
"run    runs the scene to its end time, writing HDF5 snapshots, an XDMF\n"
"       index (particles.xmf) and diagnostics.csv to DIR (default: the\n"
"       scene's output dir, else out/<scene name>)\n"
"repl   loads the scene without running it and gives a Lua prompt with the\n"
"       simulation as 'sim': sim:step(n), sim:run(t), sim:energy(),\n"
"       sim:bodies(), sim:snapshot(path); help() lists more\n"
"test   runs verification scripts; each check prints measured vs reference\n"
"       and tolerance; ends with 'N passed, M failed'\n"
"render draws a snapshot's particles as a PNG, coloured by KEY: body,\n"
"       pressure, sdiff (principal stress difference), speed, or a field\n"
"       such as velocity.x, stress.xy, mass (default: body); FILE defaults\n"
"       to the snapshot's name with _KEY.png\n"
"--set  overrides a parameter the scene declares with mvmpm.params{...}\n",
          progname, progname, progname, progname, progname);
}

static lua_State *newstate(const char *argv0) {
  lua_State *L = luaL_newstate();
  if (!L) {
    fprintf(stderr, "%s: cannot create a Lua state (out of memory)\n", progname);
    exit(1);
  }
  luaL_openlibs(L);
  lmvmpm_setpath(L, argv0);
  luaL_requiref(L, "mvmpm", luaopen_mvmpm, 1);
  lua_pop(L, 1);
  return L;
}

static int fail(lua_State *L, const char *what) {
  fprintf(stderr, "%s: %s\n", progname, what ? what : lua_tostring(L, -1));
  return 1;
}

/* --set a=b and --out DIR; returns the remaining positional argument */
static int options(lua_State *L, int argc, char **argv, int i, const char **scene,
                   const char **out, int *quiet) {
  for (; i < argc; i++) {
    if (strcmp(argv[i], "--set") == 0 || strncmp(argv[i], "--set=", 6) == 0) {
      const char *kv = argv[i][5] == '=' ? argv[i] + 6 : (i + 1 < argc ? argv[++i] : NULL);
      const char *eq = kv ? strchr(kv, '=') : NULL;
      char name[128];
      if (!eq || eq == kv || (size_t)(eq - kv) >= sizeof name) {
        fprintf(stderr, "%s: --set needs name=value\n", progname);
        return -1;
      }
      memcpy(name, kv, eq - kv);
      name[eq - kv] = 0;
      lmvmpm_override(L, name, eq + 1);
    } else if (strcmp(argv[i], "--out") == 0) {
      if (i + 1 >= argc) { fprintf(stderr, "%s: --out needs a directory\n", progname); return -1; }
      *out = argv[++i];
    } else if (strcmp(argv[i], "--quiet") == 0) {
      *quiet = 1;
    } else if (argv[i][0] == '-' && argv[i][1]) {
      fprintf(stderr, "%s: unknown option '%s' (see %s --help)\n", progname, argv[i], progname);
      return -1;
    } else if (!*scene) {
      *scene = argv[i];
    } else {
      fprintf(stderr, "%s: unexpected argument '%s'\n", progname, argv[i]);
      return -1;
    }
  }
  return 0;
}

static void basename_noext(const char *path, char *out, size_t n) {
  const char *b = strrchr(path, '/');
  char *dot;
  snprintf(out, n, "%s", b ? b + 1 : path);
  dot = strrchr(out, '.');
  if (dot && dot != out) *dot = 0;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int traceback(lua_State *L) {
  const char *msg = lua_tostring(L, 1);
  luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
  return 1;
}

static int cmd_run(int argc, char **argv) {
  const char *scene = NULL, *out = NULL;
  int quiet = 0, rc;
  lua_State *L = newstate(argv[0]);
  lsim *ls;
  double w0;
  char name[256];
  if (options(L, argc, argv, 2, &scene, &out, &quiet)) return 2;
  if (!scene) { usage(stderr); return 2; }
  if (lmvmpm_load(L, scene) || lmvmpm_check_overrides(L)) return fail(L, NULL);
  ls = lua_touserdata(L, -1);
  if (out) { snprintf(ls->outdir, sizeof ls->outdir, "%s", out); ls->out_enabled = 1; }
  if (!ls->outdir[0]) {
    basename_noext(scene, name, sizeof name);
    snprintf(ls->outdir, sizeof ls->outdir, "out/%s", name);
    ls->out_enabled = 1;
  }
  if (ls->out_enabled && ls->out_every <= 0) ls->out_every = ls->s.t_end / 20;
  if (ls->out_enabled && ls->csv_every <= 0) ls->csv_every = 1;
  ls->progress = !quiet;
  lua_setglobal(L, "sim");
  w0 = now();
  interrupt_install(L);
  lua_pushcfunction(L, traceback);
  lua_getglobal(L, "sim");
  lua_getfield(L, -1, "run");
  lua_insert(L, -2);
  rc = lua_pcall(L, 1, 0, -3);
  interrupt_uninstall();
  if (rc) {
    fprintf(stderr, "\n");
    fail(L, NULL);
  }
  lua_settop(L, 0);
  lua_getglobal(L, "sim");
  ls = lua_touserdata(L, -1);
  if (run_close(L, ls) == 0 && !rc && !quiet) {
    sim *s = &ls->s;
    printf("%s: %ld steps to t = %g, %zu particles, %d bodies, %.2f s wall\n",
           scene, s->step, s->t, s->ps.n, s->nbody, now() - w0);
    printf("energy: initial %.6g  kinetic %.6g  strain %.6g  dissipated %.6g  "
           "boundary work %.6g  residual %.3g (%.3g%% of initial)\n",
           s->e.initial, s->e.kinetic, s->e.strain, s->e.friction, s->e.boundary,
           sim_residual(s),
           100 * sim_residual(s) / (s->e.initial > 0 ? s->e.initial : 1));
    if (s->e.plastic != 0 || s->e.viscous != 0 || s->e.thermal != 0)
      printf("        plastic %.6g  viscous %.6g  thermal work %.6g\n",
             s->e.plastic, s->e.viscous, s->e.thermal);
    if (s->nremoved) printf("%zu particles left the domain and were removed\n", s->nremoved);
    printf("output: %s/ (particles.xmf, %d snapshots, diagnostics.csv)\n",
           ls->outdir, ls->nsnap);
  }
  lua_close(L);
  return rc ? 1 : 0;
}

static int cmd_repl(int argc, char **argv) {
  const char *scene = NULL, *out = NULL;
  int quiet = 0;
  lua_State *L = newstate(argv[0]);
  char hist[1024];
  const char *home = getenv("HOME");
  if (options(L, argc, argv, 2, &scene, &out, &quiet)) return 2;
  if (luaL_dostring(L, "require 'mvmpm.repl'"))
    fprintf(stderr, "%s: %s\n", progname, lua_tostring(L, -1));
  lua_settop(L, 0);
  if (scene) {
    lsim *ls;
    if (lmvmpm_load(L, scene) || lmvmpm_check_overrides(L)) return fail(L, NULL);
    ls = lua_touserdata(L, -1);
    if (out) { snprintf(ls->outdir, sizeof ls->outdir, "%s", out); ls->out_enabled = 1; }
    ls->progress = 1;
    lua_setglobal(L, "sim");
  }
  if (isatty(0)) {
    printf("mvmpm %s  (Lua %s.%s)  %s\n", MVMPM_VERSION, LUA_VERSION_MAJOR,
           LUA_VERSION_MINOR, scene ? scene : "");
    if (scene) printf("the scene is loaded as 'sim'; help() lists what you can do\n");
    else printf("help() lists what you can do\n");
  }
  snprintf(hist, sizeof hist, "%s/.mvmpm_history", home ? home : ".");
  repl_run(L, hist);
  lua_close(L);
  return 0;
}

static int verify_counts(lua_State *L, int *pass, int *failc) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "loaded");
  lua_getfield(L, -1, "mvmpm.verify");
  if (lua_istable(L, -1)) {
    lua_getfield(L, -1, "passed");
    *pass += (int)lua_tointeger(L, -1);
    lua_getfield(L, -2, "failed");
    *failc += (int)lua_tointeger(L, -1);
    lua_pop(L, 2);
  }
  lua_pop(L, 3);
  return 0;
}

static int cmd_test(int argc, char **argv) {
  glob_t gl;
  char **files;
  int nfiles, k, pass = 0, failc = 0, own = 0;
  memset(&gl, 0, sizeof gl);
  if (argc > 2) {
    files = argv + 2;
    nfiles = argc - 2;
  } else {
    if (glob("tests/verify/*.lua", 0, NULL, &gl) || gl.gl_pathc == 0) {
      fprintf(stderr, "%s: no tests/verify/*.lua here (run from the project root "
                      "or name the files)\n", progname);
      return 2;
    }
    files = gl.gl_pathv;
    nfiles = (int)gl.gl_pathc;
    own = 1;
  }
  for (k = 0; k < nfiles; k++) {
    lua_State *L = newstate(argv[0]);
    int p = 0, f = 0;
    double w0 = now();
    printf("== %s\n", files[k]);
    fflush(stdout);
    lua_pushboolean(L, 1);
    lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.testing");
    lua_pushcfunction(L, traceback);
    if (luaL_loadfile(L, files[k]) || lua_pcall(L, 0, 0, 1)) {
      printf("FAIL %s: %s\n", files[k], lua_tostring(L, -1));
      f++;
    }
    verify_counts(L, &p, &f);
    printf("-- %s: %d passed, %d failed (%.1f s)\n", files[k], p, f, now() - w0);
    pass += p;
    failc += f;
    lua_close(L);
  }
  if (own) globfree(&gl);
  printf("%d passed, %d failed\n", pass, failc);
  return failc ? 1 : 0;
}

int main(int argc, char **argv) {
  if (argc < 2) { usage(stderr); return 2; }
  if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
      strcmp(argv[1], "help") == 0) {
    usage(stdout);
    return 0;
  }
  if (strcmp(argv[1], "--version") == 0) {
    printf("mvmpm %s (%dD, Lua %s.%s)\n", MVMPM_VERSION, DIM, LUA_VERSION_MAJOR,
           LUA_VERSION_MINOR);
    return 0;
  }
  if (strcmp(argv[1], "run") == 0) return cmd_run(argc, argv);
  if (strcmp(argv[1], "repl") == 0) return cmd_repl(argc, argv);
  if (strcmp(argv[1], "test") == 0) return cmd_test(argc, argv);
  if (strcmp(argv[1], "render") == 0) return render_cmd(argc, argv);
  fprintf(stderr, "%s: unknown command '%s' (see %s --help)\n", progname, argv[1], progname);
  return 2;
}
