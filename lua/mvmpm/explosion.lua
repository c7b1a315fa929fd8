-- mvmpm.explosion: Frank-Kamenetskii's thermal explosion of a disc in the
-- engine, for tests/verify/reaction.lua and studies/thermal_explosion.lua.
--
-- A disc of radius r of zero-order reacting material, inside a ring held
-- at T0 (a reservoir: hold_temperature) in perfect thermal contact.  With
-- theta = Ta (T - T0) / T0^2 and eps = T0 / Ta the steady problem is
--   lap theta + delta exp(theta / (1 + eps theta)) = 0, theta = 0 at r,
--   delta = Q rho Z Ta r^2 exp(-Ta/T0) / (k T0^2);
-- with the linearised (fk) exponent about T0 the exponent is theta alone
-- (eps = 0) and the critical delta is 2 exactly (an infinite cylinder);
-- at finite eps E.reference computes it by shooting, without the engine.
-- Units: rho = cv = k = 1; the Todes number Q Ta / (cv T0^2) is 2000
-- (burn-out far later than the run-away: zero order, lambda clamps only
-- at 1).
local mvmpm = require "mvmpm"
local E = {}

-- the kinetics whose delta is delta1 at r = 1 (so delta = delta1 r^2);
-- ratio = Ta/T0 (20 unless given); the fk exponent unless arrhenius
function E.kinetics(T0, delta1, ratio, arrhenius)
  local Ta = (ratio or 20) * T0
  local Q = 2000 * T0 * T0 / Ta
  local Z = delta1 * T0 * T0 * math.exp(Ta / T0) / (Q * Ta)
  return {Z = Z, Ta = Ta, Q = Q, order = 0, fk = not arrhenius and T0 or nil}
end

-- The reference: the critical delta of the steady disc at eps = T0/Ta
-- (0: the fk exponent), independent of the engine.  With s = sqrt(delta)
-- r the problem is w'' + w'/s + exp(w / (1 + eps w)) = 0, w(0) = a,
-- w'(0) = 0; its first zero s1(a) gives delta(a) = s1(a)^2 on the
-- solution branch, whose fold (the largest delta) is critical.  RK4 in s
-- from a series start, the zero by cubic Hermite interpolation, the fold
-- by golden section in a; eps = 0 gives 2 to 1e-12 at a = ln 4.
local function first_zero(a, eps)
  local function f(w) return math.exp(w / (1 + eps * w)) end
  local function rhs(x, w, v) return v, -v / x - f(w) end
  local h, x = 1e-3, 1e-4
  local w, v = a - f(a) * x * x / 4, -f(a) * x / 2
  while true do
    local k1w, k1v = rhs(x, w, v)
    local k2w, k2v = rhs(x + h / 2, w + h / 2 * k1w, v + h / 2 * k1v)
    local k3w, k3v = rhs(x + h / 2, w + h / 2 * k2w, v + h / 2 * k2v)
    local k4w, k4v = rhs(x + h, w + h * k3w, v + h * k3v)
    local w1 = w + h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)
    local v1 = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
    if w1 <= 0 then
      local lo, hi = 0, 1
      for _ = 1, 60 do
        local t = 0.5 * (lo + hi)
        local wt = (2 * t ^ 3 - 3 * t ^ 2 + 1) * w + (t ^ 3 - 2 * t ^ 2 + t) * h * v +
                   (3 * t ^ 2 - 2 * t ^ 3) * w1 + (t ^ 3 - t ^ 2) * h * v1
        if wt > 0 then lo = t else hi = t end
      end
      return x + h * 0.5 * (lo + hi)
    end
    x, w, v = x + h, w1, v1
  end
end

function E.reference(eps)
  local g = (math.sqrt(5) - 1) / 2
  local a, b = 0.3, 6
  local function D(t) return first_zero(t, eps) ^ 2 end
  local c, d = b - g * (b - a), a + g * (b - a)
  local fc, fd = D(c), D(d)
  for _ = 1, 40 do
    if fc > fd then b, d, fd = d, c, fc; c = b - g * (b - a); fc = D(c)
    else a, c, fc = c, d, fd; d = a + g * (b - a); fd = D(d) end
  end
  return math.max(fc, fd), 0.5 * (a + b)
end

-- one run: does the disc of radius r run away before t_end (in units of
-- the conduction time r^2)?  n cells per radius.  The step is the
-- conduction's stable step (one conduction substep a step), so that the
-- step shrinks as h^2 under refinement: the split of reaction and
-- conduction and the held ring's pull at the rim (once a substep) are
-- then refined with the grid; per = steps per r^2 overrides it.  Returns the verdict,
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
  sim.dt = o.per and t_c / o.per or 0.2 * h * h -- below 0.225 h^2: one substep
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
                                   t_end = o.t_end, shape = o.shape, per = o.per}
    cpu = cpu + c
    if run then hi = mid else lo = mid end
  end
  return math.sqrt(lo * hi), cpu, lo, hi
end

return E
