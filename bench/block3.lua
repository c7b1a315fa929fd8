-- bench/block3.lua - (f) the 3-D figures: a filled elastic block of
-- 40 x 40 x 40 cells, one velocity field, 2 x 2 x 2 particles per cell
-- (512,000 particles), FLIP, MUSL, with a standing shear wave
-- vx = 0.01 sin(2 pi y) so that every particle strains; two empty cells
-- on each side keep it inside the domain with free sides.  Rates of the
-- three shape functions on one thread, 1 against 2 threads (linear hats),
-- and memory per particle: the peak resident size of this process (VmHWM)
-- less its size before the block was made, over the particles.
-- Each rate is given on the wall clock and on the process's CPU clock
-- (os.clock): on a loaded machine the wall figure falls and the CPU one
-- holds.  BENCH3_CELLS=N changes the block's size.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local CELLS = tonumber(os.getenv("BENCH3_CELLS") or 40)

local function block(shape)
  local h, pad = 1 / CELLS, 2 / CELLS
  local sim = mvmpm.sim {dim = 3,
    domain = {x = {-pad, 1 + pad}, y = {-pad, 1 + pad}, z = {-pad, 1 + pad}},
    cell = h, ppc = 2, shape = shape, update = "musl", flip = 1.0,
    sides = "free", t_end = 1e9, threads = 1}
  sim:body {shape = mvmpm.box {lo = {0, 0, 0}, hi = {1, 1, 1}},
            material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
            velocity = function(x, y, z) return 0.01 * math.sin(2 * math.pi * y), 0, 0 end}
  return sim
end

-- seconds per step, wall and CPU, median of B.reps repeats of n steps
local function time_steps(sim, warm)
  sim:step(warm)
  local t0 = mvmpm.clock()
  sim:step(1)
  local n = math.max(1, math.floor(B.target / math.max(mvmpm.clock() - t0, 1e-6) + 0.5))
  local wall, cpu = {}, {}
  for r = 1, B.reps do
    local w0, c0 = mvmpm.clock(), os.clock()
    sim:step(n)
    wall[r], cpu[r] = (mvmpm.clock() - w0) / n, (os.clock() - c0) / n
  end
  return B.median(wall), B.median(cpu), n
end

local function load()
  local f = io.open("/proc/loadavg")
  if not f then return "?" end
  local s = f:read("l")
  f:close()
  return s:match("^(%S+)")
end

-- peak resident size (VmHWM) in bytes, or nil
local function hwm()
  local f = io.open("/proc/self/status")
  if not f then return nil end
  local s = f:read("a")
  f:close()
  local kb = s:match("VmHWM:%s*(%d+)%s*kB")
  return kb and tonumber(kb) * 1024
end

collectgarbage()
local base = B.rss()
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  local sim = block(shape)
  local wall, cpu, n = time_steps(sim, 5)
  B.line("rate", string.format("(f) 3-D block %d^3 %s, 1 thread", CELLS, shape), sim.n / wall / 1e6,
    "M p-st/s", string.format("wall; CPU %.3f M p-st/s (%.1f ms/step CPU, %.1f wall), %d particles, median of %d x %d steps, load %s",
      sim.n / cpu / 1e6, 1e3 * cpu, 1e3 * wall, sim.n, B.reps, n, load()))
  if shape == "linear" then
    local peak, mem = hwm(), sim.memory
    B.line("memory", "(f) 3-D particle store / particle", mem.particles / sim.n, "bytes",
      string.format("allocation sizes, capacity %d", mem.capacity))
    B.line("memory", "(f) 3-D grid / particle", mem.grid / sim.n, "bytes",
      "allocation sizes: dense node arrays and slot pool")
    if peak and base then
      B.line("memory", "(f) 3-D peak RSS growth / particle", (peak - base) / sim.n, "bytes",
        string.format("VmHWM %.0f MB less %.0f MB before the block; adds the seeding lattice",
          peak / 2 ^ 20, base / 2 ^ 20))
    end
  end
  sim = nil
  collectgarbage()
  collectgarbage()
end

-- 1 against 2 threads, timed in turns as bench/threads.lua does: two
-- copies of the block in lockstep, n steps of one then of the other, the
-- order swapped each round; the median of the rounds' ratios.  Also on the
-- threads' CPU clocks (mvmpm.cpu): the serial part plus each threaded
-- job's longest part, what a step takes on idle cores.
local function crit_steps(sim, n)
  local tc0, _, c0, o0 = mvmpm.cpu()
  sim:step(n)
  local tc1, _, c1, o1 = mvmpm.cpu()
  return (tc1 - tc0) - (o1 - o0) + (c1 - c0)
end
local ROUNDS = tonumber(os.getenv("BENCH_ROUNDS") or (os.getenv("BENCH_QUICK") == "1" and 5 or 9))
do
  local l = load()
  local sims = {block("linear"), block("linear")}
  sims[1].threads, sims[2].threads = 1, 2
  for _, sim in ipairs(sims) do sim:step(5) end
  local t0 = mvmpm.clock()
  sims[1]:step(1)
  sims[2]:step(1)
  local n = math.max(1, math.floor(B.target / math.max(mvmpm.clock() - t0, 1e-6) + 0.5))
  local per, cpu, ratio, cratio = {{}, {}}, {{}, {}}, {}, {}
  for r = 1, ROUNDS do
    for _, t in ipairs(r % 2 == 1 and {1, 2} or {2, 1}) do
      local t1 = mvmpm.clock()
      cpu[t][r] = crit_steps(sims[t], n) / n
      per[t][r] = (mvmpm.clock() - t1) / n
    end
    ratio[r] = per[1][r] / per[2][r]
    cratio[r] = cpu[1][r] / cpu[2][r]
  end
  for t = 1, 2 do
    local sec = B.median(per[t])
    B.line("rate", string.format("(f) 3-D block %d^3 linear, %d thread%s", CELLS, t, t > 1 and "s" or ""),
      sims[t].n / sec / 1e6, "M p-st/s", string.format("%.1f ms/step wall, %.1f CPU on idle cores, %d rounds of %d steps, load %s",
        1e3 * sec, 1e3 * B.median(cpu[t]), ROUNDS, n, l))
  end
  local lo, hi = math.huge, 0
  for _, q in ipairs(ratio) do lo, hi = math.min(lo, q), math.max(hi, q) end
  B.line("ratio", "(f) 3-D block: speed-up 2 / 1 thread", B.median(ratio), "",
    string.format("goal >= 1.8; wall, median of %d rounds, range %.2f-%.2f, load after %s", ROUNDS, lo, hi, load()))
  lo, hi = math.huge, 0
  for _, q in ipairs(cratio) do lo, hi = math.min(lo, q), math.max(hi, q) end
  B.line("ratio", "(f) 3-D block: idle-core speed-up", B.median(cratio), "",
    string.format("CPU clocks; range %.2f-%.2f", lo, hi))
  local mem = sims[2].memory
  B.line("memory", "(f) 3-D block, 2 threads / particle", (mem.particles + mem.grid + mem.threads) / sims[2].n,
    "bytes", string.format("of which partial sums and plan %d bytes in all", mem.threads))
end
