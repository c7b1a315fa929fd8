-- bench/schemes.lua - what each scheme costs on the 1,000-grain scene of
-- bench/grains.lua (1,000 elastic discs, one field each, in contact):
-- CPU seconds per step (os.clock) of shape x update, against linear
-- hats, MUSL in the same process, two repeats.
--   ./mvmpm test bench/schemes.lua          (about a minute)
-- Nothing here passes or fails: speed is never a test.
local B = dofile("bench/lib.lua")

local schemes = {
  {"linear MUSL", {}},
  {"linear USAVG", {update = "usavg"}},
  {"GIMP MUSL", {shape = "gimp"}},
  {"GIMP USAVG", {shape = "gimp", update = "usavg"}},
  {"B-spline MUSL (default)", {shape = "bspline2"}},
  {"B-spline USAVG", {shape = "bspline2", update = "usavg"}},
}
local steps = os.getenv("BENCH_QUICK") and 5 or 20
for rep = 1, 2 do
  local base
  for _, s in ipairs(schemes) do
    local sim = B.packing(50, 20, s[2])
    sim:step(2)
    local c0 = os.clock()
    sim:step(steps)
    local c = (os.clock() - c0) / steps
    base = base or c
    print(string.format("repeat %d  %-24s %7.1f ms CPU per step   ratio %.2f",
      rep, s[1], 1e3 * c, c / base))
    sim = nil
    collectgarbage()
  end
end
