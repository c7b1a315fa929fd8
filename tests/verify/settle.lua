-- Settling a packing under gravity (sim:settle, kinetic damping) and the
-- energy budget's scale.
--
-- Six elastic discs dropped into a box three diameters wide settle into
-- a stacked triangle: three on the floor, filling the box from side to
-- side, two in their hollows, one on top.  The bottom row cannot spread,
-- so the rest is stable whatever the contact lets round bodies do: roll
-- on the floor or on each other.  (A disc balanced on another is not a
-- stable rest; nor is a free-standing triangle of discs with friction
-- 0.5 between them, which needs about 0.44 once its floor lets them
-- roll.)  Friction 0.5 between the discs and at the floor; the sides are
-- frictionless, so that the floor carries the whole weight.  At rest the
-- floor carries it (static equilibrium, measured by the wall's force),
-- the pile stays put when the run goes on undamped, and the budget
-- closes with the kinetic energy settling took out booked.  The budget's
-- scale does not depend on where the origin is: a scene shifted up by
-- 100 gives the same residual over scale, while the residual over the
-- initial energy (which holds the potential's arbitrary value) changes by
-- orders of magnitude.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local g = 1
-- a box of the given width under gravity, friction 0.5 between bodies,
-- and the elastic discs' material
local function box(y0, shape, width, sides)
  local sim = mvmpm.sim {domain = {x = {0, width}, y = {y0, y0 + 1}}, cell = 0.05,
                         gravity = {0, -g}, shape = shape, t_end = 100, sides = sides}
  sim:contact {friction = 0.5}
  return sim, mvmpm.elastic {K = 200, G = 100, density = 1}
end

local function pile(y0, shape)
  local floor, side = {"wall", friction = 0.5}, {"wall", friction = 0}
  local sim, m = box(y0, shape, 0.75, {left = side, right = side, bottom = floor, top = floor})
  local R = 0.123 -- a little play between the discs and the sides
  local h = 2 * R * math.sin(math.rad(60)) -- between the rows at rest
  local c = {{0.125, 0.13}, {0.375, 0.13}, {0.625, 0.13}, -- each row has a gap to fall
             {0.25, 0.13 + h + 0.08}, {0.5, 0.13 + h + 0.10}, {0.375, 0.13 + 2 * h + 0.2}}
  for _, p in ipairs(c) do
    sim:body {shape = mvmpm.disk {center = {p[1], y0 + p[2]}, radius = R}, material = m}
  end
  return sim
end

-- six discs dropped in three columns of two, apart, into a box one wide:
-- they fall and strike one by one, so two runs parted by round-off stay
-- together long enough to compare (in the pile above, discs a few
-- thousandths apart from the start make the run chaotic at once)
local function drop(y0, shape)
  local wall = {"wall", friction = 0.5}
  local sim, m = box(y0, shape, 1, {left = wall, right = wall, bottom = wall, top = wall})
  for i = 0, 2 do
    for j = 0, 1 do
      sim:body {shape = mvmpm.disk {center = {0.18 + 0.32 * i, y0 + 0.14 + 0.4 * j + 0.05 * i},
                                    radius = 0.12}, material = m}
    end
  end
  return sim
end

for _, shape in ipairs {"gimp", "bspline2"} do
  V.case("a pile of six discs settles (" .. shape .. ")")
  local sim = pile(0, shape)
  local e0 = sim:energy()
  local ok, t, k = sim:settle {tol = 1e-3, t_max = 40}
  local e = sim:energy()
  local drop = e0.potential - e.potential
  V.holds("settled before t_max", ok, t)
  V.below("kinetic energy left / potential released", k / drop, 1e-3)
  local mass = 0
  for _, b in ipairs(sim:bodies()) do mass = mass + b:mass() end
  -- unbooked, the energy the stops took out would be the residual itself
  V.below("|budget residual| / energy settled away", math.abs(e.residual) / e.settled, 0.1)
  V.info("energy settled away / potential released", e.settled / drop)
  V.below("|budget residual| / scale", math.abs(e.residual) / e.scale, 0.02)
  -- undamped from here: it stays where it settled, and the floor carries
  -- the weight (its impulse over the time, as the momentum stays ~0)
  local function byid()
    local p, id, r = sim:particles("position"), sim:particles("id"), {}
    for i = 1, #id do r[id[i]] = {p.x[i], p.y[i]} end
    return r
  end
  local y0 = byid()
  local imp, t1 = 0, sim.t
  sim:every {steps = 1, fn = function() local _, fy = sim:wall_force("bottom"); imp = imp + fy * sim.dt end}
  sim:run(sim.t + 0.5)
  V.near("floor's mean force / weight (static equilibrium)", imp / (sim.t - t1) / (mass * g), 1, 0.01)
  local y1 = byid()
  local moved = 0
  for id, p in pairs(y0) do
    moved = math.max(moved, math.abs(y1[id][1] - p[1]), math.abs(y1[id][2] - p[2]))
  end
  V.below("largest particle move over 0.5 more, in cells", moved / 0.05, 0.1)
end

V.case "the budget's scale does not depend on the origin"
local r = {}
for _, y0 in ipairs {0, 100} do
  local sim = drop(y0, "gimp")
  sim:run(1.0)
  local e = sim:energy()
  r[#r + 1] = {rel = e.residual / e.scale, init = e.residual / e.initial, scale = e.scale}
end
V.near("scale, origin at 0 and at -100", r[2].scale, r[1].scale, 1e-6, true)
V.near("residual / scale, origin at 0 and at -100", r[2].rel, r[1].rel, 1e-4 * math.abs(r[1].rel) + 1e-9)
V.info("residual / initial energy, origin at 0", r[1].init)
V.info("residual / initial energy, origin at -100", r[2].init)

V.case "sim:at_end runs once, at the scene's end, with the final state"
do
  local sim = pile(0, "gimp")
  sim.t_end = 0.2
  local calls, seen = 0, -1
  sim:at_end(function(s) calls = calls + 1; seen = s.t end)
  sim:run(0.1)
  V.holds("not before the end", calls == 0, calls)
  sim:run()
  sim:run()
  V.holds("once at the end (a second run to it takes no step)", calls == 1, calls)
  V.near("with the state at t_end", seen, 0.2, 1e-12)
  sim.t_end = 0.3
  sim:run()
  V.holds("again when the end is moved and reached", calls == 2, calls)
end
