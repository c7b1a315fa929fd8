-- The report's debonding benchmark (Figure 5): an inner disc with thermal
-- expansion alpha bonded inside an annulus with none, both elastic with
-- the bounce's constants (K = 1, G = 0.5, density 1), on a 50 x 50 grid
-- with 2 x 2 particles per cell.  Slow uniform cooling shrinks the disc,
-- which pulls on the annulus through the bond; the interface's radial
-- traction grows as s = 0.675 |alpha dT| (plane strain, 3-D K: see
-- docs/verification.md) until it reaches the bond strength, and the
-- interface lets go.
--
--   mvmpm run scenarios/concentric_debond.lua --set strength=0.01
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  strength = 0.005,    -- bond strength of the interface
  alpha = 1.0,         -- expansion coefficient of the inner disc
  rate = 4e-4,         -- cooling rate |dT/dt|
  cells = 50,          -- cells across the square domain
  a = 0.2,             -- inner radius
  b = 0.4,             -- outer radius
  t_end = 24,
  shape = "linear",
  traction = "mixture", -- the bond test's traction: "mixture" or "fit"
  bond_length = 0,     -- with "fit": the length it is averaged over
}

local sim = mvmpm.sim {
  domain = {x = {0, 1}, y = {0, 1}},
  cell = 1 / P.cells,
  shape = P.shape,
  t_end = P.t_end,
  sides = "free",
  bond_traction = P.traction,
  bond_length = P.bond_length,
}
local core = mvmpm.elastic {K = 1, G = 0.5, density = 1, alpha = P.alpha, name = "core"}
local shell = mvmpm.elastic {K = 1, G = 0.5, density = 1, alpha = 0, name = "shell"}
local c = {0.5, 0.5}
sim:body {name = "inner", shape = mvmpm.disk {center = c, radius = P.a},
          material = core, bond = P.strength}
sim:body {name = "outer", shape = mvmpm.annulus {center = c, inner = P.a, outer = P.b},
          material = shell, bond = P.strength}
-- cooling from T = 0 (the stress-free state) at a steady rate
sim:temperature(function(t) return -P.rate * t end)
sim:output {dir = "out/concentric_debond", every = 0.5, csv_every = 10}
return sim
