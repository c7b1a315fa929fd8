-- mvmpm.sim and sim:render at the edges of the doubles: a domain of
-- 1e308 (and wider than the largest double), a cell of 1e-300, a
-- colour range of +-1e308 or of denormals, an extreme aspect
local mvmpm = require "mvmpm"
local el = mvmpm.elastic {K = 1, G = 1, density = 1}
local sims = {
  {domain = {x = {0, 1e308}, y = {0, 1e308}}, cell = 1e307},
  {domain = {x = {-1e308, 1e308}, y = {0, 1}}, cell = 0.5},
  {domain = {x = {0, 1}, y = {0, 1}}, cell = 1e-300},
  {domain = {x = {0, 1e308}, y = {0, 1}}, cell = 1},
  {domain = {x = {0, 1e-300}, y = {0, 1e-300}}, cell = 1e-301},
  {domain = {x = {0, 1e-310}, y = {0, 1e-310}}, cell = 1e-311},
  {domain = {x = {1e300, 1e300 * (1 + 1e-15)}, y = {0, 1}}, cell = 0.25},
  {domain = {x = {0, 1}, y = {0, 200}}, cell = 0.5},
  {domain = {x = {0, 8}, y = {0, 1}}, cell = 1},
}
for k, t in ipairs(sims) do
  local ok, s = pcall(mvmpm.sim, t)
  print("sim", k, ok, ok and "" or s)
  if ok then
    local x, y = t.domain.x, t.domain.y
    pcall(s.body, s, {shape = mvmpm.rect {lo = {x[1], y[1]}, hi = {x[1] + (x[2] - x[1]) / 4,
      y[1] + (y[2] - y[1]) / 4}}, material = el, velocity = {1e308, -1e308}})
    for _, r in ipairs {{-1e308, 1e308}, {-1.7e308, 1.7e308}, {0, 5e-324}, {1e-310, 2e-310},
                        {1, 1 + 2.3e-16}, {1e308, 1.7e308}} do
      print("render", k, pcall(s.render, s, {file = "sim_extremes.png", by = "speed", range = r, width = 200}))
    end
    print("render", k, pcall(s.render, s, {file = "sim_extremes.png", by = "velocity.x", width = 200}))
    print("step", k, pcall(s.step, s, 2))
  end
end
