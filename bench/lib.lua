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

-- The bench scenes, built in one place.  opt: fields of mvmpm.sim to
-- add or replace (shape, update, dt, t_end ...).  Both name linear hats,
-- so the series of rates stays one measure across the change of the
-- default shape; bench/schemes.lua prices the others.
local function with(base, opt)
  for k, v in pairs(opt or {}) do base[k] = v end
  return base
end

-- (a), (e): a filled 400 x 400-cell elastic block with a standing shear
-- wave, vx = 0.01 sin(2 pi y), so every particle strains; two empty cells
-- on each side keep it inside the domain with free sides.  opt: options
-- of mvmpm.sim, and cells (default 400) for a smaller block
function B.block(opt)
  local CELLS, PAD = opt and opt.cells or 400, 2
  local h = 1 / CELLS
  if opt then opt.cells = nil end
  local sim = mvmpm.sim(with({
    domain = {x = {-PAD * h, 1 + PAD * h}, y = {-PAD * h, 1 + PAD * h}},
    cell = h, ppc = 2, shape = "linear", update = "musl", flip = 1.0,
    sides = "free", t_end = 1e9,
  }, opt))
  sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {1, 1}},
            material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
            velocity = function(x, y) return 0.01 * math.sin(2 * math.pi * y), 0 end}
  return sim
end

-- (c), (e): nx x ny touching elastic discs in a 400 x 160-cell box, one
-- field each, frictionless, under uniform compression
function B.packing(nx, ny, opt)
  local H = 1 / 400
  local W, HT = 400 * H, 160 * H
  local r = W / (2 * nx)
  local sim = mvmpm.sim(with({
    domain = {x = {0, W}, y = {0, HT}}, cell = H, ppc = 2, shape = "linear",
    sides = "free", t_end = 1e9, contact = {friction = 0},
  }, opt))
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

return B
