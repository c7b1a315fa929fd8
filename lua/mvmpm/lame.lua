-- mvmpm.lame: the plane-strain Lame solution of the concentric cylinders
-- (an inner disc of radius a with eigenstrain bonded in an annulus to b;
-- K the 3-D bulk modulus, eps_zz = 0, free in-plane eigenstrain
-- e = (1 + nu) alpha dT), and a particle profile measured against it.
--   s = -e / [1/(2K') + (a^2/(2K') + b^2/(2G)) / (b^2 - a^2)],  K' = K + G/3
--   disc:    sigma_rr = sigma_tt = s
--   annulus: sigma_rr = s a^2/(b^2 - a^2) (b^2/r^2 - 1)
--            sigma_tt = -s a^2/(b^2 - a^2) (b^2/r^2 + 1)
local M = {}

-- s per unit |alpha dT| (0.675 for K = 1, G = 0.5)
function M.unit(K, G, a, b)
  local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
  local Kp = K + G / 3
  return (1 + nu) / (1 / (2 * Kp) + (a * a / (2 * Kp) + b * b / (2 * G)) / (b * b - a * a))
end

-- sigma_rr, sigma_tt at radius r for the interface stress s
function M.stress(s, a, b, r)
  if r < a then return s, s end
  local f = s * a * a / (b * b - a * a)
  return f * (b * b / (r * r) - 1), -f * (b * b / (r * r) + 1)
end

-- the worst error over s of the particles' polar stresses, averaged in
-- radial bins of width h about c, against the solution: away from the
-- interface's and the rim's own cells (where two materials, or material
-- and void, share a cell), and in those cells
function M.profile(sim, c, s, a, b, h)
  local x, st = sim:particles("position"), sim:particles("stress")
  local bins = {}
  for i = 1, #x.x do
    local dx, dy = x.x[i] - c[1], x.y[i] - c[2]
    local r = math.sqrt(dx * dx + dy * dy)
    local co, sn = dx / r, dy / r
    local srr = co * co * st.xx[i] + sn * sn * st.yy[i] + 2 * co * sn * st.xy[i]
    local stt = sn * sn * st.xx[i] + co * co * st.yy[i] - 2 * co * sn * st.xy[i]
    local k = math.floor(r / h) + 1
    local bin = bins[k] or {n = 0, rr = 0, tt = 0, r = 0}
    bin.n, bin.rr, bin.tt, bin.r = bin.n + 1, bin.rr + srr, bin.tt + stt, bin.r + r
    bins[k] = bin
  end
  local worst, edge = 0, 0
  for _, bin in pairs(bins) do
    local r = bin.r / bin.n
    local rr, tt = M.stress(s, a, b, r)
    local err = math.max(math.abs(bin.rr / bin.n - rr), math.abs(bin.tt / bin.n - tt)) / s
    if math.abs(r - a) > 1.5 * h and r < b - 1.5 * h and r > h then worst = math.max(worst, err)
    else edge = math.max(edge, err) end
  end
  return worst, edge
end

-- The concentric spheres: an inner sphere of radius a (bulk K1, free
-- strain e1 = alpha1 dT, isotropic) bonded in a shell to b (K2, G2, free
-- strain e2 = alpha2 dT).  The sphere under a uniform radial stress s is
-- strained s / (3 K1) in every direction; the shell under sigma_rr(a) = s,
-- sigma_rr(b) = 0 has u = A r + B / r^2 with 3 K2 A = -s a^3 / (b^3 - a^3),
-- 4 G2 B = -s a^3 b^3 / (b^3 - a^3).  Equal radial displacements at r = a:
--   s = -(e1 - e2) / [1/(3 K1) + (a^3/(3 K2) + b^3/(4 G2)) / (b^3 - a^3)]
--   sphere: sigma_rr = sigma_tt = s
--   shell:  sigma_rr = s a^3/(b^3 - a^3) (b^3/r^3 - 1)
--           sigma_tt = -s a^3/(b^3 - a^3) (b^3/(2 r^3) + 1)
-- (cooling, e1 < e2: s > 0, the interface in tension)
local sphere = {}
M.sphere = sphere

-- s for the free strains e1 (inside) and e2 (shell)
function sphere.interface(K1, K2, G2, a, b, e1, e2)
  local a3, b3 = a ^ 3, b ^ 3
  return -(e1 - e2) / (1 / (3 * K1) + (a3 / (3 * K2) + b3 / (4 * G2)) / (b3 - a3))
end

-- sigma_rr, sigma_tt at radius r for the interface stress s
function sphere.stress(s, a, b, r)
  if r < a then return s, s end
  local f = s * a ^ 3 / (b ^ 3 - a ^ 3)
  local q = b ^ 3 / r ^ 3
  return f * (q - 1), -f * (0.5 * q + 1)
end

-- the particles' radial and hoop stresses about c (3-D): lists r, rr, tt
-- (tt the mean of the two hoop directions, (tr - rr) / 2)
function sphere.polar(sim, c)
  local x, st = sim:particles("position"), sim:particles("stress")
  local r, rr, tt = {}, {}, {}
  for i = 1, #x.x do
    local d = {x.x[i] - c[1], x.y[i] - c[2], x.z[i] - c[3]}
    local l = math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
    local n = {d[1] / l, d[2] / l, d[3] / l}
    local s = st.xx[i] * n[1] ^ 2 + st.yy[i] * n[2] ^ 2 + st.zz[i] * n[3] ^ 2
            + 2 * (st.xy[i] * n[1] * n[2] + st.yz[i] * n[2] * n[3] + st.xz[i] * n[1] * n[3])
    r[i], rr[i], tt[i] = l, s, 0.5 * (st.xx[i] + st.yy[i] + st.zz[i] - s)
  end
  return r, rr, tt
end

-- The concentric spheres scene (3-D): the sphere (alpha = 1) and the
-- shell (alpha = 0), K = 1, G = 0.5, density 1, a = 0.2, b = 0.4, on one
-- velocity field (a perfectly bonded interface), the whole sphere in a
-- box with free sides, cooled by dT = -0.004 in one step and brought to
-- rest by kinetic damping (sim:settle, called `settles` times: its end
-- test watches the centres of mass, which do not move here, so one call
-- can end with a breathing mode left; the second takes it out).  The
-- octant with walls on its three cut planes would cost an eighth, but a
-- wall is one-sided and the net normal force across a plane of symmetry
-- is zero: the sphere pulls on it where the shell pushes, and the cut
-- opens.
-- o: cells (across the outer radius b), ppc (2), shape, transfer,
-- update, threads, settles (2), run (function(sim) that settles).
-- Returns {inner, band, hoop, shell, s, particles, cpu}: the sphere's mean
-- radial stress (particles a cell and a half or more inside the
-- interface) over s, the mean of sigma_rr - (Lame's sigma_rr(r) - s) over
-- the particles within a cell of the interface, over s (the interface
-- stress read across the interface's own cells), the sphere's mean hoop
-- stress over s, and the worst radial-bin mean of sigma_rr in the shell
-- (bins of h, away from the interface and the rim by 1.5 h) off Lame, over s
function sphere.run(o)
  local mvmpm = require "mvmpm"
  local K, G, a, b, dT = 1, 0.5, 0.2, 0.4, -0.004
  local h = b / o.cells
  local L = 2 * b + 2 * h
  local c = L / 2
  local sim = mvmpm.sim {dim = 3, domain = {x = {0, L}, y = {0, L}, z = {0, L}}, cell = h,
    ppc = o.ppc or 2, shape = o.shape, transfer = o.transfer, update = o.update,
    threads = o.threads, t_end = 1e9, sides = "free"}
  local core = mvmpm.elastic {K = K, G = G, density = 1, alpha = 1, name = "core"}
  local shell = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0, name = "shell"}
  sim:body {shape = mvmpm.ball {center = {c, c, c}, radius = a}, material = core, field = "one"}
  sim:body {shape = mvmpm.shell {center = {c, c, c}, inner = a, outer = b}, material = shell,
            field = "one"}
  sim:temperature(dT)
  local s = sphere.interface(K, K, G, a, b, dT, 0)
  local c0 = os.clock()
  if o.run then o.run(sim)
  else for _ = 1, o.settles or 2 do sim:settle {t_max = 5} end end
  local cpu = os.clock() - c0
  local r, rr, tt = sphere.polar(sim, {c, c, c})
  local n1, m1, mt, n2, m2, bins = 0, 0, 0, 0, 0, {}
  for i = 1, #r do
    if r[i] < a - 1.5 * h then n1, m1, mt = n1 + 1, m1 + rr[i], mt + tt[i] end
    if math.abs(r[i] - a) < h then n2, m2 = n2 + 1, m2 + rr[i] - sphere.stress(s, a, b, r[i]) + s end
    if r[i] > a + 1.5 * h and r[i] < b - 1.5 * h then
      local k = math.floor(r[i] / h)
      local bin = bins[k] or {0, 0, 0}
      bin[1], bin[2], bin[3] = bin[1] + 1, bin[2] + rr[i], bin[3] + r[i]
      bins[k] = bin
    end
  end
  local worst = 0
  for _, bin in pairs(bins) do
    local ref = sphere.stress(s, a, b, bin[3] / bin[1])
    worst = math.max(worst, math.abs(bin[2] / bin[1] - ref) / s)
  end
  return {inner = m1 / n1 / s, band = m2 / n2 / s, hoop = mt / n1 / s, shell = worst, s = s,
          particles = #r, cpu = cpu, e = sim:energy()}
end

return M
