/*
** main.c - the mvmpm command: run a scene, step it at a prompt, or run
** verification scripts.
*/
#include <errno.h>
#include <glob.h>
#include <math.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "ckpt.h"
#include "interrupt.h"
#include "lauxlib.h"
#include "lmvmpm.h"
#include "lsim.h"
#include "lualib.h"
#include "render_cmd.h"
#include "prof.h"
#include "repl.h"
#include "sandbox.h"

static const char *progname = "mvmpm";

static void usage(FILE *f) {
  fprintf(f,
"usage: %s run SCENE.lua [--set name=value ...] [--out DIR] [--quiet]\n"
"                [--checkpoint-every T] [--sandbox] [--threads N] [--profile]\n"
"       %s run --restart CHECKPOINT|DIR [SCENE.lua] [--set ...] [--quiet]\n"
"                [--checkpoint-every T] [--sandbox]\n"
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
"--set  overrides a parameter the scene declares with mvmpm.params{...}\n"
"--checkpoint-every T  writes DIR/checkpoint_NNNNNN.h5 every T of simulated\n"
"       time (the newest two are kept); --restart continues one bit for bit\n"
"       (DIR: its newest), in its directory, with the same --set values\n"
"--threads N  steps with N threads (default: the scene's sim{threads = N},\n"
"       else $MVMPM_THREADS, else 1); the results are the same bit for bit\n"
"--profile  prints the effects the step runs and the wall time per phase\n"
"--sandbox  the scene gets no io, os (but clock/time/date), debug, package,\n"
"       dofile/loadfile or bytecode, and writes only inside DIR, following\n"
"       no link there; its checkpoints restart sandboxed\n"
"exit status: 0 done, 1 error, 2 usage, 130 stopped by Ctrl-C (a checkpoint\n"
"       was written; the message says how to continue)\n",
          progname, progname, progname, progname, progname, progname);
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

typedef struct runopts {
  const char *scene, *out, *restart;
  int quiet, sandbox, nset;
  int threads;             /* 0: not given (the scene's, or $MVMPM_THREADS) */
  int profile;             /* print the effects and the time per phase */
  double ck_every;         /* < 0: not given */
} runopts;

/* the options of run and repl (repl takes only --set, --out, --quiet) */
static int options(lua_State *L, int argc, char **argv, int i, runopts *o,
                   int run) {
  memset(o, 0, sizeof *o);
  o->ck_every = -1;
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
      o->nset++;
    } else if (strcmp(argv[i], "--out") == 0) {
      if (i + 1 >= argc) { fprintf(stderr, "%s: --out needs a directory\n", progname); return -1; }
      o->out = argv[++i];
      if (!o->out[0]) { /* not "/": an empty root would be no root */
        fprintf(stderr, "%s: --out needs a directory (the name given is "
                "empty)\n", progname);
        return -1;
      }
    } else if (strcmp(argv[i], "--quiet") == 0) {
      o->quiet = 1;
    } else if (run && strcmp(argv[i], "--sandbox") == 0) {
      o->sandbox = 1;
    } else if (run && strcmp(argv[i], "--restart") == 0) {
      if (i + 1 >= argc) {
        fprintf(stderr, "%s: --restart needs a checkpoint file or its directory\n", progname);
        return -1;
      }
      o->restart = argv[++i];
    } else if (run && strcmp(argv[i], "--threads") == 0) {
      char *end = NULL;
      long n = i + 1 < argc ? strtol(argv[++i], &end, 10) : 0;
      if (!end || *end || n < 1 || n > PAR_MAX) {
        fprintf(stderr, "%s: --threads needs a count from 1 to %d\n", progname,
                PAR_MAX);
        return -1;
      }
      o->threads = (int)n;
    } else if (run && strcmp(argv[i], "--profile") == 0) {
      o->profile = 1;
    } else if (run && strcmp(argv[i], "--checkpoint-every") == 0) {
      char *end = NULL;
      if (i + 1 < argc) o->ck_every = strtod(argv[++i], &end);
      if (!end || *end || !(o->ck_every > 0) || !isfinite(o->ck_every)) {
        fprintf(stderr, "%s: --checkpoint-every needs a time > 0 (simulated "
                        "time between checkpoints)\n", progname);
        return -1;
      }
    } else if (argv[i][0] == '-' && argv[i][1]) {
      fprintf(stderr, "%s: unknown option '%s' (see %s --help)\n", progname, argv[i], progname);
      return -1;
    } else if (!o->scene) {
      o->scene = argv[i];
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

/* the directory part of a path ("." for a bare name) */
static void dirname_of(const char *path, char *out, size_t n) {
  const char *b = strrchr(path, '/');
  if (!b) snprintf(out, n, ".");
  else if (b == path) snprintf(out, n, "/");
  else snprintf(out, n, "%.*s", (int)(b - path), path);
}

/*
** Before the scene loads again: which checkpoint, its directory, and the
** parameters.  With no --set the stored ones apply; with some, they must
** be the stored ones (a run continued with other parameters would be
** neither run).  Prints the reason and returns -1 on failure.
*/
static int restart_prepare(lua_State *L, runopts *o, ckpt *c, char *outdir,
                           size_t outlen) {
  char path[1100], err[1400];
  struct stat st;
  char *stored, *given;
  if (o->out) {
    fprintf(stderr, "%s: --out cannot be given with --restart: the run "
            "continues in its checkpoint's directory\n", progname);
    return -1;
  }
  snprintf(path, sizeof path, "%s", o->restart);
  if (stat(path, &st) == 0 && S_ISDIR(st.st_mode) &&
      ckpt_latest(o->restart, path, sizeof path, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", progname, err);
    return -1;
  }
  if (ckpt_read(c, path, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", progname, err);
    return -1;
  }
  dirname_of(path, outdir, outlen);
  stored = ckpt_string(c, CB_PARAMS);
  given = o->nset ? ckpt_overrides(L) : NULL;
  if (!stored || (o->nset && !given)) {
    fprintf(stderr, "%s: out of memory\n", progname);
    return -1;
  }
  if (o->nset && strcmp(stored, given) != 0) {
    fprintf(stderr, "%s: %s: the run was made with other parameters; give the "
            "same --set values or none (then the stored ones apply)\n"
            "  stored: %s\n  given:  %s\n", progname, path,
            stored[0] ? stored : "(none)\n", given);
    free(stored);
    free(given);
    return -1;
  }
  if (!o->nset) {
    char *line = stored, *nl;
    for (; (nl = strchr(line, '\n')); line = nl + 1) {
      char *eq = strchr(line, '=');
      *nl = '\0';
      if (!eq) continue;
      *eq = '\0';
      lmvmpm_override(L, line, eq + 1);
    }
  }
  free(stored);
  free(given);
  return 0;
}

/*
** Before anything runs: the scene file must hold the text the checkpoint
** was written from.  What then runs is that compared text, not the file
** read again, so a file changed in between is never executed.  Returns
** the text (malloc'ed), or NULL after printing why.
*/
static char *restart_scene_text(const ckpt *c, const char *scene) {
  char err[1200];
  char *src = ckpt_string(c, CB_SOURCE), *file = lmvmpm_read(scene, err, sizeof err);
  int same = src && file && strcmp(src, file) == 0;
  if (!src)
    fprintf(stderr, "%s: out of memory\n", progname);
  else if (!file)
    fprintf(stderr, "%s: %s\n", progname, err);
  else if (!same)
    fprintf(stderr, "%s: %s is not the scene %s was written from (its text "
            "differs); a changed scene cannot continue the run, and none of "
            "it was run\n", progname, scene, c->path);
  free(file);
  if (!same) free(src);
  return same ? src : NULL;
}

/* a run under --sandbox continues under it: a checkpoint does not give
** the scene more than it had */
static int restart_sandbox(runopts *o, const ckpt *c) {
  int was = ckpt_sandboxed(c);
  if (was < 0) {
    fprintf(stderr, "%s: %s does not record whether its run was under "
            "--sandbox (written by an older mvmpm); it cannot continue\n",
            progname, c->path);
    return -1;
  }
  if (was && !o->sandbox) {
    fprintf(stderr, "%s: %s was written by a run under --sandbox, so this "
            "one is too (--sandbox applies)\n", progname, c->path);
    o->sandbox = 1;
  }
  return 0;
}

/*
** The output directory the command line decides must be one the run can
** use: a directory that is there and writable, or one whose nearest
** existing parent is (then it is made when output starts).
*/
static int usable_dir(const char *dir, char *err, size_t errlen) {
  char up[1024], next[1024];
  const char *why;
  struct stat st;
  if (stat(dir, &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      snprintf(err, errlen, "%s: the output directory is not a directory",
               dir);
    else if (access(dir, W_OK | X_OK) != 0)
      snprintf(err, errlen, "%s: the output directory cannot be written (%s)",
               dir, strerror(errno));
    else return 0;
    return -1;
  }
  if (errno != ENOENT) {
    snprintf(err, errlen, "%s: cannot create directory (%s)", dir,
             strerror(errno));
    return -1;
  }
  snprintf(up, sizeof up, "%s", dir);
  for (;;) { /* the nearest parent that exists */
    dirname_of(up, next, sizeof next);
    if (strcmp(next, up) == 0) break;
    snprintf(up, sizeof up, "%s", next);
    if (stat(up, &st) == 0 || errno != ENOENT) break;
  }
  if (stat(up, &st) != 0) why = strerror(errno);
  else if (!S_ISDIR(st.st_mode)) why = "not a directory";
  else if (access(up, W_OK | X_OK) != 0) why = strerror(errno);
  else return 0;
  snprintf(err, errlen, "%s: the output directory cannot be made (%s: %s)",
           dir, up, why);
  return -1;
}

/* --profile: what the engine does each step, and where the time went */
static void profile(const lsim *ls) {
  prof_effects(stdout, &ls->s);
  printf("per step, outside the engine:\n");
  printf("  %-22s %s", "CSV row", ls->csv_open && ls->csv_every > 0 ? "" : "no\n");
  if (ls->csv_open && ls->csv_every > 0)
    printf("every %ld step(s)\n", ls->csv_every);
  printf("  %-22s %d\n", "callbacks (sim:every)", ls->nevery);
  printf("  %-22s %s\n", "drives as functions",
         ls->drives || ls->sidefns || ls->tempfn ? "yes" : "no");
  printf("  %-22s %d written\n", "snapshots", ls->nsnap);
  printf("  %-22s %d written\n", "checkpoints", ls->ck_count);
  prof_report(stdout, &ls->s);
}

static int cmd_run(int argc, char **argv) {
  runopts o;
  int rc;
  lua_State *L = newstate(argv[0]);
  lsim *ls;
  double w0;
  char name[256], root[1024] = "", err[1400], *stored_scene = NULL;
  char *text = NULL;       /* restart: the compared scene text */
  char cont[1200];         /* how to continue from the newest checkpoint */
  ckpt c;
  memset(&c, 0, sizeof c);
  particles_init(&c.ps);
  if (options(L, argc, argv, 2, &o, 1)) { lua_close(L); return 2; }
  if (!o.scene && !o.restart) { usage(stderr); lua_close(L); return 2; }
  if (o.restart) {
    struct stat st;
    /* a checkpoint that is no regular file (a FIFO) would block its reader */
    if (!(stat(o.restart, &st) == 0 && S_ISDIR(st.st_mode)) &&
        lmvmpm_regular(o.restart, err, sizeof err)) {
      fprintf(stderr, "%s: %s\n", progname, err);
      lua_close(L);
      return 1;
    }
    if (restart_prepare(L, &o, &c, root, sizeof root) ||
        restart_sandbox(&o, &c) ||
        (!o.scene && !(o.scene = stored_scene = ckpt_string(&c, CB_SCENE))) ||
        !(text = restart_scene_text(&c, o.scene))) {
      ckpt_free(&c);
      free(stored_scene);
      lua_close(L);
      return 1;
    }
  } else if (o.out) snprintf(root, sizeof root, "%s", o.out);
  else {
    basename_noext(o.scene, name, sizeof name);
    snprintf(root, sizeof root, "out/%s", name);
  }
  /* the root the command line fixes is checked before the scene runs */
  if ((o.out || o.sandbox) && usable_dir(root, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", progname, err);
    ckpt_free(&c);
    free(stored_scene);
    free(text);
    lua_close(L);
    return 1;
  }
  if (o.sandbox) sandbox_open(L, root);
  if ((text ? lmvmpm_load_text(L, o.scene, text) : lmvmpm_load(L, o.scene)) ||
      lmvmpm_check_overrides(L)) {
    fail(L, NULL);
    ckpt_free(&c);
    free(stored_scene);
    free(text);
    lua_close(L);
    return 1;
  }
  free(text);
  ls = lua_touserdata(L, -1);
  if (o.ck_every > 0 && (ls->s.t_end - ls->s.t) / o.ck_every > LSIM_MAX_EVENTS) {
    fprintf(stderr, "%s: --checkpoint-every %g would write %.3g checkpoints "
            "to t_end = %g (at most %.0e): give at least %g\n", progname,
            o.ck_every, (ls->s.t_end - ls->s.t) / o.ck_every, ls->s.t_end,
            LSIM_MAX_EVENTS, (ls->s.t_end - ls->s.t) / LSIM_MAX_EVENTS);
    ckpt_free(&c);
    free(stored_scene);
    lua_close(L);
    return 1;
  }
  if (o.restart || o.sandbox || o.out) { /* the command line decides */
    snprintf(ls->outdir, sizeof ls->outdir, "%s", root);
    ls->out_enabled = 1;
  }
  if (!ls->outdir[0]) {
    snprintf(ls->outdir, sizeof ls->outdir, "%s", root);
    ls->out_enabled = 1;
  }
  if (ls->out_enabled && ls->out_every <= 0) ls->out_every = ls->s.t_end / 20;
  if (ls->out_enabled && ls->csv_every <= 0) ls->csv_every = 1;
  if (o.restart) {
    int bad = ckpt_apply(L, -1, &c, err, sizeof err);
    if (bad) fprintf(stderr, "%s: %s\n", progname, err);
    if (bad) {
      ckpt_free(&c);
      free(stored_scene);
      lua_close(L);
      return 1;
    }
    if (!o.quiet)
      printf("%s: continuing from %s at step %ld, t = %g\n", o.scene, c.path,
             ls->s.step, ls->s.t);
    /* until this run writes one, the newest is where it started */
    snprintf(ls->ck_last, sizeof ls->ck_last, "%s", c.path);
    ckpt_free(&c);
    if (o.ck_every > 0) ls->ck_next = ls->s.t + o.ck_every;
  }
  if (o.ck_every > 0) ls->ck_every = o.ck_every;
  ls->ck_on_interrupt = 1;
  ls->progress = !o.quiet;
  if (o.threads) sim_set_threads(&ls->s, o.threads);
  if (o.profile && !(ls->s.prof = calloc(1, sizeof *ls->s.prof))) {
    fprintf(stderr, "%s: out of memory\n", progname);
    lua_close(L);
    free(stored_scene);
    return 1;
  }
  if (ls->s.prof) ls->s.prof->last = prof_clock();
  lua_setglobal(L, "sim");
  w0 = now();
  /* no Lua hook: Ctrl-C stops the run at the next step boundary, where a
  ** checkpoint can be written; a second Ctrl-C kills */
  interrupt_install(NULL);
  lua_pushcfunction(L, traceback);
  lua_getglobal(L, "sim");
  lua_getfield(L, -1, "run");
  lua_insert(L, -2);
  rc = lua_pcall(L, 1, 0, -3);
  interrupt_uninstall();
  interrupt_clear();
  lua_getglobal(L, "sim");
  ls = lua_touserdata(L, -1);
  /* a sandboxed run is continued sandboxed: the command says so too */
  snprintf(cont, sizeof cont, "%s run --restart %s%s", progname, ls->ck_last,
           o.sandbox ? " --sandbox" : "");
  if (rc && ls->interrupted) {
    fprintf(stderr, "%s%s: interrupted at step %ld, t = %g; checkpoint written: "
            "%s\ncontinue with: %s\n",
            ls->progress && isatty(2) ? "\n" : "", progname, ls->s.step,
            ls->s.t, ls->ck_last, cont);
    lua_close(L);
    free(stored_scene);
    return 130;
  }
  if (rc) {
    if (ls->progress && isatty(2)) fprintf(stderr, "\n"); /* end the progress line */
    lua_pop(L, 1);
    fail(L, NULL);
    if (ls->ck_last[0])
      fprintf(stderr, "%s: the newest checkpoint is %s (continue with: %s)\n",
              progname, ls->ck_last, cont);
  }
  lua_settop(L, 0);
  lua_getglobal(L, "sim");
  ls = lua_touserdata(L, -1);
  if (ls->csv_open && ls->csv.f && out_csv_close(&ls->csv, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", progname, err);
    if (!rc) rc = 1;
  } else if (!rc && !o.quiet) {
    sim *s = &ls->s;
    printf("%s: %ld steps to t = %g, %zu particles, %d bodies, %.2f s wall\n",
           o.scene, s->step, s->t, s->ps.n, s->nbody, now() - w0);
    printf("energy: initial %.6g  kinetic %.6g  strain %.6g  dissipated %.6g  "
           "boundary work %.6g  residual %.3g (%.3g%% of initial)\n",
           s->e.initial, s->e.kinetic, s->e.strain, s->e.friction, s->e.boundary,
           sim_residual(s),
           100 * sim_residual(s) / (s->e.initial > 0 ? s->e.initial : 1));
    if (s->e.transfer != 0 || s->e.impact != 0)
      printf("        numerical: transfer %.6g  impact %.6g\n", s->e.transfer,
             s->e.impact);
    if (s->e.plastic != 0 || s->e.viscous != 0 || s->e.thermal != 0)
      printf("        plastic %.6g  viscous %.6g  thermal work %.6g\n",
             s->e.plastic, s->e.viscous, s->e.thermal);
    if (s->nremoved) printf("%zu particles left the domain and were removed\n", s->nremoved);
    printf("output: %s/ (particles.xmf, %d snapshots, diagnostics.csv)\n",
           ls->outdir, ls->nsnap);
  }
  if (o.profile) profile(ls);
  lua_close(L);
  free(stored_scene);
  return rc ? 1 : 0;
}

static int cmd_repl(int argc, char **argv) {
  runopts o;
  const char *scene, *out;
  lua_State *L = newstate(argv[0]);
  char hist[1024];
  const char *home = getenv("HOME");
  if (options(L, argc, argv, 2, &o, 0)) { lua_close(L); return 2; }
  scene = o.scene;
  out = o.out;
  if (luaL_dostring(L, "require 'mvmpm.repl'"))
    fprintf(stderr, "%s: %s\n", progname, lua_tostring(L, -1));
  lua_settop(L, 0);
  if (scene) {
    lsim *ls;
    if (lmvmpm_load(L, scene) || lmvmpm_check_overrides(L)) {
      fail(L, NULL);
      lua_close(L);
      return 1;
    }
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
    char err[1200];
    lua_pushcfunction(L, traceback);
    if (lmvmpm_regular(files[k], err, sizeof err)) { /* a FIFO would block */
      printf("FAIL %s\n", err);
      f++;
    } else if (luaL_loadfile(L, files[k]) || lua_pcall(L, 0, 0, 1)) {
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
