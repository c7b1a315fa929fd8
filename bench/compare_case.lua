-- bench/compare_case.lua - one timing for bench/compare.sh: the 2-D
-- scene named by $CMP_CASE, CMP_STEPS steps after 3 warm-up steps
-- (untimed), printed as one line
--   cmp CASE PARTICLES STEPS WALL_SECONDS CPU_SECONDS
-- Written for the mvmpm module of any version that has mvmpm.clock (so
-- that an older build runs it too): plain 2-D scenes, no newer options.
local mvmpm = require "mvmpm"

local name = os.getenv("CMP_CASE") or "block-linear-musl"
local steps = tonumber(os.getenv("CMP_STEPS") or 10)

-- bench/lib.lua's block (200 x 200 cells) and packing, on one thread
local B = dofile("bench/lib.lua")
local function block(shape, update)
  return B.block {cells = 200, shape = shape, update = update, threads = 1}
end
local function grains(nx, ny) return B.packing(nx, ny, {threads = 1}) end

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
