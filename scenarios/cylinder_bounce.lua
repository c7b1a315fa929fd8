-- The report's bouncing cylinder: a unit-diameter elastic disc (K = 1,
-- G = 0.5, density 1) launched at (0.1, 0.1) in a 3 x 3 box, 8 cells
-- across its diameter, 2 x 2 particles per cell.  It starts off the box's
-- diagonal so that it meets the right, top and left walls in turn, about
-- 10 time units apart, instead of hitting corners.
--
--   mvmpm run scenarios/cylinder_bounce.lua --set friction=0.1
--
-- With walls=driven the box's sides are driven (still, rigid) bodies
-- half a unit thick outside the box, the grid grown to hold them, and
-- the disc meets them through contact between bodies (friction then
-- the contact law's); offset moves their faces out by that fraction of
-- a cell (0: on node lines, as the grid's walls are).
--
-- The scheme (shape, update, transfer, flip) is the engine's default
-- unless set: "default" passes nothing to mvmpm.sim.
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  friction = 0.0,      -- wall friction coefficient (0 = frictionless)
  cells = 8,           -- cells across the diameter
  ppc = 2,             -- particles per cell per direction
  t_end = 36,          -- three impacts and the ringing after the third (the
                       -- energies the docs quote are taken at t = 36)
  flip = -1,           -- FLIP fraction (0 = PIC); -1: the default
  cfl = 0.25,
  update = "default",  -- or "usl", "musl", "usavg"
  shape = "default",   -- or "linear", "gimp", "bspline2"
  transfer = "default", -- or "flip", "apic" (gimp or bspline2), "xpic"
  xpic = 2,            -- XPIC's order (2 or 3)
  separation = true,   -- contact only once surfaces meet
  wall_contact = "default", -- or "node": each wall node stopped alone;
                         -- "patch": the wall acts per contact patch;
                         -- "couple": ... with friction at the wall line
                         -- "penalty": the walls push the particles that
                         -- reach them; "spring": each column of nodes at
                         -- the wall (docs/lua-api.md)
  wall_stiffness = -1,   -- "penalty", "spring": the springs' stiffness
                         -- (sim.wall_stiffness); -1: the rule's default
  contact_gap = "default", -- or "touch", "step" (sim.contact_gap)
  speed = 0.1,         -- launch velocity (speed, speed)
  K = 1, G = 0.5,      -- the disc's bulk and shear moduli
  volume = "default",  -- the particles' volumes (sim:body's volume): "cell",
                       -- "exact" or "cut"
  walls = "grid",      -- or "driven": driven bodies for the box's sides
  offset = 0,          -- walls = "driven": their faces moved out (cells)
}
if P.walls ~= "grid" and P.walls ~= "driven" then
  error(string.format("cylinder_bounce: walls must be \"grid\" or \"driven\" (got %q)", P.walls), 0)
end

local h = 1 / P.cells
local function opt(v) if v ~= "default" and v ~= -1 then return v end end
local driven = P.walls == "driven"
local T = driven and 0.5 or 0 -- the driven walls' thickness
local sim = mvmpm.sim {
  domain = {x = {-T, 3 + T}, y = {-T, 3 + T}},
  cell = h,
  ppc = P.ppc,
  shape = opt(P.shape),
  update = opt(P.update),
  flip = opt(P.flip),
  transfer = opt(P.transfer),
  xpic = P.xpic,
  cfl = P.cfl,
  t_end = P.t_end,
  sides = {"wall", friction = driven and 0 or P.friction},
  contact = {separation = P.separation, friction = driven and P.friction or nil},
  wall_contact = opt(P.wall_contact),
  wall_stiffness = opt(P.wall_stiffness),
  contact_gap = opt(P.contact_gap),
}

local disc = mvmpm.elastic {K = P.K, G = P.G, density = 1, name = "disc"}
sim:body {
  name = "cylinder",
  shape = mvmpm.disk {center = {2.0, 1.0}, radius = 0.5},
  material = disc,
  velocity = {P.speed, P.speed},
  volume = opt(P.volume),
}
-- after the disc, which stays sim:bodies()[1]
if driven then
  local d = P.offset * h
  local m = mvmpm.elastic {K = P.K, G = P.G, density = 1, name = "wall"}
  for _, w in ipairs {
    {"bottom", {-T, -T}, {3 + T, -d}}, {"top", {-T, 3 + d}, {3 + T, 3 + T}},
    {"left", {-T, -d}, {-d, 3 + d}}, {"right", {3 + d, -d}, {3 + T, 3 + d}},
  } do
    sim:body {name = w[1], shape = mvmpm.rect {lo = w[2], hi = w[3]}, material = m, driven = {0, 0}}
  end
end

sim:output {dir = "out/cylinder_bounce", every = 0.5, csv_every = 10}
return sim
