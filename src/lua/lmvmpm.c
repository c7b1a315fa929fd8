/*
** lmvmpm.c - the "mvmpm" module: simulations, materials, shapes, scene
** parameters, and loading scenes.
**
** Parameters: a scene declares its parameters with defaults,
**   local P = mvmpm.params{friction = 0, cells = 8}
** and --set name=value (or mvmpm.load's table) overrides them, converted
** to the default's type.  Overrides live in the registry while a scene
** loads, in "mvmpm.overrides"; names a scene declares collect in
** "mvmpm.declared".
*/
#include <fcntl.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "lauxlib.h"
#include "lcheck.h"
#include "lmvmpm.h"
#include "par.h"
#include "lsim.h"
#include "lualib.h"
#include "ofile.h"
#include "sandbox.h"
#include "version.h"

static void regtable(lua_State *L, const char *name) {
  if (lua_getfield(L, LUA_REGISTRYINDEX, name) != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, name);
  }
}

void lmvmpm_override(lua_State *L, const char *name, const char *value) {
  regtable(L, "mvmpm.overrides");
  lua_pushstring(L, value);
  lua_setfield(L, -2, name);
  lua_pop(L, 1);
}

/* convert an override to the default's type */
static void convert(lua_State *L, const char *name, int deftype) {
  if (lua_type(L, -1) == LUA_TNUMBER && !isfinite(lua_tonumber(L, -1)))
    luaL_error(L, "mvmpm.load: parameter '%s' must be a finite number", name);
  if (lua_type(L, -1) != LUA_TSTRING) return; /* from mvmpm.load: as given */
  if (deftype == LUA_TNUMBER) {
    if (!lua_stringtonumber(L, lua_tostring(L, -1)))
      luaL_error(L, "--set %s=%s: parameter '%s' is a number", name,
                 lua_tostring(L, -1), name);
    /* 1e400 reads as inf: refused here, where it enters */
    if (!isfinite(lua_tonumber(L, -1)))
      luaL_error(L, "--set %s=%s: parameter '%s' must be a finite number",
                 name, lua_tostring(L, -2), name);
    lua_remove(L, -2);
  } else if (deftype == LUA_TBOOLEAN) {
    const char *s = lua_tostring(L, -1);
    int b = strcmp(s, "true") == 0 ? 1 : strcmp(s, "false") == 0 ? 0 : -1;
    if (b < 0)
      luaL_error(L, "--set %s=%s: parameter '%s' is true or false", name, s, name);
    lua_pop(L, 1);
    lua_pushboolean(L, b);
  }
}

/* mvmpm.params{name = default, ...} -> the values in force */
static int params(lua_State *L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 1);
  lua_newtable(L);
  regtable(L, "mvmpm.overrides");
  regtable(L, "mvmpm.declared");
  regtable(L, "mvmpm.used");               /* 5: for the provenance */
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    const char *name;
    int t = lua_type(L, -1);
    if (lua_type(L, -2) != LUA_TSTRING)
      luaL_error(L, "params: names must be strings");
    name = lua_tostring(L, -2);
    if (t != LUA_TNUMBER && t != LUA_TBOOLEAN && t != LUA_TSTRING)
      luaL_error(L, "params: default of '%s' must be a number, boolean or string",
                 name);
    lua_pushboolean(L, 1);
    lua_setfield(L, 4, name);              /* declared */
    if (lua_getfield(L, 3, name) != LUA_TNIL) { /* overridden */
      convert(L, name, t);
      lua_remove(L, -2);
    } else lua_pop(L, 1);
    lua_pushvalue(L, -1);
    lua_setfield(L, 5, name);              /* used */
    lua_setfield(L, 2, name);              /* key stays for lua_next */
  }
  lua_pop(L, 3);
  return 1;
}

/* one "name = value" line: numbers with the fewest digits (15 to 17)
** that read back as the same double, strings quoted */
static int usedcmp(const void *a, const void *b) {
  return strcmp(*(char *const *)a, *(char *const *)b);
}

char *lmvmpm_params_text(lua_State *L) {
  char **line = NULL, *out = NULL;
  size_t n = 0, cap = 0, len = 0, k;
  int bad = 0, top = lua_gettop(L);
  if (lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.used") == LUA_TTABLE) {
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      char val[64], *l = NULL;
      const char *name = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : NULL;
      const char *v = val;
      size_t vl;
      if (lua_isinteger(L, -1))
        snprintf(val, sizeof val, "%lld", (long long)lua_tointeger(L, -1));
      else if (lua_type(L, -1) == LUA_TNUMBER) {
        double x = lua_tonumber(L, -1);
        int prec;
        for (prec = 15; prec < 17; prec++) { /* the shortest that reads back */
          snprintf(val, sizeof val, "%.*g", prec, x);
          if (strtod(val, NULL) == x) break;
        }
        if (prec == 17) snprintf(val, sizeof val, "%.17g", x);
      }
      else if (lua_type(L, -1) == LUA_TBOOLEAN)
        snprintf(val, sizeof val, "%s", lua_toboolean(L, -1) ? "true" : "false");
      else if (lua_type(L, -1) == LUA_TSTRING) {
        lua_pushfstring(L, "\"%s\"", lua_tostring(L, -1));
        v = lua_tostring(L, -1);
      } else v = NULL;
      vl = v ? strlen(v) : 0;
      if (name && v) {
        if (n == cap) {
          char **p = realloc(line, (cap = cap ? 2 * cap : 32) * sizeof *p);
          if (!p) bad = 1;
          else line = p;
        }
        if (!bad && (l = malloc(strlen(name) + vl + 5))) {
          sprintf(l, "%s = %s\n", name, v);
          line[n++] = l;
          len += strlen(l);
        } else bad = 1;
      }
      lua_settop(L, top + 2); /* the table and the key */
      if (bad) break;
    }
  }
  lua_settop(L, top);
  if (!bad && (out = malloc(len + 1))) {
    if (n) qsort(line, n, sizeof *line, usedcmp);
    out[0] = '\0';
    for (len = 0, k = 0; k < n; k++) {
      size_t m = strlen(line[k]);
      memcpy(out + len, line[k], m + 1);
      len += m;
    }
  }
  for (k = 0; k < n; k++) free(line[k]);
  free(line);
  return out;
}

static int strptrcmp(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int lmvmpm_check_overrides(lua_State *L) {
  int ov, decl;
  regtable(L, "mvmpm.overrides");
  ov = lua_gettop(L);
  regtable(L, "mvmpm.declared");
  decl = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, ov)) {
    const char *name = lua_tostring(L, -2);
    lua_pop(L, 1);
    if (lua_getfield(L, decl, name) == LUA_TNIL) {
      const char *names[65];
      const char *hint;
      luaL_Buffer b;
      int n = 0, k;
      lua_pop(L, 1);
      lua_pushnil(L);
      while (lua_next(L, decl) && n < 64) {
        lua_pop(L, 1);
        names[n++] = lua_tostring(L, -1); /* keys stay alive in decl */
      }
      if (n == 64) lua_pop(L, 1);
      names[n] = NULL;
      qsort(names, n, sizeof *names, strptrcmp);
      hint = chk_suggest(name, names);
      /* the buffer lives on the stack: the tables are indexed absolutely */
      luaL_buffinit(L, &b);
      for (k = 0; k < n; k++) {
        if (k) luaL_addstring(&b, ", ");
        luaL_addstring(&b, names[k]);
      }
      if (!n) luaL_addstring(&b, "none");
      luaL_pushresult(&b);
      lua_pushfstring(L, "--set %s: the scene declares no parameter '%s'%s%s%s "
                         "(it declares: %s)", name, name,
                      hint ? " (did you mean '" : "", hint ? hint : "",
                      hint ? "'?)" : "", lua_tostring(L, -1));
      lua_replace(L, ov);
      lua_settop(L, ov);
      return -1;
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 2);
  return 0;
}

static int traceback(lua_State *L) {
  const char *msg = lua_tostring(L, 1);
  luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
  return 1;
}

/* open path for reading only if it is a regular file: a FIFO or a device
** would block or never end.  O_NONBLOCK makes the open itself return at
** once (a FIFO with no writer blocks in open); the descriptor, -1 with
** the reason in err */
static int open_regular(const char *path, char *err, size_t errlen) {
  struct stat st;
  int fd = open(path, O_RDONLY | O_NONBLOCK);
  if (fd < 0) {
    snprintf(err, errlen, "%s: cannot open (%s)", path, strerror(errno));
    return -1;
  }
  if (fstat(fd, &st)) {
    snprintf(err, errlen, "%s: cannot read (%s)", path, strerror(errno));
    close(fd);
    return -1;
  }
  if (!S_ISREG(st.st_mode)) {
    snprintf(err, errlen, "%s: not a regular file (%s)", path,
             S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ?
             "a FIFO" : "a device or socket");
    close(fd);
    return -1;
  }
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

int lmvmpm_regular(const char *path, char *err, size_t errlen) {
  int fd = open_regular(path, err, errlen);
  if (fd < 0) return -1;
  close(fd);
  return 0;
}

char *lmvmpm_read(const char *path, char *err, size_t errlen) {
  int fd = open_regular(path, err, errlen);
  FILE *f = fd < 0 ? NULL : fdopen(fd, "rb");
  char *buf;
  long n;
  if (!f) {
    if (fd >= 0) {
      snprintf(err, errlen, "%s: cannot read (%s)", path, strerror(errno));
      close(fd);
    }
    return NULL;
  }
  if (fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) {
    snprintf(err, errlen, "%s: cannot read the scene file", path);
    fclose(f);
    return NULL;
  }
  buf = malloc((size_t)n + 1);
  if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) { free(buf); buf = NULL; }
  if (buf) buf[n] = 0;
  else snprintf(err, errlen, "%s: cannot read the scene file", path);
  fclose(f);
  return buf;
}

int lmvmpm_load(lua_State *L, const char *path) {
  char err[1200];
  char *src = lmvmpm_read(path, err, sizeof err);
  int r;
  if (!src) {
    lua_pushstring(L, err);
    return -1;
  }
  r = lmvmpm_load_text(L, path, src);
  free(src);
  return r;
}

int lmvmpm_load_text(lua_State *L, const char *path, const char *src) {
  int base = lua_gettop(L);
  lua_pushstring(L, src);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.source");
  lua_pushstring(L, path);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.scene");
  lua_pushnil(L);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.last");
  /* sandboxed, a precompiled scene is refused: bytecode is not checked */
  if (src[0] == LUA_SIGNATURE[0] && sandbox_on(L)) {
    lua_pushfstring(L, "%s: a precompiled scene (bytecode) is not allowed "
                    "under --sandbox", path);
    return -1;
  }
  lua_pushcfunction(L, traceback);
  if (luaL_loadbufferx(L, src, strlen(src), lua_pushfstring(L, "@%s", path),
                       sandbox_on(L) ? "t" : NULL)) {
    lua_replace(L, base + 1);
    lua_settop(L, base + 1);
    return -1;
  }
  lua_remove(L, -2); /* the chunk name */
  if (lua_pcall(L, 0, 1, base + 1)) {
    lua_replace(L, base + 1);
    lua_settop(L, base + 1);
    return -1;
  }
  if (!luaL_testudata(L, -1, LSIM_MT) && !luaL_testudata(L, -1, LSIM_OTHER_MT)) {
    lua_pop(L, 1);
    if (lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.last") == LUA_TNIL) {
      lua_settop(L, base);
      lua_pushfstring(L, "%s: the scene made no simulation (call mvmpm.sim{...})",
                      path);
      return -1;
    }
  }
  lua_replace(L, base + 1);
  lua_settop(L, base + 1);
  /* the simulation may be the other dimension's (mvmpm.sim{dim = ...}) */
  if (!luaL_testudata(L, -1, LSIM_MT) && lmvmpm_loaded_other)
    return lmvmpm_loaded_other(L, base, path);
  return lmvmpm_loaded(L, base, path);
}

int lmvmpm_loaded(lua_State *L, int base, const char *path) {
  lsim *ls = lua_touserdata(L, -1);
  if (ls->closed) {
    lua_settop(L, base);
    lua_pushfstring(L, "%s: the scene closed its simulation (its __gc "
                    "ran)", path);
    return -1;
  }
  snprintf(ls->scene, sizeof ls->scene, "%s", path);
  return 0;
}

/*
** A scene loaded by mvmpm.load starts as it would in a new process: with
** the module in 2-D, its first dimension.  The module takes the
** dimension of the last simulation made (lsim_dim_check), and what a
** scene calls before its mvmpm.sim reads it: mvmpm.pack.bed without a
** `dim` built a 2-D scene's bed in 3-D after a 3-D scene had been loaded
** in the same process.  Not while mvmpm run or the prompt loads their
** scene ("mvmpm.redo"): that process already is in the scene's
** dimension.  Read from the module, not this build's DIM: a 2-D load
** kept in a local is still called after a 3-D simulation.
*/
static void load_fresh(lua_State *L) {
  int top = lua_gettop(L), redo, dim = 2;
  if (!lmvmpm_enter2) return;
  redo = lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.redo") == LUA_TBOOLEAN;
  if (!redo && lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.module") == LUA_TTABLE &&
      lua_getfield(L, -1, "dim") == LUA_TNUMBER)
    dim = (int)lua_tointeger(L, -1);
  lua_settop(L, top);
  if (redo || dim == 2) return;
  lua_pushcfunction(L, lmvmpm_enter2);
  lua_call(L, 0, 0);
}

/* mvmpm.load(path [, {name = value}]) -> the scene's simulation */
static int load(lua_State *L) {
  const char *path = luaL_checkstring(L, 1);
  int top;
  if (sandbox_on(L))
    return luaL_error(L, "mvmpm.load(\"%s\"): not allowed under --sandbox "
                      "(it reads other files)", path);
  lua_settop(L, 2);
  load_fresh(L);
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.overrides"); /* 3: saved */
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.declared");  /* 4: saved */
  lua_newtable(L);
  if (lua_istable(L, 2)) {
    lua_pushnil(L);
    while (lua_next(L, 2)) {
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_settable(L, 5);
    }
  }
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.overrides");
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.declared");
  top = lua_gettop(L);
  if (lmvmpm_load(L, path) || lmvmpm_check_overrides(L)) {
    lua_pushvalue(L, 3);
    lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.overrides");
    lua_pushvalue(L, 4);
    lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.declared");
    return lua_error(L);
  }
  lua_pushvalue(L, 3);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.overrides");
  lua_pushvalue(L, 4);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.declared");
  (void)top;
  return 1;
}

/* mvmpm.cpu() -> thread, work, crit, own: this thread's CPU seconds and
** the thread pools' accounting (par.h: all parts' CPU time, the longest
** part of each job added up, the calling thread's time in jobs).  The
** first call turns the accounting on; the sums count from then. */
static int lcpu(lua_State *L) {
  double w, c, o;
  par_account(1);
  par_cpu(&w, &c, &o);
  lua_pushnumber(L, par_thread_cpu());
  lua_pushnumber(L, w);
  lua_pushnumber(L, c);
  lua_pushnumber(L, o);
  return 4;
}

/*
** mvmpm.open(path) -> a Lua file open for writing, for a scene's own
** tables.  The bytes go to path.part, renamed to path when the file is
** closed (or collected), so a table under its final name is whole.
** Under --sandbox the path is one inside the output directory
** (sandbox_path) and no link is followed: the sandbox's way to write.
*/
static int ofclose(lua_State *L) {
  luaL_Stream *p = luaL_checkudata(L, 1, LUA_FILEHANDLE);
  char part[1200];
  const char *final;
  int ok, en;
  errno = 0;
  ok = fclose(p->f) == 0;
  en = errno;
  lua_getiuservalue(L, 1, 1);
  final = lua_tostring(L, -1);
  snprintf(part, sizeof part, "%s.part", final);
  if (ok && rename(part, final) != 0) {
    ok = 0;
    en = errno;
  }
  errno = en;
  return luaL_fileresult(L, ok, final);
}

static int lopen(lua_State *L) {
  char buf[1100], part[1200];
  const char *path = sandbox_path(L, luaL_checkstring(L, 1), "mvmpm.open",
                                  buf, sizeof buf);
  luaL_Stream *st;
  int fd;
  if (snprintf(part, sizeof part, "%s.part", path) >= (int)sizeof part)
    return luaL_error(L, "mvmpm.open: path '%s' is too long", path);
  sandbox_file(L, part, "mvmpm.open");
  /* the io library's file type; its metatable outlives a sandbox that
  ** removed the global io */
  luaL_requiref(L, "io", luaopen_io, 0);
  lua_pop(L, 1);
  st = lua_newuserdatauv(L, sizeof *st, 1);
  st->f = NULL;
  st->closef = NULL; /* a closed file until it is open */
  luaL_setmetatable(L, LUA_FILEHANDLE);
  lua_pushstring(L, path);
  lua_setiuservalue(L, -2, 1);
  fd = ofile_create(part);
  if (fd < 0 || !(st->f = fdopen(fd, "w"))) {
    int en = errno;
    if (fd >= 0) close(fd);
    errno = en;
    return luaL_fileresult(L, 0, part);
  }
  st->closef = ofclose;
  return 1;
}

/* mvmpm.clock() -> seconds on a monotonic wall clock, for timing runs
** (os.clock is the process's CPU time, not elapsed time) */
static int lclock(lua_State *L) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  lua_pushnumber(L, (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec);
  return 1;
}

/* mvmpm.NAME that the module lacks: a module of the library (mvmpm.pack)
** is named with its require; anything else gets the nearest name.  Only
** string keys: mvmpm[1] is plain nil */
static int modindex(lua_State *L) {
  const char *k;
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  k = lua_tostring(L, 2);
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.luadir");
  if (lua_isstring(L, -1) && strlen(k) < 64 && !strchr(k, '/') &&
      !strchr(k, '.')) {
    char path[PATH_MAX + 80];
    FILE *f;
    snprintf(path, sizeof path, "%s/mvmpm/%s.lua", lua_tostring(L, -1), k);
    if ((f = fopen(path, "r"))) {
      fclose(f);
      return luaL_error(L, "mvmpm.%s is a module of its own: local %s = "
                           "require \"mvmpm.%s\"", k, k, k);
    }
  }
  lua_pop(L, 1);
  return chk_nokey(L, "mvmpm", k, 1, NULL);
}

/* this dimension's functions and constants into the module table mod */
static void fill(lua_State *L, int mod) {
  static const luaL_Reg fns[] = {{"sim", lsim_new}, {"params", params},
                                 {"load", load}, {"clock", lclock}, {"cpu", lcpu},
                                 {"open", lopen},
                                 {NULL, NULL}};
  luaL_setfuncs(L, fns, 0);
  lua_pushstring(L, mvmpm_version);
  lua_setfield(L, mod, "version");
  lua_pushinteger(L, DIM);
  lua_setfield(L, mod, "dim");
  lsim_open(L);
  lbody_open(L);
  lmat_open(L, mod);
  lshape_open(L, mod);
  lrender_open(L, mod);
}

/* with no arguments only the module changes dimension (load_fresh) */
int lmvmpm_enter(lua_State *L) {
  int top = lua_gettop(L);
  if (lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.module") == LUA_TTABLE)
    fill(L, lua_gettop(L));
  lua_settop(L, top);
  return top == 0 ? 0 : lsim_new(L);
}

int luaopen_mvmpm(lua_State *L) {
  int mod;
  lua_newtable(L);
  mod = lua_gettop(L);
  fill(L, mod);
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, modindex);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, mod);
  /* the table a scene of the other dimension fills again */
  lua_pushvalue(L, mod);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.module");
  return 1;
}

/* The directory holding the Lua modules (mvmpm/NAME.lua): $MVMPM_LUA, else the first of
** lua/ beside the executable (a copy of the tree), ../lua (a build
** directory in the tree) and ../share/lua/5.4 (make install's layout, so
** an installed binary finds its modules wherever PREFIX put them).  It
** goes first on package.path, and to the registry for the sandbox's
** require. */
void lmvmpm_setpath(lua_State *L, const char *argv0) {
  static const char *const rel[] = {"/lua", "/../lua", "/../share/lua/5.4"};
  char exe[PATH_MAX], dir[PATH_MAX + 32], probe[PATH_MAX + 64];
  const char *env = getenv("MVMPM_LUA"), *found = NULL;
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  char *slash;
  size_t k;
  if (n <= 0) {
    snprintf(exe, sizeof exe, "%s", argv0);
    n = (ssize_t)strlen(exe);
  }
  exe[n] = 0;
  if ((slash = strrchr(exe, '/'))) *slash = 0;
  else snprintf(exe, sizeof exe, ".");
  if (env) found = env;
  for (k = 0; !found && k < sizeof rel / sizeof rel[0]; k++) {
    snprintf(dir, sizeof dir, "%s%s", exe, rel[k]);
    snprintf(probe, sizeof probe, "%s/mvmpm/verify.lua", dir);
    if (access(probe, F_OK) == 0) found = dir;
  }
  if (!found) return;
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  lua_pushfstring(L, "%s/?.lua;%s/?/init.lua;%s", found, found,
                  lua_tostring(L, -1));
  lua_setfield(L, -3, "path");
  lua_pop(L, 2);
  lua_pushstring(L, found);
  lua_setfield(L, LUA_REGISTRYINDEX, "mvmpm.luadir");
}
