-- mvmpm.slide: an elastic disc (R = 0.5, K = 400, G = 200, density 1)
-- thrown along a frictional floor (g = 1, periodic along it), or dropped
-- onto it, in every transfer scheme the engine offers.  The friction
-- work it books is checked against mu times the normal force times the
-- slip distance, integrated from the disc's own motion: the slip
-- velocity is vx + omega R at the contact point, the normal force m g
-- once the disc rests on the floor.  Shared by
-- tests/verify/friction_budget.lua and studies/grain_budget.lua.
local mvmpm = require "mvmpm"
local M = {g = 1, R = 0.5, K = 400, H = 0.25}

-- every scheme: shape x transfer (APIC only on GIMP and B-splines, the
-- spin transfer only on B-splines, as the engine allows), and a FLIP/PIC
-- blend
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
  {shape = "bspline2", transfer = "spin"},
}

function M.name(sc)
  return sc.shape .. "/" .. sc.transfer .. (sc.flip and sc.flip < 1 and (" " .. sc.flip) or "")
end

-- The rigid disc's friction work for the seeded particles: thrown at v0
-- without spin, it slides until its contact point stops, keeping its
-- angular momentum about that point, m v0 R = m v R + I w with v = w R,
-- and friction takes what the kinetic energy loses,
--   W = 1/2 m v0^2 I / (I + m R^2)   (1/6 m v0^2 for I = m R^2 / 2),
-- whatever mu, once it rolls.  I from the particles about their mass
-- centre, each with its own square's m a^2 / 6 (a = cell / ppc); in 3-D
-- the same sums give a ball's I about the z axis, its rolling axis when
-- thrown along x on a floor normal to y.
-- (body: the disc's body index, when there are others)
function M.rigid(sim, v0, cell, ppc, body)
  local x, ms, b = sim:particles("position"), sim:particles("mass"), sim:particles("body")
  local m, cx, cy = 0, 0, 0
  local function mine(i) return not body or b[i] == body end
  for i, mi in ipairs(ms) do
    if mine(i) then m, cx, cy = m + mi, cx + mi * x.x[i], cy + mi * x.y[i] end
  end
  cx, cy = cx / m, cy / m
  local a, I = cell / ppc, 0
  for i, mi in ipairs(ms) do
    if mine(i) then I = I + mi * ((x.x[i] - cx) ^ 2 + (x.y[i] - cy) ^ 2 + a * a / 6) end
  end
  return 0.5 * m * v0 * v0 * I / (I + m * M.R ^ 2), m
end

-- o: cells (per diameter), scheme, mu, v0 = {vx, vy}, y0 (centre
-- height above the floor), T, n (samples), wall_contact, run
-- (function(sim, t), default sim:run), slab (true: the floor is a driven
-- slab's top face, friction the contact law's; then normals,
-- normal_window, normal_patch).  Returns the energy table, the
-- mass, the friction work of the model sum F dt . slip, the rigid disc's
-- friction work (M.rigid, for v0 along the floor), and the last state.
function M.run(o)
  local g, R = M.g, M.R
  local sc = o.scheme
  local v0 = o.v0 or {1, 0}
  local y0 = o.y0 or R
  local T, n = o.T or 2, o.n or 80
  -- with a slab, the floor is the top of a driven (rigid, still) body of
  -- thickness H: friction is then the contact law between the two
  local H = o.slab and M.H or 0
  local sim = mvmpm.sim {
    domain = {x = {0, 4}, y = {0, H + y0 + 1.5}}, cell = 2 * R / o.cells, ppc = 2,
    shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
    t_end = T, gravity = {0, -g}, wall_contact = o.wall_contact, body_contact = o.body_contact,
    normals = o.normals, normal_window = o.normal_window, normal_patch = o.normal_patch,
    sides = {left = "periodic", right = "periodic",
             bottom = {"wall", friction = o.slab and 0 or o.mu}, top = "wall"},
    contact = o.slab and {friction = o.mu} or nil,
  }
  if o.slab then
    sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {4, H}},
              material = mvmpm.elastic {K = 1000, G = 500, density = 1}, driven = {0, 0}}
  end
  local disc = sim:body {shape = mvmpm.disk {center = {1, H + y0}, radius = R},
                         material = mvmpm.elastic {K = M.K, G = M.K / 2, density = 1},
                         velocity = v0}
  local rigid, m = M.rigid(sim, v0[1], 2 * R / o.cells, 2, o.slab and 2 or nil)
  local run = o.run or function(x, t) x:run(t) end
  local work, prev = 0, nil
  for k = 1, n do
    run(sim, T * k / n)
    local d = disc:diag()
    local now = {vx = d.vx, slip = d.vx + d.omega * R}
    -- the friction force from the disc's own momentum, on its contact
    -- point's slip velocity: trapezoids, exact while both are linear
    if prev then work = work + m * (prev.vx - now.vx) * 0.5 * (prev.slip + now.slip) end
    prev = now
  end
  return {e = sim:energy(), m = m, model = work, rigid = rigid, d = disc:diag(), sim = sim}
end

return M
