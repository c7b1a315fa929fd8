/*
** lua_material.c - material constructors:
**   mvmpm.elastic{K=, G= | E=, nu=, density=, alpha=, T_ref=, name=}
** and, for heat (heat.h), on every model: cv= (specific heat per unit
** mass; m.c is the wave speed), k= (conductivity), beta= (the fraction of
** plastic work turned to heat, 0.9)
**   mvmpm.plastic{K=, G= | E=, nu=, density=, yield=, hardening=0,
**                 alpha=, T_ref=, name=}
**   mvmpm.viscoelastic{K=, G_inf=0, prony = {{G=, tau=}, ...}, density=,
**                      alpha=, T_ref=, name=}
** A material is a userdata holding its parameters; a simulation takes a
** copy the first time a body uses it.  Reading a material's field gives
** its parameters (m.K, m.yield, m.prony, ...).
*/
#include <math.h>
#include <stdio.h>
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

static const char *name_of(lua_State *L, const char *what) {
  const char *name;
  lua_getfield(L, 1, "name");
  if (lua_isnil(L, -1)) name = what;
  else if (lua_type(L, -1) == LUA_TSTRING) name = lua_tostring(L, -1);
  else
    return luaL_error(L, "%s: field 'name' must be a string (got %s)", what,
                      luaL_typename(L, -1)), NULL;
  lua_pop(L, 1); /* the table still holds the string */
  return name;
}

/* the gas constant in J/(mol K) (CODATA 2018, exact) for Ea without R */
#define GAS_R 8.314462618

/* reaction = {Z =, Ta = | Ea = [, R = 8.314462618], Q =, order = 1,
** fk = T0}: the kinetics of react.h; name, source and note are kept for
** the reader of a parameter set and not used */
static void reaction_keys(lua_State *L, const char *what, material *m) {
  static const char *const keys[] = {"Z", "Ta", "Ea", "R", "Q", "order", "fk",
                                     "name", "source", "note", NULL};
  char rw[48];
  int hasTa, hasEa, t = lua_getfield(L, 1, "reaction");
  if (t == LUA_TNIL) { lua_pop(L, 1); return; }
  snprintf(rw, sizeof rw, "%s.reaction", what);
  if (t != LUA_TTABLE)
    luaL_error(L, "%s: must be a table {Z =, Ta = (or Ea =), Q =, order = } "
                  "(got %s)", rw, luaL_typename(L, -1));
  chk_keys(L, -1, rw, keys);
  m->rx.Z = chk_num(L, -1, rw, "Z", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  lua_getfield(L, -1, "Ta"); hasTa = !lua_isnil(L, -1); lua_pop(L, 1);
  lua_getfield(L, -1, "Ea"); hasEa = !lua_isnil(L, -1); lua_pop(L, 1);
  if (hasTa == hasEa)
    luaL_error(L, "%s: give the activation temperature Ta = E/R (K), or the "
                  "activation energy Ea with R (default 8.314462618 "
                  "J/(mol K)), not both", rw);
  if (hasTa)
    m->rx.Ta = chk_num(L, -1, rw, "Ta", 0, 0, HUGE_VAL, CHK_OPENLO);
  else
    m->rx.Ta = chk_num(L, -1, rw, "Ea", 0, 0, HUGE_VAL, CHK_OPENLO) /
               chk_num(L, -1, rw, "R", GAS_R, 0, HUGE_VAL, CHK_OPENLO);
  m->rx.Q = chk_num(L, -1, rw, "Q", 0, 0, HUGE_VAL, CHK_REQUIRED);
  m->rx.n = chk_num(L, -1, rw, "order", 1, 0, 3, 0);
  m->rx.T_fk = chk_num(L, -1, rw, "fk", 0, 0, HUGE_VAL, CHK_OPENLO);
  if (!(m->cv > 0))
    luaL_error(L, "%s: a reacting material needs its specific heat cv > 0 "
                  "(the heat of reaction Q raises T by Q / cv)", what);
  lua_pop(L, 1);
}

/* alpha and T_ref, and the heat keys (heat.h): specific heat cv > 0
** (0 when absent: a scene with heat then refuses the material),
** conductivity k >= 0, Taylor-Quinney fraction beta in [0, 1] (0.9) */
static void thermal_keys(lua_State *L, const char *what, material *m) {
  m->alpha = chk_num(L, 1, what, "alpha", 0, -HUGE_VAL, HUGE_VAL, 0);
  m->T_ref = chk_num(L, 1, what, "T_ref", 0, -HUGE_VAL, HUGE_VAL, 0);
  lua_getfield(L, 1, "cv");
  if (!lua_isnil(L, -1))
    m->cv = chk_num(L, 1, what, "cv", 0, 0, HUGE_VAL, CHK_OPENLO);
  lua_pop(L, 1);
  m->kcond = chk_num(L, 1, what, "k", 0, 0, HUGE_VAL, 0);
  m->beta = chk_num(L, 1, what, "beta", 0.9, 0, 1, 0);
  m->T_melt = chk_num(L, 1, what, "T_melt", 0, 0, HUGE_VAL, CHK_OPENLO);
  reaction_keys(L, what, m);
}

static material *newmat(lua_State *L) {
  material *m = lua_newuserdatauv(L, sizeof *m, 0);
  memset(m, 0, sizeof *m);
  return m;
}

static int elastic(lua_State *L) {
  static const char *const keys[] = {"K", "G", "E", "nu", "density", "name",
                                     "alpha", "T_ref", "cv", "k", "beta",
                                     "reaction", "T_melt", NULL};
  const char *what = "elastic";
  material tmp, *m;
  double K, G, rho;
  const char *name;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  moduli(L, what, &K, &G);
  rho = chk_num(L, 1, what, "density", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  name = name_of(L, what);
  material_init(&tmp, &mat_elastic, name, rho, K, G);
  thermal_keys(L, what, &tmp);
  m = newmat(L);
  *m = tmp;
  luaL_setmetatable(L, LMAT_MT);
  return 1;
}

static int plastic(lua_State *L) {
  static const char *const keys[] = {"K", "G", "E", "nu", "density", "name",
                                     "yield", "hardening", "alpha", "T_ref",
                                     "cv", "k", "beta", "reaction",
                                     "T_melt", NULL};
  const char *what = "plastic";
  material tmp, *m;
  double K, G, rho, y, H;
  const char *name;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  moduli(L, what, &K, &G);
  rho = chk_num(L, 1, what, "density", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  y = chk_num(L, 1, what, "yield", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  H = chk_num(L, 1, what, "hardening", 0, 0, HUGE_VAL, 0);
  name = name_of(L, what);
  if (material_plastic(&tmp, name, rho, K, G, y, H))
    luaL_error(L, "%s: inconsistent parameters", what);
  thermal_keys(L, what, &tmp);
  m = newmat(L);
  *m = tmp;
  luaL_setmetatable(L, LMAT_MT);
  return 1;
}

/* prony = {{G = , tau = }, ...}: at most MAT_MAXPRONY elements */
static int prony(lua_State *L, const char *what, double *G, double *tau) {
  static const char *const keys[] = {"G", "tau", NULL};
  lua_Integer n, k;
  lua_getfield(L, 1, "prony");
  if (lua_isnil(L, -1)) { lua_pop(L, 1); return 0; }
  if (!lua_istable(L, -1))
    luaL_error(L, "%s: field 'prony' must be a list of elements {G = , tau = } "
                  "(got %s)", what, luaL_typename(L, -1));
  n = luaL_len(L, -1);
  if (n > MAT_MAXPRONY)
    luaL_error(L, "%s: field 'prony' has %d elements; at most %d are allowed",
               what, (int)n, MAT_MAXPRONY);
  for (k = 1; k <= n; k++) {
    char ew[48];
    snprintf(ew, sizeof ew, "%s.prony[%d]", what, (int)k);
    if (lua_geti(L, -1, k) != LUA_TTABLE)
      luaL_error(L, "%s: must be a table {G = , tau = } (got %s)", ew,
                 luaL_typename(L, -1));
    chk_keys(L, -1, ew, keys);
    G[k - 1] = chk_num(L, -1, ew, "G", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
    tau[k - 1] = chk_num(L, -1, ew, "tau", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return (int)n;
}

static int viscoelastic(lua_State *L) {
  static const char *const keys[] = {"K", "G_inf", "prony", "density", "name",
                                     "alpha", "T_ref", "cv", "k", "beta",
                                     "reaction", "T_melt", NULL};
  const char *what = "viscoelastic";
  material tmp, *m;
  double K, Ginf, rho, G[MAT_MAXPRONY], tau[MAT_MAXPRONY];
  const char *name;
  int n;
  luaL_checktype(L, 1, LUA_TTABLE);
  chk_keys(L, 1, what, keys);
  K = chk_num(L, 1, what, "K", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  Ginf = chk_num(L, 1, what, "G_inf", 0, 0, HUGE_VAL, 0);
  n = prony(L, what, G, tau);
  if (n == 0 && Ginf == 0)
    luaL_error(L, "%s: give a long-term modulus G_inf > 0 or at least one "
                  "Maxwell element in 'prony' (a solid needs shear stiffness)",
               what);
  rho = chk_num(L, 1, what, "density", 0, 0, HUGE_VAL, CHK_OPENLO | CHK_REQUIRED);
  name = name_of(L, what);
  if (material_viscoelastic(&tmp, name, rho, K, Ginf, n, G, tau))
    luaL_error(L, "%s: inconsistent parameters", what);
  thermal_keys(L, what, &tmp);
  m = newmat(L);
  *m = tmp;
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
  else if (strcmp(k, "alpha") == 0) lua_pushnumber(L, m->alpha);
  else if (strcmp(k, "T_ref") == 0) lua_pushnumber(L, m->T_ref);
  else if (strcmp(k, "cv") == 0) lua_pushnumber(L, m->cv);
  else if (strcmp(k, "k") == 0) lua_pushnumber(L, m->kcond);
  else if (strcmp(k, "beta") == 0) lua_pushnumber(L, m->beta);
  else if (m->model == &mat_plastic && strcmp(k, "yield") == 0)
    lua_pushnumber(L, m->yield);
  else if (m->model == &mat_plastic && strcmp(k, "hardening") == 0)
    lua_pushnumber(L, m->hardening);
  else if (m->model == &mat_viscoelastic && strcmp(k, "G_inf") == 0)
    lua_pushnumber(L, m->G_inf);
  else if (m->model == &mat_viscoelastic && strcmp(k, "prony") == 0) {
    int j;
    lua_createtable(L, m->nprony, 0);
    for (j = 0; j < m->nprony; j++) {
      lua_createtable(L, 0, 2);
      lua_pushnumber(L, m->prony_G[j]);
      lua_setfield(L, -2, "G");
      lua_pushnumber(L, m->prony_tau[j]);
      lua_setfield(L, -2, "tau");
      lua_rawseti(L, -2, j + 1);
    }
  } else lua_pushnil(L);
  return 1;
}

static int tostr(lua_State *L) {
  material *m = lmat_check(L, 1);
  char buf[160];
  int n = snprintf(buf, sizeof buf, "material %s (%s, K=%g G=%g density=%g",
                   m->name, m->model->name, m->K, m->G, m->rho);
  if (m->model == &mat_plastic && n > 0 && n < (int)sizeof buf)
    n += snprintf(buf + n, sizeof buf - n, " yield=%g hardening=%g", m->yield,
                  m->hardening);
  if (m->model == &mat_viscoelastic && n > 0 && n < (int)sizeof buf)
    n += snprintf(buf + n, sizeof buf - n, " G_inf=%g, %d Maxwell elements",
                  m->G_inf, m->nprony);
  if (m->alpha != 0 && n > 0 && n < (int)sizeof buf)
    snprintf(buf + n, sizeof buf - n, " alpha=%g T_ref=%g", m->alpha, m->T_ref);
  lua_pushfstring(L, "%s)", buf);
  return 1;
}

void lmat_open(lua_State *L, int modidx) {
  static const luaL_Reg meta[] = {{"__index", index_}, {"__tostring", tostr},
                                  {NULL, NULL}};
  luaL_newmetatable(L, LMAT_MT);
  luaL_setfuncs(L, meta, 0);
  lsim_lock(L, -1);
  lua_pop(L, 1);
  lua_pushcfunction(L, elastic);
  lua_setfield(L, modidx, "elastic");
  lua_pushcfunction(L, plastic);
  lua_setfield(L, modidx, "plastic");
  lua_pushcfunction(L, viscoelastic);
  lua_setfield(L, modidx, "viscoelastic");
}
