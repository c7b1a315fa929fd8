-- Bonded interfaces, the longer runs (tests/heavy): the debond front of
-- scenarios/debond_front.lua with the fitted traction over a length of
-- the scene's, at 16 and 24 cells, and a bar bonded to a grip at rest,
-- ringing, its energy kept at 8, 16 and 32 cells and under USAVG.  The
-- bonded pull and the front with the default traction are in
-- tests/verify/bonds.lua; tests/verify/paths.lua runs the fitted front
-- at 16 cells under the sanitizers.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

-- The fitted traction averaged over a length of interface that is the
-- scene's, not the grid's (bond_length = 0.1 and 0.2, i.e. 1.6 and 3.2
-- cells at 16 cells per unit, 2.4 and 4.8 at 24): the length acts as a
-- process zone, the longer one a tougher interface, so its front runs
-- slower (at 16 cells the 0.2 one does not run at all: 3 cells are too
-- few to resolve it).  The speeds' convergence (16 to 48 cells) is in
-- studies/debond_front.lua.
V.case "a debond front with the fitted traction over a fixed length (scenarios/debond_front.lua)"
do
  local F = require "mvmpm.front"
  local v = {}
  for k, c in ipairs {16, 24} do
    v[k] = F.run {cells = c, traction = "fit", bond_length = 0.1}
    V.info(string.format("bond_length 0.1, %d cells: front speed / c_R", c), v[k])
    V.below(string.format("bond_length 0.1, %d cells: front speed / c_R (must not exceed 1)", c), v[k], 1.0)
    V.above(string.format("bond_length 0.1, %d cells: front speed / c_R (a front runs)", c), v[k], 0.5)
  end
  local tough = F.run {cells = 24, traction = "fit", bond_length = 0.2}
  V.info("bond_length 0.2, 24 cells: front speed / c_R", tough)
  V.above("bond_length 0.2, 24 cells: a front runs", tough, 0.3)
  V.below("bond_length 0.2 runs slower than 0.1 (24 cells)", tough, v[2])
end

-- A bar bonded to a grip at rest (a driven body), ringing in its first
-- fixed-free mode, v = 0.01 sin(pi s / 2L) (s from the grip, L = 2):
-- nothing does work on it, so its energy stays E0, and the bonded
-- impulses may dissipate a little but never give energy back.  Measured
-- before bond_remap took the drive's velocity at such nodes (bond.c):
-- +2.5 / +0.56 / +0.13 % of E0 gained by t = 40 at 16 / 32 / 64 cells,
-- booked as bonding -2.3 / -0.58 / -0.15 %; now +0.19 / -0.02 / -0.03 %,
-- bonding +0.08 / +0.013 / +0.004 % (64 cells: docs/verification.md)
V.case "a bar bonded to a grip at rest, ringing: its energy kept, 8 16 32 cells"
local function grip(cells, update)
  local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 0.5}}, cell = 1 / cells, t_end = 40, update = update,
    sides = {left = "free", right = "free", bottom = "periodic", top = "periodic"}}
  local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  sim:body {name = "grip", shape = mvmpm.rect {lo = {0.25, 0}, hi = {0.5, 0.5}}, material = m,
            driven = {0, 0}}
  sim:body {name = "bar", shape = mvmpm.rect {lo = {0.5, 0}, hi = {2.5, 0.5}}, material = m, bond = 1,
            velocity = function(x) return 0.01 * math.sin(math.pi * (x - 0.5) / 4), 0 end}
  local e0 = sim:energy().total
  local worst = 0
  sim:every {time = 0.5, fn = function(s) worst = math.max(worst, math.abs(s:energy().total / e0 - 1)) end}
  sim:run()
  local e = sim:energy()
  return {dE = e.total / e0 - 1, worst = worst, bond = e.bonding / e0, res = e.residual / e0}
end
local gb = {}
for i, c in ipairs {8, 16, 32} do
  local r = grip(c)
  gb[i] = r
  local tag = string.format("%d cells", c)
  V.info(tag .. ": E(40)/E0 - 1", r.dE)
  -- 8 cells (the bar 4 cells high): the bonded impulses take 0.65 % of
  -- E0 by t = 40 and the reading swings 1.2 %; 2 % there, 1 % finer
  V.below(tag .. ": largest |E/E0 - 1| over t = 0 .. 40", r.worst, c == 8 and 0.02 or 0.01)
  V.above(tag .. ": bonding loss / E0 (never energy given back)", r.bond, 0)
  V.below(tag .. ": |residual| / E0", math.abs(r.res), 0.005)
end
V.below("16 and 32 cells: |E(40)/E0 - 1|", math.max(math.abs(gb[2].dE), math.abs(gb[3].dE)), 0.005)
V.holds("the bonded impulses' loss falls 8 -> 16 -> 32 cells",
        gb[3].bond < gb[2].bond and gb[2].bond < gb[1].bond, gb[3].bond / gb[1].bond)

-- the same under USAVG, whose first half-step holds the bonded slots
-- beside the grip at its velocity (usf.c): measured +0.02 % at 16 cells,
-- bonding +0.08 % (+1.1 % gained without the hold)
do
  local r = grip(16, "usavg")
  V.below("USAVG, 16 cells: |E(40)/E0 - 1|", math.abs(r.dE), 0.005)
  V.below("USAVG, 16 cells: largest |E/E0 - 1| over t = 0 .. 40", r.worst, 0.01)
  V.above("USAVG, 16 cells: bonding loss / E0", r.bond, 0)
  V.below("USAVG, 16 cells: |residual| / E0", math.abs(r.res), 0.005)
end
