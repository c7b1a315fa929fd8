-- The code of the long convergence files (tests/heavy) at their coarsest
-- rungs and over short times.  make test SAN=1 leaves those files out
-- (an hour and more under the sanitizers), so this file is what runs
-- their contact rules, schemes and laws there.  Each case asserts what
-- holds at any resolution (finite state, the energy budget closing,
-- friction taking energy and never giving it, nothing passing through);
-- the convergence is asserted by the file each case names.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"

local function finite(x) return x == x and x > -math.huge and x < math.huge end
local function closes(e)
  return math.abs(e.residual) / (e.initial + math.abs(e.boundary_work))
end

V.case "disc thrown along a driven slab and a wall, mu 0.3, 8 cells (body_patch.lua, friction_work.lua)"
for _, k in ipairs {
  {"patch between bodies, linear FLIP", {shape = "linear", transfer = "flip"}, {slab = true, body_contact = "patch"}},
  {"patch between bodies, GIMP APIC", {shape = "gimp", transfer = "apic"}, {slab = true, body_contact = "patch"}},
  {"patch between bodies, B-spline FLIP", {shape = "bspline2", transfer = "flip"}, {slab = true, body_contact = "patch"}},
  {"wall patch, linear XPIC", {shape = "linear", transfer = "xpic"}, {wall_contact = "patch"}},
  {"wall couple, linear FLIP", {shape = "linear", transfer = "flip"}, {wall_contact = "couple"}},
} do
  local o = {cells = 8, scheme = k[2], mu = 0.3, T = 0.6, n = 6}
  for key, v in pairs(k[3]) do o[key] = v end
  local r = S.run(o)
  V.holds(k[1] .. ": speed and spin finite", finite(r.d.vx) and finite(r.d.omega))
  -- friction slows the disc and spins it forward (omega < 0 rolling
  -- right); measured vx 0.81-0.82, omega -0.14 (XPIC) to -0.76
  V.below(k[1] .. ": vx at t = 0.6 (thrown at 1)", r.d.vx, 0.95)
  V.below(k[1] .. ": omega at t = 0.6", r.d.omega, -0.05)
  V.above(k[1] .. ": friction work (never negative)", r.e.dissipated, 0)
  V.below(k[1] .. ": |budget residual| / (E0 + |boundary work|)", closes(r.e), 0.02)
end

V.case "bonded binder shear cell, 20 cells, to strain 0.1 (shear.lua, shear_burial.lua)"
do
  local shear = require "mvmpm.shear"
  for _, rule in ipairs {"node", "patch"} do
    local P = shear.params {binder = true, bond = 0.01, cells = 20, strain = 0.1, body_contact = rule}
    local sim, mon = shear.build(P)
    sim:run()
    local s = shear.summary(mon)
    V.holds(rule .. ": no NaN, det F > 0, nothing buried, at every sample", #mon.bad == 0, #mon.bad, mon.bad[1])
    V.below(rule .. ": deepest burial of a particle in another body (cells)", s.max_depth, 0)
  end
end

V.case "cohesive pull, 8 cells, 2-D and 3-D (cohesive.lua)"
do
  local P = require "mvmpm.pull"
  for _, o in ipairs {{cells = 8}, {cells = 8, shape = "bspline2", transfer = "apic"}, {cells = 8, dim = 3}} do
    local r = P.run(o)
    local name = string.format("%s %s, %d-D", o.shape or "linear", o.transfer or "flip", o.dim or 2)
    -- measured 1.03-1.05 at 8 cells; 1.0177 at 12 (docs/verification.md)
    V.near(name .. ": work of separation / (G_c A)", r.w, 1, 0.1)
  end
end

V.case "cylinder bounce, GIMP USAVG, walls by the step's gap, 8 cells, to t = 12 (bounce_convergence.lua)"
do
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
    {cells = 8, t_end = 12, shape = "gimp", update = "usavg", contact_gap = "step"})
  local e0 = sim:energy().total
  sim:run()
  local e = sim:energy()
  V.holds("energy finite", finite(e.total))
  V.below("energy E / E0 after the first impact", e.total / e0, 1.001)
  V.below("|budget residual| / E0", math.abs(e.residual) / e0, 0.01)
end

V.case "sphere bounce, GIMP USAVG, 6 cells (d3_bounce_usavg.lua)"
do
  local r = require("mvmpm.bounce3").run(6, {shape = "gimp", update = "usavg", cfl = 0.4})
  V.holds("energy finite", finite(r.energy))
  V.below("energy change E(14)/E0 - 1", r.energy, 0.001)
  V.below("|budget residual| / E0", math.abs(r.residual), 0.01)
end

V.case "sphere rolling on a sticking floor, 8 cells, to t = 0.5 (d3_rolling.lua)"
do
  local I = require "mvmpm.incline3"
  local r = I.run {cells = 8, deg = 25, mu = "stick", T = 0.5}
  V.holds("acceleration finite", finite(r.a))
  V.above("rolls down the slope: a / (5/7 g sin th)", r.a / (5 / 7 * I.g * math.sin(r.th)), 0.5)
  V.below("|budget residual| / (kinetic + strain at the end)", math.abs(r.e.residual) / (r.e.kinetic + r.e.strain), 0.05)
end

V.case "piston pack (30 discs, mu 0.3), 2 cells, to t = 1 (pack_budget.lua)"
do
  local Pk = require "mvmpm.piston"
  local e, w = Pk.run {cells = 2, scheme = {shape = "linear", transfer = "flip"}, T = 1}
  V.holds("energy finite", finite(e.total))
  V.above("friction work", e.dissipated, 0)
  V.below("|budget residual| / piston's work", math.abs(e.residual) / w, 0.05)
end

V.case "block on a tilted flat face and two discs meeting, 8 cells (normals.lua)"
do
  local C = require "mvmpm.normals"
  for _, m in ipairs {"mass", "plane/8", "plane/4+patch"} do
    local b = C.block {k = 8, method = m, mu = 0.2, deg = 30}
    V.holds(m .. ": block's acceleration finite", finite(b.a))
    -- g (sin 30 - 0.2 cos 30) slides the block down; the mass normals
    -- tilt at the block's corners and hold it (normals.lua prints it)
    if m == "mass" then V.info(m .. ": block's acceleration / Coulomb's", b.a)
    else V.above(m .. ": block's acceleration / Coulomb's", b.a, 0.5) end
    V.below(m .. ": |budget residual| / gravity's work", math.abs(b.residual), 0.05)
    local d = C.discs {cells = 8, method = m, offset = 0.2}
    V.holds(m .. ": discs' energy finite", finite(d.energy))
    V.below(m .. ": kinetic + strain after / before (frictionless)", d.energy, 1.001)
  end
end

V.case "concentric disc in an annulus, cooled: bonded, then debonding, 25 cells (concentric.lua)"
do
  local sim = mvmpm.load("scenarios/concentric_debond.lua",
    {cells = 25, strength = 0.005, t_end = 24, shape = "linear", traction = "fit", bond_length = 0.12})
  sim:run()
  local e = sim:energy()
  V.holds("energy finite", finite(e.total))
  V.above("bond cuts by t = 24 (measured 60)", e.debonded, 1)
end

V.case "cylinder bounce in a box of driven bodies, 8 cells, to t = 10 (driven_walls.lua)"
do
  local e = {}
  for _, w in ipairs {"grid", "driven"} do
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua", {cells = 8, t_end = 10, walls = w})
    local e0 = sim:energy().total
    sim:run(10)
    e[w] = sim:energy().total / e0 - 1
  end
  V.holds("driven: energy finite", finite(e.driven))
  V.below("driven: E/E0 - 1 after the first impact (no gain)", e.driven, 0)
  -- measured equal to round-off (faces on node lines)
  V.below("|driven - grid walls| after the first impact", math.abs(e.driven - e.grid), 1e-3)
end

V.case "two discs head on and glancing, 20 cells across, frictionless (two_disks.lua)"
do
  local C = require "mvmpm.normals"
  -- the defaults head on: measured -2.97 % at 20 cells
  local h = C.discs {cells = 20, shape = "bspline2", method = "mass/0", offset = 0}
  V.holds("head on: energy finite", finite(h.total))
  V.below("head on: |total energy after / before - 1|", math.abs(h.total - 1), 0.05)
  V.below("head on: |momentum| / one disc's (equal discs, opposite velocities)",
    math.abs(h.a.mass * h.a.vx + h.b.mass * h.b.vx) / (h.a.mass * 0.1), 1e-9)
  V.above("head on: separating along the line of centres after", (h.b.vx - h.a.vx) + (h.b.vy - h.a.vy), 0)
  -- GIMP with "maxvolume"/4 glancing: measured 2.2 % of the tangential
  -- velocity lost, |Jt / Jn| 0.003 at 20 cells
  local g = C.discs {cells = 20, shape = "gimp", method = "maxvolume/4", offset = 0.2}
  V.below("glancing: tangential relative velocity lost", math.abs(g.kept - 1), 0.1)
  V.below("glancing: |Jt / Jn|", math.abs(g.jt), 0.02)
  V.below("glancing: kinetic + strain after / before (frictionless)", g.energy, 1.001)
end

V.case "two spheres head on, 6 cells per diameter (d3_spheres.lua)"
do
  local r = require("mvmpm.spheres3").run(6, 0, 5)
  V.holds("energy finite", finite(r.energy))
  V.below("energy change E(5)/E0 - 1 (no gain)", r.energy, 0.001)
  for d, n in ipairs {"x", "y", "z"} do
    V.below(string.format("largest |p_%s - p_%s(0)| / (m v)", n, n), r.dp[d], 1e-12)
  end
  V.holds("no particle inside the other sphere (t = 1..5)", r.overlap == 0, r.overlap)
  V.above("separating along the line of centres after", r.vn, 0.1)
end

V.case "concentric spheres, bonded, cooled, 6 cells across the shell (d3_concentric.lua)"
do
  local r = require("mvmpm.lame").sphere.run {cells = 6, shape = "linear"}
  -- measured within 1 % of Lame at 6, 8, 10 cells
  V.near("sphere's sigma_rr / s", r.inner, 1, 0.03)
  V.near("sigma_rr at the interface's cells / s", r.band, 1, 0.03)
end

V.case "debond front with the fitted traction over 0.1, 16 cells (bonds_long.lua)"
do
  -- measured 0.684 c_R at 16 cells
  local v = require("mvmpm.front").run {cells = 16, traction = "fit", bond_length = 0.1}
  V.below("front speed / c_R (must not exceed 1)", v, 1.0)
  V.above("front speed / c_R (a front runs)", v, 0.5)
end
