-- mvmpm.piston: a random pack of frictional discs in a walled box,
-- pushed by a driven body (a piston) at constant speed; shared by
-- tests/verify/piston_pack.lua and studies/piston_pack.lua.
--
-- The box is [0, 8] x [0, 4], walled on every side (friction mu); the
-- piston, a rigid rectangle [6.1, 7.1] x [0.05, 3.95], moves in -x at v
-- from t = 0.  The discs (radii 0.25-0.45, elastic K = 100, G = 50,
-- density 1, no gravity) are placed by random sequential addition in
-- [0, 6] x [0, 4] with a gap of 0.05 from each other and the walls, from
-- a seeded generator of its own (a 31-bit linear congruential one), so
-- a seed gives one pack on any machine.  The piston meets the pack
-- after a free run and compresses it to T (by then it has moved v T).
-- Energy in: the piston's work (sim:energy().boundary_work; the walls
-- are still and do none).
local mvmpm = require "mvmpm"
local M = {W = 8, H = 4, x1 = 6, rmin = 0.25, rmax = 0.45, gap = 0.05}

-- the pack: n discs {x, y, r}, or an error if the box is too full
function M.pack(n, seed)
  local s = seed or 1
  local function rnd()
    s = (s * 1103515245 + 12345) % 2147483648
    return s / 2147483648
  end
  local d = {}
  for _ = 1, n do
    local placed = false
    for _ = 1, 20000 do
      local r = M.rmin + (M.rmax - M.rmin) * rnd()
      local x = r + M.gap + (M.x1 - 2 * (r + M.gap)) * rnd()
      local y = r + M.gap + (M.H - 2 * (r + M.gap)) * rnd()
      local ok = true
      for _, o in ipairs(d) do
        local dx, dy = x - o.x, y - o.y
        if dx * dx + dy * dy < (r + o.r + M.gap) ^ 2 then ok = false; break end
      end
      if ok then d[#d + 1] = {x = x, y = y, r = r}; placed = true; break end
    end
    if not placed then error(string.format("piston pack: no room for disc %d of %d", #d + 1, n), 2) end
  end
  return d
end

-- o: cells (per smallest diameter, 2 rmin), scheme {shape, transfer,
-- flip}, mu, n (discs, 30), seed, v (piston speed, 0.5), T (4),
-- body_contact, wall_contact, normals, normal_window, normal_patch (the sim's);
-- samples, sample: sample(energy, t) is called at T k / samples.
-- Returns the energy table, the piston's work, the CPU time.
function M.run(o)
  local sc = o.scheme
  local mu, v, T = o.mu or 0.3, o.v or 0.5, o.T or 4
  local wall = {"wall", friction = mu}
  local sim = mvmpm.sim {
    domain = {x = {0, M.W}, y = {0, M.H}}, cell = 2 * M.rmin / o.cells, ppc = 2,
    shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
    t_end = T, sides = {left = wall, right = wall, bottom = wall, top = wall},
    contact = {friction = mu}, body_contact = o.body_contact, wall_contact = o.wall_contact,
    normals = o.normals, normal_window = o.normal_window, normal_patch = o.normal_patch,
  }
  local m = mvmpm.elastic {K = 100, G = 50, density = 1}
  for _, g in ipairs(M.pack(o.n or 30, o.seed or 1)) do
    sim:body {shape = mvmpm.disk {center = {g.x, g.y}, radius = g.r}, material = m}
  end
  sim:body {name = "piston", shape = mvmpm.rect {lo = {M.x1 + 0.1, 0.05}, hi = {M.x1 + 1.1, M.H - 0.05}},
            material = m, driven = {-v, 0}, velocity = {-v, 0}}
  local t0 = os.clock()
  local n = o.samples or 1
  for k = 1, n do
    sim:run(T * k / n)
    if o.sample then o.sample(sim:energy(), sim.t) end
  end
  local e = sim:energy()
  return e, e.boundary_work, os.clock() - t0
end

return M
