-- Study: Frank-Kamenetskii's thermal explosion of a disc held at T0 on
-- its rim (mvmpm.explosion: a zero-order reacting disc inside a ring
-- body at hold_temperature, perfect thermal contact).  The critical
-- radius is found by bisection (the grid scaled with the radius: n cells
-- per radius; the step the conduction's stable step, so it shrinks as
-- h^2) and given as delta_c = 2 r_c^2 (the kinetics make delta = 2 r^2).
-- Four problems, each against its own reference computed without the
-- engine (E.reference, shooting to the fold of the steady branch): the
-- linearised (fk) exponent, delta_c = 2 exactly, and the Arrhenius
-- exponent at Ta/T0 = 20, 30, 50.  Also: the answer against the length
-- of the runs (8, 16, 32, 64 conduction times r^2).
--
--   ./mvmpm test studies/thermal_explosion.lua      (STUDY_QUICK=1: n = 4, 6)
local V = require "mvmpm.verify"
local E = require "mvmpm.explosion"

local quick = os.getenv("STUDY_QUICK") == "1"
local ns = quick and {4, 6} or {4, 6, 8, 12}
local T0 = 500

-- the critical delta at n cells per radius, bracketed within
-- [0.85, 1.1] delta_ref by 6 halvings (resolution 0.4 % of delta)
local function critical(kin, ref, n, t_end)
  local rc, cpu = E.critical {lo = math.sqrt(0.85 * ref / 2), hi = math.sqrt(1.1 * ref / 2),
                              n = n, T0 = T0, kinetics = kin, t_end = t_end or 8, iters = 6}
  return 2 * rc * rc, cpu
end

for _, ratio in ipairs {0, 20, 30, 50} do
  local name = ratio == 0 and "fk exponent" or string.format("Arrhenius, Ta/T0 = %d", ratio)
  local ref = ratio == 0 and 2 or E.reference(1 / ratio)
  local kin = ratio == 0 and E.kinetics(T0, 2.0) or E.kinetics(T0, 2.0, ratio, true)
  V.case("disc, " .. name .. ": critical delta at n cells per radius")
  V.info("reference delta_c (shooting)", ref)
  local errs = {}
  for k, n in ipairs(ns) do
    local d, cpu = critical(kin, ref, n)
    errs[k] = d / ref - 1
    V.info(string.format("n = %d: delta_c", n), d)
    V.info(string.format("n = %d: relative error", n), errs[k])
    V.info(string.format("n = %d: CPU s", n), cpu, "s")
  end
  for k = 2, #ns do
    V.info(string.format("observed order %d -> %d", ns[k - 1], ns[k]),
           math.log(math.abs(errs[k - 1]) / math.abs(errs[k])) / math.log(ns[k] / ns[k - 1]))
  end
  V.below("within 2 % at the finest n", math.abs(errs[#errs]), quick and 0.05 or 0.02)
end

V.case "disc, fk exponent: the critical delta against the length of the runs (n = 6)"
local d = {}
for k, te in ipairs {8, 16, 32, 64} do
  d[k] = critical(E.kinetics(T0, 2.0), 2, 6, te)
  V.info(string.format("t_end = %d r^2: delta_c", te), d[k])
end
V.info("8 -> 64 conduction times: relative change", d[4] / d[1] - 1)
V.below("32 -> 64 conduction times: change below the bisection's 0.4 %",
        math.abs(d[4] / d[3] - 1), 0.004)
