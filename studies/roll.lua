-- Study: a disc on an incline, the incline being the floor wall of a box
-- with gravity rotated by theta (g = 1), periodic along the incline, the
-- wall acting per contact patch (wall_contact = "patch"; WALL_CONTACT=couple
-- in the environment: friction at the wall line).  An
-- elastic disc (K = 100, G = 50, density 1, R = 0.5: sqrt(g R) / c_L =
-- 0.05) starts at rest touching the floor.  Two regimes:
--
--   roll:  theta = 25 deg, mu = 0.5 >= tan(theta) / 3: rolling without
--          slip, a = (2/3) g sin(theta), alpha = a / R
--   slide: theta = 30 deg, mu = 0.1 <  tan(theta) / 3: sliding,
--          a = g (sin(theta) - mu cos(theta)), R alpha = 2 mu g cos(theta)
--
-- Measured: least-squares slopes of the centroid velocity along the
-- incline and of the spin (sim diag omega, clockwise = down the incline)
-- over t = 0.5 .. 2 (40 samples; the first quarter is the settling).
-- Errors: |a / a_ref - 1| and |alpha / alpha_ref - 1| per regime.
--
--   ./mvmpm test studies/roll.lua          (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local I = require "mvmpm.incline"

local rule = os.getenv("WALL_CONTACT") or "patch"
return S.main(I.study {
  name = rule == "patch" and "roll" or "roll_" .. rule,
  wall_contact = rule,
  title = "disc on an incline: rolling (25 deg, mu 0.5) and sliding (30 deg, mu 0.1)",
  grid = {cells = {8, 16, 32}, shape = {"linear", "gimp", "bspline2"},
           transfer = {"flip", "apic", "spin"}, ppc = {2, 4}},
  slab = nil,
})
