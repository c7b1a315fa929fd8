/*
** lua_hotspot.c - hot spots in Lua and in a run's output.
**   sim:hotspots{threshold = T, link = 1.5} -> a list of regions, largest
**     first, each {particles =, area =, mass =, T_max =, T_mean =, x =,
**     y =, reacted =}; the list's fields count, area (hot area) and
**     area_fraction (of all material) say the whole.
**   sim:output{hotspots = {threshold = T, link = 1.5}}: every snapshot
**     gets hotspots_NNNNNN.csv beside it (one row per region), and the
**     diagnostics table's columns hotspots and hotspot_area_fraction
**     are filled at every row (0 without it).
** The rule that joins particles is diag_hotspot.h's.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lcheck.h"
#include "lsim.h"
#include "ofile.h"
#include "sandbox.h"

static void setnum(lua_State *L, const char *k, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, k);
}

/* {threshold =, link =} at idx into *T, *link */
void lsim_hotspot_opts(lua_State *L, int idx, const char *what, double *T,
                       double *link) {
  static const char *const keys[] = {"threshold", "link", NULL};
  if (!lua_istable(L, idx))
    luaL_error(L, "%s: give a table {threshold = T, link = 1.5} (got %s)",
               what, luaL_typename(L, idx));
  chk_keys(L, idx, what, keys);
  *T = chk_num(L, idx, what, "threshold", 0, -HUGE_VAL, HUGE_VAL,
               CHK_REQUIRED);
  *link = chk_num(L, idx, what, "link", HOTSPOT_LINK, 0, 100, CHK_OPENLO);
}

int lsim_hotspots(lua_State *L) {
  lsim *ls = lsim_check(L, 1);
  double T, link;
  size_t j;
  int d;
  lsim_hotspot_opts(L, 2, "hotspots", &T, &link);
  if (diag_hotspots(&ls->s, T, link, &ls->hs))
    return luaL_error(L, "%s", ls->s.err);
  lua_createtable(L, (int)ls->hs.n, 3);
  for (j = 0; j < ls->hs.n; j++) {
    const hotspot *h = &ls->hs.r[j];
    lua_createtable(L, 0, 8);
    lua_pushinteger(L, (lua_Integer)h->n);
    lua_setfield(L, -2, "particles");
    setnum(L, "area", h->area);
    setnum(L, "mass", h->mass);
    setnum(L, "T_max", h->Tmax);
    setnum(L, "T_mean", h->Tmean);
    for (d = 0; d < DIM; d++) {
      char k[2] = {"xyz"[d], 0};
      setnum(L, k, h->x[d]);
    }
    setnum(L, "reacted", h->reacted);
    lua_rawseti(L, -2, (lua_Integer)j + 1);
  }
  lua_pushinteger(L, (lua_Integer)ls->hs.n);
  lua_setfield(L, -2, "count");
  setnum(L, "area", ls->hs.area_hot);
  setnum(L, "area_fraction",
         ls->hs.area_all > 0 ? ls->hs.area_hot / ls->hs.area_all : 0);
  return 1;
}

/* the count and area fraction for the diagnostics table (0, 0 when the
** output asks for none) */
void lsim_hotspot_row(lua_State *L, lsim *ls, double *count, double *frac) {
  *count = *frac = 0;
  if (!ls->hs_on) return;
  if (diag_hotspots(&ls->s, ls->hs_threshold, ls->hs_link, &ls->hs))
    luaL_error(L, "%s", ls->s.err);
  *count = (double)ls->hs.n;
  *frac = ls->hs.area_all > 0 ? ls->hs.area_hot / ls->hs.area_all : 0;
}

/* hotspots_NNNNNN.csv for snapshot number k, written whole or not at all */
void lsim_hotspot_file(lua_State *L, lsim *ls, int k) {
  char path[1100], err[1200], *buf;
  size_t cap, len = 0, j;
  if (!ls->hs_on) return;
  if (diag_hotspots(&ls->s, ls->hs_threshold, ls->hs_link, &ls->hs))
    luaL_error(L, "%s", ls->s.err);
  snprintf(path, sizeof path, "%s/hotspots_%06d.csv", ls->outdir, k);
  sandbox_file(L, path, "output");
  cap = 256 + 250 * (ls->hs.n + 1);
  if (!(buf = malloc(cap))) luaL_error(L, "output: out of memory");
  len += (size_t)snprintf(buf + len, cap - len,
      "# t = %.17g, step %ld, threshold %.17g, link %.17g spacings, "
      "hot area fraction %.17g\n"
      "region,particles,area,mass,T_max,T_mean,%s,reacted\n",
      ls->s.t, ls->s.step, ls->hs_threshold, ls->hs_link,
      ls->hs.area_all > 0 ? ls->hs.area_hot / ls->hs.area_all : 0,
      DIM == 2 ? "x,y" : "x,y,z");
  for (j = 0; j < ls->hs.n; j++) {
    const hotspot *h = &ls->hs.r[j];
    int d;
    len += (size_t)snprintf(buf + len, cap - len, "%zu,%zu,%.17g,%.17g,%.17g,%.17g",
                            j + 1, h->n, h->area, h->mass, h->Tmax, h->Tmean);
    for (d = 0; d < DIM; d++)
      len += (size_t)snprintf(buf + len, cap - len, ",%.17g", h->x[d]);
    len += (size_t)snprintf(buf + len, cap - len, ",%.17g\n", h->reacted);
  }
  if (ofile_put(path, buf, len, err, sizeof err)) {
    free(buf);
    luaL_error(L, "%s", err);
  }
  free(buf);
}
