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
-- 1.3 %, 0.6 %, 0.6 %: from 8 cells the error is at the level the
-- settling leaves (0.2 % between successive settles) and the seeded
-- volumes' staircase; no steady order (docs/verification.md)
V.info("observed order of the sphere's error, 6 -> 8 cells", math.log(err[1] / err[2]) / math.log(8 / 6))
V.info("observed order of the sphere's error, 8 -> 10 cells", math.log(err[2] / err[3]) / math.log(10 / 8))
do
  local r = S.run {cells = 8, shape = "gimp"}
  V.near("GIMP, 8 cells: sphere's sigma_rr / s", r.inner, 1, 0.03)
  V.near("GIMP, 8 cells: sigma_rr at the interface's cells / s", r.band, 1, 0.03)
  V.info("GIMP, 8 cells: shell, worst radial bin |sigma_rr - Lame| / s", r.shell)
end
