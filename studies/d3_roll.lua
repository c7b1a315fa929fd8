-- Study (3-D): a sphere on an incline, the incline being the floor wall
-- of a box with gravity rotated by theta = 25 deg about z (g = 1),
-- periodic down the slope (lua/mvmpm/incline3.lua).  An elastic sphere
-- (K = 100, G = 50, density 1, R = 0.5) starts at rest on the floor.
--   roll:  the floor sticking (friction = "stick"), wall_contact "patch":
--          a = (5/7) g sin(theta), alpha = a / R
--   slide: the floor frictionless: a = g sin(theta), no spin
-- Measured: least-squares slopes of the centre of mass velocity and spin
-- over t = 0.5 .. 2.  Errors |a / a_ref - 1|, |R alpha / a_ref - 1|.
--
--   ./mvmpm test studies/d3_roll.lua          (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local I = require "mvmpm.incline3"

return S.main({
  name = "d3_roll",
  title = "3-D sphere on an incline: rolling (25 deg, sticking) and sliding (frictionless)",
  length = "D",
  reference = "rigid sphere: rolling a = 5/7 g sin, alpha = a/R; frictionless a = g sin",
  metrics = {{key = "roll_a", label = "rolling |a/a_ref - 1|"},
             {key = "roll_alpha", label = "rolling |R alpha/a_ref - 1|"},
             {key = "slide_a", label = "sliding |a/(g sin) - 1|"}},
  extra = {"roll_a_ratio", "roll_alpha_ratio", "roll_residual"},
  grid = {cells = {8, 12, 16}, shape = {"linear", "gimp"}, transfer = {"flip", "apic"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl", ppc = 2},
  run = function(s, clock)
    local function go(mu)
      return I.run {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer,
                    flip = s.flip, update = s.update, cfl = s.cfl, deg = 25, mu = mu,
                    run = clock.run}
    end
    local r = go("stick")
    local ref = 5 / 7 * I.g * math.sin(r.th)
    local f = go(0)
    return {roll_a = math.abs(r.a / ref - 1), roll_alpha = math.abs(r.alpha * I.R / ref - 1),
            slide_a = math.abs(f.a / (I.g * math.sin(f.th)) - 1),
            roll_a_ratio = r.a / ref, roll_alpha_ratio = r.alpha * I.R / ref,
            roll_residual = r.e.residual / (r.e.initial - r.e.potential)}
  end,
}, {repeats = 1})
