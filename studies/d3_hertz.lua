-- Study (3-D): Hertz contact.  An elastic hemisphere (R = 0.5, K = 100,
-- G = 50: E* = 140; curved side down) pressed on a frictionless floor
-- wall by its weight, the gravity set so that Hertz's contact radius is
-- a = 0.35 R, brought to rest by kinetic damping (two sim:settle calls,
-- timed as the stepping; lua/mvmpm/hertz.lua).  Reference: a^3 = 3 F R /
-- (4 E*) with F the weight.  Errors: the contact radius from the
-- floor's normal force node by node (sim:wall_nodes), a_w = sqrt(5/2
-- <r^2>_f) (Hertz: <r^2>_f = 2/5 a^2; a_w4 = (35/8 <r^4>_f)^(1/4)
-- printed), and read from the particles in contact (centres within 3/4
-- of a spacing of the wall: the outermost one's radius plus half a
-- spacing), a_e, and from the second
-- moment of their pressure, a_m = sqrt(5/2 <rho^2>_p), both against a;
-- the floor's force against the weight.  `cells` counts cells across the
-- diameter 2R; a spans 0.175 cells per cell across D, 4.2 cells at 24.
--
--   ./mvmpm test studies/d3_hertz.lua          (STUDY_QUICK=1: fewer settings)
local S = require "mvmpm.study"
local H = require "mvmpm.hertz"

return S.main({
  name = "d3_hertz",
  title = "3-D Hertz: hemisphere on a rigid frictionless flat under its weight (a = 0.35 R)",
  length = "D",
  reference = "Hertz, rigid flat: a^3 = 3 F R / (4 E*), E* = E / (1 - nu^2)",
  metrics = {{key = "a_w", label = "floor forces' moment |a_w/a - 1|"},
             {key = "a_e", label = "contact edge |a_e/a - 1|"},
             {key = "a_m", label = "pressure moment |a_m/a - 1|"},
             {key = "force", label = "|F_wall/W - 1|"}},
  extra = {"a_w_ratio", "a_w4_ratio", "a_e_ratio", "a_m_ratio", "a_q_ratio", "a_cells"},
  grid = {cells = {12, 16, 24, 32}, shape = {"linear", "gimp"}},
  baseline = {cells = 16, shape = "linear", transfer = "flip", flip = 1, update = "musl", ppc = 2},
  run = function(s, clock)
    local r = H.run {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer,
      update = s.update, ar = 0.35, run = function(sim)
        clock.run({run = function() sim:settle {t_max = 20}; sim:settle {t_max = 20} end}, 0)
        clock.sim = sim
      end}
    return {a_w = math.abs(r.a_w / r.a_h - 1), a_w_ratio = r.a_w / r.a_h,
            a_w4_ratio = r.a_w4 / r.a_h, a_e = math.abs(r.a_e / r.a_h - 1),
            a_m = math.abs(r.a_m / r.a_h - 1),
            force = math.abs(r.F / r.W - 1), a_e_ratio = r.a_e / r.a_h, a_m_ratio = r.a_m / r.a_h,
            a_q_ratio = r.a_q / r.a_h, a_cells = r.a_h / r.h}
  end,
}, {repeats = 1})
