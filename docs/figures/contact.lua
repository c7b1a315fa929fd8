-- The contact normals' cases (lua/mvmpm/normals.lua) as figures for
-- docs/verification.md: the error of each normals method against the
-- resolution, log-log.  Run by `make figures` (a few minutes).
--   contact_block.png  block on a flat body rotated 45 degrees to the
--                      grid, |a / a_ref - 1| at 4, 8, 16, 32 cells per
--                      side, frictionless and mu = 0.2, linear hats,
--                      node by node and with one normal per contact patch
--                      ("+patch": normal_patch = true)
--   contact_discs.png  two discs, head on: |E / E0 - 1|; glancing
--                      (offset 0.2): the tangential relative velocity
--                      lost, at 20, 40, 80 cells across the domain
local mvmpm = require "mvmpm"
local C = require "mvmpm.normals"
local dir = arg and arg[1] or "docs/figures"
local METHODS = {"mass", "maxvolume/4", "plane/4"}

-- a zero error cannot be drawn on a log axis: the floor of the plot
local function floor(e) return math.max(e, 1e-4) end

local series = {}
for _, mu in ipairs {0, 0.2} do
  for _, m in ipairs {"mass", "maxvolume/4", "plane/4", "plane/4+patch"} do
    local x, y = {}, {}
    for _, k in ipairs {4, 8, 16, 32} do
      local r = C.block {k = k, method = m, mu = mu, deg = 45}
      x[#x + 1], y[#y + 1] = k, floor(math.abs(r.a - 1))
      print(string.format("block 45 deg mu %.1f %-14s %2d cells: |a/aref - 1| = %.4f", mu, m, k,
                          math.abs(r.a - 1)))
    end
    series[#series + 1] = {x = x, y = y, style = "both",
                           label = string.format("%s, mu = %.1f", m, mu)}
  end
end
mvmpm.plot {file = dir .. "/contact_block.png", xlog = true, ylog = true,
            title = "Block sliding on a flat body at 45 degrees to the grid", yrange = {0.001, 1000},
            xlabel = "cells per block side", ylabel = "|a / a_ref - 1|", series = series}

local head, glance = {}, {}
for _, m in ipairs(METHODS) do
  local x, yh, yg = {}, {}, {}
  for _, c in ipairs {20, 40, 80} do
    local r0 = C.discs {cells = c, method = m}
    local r1 = C.discs {cells = c, method = m, offset = 0.2}
    x[#x + 1] = c
    yh[#yh + 1], yg[#yg + 1] = floor(math.abs(r0.total - 1)), floor(math.abs(r1.kept - 1))
    print(string.format("discs %-12s %2d cells: head on |dE/E0| = %.4f, glancing lost %.4f", m, c,
                        math.abs(r0.total - 1), math.abs(r1.kept - 1)))
  end
  head[#head + 1] = {x = x, y = yh, style = "both", label = "head on |E/E0 - 1|, " .. m}
  glance[#glance + 1] = {x = x, y = yg, style = "both", label = "glancing, velocity lost, " .. m}
end
for _, s in ipairs(glance) do head[#head + 1] = s end
mvmpm.plot {file = dir .. "/contact_discs.png", xlog = true, ylog = true,
            title = "Two frictionless discs (Sulsky), linear hats",
            xlabel = "cells across the domain", ylabel = "error", series = head}
print("contact: pictures in " .. dir)
