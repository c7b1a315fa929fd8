-- bench/scene_grains.lua - the bed of 1,000 touching elastic grains of
-- bench (c) and (e) as a scene, for `mvmpm run bench/scene_grains.lua
-- --profile`: 50 x 20 discs of radius 4 cells, each its own field,
-- frictionless contact, under uniform compression.
local mvmpm = require "mvmpm"
local P = mvmpm.params {steps = 40}
local H = 1 / 400
local W, HT, nx, ny = 400 * H, 160 * H, 50, 20
local r = W / (2 * nx)
local sim = mvmpm.sim {
  domain = {x = {0, W}, y = {0, HT}}, cell = H, ppc = 2,
  sides = "free", dt = 2.5e-4, t_end = P.steps * 2.5e-4, contact = {friction = 0},
}
local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
local xc, yc = W / 2, HT / 2
local v = function(x, y) return -0.05 * (x - xc), -0.05 * (y - yc) end
for j = 0, ny - 1 do
  for i = 0, nx - 1 do
    sim:body {shape = mvmpm.disk {center = {(2 * i + 1) * r, (2 * j + 1) * r}, radius = r},
              material = m, velocity = v}
  end
end
sim:output {dir = "out/scene_grains", every = 1e9, csv_every = 1}
return sim
