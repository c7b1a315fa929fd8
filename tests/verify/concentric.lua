-- The report's debonding benchmark (scenarios/concentric_debond.lua): an
-- inner disc (alpha = 1) bonded in an annulus (alpha = 0), a/b = 0.5, on
-- 50 x 50 cells, cooled slowly.  While bonded, the stresses follow the
-- plane-strain Lame solution (3-D K, eps_zz = 0, e = (1 + nu) alpha dT):
--   s = -e / [1/(2K') + (a^2/(2K') + b^2/(2G)) / (b^2 - a^2)],  K' = K + G/3
--   disc:    sigma_rr = sigma_tt = s
--   annulus: sigma_rr = s a^2/(b^2 - a^2) (b^2/r^2 - 1)
--            sigma_tt = -s a^2/(b^2 - a^2) (b^2/r^2 + 1)
-- (s = 0.675 |alpha dT| here).  Debonding starts when s reaches the bond
-- strength; then the annulus relaxes toward no stress and the disc only
-- in plane: sigma_zz = -E alpha dT stays (eps_zz = 0).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local K, G, alpha, rate, a, b, sb = 1, 0.5, 1, 4e-4, 0.2, 0.4, 0.005
local lame = require "mvmpm.lame"
local E = 9 * K * G / (3 * K + G)
local h = 1 / 50
local unit = lame.unit(K, G, a, b)

local function profile(sim, dT)
  return lame.profile(sim, {0.5, 0.5}, unit * alpha * math.abs(dT), a, b, h)
end

-- the shape set here: the numbers below depend on it
-- the bond test's traction: both sides' stress profiles fitted across the
-- interface and averaged over 0.12 along it (sim.bond_traction = "fit")
local fit = {traction = "fit", bond_length = 0.12}
local sim = mvmpm.load("scenarios/concentric_debond.lua",
  {strength = sb, t_end = 30, shape = "linear", traction = fit.traction, bond_length = fit.bond_length})
local first, gone
sim:every {steps = 1, fn = function(s)
  local e = s:energy()
  if not first and e.debonded > 0 then first = s.t end
  if first and not gone and e.bonded_area == 0 then gone = s.t end
end}

V.case "bonded: stresses against the plane-strain Lame solution"
V.info("s / |alpha dT| (interface radial stress, analytic)", unit)
for _, t in ipairs {8, 12} do
  sim:run(t)
  local w, wi = profile(sim, -rate * t)
  V.below(string.format("t = %g: worst |sigma - Lame| / s along the radius (bin means)", t), w, 0.1)
  V.info(string.format("t = %g: the same in the cells at the interface and the rim", t), wi)
  -- what the bond test reads at each bonded node (sim:bonds(), fitted
  -- traction): Lame's s all along the interface, both sides, every node
  -- under its strength
  local bn, s = sim:bonds(), unit * alpha * rate * t
  local lo, hi, sum, per, worst = math.huge, -math.huge, 0, {0, 0}, 0
  for i = 1, #bn.x do
    local r = bn.traction[i] / s
    lo, hi, sum = math.min(lo, r), math.max(hi, r), sum + r
    per[bn.body[i]] = per[bn.body[i]] + 1
    worst = math.max(worst, math.abs(bn.strength[i] / sb - 1))
    local rr = math.sqrt((bn.x[i] - 0.5) ^ 2 + (bn.y[i] - 0.5) ^ 2)
    worst = math.max(worst, math.abs(rr - a) > 1.5 * h and 1 or 0)
  end
  V.info(string.format("t = %g: bonded interface nodes reported (each side)", t), per[1])
  V.holds(string.format("t = %g: both sides reported at every node, within 1.5 cells of r = a, strength %g", t, sb),
    per[1] == per[2] and per[1] > 0 and worst < 1e-12, worst)
  V.below(string.format("t = %g: |mean traction / s - 1| over the nodes", t), math.abs(sum / #bn.x - 1), 0.03)
  V.below(string.format("t = %g: (largest - least traction) / s", t), hi - lo, 0.05)
  V.below(string.format("t = %g: largest traction / strength (bonded: < 1)", t), hi * s / sb, 1)
end

V.case "debonding onset at three resolutions (linear hats, then uGIMP and B-splines)"
sim:run(20)
local dTc = sb / (unit * alpha)
V.info("analytic onset |dT| = strength / (s per unit |alpha dT|)", dTc)
-- the disc's in-plane stress over s, its time mean from t = 20 on
local function relaxed(sm)
  local sum, n = 0, 0
  sm:every {time = 0.1, fn = function(x)
    if x.t < 20 then return end
    local st, body = x:particles("stress"), x:particles("body")
    local d1, nd = 0, 0
    for i = 1, #body do
      if body[i] ~= 2 then d1, nd = d1 + 0.5 * (st.xx[i] + st.yy[i]), nd + 1 end
    end
    sum, n = sum + d1 / nd / (unit * alpha * rate * x.t), n + 1
  end}
  return function() return sum / n end
end
-- the onset |dT| over the analytic one, on a fresh scene run to its first
-- cut; with a list, the scene goes on to t = 24 and the disc's mean
-- in-plane stress over t = 20..24 is added to it
local relax = {}
local function onset(cells, shape, rel)
  local sm = mvmpm.load("scenarios/concentric_debond.lua",
    {strength = sb, t_end = 30, cells = cells, shape = shape,
     traction = fit.traction, bond_length = fit.bond_length})
  local t0, mean = nil, rel and relaxed(sm)
  sm:every {steps = 1, fn = function(x)
    if not t0 and x:energy().debonded > 0 then t0 = x.t end
  end}
  while not t0 and sm.t < 1.5 * dTc / rate do sm:run(sm.t + 0.5) end
  if rel then
    sm:run(24)
    rel[#rel + 1] = {cells, mean()}
  end
  return t0 and rate * t0 / dTc or 0 / 0
end
local res = {{25, onset(25, "linear", relax)}, {35, onset(35, "linear", relax)}, {50, rate * first / dTc}}
local err = {}
for i, r in ipairs(res) do
  err[i] = math.abs(r[2] - 1)
  V.info(string.format("%d cells: onset / analytic", r[1]), r[2])
  -- target: within 3 % at every resolution (with the mixture of the
  -- particles' stresses it was 1.065, 1.059, 1.007, 0.964 at 25, 35, 50,
  -- 100 cells: docs/verification.md)
  V.below(string.format("%d cells: |onset / analytic - 1|", r[1]), err[i], 0.03)
end
-- the errors are 0.32 %, 0.44 %, 0.74 %: within the target, but growing
-- a little from 25 to 50 cells (docs/verification.md)
V.info("observed order, 25 -> 35 cells", math.log(err[1] / err[2]) / math.log(35 / 25))
V.info("observed order, 35 -> 50 cells", math.log(err[2] / err[3]) / math.log(50 / 35))
-- The wider stencils, each at the same three resolutions.  uGIMP:
-- 1.002 / 1.001 / 0.996 (the fit's strip four cells each way; over
-- three it was 1.055 at 25 cells).  Quadratic B-splines (the default
-- shape): 0.960 / 1.003 / 0.992, the 25-cell onset 4.0 % early, which is
-- the discrete solution's, not the fit's: at 25 cells the disc is five
-- cells across its radius and its particles' radial stress, binned by
-- half cells at t = 14..18, runs from 0.97 to 1.08 of Lame's inside 3.5
-- cells of the centre, where the fit reads the disc's side
-- (docs/verification.md)
for _, shape in ipairs {"gimp", "bspline2"} do
  local e = {}
  for i, c in ipairs {25, 35, 50} do
    local r = onset(c, shape)
    e[i] = math.abs(r - 1)
    V.info(string.format("%s, %d cells: onset / analytic", shape, c), r)
  end
  if shape == "gimp" then
    for i, c in ipairs {25, 35, 50} do
      V.below(string.format("gimp, %d cells: |onset / analytic - 1|", c), e[i], 0.03)
    end
  else
    V.info("bspline2, 25 cells: |onset / analytic - 1| (target 3 %: missed)", e[1])
    V.below("bspline2, 35 cells: |onset / analytic - 1|", e[2], 0.03)
    V.below("bspline2, 50 cells: |onset / analytic - 1|", e[3], 0.03)
    V.below("bspline2: error at 50 cells over error at 25", e[3] / e[1], 1)
  end
end
-- The load is uniform along the interface (the exact solution lets go
-- everywhere at once): what spreads the release over time is only the
-- traction's residual scatter, so the "front" here is no crack tip.  The
-- bound c_R is checked on a true front in tests/verify/bonds.lua.
V.info("time from the first node let go to none bonded", gone - first)
V.info("  the same as a speed from 4 sites, 8 tips, / c_R",
  2 * math.pi * a / (8 * (gone - first)) / 0.6542)

V.case "after debonding: the annulus relaxes, the disc only in plane"
do
  -- the two ring freely after the release: average over t = 20 .. 24
  local ann, disc, zz, ref, n = 0, 0, 0, 0, 0
  sim:every {time = 0.1, fn = function(sm)
    if sm.t < 20 then return end
    local st, body = sm:particles("stress"), sm:particles("body")
    local dT = -rate * sm.t
    local s = unit * alpha * math.abs(dT)
    local a1, d1, z1, na, nd = 0, 0, 0, 0, 0
    for i = 1, #body do
      if body[i] == 2 then a1, na = a1 + 0.5 * (math.abs(st.xx[i]) + math.abs(st.yy[i])), na + 1
      else d1, z1, nd = d1 + 0.5 * (st.xx[i] + st.yy[i]), z1 + st.zz[i], nd + 1 end
    end
    ann, disc, zz = ann + a1 / na / s, disc + d1 / nd / s, zz + z1 / nd / (-E * alpha * dT)
    n = n + 1
  end}
  sim:run(24)
  -- The released gap is about a tenth of a cell, less than the contact's
  -- separation check resolves (particle squares of half a cell).  Judged
  -- by that check (bond_release = "contact") the annulus rang against the
  -- disc and contact rectified the ringing into a squeeze: the disc's mean
  -- in-plane stress was -0.67 s and sigma_zz 0.80 of the free value, the
  -- residual -6.7 % of the cooling's work.  With the opening measured from
  -- the released particles' displacements (the default, "open") the disc
  -- relaxes: the target is |mean in-plane stress| < 0.1 s.
  V.below("annulus: mean |in-plane stress| / s (bonded: about s)", ann / n, 0.4)
  relax[#relax + 1] = {50, disc / n}
  for _, r in ipairs(relax) do
    V.below(string.format("%d cells: disc |mean in-plane stress| / s (free: 0; bonded: +1)", r[1]),
      math.abs(r[2]), 0.1)
  end
  V.below("disc: |mean sigma_zz / (-E alpha dT) - 1| (free disc: 0)", math.abs(zz / n - 1), 0.05)
  V.below("bonded area left (of 2 pi a = 1.257)", sim:energy().bonded_area, 0)
  V.below("bonded nodes sim:bonds() reports after the release", #sim:bonds().x, 0)
  local e = sim:energy()
  V.below("|energy residual| / work of the cooling, linear hats, t = 24",
    math.abs(e.residual / e.thermal_work), 0.03)
end

V.case "energy budget through the release, quadratic B-splines"
do
  -- With linear hats (and GIMP) the free ringing after the release gains
  -- energy (residual -7 % of the cooling's work by t = 20, -13 % by t =
  -- 30: see docs/verification.md); the C1 B-spline keeps the budget.
  local bs = mvmpm.load("scenarios/concentric_debond.lua", {strength = sb, shape = "bspline2"})
  bs:run(24)
  local e = bs:energy()
  V.below("|energy residual| / work of the cooling at t = 24", math.abs(e.residual) / e.thermal_work, 0.03)
  V.above("debonded by t = 24 (bonded area 0)", -e.bonded_area, 0)
end

V.case "sim:bonds() changes nothing, and reads the same on two threads"
do
  -- a coarse copy of the scene, cooled slower: asked at t = 1, the run
  -- goes on bit for bit
  local function scene(threads)
    local sm = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 25, t_end = 3,
      sides = "free", threads = threads, bond_traction = "fit", bond_length = 0.16}
    sm:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = a}, bond = sb,
      material = mvmpm.elastic {K = K, G = G, density = 1, alpha = alpha}}
    sm:body {shape = mvmpm.annulus {center = {0.5, 0.5}, inner = a, outer = b}, bond = sb,
      material = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0}}
    sm:temperature(function(t) return -0.002 * t end)
    return sm
  end
  local plain, asked, two = scene(1), scene(1), scene(2)
  plain:run(1) -- the same stops (a run ends its last step on the time asked)
  plain:run(2)
  asked:run(1)
  two:run(1)
  local b1, b2 = asked:bonds(), two:bonds()
  local same = #b1.x == #b2.x and #b1.x > 0
  for i = 1, #b1.x do
    same = same and b1.traction[i] == b2.traction[i] and b1.x[i] == b2.x[i] and b1.body[i] == b2.body[i]
  end
  V.holds("one and two threads: the same records, bit for bit", same, #b1.x)
  asked:run(2)
  local p, q = plain:particles("position"), asked:particles("position")
  local ep, eq = plain:energy(), asked:energy()
  V.holds("asked at t = 1: positions and energies at t = 2 bit for bit as unasked",
    p.x[1] == q.x[1] and p.y[#p.y] == q.y[#q.y] and ep.total == eq.total and ep.strain == eq.strain
    and ep.debonded == eq.debonded)
end
