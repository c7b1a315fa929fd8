-- bench/threads.lua - (e) 1 against 2 threads on the filled 400 x 400
-- block of (a) (linear, MUSL, 640,000 particles), on the same block cut
-- in two bodies along x = 1/2 in frictional contact (two fields, 401
-- shared nodes), and on the 1,000-grain bed of (c) (about 208,000
-- particles, 1,000 fields): rates, the speed-up, and memory per particle
-- with threads.  The machine is shared, so the load average before each
-- timing is printed with it; a speed-up on the wall clock is only as
-- good as the cores that were free.  So each is also given on the
-- threads' CPU clocks (mvmpm.cpu, par.h): the serial code plus each
-- threaded job's longest part, what a step takes on idle cores.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local function block() return B.block() end

local function grains() return B.packing(50, 20) end

-- the block cut in two bodies along x = 1/2, in contact (friction 0.3)
local function two()
  local CELLS, PAD = 400, 2
  local h = 1 / CELLS
  local sim = mvmpm.sim {domain = {x = {-PAD * h, 1 + PAD * h}, y = {-PAD * h, 1 + PAD * h}},
    cell = h, ppc = 2, shape = "linear", update = "musl", flip = 1.0, sides = "free",
    t_end = 1e9}
  local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  local v = function(x, y) return 0.01 * math.sin(2 * math.pi * y), 0 end
  local a = sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {0.5, 1}}, material = m, velocity = v}
  local b = sim:body {shape = mvmpm.rect {lo = {0.5, 0}, hi = {1, 1}}, material = m, velocity = v}
  sim:contact(a, b, {friction = 0.3})
  return sim
end

-- seconds on idle cores of sim:step(n): the caller's serial CPU time
-- plus the longest part of each threaded job
local function crit_steps(sim, n)
  local tc0, _, c0, o0 = mvmpm.cpu()
  sim:step(n)
  local tc1, _, c1, o1 = mvmpm.cpu()
  return (tc1 - tc0) - (o1 - o0) + (c1 - c0)
end

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

-- The two runs are timed in turns, not one after the other: the same
-- scene built twice, one with one thread and one with two, stepped in
-- lockstep (so both hold the same state), n steps of one then n of the
-- other, the order swapped each round.  A neighbour's burst of load then
-- falls on both, and the ratio of each round is taken; its median is the
-- speed-up, its range says how steady the machine was.
local ROUNDS = tonumber(os.getenv("BENCH_ROUNDS") or 9)
for _, c in ipairs {{"block 400x400 linear MUSL", block}, {"block in two bodies", two},
                    {"1000 grains", grains}} do
  local l = load()
  local sims = {c[2](), c[2]()}
  sims[1].threads, sims[2].threads = 1, 2
  for _, sim in ipairs(sims) do sim:step(25) end -- warm past the first sort by cell
  local t0 = mvmpm.clock()
  sims[1]:step(1)
  sims[2]:step(1)
  local n = math.max(1, math.floor(B.target / math.max(mvmpm.clock() - t0, 1e-6) + 0.5))
  local per, ratio, cpu, cratio = {{}, {}}, {}, {{}, {}}, {}
  for r = 1, ROUNDS do
    local order = r % 2 == 1 and {1, 2} or {2, 1}
    for _, t in ipairs(order) do
      local t1 = mvmpm.clock()
      cpu[t][r] = crit_steps(sims[t], n) / n
      per[t][r] = (mvmpm.clock() - t1) / n
    end
    ratio[r] = per[1][r] / per[2][r]
    cratio[r] = cpu[1][r] / cpu[2][r]
  end
  for t = 1, 2 do
    local sec = B.median(per[t])
    B.line("rate", string.format("(e) %s, %d thread%s", c[1], t, t > 1 and "s" or ""),
      sims[t].n / sec / 1e6, "M p-st/s", string.format("%d particles, %.1f ms/step, %d rounds of %d steps, load %s",
        sims[t].n, 1e3 * sec, ROUNDS, n, l))
  end
  local mem = sims[2].memory
  B.line("memory", string.format("(e) %s, 2 threads / particle", c[1]),
    (mem.particles + mem.grid + mem.threads + mem.contact) / sims[2].n, "bytes",
    string.format("of which partial sums and plan %d bytes, contact's records %d bytes in all",
      mem.threads, mem.contact))
  local lo, hi = math.huge, 0
  for _, q in ipairs(ratio) do lo, hi = math.min(lo, q), math.max(hi, q) end
  B.line("ratio", string.format("(e) %s: speed-up 2 / 1 thread", c[1]), B.median(ratio),
    "", string.format("goal >= 1.8; median of %d rounds, range %.2f-%.2f, load after %s", ROUNDS, lo, hi, load()))
  lo, hi = math.huge, 0
  for _, q in ipairs(cratio) do lo, hi = math.min(lo, q), math.max(hi, q) end
  B.line("ratio", string.format("(e) %s: idle-core speed-up", c[1]), B.median(cratio),
    "", string.format("CPU clocks: %.1f ms/step 1 thread, %.1f on idle cores with 2; range %.2f-%.2f",
      1e3 * B.median(cpu[1]), 1e3 * B.median(cpu[2]), lo, hi))
  sims = nil
  collectgarbage()
  collectgarbage()
end
