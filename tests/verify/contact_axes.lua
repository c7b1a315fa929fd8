-- Contact in this build's dimension (contact.c): what the rule must give
-- whatever the dimension, by symmetry, on a block on a flat driven slab
-- under gravity tilted 30 degrees from the slab's normal.
--   1. Sliding along any in-plane axis gives the same motion (3-D: along
--      x and along y, bit for bit: the window, the normals and the
--      friction treat the axes alike).
--   2. Tilted along the diagonal of x and y (3-D), the block slides along
--      the diagonal, and friction (a vector, against the slip) keeps it
--      there.
--   3. Without friction nothing is dissipated; with mu = 0.2 friction
--      dissipates, and the energy budget closes to its step error.
-- The acceleration itself is V.info'd against g (sin - mu cos): on this
-- coarse block (4 cells a side, linear hats) the block's leading edge
-- drags it in 2-D as in 3-D (measured without friction 0.807 of it in
-- 2-D and 0.807 in 3-D, 0.684 along the diagonal; with mu = 0.2, 0.398
-- and 0.394; the convergence of sliding is studied in normals.lua).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local D = mvmpm.dim
local th = math.rad(30)

-- a point with in-plane coordinates u (x and, in 3-D, y alike) and
-- height h (y in 2-D, z in 3-D)
local function P(u, h) if D == 2 then return {u, h} end return {u, u, h} end

-- the block's least-squares acceleration from t = 0.1 to 0.3, the energy
-- dissipated and the budget's residual; gravity tilted toward azimuth
-- phi in the slab's plane (the plane of the first D - 1 axes)
local function slide(phi, mu)
  local L, k = 0.2, 4
  local tx, ty = math.sin(th) * math.cos(phi), math.sin(th) * math.sin(phi)
  local g = D == 2 and {tx, -math.cos(th)} or {tx, ty, -math.cos(th)}
  local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, D == 2 and 0.6 or 1}, z = D == 3 and {0, 0.6} or nil},
    cell = L / k, ppc = 2, dim = D, sides = "free", gravity = g, shape = "linear", t_end = 0.3,
    contact = {friction = mu}}
  local m = mvmpm.elastic {E = 200, nu = 0.3, density = 1}
  sim:body {name = "slab", material = m, driven = P(0, 0),
    shape = mvmpm.box {lo = P(0.02, 0.1), hi = P(0.98, 0.2)}}
  local b = sim:body {name = "block", material = m,
    shape = mvmpm.box {lo = P(0.2, 0.2), hi = P(0.2 + L, 0.2 + L)}}
  local ts, vs = {}, {}
  sim:every {steps = 1, fn = function(s)
    if s.t < 0.1 then return end
    local d = b:diag()
    ts[#ts + 1], vs[#vs + 1] = s.t, {d.vx, d.vy, d.vz}
  end}
  sim:run(0.3)
  local n, st, stt, a = #ts, 0, 0, {}
  for i = 1, n do st, stt = st + ts[i], stt + ts[i] ^ 2 end
  for c = 1, D - 1 do
    local sv, stv = 0, 0
    for i = 1, n do sv, stv = sv + vs[i][c], stv + ts[i] * vs[i][c] end
    a[c] = (n * stv - st * sv) / (n * stt - st * st)
  end
  local e = sim:energy()
  return a, e.dissipated, e.residual / math.max(e.scale, 1e-300)
end

for _, mu in ipairs {0, 0.2} do
  V.case(string.format("block on a flat driven slab, gravity tilted 30 degrees, mu = %g (%d-D)", mu, D))
  local ref = math.sin(th) - mu * math.cos(th)
  local ax, dis, res = slide(0, mu)
  V.info("a along x / g (sin - mu cos)", ax[1] / ref)
  if mu == 0 then V.near("dissipated without friction", dis, 0, 0)
  else V.above("dissipated with friction", dis, 0) end
  -- measured 0.0025 / 0.0016 (mu 0 / 0.2), in 2-D and in 3-D alike
  V.below("|budget residual| / scale", math.abs(res), 0.01)
  if D == 3 then
    local ay = slide(math.pi / 2, mu)
    V.near("tilted along y: a_y as a_x tilted along x", ay[2], ax[1], 1e-12, true)
    V.near("tilted along y: no a_x", ay[1], 0, 1e-9 * math.abs(ax[1]))
    local ad = slide(math.pi / 4, mu)
    V.near("tilted along the diagonal: a_x = a_y", ad[1], ad[2], 1e-12, true)
    V.info("... |a| / g (sin - mu cos)", math.sqrt(ad[1] ^ 2 + ad[2] ^ 2) / ref)
  end
end
