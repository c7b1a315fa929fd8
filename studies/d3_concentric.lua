-- Study (3-D): concentric spheres cooled while bonded (lua/mvmpm/lame.lua,
-- sphere.run): an inner sphere (a = 0.2, alpha = 1) and a shell (to
-- b = 0.4, alpha = 0) on one velocity field, K = 1, G = 0.5, cooled by
-- dT = -0.004 in one step and brought to rest by kinetic damping (two
-- sim:settle calls, timed as the stepping).  Reference: the spherical
-- Lame solution, interface radial stress s = 1.050 |alpha dT|.
-- Errors: the sphere's mean radial stress (1.5 cells or more inside the
-- interface) off s, the interface cells' radial stress off s, and the
-- shell's worst radial bin, all over s.  `cells` counts cells across b.
--
--   ./mvmpm test studies/d3_concentric.lua          (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local L = require "mvmpm.lame"

return S.main({
  name = "d3_concentric",
  title = "3-D concentric spheres, bonded, cooled: interface stress against Lame",
  length = "b (outer radius)",
  reference = "spherical Lame: s = -(e1 - e2) / [1/(3K1) + (a^3/(3K2) + b^3/(4G2))/(b^3 - a^3)]",
  metrics = {{key = "inner", label = "sphere |sigma_rr/s - 1|"},
             {key = "band", label = "interface cells |sigma_rr/s - 1|"},
             {key = "shell", label = "shell worst bin |sigma_rr - Lame|/s"}},
  extra = {"inner_ratio", "band_ratio"},
  grid = {cells = {6, 8, 10, 12, 16}, shape = {"linear", "gimp"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl", ppc = 2},
  run = function(s, clock)
    local r = L.sphere.run {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer,
      update = s.update, run = function(sim)
        -- the settling, timed: clock.run calls .run(sim, t) on this table
        clock.run({run = function() sim:settle {t_max = 5}; sim:settle {t_max = 5} end}, 0)
        clock.sim = sim
      end}
    return {inner = math.abs(r.inner - 1), band = math.abs(r.band - 1),
            shell = r.shell > 0 and r.shell or nil, inner_ratio = r.inner, band_ratio = r.band}
  end,
}, {repeats = 1})
