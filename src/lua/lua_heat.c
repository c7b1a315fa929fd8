/*
** lua_heat.c - sim:heat{...}: switch heat on (heat.h), before the first
** step.  Every key is optional:
**   friction_split = 0.5 | "effusivity"  contact friction heat: the share
**                    of the first body's field at a two-field node, or
**                    in proportion to sqrt(k rho c) of each side
**   wall_friction = 1   fraction of wall friction heat to the material
**                       (the rest leaves through the wall)
**   contact = "perfect" | {conductance = h}   thermal contact between
**                    fields (W/(m^2 K), per unit length in 2-D)
**   sides = {left = "insulated" | {temperature = T} |
**            {h = , ambient = }, ...}
** sim:heat() with no table takes the defaults; sim:heat() after the start
** returns a table of the settings and the last step's conduction
** substeps.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "conduct.h"
#include "heat.h"
#include "lcheck.h"
#include "lsim.h"

static void side_spec(lua_State *L, sim *s, int idx, int k) {
  static const char *const keys[] = {"temperature", "h", "ambient", NULL};
  heat_wall *w = &s->heat->walls[k];
  char what[48];
  snprintf(what, sizeof what, "heat.sides.%s", lsim_side_names[k]);
  if (lua_type(L, idx) == LUA_TSTRING) {
    if (strcmp(lua_tostring(L, idx), "insulated") != 0)
      luaL_error(L, "%s: must be \"insulated\", {temperature = T} or {h = , "
                    "ambient = } (got \"%s\")", what, lua_tostring(L, idx));
    w->kind = HEAT_INSULATED;
    return;
  }
  if (!lua_istable(L, idx))
    luaL_error(L, "%s: must be \"insulated\", {temperature = T} or {h = , "
                  "ambient = } (got %s)", what, luaL_typename(L, idx));
  chk_keys(L, idx, what, keys);
  lua_getfield(L, idx, "temperature");
  if (!lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_getfield(L, idx, "h");
    if (!lua_isnil(L, -1))
      luaL_error(L, "%s: give either temperature (a fixed temperature) or h "
                    "and ambient (a heat-transfer coefficient)", what);
    lua_pop(L, 1);
    w->kind = HEAT_FIXED;
    w->T = chk_num(L, idx, what, "temperature", 0, -HUGE_VAL, HUGE_VAL, 0);
    return;
  }
  lua_pop(L, 1);
  w->kind = HEAT_FILM;
  w->h = chk_num(L, idx, what, "h", 0, 0, HUGE_VAL, CHK_REQUIRED);
  w->T = chk_num(L, idx, what, "ambient", 0, -HUGE_VAL, HUGE_VAL, CHK_REQUIRED);
}

static void settings(lua_State *L, sim *s) {
  static const char *const keys[] = {"friction_split", "wall_friction",
                                     "contact", "sides", NULL};
  heat_state *h = s->heat;
  int k;
  chk_keys(L, 2, "heat", keys);
  lua_getfield(L, 2, "friction_split");
  if (lua_type(L, -1) == LUA_TSTRING) {
    if (strcmp(lua_tostring(L, -1), "effusivity") != 0)
      luaL_error(L, "heat: field 'friction_split' must be a number in [0, 1] "
                    "or \"effusivity\" (got \"%s\")", lua_tostring(L, -1));
    h->split = HEAT_SPLIT_EFFUSIVITY;
  } else if (!lua_isnil(L, -1)) {
    h->split = HEAT_SPLIT_SHARE;
    h->share = chk_num(L, 2, "heat", "friction_split", 0.5, 0, 1, 0);
  }
  lua_pop(L, 1);
  h->wall_share = chk_num(L, 2, "heat", "wall_friction", 1, 0, 1, 0);
  lua_getfield(L, 2, "contact");
  if (lua_type(L, -1) == LUA_TSTRING) {
    if (strcmp(lua_tostring(L, -1), "perfect") != 0)
      luaL_error(L, "heat: field 'contact' must be \"perfect\" or "
                    "{conductance = h} (got \"%s\")", lua_tostring(L, -1));
    h->contact = HEAT_PERFECT;
  } else if (lua_istable(L, -1)) {
    static const char *const ck[] = {"conductance", NULL};
    chk_keys(L, -1, "heat.contact", ck);
    h->contact = HEAT_CONDUCTANCE;
    h->hc = chk_num(L, lua_gettop(L), "heat.contact", "conductance", 0, 0,
                    HUGE_VAL, CHK_REQUIRED);
  } else if (!lua_isnil(L, -1))
    luaL_error(L, "heat: field 'contact' must be \"perfect\" or "
                  "{conductance = h} (got %s)", luaL_typename(L, -1));
  lua_pop(L, 1);
  lua_getfield(L, 2, "sides");
  if (!lua_isnil(L, -1)) {
    int t = lua_gettop(L);
    if (!lua_istable(L, t))
      luaL_error(L, "heat: field 'sides' must be a table {left = ..., ...} "
                    "(got %s)", luaL_typename(L, t));
    {
      const char *names[NSIDES + 1]; /* this dimension's sides only */
      for (k = 0; k < NSIDES; k++) names[k] = lsim_side_names[k];
      names[NSIDES] = NULL;
      chk_keys(L, t, "heat.sides", names);
    }
    for (k = 0; k < NSIDES; k++) {
      lua_getfield(L, t, lsim_side_names[k]);
      if (!lua_isnil(L, -1)) {
        if (s->g.periodic[k / 2])
          luaL_error(L, "heat.sides.%s: the side is periodic: it has no wall "
                        "to exchange heat with", lsim_side_names[k]);
        side_spec(L, s, lua_gettop(L), k);
      }
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
}

int lsim_heat(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  if (s->started) {
    const heat_state *h = s->heat;
    if (!lua_isnoneornil(L, 2))
      luaL_error(L, "heat: switch heat on and set it before the first step");
    if (!h) { lua_pushnil(L); return 1; }
    lua_createtable(L, 0, 6);
    lua_pushinteger(L, (lua_Integer)h->nsub);
    lua_setfield(L, -2, "substeps");
    lua_pushnumber(L, h->dtc);
    lua_setfield(L, -2, "stable_dt");
    lua_pushboolean(L, h->conduct);
    lua_setfield(L, -2, "conduction");
    lua_pushstring(L, h->contact == HEAT_PERFECT ? "perfect" : "conductance");
    lua_setfield(L, -2, "contact");
    lua_pushnumber(L, h->hc);
    lua_setfield(L, -2, "conductance");
    return 1;
  }
  if (ls->tempfn)
    luaL_error(L, "heat: the scene imposes a temperature function "
                  "(sim:temperature(fn)); with heat the temperature is "
                  "computed: set the initial temperature and use walls or "
                  "held bodies (hold_temperature) instead");
  {
    int b;
    for (b = 0; b < s->nbody; b++)
      if (s->bmat[b] >= 0 && !(s->mats[s->bmat[b]].cv > 0))
        luaL_error(L, "heat: body '%s' uses material '%s', which has no "
                      "specific heat: give cv > 0 (per unit mass) in its "
                      "constructor", s->bodies[b].name, s->mats[s->bmat[b]].name);
  }
  if (heat_enable(s)) luaL_error(L, "%s", s->err);
  if (!lua_isnoneornil(L, 2)) {
    luaL_checktype(L, 2, LUA_TTABLE);
    settings(L, s);
  }
  return 0;
}
