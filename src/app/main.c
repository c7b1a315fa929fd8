/*
** main.c - the mvmpm command: run a scene, step it at a prompt, or run
** verification scripts.
*/
#include <errno.h>
#include <glob.h>
#ifdef __linux__
#include <malloc.h>
#endif
#include <math.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "lckpt.h"
#include "interrupt.h"
#include "lauxlib.h"
#include "lmvmpm.h"
#include "lsim.h"
#include "lualib.h"
#include "render_cmd.h"
#include "app.h"
#include "out_h5.h"

#define APP_OTHER LSIM_OTHER_DIM
#include "prof.h"
#include "repl.h"
#include "sandbox.h"
#include "version.h"

static const char *progname = "mvmpm";

/* each command: its synopsis and what it does; usage() prints them all,
** "mvmpm CMD --help" its own */
typedef struct cmdhelp { const char *name, *syn, *text; } cmdhelp;
static const cmdhelp helps[] = {
  {"run",
"run SCENE.lua [--set name=value ...] [--out DIR] [--quiet]\n"
"                [--t-end T] [--overwrite] [--checkpoint-every T] [--sandbox]\n"
"                [--threads N] [--profile]\n"
"       %s run --restart CHECKPOINT|DIR [SCENE.lua] [--set ...] [--quiet]\n"
"                [--t-end T] [--checkpoint-every T] [--sandbox]\n",
"run    runs the scene to its end time, writing HDF5 snapshots, an XDMF\n"
"       index (particles.xmf) and diagnostics.csv to DIR (default: the\n"
"       scene's output dir, else out/<scene name>)\n"
"--set  overrides a parameter the scene declares with mvmpm.params{...}\n"
"--t-end T  runs to simulated time T instead of the scene's t_end (a quick\n"
"       trial; with --restart: extends a run, or a finished one)\n"
"--overwrite  a directory holding another run's outputs is refused unless\n"
"       this is given; it then removes that run's particles_*.h5,\n"
"       particles.xmf, diagnostics.csv, checkpoint_*.h5 and failed_*.h5\n"
"       (nothing else)\n"
"--quiet  no progress and no summary; without it, a terminal shows a live\n"
"       progress line, anything else (2>log) a plain line every 10 % of\n"
"       the run or 30 s\n"
"--checkpoint-every T  writes DIR/checkpoint_NNNNNN.h5 every T of simulated\n"
"       time (the newest two are kept); --restart continues one bit for bit\n"
"       (DIR: its newest), in its directory, with the same --set values\n"
"--threads N  steps with N threads (default: the scene's sim{threads = N},\n"
"       else $MVMPM_THREADS, else 1); the results are the same bit for bit\n"
"--profile  prints the effects the step runs and, per phase, the wall time,\n"
"       the threads' CPU time and the time on idle cores\n"
"--sandbox  the scene gets no io, os (but clock/time/date), debug, package,\n"
"       dofile/loadfile or bytecode, and writes only inside DIR, following\n"
"       no link there; its checkpoints restart sandboxed\n"
"exit status: 0 done, 1 error, 2 usage, 130 stopped by Ctrl-C (a checkpoint\n"
"       was written; the message says how to continue)\n"},
  {"repl",
"repl [SCENE.lua] [--set name=value ...] [--out DIR]\n",
"repl   loads the scene without running it and gives a Lua prompt with the\n"
"       simulation as 'sim': sim:step(n), sim:run(t), sim:energy(),\n"
"       sim:bodies(), sim:snapshot(path); help() lists more.  Without a\n"
"       scene, a prompt with the mvmpm module loaded\n"
"--set  overrides a parameter the scene declares with mvmpm.params{...}\n"
"--out  the directory the scene's outputs go to\n"},
  {"test",
"test [FILE.lua ...]        (default: tests/verify/*.lua)\n",
"test   runs verification scripts; each check prints measured vs reference\n"
"       and tolerance; ends with 'N passed, M failed' (status 1 if any\n"
"       failed)\n"},
  {"render",
"render SNAPSHOT.h5|CHECKPOINT.h5 [--by KEY] [--out FILE.png|.svg]\n"
"                [--width N] [--range LO,HI|robust|full] [--log] [--no-axes]\n"
"                [--colormap auto|seq|div] [--title TEXT] [--matrix BODY]\n"
"                [--domain X0,X1,Y0,Y1]\n"
"                3-D: [--axis x|y|z] [--at POS] [--thick T] [--project]\n",
"render draws a snapshot's or a checkpoint's particles as a PNG or SVG,\n"
"       coloured by KEY: body, pressure, sdiff (principal stress\n"
"       difference), speed, or a field such as velocity.x, stress.xy, mass\n"
"       (default: body); FILE defaults to the snapshot's name with _KEY.png\n"
"--range  the colour scale's ends (default robust: the 1st to 99th\n"
"       percentile; full: min to max)\n"
"--log  colour by log10 of the value (every value must be above zero)\n"
"--colormap  seq (one hue), div (two, centred on 0) or auto\n"
"--domain  the part of the plane drawn (default: the scene's domain the\n"
"       file records, else the particles')\n"
"--no-axes  no ticks, tick labels or axis titles\n"
"--matrix  the body drawn grey among grains (default: one named binder or\n"
"       matrix, else a body holding most of the particles)\n"
"--axis  3-D: the axis the picture looks along (default z; 2-D: only z)\n"
"--at  3-D: where along --axis the slice lies (default: the middle of the\n"
"       stored domain)\n"
"--thick  3-D: a slab of that thickness, the particles whose centres lie\n"
"       in it (default: those whose own cube crosses the plane)\n"
"--project  3-D: every particle, projected along --axis, instead of a slice\n"},
};
#define NCMD (int)(sizeof helps / sizeof helps[0])

static void usage(FILE *f) {
  int k;
  for (k = 0; k < NCMD; k++) {
    fprintf(f, "%s %s ", k ? "      " : "usage:", progname);
    fprintf(f, helps[k].syn, progname);
  }
  fprintf(f, "       %s CMD --help | --help | --version\n\n", progname);
  for (k = 0; k < NCMD; k++) fputs(helps[k].text, f);
  fprintf(f, "\nmanual: man mvmpm (docs/mvmpm.1)\n");
}

/* "mvmpm CMD ... --help": CMD's synopsis and options on stdout, 0; -1 if
** the line asks for no help.  An argument that follows an option taking
** a value (--set --help) is that value, not a request */
static int cmdhelp_of(int argc, char **argv) {
  int i, k;
  for (i = 2; i < argc; i++) {
    const char *a = argv[i];
    if (strcmp(a, "--help") != 0 && strcmp(a, "-h") != 0) continue;
    if (i > 2 && argv[i - 1][0] == '-' && argv[i - 1][1] == '-' &&
        strcmp(argv[i - 1], "--quiet") != 0 &&
        strcmp(argv[i - 1], "--sandbox") != 0 &&
        strcmp(argv[i - 1], "--profile") != 0)
      continue;
    for (k = 0; k < NCMD; k++)
      if (strcmp(argv[1], helps[k].name) == 0) {
        printf("usage: %s ", progname);
        printf(helps[k].syn, progname);
        printf("\n%s", helps[k].text);
        return 0;
      }
  }
  return -1;
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
  int overwrite;           /* remove another run's outputs in the dir */
  double t_end;            /* --t-end; <= 0: not given */
  int t_end_set;           /* --set t_end=... was given */
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
      if (strcmp(name, "t_end") == 0) o->t_end_set = 1;
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
    } else if (run && strcmp(argv[i], "--overwrite") == 0) {
      o->overwrite = 1;
    } else if (run && (strcmp(argv[i], "--t-end") == 0 ||
                       strncmp(argv[i], "--t-end=", 8) == 0)) {
      const char *v = argv[i][7] == '=' ? argv[i] + 8 : (i + 1 < argc ? argv[++i] : NULL);
      char *end = NULL;
      if (v) o->t_end = strtod(v, &end);
      if (!v || !end || end == v || *end || !(o->t_end > 0) || !isfinite(o->t_end)) {
        fprintf(stderr, "%s: --t-end needs a time > 0 (the simulated time "
                "to run to)\n", progname);
        return -1;
      }
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

/* the command line as one shell-quoted string, for the provenance every
** output file carries (registry "mvmpm.command") */
static void set_command(lua_State *L, int argc, char **argv) {
  luaL_Buffer b;
  int i;
  luaL_buffinit(L, &b);
  for (i = 0; i < argc; i++) {
    const char *a = argv[i], *p;
    int plain = a[0] != 0;
    for (p = a; *p; p++)
      if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                  "0123456789_./=:,+-@%", *p))
        plain = 0;
    if (i) luaL_addchar(&b, ' ');
    if (plain) { luaL_addstring(&b, a); continue; }
    luaL_addchar(&b, '\'');
    for (p = a; *p; p++) {
      if (*p == '\'') luaL_addstring(&b, "'\\''");
      else luaL_addchar(&b, (unsigned char)*p < ' ' ? '?' : *p);
    }
    luaL_addchar(&b, '\'');
  }
  luaL_pushresult(&b);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.command");
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
  /* a regular file only: a FIFO would block its reader (ckpt_read
  ** refuses it below) */
  if (stat(path, &st) == 0 && S_ISREG(st.st_mode) &&
      out_h5_file_dim(path) == APP_OTHER)
    return APP_REDO;
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
            "  stored: %s\n  given:  %s\n%s", progname, path,
            stored[0] ? stored : "(none)\n", given,
            o->t_end_set ? "  (to extend the run to a later end time, give "
            "--t-end T)\n" : "");
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

/* A scene of the other dimension (lsim_dim_check) while the C side holds
** a simulation of this one: the scene stops, and the command starts again
** in that dimension (entry.c).  mark: on while a scene is loaded */
static void redo_mark(lua_State *L, int on) {
  if (on) lua_pushboolean(L, 1);
  else lua_pushnil(L);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.redo");
}

static int redo_asked(lua_State *L) {
  int r = lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.redo_dim") == LUA_TNUMBER;
  lua_pop(L, 1);
  return r;
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
  set_command(L, argc, argv);
  if (o.restart) {
    struct stat st;
    /* a checkpoint that is no regular file (a FIFO) would block its reader */
    if (!(stat(o.restart, &st) == 0 && S_ISDIR(st.st_mode)) &&
        lmvmpm_regular(o.restart, err, sizeof err)) {
      fprintf(stderr, "%s: %s\n", progname, err);
      lua_close(L);
      return 1;
    }
    if ((rc = restart_prepare(L, &o, &c, root, sizeof root)) == APP_REDO) {
      ckpt_free(&c);
      lua_close(L);
      return APP_REDO;
    }
    if (rc || restart_sandbox(&o, &c) ||
        (!o.scene && !(o.scene = stored_scene = ckpt_string(&c, CB_SCENE))) ||
        !(text = restart_scene_text(&c, o.scene))) {
      ckpt_free(&c);
      free(stored_scene);
      lua_close(L);
      return 1;
    }
    /* the provenance of what this run writes names where it came from */
    lua_pushstring(L, c.path);
    lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.restarted");
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
  redo_mark(L, 1);
  if ((text ? lmvmpm_load_text(L, o.scene, text) : lmvmpm_load(L, o.scene)) ||
      lmvmpm_check_overrides(L)) {
    if (redo_asked(L)) {
      ckpt_free(&c);
      free(stored_scene);
      free(text);
      lua_close(L);
      return APP_REDO;
    }
    fail(L, NULL);
    ckpt_free(&c);
    free(stored_scene);
    free(text);
    lua_close(L);
    return 1;
  }
  free(text);
  redo_mark(L, 0);
  ls = lua_touserdata(L, -1);
  if (o.t_end > 0 && !o.restart) ls->s.t_end = o.t_end;
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
  /* a new run never mixes its outputs with an older run's */
  if (!o.restart && ls->out_enabled &&
      run_claim_outdir(ls->outdir, o.overwrite, err, sizeof err)) {
    fprintf(stderr, "%s: %s\n", progname, err);
    free(stored_scene);
    lua_close(L);
    return 1;
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
    if (o.t_end > 0) { /* extend (or shorten) the run */
      if (!(o.t_end > ls->s.t)) {
        fprintf(stderr, "%s: --t-end %g: the checkpoint %s is at t = %g; "
                "give a later time\n", progname, o.t_end, c.path, ls->s.t);
        ckpt_free(&c);
        free(stored_scene);
        lua_close(L);
        return 1;
      }
      ls->s.t_end = o.t_end;
    }
    if (!o.quiet)
      printf("%s: continuing from %s at step %ld, t = %g (to t = %g)\n",
             o.scene, c.path, ls->s.step, ls->s.t, ls->s.t_end);
    /* until this run writes one, the newest is where it started */
    snprintf(ls->ck_last, sizeof ls->ck_last, "%s", c.path);
    ckpt_free(&c);
    if (o.ck_every > 0) ls->ck_next = ls->s.t + o.ck_every;
  }
  if (o.ck_every > 0) ls->ck_every = o.ck_every;
  ls->ck_on_interrupt = 1;
  ls->progress = !o.quiet;
  if (o.threads) sim_set_threads(&ls->s, o.threads);
  if (o.profile) par_account(1);
  if (o.profile && !(ls->s.work.prof = calloc(1, sizeof *ls->s.work.prof))) {
    fprintf(stderr, "%s: out of memory\n", progname);
    lua_close(L);
    free(stored_scene);
    return 1;
  }
  if (ls->s.work.prof) ls->s.work.prof->last = prof_clock();
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
    /* the residual against the budget's scale: a share of the initial
    ** energy would hold the potential's value, which the origin sets */
    printf("energy: initial %.6g  kinetic %.6g  strain %.6g  dissipated %.6g  "
           "boundary work %.6g  residual %.3g (%.3g%% of the scale %.6g)\n",
           s->e.initial, s->e.kinetic, s->e.strain, s->e.friction, s->e.boundary,
           sim_residual(s),
           100 * sim_residual(s) / (sim_scale(s) > 0 ? sim_scale(s) : 1),
           sim_scale(s));
    /* the rest of the total the residual takes (sim_total): without it
    ** the line above does not add up under gravity or spring walls */
    if (s->e.potential != 0 || s->e.wall_spring != 0)
      printf("        potential %.6g (initial %.6g)  wall springs %.6g  "
             "step lag %.3g\n", s->e.potential, s->e.potential0,
             s->e.wall_spring, s->e.lag);
    if (s->e.transfer != 0 || s->e.impact != 0 || s->e.bonding != 0)
      printf("        numerical: transfer %.6g  impact %.6g  bonding %.6g\n",
             s->e.transfer, s->e.impact, s->e.bonding);
    if (s->e.plastic != 0 || s->e.viscous != 0 || s->e.thermal != 0 ||
        s->e.settled != 0)
      printf("        plastic %.6g  viscous %.6g  thermal work %.6g  settled "
             "%.6g\n", s->e.plastic, s->e.viscous, s->e.thermal,
             s->e.settled);
    if (s->nremoved)
      printf("%zu particles left the domain and were removed, taking energy "
             "%.6g (booked as removed)\n", s->nremoved, s->e.removed);
    if (s->nheld)
      printf("%zu particle moves were held at a penalty wall (its spring too "
             "soft for the load: raise wall_stiffness)\n", s->nheld);
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
    redo_mark(L, 1);
    if (lmvmpm_load(L, scene) || lmvmpm_check_overrides(L)) {
      int redo = redo_asked(L);
      if (!redo) fail(L, NULL);
      lua_close(L);
      return redo ? APP_REDO : 1;
    }
    redo_mark(L, 0);
    ls = lua_touserdata(L, -1);
    if (out) { snprintf(ls->outdir, sizeof ls->outdir, "%s", out); ls->out_enabled = 1; }
    ls->progress = 1;
    lua_setglobal(L, "sim");
  }
  if (isatty(0)) {
    printf("mvmpm %s  (Lua %s.%s)  %s\n", mvmpm_version, LUA_VERSION_MAJOR,
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

/*
** glibc hands memory above 128 KiB back to the system when it is freed
** (munmap, or trimming the heap's top), and the next allocation of that
** size faults in fresh zeroed pages.  A snapshot allocates and frees a
** few such buffers (zlib's state, HDF5's file image in memory, ours):
** with the defaults, page faults were 2/3 of a small snapshot's CPU
** time.  Keeping up to 64 MiB of freed memory, and mapping only blocks
** of 16 MiB and more, reuses the pages instead.
*/
static void malloc_tune(void) {
#if defined(__GLIBC__) && defined(M_TRIM_THRESHOLD) && defined(M_MMAP_THRESHOLD)
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_MMAP_THRESHOLD, 16 << 20);
#endif
}

int app_main(int argc, char **argv) {
  malloc_tune();
  if (argc < 2) { usage(stderr); return 2; }
  if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
      strcmp(argv[1], "help") == 0) {
    usage(stdout);
    return 0;
  }
  if (strcmp(argv[1], "--version") == 0) {
    printf("mvmpm %s (2-D and 3-D, Lua %s.%s)\n", mvmpm_version,
           LUA_VERSION_MAJOR, LUA_VERSION_MINOR);
    return 0;
  }
  if (cmdhelp_of(argc, argv) == 0) return 0;
  if (strcmp(argv[1], "run") == 0) return cmd_run(argc, argv);
  if (strcmp(argv[1], "repl") == 0) return cmd_repl(argc, argv);
  if (strcmp(argv[1], "test") == 0) return cmd_test(argc, argv);
  if (strcmp(argv[1], "render") == 0) return render_cmd(argc, argv);
  fprintf(stderr, "%s: unknown command '%s' (see %s --help)\n", progname, argv[1], progname);
  return 2;
}
