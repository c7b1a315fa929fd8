-- Study: the concentric cylinders of the report's Figure 5 while still
-- bonded (scenarios/concentric_debond.lua with a bond strength too large
-- to break): an inner disc (radius a = 0.2, alpha = 1) in an annulus
-- (a < r < b = 0.4, alpha = 0), cooled slowly (|dT/dt| = 4e-4), measured
-- at t = 12.  Reference: the plane-strain Lame solution (3-D K, eps_zz = 0,
-- eigenstrain e = (1 + nu) alpha dT, K' = K + G/3):
--   s = -e / [1/(2K') + (a^2/(2K') + b^2/(2G)) / (b^2 - a^2)]
--   disc: sigma_rr = sigma_tt = s;  annulus: sigma_rr = s a^2/(b^2-a^2) (b^2/r^2 - 1),
--   sigma_tt = -s a^2/(b^2-a^2) (b^2/r^2 + 1).
-- Error, as tests/verify/concentric.lua measures it: the worst difference
-- between the cell-wide radial bin means of sigma_rr, sigma_tt and Lame,
-- over s, leaving out the bins within 1.5 cells of the interface and of
-- the rim.  "cells" counts cells across the inner disc (the grain); the
-- report's 50 x 50 grid is 20.
--
--   ./mvmpm test studies/concentric.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local K, G, alpha, rate, a, b = 1, 0.5, 1, 4e-4, 0.2, 0.4
local lame = require "mvmpm.lame"
local unit = lame.unit(K, G, a, b)
local t_end = 12

local function lame_error(sim, h)
  return (lame.profile(sim, {0.5, 0.5}, unit * alpha * rate * sim.t, a, b, h))
end

local case = {
  name = "concentric",
  title = "concentric cylinders, bonded",
  length = "the inner disc's diameter",
  reference = "plane-strain Lame solution, s = 0.675 |alpha dT|",
  metrics = {{key = "lame", label = "max |sigma - Lame| / s"}},
  grid = {cells = {8, 12, 16, 20, 24, 32}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic"}, flip = {1, 0}},
  baseline = {cells = 20, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  skip = function(s) return s.flip == 0 and s.shape ~= "linear" end,   -- PIC only on linear hats
  run = function(s, clock)
    local n = math.floor(s.cells / (2 * a) + 0.5)  -- cells across the unit domain
    -- the scene scenarios/concentric_debond.lua, built here with every setting
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / n, ppc = s.ppc,
      shape = s.shape, transfer = s.transfer, flip = s.flip, update = s.update, cfl = s.cfl,
      t_end = t_end, sides = "free"}
    local core = mvmpm.elastic {K = K, G = G, density = 1, alpha = alpha, name = "core"}
    local shell = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0, name = "shell"}
    sim:body {name = "inner", shape = mvmpm.disk {center = {0.5, 0.5}, radius = a},
              material = core, bond = 1e9}
    sim:body {name = "outer", shape = mvmpm.annulus {center = {0.5, 0.5}, inner = a, outer = b},
              material = shell, bond = 1e9}
    sim:temperature(function(t) return -rate * t end)
    clock.run(sim, t_end)
    return {lame = lame_error(sim, 1 / n)}
  end,
}
return S.main(case)
