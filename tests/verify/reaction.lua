-- The reaction phase against solutions that do not use the engine.
--
-- (a) Adiabatic induction: a block at rest, no conduction, zero-order
-- kinetics.  c dT/dt = Q Z exp(-Ta/T), so the time to reach T is
-- t(T) = c / (Q Z) * integral from T0 to T of exp(Ta/T') dT', computed
-- here by quadrature; its large-activation limit is Frank-Kamenetskii's
-- adiabatic explosion time c T0^2 / (Q Z Ta) exp(Ta/T0).  The engine's
-- temperature history and ignition time (lambda = 1/2) at three
-- mechanical steps, with the observed order.
-- (b) First-order decay at constant temperature (Q = 0): lambda(t) =
-- 1 - exp(-k t) to round-off, whatever the step.
-- (c) The chemical energy released equals the heat the particles gained.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local T0, Ta, c, Q, Z = 1000.0, 20000.0, 1000.0, 5.0e6, 5.0e6

-- the exact time to reach T (zero order, adiabatic) on a table: the
-- integral of exp(Ta/T') by the trapezoid rule on 200000 panels
-- (relative error ~1e-8 here), then inverted panel by panel
local NT = 200000
local dT = (Q / c) / NT
local Ttab, ttab = {}, {}
do
  local acc, f0 = 0, math.exp(Ta / T0)
  Ttab[0], ttab[0] = T0, 0
  for j = 1, NT do
    local T = T0 + j * dT
    local f1 = math.exp(Ta / T)
    acc = acc + 0.5 * (f0 + f1) * dT
    Ttab[j], ttab[j], f0 = T, acc * c / (Q * Z), f1
  end
end
local function t_of(T)
  local j = math.min(NT - 1, math.floor((T - T0) / dT))
  return ttab[j] + (ttab[j + 1] - ttab[j]) * (T - Ttab[j]) / dT
end
local function T_of(t)
  local lo, hi = 0, NT
  while hi - lo > 1 do
    local mid = (lo + hi) // 2
    if ttab[mid] <= t then lo = mid else hi = mid end
  end
  return Ttab[lo] + dT * (t - ttab[lo]) / (ttab[hi] - ttab[lo])
end

-- a 4 x 4 particle block of reacting material, at rest, no gravity
local function block(reaction, temp)
  local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.25, ppc = 2,
                         shape = "gimp", update = "usavg"}
  sim:body {shape = mvmpm.rect {lo = {0.25, 0.25}, hi = {0.75, 0.75}},
            material = mvmpm.elastic {K = 1e3, G = 5e2, density = 1, cv = c,
                                      reaction = reaction},
            temperature = temp}
  return sim
end

local function mean(t) local s = 0 for _, v in ipairs(t) do s = s + v end return s / #t end

V.case "adiabatic induction, zero order: temperature history and ignition time"
local t_half = t_of(T0 + 0.5 * Q / c)  -- lambda = 1/2
local t_fk = c * T0 ^ 2 / (Q * Z * Ta) * math.exp(Ta / T0)
V.info("exact ignition time (lambda = 1/2), quadrature", t_half)
V.info("large-activation limit c T0^2/(Q Z Ta) exp(Ta/T0)", t_fk)
V.info("  its offset from the exact time (Ta/T0 = 20)", t_fk / t_half - 1)
-- the largest error of T - T0 at 0.5, 0.8 and 0.9 t_ign (relative to the
-- exact rise), and the ignition time, at N steps to t_ign
local probes = {0.5, 0.8, 0.9}
local function induction(N, tol)
  local sim = block({Z = Z, Ta = Ta, Q = Q, order = 0}, T0)
  sim.dt = t_half / N
  if tol then sim.reaction_tol = tol end
  local worst, most = 0, 0
  for step = 1, N + N // 10 do
    sim:step()
    most = math.max(most, sim.reaction_substeps)
    for _, p in ipairs(probes) do
      if math.abs(step / N - p) < 1e-9 then
        local T, Tx = mean(sim:particles("temperature")), T_of(sim.t)
        worst = math.max(worst, math.abs(T - Tx) / (Tx - T0))
      end
    end
  end
  return worst, sim.ignition_time or math.huge, most
end
-- the mechanical step: the substeps follow the rate, not dt, so the error
-- should not depend on it
local errs = {}
for k, N in ipairs {10, 20, 40} do
  local e, ti, most = induction(N)
  errs[k] = e
  V.info(string.format("dt = t_ign/%d: error of T - T0 (0.5, 0.8, 0.9 t_ign)", N), e)
  V.info(string.format("dt = t_ign/%d: most substeps of a particle in a step", N), most)
  V.near(string.format("dt = t_ign/%d: ignition time", N), ti, t_half, 0.01, true)
end
V.below("temperature history within 1 % at every step size", math.max(errs[1], errs[2], errs[3]), 0.01)
V.info("observed order in dt (10 -> 20 -> 40 steps)", math.log(errs[1] / errs[3], 2) / 2)
-- the substep tolerance: the scheme's own order (midpoint, 2)
local et = {}
for k, tol in ipairs {0.1, 0.05, 0.025} do
  local e, ti = induction(10, tol)
  et[k] = e
  V.info(string.format("tol %.3g: error of T - T0", tol), e)
  V.info(string.format("tol %.3g: ignition time error", tol), ti / t_half - 1)
end
local p1, p2 = math.log(et[1] / et[2], 2), math.log(et[2] / et[3], 2)
V.info("observed order in the substep tolerance (0.1 -> 0.05)", p1)
V.info("observed order in the substep tolerance (0.05 -> 0.025)", p2)
V.above("second order in the substep tolerance (0.05 -> 0.025)", p2, 1.7)

V.case "first-order decay at constant temperature: lambda = 1 - exp(-k t)"
do
  local k = Z * math.exp(-Ta / T0) * 1e8 -- rate constant at T0 with Z' = 1e8 Z
  local worst = 0
  for _, N in ipairs {3, 17, 100} do
    local sim = block({Z = Z * 1e8, Ta = Ta, Q = 0, order = 1}, T0)
    local tend = 3 / k
    sim.dt = tend / N
    for _ = 1, N do sim:step() end
    local lam = sim:particles("reacted")
    local exact = 1 - math.exp(-k * sim.t)
    for _, l in ipairs(lam) do worst = math.max(worst, math.abs(l - exact)) end
    V.info(string.format("%d steps to k t = 3: max |lambda - exact|", N), worst)
  end
  V.below("round-off level at 3, 17 and 100 steps", worst, 1e-13)
end

V.case "energy: chemical energy released = heat gained by the particles"
do
  local sim = block({Z = Z, Ta = Ta, Q = Q, order = 1}, T0)
  sim.dt = t_half / 20
  for _ = 1, 30 do sim:step() end
  local T, m, lam = sim:particles("temperature"), sim:particles("mass"),
                    sim:particles("reacted")
  local heat, burnt = 0, 0
  for i = 1, #T do
    heat = heat + m[i] * c * (T[i] - T0)
    burnt = burnt + m[i] * Q * lam[i]
  end
  local chem = sim:energy().chemical
  V.info("chemical energy released", chem)
  V.near("sum m c (T - T0) = chemical", heat, chem, 1e-12, true)
  V.near("sum m Q lambda = chemical", burnt, chem, 1e-12, true)
  V.above("the block burnt (mean lambda)", sim.reacted, 0.99)
  local e = sim:energy()
  V.near("the heat budget books it as a source (heat_source = chemical)", e.heat_source, chem, 1e-12, true)
  V.below("heat residual / chemical", math.abs(e.heat_residual) / chem, 1e-12)
end

V.case "no reacting material: no reacted field, no chemical energy"
do
  local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.25, ppc = 2,
                         shape = "gimp", update = "usavg"}
  sim:body {shape = mvmpm.rect {lo = {0.25, 0.25}, hi = {0.75, 0.75}},
            material = mvmpm.elastic {K = 1e3, G = 5e2, density = 1}}
  sim:step(2)
  local has = false
  for _, f in ipairs(sim:particles()) do if f == "reacted" then has = true end end
  V.holds("no 'reacted' field", not has, has and 1 or 0)
  V.near("chemical energy 0", sim:energy().chemical, 0, 0)
end

-- (d) Thermal explosion of a disc held at T0 on its rim (a ring body at
-- hold_temperature, perfect thermal contact), zero order: Frank-
-- Kamenetskii's problem.  Four problems, each against its own critical
-- delta computed here without the engine (E.reference: shooting on the
-- steady radial problem to the fold of its branch): the linearised (fk)
-- exponent (delta_c = 2 exactly) and the Arrhenius exponent at
-- Ta/T0 = 20, 30, 50.  CI size: 6 cells per radius, bracketed (delta =
-- 0.95 delta_ref stays bounded, 1.03 delta_ref runs away over 8
-- conduction times); the bisections at 4, 6, 8, 12 cells per radius are
-- in studies/thermal_explosion.lua.  The 2 % check (0.97 delta_ref
-- bounded) is reported, not asserted: it holds for all four over 8
-- conduction times at this size, but the disc's critical delta at 6
-- cells is 2.7 % low (and 3.5 % over long runs): see docs/verification.md.
V.case "thermal explosion of a disc (Frank-Kamenetskii): critical delta at four exponents"
do
  local E = require "mvmpm.explosion"
  local T0 = 500
  local d0, a0 = E.reference(0)
  V.near("the shooting reference at eps = 0: delta_c = 2", d0, 2, 1e-9)
  V.near("... at theta(0) = ln 4", a0, math.log(4), 1e-5)
  local kin = E.kinetics(T0, 2.0) -- delta = 2 r^2
  local function theta_exact(d) -- the steady fk solution's peak
    local a = 8 / d - 2
    local B = (a - math.sqrt(a * a - 4)) / 2
    return math.log(8 * B / d)
  end
  local run, th, _, _, _, thc = E.run {r = math.sqrt(0.25 / 2), n = 4, T0 = T0, kinetics = kin,
                                       t_end = 8}
  V.holds("fk, delta = 0.25 stays bounded over 8 conduction times", not run, th)
  V.below("... its peak theta below ln 4 (the largest steady peak)", th, math.log(4))
  V.info("... its peak theta (exact steady peak, at the centre, " ..
         string.format("%.4f", theta_exact(0.25)) .. ")", th)
  V.info("... theta at the centre", thc)
  local n, cpu = 6, 0
  for _, ratio in ipairs {0, 20, 30, 50} do
    local name = ratio == 0 and "fk exponent" or string.format("Arrhenius, Ta/T0 = %d", ratio)
    local ref = ratio == 0 and 2 or E.reference(1 / ratio)
    local k = ratio == 0 and kin or E.kinetics(T0, 2.0, ratio, true)
    local function runs(f)
      local r, _, _, _, c = E.run {r = math.sqrt(f * ref / 2), n = n, T0 = T0, kinetics = k,
                                   t_end = 8}
      cpu = cpu + c
      return r
    end
    V.info(name .. ": reference delta_c (shooting)", ref)
    V.holds(name .. ": 0.95 delta_ref stays bounded, 6 cells per radius", not runs(0.95), 0)
    V.holds(name .. ": 1.03 delta_ref runs away", runs(1.03), 0)
    V.info(name .. ": 0.97 delta_ref stays bounded (the 2 % target; 1 = yes)",
           runs(0.97) and 0 or 1)
  end
  V.info("CPU s of the disc runs", cpu, "s")
end

-- (e) The melting cap of friction heating: a block slid along a frictional
-- floor (0.75 of the friction work to the material, no conduction), with
-- and without T_melt between the start and the peak the free run reaches.
V.case "melting cap: friction heat stops at T_melt, the rest is latent heat"
do
  local function slide(T_melt)
    local sim = mvmpm.sim {
      domain = {x = {0, 3}, y = {0, 1}}, cell = 0.1, ppc = 2, shape = "bspline2",
      gravity = {0, -1}, t_end = 1,
      sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = 0.3},
               top = "wall"}}
    sim:heat {wall_friction = 0.75}
    local mat = mvmpm.elastic {K = 400, G = 200, density = 1, cv = 3, T_melt = T_melt}
    sim:body {shape = mvmpm.rect {lo = {1, 0}, hi = {2, 0.5}}, material = mat,
              velocity = {1, 0}, temperature = 20}
    sim:run(0.5)
    local T, m = sim:particles("temperature"), sim:particles("mass")
    local Tmax, heat = -math.huge, 0
    for i = 1, #T do Tmax = math.max(Tmax, T[i]); heat = heat + m[i] * 3 * (T[i] - 20) end
    return Tmax, heat, sim:energy()
  end
  local Tfree, hfree, efree = slide(nil)
  local Tm = 20 + 0.5 * (Tfree - 20)
  local Tcap, hcap, ecap = slide(Tm)
  V.info("peak temperature without the cap", Tfree)
  V.near("no cap: no latent heat", efree.latent, 0, 0)
  V.below("with T_melt halfway: peak temperature - T_melt", Tcap - Tm, 1e-12 * Tm)
  V.above("latent heat booked", ecap.latent, 0.01 * hfree)
  V.near("heat held + latent = 0.75 friction work", (hcap + ecap.latent) / (0.75 * ecap.dissipated),
         1, 1e-10)
  V.below("heat residual / friction work", math.abs(ecap.heat_residual) / ecap.dissipated, 1e-10)
  V.near("the motion does not change (friction work with and without the cap)",
         ecap.dissipated, efree.dissipated, 0)
end
