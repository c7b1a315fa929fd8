-- bench/block.lua - (a) a filled elastic block of 400 x 400 cells, one
-- velocity field, 2 x 2 particles per cell (640,000 particles), FLIP,
-- for each update scheme and shape function; (d) memory per particle.
-- The block (K = 1, G = 0.5, density 1) carries a standing shear wave,
-- vx = 0.01 sin(2 pi y), so every particle strains; two empty cells on
-- each side keep it inside the domain with free sides.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")


local function block(shape, update)
  return B.block {shape = shape, update = update}
end

local cases = {
  {"linear", "musl"}, {"linear", "usl"}, {"gimp", "musl"}, {"bspline2", "musl"},
}
for _, c in ipairs(cases) do
  local rss0 = B.rss()
  local sim = block(c[1], c[2])
  local rate, sec, n = B.rate(sim)
  B.line("rate", string.format("(a) block 400x400 %s %s", c[1], c[2]), rate / 1e6,
    "M p-st/s", string.format("%d particles, %.1f ms/step, median of %d x %d steps",
      sim.n, 1e3 * sec, B.reps, n))
  if c[1] == "linear" and c[2] == "musl" then
    local mem, np = sim.memory, sim.n
    local rss1 = B.rss()
    B.line("memory", "(d) particle store / particle", mem.particles / np, "bytes",
      string.format("allocation sizes: arrays and sort buffers, capacity %d", mem.capacity))
    B.line("memory", "(d) grid / particle", mem.grid / np, "bytes",
      "allocation sizes: dense node arrays and slot pool")
    B.line("memory", "(d) total allocated / particle", (mem.particles + mem.grid) / np,
      "bytes")
    if rss0 and rss1 then
      B.line("memory", "(d) VmRSS growth / particle", (rss1 - rss0) / np, "bytes",
        "upper bound: adds the seeding lattice and buffers, Lua garbage")
    end
  end
  sim = nil
  collectgarbage()
  collectgarbage()
end
B.line("reference", "block 400x400 GIMP, FLIP (code A, one core)", 0.78, "M p-st/s")
B.line("reference", "block 400x400 linear, FLIP (code B, one core)", 2.18, "M p-st/s")
