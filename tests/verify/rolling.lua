-- Contact: rolling and spin-up.  An elastic disc (R = 0.5, K = 100,
-- G = 50, density 1) on an incline, the incline being the floor wall with
-- gravity rotated by theta (g = 1), periodic along it, at 8, 16 and 32
-- cells per diameter (FLIP, MUSL, 2 x 2 particles per cell), with linear
-- hats and with GIMP, the walls acting per contact patch
-- (wall_contact = "patch", docs/algorithm.md §9):
--   sliding (theta 30 deg, mu 0.1 < tan(theta)/3):
--     a = g (sin - mu cos),  R alpha = 2 mu g cos
--   rolling (theta 25 deg, mu 0.5 >= tan(theta)/3):
--     a = (2/3) g sin,  alpha = a / R
-- Slopes of the centroid velocity and of the spin are fitted over
-- t = 0.5 .. 2, after the settling.  Targets: sliding a within 1 %, its
-- spin-up within 5 % from 16 cells; rolling a within 2 % at 8 cells and
-- 1 % at 16.  Met with 2 x 2 particles: all but rolling at 8 cells
-- (about 7 % short: the friction acts on the nodes of the wall line,
-- whose material lies a fraction of a cell above the contact point, so
-- the disc rolls on a slightly smaller radius) and rolling at 16 cells
-- with linear hats (1.4 %).  With 4 x 4 particles, GIMP and APIC, the
-- rolling targets are met at 8 and 16 cells (asserted).  The
-- misses are printed beside the target.  The node rule (each wall node
-- stopped alone) is printed for comparison at 16 cells: it rocks the disc
-- on the flat of its lowest particle row (docs/verification.md).
local V = require "mvmpm.verify"
local I = require "mvmpm.incline"

local g, R = I.g, I.R

local function incline(cells, shape, deg, mu, o)
  o = o or {}
  return I.run {cells = cells, shape = shape, deg = deg, mu = mu, w0 = o.w0, ppc = o.ppc,
                wall_contact = o.wall or "patch"}
end

local function order(e)
  if e[1] > 0 and e[3] > 0 then return math.log(e[1] / e[3], 2) / 2 end
  return 0 / 0
end

local function target(name, err, tol)
  V.info(string.format("%s: error %.4f, target %g: %s", name, err, tol,
                       err <= tol and "met" or "NOT met"), err)
end

local cells = {8, 16, 32}

for _, shape in ipairs {"linear", "gimp"} do
  V.case("sliding disc (theta 30 deg, mu 0.1), " .. shape .. ": acceleration, energy, spin-up")
  local sal = {}
  for k, c in ipairs(cells) do
    local r = incline(c, shape, 30, 0.1)
    local a_ref = g * (math.sin(r.th) - 0.1 * math.cos(r.th))
    local al_ref = 2 * 0.1 * g * math.cos(r.th) / R
    sal[k] = math.abs(r.alpha / al_ref - 1)
    V.near(string.format("sliding a / (g (sin - mu cos)), %d cells", c), r.a / a_ref, 1, 0.01)
    V.near(string.format("energy residual / |potential change|, %d cells", c),
           r.e.residual / math.abs(r.e.potential), 0, 0.01)
    V.above(string.format("friction work dissipated (> 0), %d cells", c), r.e.dissipated, 1e-3)
    if c >= 16 then
      V.near(string.format("spin-up alpha / (2 mu g cos / R), %d cells", c), r.alpha / al_ref, 1, 0.05)
    else
      V.info(string.format("spin-up alpha / (2 mu g cos / R), %d cells", c), r.alpha / al_ref)
    end
  end
  V.info("sliding spin-up error, observed order (8 -> 32)", order(sal))

  V.case("rolling disc (theta 25 deg, mu 0.5), " .. shape .. ": acceleration, no slip, no hop")
  local ra = {}
  for k, c in ipairs(cells) do
    local r = incline(c, shape, 25, 0.5)
    local a_ref = 2 / 3 * g * math.sin(r.th)
    ra[k] = math.abs(r.a / a_ref - 1)
    V.info(string.format("rolling a / ((2/3) g sin), %d cells", c), r.a / a_ref)
    if c == 8 then target("rolling a, 8 cells", ra[k], 0.02)
    elseif c == 16 then target("rolling a, 16 cells", ra[k], 0.01) end
    if c >= 16 then
      -- the 8-cell target's tolerance, held from 16 cells on
      V.near(string.format("rolling a / ((2/3) g sin), %d cells", c), r.a / a_ref, 1, 0.02)
    end
    -- rolling without slip: R alpha = a.  Held at 16 cells; at 32 GIMP's
    -- disc slips (a 1.7 % high, spin 3.3 % low: R alpha / a = 0.95, not
    -- yet explained), printed
    if c == 16 then
      V.near(string.format("R alpha / a (no slip), %d cells", c), r.alpha * R / r.a, 1, 0.03)
    else
      V.info(string.format("R alpha / a (no slip), %d cells", c), r.alpha * R / r.a)
    end
    V.below(string.format("largest hop (centre above R), %d cells", c), r.hop, 0.005)
    V.near(string.format("energy residual / |potential change|, %d cells", c),
           r.e.residual / math.abs(r.e.potential), 0, 0.01)
  end
  V.info("rolling acceleration error, observed order (8 -> 32)", order(ra))
end

V.case "rolling disc, 4 x 4 particles per cell: the targets (2 % at 8 cells, 1 % at 16)"
-- a lower mass centre of the wall nodes' material (see the header)
for _, c in ipairs {8, 16} do
  local r = I.run {cells = c, shape = "gimp", transfer = "apic", ppc = 4, deg = 25, mu = 0.5,
                   wall_contact = "patch"}
  local a_ref = 2 / 3 * g * math.sin(r.th)
  V.near(string.format("GIMP APIC, 4 x 4: rolling a / ((2/3) g sin), %d cells", c), r.a / a_ref, 1,
         c == 8 and 0.02 or 0.01)
end
do
  local r = incline(16, "linear", 25, 0.5, {ppc = 4})
  V.info("linear FLIP, 4 x 4: rolling a / ((2/3) g sin), 16 cells", r.a / (2 / 3 * g * math.sin(r.th)))
end

V.case "frictionless spinning disc resting under gravity: the spin is kept"
for _, shape in ipairs {"linear", "gimp"} do
  for _, c in ipairs(cells) do
    local r = incline(c, shape, 0, 0, {w0 = -0.2})
    -- a round disc on a frictionless floor keeps omega = 0.2
    V.below(string.format("%s: spin range over t = 0..2 / 0.2, %d cells", shape, c),
            (r.wmax - r.wmin) / 0.2, 0.5)
  end
end

V.case "the patch rule is deterministic: 1 and 2 threads give the same bits"
do
  local a = I.run {cells = 8, shape = "gimp", deg = 25, mu = 0.5, wall_contact = "patch", threads = 1}
  local b = I.run {cells = 8, shape = "gimp", deg = 25, mu = 0.5, wall_contact = "patch", threads = 2}
  V.holds("rolling a, spin and residual equal at 1 and 2 threads",
          a.a == b.a and a.alpha == b.alpha and a.e.residual == b.e.residual, a.a - b.a)
end

V.case "the node rule, for comparison (16 cells, linear hats)"
do
  local s = incline(16, "linear", 30, 0.1, {wall = "node"})
  local r = incline(16, "linear", 25, 0.5, {wall = "node"})
  local z = incline(16, "linear", 0, 0, {wall = "node", w0 = -0.2})
  V.info("node rule: sliding spin-up / reference", s.alpha / (2 * 0.1 * g * math.cos(s.th) / R))
  V.info("node rule: rolling a / reference", r.a / (2 / 3 * g * math.sin(r.th)))
  V.info("node rule: frictionless spin range / 0.2", (z.wmax - z.wmin) / 0.2)
end

V.case "friction at the wall line (wall_contact = \"couple\"), linear hats"
-- On the patch alone sliding friction acts at the mass centre of the
-- material the wall line's nodes move (0.4 cell above the contact with
-- linear hats), and the spin-up at 8 cells falls 17 % short; the couple
-- puts it at the wall line.  Sticking is as under "patch", so rolling
-- gains only from the steps that slide.  At 32 cells the spin-up
-- overshoots (1.04 linear, 1.07 GIMP: docs/verification.md), printed.
do
  for _, c in ipairs {8, 16} do
    local s = I.run {cells = c, shape = "linear", deg = 30, mu = 0.1, wall_contact = "couple"}
    local r = I.run {cells = c, shape = "linear", deg = 25, mu = 0.5, wall_contact = "couple"}
    local al_ref = 2 * 0.1 * g * math.cos(s.th) / R
    V.near(string.format("couple: sliding spin-up alpha / (2 mu g cos / R), %d cells", c),
           s.alpha / al_ref, 1, 0.05)
    V.near(string.format("couple: sliding a / (g (sin - mu cos)), %d cells", c),
           s.a / (g * (math.sin(s.th) - 0.1 * math.cos(s.th))), 1, 0.01)
    V.near(string.format("couple: energy residual / |potential change|, %d cells", c),
           s.e.residual / math.abs(s.e.potential), 0, 0.01)
    local ratio = r.a / (2 / 3 * g * math.sin(r.th))
    V.info(string.format("couple: rolling a / ((2/3) g sin), %d cells", c), ratio)
    target(string.format("couple: rolling a, %d cells", c), math.abs(ratio - 1), c == 8 and 0.02 or 0.01)
  end
  local a = I.run {cells = 8, shape = "linear", deg = 30, mu = 0.1, wall_contact = "couple", threads = 1}
  local b = I.run {cells = 8, shape = "linear", deg = 30, mu = 0.1, wall_contact = "couple", threads = 2}
  V.holds("couple: sliding a, spin and residual equal at 1 and 2 threads",
          a.a == b.a and a.alpha == b.alpha and a.e.residual == b.e.residual, a.a - b.a)
end

V.case "a disc thrown spinning into a box of frictional walls under gravity: the energy stays below the work put in"
-- A disc (R = 0.2, K = 10, G = 6) thrown at (0.8, -0.6) spinning at 2
-- into the unit box, walls with friction 0.3, g = 1, to t = 1.5: it
-- bounces, then slides and rolls on the floor.  Nothing makes energy, so
-- the total must stay at or below the work put in (initial + boundary);
-- friction's booked work must not be negative.  Node by node and per
-- patch that holds; with the couple the total rose 9.3 / 15.4 / 14.9 %
-- above it at 24 / 32 / 48 cells across the box (B-splines; linear hats
-- 6.7 / 9.8 / 9.7 %), friction booking negative work (-0.12 / -0.17 /
-- -0.19 of the energy): its two impulses move the slip at the wall line
-- several times as much as the patch's mean velocity, on which mu N and
-- the slide test are judged, so mu N can reverse that slip within a
-- step.  Capping the impulse at what stops the wall line's slip removed
-- the gain but let the rolling discs above slip (R alpha / a 0.80-0.90
-- at 8 cells), as stopping that slip always has.  So the couple is
-- warned of (sim.wall_advice) and its excess printed.
do
  local mvmpm = require "mvmpm"
  local function throw(rule, cells)
    local sim = mvmpm.sim {wall_contact = rule, domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / cells,
                           t_end = 1.5, sides = {"wall", friction = 0.3}, gravity = {0, -1}}
    sim:body {shape = mvmpm.disk {center = {0.5, 0.4}, radius = 0.2},
              material = mvmpm.elastic {K = 10, G = 6, density = 1},
              velocity = {0.8, -0.6}, angular_velocity = 2}
    local peak, scale = 0, 0
    sim:every {steps = 1, fn = function(s)
      local e = s:energy()
      local put = e.initial + e.boundary_work
      scale = math.max(scale, math.abs(put), e.total)
      peak = math.max(peak, e.total - put)
    end}
    sim:run()
    return peak / scale, sim:energy().dissipated / scale, sim
  end
  for _, rule in ipairs {"node", "patch", "couple"} do
    for _, c in ipairs {16, 32} do
      local peak, diss, sim = throw(rule, c)
      local what = string.format("%s, %d cells: ", rule, c)
      if rule == "couple" then
        V.info(what .. "total above the work put in, at its peak (0 wanted)", peak)
        V.info(what .. "friction's booked work / energy (>= 0 wanted)", diss)
        V.holds(what .. "warned of (sim.wall_advice names the couple)",
                sim.wall_advice ~= nil and sim.wall_advice:find("couple", 1, true) ~= nil, 0, sim.wall_advice)
      else
        V.below(what .. "total above the work put in, at its peak", peak, 1e-3)
        V.above(what .. "friction's booked work / energy", diss, 0)
      end
    end
  end
end

-- What a scene that names no rule gets: B-splines, pure FLIP, and
-- wall_contact = "auto", which takes the patch rule for the round disc at
-- the frictional wall.  Targets as above: sliding a within 1 % and its
-- spin-up within 5 % at 16 cells, rolling a within 2 % at 8 cells and 1 %
-- at 16 (printed as met or not); asserted: sliding a within 1 % at every
-- size, the spin-up within 5 % at 16 cells, rolling within 2 % from 16
-- cells on and within 1 % at 32, the budget within 1 % of the potential
-- energy released.  CPU seconds of the two runs are printed.
-- the sliding and the rolling run of one scheme at c cells (volume: the
-- disc's, sim:body), their shared rows printed and asserted under tag
local function pair(c, tag, volume)
  local t0 = os.clock()
  local s = I.run {cells = c, deg = 30, mu = 0.1, volume = volume}
  local r = I.run {cells = c, deg = 25, mu = 0.5, volume = volume}
  local cpu = os.clock() - t0
  local a_s = g * (math.sin(s.th) - 0.1 * math.cos(s.th))
  local al_ref = 2 * 0.1 * g * math.cos(s.th) / R
  local a_r = 2 / 3 * g * math.sin(r.th)
  local o = {spin = s.alpha / al_ref, roll = r.a / a_r, slip = r.alpha * R / r.a}
  o.se, o.re = math.abs(o.spin - 1), math.abs(o.roll - 1)
  V.near(string.format("%s: sliding a / (g (sin - mu cos)), %d cells", tag, c), s.a / a_s, 1, 0.01)
  V.info(string.format("%s: R alpha / a (no slip), %d cells", tag, c), o.slip)
  for _, x in ipairs {s, r} do
    V.near(string.format("%s: energy residual / |potential change|, %d cells", tag, c),
           x.e.residual / math.abs(x.e.potential), 0, 0.01)
  end
  V.info(string.format("%s: CPU s of the two runs, %d cells", tag, c), cpu)
  return o
end

local def_se, def_re = {}, {} -- the defaults' errors, for the cut volumes below
V.case "the defaults (B-splines, FLIP, wall_contact = \"auto\"): sliding and rolling"
for k, c in ipairs(cells) do
  local o = pair(c, "defaults")
  def_se[k], def_re[k] = o.se, o.re
  if c == 16 then
    V.near(string.format("defaults: spin-up alpha / (2 mu g cos / R), %d cells", c), o.spin, 1, 0.05)
  else
    V.info(string.format("defaults: spin-up alpha / (2 mu g cos / R), %d cells", c), o.spin)
  end
  if c == 8 then target("defaults: rolling a, 8 cells", o.re, 0.02)
  elseif c == 16 then target("defaults: rolling a, 16 cells", o.re, 0.01) end
  if c >= 16 then
    V.near(string.format("defaults: rolling a / ((2/3) g sin), %d cells", c), o.roll, 1,
           c == 16 and 0.02 or 0.01)
  else
    V.info(string.format("defaults: rolling a / ((2/3) g sin), %d cells", c), o.roll)
  end
end
V.info("defaults: sliding spin-up error, observed order (8 -> 32)", order(def_se))
V.info("defaults: rolling acceleration error, observed order (8 -> 32)", order(def_re))

-- The defaults with the disc seeded by volume = "cut" (sim:body): the
-- particles take the disc's area inside their sub-cells, so the disc has
-- the continuum's mass and inertia (the lattice count gives I = 0.519 /
-- 0.505 / 0.502 m R^2 at 8 / 16 / 32 cells, for which a rigid disc rolls
-- at 0.988 / 0.996 / 0.999 of (2/3) g sin).  Asserted: the spin-up and
-- the rolling acceleration nearer the rigid disc's than the lattice
-- count's at 8 cells, the spin-up at 16 too, and the rows the defaults
-- assert at 16 cells; at 32 cells the rolling disc slips (R alpha / a
-- 0.96) and runs 1.3 % fast: printed.
V.case "the defaults with volume = \"cut\": sliding and rolling"
for k, c in ipairs(cells) do
  local o = pair(c, "cut", "cut")
  V.info(string.format("cut: spin-up alpha / (2 mu g cos / R), %d cells", c), o.spin)
  V.info(string.format("cut: rolling a / ((2/3) g sin), %d cells", c), o.roll)
  if c == 8 then
    target("cut: rolling a, 8 cells", o.re, 0.02)
    V.below("cut: spin-up error below the lattice count's, 8 cells", o.se, def_se[k])
    V.below("cut: rolling error below the lattice count's, 8 cells", o.re, def_re[k])
  elseif c == 16 then
    target("cut: rolling a, 16 cells", o.re, 0.01)
    V.below("cut: spin-up error below the lattice count's, 16 cells", o.se, def_se[k])
    V.near("cut: spin-up alpha / (2 mu g cos / R), 16 cells", o.spin, 1, 0.05)
    V.near("cut: rolling a / ((2/3) g sin), 16 cells", o.roll, 1, 0.02)
  end
end
