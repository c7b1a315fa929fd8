-- Study: two elastic spheres colliding, frictionless (the scene of
-- tests/verify/d3_spheres.lua), head on and oblique (offset 0.5 D), energy
-- change once apart, E(t_end)/E0 - 1, per scheme at 8, 12 and 16 cells
-- per diameter; and the same head-on collision with the grid moved along
-- x by 0, 1/8, ... 1/2 cell (the grid phase of the spheres, their seeded
-- lattice and the contact plane).  Reported, not asserted (V.info): the
-- table is in docs/verification.md (3-D: two spheres).
--
--   ./mvmpm test studies/d3_spheres.lua   (STUDY_QUICK=1: 8 and 12 cells,
--                                          no phase scan; the whole: about
--                                          5 CPU minutes)
local V = require "mvmpm.verify"
local spheres = require("mvmpm.spheres3").run



local quick = os.getenv("STUDY_QUICK") == "1"
local sizes = quick and {8, 12} or {8, 12, 16}
local schemes = {
  {name = "linear, mass normals (defaults)"},
  {name = "linear, contact_gap = step", contact_gap = "step"},
  {name = "linear, maxvolume, window 4", normals = "maxvolume", normal_window = 4},
  {name = "GIMP", shape = "gimp"},
  {name = "GIMP, maxvolume, window 4", shape = "gimp", normals = "maxvolume", normal_window = 4},
  {name = "B-spline", shape = "bspline2"},
  -- the 3-D bounce's scheme (tests/verify/d3_bounce_usavg.lua)
  {name = "GIMP, USAVG, cfl 0.4", shape = "gimp", update = "usavg", cfl = 0.4},
  {name = "linear, USAVG, cfl 0.4", update = "usavg", cfl = 0.4},
  {name = "GIMP, USAVG, cfl 0.4, maxvolume, window 4", shape = "gimp", update = "usavg", cfl = 0.4,
   normals = "maxvolume", normal_window = 4},
}
for _, case in ipairs {{"head on", 0, 5}, {"oblique", 0.5, 6}} do
  V.case("two spheres, " .. case[1] .. ": energy change per scheme")
  for _, sc in ipairs(schemes) do
    for _, c in ipairs(sizes) do
      local r = spheres(c, case[2], case[3], sc)
      V.info(string.format("%s, %d cells: E/E0 - 1", sc.name, c), r.energy)
      if case[2] > 0 then
        V.info(string.format("%s, %d cells: relative v_y after (0.2 before)", sc.name, c), r.vrel[2])
        V.info(string.format("%s, %d cells: spin |omega| R / |v|", sc.name, c), r.spin)
      end
    end
  end
end
if not quick then
  V.case "two spheres head on, defaults: the grid moved by a fraction of a cell"
  for _, c in ipairs(sizes) do
    local sum, lo, hi = 0, math.huge, -math.huge
    for _, sh in ipairs {0, 0.125, 0.25, 0.375, 0.5} do
      local e = spheres(c, 0, 5, {shift = sh}).energy
      V.info(string.format("%d cells, shift %.3f cell: E/E0 - 1", c, sh), e)
      sum, lo, hi = sum + e, math.min(lo, e), math.max(hi, e)
    end
    V.info(string.format("%d cells: mean over the 5 shifts", c), sum / 5)
    V.info(string.format("%d cells: range over the 5 shifts", c), hi - lo)
  end
end
