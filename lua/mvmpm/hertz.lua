-- mvmpm.hertz: an elastic hemisphere (radius R = 0.5, curved side down,
-- flat face up and free) pressed on a rigid frictionless flat, the floor
-- wall, by its own weight, brought to rest by kinetic damping
-- (sim:settle).  Hertz for a sphere on a rigid flat:
--   a^3 = 3 F R / (4 E*),  E* = E / (1 - nu^2),  F = 4/3 E* sqrt(R) delta^(3/2)
--   p(rho) = p0 sqrt(1 - rho^2 / a^2),  p0 = 3 F / (2 pi a^2)
-- The load is the weight F = m g; the body's own compression under the
-- weight away from the contact enters only through R's far field (a
-- correction of order a / R).  The contact radius a is read from the
-- particles in contact, those whose centre lies within 3/4 of a particle
-- spacing hp = h / ppc of the wall (a touching particle's centre is half
-- a spacing up, less its compression; the next layer starts a spacing
-- and a half up), in two ways:
--   a_m: from the second moment of the pressure: for Hertz's
--        distribution <rho^2>_p = (2/5) a^2, so a_m = sqrt(5/2 <rho^2>_p)
--        (a mean over the patch, not tied to the outermost particle)
--   a_e: the edge: the radius of the outermost particle in contact plus
--        half a particle spacing (its cube's outer face), rounded to the
--        lattice: an honest bound to half a spacing
local mvmpm = require "mvmpm"
local M = {R = 0.5, K = 100, G = 50}

-- Hertz's gap between the sphere and the flat outside the contact (r >= a):
--   g(r) = r^2/(2R) - a^2/R + [(2a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)] / (pi R)
-- and the radius where it reaches q (what a count of the particles within
-- q of the wall reads on the exact surface), by bisection
function M.gap(a, r)
  local R = M.R
  if r <= a then return 0 end
  return r * r / (2 * R) - a * a / R
         + ((2 * a * a - r * r) * math.asin(a / r) + a * math.sqrt(r * r - a * a)) / (math.pi * R)
end

function M.reach(a, q)
  local lo, hi = a, 2 * a
  for _ = 1, 60 do
    local mid = 0.5 * (lo + hi)
    if M.gap(a, mid) < q then lo = mid else hi = mid end
  end
  return 0.5 * (lo + hi)
end

function M.estar()
  local K, G = M.K, M.G
  local E = 9 * K * G / (3 * K + G)
  local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
  return E / (1 - nu * nu), E, nu
end

-- o: cells (per diameter), ar (a / R aimed at: sets g), ppc (2), shape,
-- transfer, update, cfl, threads, tol (settle's), run (function(sim)
-- that settles; default sim:settle).  Returns {F, W (weight), a_m, a_e,
-- a_h (Hertz's a for the weight), a_q (the radius where Hertz's gap is a
-- quarter spacing: the contact count's reading of the exact surface), delta (the top face's drop beyond
-- the free compression, not used), n (contact particles), ok, t, cpu, particles}
function M.run(o)
  local R = M.R
  local Es = M.estar()
  local h = 2 * R / o.cells
  local ppc = o.ppc or 2
  -- (a/R)^3 = 3 m g R / (4 E* R^3), m = (2/3) pi R^3 (density 1)
  local g = (o.ar or 0.35) ^ 3 * 4 * Es / (2 * math.pi * R)
  local m = 2 / 3 * math.pi * R ^ 3
  local L = 2 * R + 2 * h * math.ceil(0.125 / h)
  local c = L / 2
  local sim = mvmpm.sim {
    dim = 3, domain = {x = {0, L}, y = {0, R + 2 * h}, z = {0, L}}, cell = h, ppc = ppc,
    shape = o.shape, transfer = o.transfer, update = o.update, cfl = o.cfl or 0.25,
    threads = o.threads, t_end = 1e9, gravity = {0, -g, 0},
    sides = {bottom = "wall", top = "free", left = "free", right = "free", back = "free",
             front = "free"},
  }
  local body = sim:body {
    shape = mvmpm.region {inside = function(x, y, z)
      return (x - c) ^ 2 + (y - R) ^ 2 + (z - c) ^ 2 < R * R and y < R
    end, lo = {c - R, 0, c - R}, hi = {c + R, R, c + R}},
    material = mvmpm.elastic {K = M.K, G = M.G, density = 1}, volume = "cell"}
  local c0 = os.clock()
  local ok, t = true, 0
  if o.run then o.run(sim) else ok, t = sim:settle {tol = o.tol, t_max = o.t_max or 20} end
  local cpu = os.clock() - c0
  local mass = body:diag().mass
  local _, Fy = sim:wall_force("bottom")
  local x, st = sim:particles("position"), sim:particles("stress")
  local hp = h / ppc
  local s0, s2, n, re = 0, 0, 0, 0
  for i = 1, #x.x do
    if x.y[i] < 0.75 * hp then
      local p = -st.yy[i]
      local rho = math.sqrt((x.x[i] - c) ^ 2 + (x.z[i] - c) ^ 2)
      if p > 0 then s0, s2, n = s0 + p, s2 + p * rho * rho, n + 1 end
      re = math.max(re, rho)
    end
  end
  -- the floor's normal force node by node (sim:wall_nodes): its moments
  local wn = sim:wall_nodes("bottom")
  local f0, f2, f4 = 0, 0, 0
  for i = 1, #wn.force do
    local r2 = (wn.x[i] - c) ^ 2 + (wn.z[i] - c) ^ 2
    f0, f2, f4 = f0 + wn.force[i], f2 + wn.force[i] * r2, f4 + wn.force[i] * r2 * r2
  end
  local W = mass * g
  local a_h = (3 * W * R / (4 * Es)) ^ (1 / 3)
  return {F = Fy, W = W, a_m = math.sqrt(2.5 * s2 / s0), a_e = re + 0.5 * hp, a_h = a_h,
          a_w = math.sqrt(2.5 * f2 / f0), a_w4 = (35 / 8 * f4 / f0) ^ 0.25, F_w = f0,
          nw = #wn.force,
          a_q = M.reach(a_h, 0.25 * hp), n = n, ok = ok, t = t, cpu = cpu,
          particles = #x.x, h = h, mass = mass, m_exact = m}
end

return M
