/*
** lua_thermal.c - sim:temperature(T) or sim:temperature(function(t)
** return T end): impose a uniform temperature; sim:temperature() reads
** it (nil if none is imposed).  A function is called
** between steps, once per step, with the time at the end of the coming
** step (run.c); its value is the temperature every particle has when the
** step ends, so each step's change is T(t + dt) - T(t).  A number holds
** from now on.  Before the first step either one also sets the initial
** temperature (see thermal.h for T_ref and the stress that follows).
*/
#include <math.h>
#include <stdio.h>
#include "lcheck.h"
#include "lsim.h"
#include "thermal.h"

/* the uniform temperature a function gives at time t; checked */
double lsim_temperature_at(lua_State *L, int simidx, double t) {
  double T;
  int fn;
  lsim_uv(L, simidx, "temperature");
  fn = lua_gettop(L);
  lua_pushvalue(L, fn);
  lua_pushnumber(L, t);
  lua_call(L, 1, 1);
  T = chk_result(L, -1, fn, "temperature function at t = %g", t);
  lua_pop(L, 2);
  return T;
}

int lsim_temperature(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  sim *s = &ls->s;
  double T;
  if (lua_isnoneornil(L, 2)) {
    if (s->temp_on) lua_pushnumber(L, s->temp);
    else lua_pushnil(L);
    return 1;
  }
  lua_settop(L, 2);
  if (s->heat && (s->started || lua_isfunction(L, 2)))
    luaL_error(L, "temperature: with heat on (sim:heat) the temperature is "
                  "computed; sim:temperature(T) before the first step sets "
                  "the initial temperature only (use walls or "
                  "hold_temperature to impose one)");
  lua_getiuservalue(L, 1, 1);
  if (lua_isfunction(L, 2)) {
    lua_pushvalue(L, 2);
    lua_setfield(L, -2, "temperature");
    lua_pop(L, 1);
    ls->tempfn = 1;
    T = lsim_temperature_at(L, 1, s->t);
  } else if (lua_type(L, 2) == LUA_TNUMBER) {
    lua_pushnil(L);
    lua_setfield(L, -2, "temperature");
    lua_pop(L, 1);
    ls->tempfn = 0;
    T = chk_arg(L, 2, "temperature", "T", 0, -HUGE_VAL, HUGE_VAL, 0);
  } else
    return luaL_error(L, "temperature: give a number or a function(t) "
                         "returning the temperature (got %s)",
                      luaL_typename(L, 2));
  if (thermal_uniform(s, T)) luaL_error(L, "temperature: out of memory");
  return 0;
}
