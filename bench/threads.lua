-- bench/threads.lua - (e) 1 against 2 threads on the filled 400 x 400
-- block of (a) (linear, MUSL, 640,000 particles) and on the 1,000-grain
-- bed of (c) (about 208,000 particles, 1,000 fields): rates, the
-- speed-up, and memory per particle with threads.  The machine is
-- shared, so the load average before each timing is printed with it;
-- a speed-up is only as good as the cores that were free.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local function block() return B.block() end

local function grains() return B.packing(50, 20) end

local function load()
  local f = io.open("/proc/loadavg")
  if not f then return "?" end
  local s = f:read("l")
  f:close()
  return s:match("^(%S+)")
end

-- the first timed scene of a process runs slow (fresh pages, the clock
-- ramping up): a block is timed once first and thrown away, or the
-- one-thread figure, taken first, would read low and the ratio high
do
  local sim = block()
  B.rate(sim, 25)
  sim = nil
  collectgarbage()
end

for _, c in ipairs {{"block 400x400 linear MUSL", block}, {"1000 grains", grains}} do
  local rate = {}
  for _, t in ipairs {1, 2} do
    local l = load()
    local sim = c[2]()
    sim.threads = t
    local r, sec, n = B.rate(sim, 25) -- warm past the first sort by cell
    rate[t] = r
    B.line("rate", string.format("(e) %s, %d thread%s", c[1], t, t > 1 and "s" or ""),
      r / 1e6, "M p-st/s", string.format("%d particles, %.1f ms/step, load %s", sim.n,
        1e3 * sec, l))
    if t == 2 then
      local mem = sim.memory
      B.line("memory", string.format("(e) %s, 2 threads / particle", c[1]),
        (mem.particles + mem.grid + mem.threads) / sim.n, "bytes",
        string.format("of which partial sums and plan %d bytes in all", mem.threads))
    end
    sim = nil
    collectgarbage()
    collectgarbage()
  end
  B.line("ratio", string.format("(e) %s: speed-up 2 / 1 thread", c[1]), rate[2] / rate[1],
    "", "goal >= 1.8")
end
