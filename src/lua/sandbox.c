/*
** sandbox.c - a restricted Lua state for scenes from someone else (the
** rules are in sandbox.h).  The registry's "mvmpm.sandbox" holds the
** output directory while the state is restricted.
*/
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "lauxlib.h"
#include "lsim.h"
#include "ofile.h"
#include "sandbox.h"

#define KEY "mvmpm.sandbox"

/* load(chunk [, name [, mode [, env]]]) with mode "t" only; the number
** of arguments is kept, as load tells an absent env from a nil one */
static int sload(lua_State *L) {
  int n = lua_gettop(L);
  const char *mode = luaL_optstring(L, 3, "t");
  if (strcmp(mode, "t") != 0)
    return luaL_error(L, "load: mode \"%s\" is not allowed under --sandbox "
                      "(text chunks only, mode \"t\")", mode);
  if (n < 3) lua_settop(L, n = 3);
  lua_pushliteral(L, "t");
  lua_replace(L, 3);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, n, LUA_MULTRET);
  return lua_gettop(L);
}

/* "mvmpm" or "mvmpm." followed by letters, digits and '_' */
static int engine_module(const char *name) {
  const char *p;
  if (strcmp(name, "mvmpm") == 0) return 1;
  if (strncmp(name, "mvmpm.", 6) != 0 || !name[6]) return 0;
  for (p = name + 6; *p; p++)
    if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
          (*p >= '0' && *p <= '9') || *p == '_'))
      return 0;
  return 1;
}

static int srequire(lua_State *L) {
  const char *name = luaL_checkstring(L, 1);
  if (!engine_module(name))
    return luaL_error(L, "require \"%s\": under --sandbox only the mvmpm "
                      "modules (\"mvmpm\", \"mvmpm.NAME\") can be loaded", name);
  lua_settop(L, 1);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, 1, LUA_MULTRET);
  return lua_gettop(L);
}

static void drop(lua_State *L, int tbl, const char *name) {
  lua_pushnil(L);
  lua_setfield(L, tbl, name);
}

/* __index of the globals and of os: a name the sandbox took away gets
** an error that says so, instead of "attempt to index a nil value" */
static int missing(lua_State *L) {
  const char *prefix = lua_tostring(L, lua_upvalueindex(1));
  lua_pushvalue(L, 2);
  if (lua_rawget(L, lua_upvalueindex(2)) != LUA_TNIL)
    return luaL_error(L, "%s%s is not available under --sandbox (%s)", prefix,
                      lua_tostring(L, 2), lua_tostring(L, -1));
  return 0;
}

/* t's metatable: __index = missing, with a table name -> why */
static void explain(lua_State *L, int t, const char *prefix,
                    const char *const names[], const char *why) {
  int k;
  lua_createtable(L, 0, 1);
  lua_pushstring(L, prefix);
  lua_newtable(L);
  for (k = 0; names[k]; k++) {
    lua_pushstring(L, why);
    lua_setfield(L, -2, names[k]);
  }
  lua_pushcclosure(L, missing, 2);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, t);
}

void sandbox_open(lua_State *L, const char *root) {
  static const char *const gone[] = {"io", "debug", "package", "dofile",
                                     "loadfile", NULL};
  static const char *const oskeep[] = {"clock", "time", "date", NULL};
  int g, k;
  lua_pushstring(L, root);
  lua_setfield(L, LUA_REGISTRYINDEX, KEY);
  ofile_strict(); /* no output file is written through a link */
  lua_pushglobaltable(L);
  g = lua_gettop(L);
  /* require: engine modules from the engine's directory, Lua files only */
  lua_getglobal(L, "package");
  lua_getfield(L, LUA_REGISTRYINDEX, "mvmpm.luadir");
  if (lua_isstring(L, -1))
    lua_pushfstring(L, "%s/?.lua;%s/?/init.lua", lua_tostring(L, -1),
                    lua_tostring(L, -1));
  else lua_pushliteral(L, "");
  lua_setfield(L, -3, "path");
  lua_pop(L, 1);
  lua_pushliteral(L, "");
  lua_setfield(L, -2, "cpath");
  drop(L, lua_gettop(L), "loadlib");
  lua_getfield(L, -1, "searchers"); /* keep the preload and Lua searchers */
  if (lua_istable(L, -1)) {
    lua_pushnil(L); lua_rawseti(L, -2, 4);
    lua_pushnil(L); lua_rawseti(L, -2, 3);
  }
  lua_pop(L, 2);
  lua_getfield(L, g, "require");
  lua_pushcclosure(L, srequire, 1);
  lua_setfield(L, g, "require");
  lua_getfield(L, g, "load");
  lua_pushcclosure(L, sload, 1);
  lua_setfield(L, g, "load");
  for (k = 0; gone[k]; k++) drop(L, g, gone[k]);
  explain(L, g, "", gone, "files and the system are out of a scene's reach; "
          "output goes through sim:output, sim:snapshot and sim:render");
  /* os: only the clocks and dates */
  lua_getfield(L, g, "os");
  lua_newtable(L);
  for (k = 0; oskeep[k]; k++) {
    lua_getfield(L, -2, oskeep[k]);
    lua_setfield(L, -2, oskeep[k]);
  }
  {
    static const char *const osgone[] = {"execute", "exit", "getenv",
        "remove", "rename", "tmpname", "setlocale", "difftime", NULL};
    explain(L, lua_gettop(L), "os.", osgone,
            "only os.clock, os.time and os.date are");
  }
  lua_setfield(L, g, "os");
  lua_pop(L, 1);
  lua_getfield(L, g, "string");
  drop(L, lua_gettop(L), "dump");
  {
    static const char *const strgone[] = {"dump", NULL};
    explain(L, lua_gettop(L), "string.", strgone,
            "bytecode cannot be loaded here");
  }
  lua_pop(L, 2);
}

int sandbox_on(lua_State *L) {
  int on = lua_getfield(L, LUA_REGISTRYINDEX, KEY) == LUA_TSTRING;
  lua_pop(L, 1);
  return on;
}

/*
** The components of full below root, one by one: none may be a link (a
** link planted in the output directory would carry a write outside it);
** with make, the missing directories on the way are made.  Links are
** looked at with lstat before the file is written; the writers
** themselves never follow one at the temp name (ofile.h), and rename
** replaces a link at the final name instead of writing through it.
*/
static void walk(lua_State *L, const char *root, const char *full,
                 const char *what, int make) {
  char buf[1100];
  size_t n = strlen(root), k;
  struct stat st;
  if (make && run_mkdirs(root, buf, sizeof buf)) /* the root: the user's */
    luaL_error(L, "%s: %s", what, buf);
  if (strncmp(full, root, n) != 0 || (full[n] != '/' && root[n - 1] != '/'))
    luaL_error(L, "%s: %s is not inside the output directory %s", what, full,
               root);
  if (strlen(full) >= sizeof buf) luaL_error(L, "%s: path '%s' is too long",
                                             what, full);
  memcpy(buf, full, strlen(full) + 1);
  for (k = n + 1; ; k++) {
    char c = buf[k];
    if (c != '/' && c != '\0') continue;
    buf[k] = '\0';
    if (lstat(buf, &st) == 0) {
      if (S_ISLNK(st.st_mode))
        luaL_error(L, "%s: %s is a symbolic link; under --sandbox no link "
                   "inside the output directory is followed (remove it)",
                   what, buf);
      if (c == '/' && !S_ISDIR(st.st_mode))
        luaL_error(L, "%s: %s is not a directory", what, buf);
    } else if (errno != ENOENT)
      luaL_error(L, "%s: %s: %s", what, buf, strerror(errno));
    else if (c == '\0' || !make)
      return; /* what is not there holds no link */
    else if (mkdir(buf, 0777) != 0 && errno != EEXIST)
      luaL_error(L, "%s: %s: cannot create directory (%s)", what, buf,
                 strerror(errno));
    if (c == '\0') return;
    buf[k] = '/';
  }
}

void sandbox_file(lua_State *L, const char *path, const char *what) {
  char tmp[1100];
  if (lua_getfield(L, LUA_REGISTRYINDEX, KEY) == LUA_TSTRING) {
    walk(L, lua_tostring(L, -1), path, what, 0);
    /* its temp name too: ofile would remove a link there, but a link
    ** planted beside the outputs is named, not passed over */
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.tmp", path) < sizeof tmp)
      walk(L, lua_tostring(L, -1), tmp, what, 0);
  }
  lua_pop(L, 1);
}

const char *sandbox_path(lua_State *L, const char *path, const char *what,
                         char *buf, size_t len) {
  const char *p, *root;
  size_t n;
  if (lua_getfield(L, LUA_REGISTRYINDEX, KEY) != LUA_TSTRING) {
    lua_pop(L, 1);
    return path;
  }
  root = lua_tostring(L, -1);
  n = strlen(root);
  /* the command line refuses an empty root; were it empty, root/path
  ** would be the absolute /path */
  if (n == 0)
    luaL_error(L, "%s: no output directory is set under --sandbox", what);
  /* a name built from sim.outdir (the root itself) means the same file
  ** as the name below it */
  if (strncmp(path, root, n) == 0 && root[n - 1] != '/' && path[n] == '/' &&
      path[n + 1])
    path += n + 1;
  if (!path[0] || path[0] == '/')
    luaL_error(L, "%s: path '%s' is not allowed under --sandbox (give a "
               "relative path; files go inside the output directory %s)",
               what, path, root);
  for (p = path; *p; p = strchr(p, '/') ? strchr(p, '/') + 1 : p + strlen(p))
    if (strncmp(p, "..", 2) == 0 && (p[2] == '/' || p[2] == '\0'))
      luaL_error(L, "%s: path '%s' is not allowed under --sandbox (no '..': "
                 "files go inside the output directory %s)", what, path, root);
  if ((size_t)snprintf(buf, len, "%s%s%s", root, root[n - 1] == '/' ? "" : "/",
                       path) >= len)
    luaL_error(L, "%s: path '%s' is too long", what, path);
  walk(L, root, buf, what, 1);
  lua_pop(L, 1);
  sandbox_file(L, buf, what); /* and its temp name */
  return buf;
}
