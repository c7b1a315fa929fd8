-- mvmpm.incline3: a sphere on an incline (3-D), the incline being the
-- floor wall of a box with gravity rotated by theta about z (g = 1),
-- periodic along x (down the slope); frictionless walls at the low and
-- high z sides, a sphere's radius plus a cell or more away.  An elastic
-- sphere (K = 100, G = 50, density 1, R = 0.5: sqrt(g R) / c_L = 0.05)
-- starts at rest touching the floor.  Measured: least-squares slopes of
-- the centre of mass velocity along x and of the spin about -z
-- (clockwise seen from +z = rolling down the slope) over t = T/4 .. T
-- (40 samples; the first quarter is the settling on the floor).
--   rolling (no slip):  a = (5/7) g sin,  alpha = a / R
--   frictionless:       a = g sin,        alpha = 0
local mvmpm = require "mvmpm"
local M = {g = 1, R = 0.5, T = 2}

-- o: cells (per diameter), deg, mu (number or "stick"), and optionally
-- ppc (2), shape, transfer, flip, update, cfl (0.25), wall_contact
-- ("patch"), threads, T, run (function(sim, t)).  Returns {a, alpha, hop,
-- drift (largest |z - z0|), e (sim:energy()), th, particles, cpu}
function M.run(o)
  local g, R, T = M.g, M.R, o.T or M.T
  local th = math.rad(o.deg)
  local h = 2 * R / o.cells
  local W = 2 * R + 2 * h * math.ceil(0.25 / h)   -- across z: a quarter of R each side
  local sim = mvmpm.sim {
    dim = 3, domain = {x = {0, 4 * R}, y = {0, 2 * R + 0.25}, z = {0, W}}, cell = h,
    ppc = o.ppc or 2, shape = o.shape, transfer = o.transfer, flip = o.flip,
    update = o.update, cfl = o.cfl or 0.25, wall_contact = o.wall_contact or "patch",
    threads = o.threads, t_end = T,
    gravity = {g * math.sin(th), -g * math.cos(th), 0},
    sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = o.mu},
             top = "wall", back = "wall", front = "wall"},
  }
  local z0 = W / 2
  local ball = sim:body {shape = mvmpm.ball {center = {R, R, z0}, radius = R},
                         material = mvmpm.elastic {K = 100, G = 50, density = 1}}
  local run = o.run or function(s, t) s:run(t) end
  local n, ts, vs, ws, hop, drift = 40, {}, {}, {}, 0, 0
  local c0 = os.clock()
  for k = 1, n do
    run(sim, T * k / n)
    local d = ball:diag()
    ts[k], vs[k], ws[k] = sim.t, d.vx, -d.omega[3]
    hop = math.max(hop, d.y - R)
    drift = math.max(drift, math.abs(d.z - z0))
  end
  local cpu = os.clock() - c0
  local function slope(y)
    local sx, sy, sxx, sxy, c = 0, 0, 0, 0, 0
    for i = n // 4, n do
      sx, sy, sxx, sxy, c = sx + ts[i], sy + y[i], sxx + ts[i] ^ 2, sxy + ts[i] * y[i], c + 1
    end
    return (c * sxy - sx * sy) / (c * sxx - sx * sx)
  end
  return {a = slope(vs), alpha = slope(ws), hop = hop, drift = drift, e = sim:energy(),
          th = th, particles = #sim:particles("body"), cpu = cpu}
end

return M
