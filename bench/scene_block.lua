-- bench/scene_block.lua - the filled 400 x 400-cell block of bench (a)
-- and (e) as a scene, for `mvmpm run bench/scene_block.lua --profile`:
-- linear, MUSL, 640,000 particles carrying a standing shear wave.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")
local P = mvmpm.params {steps = 40}
local sim = B.block {dt = 2.5e-4, t_end = P.steps * 2.5e-4}
sim:output {dir = "out/scene_block", every = 1e9, csv_every = 1}
return sim
