-- Penalty walls against the node rule as a figure for
-- docs/verification.md: the frictionless bounce
-- (scenarios/cylinder_bounce.lua, the default shape) at 8 and 16 cells
-- across the disc, E/E0 - 1 against time over three impacts, the walls
-- acting node by node (the default) or by penalty springs on the
-- particles (wall_contact = "penalty").  Run by `make figures` (about
-- ten seconds).
local mvmpm = require "mvmpm"
local series = {}
for _, wall in ipairs {"node", "penalty"} do
  for _, n in ipairs {8, 16} do
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua", {cells = n, t_end = 36, wall_contact = wall})
    local e0 = sim:energy().total
    local x, y = {0}, {0}
    for k = 1, 144 do
      sim:run(0.25 * k)
      x[#x + 1], y[#y + 1] = sim.t, sim:energy().total / e0 - 1
    end
    print(string.format("frictionless bounce, %-7s %2d cells: E/E0 - 1 at t = 36: %+.4f", wall, n, y[#y]))
    series[#series + 1] = {x = x, y = y, style = "line",
                           label = string.format("%s, %d cells", wall == "node" and "node rule" or "penalty", n)}
  end
end
mvmpm.plot {file = "docs/figures/penalty_bounce.png",
            title = "Frictionless bounce: energy through three impacts",
            xlabel = "t", ylabel = "E/E0 - 1 (springs' energy included)", series = series}
