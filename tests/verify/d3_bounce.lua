-- 3-D impacts on walls.  The bouncing cylinder's sphere (scenarios/
-- sphere_bounce.lua): a unit-diameter elastic sphere (K = 1, G = 0.5,
-- density 1) at (0.1, 0.1, 0.1) in a 3 x 3 x 3 box with frictionless
-- walls meets the right, front and top walls one at a time (t = 2, 6,
-- 10).  Walls do no work: the total energy (kinetic + strain) at t = 14,
-- after the third impact, must equal the discrete initial energy; each
-- wall stops only its normal, so the momentum along the axes not hit yet
-- is kept to round-off, and the spin stays near zero.  The setting
-- for 3-D impacts: tests/verify/d3_bounce_usavg.lua.  Two spheres
-- colliding: tests/verify/d3_spheres.lua.  Larger grids and the other
-- schemes: studies/d3_bounce.lua, docs/accuracy.md.
local V = require "mvmpm.verify"

-- the scene and its measures: lua/mvmpm/bounce3.lua
local run = require("mvmpm.bounce3").run

local function order(a, b, ra, rb) return math.log(math.abs(ra) / math.abs(rb)) / math.log(b / a) end

local CELLS = {8, 12, 16}
V.case "sphere bounce, linear hats, FLIP, MUSL: energy after 3 impacts, 8 12 16 cells"
local def = {}
for k, c in ipairs(CELLS) do
  def[k] = run(c, {shape = "linear"})
  V.info(string.format("%d cells: energy change E(14)/E0 - 1", c), def[k].energy)
  V.info(string.format("%d cells: largest spin |omega| R / |v|", c), def[k].spin)
  V.info(string.format("%d cells: CPU seconds (os.clock)", c), def[k].cpu, "s")
end
for k = 2, #CELLS do
  V.info(string.format("energy error, observed order %d -> %d", CELLS[k - 1], CELLS[k]),
    order(CELLS[k - 1], CELLS[k], def[k - 1].energy, def[k].energy))
end
local s8 = def[1].sim
V.holds("linear hats, MUSL, FLIP",
  s8.shape == "linear" and s8.update == "musl" and s8.transfer == "flip")
-- measured -2.24 / -1.84 / -0.66 %: the 2 % wanted at 8 cells is missed
-- by linear hats (the walls' booked impact loss, 2.45 % of E0 at 8
-- cells); GIMP, USAVG, cfl 0.4 meets it and falls with refinement
-- (tests/verify/d3_bounce_usavg.lua, docs/accuracy.md); asserted here
-- is linear hats' fall, and 1 % at 16 cells
V.info(string.format("linear hats, |energy change| <= 2 %% at 8 cells: %s",
  math.abs(def[1].energy) <= 0.02 and "met" or "NOT met"), def[1].energy)
V.below("|energy change| falls 8 -> 12 cells", math.abs(def[2].energy), math.abs(def[1].energy))
V.below("|energy change| falls 12 -> 16 cells", math.abs(def[3].energy), math.abs(def[2].energy))
V.below("|energy change| at 16 cells", math.abs(def[3].energy), 0.01)
V.below("spin |omega| R / |v| falls 8 -> 16 cells", def[3].spin, def[1].spin)
V.below("spin |omega| R / |v| at 16 cells", def[3].spin, 0.02)

V.case "sphere bounce: momentum along the axes not hit yet (8 cells, linear hats)"
local r = def[1]
V.near("after the right wall: p_y / m kept", r[5].py, r.p0[2], 1e-12, true)
V.near("after the right wall: p_z / m kept", r[5].pz, r.p0[3], 1e-12, true)
V.near("after the front wall: p_y / m kept", r[9.5].py, r.p0[2], 1e-12, true)
V.near("after the front wall: p_x / m as after the right wall", r[9.5].px, r[5].px, 1e-12, true)
V.near("after the top wall: p_x / m as after the right wall", r[14].px, r[5].px, 1e-12, true)
V.near("after the top wall: p_z / m as after the front wall", r[14].pz, r[9.5].pz, 1e-12, true)
V.below("right wall reverses v_x: after / before", r[5].px / r.p0[1], -0.75)
V.below("front wall reverses v_z: after / before", r[9.5].pz / r.p0[3], -0.75)
V.below("top wall reverses v_y: after / before", r[14].py / r.p0[2], -0.75)

-- The defaults (quadratic B-splines, MUSL, FLIP): the wider stencil
-- takes more at each impact at coarse grids (-6.2 / -4.7 / -3.1 % at 8 /
-- 12 / 16 cells, docs/accuracy.md), falling at first order.  GIMP and
-- B-splines keep the momentum along the axes not hit to 1e-8 of it, not
-- to round-off: walls' ghost planes, docs/verification.md open items.
V.case "sphere bounce, the defaults (B-splines, FLIP, MUSL): 8 and 12 cells"
local b8, b12 = run(8), run(12)
V.holds("the defaults are B-splines, MUSL, FLIP",
  b8.sim.shape == "bspline2" and b8.sim.update == "musl" and b8.sim.transfer == "flip")
V.info("B-splines, 8 cells: energy change E(14)/E0 - 1", b8.energy)
V.info("B-splines, 12 cells: energy change E(14)/E0 - 1", b12.energy)
V.below("|energy change| falls 8 -> 12 cells", math.abs(b12.energy), math.abs(b8.energy))
V.below("|energy change| at 12 cells", math.abs(b12.energy), 0.06)
V.near("after the right wall: p_y / m kept (8 cells)", b8[5].py, b8.p0[2], 1e-6, true)
