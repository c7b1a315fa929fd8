-- Contact: rolling and spin-up.  An elastic disc (R = 0.5, K = 100,
-- G = 50, density 1) on an incline, the incline being the floor wall with
-- gravity rotated by theta (g = 1), periodic along it, at 8, 16 and 32
-- cells per diameter (linear hats, FLIP, MUSL, 2 x 2 particles per cell).
--   sliding (theta 30 deg, mu 0.1 < tan(theta)/3):
--     a = g (sin - mu cos),  R alpha = 2 mu g cos
--   rolling (theta 25 deg, mu 0.5 >= tan(theta)/3):
--     a = (2/3) g sin,  alpha = a / R
-- Slopes of the centroid velocity and of the spin are fitted over
-- t = 0.5 .. 2, after the settling.  The wall gives the exact Coulomb
-- force, so the sliding acceleration is held to 1 % and the energy budget
-- must close.  The spin is not yet right: the particles of a seeded disc
-- lie in lattice rows, so its lowest row is a flat of half-width about
-- sqrt(R h / 2) (a quarter of R at 16 cells), and the wall holds the
-- whole flat.  The disc rocks on that flat like a polygon: a frictionless
-- spinning disc resting under gravity swings its spin back and forth
-- (printed below), a sliding disc's friction torque (arm mu R) is smaller
-- than the flat's (arm ~ sqrt(R h / 2)), so it hardly spins up, and a
-- rolling one tips from flat to flat, hops and rolls slow.  Those errors
-- are printed, with their observed order, not asserted (docs/verification.md).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local I = require "mvmpm.incline"

local g, R, T = I.g, I.R, I.T

local function incline(cells, deg, mu, w0)
  return I.run {cells = cells, deg = deg, mu = mu, w0 = w0}
end

local function order(e)
  if e[1] > 0 and e[3] > 0 then return math.log(e[1] / e[3], 2) / 2 end
  return 0 / 0
end

local cells = {8, 16, 32}

V.case "sliding disc (theta 30 deg, mu 0.1): acceleration, energy, spin-up"
local sa, sal = {}, {}
for k, c in ipairs(cells) do
  local r = incline(c, 30, 0.1)
  local a_ref = g * (math.sin(r.th) - 0.1 * math.cos(r.th))
  local al_ref = 2 * 0.1 * g * math.cos(r.th) / R
  sa[k], sal[k] = math.abs(r.a / a_ref - 1), math.abs(r.alpha / al_ref - 1)
  V.near(string.format("sliding a / (g (sin - mu cos)), %d cells", c), r.a / a_ref, 1, 0.01)
  V.near(string.format("energy residual / |potential change|, %d cells", c),
         r.e.residual / math.abs(r.e.potential), 0, 0.01)
  V.above(string.format("friction work dissipated (> 0), %d cells", c), r.e.dissipated, 1e-3)
  V.info(string.format("spin-up alpha / (2 mu g cos / R), %d cells", c), r.alpha / al_ref)
end
V.info("sliding spin-up error, observed order (8 -> 32)", order(sal))

V.case "rolling disc (theta 25 deg, mu 0.5): acceleration and spin-up (printed)"
local ra, ral = {}, {}
for k, c in ipairs(cells) do
  local r = incline(c, 25, 0.5)
  local a_ref = 2 / 3 * g * math.sin(r.th)
  ra[k], ral[k] = math.abs(r.a / a_ref - 1), math.abs(r.alpha / (a_ref / R) - 1)
  V.info(string.format("rolling a / ((2/3) g sin), %d cells", c), r.a / a_ref)
  V.info(string.format("rolling alpha R / a_ref, %d cells", c), r.alpha / (a_ref / R))
  V.info(string.format("largest hop (centre above R), %d cells", c), r.hop)
  -- the tipping from flat to flat loses energy the budget does not book
  -- at 8 cells (17 % of the potential energy released); closed from 16
  local res = r.e.residual / math.abs(r.e.potential)
  if c >= 16 then
    V.near(string.format("energy residual / |potential change|, %d cells", c), res, 0, 0.01)
  else
    V.info(string.format("energy residual / |potential change|, %d cells", c), res)
  end
end
V.info("rolling acceleration error, observed order (8 -> 32)", order(ra))
V.info("rolling spin-up error, observed order (8 -> 32)", order(ral))

V.case "frictionless spinning disc resting under gravity (the lattice flat, printed)"
for _, c in ipairs(cells) do
  local r = incline(c, 0, 0, -0.2)
  -- a round disc keeps omega = 0.2; rocking on the flat swings it
  V.info(string.format("spin range over t = 0..2 (from 0.2), %d cells", c), r.wmax - r.wmin)
end
