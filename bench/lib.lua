-- bench/lib.lua - timing helpers for the bench scripts (run through
-- `mvmpm test`, so `require "mvmpm"` works and no output files are
-- written).  Times are wall-clock seconds from mvmpm.clock(), a
-- monotonic clock, taken around sim:step(n) only: scene set-up and the
-- warm-up steps are not timed.
local mvmpm = require "mvmpm"

local B = {}

-- BENCH_QUICK=1 (run.sh --quick) trades precision for time
local quick = os.getenv("BENCH_QUICK") == "1"
B.reps = quick and 3 or 5        -- repeats; the median is reported
B.target = quick and 0.15 or 0.4 -- seconds one repeat should last

local function median(t)
  local s = {}
  for k, v in ipairs(t) do s[k] = v end
  table.sort(s)
  local n = #s
  return n % 2 == 1 and s[(n + 1) // 2] or 0.5 * (s[n // 2] + s[n // 2 + 1])
end
B.median = median

-- steady-state seconds per step: `warm` untimed steps, then B.reps
-- repeats of n steps, n chosen so that one repeat lasts about B.target
function B.time_steps(sim, warm)
  sim:step(warm or 3)
  local t0 = mvmpm.clock()
  sim:step(1)
  local one = mvmpm.clock() - t0
  local n = math.max(1, math.floor(B.target / math.max(one, 1e-6) + 0.5))
  local per = {}
  for r = 1, B.reps do
    t0 = mvmpm.clock()
    sim:step(n)
    per[r] = (mvmpm.clock() - t0) / n
  end
  return median(per), n, per
end

-- particle-steps per second of sim at its current state
function B.rate(sim, warm)
  local sec, n = B.time_steps(sim, warm)
  return sim.n / sec, sec, n
end

function B.line(kind, name, value, unit, note)
  print(string.format("%-9s %-46s %10.3f %-10s %s", kind, name, value, unit or "",
    note or ""))
end

-- resident set size of this process in bytes (Linux), or nil
function B.rss()
  local f = io.open("/proc/self/status")
  if not f then return nil end
  local s = f:read("a")
  f:close()
  local kb = s:match("VmRSS:%s*(%d+)%s*kB")
  return kb and tonumber(kb) * 1024
end

return B
