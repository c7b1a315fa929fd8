-- tests/verify/scenes/threads_grains.lua - a scene for threads.lua (not a
-- case itself): a bed of frictional elastic grains, each its own field,
-- under gravity in a walled box, pressed by a driven plate from above, so
-- that contact books friction work, boundary work and the plate's force
-- at many shared nodes at once.
local mvmpm = require "mvmpm"
local P = mvmpm.params {cells = 80, friction = 0.3}
local H = 1 / P.cells
local nx, ny, r = 6, 3, 1 / 14
local sim = mvmpm.sim {
  domain = {x = {0, 1}, y = {0, 1}}, cell = H, ppc = 2, t_end = 1,
  gravity = {0, -1}, sides = "wall", contact = {friction = P.friction},
}
local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
for j = 0, ny - 1 do
  for i = 0, nx - 1 do
    local x = 0.08 + (2 * i + 1) * r + (j % 2) * 0.5 * r
    sim:body {shape = mvmpm.disk {center = {x, (2 * j + 1) * r + 0.01}, radius = r * 0.98},
              material = m, velocity = {0.05 * (i - 2.5), 0}}
  end
end
local top = 2 * ny * r + 0.01
sim:body {name = "plate", shape = mvmpm.rect {lo = {0.1, top + 0.5 * H}, hi = {0.9, top + 0.08}},
          material = m, driven = function(t) return 0.02, -0.1 end}
return sim
