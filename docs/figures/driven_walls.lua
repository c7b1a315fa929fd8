-- The report's frictionless bounce (scenarios/cylinder_bounce.lua, the
-- default scheme) in a box of the grid's walls and in a box of driven
-- bodies (walls = "driven"), their faces on node lines and half a cell
-- off them, and the driven box per contact patch: the energy error after
-- three impacts (t = 36) and the first impact's restitution (t = 10)
-- against the cells across the disc, for docs/verification.md (the
-- bounce in a box of driven bodies).  Run by `make figures` (about four
-- minutes).
local mvmpm = require "mvmpm"
local W = dofile("tests/tools/walls.lua") -- the bounce run the wall tests share
local runs = {
  {"grid's walls", {walls = "grid"}},
  {"driven bodies, faces on node lines", {walls = "driven"}},
  {"driven bodies, faces half a cell off", {walls = "driven", offset = 0.3}},
}
local cells = {8, 16, 32}
local energy, rest = {}, {}
for _, r in ipairs(runs) do
  local x, ye, yr = {}, {}, {}
  for _, n in ipairs(cells) do
    local b = W.bounce(mvmpm, n, nil, r[2])
    print(string.format("frictionless bounce, %-38s %2d cells: E/E0 - 1 after three impacts %+.4f, restitution %.4f",
                        r[1], n, b.three, b.rest))
    x[#x + 1], ye[#ye + 1], yr[#yr + 1] = n, math.abs(b.three), b.rest
  end
  energy[#energy + 1] = {x = x, y = ye, label = r[1], style = "both"}
  rest[#rest + 1] = {x = x, y = yr, label = r[1], style = "both"}
end
energy[#energy + 1] = {x = {8, 16, 32}, y = {0.02, 0.01, 0.005}, label = "goal", style = "line"}
mvmpm.plot {file = "docs/figures/driven_walls_energy.png",
            title = "Bounce in a box of driven bodies: |E/E0 - 1| after three impacts",
            xlabel = "cells across the disc", ylabel = "|E/E0 - 1|",
            xlog = true, ylog = true, series = energy}
mvmpm.plot {file = "docs/figures/driven_walls_restitution.png",
            title = "Bounce in a box of driven bodies: restitution of the first impact",
            xlabel = "cells across the disc", ylabel = "restitution", xlog = true, series = rest}
