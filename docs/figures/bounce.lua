-- The bouncing cylinder (the report's Figures 2-4): energy and spin
-- against time, frictionless and with mu = 0.1, and the disc at its
-- first impact coloured by pressure, in the report's scheme (linear
-- hats, MUSL, FLIP), as tests/verify/cylinder_bounce.lua.  Run by `make figures`.
local mvmpm = require "mvmpm"
local dir = arg and arg[1] or "docs/figures"
local series_e, series_w = {}, {}
for _, mu in ipairs {0, 0.1} do
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", {friction = mu, t_end = 36, shape = "linear"})
  local disc = sim:bodies()[1]
  local e0 = sim:energy().total
  local t, e, w, diss = {}, {}, {}, {}
  sim:every {time = 0.25, fn = function(s)
    local en = s:energy()
    t[#t + 1], e[#e + 1], w[#w + 1] = s.t, en.total / e0, disc:omega()
    diss[#diss + 1] = (en.total + en.dissipated) / e0
  end}
  if mu == 0 then
    sim:run(6.5)
    sim:render {file = dir .. "/bounce_impact_pressure.png", by = "pressure", width = 480,
                title = string.format("first impact, t = %.2f: pressure", sim.t)}
  end
  sim:run()
  local tag = mu == 0 and "frictionless" or "mu = 0.1"
  series_e[#series_e + 1] = {x = t, y = e, label = "total / E0, " .. tag, style = "line"}
  if mu > 0 then
    series_e[#series_e + 1] = {x = t, y = diss, label = "(total + friction work) / E0, " .. tag, style = "line"}
  end
  series_w[#series_w + 1] = {x = t, y = w, label = "spin, " .. tag, style = "line"}
end
mvmpm.plot {file = dir .. "/bounce_energy.png", title = "Bouncing cylinder: energy",
            xlabel = "time", ylabel = "energy / initial", series = series_e}
mvmpm.plot {file = dir .. "/bounce_spin.png", title = "Bouncing cylinder: spin",
            xlabel = "time", ylabel = "angular velocity", series = series_w}
print("bounce: pictures in " .. dir)
