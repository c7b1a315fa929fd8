-- Study: the frictionless bouncing cylinder (scenarios/cylinder_bounce.lua,
-- the report's Figures 2-4): a unit-diameter elastic disc launched at
-- (0.1, 0.1) in a 3 x 3 box meets the right, top and left walls (near
-- t = 5, 15 and 30; the fourth impact, on the bottom wall, comes after
-- t = 40).  Reference: frictionless walls do no work, so the total energy
-- (kinetic + strain) after the three impacts (t = 36, the time
-- tests/verify/cylinder_bounce.lua uses) must equal the *discrete*
-- initial energy of the seeded particles (not pi/4 * 0.01 / 2: the seeding
-- holds 3 % more area than the circle).  Error: |E(36) / E(0) - 1|.
--
--   ./mvmpm test studies/bounce.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local case = {
  name = "bounce",
  title = "frictionless bounce",
  length = "D",
  reference = "the discrete initial energy E0; frictionless walls do no work",
  metrics = {{key = "energy", label = "|E/E0 - 1| after 3 bounces"}},
  extra = {"dE"},
  grid = {cells = {8, 12, 16, 24, 32, 48}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic", "spin"}, flip = {1, 0}, update = {"musl", "usl"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  -- PIC only on linear hats; USL only with FLIP (enough to show what each does)
  skip = function(s)
    if s.update == "usl" then return s.transfer ~= "flip" or s.flip ~= 1 end
    return s.flip == 0 and s.shape ~= "linear"
  end,
  run = function(s, clock)
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
      {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer, flip = s.flip,
       update = s.update, cfl = s.cfl, t_end = 36})
    local e0 = sim:energy().total
    clock.run(sim, 36)
    local d = sim:energy().total / e0 - 1
    return {energy = math.abs(d), dE = d}
  end,
}
return S.main(case)
