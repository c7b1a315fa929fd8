-- bench/compare_case.lua - one timing for bench/compare.sh: the 2-D
-- scene named by $CMP_CASE, CMP_STEPS steps after 3 warm-up steps
-- (untimed), printed as one line
--   cmp CASE PARTICLES STEPS WALL_SECONDS CPU_SECONDS
-- Written for the mvmpm module of any version that has mvmpm.clock (so
-- that an older build runs it too): plain 2-D scenes, no newer options.
local mvmpm = require "mvmpm"

local name = os.getenv("CMP_CASE") or "block-linear-musl"
local steps = tonumber(os.getenv("CMP_STEPS") or 10)

-- a filled elastic block of C x C cells, 2 x 2 particles per cell, with
-- a standing shear wave (bench/lib.lua's block, smaller)
local function block(shape, update)
  local C = 200
  local h = 1 / C
  local sim = mvmpm.sim {domain = {x = {-2 * h, 1 + 2 * h}, y = {-2 * h, 1 + 2 * h}},
    cell = h, ppc = 2, shape = shape, update = update, flip = 1.0,
    sides = "free", t_end = 1e9, threads = 1}
  sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {1, 1}},
            material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
            velocity = function(x, y) return 0.01 * math.sin(2 * math.pi * y), 0 end}
  return sim
end

-- nx x ny touching elastic discs, one field each, frictionless contact,
-- under uniform compression (bench/lib.lua's packing)
local function grains(nx, ny)
  local H = 1 / 400
  local W, HT = 400 * H, 160 * H
  local r = W / (2 * nx)
  local sim = mvmpm.sim {domain = {x = {0, W}, y = {0, HT}}, cell = H, ppc = 2,
    sides = "free", t_end = 1e9, contact = {friction = 0}, threads = 1}
  local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  local xc, yc = W / 2, HT / 2
  local v = function(x, y) return -0.05 * (x - xc), -0.05 * (y - yc) end
  for j = 0, ny - 1 do
    for i = 0, nx - 1 do
      sim:body {shape = mvmpm.disk {center = {(2 * i + 1) * r, (2 * j + 1) * r}, radius = r},
                material = m, velocity = v}
    end
  end
  return sim
end

local cases = {
  ["block-linear-musl"] = function() return block("linear", "musl") end,
  ["block-linear-usl"] = function() return block("linear", "usl") end,
  ["block-gimp-musl"] = function() return block("gimp", "musl") end,
  ["block-bspline2-musl"] = function() return block("bspline2", "musl") end,
  ["block-gimp-usavg"] = function() return block("gimp", "usavg") end,
  ["grains-250"] = function() return grains(25, 10) end,
}
local make = cases[name]
if not make then error("compare_case: unknown CMP_CASE " .. name) end
local sim = make()
sim:step(3)
local w0, c0 = mvmpm.clock(), os.clock()
sim:step(steps)
print(string.format("cmp %s %d %d %.6f %.6f", name, sim.n, steps,
  mvmpm.clock() - w0, os.clock() - c0))
