-- The report's Figure 5 from scenarios/concentric_debond.lua: bond
-- strength on the particles (top) and pressure (bottom), before the
-- interface lets go and after.  Run by `make figures`.
local mvmpm = require "mvmpm"
local dir = arg and arg[1] or "docs/figures"
local sim = mvmpm.load("scenarios/concentric_debond.lua", {t_end = 20})
local first
sim:every {steps = 1, fn = function(s)
  if not first and s:energy().debonded > 0 then first = s.t end
end}
local function pictures(tag)
  local note = string.format("t = %.2f, dT = %.4f", sim.t, -4e-4 * sim.t)
  sim:render {file = dir .. "/fig5_bond_" .. tag .. ".png", by = "bond", width = 480,
              title = "bond strength, " .. tag .. " (" .. note .. ")", range = {0, 0.005}}
  -- a fixed scale, twice the Lame interface stress at the onset: the
  -- cells where disc and annulus share a cell carry mixed stresses that
  -- would otherwise set the scale
  sim:render {file = dir .. "/fig5_pressure_" .. tag .. ".png", by = "pressure", width = 480,
              title = "pressure, " .. tag .. " (" .. note .. ")", range = {-0.01, 0.01}}
end
sim:run(16)
pictures("before")
while not first do sim:step(1) end
sim:run(first + 0.1)
pictures("during")
sim:run(first + 1.0)
pictures("after")
print(string.format("fig5: debonding began at t = %.3f; pictures in %s", first, dir))
