-- The default shape's reason as a figure for docs/accuracy.md: the
-- frictionless bounce (scenarios/cylinder_bounce.lua, three impacts,
-- t = 36) refined from 8 to 64 cells across the disc, |E/E0 - 1| for
-- linear hats and for quadratic B-splines (the default), MUSL, FLIP.
-- Run by `make figures` (about two minutes).
local mvmpm = require "mvmpm"
local series = {}
for _, shape in ipairs {"linear", "bspline2"} do
  local x, y = {}, {}
  for _, n in ipairs {8, 16, 32, 48, 64} do
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua", {cells = n, t_end = 36, shape = shape})
    local e0 = sim:energy().total
    sim:run(36)
    local d = sim:energy().total / e0 - 1
    x[#x + 1], y[#y + 1] = n, math.abs(d)
    print(string.format("frictionless bounce, %-8s %2d cells: E/E0 - 1 %+.4f", shape, n, d))
  end
  series[#series + 1] = {x = x, y = y, style = "both",
                         label = shape == "linear" and "linear hats" or "B-splines (default)"}
end
series[#series + 1] = {x = {8, 16, 32}, y = {0.02, 0.01, 0.005}, style = "points", label = "goal"}
mvmpm.plot {file = "docs/figures/default_shape.png", xlog = true, ylog = true,
            title = "Frictionless bounce refined: energy error after three impacts",
            xlabel = "cells across the disc", ylabel = "|E/E0 - 1|", series = series}
