-- Study: a disc on an incline that is a body: a driven (rigid, fixed)
-- slab 0.25 thick on the floor of a box with gravity rotated by theta
-- (g = 1), periodic along the incline, its top face grid-aligned; the
-- disc meets it through body-body contact (contact.c, friction mu).  An
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
--   ./mvmpm test studies/roll_slab.lua     (STUDY_QUICK=1: fewer settings)
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"
local I = require "mvmpm.incline"

local g, R, T = I.g, I.R, I.T

-- one regime at settings s: slopes of v and omega after the settling
local function incline(s, clock, deg, mu, slab)
  local r = I.run {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer,
                   flip = s.flip, update = s.update, cfl = s.cfl, deg = deg, mu = mu,
                   wall_contact = "patch", slab = slab, run = clock.run}
  return r.a, r.alpha, r.hop, r.th
end

local case = {
  name = "roll_slab",
  title = "disc on a driven slab: rolling (25 deg, mu 0.5) and sliding (30 deg, mu 0.1)",
  length = "D",
  reference = "rigid disc: rolling a = 2/3 g sin, alpha = a/R; sliding a = g (sin - mu cos), R alpha = 2 mu g cos",
  metrics = {{key = "roll_a", label = "rolling |a/a_ref - 1|"},
             {key = "roll_alpha", label = "rolling |alpha/alpha_ref - 1|"},
             {key = "slide_a", label = "sliding |a/a_ref - 1|"},
             {key = "slide_alpha", label = "sliding |alpha/alpha_ref - 1|"}},
  extra = {"roll_a_ratio", "roll_alpha_ratio", "slide_a_ratio", "slide_alpha_ratio", "roll_hop"},
  grid = {cells = {8, 16, 32}, shape = {"linear", "gimp"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl", ppc = 2},
  skip = function(s) return s.transfer == "apic" and s.shape == "linear" end,
  run = function(s, clock)
    local ra, ral, hop, th = incline(s, clock, 25, 0.5, "driven")
    local a_r = 2 / 3 * g * math.sin(th)
    local sa, sal, _, ts = incline(s, clock, 30, 0.1, "driven")
    local a_s = g * (math.sin(ts) - 0.1 * math.cos(ts))
    local al_s = 2 * 0.1 * g * math.cos(ts) / R
    return {roll_a = math.abs(ra / a_r - 1), roll_alpha = math.abs(ral / (a_r / R) - 1),
            slide_a = math.abs(sa / a_s - 1), slide_alpha = math.abs(sal / al_s - 1),
            roll_a_ratio = ra / a_r, roll_alpha_ratio = ral / (a_r / R),
            slide_a_ratio = sa / a_s, slide_alpha_ratio = sal / al_s, roll_hop = hop}
  end,
}
return S.main(case)
