/*
** lua_material.c - material constructors: mvmpm.elastic{...}.
** A material is a userdata holding its parameters; a simulation takes a
** copy the first time a body uses it.
*/
#include <math.h>
#include <string.h>
#include "lcheck.h"
#include "lsim.h"

material *lmat_check(lua_State *L, int idx) {
  return luaL_checkudata(L, idx, LMAT_MT);
}

/* K and G, or E and nu: exactly one pair */
static void moduli(lua_State *L, const char *what, double *K, double *G) {
  int hasK, hasE;
  lua_getfield(L, 1, "K"); hasK = !lua_isnil(L, -1); lua_pop(L, 1);
  lua_getfield(L, 1, "E"); hasE = !lua_isnil(L, -1); lua_pop(L, 1);
  if (hasK == hasE)
    luaL_error(L, "%s: give the moduli as K and G, or as E and nu", what);
  if (hasK) {
    *K = chk_num(L, 1, what, "K", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
    *G = chk_num(L, 1, what, "G", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  } else {
    double E = chk_num(L, 1, what, "E", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
    double nu = chk_num(L, 1, what, "nu", 0, -1, 0.5,
                        CHK_OPENLO | CHK_OPENHI | CHK_REQUIRED);
    *K = E / (3 * (1 - 2 * nu));
    *G = E / (2 * (1 + nu));
  }
}

static int elastic(lua_State *L) {
  static const char *const keys[] = {"K", "G", "E", "nu", "density", "name",
                                     NULL};
  const char *what = "elastic";
  material *m;
  double K, G, rho;
  const char *name;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  moduli(L, what, &K, &G);
  rho = chk_num(L, 1, what, "density", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  lua_getfield(L, 1, "name");
  name = lua_isnil(L, -1) ? "elastic" : luaL_checkstring(L, -1);
  m = lua_newuserdatauv(L, sizeof *m, 0);
  material_init(m, &mat_elastic, name, rho, K, G);
  luaL_setmetatable(L, LMAT_MT);
  return 1;
}

static int index_(lua_State *L) {
  material *m = lmat_check(L, 1);
  const char *k = luaL_checkstring(L, 2);
  if (strcmp(k, "K") == 0) lua_pushnumber(L, m->K);
  else if (strcmp(k, "G") == 0) lua_pushnumber(L, m->G);
  else if (strcmp(k, "density") == 0) lua_pushnumber(L, m->rho);
  else if (strcmp(k, "name") == 0) lua_pushstring(L, m->name);
  else if (strcmp(k, "model") == 0) lua_pushstring(L, m->model->name);
  else if (strcmp(k, "c") == 0) lua_pushnumber(L, m->c);
  else if (strcmp(k, "nu") == 0)
    lua_pushnumber(L, (3 * m->K - 2 * m->G) / (2 * (3 * m->K + m->G)));
  else if (strcmp(k, "E") == 0)
    lua_pushnumber(L, 9 * m->K * m->G / (3 * m->K + m->G));
  else lua_pushnil(L);
  return 1;
}

static int tostr(lua_State *L) {
  material *m = lmat_check(L, 1);
  lua_pushfstring(L, "material %s (%s, K=%f G=%f density=%f)", m->name,
                  m->model->name, m->K, m->G, m->rho);
  return 1;
}

void lmat_open(lua_State *L, int modidx) {
  static const luaL_Reg meta[] = {{"__index", index_}, {"__tostring", tostr},
                                  {NULL, NULL}};
  luaL_newmetatable(L, LMAT_MT);
  luaL_setfuncs(L, meta, 0);
  lua_pop(L, 1);
  lua_pushcfunction(L, elastic);
  lua_setfield(L, modidx, "elastic");
}
