-- mvmpm.explosion: Frank-Kamenetskii's thermal explosion of a disc in the
-- engine, for tests/verify/reaction.lua and studies/thermal_explosion.lua.
--
-- A disc of radius r of zero-order reacting material, inside a ring held
-- at T0 (a reservoir: hold_temperature) in perfect thermal contact, with
-- the linearised (fk) exponent about T0, so that the steady problem is
-- exactly Frank-Kamenetskii's: lap theta + delta exp(theta) = 0, theta =
-- 0 at the rim, theta = Ta (T - T0) / T0^2, with
--   delta = Q rho Z Ta r^2 exp(-Ta/T0) / (k T0^2),
-- critical at delta_c = 2 (an infinite cylinder).  Subcritical, theta
-- rises to a steady state with theta_max <= ln 4 = 1.386; supercritical,
-- it runs away.  Units: rho = cv = k = 1; Ta = 20 T0; Q so that the
-- Todes number Q Ta / (cv T0^2) is 2000 (burn-out far later than the
-- run-away: zero order, lambda clamps only at 1).
local mvmpm = require "mvmpm"
local E = {}

-- the kinetics whose delta is delta1 at r = 1 (so r_c = sqrt(2/delta1))
function E.kinetics(T0, delta1)
  local Ta = 20 * T0
  local Q = 2000 * T0 * T0 / Ta
  local Z = delta1 * T0 * T0 * math.exp(Ta / T0) / (Q * Ta)
  return {Z = Z, Ta = Ta, Q = Q, order = 0, fk = T0}
end

-- one run: does the disc of radius r run away before t_end (in units of
-- the conduction time r^2)?  n cells per radius.  Returns the verdict,
-- theta_max reached, the disc's area-equivalent radius, steps, CPU s and
-- theta at the centre (the particles within a cell of it) at the end.
function E.run(o)
  local r, n, T0 = o.r, o.n or 6, o.T0
  local kin = o.kinetics
  local h = r / n
  local L = r + 4 * h
  local sim = mvmpm.sim {domain = {x = {-L, L}, y = {-L, L}}, cell = h, ppc = 2,
                         shape = o.shape or "gimp", update = "usavg"}
  sim:heat {}
  local mat = mvmpm.elastic {K = 1, G = 0.5, density = 1, cv = 1, k = 1, reaction = kin}
  local ring = mvmpm.elastic {K = 1, G = 0.5, density = 1, cv = 1, k = 1}
  sim:body {name = "disc", shape = mvmpm.disk {center = {0, 0}, radius = r},
                         material = mat, temperature = T0}
  sim:body {name = "ring", shape = mvmpm.rest(), material = ring, hold_temperature = T0}
  -- the disc as seeded (particles inside r): its area-equivalent radius
  local nd = 0
  for _, b in ipairs(sim:particles("body")) do if b == 1 then nd = nd + 1 end end
  local req = math.sqrt(nd * (h / 2) ^ 2 / math.pi)
  local t_c = r * r
  sim.dt = o.dt or t_c / 200
  local Ta = kin.Ta
  local nsteps = math.ceil((o.t_end or 25) * t_c / sim.dt)
  local th, thc, c0 = 0, 0, os.clock()
  local runaway = false
  while sim.steps < nsteps do -- checked every quarter of t_c
    sim:step(math.min(nsteps - sim.steps, math.ceil(0.25 * t_c / sim.dt)))
    local T = sim:particles("temperature")
    local bodyof, x = sim:particles("body"), sim:particles("position")
    thc = 0
    for i = 1, #T do
      if bodyof[i] == 1 then
        local thi = Ta * (T[i] - T0) / (T0 * T0)
        th = math.max(th, thi)
        if x.x[i] ^ 2 + x.y[i] ^ 2 < h * h then thc = math.max(thc, thi) end
      end
    end
    if th > 5 then runaway = true break end
  end
  return runaway, th, req, sim.steps, os.clock() - c0, thc
end

-- bisection on the radius (the grid scaled with it: n cells per radius)
-- between lo and hi; returns the critical radius and the runs' CPU time
function E.critical(o)
  local lo, hi, cpu = o.lo, o.hi, 0
  for _ = 1, o.iters or 6 do
    local mid = math.sqrt(lo * hi)
    local run, _, _, _, c = E.run {r = mid, n = o.n, T0 = o.T0, kinetics = o.kinetics,
                                   t_end = o.t_end, shape = o.shape}
    cpu = cpu + c
    if run then hi = mid else lo = mid end
  end
  return math.sqrt(lo * hi), cpu, lo, hi
end

return E
