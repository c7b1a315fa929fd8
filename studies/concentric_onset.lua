-- Study: the debond onset of the concentric cylinders
-- (scenarios/concentric_debond.lua): an inner disc (radius a = 0.2,
-- alpha = 1) bonded in an annulus (to b = 0.4, alpha = 0), bond strength
-- 0.005 on both, cooled at |dT/dT| = 4e-4 until the first node lets go.
-- Reference: the plane-strain Lame interface stress s = 0.675 |alpha dT|
-- (mvmpm.lame) reaches the strength at |dT| = 0.0074074.  Error: |onset
-- |dT| / analytic - 1|, the time of the first cut read each step; the
-- signed ratio is recorded beside it (below 1: the bond let go early).
-- The bond test takes the fitted traction (sim.bond_traction = "fit")
-- averaged over bond_length = 0.12 along the interface.
-- "cells" counts cells across the inner disc; the report's 50 x 50
-- grid is 20.
--
--   ./mvmpm test studies/concentric_onset.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"
local lame = require "mvmpm.lame"

local K, G, alpha, rate, a, b, sb = 1, 0.5, 1, 4e-4, 0.2, 0.4, 0.005
local dTc = sb / (lame.unit(K, G, a, b) * alpha)

local case = {
  name = "concentric_onset",
  title = "concentric cylinders, debond onset",
  length = "the inner disc's diameter",
  reference = "plane-strain Lame solution: onset at |dT| = 0.0074074",
  metrics = {{key = "onset", label = "|onset / Lame - 1|"}},
  grid = {cells = {10, 14, 20, 28, 40}, shape = {"linear", "gimp", "bspline2"}},
  baseline = {cells = 20, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local n = math.floor(s.cells / (2 * a) + 0.5)  -- cells across the unit domain
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / n, ppc = s.ppc,
      shape = s.shape, transfer = s.transfer, flip = s.flip, update = s.update, cfl = s.cfl,
      t_end = 2 * dTc / rate, sides = "free", bond_traction = "fit", bond_length = 0.12}
    local core = mvmpm.elastic {K = K, G = G, density = 1, alpha = alpha, name = "core"}
    local shell = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0, name = "shell"}
    sim:body {name = "inner", shape = mvmpm.disk {center = {0.5, 0.5}, radius = a},
              material = core, bond = sb}
    sim:body {name = "outer", shape = mvmpm.annulus {center = {0.5, 0.5}, inner = a, outer = b},
              material = shell, bond = sb}
    sim:temperature(function(t) return -rate * t end)
    local first
    sim:every {steps = 1, fn = function(x)
      if not first and x:energy().debonded > 0 then first = x.t end
    end}
    while not first and sim.t < 1.5 * dTc / rate do clock.run(sim, sim.t + 0.5) end
    local ratio = first and rate * first / dTc or 0 / 0
    return {onset = math.abs(ratio - 1), ratio = ratio}
  end,
}
return S.main(case)
