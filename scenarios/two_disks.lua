-- Two elastic disks meeting head on (the geometry of Sulsky, Chen &
-- Schreyer 1994): radius 0.2, centres (0.2, 0.2) and (0.8, 0.8) in a unit
-- square (widened for an offset), velocities +-(0.1, 0.1), E = 1000,
-- nu = 0.3, density 1000.
-- fields = "body" gives each disk its own velocity field (frictionless
-- multi-field contact: they bounce apart); fields = "single" puts both on
-- one grid field, where the interface cannot slip: in a glancing
-- collision (offset > 0) they stick tangentially and spin each other up,
-- where frictionless multi-field contact leaves them without spin.
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  cells = 20,          -- cells across the unit square
  fields = "body",     -- "body" or "single"
  friction = 0.0,
  t_end = 3.5,
  cfl = 0.25,
  offset = 0.0,        -- upper disk shifted across the line of approach
  shape = "linear",
}
local o = P.offset / math.sqrt(2)

local sim = mvmpm.sim {
  -- the unit square head on; with an offset, wide enough for the upper
  -- disk and a cell more (on the unit square its part past the side
  -- would not be seeded)
  domain = require("mvmpm.normals").discs_domain(P.offset, P.cells),
  cell = 1 / P.cells,
  ppc = 2,
  sides = "free",
  fields = P.fields,
  cfl = P.cfl, shape = P.shape,
  t_end = P.t_end,
  contact = {friction = P.friction},
}
local m = mvmpm.elastic {E = 1000, nu = 0.3, density = 1000}
sim:body {name = "lower", shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.2},
          material = m, velocity = {0.1, 0.1}}
sim:body {name = "upper", shape = mvmpm.disk {center = {0.8 + o, 0.8 - o}, radius = 0.2},
          material = m, velocity = {-0.1, -0.1}}
sim:output {dir = "out/two_disks", every = 0.1, csv_every = 10}
return sim
