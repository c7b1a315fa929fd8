-- tests/fault/pieces.lua - a scene that exercises what a restart must
-- carry: two bodies in frictional contact with a bond, a plastic body, a
-- driven platen, a moving wall, a temperature ramp, sorting, callbacks by
-- time and by steps that accumulate into sim:state.  With dump = true it
-- writes every particle field (hex floats) and the state at t_end to
-- fields.txt in the output directory.
local mvmpm = require "mvmpm"
local P = mvmpm.params {t_end = 0.6, dump = false, cell = 1/16}
local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 2}}, cell = P.cell,
  t_end = P.t_end, sides = {left = "wall", right = "wall", bottom = {"wall", friction = 0.3},
  top = {"wall", velocity = function(t) return 0.05 * t, 0 end}},
  gravity = {0, -1}, sort_every = 7, contact = {friction = 0.2}}
local rubber = mvmpm.elastic {K = 20, G = 8, density = 1, alpha = 1e-3}
local metal = mvmpm.plastic {K = 40, G = 20, density = 2, yield = 0.5, hardening = 1}
sim:body {name = "a", shape = mvmpm.disk {center = {0.6, 0.5}, radius = 0.3}, material = rubber,
          velocity = {0.4, 0}}
sim:body {name = "b", shape = mvmpm.disk {center = {1.25, 0.5}, radius = 0.3}, material = metal,
          velocity = {-0.4, 0.1}}
local platen = sim:body {name = "platen", shape = mvmpm.rect {lo = {0.3, 1.5}, hi = {1.7, 1.625}},
          material = metal, driven = {0, -0.2}}
sim:temperature(function(t) return 10 * t end)
local S = sim:state {series = {}, nsteps = 0, label = "run", flags = {seen = false}}
sim:every {time = 0.05, fn = function(s)
  local fx, fy = platen:force()
  S.series[#S.series + 1] = {t = s.t, f = fy, e = s:energy().total}
  S.flags.seen = true
end}
sim:every {steps = 3, fn = function(s) S.nsteps = S.nsteps + 1 end}
sim:every {steps = 1, fn = function(s)
  if P.dump and s.t >= s.t_end - 1e-12 then
    local f = assert(io.open(s.outdir .. "/fields.txt", "w"))
    for _, name in ipairs(s:particles()) do
      local v = s:particles(name)
      local comps = {}
      if v[1] ~= nil or next(v) == nil then comps = {{name, v}}
      else for k, c in pairs(v) do comps[#comps + 1] = {name .. "." .. k, c} end end
      table.sort(comps, function(x, y) return x[1] < y[1] end)
      for _, c in ipairs(comps) do
        f:write(c[1])
        for i = 1, #c[2] do f:write(" ", string.format("%a", c[2][i])) end
        f:write("\n")
      end
    end
    local sum = 0
    for _, r in ipairs(S.series) do sum = sum + r.f + r.e end
    f:write(string.format("state %d %d %a %s\n", #S.series, S.nsteps, sum, tostring(S.flags.seen)))
    f:close()
  end
end}
sim:output {every = 0.1, csv_every = 1}
return sim
