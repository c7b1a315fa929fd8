-- mvmpm.bounce3: the 3-D sphere bounce (scenarios/sphere_bounce.lua: a
-- unit-diameter elastic sphere at (0.1, 0.1, 0.1) meeting the right,
-- front and top walls at t = 2, 6, 10), run to t = 14 with its measures.
-- Used by tests/verify/d3_bounce.lua and d3_bounce_usavg.lua.
local mvmpm = require "mvmpm"
local M = {}

local function norm3(w) return math.sqrt(w[1]^2 + w[2]^2 + w[3]^2) end

-- run(cells, o): o's keys go to the scene as --set would (shape, update,
-- cfl, ...).  Returns {energy (E(14)/E0 - 1), impact and residual (the
-- booked impact loss and the budget's residual, per E0), p0 and r[t] for
-- t = 5 (after the right wall, x), 9.5 (after the front, z, before the
-- top, y, from t = 10) and 14 (the momenta per mass), spin (the largest
-- |omega| R / |v| seen), cpu, sim}
function M.run(cells, o)
  local p = {cells = cells}
  for k, v in pairs(o or {}) do p[k] = v end
  local c0 = os.clock()
  local sim = mvmpm.load("scenarios/sphere_bounce.lua", p)
  local b = sim:bodies()[1]
  local e0 = sim:energy()
  local m, r = b:mass(), {spin = 0}
  for _, t in ipairs {5, 9.5, 14} do
    sim:run(t)
    local e, d = sim:energy(), b:diag()
    r[t] = {px = e.px / m, py = e.py / m, pz = e.pz / m}
    r.spin = math.max(r.spin, norm3(d.omega) * 0.5 / (0.1 * math.sqrt(3)))
  end
  local e = sim:energy()
  r.p0 = {e0.px / m, e0.py / m, e0.pz / m}
  r.energy = e.total / e0.total - 1
  r.impact = e.impact / e0.total
  r.residual = e.residual / e0.total
  r.cpu = os.clock() - c0
  r.sim = sim
  return r
end

return M
