-- The three frictionless wall rules on the report's bounce
-- (scenarios/cylinder_bounce.lua, the default shape) at 8, 16, 32 and 64
-- cells across the disc, as figures for docs/verification.md: the
-- energy error after three impacts (t = 36) against the issue's goal
-- (2 / 1 / 0.5 % at 8 / 16 / 32 cells), and the first impact's
-- restitution (the disc's x velocity after it over before, at t = 10)
-- against the goal of 0.9 at 16 cells.  Run by `make figures` (about two
-- minutes).
local mvmpm = require "mvmpm"
local W = dofile("tests/tools/walls.lua") -- the bounce run the wall tests share
local rules = {{"node", "node rule (default)"}, {"penalty", "penalty springs"},
               {"spring", "spring walls"}}
local cells = {8, 16, 32, 64}
local energy, rest = {}, {}
for _, r in ipairs(rules) do
  local x, ye, yr = {}, {}, {}
  for _, n in ipairs(cells) do
    local b = W.bounce(mvmpm, n, r[1])
    local de, e = b.three, b.rest
    print(string.format("frictionless bounce, %-7s %2d cells: E/E0 - 1 after three impacts %+.4f, restitution %.4f",
                        r[1], n, de, e))
    x[#x + 1], ye[#ye + 1], yr[#yr + 1] = n, math.abs(de), e
  end
  energy[#energy + 1] = {x = x, y = ye, label = r[2], style = "both"}
  rest[#rest + 1] = {x = x, y = yr, label = r[2], style = "both"}
end
energy[#energy + 1] = {x = {8, 16, 32}, y = {0.02, 0.01, 0.005}, label = "goal", style = "line"}
rest[#rest + 1] = {x = {16}, y = {0.9}, label = "goal at 16 cells", style = "points"}
mvmpm.plot {file = "docs/figures/wall_rules_energy.png",
            title = "Frictionless bounce: |E/E0 - 1| after three impacts",
            xlabel = "cells across the disc", ylabel = "|E/E0 - 1| (springs' energy included)",
            xlog = true, ylog = true, series = energy}
mvmpm.plot {file = "docs/figures/wall_rules_restitution.png",
            title = "Frictionless bounce: restitution of the first impact",
            xlabel = "cells across the disc", ylabel = "restitution", xlog = true, series = rest}
