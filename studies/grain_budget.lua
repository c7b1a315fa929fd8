-- Study: the energy budget of a collapsing column of frictional grains,
-- in every transfer scheme, at three resolutions.
-- 50 elastic discs (R = 0.5, K = 400, G = 200, density 1), 5 across and
-- 10 high, every other row shifted by a quarter diameter and jittered,
-- collapse under gravity (g = 1) in a box 12 wide with mu = 0.3 at the
-- walls and between grains, to t = 8 (at rest by then).  Per scheme and
-- resolution: the friction work, the numerical losses the budget books
-- (transfer: the transfer's own smoothing; impact: the normal impulses'
-- loss at the nodes) and the residual, all over the energy put in (the
-- initial energy, potential from the floor, plus boundary work: none
-- here).  Targets: |residual| < 2 % in every scheme; friction work within
-- 10 % across schemes at >= 16 cells per grain and converging.
--
--   ./mvmpm test studies/grain_budget.lua      (STUDY_QUICK=1: 4, 6, 8 cells)
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"

local quick = os.getenv("STUDY_QUICK") == "1"
local cells = quick and {4, 6, 8} or {8, 12, 16}
local mu, R, W, nx, ny, T = 0.3, 0.5, 12, 5, 10, 8

local function column(c, sc)
  local sim = mvmpm.sim {
    domain = {x = {0, W}, y = {0, ny * 1.1 + 1}}, cell = 2 * R / c, ppc = 2,
    shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
    t_end = T, gravity = {0, -1},
    sides = {bottom = {"wall", friction = mu}, left = {"wall", friction = mu},
             right = {"wall", friction = mu}, top = "wall"},
    contact = {friction = mu},
  }
  local m = mvmpm.elastic {K = 400, G = 200, density = 1}
  local seed = 1   -- a fixed jitter, the same for every run
  local function rnd()
    seed = (seed * 1103515245 + 12345) % 2147483648
    return seed / 2147483648
  end
  local x0 = W / 2 - nx * 0.55
  for j = 0, ny - 1 do
    for i = 0, nx - 1 do
      local x = x0 + 0.55 + i * 1.1 + (j % 2) * 0.25 + 0.05 * (rnd() - 0.5)
      sim:body {shape = mvmpm.disk {center = {x, R + 0.02 + j * 1.08}, radius = R}, material = m}
    end
  end
  local t0 = os.clock()
  sim:run(T)
  return sim:energy(), os.clock() - t0
end

V.case(string.format("column of %d frictional discs (mu %g), %s cells per diameter",
                     nx * ny, mu, table.concat(cells, ", ")))
local fr = {}
for k, c in ipairs(cells) do
  fr[k] = {}
  for _, sc in ipairs(S.schemes) do
    local e, cpu = column(c, sc)
    local put = e.initial + e.boundary_work
    local n = S.name(sc)
    fr[k][n] = e.dissipated / put
    V.info(string.format("%s, %d cells: friction / put", n, c), e.dissipated / put)
    V.info(string.format("%s, %d cells: transfer / put", n, c), e.transfer / put)
    V.info(string.format("%s, %d cells: impact / put", n, c), e.impact / put)
    V.info(string.format("%s, %d cells: residual / put", n, c), e.residual / put)
    V.info(string.format("%s, %d cells: kinetic left / put", n, c), e.kinetic / put)
    V.info(string.format("%s, %d cells: cpu", n, c), cpu, "s")
  end
  local lo, hi = math.huge, -math.huge
  for _, w in pairs(fr[k]) do lo, hi = math.min(lo, w), math.max(hi, w) end
  V.info(string.format("friction spread over the schemes (max/min - 1), %d cells", c), hi / lo - 1)
end
-- the friction work's change between resolutions, per scheme: the
-- observed order of its convergence where it converges
for _, sc in ipairs(S.schemes) do
  local n = S.name(sc)
  local d1, d2 = math.abs(fr[2][n] - fr[1][n]), math.abs(fr[3][n] - fr[2][n])
  V.info(string.format("%s: friction change %d->%d, %d->%d cells", n, cells[1], cells[2], cells[2], cells[3]), d2)
  if d1 > 0 and d2 > 0 then
    V.info(string.format("%s: observed order of the friction work", n),
           math.log(d1 / d2) / math.log(cells[3] / cells[2]))
  end
end
