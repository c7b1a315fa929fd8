-- mvmpm.hotspot: the Frank-Kamenetskii critical curve of a hot disc and
-- the size-temperature picture of the hot spots sim:hotspots finds.
--
-- A disc of radius r (an infinite cylinder) whose surface is held at T,
-- zero-order kinetics in the large-activation (or linearised-exponent)
-- limit, runs away when
--   delta = Q rho Z Ta r^2 exp(-Ta/T) / (k T^2) > delta_c = 2.
-- critical_radius(kin, rho, k, T) is the r at which delta = 2;
-- critical_T(kin, rho, k, r) the T (below Ta/2, where delta rises with T).
-- A hot spot whose temperature lies above the curve at its size is
-- supercritical in this sense (it ignites before conduction cools it);
-- the curve is the steady-state criterion, not a time to ignition.
--
--   local H = require "mvmpm.hotspot"
--   H.plot {file = "spots.png", spots = sim:hotspots {threshold = 600},
--           kinetics = K.hmx, density = 1840, conductivity = 0.452}
local mvmpm = require "mvmpm"
local H = {}

H.delta_disc = 2.0
local GAS_R = 8.314462618

local function Ta_of(kin)
  return kin.Ta or kin.Ea / (kin.R or GAS_R)
end

function H.delta(kin, rho, k, T, r)
  local Ta = Ta_of(kin)
  return kin.Q * rho * kin.Z * Ta * r * r * math.exp(-Ta / T) / (k * T * T)
end

function H.critical_radius(kin, rho, k, T)
  return math.sqrt(H.delta_disc / H.delta(kin, rho, k, T, 1.0))
end

function H.critical_T(kin, rho, k, r)
  local Ta = Ta_of(kin)
  local lo, hi = Ta / 1000, Ta / 2
  if H.delta(kin, rho, k, hi, r) < H.delta_disc then return nil end
  for _ = 1, 200 do
    local mid = 0.5 * (lo + hi)
    if H.delta(kin, rho, k, mid, r) < H.delta_disc then lo = mid else hi = mid end
    if hi - lo <= 1e-13 * hi then break end
  end
  return 0.5 * (lo + hi)
end

-- hot spots (sim:hotspots's list) as points at their equivalent radius
-- sqrt(area / pi) and peak temperature, over the critical curve
function H.plot(o)
  local kin, rho, k = o.kinetics, o.density, o.conductivity
  assert(kin and rho and k, "hotspot.plot: give kinetics, density and conductivity")
  local xs, ys = {}, {}
  local rmin, rmax = math.huge, 0
  for _, h in ipairs(o.spots or {}) do
    local r = math.sqrt(h.area / math.pi)
    xs[#xs + 1], ys[#ys + 1] = r, h.T_max
    rmin, rmax = math.min(rmin, r), math.max(rmax, r)
  end
  if rmax == 0 then rmin, rmax = o.rmin or 1e-6, o.rmax or 1e-3 end
  rmin, rmax = o.rmin or rmin / 3, o.rmax or rmax * 3
  local cx, cy = {}, {}
  for j = 0, 60 do
    local r = rmin * (rmax / rmin) ^ (j / 60)
    local T = H.critical_T(kin, rho, k, r)
    if T then cx[#cx + 1], cy[#cy + 1] = r, T end
  end
  local series = {{x = cx, y = cy, label = "critical (FK, disc, delta_c = 2)",
                   style = "line"}}
  if #xs > 0 then
    series[2] = {x = xs, y = ys, label = "hot spots (peak T)", style = "points"}
  end
  mvmpm.plot {file = o.file, title = o.title or "hot spots against the critical curve",
              xlabel = "equivalent radius sqrt(area/pi)", ylabel = "temperature",
              xlog = true, series = series}
  return #xs
end

return H
