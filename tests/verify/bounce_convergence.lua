-- The frictionless bouncing disc (scenarios/cylinder_bounce.lua) refined:
-- 8, 16 and 32 cells across the diameter, per scheme.  Walls do no work,
-- so the energy after three impacts (t = 36) should equal the discrete
-- initial energy, better the finer the grid.  Error: E/E0 - 1; observed
-- order: log2 of the error's ratio between resolutions.  Restitution:
-- -vx after the first impact / vx before (t = 10).
--
-- The goal for the default scheme: |error| <= 2 %, 1 %, 0.5 % at 8, 16,
-- 32 cells, falling, and restitution >= 0.9 at 16 cells.  No scheme
-- meets all of it (docs/accuracy.md); what each misses is printed as
-- info with the measured number.  The defaults (quadratic B-splines,
-- MUSL, FLIP) fall 8 -> 16 -> 32 cells; linear hats under MUSL gain
-- energy in free flight as the grid is refined and carry the load-time
-- warning (sim.advice).  USAVG (update = "usavg") removes most of that
-- gain; GIMP under USAVG is the closest to the goal.  GIMP under MUSL
-- and XPIC are kept for comparison (GIMP MUSL's growth beyond 16 cells
-- and every scheme's beyond 32 are in studies/bounce.lua).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local function bounce(o, cells)
  local p = {cells = cells, t_end = 36}
  for k, v in pairs(o) do p[k] = v end
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", p)
  local disc = sim:bodies()[1]
  local e0 = sim:energy().total
  sim:run(10)
  local e1 = -disc:diag().vx / 0.1
  sim:run(36)
  return sim:energy().total / e0 - 1, e1, sim
end

local function study(name, o, sizes)
  local r = {}
  sizes = sizes or {8, 16, 32}
  for _, c in ipairs(sizes) do
    local d, e, sim = bounce(o, c)
    r[c] = {d = d, e = e, sim = sim}
    V.info(string.format("%s, %d cells: energy change E/E0 - 1", name, c), d)
    V.info(string.format("%s, %d cells: restitution, impact 1", name, c), e)
  end
  for k = 2, #sizes do
    local a, b = sizes[k - 1], sizes[k]
    V.info(string.format("%s: observed order %d -> %d", name, a, b),
      math.log(math.abs(r[a].d) / math.abs(r[b].d), 2))
  end
  return r
end

-- the goal: printed as met or not, with the measured number
local function goal(r, name)
  local lim = {[8] = 0.02, [16] = 0.01, [32] = 0.005}
  for _, c in ipairs({8, 16, 32}) do
    if r[c] then
      V.info(string.format("%s, goal |E/E0 - 1| <= %g at %d cells: %s", name,
        lim[c], c, math.abs(r[c].d) <= lim[c] and "met" or "NOT met"), r[c].d)
    end
  end
  V.info(string.format("%s, goal restitution >= 0.9 at 16 cells: %s", name,
    r[16].e >= 0.9 and "met" or "NOT met"), r[16].e)
end

V.case "the defaults: quadratic B-splines, MUSL, FLIP"
local def = study("defaults", {})
local s8 = def[8].sim
V.holds("the defaults are quadratic B-splines, MUSL, pure FLIP",
  s8.shape == "bspline2" and s8.update == "musl" and s8.transfer == "flip" and s8.flip == 1)
goal(def, "defaults")
V.holds("no warning for the defaults", s8.advice == nil)
-- measured -7.4 / -3.8 / -1.36 %: the impacts' loss falls at order 1 to
-- 1.5.  (With the stress rate written for the Cauchy stress, as before,
-- the same runs read -5.7 / -2.9 / +0.51 %: that form made energy in
-- the compressed contact, +1.7 to +1.9 % of E0 over the three impacts,
-- docs/algorithm.md section 12, and the 1 % asserted at 32 cells was met
-- through it; the goal lines above print what is met now.)
V.below("error falls 8 -> 16 cells", math.abs(def[16].d), math.abs(def[8].d))
V.below("error falls 16 -> 32 cells", math.abs(def[32].d), math.abs(def[16].d))
-- frictionless static walls and an elastic material that stores exactly
-- the work done on it: the total can only fall (the node rule's stops)
V.below("never gains: largest E/E0 - 1 at 8, 16, 32 cells",
  math.max(def[8].d, def[16].d, def[32].d), 0)
V.above("restitution at 32 cells", def[32].e, 0.9)

-- The defaults with the disc seeded by volume = "cut" (sim:body): the
-- particles take the disc's area inside their sub-cells (the lattice
-- count gives the disc 3.5 / 1.0 / 0.3 % too much mass at 8 / 16 / 32
-- cells, all of it at its rim).  Asserted: the error falls with the
-- grid, never gains, and is below the lattice count's at every size.
V.case "the defaults with volume = \"cut\""
local cut = study("cut", {volume = "cut"})
goal(cut, "cut")
V.below("cut: error falls 8 -> 16 cells", math.abs(cut[16].d), math.abs(cut[8].d))
V.below("cut: error falls 16 -> 32 cells", math.abs(cut[32].d), math.abs(cut[16].d))
V.below("cut: never gains: largest E/E0 - 1 at 8, 16, 32 cells",
  math.max(cut[8].d, cut[16].d, cut[32].d), 0)
for _, c in ipairs {8, 16, 32} do
  V.below(string.format("cut: |error| below the lattice count's, %d cells", c),
    math.abs(cut[c].d), math.abs(def[c].d))
end

V.case "linear hats, MUSL, FLIP (the defaults before B-splines)"
local lin = study("linear MUSL", {shape = "linear"})
goal(lin, "linear MUSL")
-- a scheme whose energy error grows with refinement must say so at load
local grows = math.abs(lin[32].d) > math.abs(lin[16].d)
V.holds("error grows 16 -> 32 cells only with the warning given",
  not grows or lin[32].sim.advice ~= nil, lin[32].d)

V.case "linear hats, USAVG, FLIP: the free-flight gain removed"
local lu = study("linear USAVG", {shape = "linear", update = "usavg"})
goal(lu, "linear USAVG")
V.holds("update = \"usavg\" is taken", lu[8].sim.update == "usavg")
-- -5.3 / -2.6 / -0.57 % (the Cauchy form read -5.2 / -1.2 / +1.4 %)
V.below("error falls 8 -> 16 cells", math.abs(lu[16].d), math.abs(lu[8].d))
V.below("error falls 16 -> 32 cells", math.abs(lu[32].d), math.abs(lu[16].d))
V.below("|energy change|, 32 cells", math.abs(lu[32].d), 0.02)
-- MUSL's gain at 32 cells is made between impacts; USAVG's symmetric
-- step keeps a tenth of it at most
V.below("|energy change| at 32 cells, USAVG / MUSL", math.abs(lu[32].d) / math.abs(lin[32].d), 0.1)
-- linear hats still gain a little per cell crossed (+1.4 % at 32, +3.3 %
-- at 48 cells): the warning stays
V.holds("error grows 16 -> 32 cells only with the warning given",
  math.abs(lu[32].d) <= math.abs(lu[16].d) or lu[32].sim.advice ~= nil, lu[32].d)

V.case "GIMP, USAVG, FLIP: the closest to the goal"
local gu = study("GIMP USAVG", {shape = "gimp", update = "usavg"})
goal(gu, "GIMP USAVG")
V.holds("no warning for GIMP under USAVG", gu[8].sim.advice == nil)
V.below("error falls 8 -> 16 cells", math.abs(gu[16].d), math.abs(gu[8].d))
V.below("error falls 16 -> 32 cells", math.abs(gu[32].d), math.abs(gu[16].d))
V.below("|energy change|, 32 cells", math.abs(gu[32].d), 0.01)
-- restitution at 16 cells 0.891 (goal 0.9, printed above; 0.90 under the
-- Cauchy form)
V.above("restitution at 32 cells", gu[32].e, 0.9)

V.case "GIMP, USAVG, FLIP, walls by the gap at the step's end (contact_gap = \"step\")"
-- the walls stop only the part of a node's approach that would carry the
-- material past the wall line within the step, as contact does between
-- bodies.  Under the Cauchy form the first step of each impact took less
-- (-2.2 -> -1.5 % at 8 cells); with the material's energy exact it loses
-- more than "touch" at 8 cells (-7.2 % against -5.6 %), printed
local gs = study("GIMP USAVG, gap step", {shape = "gimp", update = "usavg", contact_gap = "step"})
goal(gs, "GIMP USAVG, gap step")
V.below("error falls 8 -> 16 cells", math.abs(gs[16].d), math.abs(gs[8].d))
V.below("error falls 16 -> 32 cells", math.abs(gs[32].d), math.abs(gs[16].d))
V.info("|energy change|, 8 cells, over \"touch\"'s", math.abs(gs[8].d) / math.abs(gu[8].d))
V.below("|energy change|, 32 cells", math.abs(gs[32].d), 0.01)

V.case "GIMP, MUSL, FLIP"
local gimp = study("GIMP MUSL", {shape = "gimp", update = "musl"}, {8, 16})
V.holds("the warning for GIMP under MUSL (grows from 16 cells)",
  gimp[8].sim.advice ~= nil)
-- -2.0 / -1.3 % at 8 / 16 cells, restitution 0.890 at 16 (the Cauchy
-- form: +1.2 / +0.14 %, 0.90)
goal(gimp, "GIMP MUSL")
V.below("error falls 8 -> 16 cells", math.abs(gimp[16].d), math.abs(gimp[8].d))
V.below("|energy change|, 16 cells", math.abs(gimp[16].d), 0.02)

V.case "XPIC(2), GIMP, MUSL: noise removed, vibration damped"
local xo = {shape = "gimp", update = "musl", transfer = "xpic"}
local x8, xe8 = bounce(xo, 8)
local x16, xe16, xs = bounce(xo, 16)
V.holds("transfer = \"xpic\" is taken", xs.transfer == "xpic")
V.info("XPIC(2) GIMP, 8 cells: energy change", x8)
V.info("XPIC(2) GIMP, 16 cells: energy change", x16)
V.info("XPIC(2) GIMP, 8 cells: restitution", xe8)
V.info("XPIC(2) GIMP, 16 cells: restitution", xe16)
-- XPIC, like PIC, damps the disc's ringing after each impact (energy the
-- frictionless walls leave to it), less as the grid is refined; it never
-- gains energy
V.below("XPIC never gains energy (16 cells)", x16, 0)
V.below("XPIC's loss falls 8 -> 16 cells", math.abs(x16), math.abs(x8))
local ok, err = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                                  transfer = "xpic", xpic = 4})
V.holds("xpic = 4 is refused with the allowed orders",
  not ok and tostring(err):find("xpic") ~= nil and tostring(err):find("3") ~= nil, 4, tostring(err))
