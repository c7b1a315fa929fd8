-- Penalty walls (sim.wall_contact = "penalty", src/core/wall_penalty.c):
-- frictionless walls that push each particle passing the wall line with
-- a spring, k = wall_stiffness * (K + 4G/3) * (2l)^(DIM-2), instead of
-- stopping the nodes that approach.
--
-- 1. The report's frictionless bounce (scenarios/cylinder_bounce.lua,
--    the default shape) at 8, 16, 32 cells per diameter.  Reference: the
--    walls do no work, so E/E0 = 1 after the first impact (t = 10) and
--    after three (t = 36); the goal of the contact work is <= 2 %, 1 %,
--    0.5 % at 8, 16, 32 cells.  Measured with the node rule (the
--    default): -3.3 / -1.7 / -0.6 % after the first impact, -7.4 / -3.8
--    / -1.4 % after three (tests/verify/bounce_convergence.lua).  (With
--    the stress rate written for the Cauchy stress, which made energy in
--    the compressed contact, every number here read 1 to 2 % of E0
--    higher: docs/algorithm.md section 12.)
-- 2. Momentum: the walls' forces (sim:wall_force) are the only external
--    ones, so the momentum's change is their impulse, to round-off with
--    no mass cutoff.
-- 3. A block set on the floor under gravity: the floor carries its
--    weight, and its vibration stays small and is not pumped (MUSL
--    holds the springs' nodes when gravity is on: wall_penalty_hold).
-- 4. The 3-D sphere bounce (scenarios/sphere_bounce.lua), 8 cells.
-- 5. One and two threads give the same bits; bad input is refused.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local W = dofile("tests/tools/walls.lua")
local function bounce(cells, o) return W.bounce(mvmpm, cells, "penalty", o) end

V.case "frictionless bounce, penalty walls, default shape: 8, 16, 32 cells"
local lim = {[8] = 0.02, [16] = 0.01, [32] = 0.005}
local res = {}
for _, c in ipairs {8, 16, 32} do
  local r = bounce(c)
  res[c] = r
  -- measured -1.40 / -0.69 / -0.41 % (node rule -3.3 / -1.7 / -0.6 %);
  -- the Cauchy form read -0.51 / -0.19 / -0.20 %, 1 % was asserted
  V.info(string.format("%d cells: E/E0 - 1 after the first impact", c), r.first)
  -- measured -3.8 / -1.7 / -1.1 %: the goal is not met (the Cauchy form
  -- read -1.42 / -0.31 / +0.50 %)
  V.info(string.format("%d cells: goal |E/E0 - 1| <= %g after three impacts: %s", c, lim[c],
                       math.abs(r.three) <= lim[c] and "met" or "NOT met"), r.three)
  -- static frictionless walls and a material that stores exactly the work
  -- done on it: the springs give back what they take, so the total ends
  -- below E0 (the grid's loss), never above
  V.below(string.format("%d cells: E/E0 - 1 after three impacts <= 0 (no energy made)", c), r.three, 0)
  V.info(string.format("%d cells: restitution, impact 1", c), r.rest)
  V.info(string.format("%d cells: budget residual / E0 (the springs' energy in the total)", c),
          r.residual)
  V.holds(string.format("%d cells: no particle held at a wall (spring stiff enough)", c), r.held == 0, r.held)
end
V.below("first impact's loss falls 8 -> 16 cells", math.abs(res[16].first), math.abs(res[8].first))
V.below("first impact's loss falls 16 -> 32 cells", math.abs(res[32].first), math.abs(res[16].first))
V.below("three impacts' loss falls 8 -> 16 cells", math.abs(res[16].three), math.abs(res[8].three))
V.below("three impacts' loss falls 16 -> 32 cells", math.abs(res[32].three), math.abs(res[16].three))
V.info("observed order of the three impacts' error, 8 -> 16",
       math.log(math.abs(res[8].three) / math.abs(res[16].three), 2))
V.info("observed order of the three impacts' error, 16 -> 32",
       math.log(math.abs(res[16].three) / math.abs(res[32].three), 2))
V.holds("no warning for the default shape with penalty walls", res[8].sim.advice == nil)

V.case "against the node rule at 8 cells (the same scene)"
do
  local p = {cells = 8, t_end = 10}
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", p)
  local e0 = sim:energy().total
  sim:run(10)
  local node = sim:energy().total / e0 - 1
  V.info("node rule, 8 cells: E/E0 - 1 after the first impact", node)
  -- measured 0.42 of it (0.22 under the Cauchy form)
  V.below("penalty loses less than half the node rule at the first impact",
          math.abs(res[8].first), math.abs(node) / 2)
end

V.case "momentum: the change is the walls' impulse"
W.momentum(mvmpm, V, "penalty")

V.case "a block set on the floor under gravity: carried, and not pumped"
local function block(remap)
  local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 1}}, cell = 1 / 16, sides = "wall",
                         t_end = 12, gravity = {0, -1}, wall_contact = "penalty", wall_remap = remap}
  local b = sim:body {shape = mvmpm.rect {lo = {0.5, 0}, hi = {1.5, 0.5}},
                      material = mvmpm.elastic {K = 100, G = 50, density = 1}}
  local r = {w = b:mass(), fy = 0, T = 0, early = 0, late = 0}
  sim:every {steps = 1, fn = function(s)
    local ke = s:energy().kinetic
    if s.t > 3 and s.t <= 6 then
      local _, f = s:wall_force("bottom")
      r.fy, r.T = r.fy + f * s.dt, r.T + s.dt
      r.early = math.max(r.early, ke)
    elseif s.t > 9 then
      r.late = math.max(r.late, ke)
    end
  end}
  sim:run()
  r.held, r.x = sim:energy().wall_held, b:diag().x
  return r
end
do
  local r = block()  -- "auto": held, since gravity is on
  V.near("time mean of the floor's force / weight, t = 3 .. 6", r.fy / r.T / r.w, 1, 0.01)
  -- gravity switched on at t = 0 sets the block vibrating; a load put
  -- on a linear body at once gives it at most its static strain energy
  -- U as kinetic energy.  U of the block's own sag, uniaxial in plane
  -- strain (an estimate: the sides are free): (rho g)^2 H^3 W / (6 E'),
  -- E' = E / (1 - nu^2); measured 0.29 U
  local E, nu = 9 * 100 * 50 / (300 + 50), (300 - 100) / (2 * 350)
  local U = 0.5 ^ 3 * 1 / (6 * E / (1 - nu * nu))
  V.below("largest kinetic energy / static strain energy U, t = 3 .. 6", r.early / U, 1)
  -- measured 1.8e-5 late against 3.2e-4 early
  V.below("largest kinetic energy, t = 9 .. 12, / t = 3 .. 6 (not pumped)", r.late / r.early, 1)
  V.holds("no particle held", r.held == 0, r.held)
  V.below("block's centre within a hundredth of a cell of its start (x)", math.abs(r.x - 1), 0.01 / 16)
  local f = block("free")
  V.info("the same, wall_remap = \"free\": kinetic energy t = 9 .. 12 / t = 3 .. 6 (pumped)",
         f.late / f.early)
end

V.case "3-D: the sphere bounce at 8 cells"
do
  local sim = mvmpm.load("scenarios/sphere_bounce.lua", {cells = 8, wall_contact = "penalty"})
  local e0 = sim:energy().total
  sim:run(14)
  local e = sim:energy()
  -- measured +0.92 % (node rule -6.2 %)
  V.below("3-D, 8 cells: |E/E0 - 1| after three impacts", math.abs(e.total / e0 - 1), 0.02)
  V.holds("3-D: no particle held", e.wall_held == 0, e.wall_held)
end

V.case "threads and input"
do
  local function run(th)
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua", {cells = 8, t_end = 8, wall_contact = "penalty"})
    sim.threads = th
    sim:run(8)
    local e = sim:energy()
    return e.total, e.wall_spring, e.px
  end
  local a1, b1, c1 = run(1)
  local a2, b2, c2 = run(2)
  V.holds("1 and 2 threads: the same energy, spring energy and momentum, bit for bit",
          a1 == a2 and b1 == b2 and c1 == c2)
end
W.refusals(mvmpm, V, "penalty")
do
  local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, wall_contact = "penalty", sides = "wall"}
  local ok, msg = pcall(s.wall_nodes, s, "bottom")
  V.holds("sim:wall_nodes under penalty walls says why and what to use",
          not ok and msg:find("wall_force", 1, true) ~= nil)
end
