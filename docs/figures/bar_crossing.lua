-- The free bar crossing cells (tests/verify/bar_crossing.lua) as a
-- figure for docs/verification.md: the velocity error against the modes
-- at 16 ... 128 cells per unit length, linear hats, GIMP and B-splines
-- (the default), log-log.  Run by `make figures` (about five minutes).
local mvmpm = require "mvmpm"
local B = require "mvmpm.crossing"
local series = {}
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  local x, y = {}, {}
  for _, n in ipairs {16, 32, 48, 64, 96, 128} do
    local r = B.run(n, shape)
    x[#x + 1], y[#y + 1] = n, r.err
    print(string.format("bar crossing cells, %-6s %3d cells: velocity error %.4f, E/E0 - 1 %+.4f", shape, n, r.err, r.dE))
  end
  series[#series + 1] = {x = x, y = y, style = "both", label = shape}
end
mvmpm.plot {file = "docs/figures/bar_crossing.png", xlog = true, ylog = true,
            title = "Free bar crossing cells: velocity against the modes", yrange = {0.005, 1},
            xlabel = "cells per unit length", ylabel = "L2 velocity error / L2 v0", series = series}
