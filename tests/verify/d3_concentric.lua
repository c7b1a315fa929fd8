-- 3-D: concentric spheres under cooling, bonded.  An inner sphere (radius
-- a = 0.2, alpha = 1) on one velocity field with a shell (a .. b = 0.4,
-- alpha = 0), both K = 1, G = 0.5, density 1, cooled by dT = -0.004 in
-- one step and brought to rest by kinetic damping (two sim:settle calls).
-- Reference, the spherical Lame solution (lua/mvmpm/lame.lua, sphere):
--   s = -(e1 - e2) / [1/(3 K1) + (a^3/(3 K2) + b^3/(4 G2)) / (b^3 - a^3)]
-- (s = 1.050 |alpha dT| here); the sphere holds sigma_rr = sigma_tt = s,
-- the shell sigma_rr = s a^3/(b^3 - a^3) (b^3/r^3 - 1).
-- The whole sphere is simulated: the octant on walls would not do, a
-- wall being one-sided and the sphere pulling on its cut planes where the
-- shell pushes.  Measured: the interface radial stress as the sphere's
-- mean radial stress (particles 1.5 cells or more inside the interface;
-- the exact field is uniform there), and across the interface's own cells
-- (particles within a cell of r = a, each less Lame's variation from the
-- interface value); the shell's worst radial bin.  Target: the interface
-- stress within 3 % at every resolution (6, 8, 10 cells across b, linear
-- hats; GIMP at 8).
local V = require "mvmpm.verify"
local S = require("mvmpm.lame").sphere

V.case "concentric spheres, bonded, cooled: interface radial stress against Lame (3-D)"
V.info("s / |alpha dT| (interface radial stress, analytic)", S.interface(1, 1, 0.5, 0.2, 0.4, -1, 0))
local cells, err = {6, 8, 10}, {}
for k, c in ipairs(cells) do
  local r = S.run {cells = c, shape = "linear"}
  err[k] = math.abs(r.inner - 1)
  V.near(string.format("linear, %d cells: sphere's sigma_rr / s", c), r.inner, 1, 0.03)
  V.near(string.format("linear, %d cells: sphere's hoop stress / s", c), r.hoop, 1, 0.03)
  V.near(string.format("linear, %d cells: sigma_rr at the interface's cells / s", c), r.band, 1, 0.03)
  if c >= 8 then  -- at 6 cells no bin lies 1.5 cells from both the interface and the rim
    V.info(string.format("linear, %d cells: shell, worst radial bin |sigma_rr - Lame| / s", c), r.shell)
  end
end
-- 0.93 %, 0.98 %, 0.91 %: the error is at the level the settling
-- leaves (0.2 % between successive settles) and the seeded volumes'
-- staircase; no steady order (docs/verification.md)
V.info("observed order of the sphere's error, 6 -> 8 cells", math.log(err[1] / err[2]) / math.log(8 / 6))
V.info("observed order of the sphere's error, 8 -> 10 cells", math.log(err[2] / err[3]) / math.log(10 / 8))
do
  local r = S.run {cells = 8, shape = "gimp"}
  V.near("GIMP, 8 cells: sphere's sigma_rr / s", r.inner, 1, 0.03)
  V.near("GIMP, 8 cells: sigma_rr at the interface's cells / s", r.band, 1, 0.03)
  V.info("GIMP, 8 cells: shell, worst radial bin |sigma_rr - Lame| / s", r.shell)
end

V.case "two bodies bonded: what the bond test reads at the interface (sim:bonds, 3-D)"
do
  -- the same spheres as two bodies bonded (strength 1: nothing lets go),
  -- settled twice; every bonded node's traction against Lame's s, with
  -- the stress fitted across the interface ("fit", over 0.1) and with the
  -- mixture of both sides' stresses (the default), at 6, 8, 10 cells;
  -- the fit also on uGIMP and B-splines at 8
  local mvmpm = require "mvmpm"
  local K, G, a, b, dT = 1, 0.5, 0.2, 0.4, -0.004
  local s = S.interface(K, K, G, a, b, dT, 0)
  -- the readings' count, mean / s, spread / s, farthest node from r = a in cells
  local function read(cells, tr, shape)
    local h = b / cells
    local L = 2 * b + 2 * h
    local c = L / 2
    local sim = mvmpm.sim {dim = 3, domain = {x = {0, L}, y = {0, L}, z = {0, L}}, cell = h,
      shape = shape, t_end = 1e9, sides = "free", bond_traction = tr,
      bond_length = tr == "fit" and 0.1 or 0}
    sim:body {shape = mvmpm.ball {center = {c, c, c}, radius = a}, bond = 1,
      material = mvmpm.elastic {K = K, G = G, density = 1, alpha = 1}}
    sim:body {shape = mvmpm.shell {center = {c, c, c}, inner = a, outer = b}, bond = 1,
      material = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0}}
    sim:temperature(function() return dT end)
    sim:settle {t_max = 20}
    sim:settle {t_max = 20}
    local bn = sim:bonds()
    local lo, hi, sum, off = math.huge, -math.huge, 0, 0
    for i = 1, #bn.x do
      local r = bn.traction[i] / s
      lo, hi, sum = math.min(lo, r), math.max(hi, r), sum + r
      local d = math.sqrt((bn.x[i] - c) ^ 2 + (bn.y[i] - c) ^ 2 + (bn.z[i] - c) ^ 2)
      off = math.max(off, math.abs(d - a) / h)
    end
    return #bn.x, sum / #bn.x, hi - lo, off
  end
  local mix = {}
  for k, cells in ipairs {6, 8, 10} do
    local n, mean, spread, off = read(cells, "fit", "linear")
    V.holds(string.format("%d cells: bonded nodes reported, all within 1.5 cells of r = a", cells),
      n > 0 and off <= 1.5, n)
    -- 1.0028 / 1.0024 / 1.0014 of s, the nodes within 0.7 % of each other
    V.near(string.format("%d cells, fit: mean traction / s", cells), mean, 1, 0.02)
    V.below(string.format("%d cells, fit: (largest - least) / s", cells), spread, 0.02)
    -- 0.76 / 0.82 / 0.84: each node's mixture straddles the interface,
    -- where the shell's radial stress falls steeply: low at first order
    local _, mm = read(cells, "mixture", "linear")
    mix[k] = math.abs(mm - 1)
    V.info(string.format("%d cells, mixture: mean traction / s", cells), mm)
  end
  V.below("mixture: its error at 10 cells over its error at 6 (falls)", mix[3] / mix[1], 1)
  V.info("mixture: observed order, 6 -> 10 cells", math.log(mix[1] / mix[3]) / math.log(10 / 6))
  -- other shapes: uGIMP 1.0006, B-splines 0.9993
  for _, shape in ipairs {"gimp", "bspline2"} do
    local _, mean, spread = read(8, "fit", shape)
    V.near(string.format("%s, 8 cells, fit: mean traction / s", shape), mean, 1, 0.02)
    V.below(string.format("%s, 8 cells, fit: (largest - least) / s", shape), spread, 0.02)
  end
end
