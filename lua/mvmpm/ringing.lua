-- mvmpm.ringing: an elastic disc that vibrates while it crosses the grid.
-- A free disc (radius 0.5, K = 1, G = 0.5, density 1, so the P-wave
-- speed is 1.29) moves at (vt, vt) and carries, on top of that, a
-- standing pattern of velocity of wavelength lambda,
--   v' = amp (sin(k x) cos(0.7 k y), cos(k x + 0.3)),   k = 2 pi / lambda,
-- as the ringing an impact leaves.  Nothing acts on it, so its energy
-- must stay what it was.  The error is the change of the total energy
-- over the energy of the vibration (the total less the translation's,
-- 1/2 M |v_mean|^2), so that it does not shrink with the speed.
--
-- M.run(o, advance): o = {cells (across a unit length), shape, update,
-- transfer, flip, cfl, ppc, vt (0.1), lambda (0.25), amp (0.01), t_end
-- (10), threads, mass_cutoff}; advance(sim, t) steps it to t (default
-- sim:run, a study passes its clock's).  Returns {err (signed), mom
-- (|momentum change| over M |v_mean|, or over M amp at rest), cpu,
-- steps, particles, sim}.
local mvmpm = require "mvmpm"

local M = {}

function M.build(o)
  local vt, lam, amp = o.vt or 0.1, o.lambda or 0.25, o.amp or 0.01
  local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 3}}, cell = 1 / o.cells,
    ppc = o.ppc or 2, cfl = o.cfl or 0.25, t_end = o.t_end or 10, sides = "free",
    shape = o.shape, update = o.update, transfer = o.transfer, flip = o.flip,
    threads = o.threads, mass_cutoff = o.mass_cutoff}
  local k = 2 * math.pi / lam
  local disc = sim:body {name = "disc", material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
    shape = mvmpm.disk {center = {1.0, 1.0}, radius = 0.5},
    velocity = function(x, y)
      return vt + amp * math.sin(k * x) * math.cos(0.7 * k * y), vt + amp * math.cos(k * x + 0.3)
    end}
  return sim, disc
end

function M.run(o, advance)
  local sim, disc = M.build(o)
  local d0, e0 = disc:diag(), sim:energy()
  local trans = 0.5 * d0.mass * (d0.vx * d0.vx + d0.vy * d0.vy)
  local vib = e0.total - trans
  local c0 = os.clock()
  if advance then advance(sim, o.t_end or 10) else sim:run() end
  local cpu = os.clock() - c0
  local e = sim:energy()
  local p0 = math.max(d0.mass * math.sqrt(d0.vx * d0.vx + d0.vy * d0.vy), d0.mass * (o.amp or 0.01))
  local mom = math.sqrt((e.px - e0.px) ^ 2 + (e.py - e0.py) ^ 2) / p0
  return {err = (e.total - e0.total) / vib, mom = mom, cpu = cpu, steps = sim.steps,
          particles = sim.n, sim = sim}
end

return M
