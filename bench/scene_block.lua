-- bench/scene_block.lua - the filled 400 x 400-cell block of bench (a)
-- and (e) as a scene, for `mvmpm run bench/scene_block.lua --profile`:
-- linear, MUSL, 640,000 particles carrying a standing shear wave.
local mvmpm = require "mvmpm"
local P = mvmpm.params {steps = 40}
local CELLS, PAD = 400, 2
local h = 1 / CELLS
local sim = mvmpm.sim {
  domain = {x = {-PAD * h, 1 + PAD * h}, y = {-PAD * h, 1 + PAD * h}},
  cell = h, ppc = 2, shape = "linear", update = "musl", flip = 1.0,
  sides = "free", dt = 2.5e-4, t_end = P.steps * 2.5e-4,
}
sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {1, 1}},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
          velocity = function(x, y) return 0.01 * math.sin(2 * math.pi * y), 0 end}
sim:output {dir = "out/scene_block", every = 1e9, csv_every = 1}
return sim
