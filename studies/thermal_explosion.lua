-- Study: Frank-Kamenetskii's thermal explosion of a disc held at T0 on
-- its rim (mvmpm.explosion: a zero-order reacting disc inside a ring
-- body at hold_temperature, perfect thermal contact).  The critical
-- radius is found by bisection (the grid scaled with the radius: n cells
-- per radius) and given as delta_c = 2 r_c^2 (the kinetics make delta =
-- 2 r^2).  Reference: delta_c = 2.00 for the infinite cylinder, exact
-- for the linearised exponent (fk = T0).  The Arrhenius exponent is run
-- at three temperatures with Ta/T0 = 20 and the Todes number fixed, so
-- the three are one problem in scaled units (a check of the scaling).
-- Also the steady peak at delta = 0.25 (exact 0.0657) at the centre and
-- the largest anywhere.
--
--   ./mvmpm test studies/thermal_explosion.lua      (STUDY_QUICK=1: n = 4, 6)
local V = require "mvmpm.verify"
local E = require "mvmpm.explosion"

local quick = os.getenv("STUDY_QUICK") == "1"
local ns = quick and {4, 6} or {4, 8, 12}
local T0 = 500
local rows = {}

V.case "disc, fk exponent: critical delta at n cells per radius"
for _, n in ipairs(ns) do
  local kin = E.kinetics(T0, 2.0)
  local rc, cpu = E.critical {lo = 0.3, hi = 1.6, n = n, T0 = T0, kinetics = kin,
                              t_end = 12, iters = quick and 5 or 7}
  local _, th, _, _, _, thc = E.run {r = math.sqrt(0.125), n = n, T0 = T0, kinetics = kin,
                                     t_end = 8}
  V.info(string.format("n = %d: delta_c (exact 2.00)", n), 2 * rc * rc)
  V.info(string.format("n = %d: steady peak theta at delta 0.25, centre (exact 0.0657)", n), thc)
  V.info(string.format("n = %d: ... largest anywhere (the rim)", n), th)
  V.info(string.format("n = %d: CPU s", n), cpu, "s")
  rows[#rows + 1] = {n, 2 * rc * rc, thc, th}
end
if #rows >= 2 then
  local a, b = rows[#rows - 1], rows[#rows]
  V.info("observed order of the delta_c error (last two n)",
         math.log(math.abs(a[2] - 2) / math.abs(b[2] - 2)) / math.log(b[1] / a[1]))
end

V.case "disc, Arrhenius exponent (Ta/T0 = 20): three temperatures"
for _, T in ipairs {400, 500, 600} do
  local kin = E.kinetics(T, 2.0)
  kin.fk = nil
  local rc = E.critical {lo = 0.3, hi = 1.6, n = ns[#ns - 1] or 4, T0 = T, kinetics = kin,
                         t_end = 12, iters = 5}
  V.info(string.format("T0 = %d K: delta_c measured", T), 2 * rc * rc)
end
