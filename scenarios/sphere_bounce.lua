-- The bouncing cylinder's scene in 3-D: a unit-diameter elastic sphere
-- (K = 1, G = 0.5, density 1) launched at (0.1, 0.1, 0.1) in a 3 x 3 x 3
-- box, 8 cells across its diameter, 2 x 2 x 2 particles per cell.  It
-- starts at (2.3, 1.5, 1.9), 0.2 from the right wall, so that it meets
-- three different walls one at a time, 4 time units apart: the right
-- wall (x = 3) at t = 2, the front (z = 3) at t = 6 and the top (y = 3)
-- at t = 10.  Each impact lasts about 2.8 time units, so the sphere is
-- free between them and after t = 13; the fourth impact, on the left
-- wall, comes near t = 25.
--
--   mvmpm run scenarios/sphere_bounce.lua --set cells=12
--
-- The scheme (shape, update, transfer, flip) is the engine's default
-- unless set: "default" passes nothing to mvmpm.sim.
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  friction = 0.0,      -- wall friction coefficient (0 = frictionless)
  cells = 8,           -- cells across the diameter
  ppc = 2,             -- particles per cell per direction
  t_end = 14,          -- three impacts (the third ends near t = 13)
  flip = -1,           -- FLIP fraction (0 = PIC); -1: the default
  cfl = 0.25,
  update = "default",  -- or "usl", "musl", "usavg"
  shape = "default",   -- or "linear", "gimp", "bspline2"
  transfer = "default", -- or "flip", "apic" (gimp or bspline2), "xpic"
  xpic = 2,            -- XPIC's order (2 or 3)
  wall_contact = "node", -- or "patch", "couple", "penalty" (the walls push
                         -- the particles that reach them), "spring" (each
                         -- column of nodes at the wall): docs/lua-api.md
  wall_stiffness = -1,   -- "penalty", "spring": the springs' stiffness
                         -- (sim.wall_stiffness); -1: the rule's default
  contact_gap = "default", -- or "touch", "step" (sim.contact_gap)
}

local h = 1 / P.cells
local function opt(v) if v ~= "default" and v ~= -1 then return v end end
local sim = mvmpm.sim {
  dim = 3,
  domain = {x = {0, 3}, y = {0, 3}, z = {0, 3}},
  cell = h,
  ppc = P.ppc,
  shape = opt(P.shape),
  update = opt(P.update),
  flip = opt(P.flip),
  transfer = opt(P.transfer),
  xpic = P.xpic,
  cfl = P.cfl,
  t_end = P.t_end,
  sides = {"wall", friction = P.friction},
  wall_contact = P.wall_contact,
  wall_stiffness = opt(P.wall_stiffness),
  contact_gap = opt(P.contact_gap),
}

local ball = mvmpm.elastic {K = 1, G = 0.5, density = 1, name = "ball"}
sim:body {
  name = "sphere",
  shape = mvmpm.ball {center = {2.3, 1.5, 1.9}, radius = 0.5},
  material = ball,
  velocity = {0.1, 0.1, 0.1},
}
sim:output {dir = "out/sphere_bounce", every = 0.5, csv_every = 10}
return sim
