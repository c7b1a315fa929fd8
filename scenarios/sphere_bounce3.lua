-- A 3-D bounce: a unit-diameter elastic ball (K = 1, G = 0.5, density 1)
-- launched at (0.1, 0.1, 0.05) in a 3 x 3 x 2 box with walls on its six
-- faces, 8 cells across its diameter, 2 x 2 x 2 particles per cell.  It
-- meets the right wall near t = 5 and the top one near t = 15.
--
--   mvmpm run scenarios/sphere_bounce3.lua --set friction=0.1
--
-- make check-paraview runs it to t = 4 and opens its XDMF series with
-- ParaView's three readers.
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  friction = 0.0,      -- wall friction coefficient (0 = frictionless)
  cells = 8,           -- cells across the diameter
  ppc = 2,             -- particles per cell per direction
  t_end = 20,          -- the first two impacts
  every = 0.5,         -- time between snapshots
  shape = "gimp",      -- or "linear", "bspline2"
  update = "usavg",    -- or "usl", "musl"
}

local h = 1 / P.cells
local sim = mvmpm.sim {
  dim = 3,
  domain = {x = {0, 3}, y = {0, 3}, z = {0, 2}},
  cell = h,
  ppc = P.ppc,
  shape = P.shape,
  update = P.update,
  t_end = P.t_end,
  sides = {"wall", friction = P.friction},
}

sim:body {
  name = "ball",
  shape = mvmpm.ball {center = {2.0, 1.0, 1.0}, radius = 0.5},
  material = mvmpm.elastic {K = 1, G = 0.5, density = 1, name = "ball"},
  velocity = {0.1, 0.1, 0.05},
}
sim:output {dir = "out/sphere_bounce3", every = P.every, csv_every = 10}
return sim
