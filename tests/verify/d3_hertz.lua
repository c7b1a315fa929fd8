-- 3-D: Hertz contact.  An elastic hemisphere (R = 0.5, K = 100, G = 50,
-- E* = E / (1 - nu^2) = 140; curved side down, flat face up and free) on
-- a frictionless floor wall, loaded by its weight (the gravity set so that
-- Hertz's contact radius is a = 0.35 R), brought to rest by kinetic
-- damping (two sim:settle calls; lua/mvmpm/hertz.lua).  Reference, a
-- sphere on a rigid flat (the flat adds no compliance, so E* is the
-- sphere's alone):
--   a^3 = 3 F R / (4 E*),  F the weight,  p(r) = p0 sqrt(1 - r^2/a^2)
-- Measured: the contact radius from the floor's normal force node by
-- node (sim:wall_nodes): for Hertz's pressure the force-weighted mean of
-- r^2 is (2/5) a^2, so a_w = sqrt(5/2 sum f r^2 / sum f) (asserted), and
-- the fourth moment, <r^4> = (8/35) a^4, gives a_w4 (the profile's shape:
-- printed).  Two readings from the particles are printed beside them:
-- a_e, the outermost contact particle's radius plus half a spacing (a
-- count: it moves a ring of particles at a time, 1.009 a at 24 cells,
-- 1.117 a at 32), and a_m, the second moment of the contact particles'
-- pressure (0.82 - 0.87 a: the particles' pressure falls off before the
-- edge).  Target: a within 10 % where a spans 4 cells or more (24 cells
-- per diameter: a = 4.2 cells; 32 cells in studies/d3_hertz.lua); a_w's
-- error falls with refinement.  The floor's force, in total and summed
-- node by node, carries the weight.  Linear hats: the nodal forces of
-- B-splines (the default shape) spread a cell and a half beyond the
-- contact, a_w / a = 1.16 at 24 cells.
local V = require "mvmpm.verify"
local H = require "mvmpm.hertz"

V.case "Hertz: hemisphere on a rigid frictionless flat under its weight (3-D)"
local Es, E, nu = H.estar()
V.info("E* = E / (1 - nu^2)", Es)
V.info("nu", nu)
local CELLS, err = {12, 16, 24}, {}
for k, c in ipairs(CELLS) do
  local r = H.run {cells = c, ar = 0.35, shape = "linear", run = function(sim)
    sim:settle {t_max = 20}
    sim:settle {t_max = 20}
  end}
  V.near(string.format("%d cells: floor force / weight (at rest)", c), r.F / r.W, 1, 0.02)
  V.near(string.format("%d cells: floor's nodal forces summed / weight", c), r.F_w / r.W, 1, 0.02)
  V.info(string.format("%d cells: Hertz's a in cells", c), r.a_h / r.h)
  V.info(string.format("%d cells: a_w / a (floor forces' 2nd moment)", c), r.a_w / r.a_h)
  V.info(string.format("%d cells: a_w4 / a (floor forces' 4th moment)", c), r.a_w4 / r.a_h)
  V.info(string.format("%d cells: a_e / a (contact particles' edge)", c), r.a_e / r.a_h)
  V.info(string.format("%d cells: a_m / a (particles' pressure moment)", c), r.a_m / r.a_h)
  err[k] = math.abs(r.a_w / r.a_h - 1)
  if r.a_h / r.h >= 4 then
    V.near(string.format("%d cells: a_w / a (a spans %.1f cells)", c, r.a_h / r.h),
      r.a_w / r.a_h, 1, 0.10)
  end
end
for k = 2, #CELLS do
  V.info(string.format("a_w error, observed order %d -> %d", CELLS[k - 1], CELLS[k]),
    math.log(err[k - 1] / err[k]) / math.log(CELLS[k] / CELLS[k - 1]))
  V.below(string.format("a_w error falls %d -> %d cells", CELLS[k - 1], CELLS[k]), err[k], err[k - 1])
end
