-- Study: friction work against a physical reference.  The disc of
-- lua/mvmpm/slide.lua (R = 0.5, K = 400, G = 200, density 1, g = 1)
-- thrown at v0 = 1 without spin along the floor wall (mu = 0.3), run to
-- t = 2, the wall acting per contact patch (wall_contact = "patch";
-- WALL_CONTACT=node or couple in the environment for the other rules).
-- Reference: the rigid disc slides until friction has turned it to
-- rolling, and friction takes W = 1/2 m v0^2 I / (I + m R^2) (1/6 m v0^2
-- for a uniform disc; I from the seeded particles, M.rigid in
-- slide.lua), whatever mu.  Error: |friction work / W - 1|.
-- tests/verify/friction_work.lua asserts it at 8, 16, 32 cells.
--
--   ./mvmpm test studies/friction_work.lua   (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local Sl = require "mvmpm.slide"

local rule = os.getenv("WALL_CONTACT") or "patch"
return S.main {
  name = rule == "patch" and "friction_work" or "friction_work_" .. rule,
  title = "thrown disc, friction work, " .. rule .. " rule",
  length = "D",
  reference = "rigid disc: W = 1/2 m v0^2 I / (I + m R^2), from the seeded particles",
  metrics = {{key = "work", label = "|W / W_rigid - 1|"}},
  extra = {"ratio"},
  grid = {cells = {8, 16, 32}, shape = {"linear", "gimp", "bspline2"}, transfer = {"flip", "apic", "xpic"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  skip = function(s) return s.transfer == "apic" and s.shape == "linear" end,
  run = function(s, clock)
    local r = Sl.run {cells = s.cells, scheme = {shape = s.shape, transfer = s.transfer, flip = s.flip},
                      mu = 0.3, T = 2, n = 40, wall_contact = rule, run = clock.run}
    local ratio = r.e.dissipated / r.rigid
    return {work = math.abs(ratio - 1), ratio = ratio}
  end,
}
