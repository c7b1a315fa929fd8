-- Two elastic spheres colliding in 3-D, each on its own velocity field
-- (frictionless multi-field contact), head on and obliquely: the total
-- momentum vector is kept to round-off at every step, they separate with
-- the gap between their nearest particles opening and no particle of one
-- inside the other (sim:overlap), and the energy change once apart is
-- measured at 8, 12 and 16 cells per diameter (head on; 8 and 12
-- oblique), with the observed order between them.
local V = require "mvmpm.verify"

local function order(a, b, ra, rb) return math.log(math.abs(ra) / math.abs(rb)) / math.log(b / a) end

-- the scene and its measures: lua/mvmpm/spheres3.lua
local spheres = require("mvmpm.spheres3").run

local function collide(title, off, t_end, cells)
  V.case(title)
  local rs = {}
  for k, c in ipairs(cells) do
    local r = spheres(c, off, t_end)
    rs[k] = r
    V.info(string.format("%d cells: energy change E(%d)/E0 - 1", c, t_end), r.energy)
    V.info(string.format("%d cells: largest spin |omega| R / |v|", c), r.spin)
    V.info(string.format("%d cells: CPU seconds (os.clock)", c), r.cpu, "s")
    for d, n in ipairs {"x", "y", "z"} do
      V.below(string.format("%d cells: largest |p_%s - p_%s(0)| / (m v)", c, n, n), r.dp[d], 1e-12)
    end
    V.holds(string.format("%d cells: no particle inside the other sphere (t = 1..%d)", c, t_end),
      r.overlap == 0, r.overlap)
    local during = math.min(r.gaps[2], r.gaps[3])
    V.above(string.format("%d cells: nearest particles apart in contact (t = 2, 3) / h", c),
      during * c, 0.2)
    local g = r.gaps
    V.holds(string.format("%d cells: the gap opens after the impact (t = %d, %d, %d)", c,
      t_end - 2, t_end - 1, t_end), g[t_end - 2] < g[t_end - 1] and g[t_end - 1] < g[t_end], g[t_end])
    V.above(string.format("%d cells: separating along the line of centres after", c), r.vn, 0.1)
  end
  for k = 2, #cells do
    V.info(string.format("energy error, observed order %d -> %d", cells[k - 1], cells[k]),
      order(cells[k - 1], cells[k], rs[k - 1].energy, rs[k].energy))
  end
  return rs
end

local head = collide("two spheres head on, defaults, frictionless multi-field contact", 0, 5, {8, 12, 16})
-- measured with the defaults (B-splines, MUSL, FLIP): -7.6, -2.4, -0.49 %
-- (t = 5), falling at order 3 to 5; linear hats gave +0.84, +2.66, +0.69 %,
-- within 1 % at 8 cells but not falling (docs/verification.md)
V.below("head on: |energy change| falls 8 -> 12 cells", math.abs(head[2].energy), math.abs(head[1].energy))
V.below("head on: |energy change| falls 12 -> 16 cells", math.abs(head[3].energy), math.abs(head[2].energy))
V.below("head on: |energy change| at 16 cells", math.abs(head[3].energy), 0.01)
V.info(string.format("head on: |energy change| <= 1 %% at 8 cells: %s",
  math.abs(head[1].energy) <= 0.01 and "met" or "NOT met"), head[1].energy)
V.below("head on: spin (none by symmetry)", math.max(head[1].spin, head[2].spin, head[3].spin), 1e-12)

local obl = collide("two spheres, oblique (offset 0.5 D), defaults, frictionless multi-field contact", 0.5, 6, {8, 12})
-- The oblique impact loses -6.7 % at 8 cells and -4.5 % at 12 with the
-- defaults, and spins the spheres a little (|omega| R / |v| 0.010,
-- 0.008) where frictionless contact gives none; linear hats lost -2.2 %
-- and -4.3 % and spun them 0.038, 0.053 (the node-by-node mass-gradient
-- normals on a lattice sphere, as in the 2-D glancing disks,
-- tests/verify/two_disks.lua)
V.below("oblique: |energy change| falls 8 -> 12 cells", math.abs(obl[2].energy), math.abs(obl[1].energy))
V.below("oblique: spin |omega| R / |v| at 12 cells", obl[2].spin, 0.02)
V.info("oblique: relative v_y after, 12 cells (0.2 before)", obl[2].vrel[2])
