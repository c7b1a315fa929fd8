-- bench/scene_grains.lua - the bed of 1,000 touching elastic grains of
-- bench (c) and (e) as a scene, for `mvmpm run bench/scene_grains.lua
-- --profile`: 50 x 20 discs of radius 4 cells, each its own field,
-- frictionless contact, under uniform compression.  --set shape=bspline2
-- for the default shape's phases, --set update=usavg for USAVG's.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")
local P = mvmpm.params {steps = 40, shape = "linear", update = "musl"}
local sim = B.packing(50, 20, {dt = 2.5e-4, t_end = P.steps * 2.5e-4, shape = P.shape, update = P.update})
sim:output {dir = "out/scene_grains", every = 1e9, csv_every = 1}
return sim
