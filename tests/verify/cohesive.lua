-- The cohesive law (sim.bond_energy): a cut interface keeps a normal
-- traction that falls linearly with its opening and gives out once the
-- fracture energy G_c per area is spent.
--
-- (a) scenarios/bond_pull.lua, two blocks in uniaxial strain (periodic
--     top and bottom) pulled apart by grips slowly enough to be nearly
--     quasi-static, the interface between cells (shift 0.3 of a cell).
--     Reference, quasi-static: the pair is one bar of stiffness M / L
--     per block (M = K + 4G/3, L = 1) until the traction reaches the
--     strength sigma at grip travel u = sigma L / M (each grip); then the
--     bars unload as the opening delta = 2u - 2 L t / M grows, with
--     t = sigma (1 - delta / delta_c), delta_c = 2 G_c / sigma, so
--       t(u) = sigma (1 - 2u / delta_c) / (1 - 2 sigma L / (M delta_c)),
--     zero from 2u = delta_c on (no snap-back: delta_c > 2 sigma L / M).
--     The work of separation booked (sim:energy().cohesion) must reach
--     G_c times the interface's area, 0.5 (unit depth), whatever the grid.
-- (b) the same with quadratic B-splines.
-- (c) what the law cannot do is refused: GIMP (its area at the shared
--     node shrinks as the sides part) and an opening at failure beyond
--     half a cell (the sides stop sharing nodes).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local M = 1 + 4 * 0.5 / 3
local V0, T = 0.0002, 8
local SIG, DC = 0.005, 0.01
local GC = 0.5 * SIG * DC
local AREA = 0.5

local function u(t) return t < T and V0 * t * t / (2 * T) or V0 * (T / 2 + (t - T)) end
local function tref(t)
  local uu = u(t)
  if uu <= SIG / M then return M * uu end
  return math.max(0, SIG * (1 - 2 * uu / DC) / (1 - 2 * SIG / (M * DC)))
end

-- the run: the work of separation over G_c A, the mean |grip traction -
-- quasi-static| / sigma over 1-time-unit windows from the peak to past
-- the end of the softening (t = 19 .. 31), the residual over the work
-- put in, |mean traction| / sigma once separated (t = 34 .. 40: the
-- bars ring with what the softening left in them, about its mean),
-- the smallest gap between the blocks' particles (a cell's fraction,
-- beyond their spacing), CPU seconds
local function pull(cells, shape)
  local sim = mvmpm.load("scenarios/bond_pull.lua", {strength = SIG, energy = GC,
    cells = cells, shape = shape, V0 = V0, shift = 0.3, t_end = 40})
  local grip
  for _, b in ipairs(sim:bodies()) do if b.name == "gripR" then grip = b end end
  local sum, k, late, nl, bad = 0, 0, 0, 0, false
  sim:every {steps = 1, fn = function(s)
    local tr = grip:force() / AREA
    sum, k = sum + tr, k + 1
    if s.t > 34 then late, nl = late + tr, nl + 1 end
    local e = s:energy()
    if e.total ~= e.total then bad = true end
  end}
  local c0 = os.clock()
  sim:run(18)
  local err, n = 0, 0
  for t = 19, 31 do
    sum, k = 0, 0
    sim:run(t)
    err, n = err + math.abs(sum / k - tref(t - 0.5)) / SIG, n + 1
  end
  sim:run(40)
  local cpu = os.clock() - c0
  local e = sim:energy()
  local x, body = sim:particles("position"), sim:particles("body")
  local amax, bmin = -1e9, 1e9
  for i = 1, #x.x do
    if body[i] == 2 then amax = math.max(amax, x.x[i])
    elseif body[i] == 3 then bmin = math.min(bmin, x.x[i]) end
  end
  return {w = e.cohesion / (GC * AREA), curve = err / n,
          res = e.residual / e.boundary_work, late = math.abs(late / nl) / SIG,
          gap = (bmin - amax) * cells - 0.5, cpu = cpu, bad = bad}
end

local function order(e1, e2, c1, c2) return math.log(e1 / e2) / math.log(c2 / c1) end

for _, sh in ipairs {{"linear", {12, 16, 24}}, {"bspline2", {12, 16, 24}}} do
  local shape, cells = sh[1], sh[2]
  V.case(string.format("pull apart, %s: sigma %g, delta_c %g, G_c %g", shape, SIG, DC, GC))
  local r = {}
  for i, c in ipairs(cells) do
    r[i] = pull(c, shape)
    local tag = string.format("%s, %d cells", shape, c)
    V.near(tag .. ": work of separation / (G_c A)", r[i].w, 1, 0.03)
    V.below(tag .. ": mean |grip traction - quasi-static| / sigma, t = 19..31", r[i].curve, 0.1)
    V.below(tag .. ": |residual| / work put in", math.abs(r[i].res), 0.01)
    V.below(tag .. ": |mean grip traction| / sigma once apart (t = 34..40)", r[i].late, 0.05)
    V.above(tag .. ": gap between the blocks / cell at the end (no burial)", r[i].gap, 0)
    V.holds(tag .. ": no NaN in the energy", not r[i].bad)
    V.info(tag .. ": CPU s", r[i].cpu)
  end
  local e = {}
  for i = 1, 3 do e[i] = math.abs(r[i].w - 1) end
  V.holds(shape .. ": the work's error falls with refinement (the finest's shown)",
          e[2] < e[1] and e[3] < e[2], e[3])
  V.info(shape .. ": observed order of the work's error, " .. cells[1] .. "->" .. cells[2],
         order(e[1], e[2], cells[1], cells[2]))
  V.info(shape .. ": observed order, " .. cells[2] .. "->" .. cells[3],
         order(e[2], e[3], cells[2], cells[3]))
end

V.case "what the law cannot do is refused"
local ok, msg = pcall(mvmpm.load, "scenarios/bond_pull.lua", {strength = SIG, energy = GC, shape = "gimp"})
V.holds("GIMP with bond_energy: refused, naming the field", not ok and msg:find("bond_energy") ~= nil)
print("  " .. tostring(msg):match("[^\n]*"))
ok, msg = pcall(mvmpm.load, "scenarios/bond_pull.lua", {strength = SIG, energy = 100 * GC, cells = 16})
V.holds("an opening at failure beyond half a cell: refused, naming file, line and field",
        not ok and msg:find("bond_pull.lua:%d+") ~= nil and msg:find("'bond'") ~= nil)
print("  " .. tostring(msg):match("[^\n]*"))
