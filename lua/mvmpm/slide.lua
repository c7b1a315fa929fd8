-- mvmpm.slide: an elastic disc (R = 0.5, K = 400, G = 200, density 1)
-- thrown along a frictional floor (g = 1, periodic along it), or dropped
-- onto it, in every transfer scheme the engine offers.  The friction
-- work it books is checked against mu times the normal force times the
-- slip distance, integrated from the disc's own motion: the slip
-- velocity is vx + omega R at the contact point, the normal force m g
-- once the disc rests on the floor.  Shared by
-- tests/verify/friction_budget.lua and studies/grain_budget.lua.
local mvmpm = require "mvmpm"
local M = {g = 1, R = 0.5, K = 400}

-- every scheme: shape x transfer (APIC only on GIMP and B-splines, as
-- the engine allows), and a FLIP/PIC blend
M.schemes = {
  {shape = "linear", transfer = "flip", flip = 1},
  {shape = "linear", transfer = "flip", flip = 0.99},
  {shape = "linear", transfer = "xpic"},
  {shape = "gimp", transfer = "flip", flip = 1},
  {shape = "gimp", transfer = "apic"},
  {shape = "gimp", transfer = "xpic"},
  {shape = "bspline2", transfer = "flip", flip = 1},
  {shape = "bspline2", transfer = "apic"},
  {shape = "bspline2", transfer = "xpic"},
}

function M.name(sc)
  return sc.shape .. "/" .. sc.transfer .. (sc.flip and sc.flip < 1 and (" " .. sc.flip) or "")
end

-- o: cells (per diameter), scheme, mu, v0 = {vx, vy}, y0 (centre
-- height), T, n (samples).  Returns the energy table, the mass, the
-- friction work of the model sum F dt . slip, and the last state.
function M.run(o)
  local g, R = M.g, M.R
  local sc = o.scheme
  local v0 = o.v0 or {1, 0}
  local y0 = o.y0 or R
  local T, n = o.T or 2, o.n or 80
  local sim = mvmpm.sim {
    domain = {x = {0, 4}, y = {0, y0 + 1.5}}, cell = 2 * R / o.cells, ppc = 2,
    shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
    t_end = T, gravity = {0, -g},
    sides = {left = "periodic", right = "periodic",
             bottom = {"wall", friction = o.mu}, top = "wall"},
  }
  local disc = sim:body {shape = mvmpm.disk {center = {1, y0}, radius = R},
                         material = mvmpm.elastic {K = M.K, G = M.K / 2, density = 1},
                         velocity = v0}
  local m = 0
  for _, x in ipairs(sim:particles("mass")) do m = m + x end
  local work, prev = 0, nil
  for k = 1, n do
    sim:run(T * k / n)
    local d = disc:diag()
    local now = {vx = d.vx, slip = d.vx + d.omega * R}
    -- the friction force from the disc's own momentum, on its contact
    -- point's slip velocity: trapezoids, exact while both are linear
    if prev then work = work + m * (prev.vx - now.vx) * 0.5 * (prev.slip + now.slip) end
    prev = now
  end
  return {e = sim:energy(), m = m, model = work, d = disc:diag(), sim = sim}
end

return M
