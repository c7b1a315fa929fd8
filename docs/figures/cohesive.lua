-- The cohesive law's figures (docs/verification.md, the cohesive law).
-- Run by `make figures` (about a minute).
--   cohesive_pull.png   two blocks pulled apart through a cohesive
--                       interface (lua/mvmpm/pull.lua): the grip's
--                       traction (means over one time unit) against each
--                       grip's travel, linear hats at 12, 24, 48 cells,
--                       B-splines at 24, beside the quasi-static curve;
--                       the brittle bond (bond_energy = 0) for contrast
local mvmpm = require "mvmpm"
local P = require "mvmpm.pull"
local dir = arg and arg[1] or "docs/figures"

local series = {}
local function add(o, label)
  local r = P.run(o)
  local x, y = {}, {}
  for i = 1, #r.us do x[i], y[i] = r.us[i] / (P.sigma / P.M), r.ts[i] / P.sigma end
  series[#series + 1] = {x = x, y = y, style = "both", label = label}
  print(string.format("cohesive pull %-28s work / (G_c A) %.4f, first cut / sigma L/M %.4f",
                      label, r.w, r.onset))
end
add({cells = 12, shape = "linear"}, "linear, 12 cells")
add({cells = 24, shape = "linear"}, "linear, 24 cells")
add({cells = 48, shape = "linear"}, "linear, 48 cells")
add({cells = 24, shape = "bspline2"}, "B-spline, 24 cells")
add({cells = 24, shape = "linear", energy = 0}, "brittle (energy 0), 24 cells")
local x, y = {}, {}
for i = 0, 80 do
  local u = 0.6 * P.sigma / P.M + i * (1.4 * P.sigma / P.M) / 80
  x[#x + 1], y[#y + 1] = u / (P.sigma / P.M), P.tref(u) / P.sigma
end
series[#series + 1] = {x = x, y = y, style = "line", label = "quasi-static, G_c = " .. P.gc}
mvmpm.plot {file = dir .. "/cohesive_pull.png",
            title = "Pulled apart through a cohesive interface (sigma 0.005, delta_c 0.01)",
            xlabel = "grip travel / (sigma L / M)", ylabel = "grip traction / sigma", series = series}
print("cohesive: pictures in " .. dir)
