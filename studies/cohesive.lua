-- Study: the cohesive law (sim.bond_energy) on two blocks pulled apart
-- (lua/mvmpm/pull.lua: the scene, its quasi-static reference and the
-- measures; tests/verify/cohesive.lua asserts 12, 16, 24 cells):
--   work: |work of separation / (G_c A) - 1|
--   curve: mean |grip traction - quasi-static| / sigma over the softening
--   onset: |grip travel at the first cut / (sigma L / M) - 1|
-- at 12 to 48 cells per unit (the opening at failure, 0.01, is half a
-- cell at 50), linear hats and quadratic B-splines (GIMP is refused),
-- FLIP, APIC (B-splines) and XPIC.
--
--   ./mvmpm test studies/cohesive.lua   (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local P = require "mvmpm.pull"

return S.main {
  name = "cohesive",
  title = "two blocks pulled apart through a cohesive interface",
  length = "unit length",
  reference = "quasi-static bar with a linear-softening interface; work of separation G_c A",
  metrics = {{key = "work", label = "|W_sep / (G_c A) - 1|"},
             {key = "curve", label = "mean |t - t_qs| / sigma"},
             {key = "onset", label = "|first cut / sigma L / M - 1|"}},
  extra = {"work_ratio", "onset_ratio"},
  grid = {cells = {12, 16, 24, 32, 48}, shape = {"linear", "bspline2"},
          transfer = {"flip", "apic", "xpic"}},
  skip = function(s) return s.transfer == "apic" and s.shape == "linear" end,
  baseline = {cells = 12, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local r = P.run {cells = s.cells, shape = s.shape, transfer = s.transfer, run = clock.run}
    return {work = math.abs(r.w - 1), work_ratio = r.w, curve = r.curve,
            onset = math.abs(r.onset - 1), onset_ratio = r.onset}
  end,
}
