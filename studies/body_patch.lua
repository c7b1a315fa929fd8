-- Study: contact between bodies per contact patch (body_contact =
-- "patch"; BODY_CONTACT=node in the environment for the node rule), on
-- a disc meeting a driven slab (tests/verify/body_patch.lua asserts the
-- linear and GIMP APIC rows at 8, 16, 32 cells):
--   thrown: the disc of lua/mvmpm/slide.lua thrown at v0 = 1 along the
--     slab, mu = 0.3, t = 2; |friction work / W_rigid - 1|, W_rigid =
--     1/2 m v0^2 I / (I + m R^2) from the seeded particles;
--   rolling: the disc of lua/mvmpm/incline.lua on the slab tilted 25 deg
--     (gravity rotated), mu 0.5; |a / (2/3 g sin th) - 1|.
--
--   ./mvmpm test studies/body_patch.lua   (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local Sl = require "mvmpm.slide"
local I = require "mvmpm.incline"

local rule = os.getenv("BODY_CONTACT") or "patch"
return S.main {
  name = rule == "patch" and "body_patch" or "body_patch_" .. rule,
  title = "disc on a driven slab, " .. rule .. " rule between bodies",
  length = "D",
  reference = "rigid disc: thrown, W = 1/2 m v0^2 I / (I + m R^2); rolling, a = 2/3 g sin",
  metrics = {{key = "work", label = "thrown |W / W_rigid - 1|"},
             {key = "roll", label = "rolling |a / a_ref - 1|"}},
  extra = {"work_ratio", "roll_ratio"},
  grid = {cells = {8, 16, 32}, shape = {"linear", "gimp", "bspline2"}, transfer = {"flip", "apic", "xpic"}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  skip = function(s) return s.transfer == "apic" and s.shape == "linear" end,
  run = function(s, clock)
    local r = Sl.run {cells = s.cells, scheme = {shape = s.shape, transfer = s.transfer, flip = s.flip},
                      mu = 0.3, T = 2, n = 40, slab = true, body_contact = rule, run = clock.run}
    local q = I.run {cells = s.cells, deg = 25, mu = 0.5, slab = "driven", shape = s.shape,
                     transfer = s.transfer, flip = s.flip, body_contact = rule, run = clock.run}
    local w, a = r.e.dissipated / r.rigid, q.a / (2 / 3 * I.g * math.sin(q.th))
    return {work = math.abs(w - 1), work_ratio = w, roll = math.abs(a - 1), roll_ratio = a}
  end,
}
