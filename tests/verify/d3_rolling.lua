-- 3-D: a sphere rolling on an incline.  An elastic sphere (R = 0.5,
-- K = 100, G = 50, density 1) on the floor wall of a box with gravity
-- rotated by theta = 25 deg about z (g = 1), periodic down the slope,
-- frictionless walls across it, the floor sticking (friction = "stick"),
-- the wall acting per contact patch (lua/mvmpm/incline3.lua).  Reference,
-- the rigid sphere rolling without slip: a = (5/7) g sin(theta), alpha =
-- a / R; on a frictionless floor it slides at g sin(theta) with no spin.
-- Fitted: least-squares slopes of the centre of mass velocity down the
-- slope and of the spin about -z over t = 0.5 .. 2 (40 samples, the first
-- quarter being the settling on the floor).  Target: a within 2 % at 12
-- cells per diameter.  Linear hats, FLIP, 2 x 2 x 2 particles per cell:
-- 5.0 % and 2.3 % short at 8 and 12 cells (missed, printed; 1.2 % at 16
-- in studies/d3_roll.lua); GIMP with APIC: 0.8 % at 12 cells (asserted).
local V = require "mvmpm.verify"
local I = require "mvmpm.incline3"

local g, R = I.g, I.R

local function target(name, err, tol)
  V.info(string.format("%s: error %.4f, target %g: %s", name, err, tol,
                       err <= tol and "met" or "NOT met"), err)
end

local function roll(cells, shape, transfer)
  local r = I.run {cells = cells, shape = shape, transfer = transfer, deg = 25, mu = "stick"}
  local ref = 5 / 7 * g * math.sin(r.th)
  return r, r.a / ref
end

V.case "sphere rolling on an incline (25 deg, sticking floor), linear hats, FLIP"
local err = {}
for k, c in ipairs {8, 12} do
  local r, ratio = roll(c, "linear")
  err[k] = math.abs(ratio - 1)
  V.info(string.format("linear, %d cells: a / ((5/7) g sin)", c), ratio)
  if c == 12 then target("linear, 12 cells: rolling a", err[k], 0.02) end
  V.near(string.format("linear, %d cells: a / ((5/7) g sin), the 8-cell bound", c), ratio, 1, 0.06)
  V.info(string.format("linear, %d cells: R alpha / a (no slip: 1)", c), r.alpha * R / r.a)
  V.below(string.format("linear, %d cells: largest hop (centre above R)", c), r.hop, 0.005)
  V.below(string.format("linear, %d cells: drift across the slope", c), r.drift, 1e-9)
  V.near(string.format("linear, %d cells: energy residual / potential drop", c),
         r.e.residual / (r.e.initial - r.e.potential), 0, 0.02)
  V.info(string.format("linear, %d cells: CPU seconds", c), r.cpu)
end
V.info("linear: observed order of the error, 8 -> 12 cells", math.log(err[1] / err[2]) / math.log(1.5))

V.case "the 12-cell target with GIMP and APIC"
do
  local r, ratio = roll(12, "gimp", "apic")
  V.near("GIMP APIC, 12 cells: a / ((5/7) g sin)", ratio, 1, 0.02)
  V.near("GIMP APIC, 12 cells: R alpha / a (no slip)", r.alpha * R / r.a, 1, 0.05)
  V.near("GIMP APIC, 12 cells: energy residual / potential drop",
         r.e.residual / (r.e.initial - r.e.potential), 0, 0.02)
  V.info("GIMP APIC, 12 cells: CPU seconds", r.cpu)
end

V.case "control: frictionless floor, the sphere slides at g sin(theta) without spin"
do
  local r = I.run {cells = 8, deg = 25, mu = 0, shape = "linear"}
  V.near("linear, 8 cells: a / (g sin)", r.a / (g * math.sin(r.th)), 1, 0.005)
  V.below("linear, 8 cells: |R alpha| / a", math.abs(r.alpha * R / r.a), 0.01)
  V.near("linear, 8 cells: energy residual / potential drop",
         r.e.residual / (r.e.initial - r.e.potential), 0, 0.02)
end

V.case "3-D rolling is deterministic: 1 and 2 threads give the same bits"
do
  local a = I.run {cells = 8, deg = 25, mu = "stick", threads = 1}
  local b = I.run {cells = 8, deg = 25, mu = "stick", threads = 2}
  V.holds("rolling a, spin and residual equal at 1 and 2 threads",
          a.a == b.a and a.alpha == b.alpha and a.e.residual == b.e.residual, a.a - b.a)
end
