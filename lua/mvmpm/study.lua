-- mvmpm.study: what accuracy costs in time.  Runs one case over a grid of
-- settings (cells x ppc x shape x transfer x flip x update x cfl, any
-- subset), measures the case's error against its reference and the wall
-- time of each run (the median of R repeats), and writes
--
--   DIR/NAME.csv      one row per setting: settings, errors, seconds
--                     (wall; `cpu`: the process's CPU seconds beside them),
--                     particles, steps, simulated time, seconds per unit
--                     simulated time per 1,000 particles, status
--   DIR/NAME.md       the fitted convergence orders, the Pareto front, the
--                     cheapest setting for each error level, the baseline
--   FIGDIR/accuracy_NAME_pareto.png       error vs wall time, log-log,
--                                         the Pareto front drawn as a line
--   FIGDIR/accuracy_NAME_convergence.png  error vs cell size, log-log,
--                                         with the least-squares order
--
-- A case is a table
--
--   {name = "bounce", title = "...",
--    length = "D",                 -- what "cells" counts cells across
--    metrics = {{key = "energy", label = "|dE| / E0"}, ...}, -- first: primary
--    grid = {cells = {8, 16}, shape = {"linear", "gimp"}, ...},
--    baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1,
--                update = "musl", cfl = 0.25, ppc = 2},         -- optional
--    skip = function(s) return true end,                         -- optional
--    run = function(s, clock) ... return {energy = err, ...} end}
--
-- `run` builds the simulation from the settings s (s.cells, s.ppc, s.shape,
-- s.transfer, s.flip, s.update, s.cfl), advances it only through
-- clock.run(sim, t) and clock.step(sim, n), which time the stepping with
-- mvmpm.clock() (set-up and measurement between steps are not timed), and
-- returns the metrics by key plus any extra numbers to record.  The study
-- reads the particle count, steps and simulated time from the simulation
-- it last advanced.  clock.rep is the repeat (1 .. R): a case may skip
-- costly measurements after the first, whose results are the ones kept.  A run that raises an error (e.g. det F <= 0) is
-- recorded with its message and left out of the fits and plots.
local mvmpm = require "mvmpm"

local S = {}

-- the order settings are varied in, and their defaults
S.axes = {"cells", "ppc", "shape", "transfer", "flip", "update", "cfl"}
S.defaults = {cells = 8, ppc = 2, shape = "linear", transfer = "flip", flip = 1,
              update = "musl", cfl = 0.25}

local function median(t)
  local s = {}
  for k, v in ipairs(t) do s[k] = v end
  table.sort(s)
  local n = #s
  if n == 0 then return 0 / 0 end
  return n % 2 == 1 and s[(n + 1) // 2] or 0.5 * (s[n // 2] + s[n // 2 + 1])
end
S.median = median

-- least squares of log(err) on log(h): returns order p and factor C in
-- err = C h^p, from the points with finite positive error
function S.fit(hs, errs)
  local n, sx, sy, sxx, sxy = 0, 0, 0, 0, 0
  for i = 1, #hs do
    local e = errs[i]
    if e and e > 0 and e < math.huge then
      local x, y = math.log(hs[i]), math.log(e)
      n, sx, sy, sxx, sxy = n + 1, sx + x, sy + y, sxx + x * x, sxy + x * y
    end
  end
  if n < 2 then return nil end
  local d = n * sxx - sx * sx
  if d == 0 then return nil end
  local p = (n * sxy - sx * sy) / d
  return p, math.exp((sy - p * sx) / n), n
end

-- the rows no other row beats in both error and time, by increasing time
function S.pareto(rows, key)
  local ok = {}
  for _, r in ipairs(rows) do
    local e = r[key]
    if r.status == "ok" and e and e == e and e < math.huge then ok[#ok + 1] = r end
  end
  table.sort(ok, function(a, b)
    if a.seconds ~= b.seconds then return a.seconds < b.seconds end
    return a[key] < b[key]
  end)
  local front, best = {}, math.huge
  for _, r in ipairs(ok) do
    if r[key] < best then front[#front + 1], best = r, r[key] end
  end
  return front
end

-- every combination of the grid's axes, cells varying fastest, so that one
-- scheme's resolutions run together
local function combos(grid)
  local axes = {}
  local order = {}
  for _, a in ipairs(S.axes) do if a ~= "cells" then order[#order + 1] = a end end
  order[#order + 1] = "cells"
  for _, a in ipairs(order) do
    local v = grid[a]
    if v == nil then v = {S.defaults[a]} elseif type(v) ~= "table" then v = {v} end
    axes[#axes + 1] = {name = a, values = v}
  end
  local out = {}
  local function rec(k, cur)
    if k > #axes then
      local c = {}
      for kk, vv in pairs(cur) do c[kk] = vv end
      out[#out + 1] = c
      return
    end
    for _, v in ipairs(axes[k].values) do
      cur[axes[k].name] = v
      rec(k + 1, cur)
    end
  end
  rec(1, {})
  return out
end

-- which axes take more than one value (these name a scheme)
local function varied(grid)
  local v = {}
  for _, a in ipairs(S.axes) do
    if type(grid[a]) == "table" and #grid[a] > 1 then v[a] = true end
  end
  return v
end

-- a log range over the values with room above them for the legend
local function logrange(vals, room)
  local lo, hi = math.huge, -math.huge
  for _, v in ipairs(vals) do
    if v > 0 and v < math.huge then lo, hi = math.min(lo, v), math.max(hi, v) end
  end
  if lo == math.huge then return nil end
  if hi <= lo then lo, hi = lo / 2, hi * 2 end
  local a, b = math.log(lo, 10), math.log(hi, 10)
  local span = math.max(b - a, 0.5)
  return {10 ^ (a - 0.05 * span), 10 ^ (b + (room or 0) * span + 0.05 * span)}
end

local shape_name = {linear = "linear", gimp = "GIMP", bspline2 = "B-spline"}

-- a scheme's label: shape, transfer, update, and ppc / cfl when varied
function S.scheme(s, vary)
  local tr
  if s.transfer == "apic" then tr = "APIC"
  elseif s.transfer == "xpic" then tr = "XPIC"
  elseif s.transfer == "spin" then tr = "spin"
  elseif s.flip == 1 then tr = "FLIP"
  elseif s.flip == 0 then tr = "PIC"
  else tr = string.format("FLIP%g", s.flip) end
  local l = string.format("%s %s %s", shape_name[s.shape] or s.shape, tr, s.update:upper())
  if vary.ppc then l = l .. string.format(" ppc%d", s.ppc) end
  if vary.cfl then l = l .. string.format(" cfl%g", s.cfl) end
  return l
end

local function same(a, b)
  for _, k in ipairs(S.axes) do
    if a[k] ~= b[k] then return false end
  end
  return true
end

local function fmt(v)
  if type(v) == "number" then
    if v ~= v then return "nan" end
    if math.type(v) == "integer" then return tostring(v) end
    return string.format("%.6g", v)
  end
  return tostring(v)
end

local function csvfield(v)
  local s = fmt(v)
  if s:find('[,"\n]') then s = '"' .. s:gsub('"', '""') .. '"' end
  return s
end

-- the clock a case advances its simulation with: only stepping is timed
local function new_clock(r)
  local c = {seconds = 0, cpu = 0, sim = nil, rep = r}
  -- a failing step still counts its time, then raises the error again
  local function timed(f, sim, a)
    c.sim = sim
    local t0, c0 = mvmpm.clock(), os.clock()
    local ok, r = pcall(f, sim, a)
    c.seconds = c.seconds + (mvmpm.clock() - t0)
    c.cpu = c.cpu + (os.clock() - c0)
    if not ok then error(r, 0) end
    return r
  end
  function c.run(sim, t) return timed(sim.run, sim, t) end
  function c.step(sim, n) return timed(sim.step, sim, n) end
  return c
end

-- run one setting R times; returns the row
local function measure(case, s, R)
  local row = {}
  for k, v in pairs(s) do row[k] = v end
  local times, cpus = {}, {}
  for r = 1, R do
    local clock = new_clock(r)
    local ok, res = pcall(case.run, s, clock)
    if not ok then
      row.status = "failed: " .. tostring(res):gsub("^.-:%d+: ", ""):gsub("%s+", " ")
      row.seconds, row.cpu = clock.seconds, clock.cpu
      if clock.sim then
        row.particles, row.steps, row.t = clock.sim.n, clock.sim.steps, clock.sim.t
      end
      return row
    end
    times[#times + 1], cpus[#cpus + 1] = clock.seconds, clock.cpu
    if r == 1 then
      for k, v in pairs(res) do row[k] = v end
      local sim = clock.sim
      row.particles, row.steps, row.t = sim.n, sim.steps, sim.t
    end
  end
  row.status = "ok"
  row.seconds, row.cpu = median(times), median(cpus)
  row.seconds_min, row.seconds_max = math.min(table.unpack(times)), math.max(table.unpack(times))
  row.repeats = #times
  -- seconds per unit simulated time per 1,000 particles, and per
  -- particle-step (microseconds)
  row.cost = row.seconds / row.t / (row.particles / 1000)
  row.us_per_particle_step = 1e6 * row.seconds / (row.particles * row.steps)
  return row
end

local function mkdir(d) os.execute("mkdir -p '" .. d .. "'") end

-- run the study.  opts: repeats (R, default 3, or $STUDY_REPEATS), dir
-- (default "out/study"), figdir (default "docs/figures"), thresholds
-- (error levels for the cost table, default {0.3, 0.1, 0.03, 0.01, 0.003})
function S.run(case, opts)
  opts = opts or {}
  local R = opts.repeats or tonumber(os.getenv("STUDY_REPEATS") or "") or 3
  local dir = opts.dir or os.getenv("STUDY_DIR") or "out/study"
  local figdir = opts.figdir or os.getenv("STUDY_FIGDIR") or "docs/figures"
  local thresholds = opts.thresholds or {0.3, 0.1, 0.03, 0.01, 0.003, 0.001}
  mkdir(dir); mkdir(figdir)
  -- STUDY_QUICK=1: the three coarsest resolutions, one repeat (a smoke run)
  if os.getenv("STUDY_QUICK") == "1" then
    local g = {}
    for k, v in pairs(case.grid) do g[k] = v end
    g.cells = {table.unpack(case.grid.cells, 1, math.min(3, #case.grid.cells))}
    local c = {}
    for k, v in pairs(case) do c[k] = v end
    c.grid, case, R = g, c, opts.repeats or 1
  end
  -- STUDY_FROM_CSV=1: no runs, the summary and plots again from the CSV
  -- a previous run wrote (e.g. after changing how they are drawn)
  if os.getenv("STUDY_FROM_CSV") == "1" then
    local rows = S.read_csv(dir .. "/" .. case.name .. ".csv")
    local total = 0
    for _, r in ipairs(rows) do total = total + (r.seconds or 0) * (r.repeats or 1) end
    return S.summary(case, rows, {repeats = R, total = total, dir = dir, figdir = figdir,
                                  thresholds = thresholds})
  end
  local vary = varied(case.grid)
  local metrics = case.metrics
  local rows = {}
  local t_start = mvmpm.clock()
  print(string.format("study %s: %s (R = %d repeats)", case.name, case.title or "", R))
  for _, s in ipairs(combos(case.grid)) do
    -- the affine transfer ignores the FLIP fraction: run it once; the
    -- spin transfer is FLIP's, run with flip 1 only
    local dup = (s.transfer == "apic" and s.flip ~= (case.grid.flip and
      (type(case.grid.flip) == "table" and case.grid.flip[1] or case.grid.flip) or 1))
      or (s.transfer == "spin" and (s.flip or 1) ~= 1)
    -- what the engine refuses: APIC on linear hats, spin off B-splines
    local refused = (s.transfer == "apic" and s.shape == "linear")
      or (s.transfer == "spin" and s.shape ~= "bspline2")
    if not dup and not refused and not (case.skip and case.skip(s)) then
      if s.transfer == "apic" then s.flip = 1 end
      local row = measure(case, s, R)
      row.scheme = S.scheme(s, vary)
      row.h = 1 / s.cells
      rows[#rows + 1] = row
      local msg = {}
      for _, m in ipairs(metrics) do msg[#msg + 1] = string.format("%s %.4g", m.key, row[m.key] or 0 / 0) end
      print(string.format("  %-28s cells %-4d %-40s %8.3f s (CPU %.3f s)  n %6s  %s", row.scheme,
        s.cells, table.concat(msg, "  "), row.seconds or 0, row.cpu or 0, tostring(row.particles),
        row.status == "ok" and "" or row.status))
      io.stdout:flush()
    end
  end
  local total = mvmpm.clock() - t_start
  S.write_csv(case, rows, dir .. "/" .. case.name .. ".csv")
  S.write_csv(case, rows, figdir .. "/accuracy_" .. case.name .. ".csv")
  return S.summary(case, rows, {repeats = R, total = total, dir = dir, figdir = figdir,
                                thresholds = thresholds})
end

-- the CSV columns of a case
local function columns(case)
  local cols = {"scheme", "cells", "ppc", "shape", "transfer", "flip", "update", "cfl"}
  for _, m in ipairs(case.metrics) do cols[#cols + 1] = m.key end
  for _, c in ipairs(case.extra or {}) do cols[#cols + 1] = c end
  for _, c in ipairs {"seconds", "cpu", "seconds_min", "seconds_max", "repeats", "particles", "steps", "t",
                      "cost", "us_per_particle_step", "status"} do cols[#cols + 1] = c end
  return cols
end

function S.write_csv(case, rows, file)
  local cols = columns(case)
  local f = assert(io.open(file, "w"))
  f:write(table.concat(cols, ","), "\n")
  for _, r in ipairs(rows) do
    local v = {}
    for i, c in ipairs(cols) do
      local x = r[c]
      if c == "flip" and r.transfer == "apic" then x = "" end
      v[i] = x == nil and "" or csvfield(x)
    end
    f:write(table.concat(v, ","), "\n")
  end
  f:close()
end

-- rows back from a CSV written by S.write_csv (numbers as numbers)
function S.read_csv(file)
  local f = assert(io.open(file))
  local function split(line)
    local out, i = {}, 1
    while i <= #line + 1 do
      if line:sub(i, i) == '"' then
        local j, buf = i + 1, {}
        while true do
          local c = line:sub(j, j)
          if c == '"' and line:sub(j + 1, j + 1) == '"' then buf[#buf + 1] = '"'; j = j + 2
          elseif c == '"' or c == "" then break
          else buf[#buf + 1] = c; j = j + 1 end
        end
        out[#out + 1] = table.concat(buf)
        i = j + 2
      else
        local j = line:find(",", i, true) or #line + 1
        out[#out + 1] = line:sub(i, j - 1)
        i = j + 1
      end
    end
    return out
  end
  local head = split(f:read("l"))
  local rows = {}
  for line in f:lines() do
    local v, r = split(line), {}
    for i, c in ipairs(head) do
      local x = v[i]
      if x == "" then x = nil
      elseif c ~= "scheme" and c ~= "status" and tonumber(x) then x = tonumber(x)
      elseif x == "nan" or x == "-nan" then x = 0 / 0 end
      r[c] = x
    end
    if r.transfer == "apic" then r.flip = 1 end
    r.h = 1 / r.cells
    rows[#rows + 1] = r
  end
  f:close()
  return rows
end

-- the summary of a study's rows: the MD file and the plots
function S.summary(case, rows, o)
  local R, total, dir, figdir, thresholds = o.repeats, o.total, o.dir, o.figdir, o.thresholds
  for _, r in ipairs(rows) do if r.repeats and r.repeats > 0 then R = r.repeats end end
  local metrics = case.metrics
  local key = metrics[1].key
  -- group by scheme, in first-seen order
  local schemes, by = {}, {}
  for _, r in ipairs(rows) do
    if not by[r.scheme] then by[r.scheme] = {}; schemes[#schemes + 1] = r.scheme end
    table.insert(by[r.scheme], r)
  end

  local md = {}
  local function w(...) md[#md + 1] = string.format(...) end
  local function esc(l) return (l:gsub("|", "\\|")) end
  w("## %s\n", case.title or case.name)
  if case.reference then w("Reference: %s\n", case.reference) end
  w("%d settings, %d repeats each, %.0f s of stepping in all.  `cells` counts cells across %s.\n",
    #rows, R, total, case.length or "the case's length")

  for mi, m in ipairs(metrics) do
    local k = m.key
    -- orders
    w("\n### %s: convergence order per scheme (least squares, log-log)\n", esc(m.label))
    w("| scheme | order p | points | error at finest | cells |")
    w("|---|---|---|---|---|")
    local conv = {}
    for si, sc in ipairs(schemes) do
      local hs, es, last = {}, {}, nil
      for _, r in ipairs(by[sc]) do
        if r.status == "ok" and r[k] then
          hs[#hs + 1], es[#es + 1] = r.h, math.abs(r[k]); last = r
        end
      end
      local p, C, n = S.fit(hs, es)
      if p then
        w("| %s | %.2f | %d | %.3g | %d |", sc, p, n, math.abs(last[k]), last.cells)
      else
        w("| %s | - | %d | %s | %s |", sc, #hs, last and string.format("%.3g", math.abs(last[k])) or "-",
          last and tostring(last.cells) or "-")
      end
      if #hs > 0 then
        conv[#conv + 1] = {x = hs, y = es, label = p and string.format("%s (p = %.2f)", sc, p) or sc,
                           style = "both"}
      end
    end
    -- failures
    local failed = {}
    for _, r in ipairs(rows) do
      if r.status ~= "ok" then failed[#failed + 1] = r end
    end
    if mi == 1 and #failed > 0 then
      w("\nRuns that stopped with an error:\n")
      for _, r in ipairs(failed) do
        w("- %s, %d cells: %s (t = %s, step %s)", r.scheme, r.cells, r.status, fmt(r.t), fmt(r.steps))
      end
    end
    local ylabel = m.label
    local allerr = {}
    for _, r in ipairs(rows) do
      if r.status == "ok" and r[k] then allerr[#allerr + 1] = math.abs(r[k]) end
    end
    mvmpm.plot {file = string.format("%s/accuracy_%s%s_convergence.png", figdir, case.name,
                                     mi == 1 and "" or "_" .. k),
                title = (case.title or case.name) .. ": " .. m.label .. " vs resolution",
                xlabel = "cell size h / " .. (case.length or "L"), ylabel = ylabel,
                xlog = true, ylog = true, series = conv, width = 1000, height = 720,
                yrange = logrange(allerr, 0.25 + 0.07 * #conv)}

    -- Pareto
    local front = S.pareto(rows, k)
    w("\n### %s: Pareto front (no setting is both faster and more accurate)\n", esc(m.label))
    w("| scheme | cells | %s | seconds (wall) | CPU seconds | particles | s per unit time per 1000 particles |", esc(m.label))
    w("|---|---|---|---|---|---|---|")
    for _, r in ipairs(front) do
      w("| %s | %d | %.3g | %.3g | %s | %d | %.3g |", r.scheme, r.cells, math.abs(r[k]), r.seconds,
        r.cpu and string.format("%.3g", r.cpu) or "-", r.particles, r.cost)
    end
    local ser = {}
    for _, sc in ipairs(schemes) do
      local xs, ys = {}, {}
      for _, r in ipairs(by[sc]) do
        if r.status == "ok" and r[k] then xs[#xs + 1], ys[#ys + 1] = r.seconds, math.abs(r[k]) end
      end
      if #xs > 0 then ser[#ser + 1] = {x = xs, y = ys, label = sc, style = "points"} end
    end
    local fx, fy = {}, {}
    for _, r in ipairs(front) do fx[#fx + 1], fy[#fy + 1] = r.seconds, math.abs(r[k]) end
    ser[#ser + 1] = {x = fx, y = fy, label = "Pareto front", style = "line"}
    mvmpm.plot {file = string.format("%s/accuracy_%s%s_pareto.png", figdir, case.name,
                                     mi == 1 and "" or "_" .. k),
                title = (case.title or case.name) .. ": " .. m.label .. " vs wall time",
                xlabel = "wall time of the run, s (median of " .. R .. ")", ylabel = ylabel,
                xlog = true, ylog = true, series = ser, width = 1000, height = 720,
                yrange = logrange(allerr, 0.25 + 0.07 * #ser)}
  end

  -- the cheapest setting for each error level (primary metric)
  w("\n### Cheapest setting for a given %s\n", esc(metrics[1].label))
  w("| %s at most | scheme | cells | measured | seconds | s per unit time per 1000 particles |", esc(metrics[1].label))
  w("|---|---|---|---|---|---|")
  -- per threshold, the cheapest setting that pred(r, th) accepts
  local function cheapest(pred)
    for _, th in ipairs(thresholds) do
      local best
      for _, r in ipairs(rows) do
        if r.status == "ok" and r[key] and pred(r, th) and (not best or r.seconds < best.seconds) then best = r end
      end
      if best then
        w("| %g | %s | %d | %.3g | %.3g | %.3g |", th, best.scheme, best.cells, math.abs(best[key]),
          best.seconds, best.cost)
      else
        w("| %g | none in the grid | | | | |", th)
      end
    end
  end
  cheapest(function(r, th) return math.abs(r[key]) <= th end)

  -- the same, asking the scheme to stay within the level at every finer
  -- resolution of the grid too (an error that changes sign can pass
  -- through zero at one resolution by luck)
  w("\nThe same, for a setting whose scheme also stays within that level at every finer resolution in the grid:\n")
  w("| %s at most | scheme | cells | measured | seconds | s per unit time per 1000 particles |", esc(metrics[1].label))
  w("|---|---|---|---|---|---|")
  local function holds(r, th)
    for _, q in ipairs(by[r.scheme]) do
      if q.cells >= r.cells and (q.status ~= "ok" or not q[key] or math.abs(q[key]) > th) then return false end
    end
    return true
  end
  cheapest(holds)

  -- the baseline against the best setting at the same wall time
  if case.baseline then
    local b = {}
    for _, a in ipairs(S.axes) do b[a] = case.baseline[a] == nil and S.defaults[a] or case.baseline[a] end
    local base
    for _, r in ipairs(rows) do if same(r, b) then base = r end end
    if base and base.status == "ok" then
      w("\n### The report's setting against the best at the same wall time\n")
      for _, m in ipairs(metrics) do
        local k = m.key
        local best
        for _, r in ipairs(rows) do
          if r.status == "ok" and r[k] and r.seconds <= base.seconds * 1.0 and
             (not best or math.abs(r[k]) < math.abs(best[k])) then best = r end
        end
        w("- %s: %s at %d cells: %.3g in %.3g s; best within that time: %s at %d cells: %.3g in %.3g s",
          esc(m.label), base.scheme, base.cells, math.abs(base[k]), base.seconds,
          best.scheme, best.cells, math.abs(best[k]), best.seconds)
        -- timings carry noise: also the best within 1.5 times the time
        local near
        for _, r in ipairs(rows) do
          if r.status == "ok" and r[k] and r.seconds <= base.seconds * 1.5 and
             (not near or math.abs(r[k]) < math.abs(near[k])) then near = r end
        end
        w("  (within 1.5 times that time: %s at %d cells: %.3g in %.3g s)", near.scheme, near.cells,
          math.abs(near[k]), near.seconds)
      end
    end
  end
  local mf = assert(io.open(dir .. "/" .. case.name .. ".md", "w"))
  mf:write(table.concat(md, "\n"), "\n")
  mf:close()
  print(table.concat(md, "\n"))
  return rows
end

-- a study script ends with `return S.main(case)`: it runs the study,
-- unless S.load_only is set (then it only hands back the case, for tests
-- that run a few of its settings)
function S.main(case, opts)
  if S.load_only then return case end
  S.run(case, opts)
  return case
end

-- the settings table for one run, defaults filled in
function S.settings(t)
  local s = {}
  for _, a in ipairs(S.axes) do s[a] = t[a] == nil and S.defaults[a] or t[a] end
  return s
end

-- run a case once with the given settings (untimed use, e.g. in tests):
-- returns its result table and the simulation
function S.once(case, t)
  local clock = new_clock(1)
  local res = case.run(S.settings(t), clock)
  return res, clock.sim, clock.seconds
end

return S
