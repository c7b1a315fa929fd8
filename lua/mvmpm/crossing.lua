-- mvmpm.crossing: the free elastic bar whose particles cross cell faces,
-- against its free-free modes; shared by tests/verify/bar_crossing.lua
-- and docs/figures/bar_crossing.lua (the case and its numbers are
-- described in the test).
local mvmpm = require "mvmpm"

local Mp = 1 + 4 * 0.5 / 3  -- the p-wave (uniaxial strain) modulus
local c = math.sqrt(Mp)
local L, x0, a = 2, 0.5, 0.02

local function exact(x, t)
  local s, v = x - x0, 0
  for n = 1, 399, 2 do
    v = v - 4 * a * L / (n * n * math.pi ^ 2) * math.cos(n * math.pi * s / L) * math.cos(n * math.pi * c * t / L)
  end
  return v
end

local M = {}

-- run(cells per unit length, shape): {err (the largest velocity error of
-- t = 2, 4, 6, 8, L2 over the initial velocity's), dE (E(8)/E0 - 1)}
function M.run(cells, shape)
  local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 0.25}}, cell = 1 / cells, t_end = 8,
    shape = shape, sides = {left = "free", right = "free", bottom = "periodic", top = "periodic"}}
  local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  sim:body {shape = mvmpm.rect {lo = {0.5, 0}, hi = {2.5, 0.25}}, material = m,
            velocity = function(x) return a * (x - 1.5), 0 end}
  local e0 = sim:energy().total
  -- the series is in the material coordinate: each particle's start, by
  -- id (the sort by cell reorders them)
  local X, v0 = {}, 0
  do
    local x, id = sim:particles("position").x, sim:particles("id")
    for i = 1, #x do X[id[i]] = x[i] end
  end
  for _, vx in ipairs(sim:particles("velocity").x) do v0 = v0 + vx * vx end
  local worst = 0
  for _, t in ipairs {2, 4, 6, 8} do
    sim:run(t)
    local v, id, num = sim:particles("velocity").x, sim:particles("id"), 0
    for i = 1, #v do num = num + (v[i] - exact(X[id[i]], t)) ^ 2 end
    worst = math.max(worst, math.sqrt(num / v0))
  end
  return {err = worst, dE = sim:energy().total / e0 - 1}
end

return M
