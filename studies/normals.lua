-- Study: contact normals at the sizes tests/verify/normals.lua and
-- tests/verify/two_disks.lua leave out (lua/mvmpm/normals.lua has the
-- cases and their references).
--   Block on a flat body rotated 30 and 45 degrees to the grid, mu = 0
--   and 0.2: |a / a_ref - 1|, rotation, hop at 8, 16, 32 cells per block
--   side with linear hats and GIMP, "maxvolume" and "plane" over a
--   window of 4 cells, and node-by-node "mass"; then at 15, 22, 37, 52
--   and 60 degrees with linear hats and the windowed methods (the
--   plane also over 8 cells), each windowed method also with one normal
--   per contact patch ("+patch": normal_patch = true).
--   Two discs, head on and glancing (offset 0.2): energy, tangential
--   velocity kept, |Jt / Jn| at 40, 80, 160 cells across, each shape,
--   contact_gap "touch" and "step".
-- CPU seconds (os.clock) of each run are printed beside it; the contact
-- phases' share comes from `mvmpm run SCENE --profile`.
--
--   ./mvmpm test studies/normals.lua     (STUDY_QUICK=1: 8 and 16 cells,
--                                          40 and 80 cells only)
local C = require "mvmpm.normals"
local quick = os.getenv("STUDY_QUICK") == "1"

local K = quick and {8, 16} or {8, 16, 32}
local CELLS = quick and {40, 80} or {40, 80, 160}

local function order(e)
  local n = #e
  if n < 2 or not (e[n] > 0 and e[n - 1] > 0) then return 0 / 0 end
  return math.log(e[n - 1] / e[n], 2)
end

print("-- block on a flat body rotated to the grid: |a/a_ref - 1| (rotation rad, hop/L) [cpu s]")
for _, c in ipairs {{30, 0}, {30, 0.2}, {45, 0}, {45, 0.2}} do
  for _, shape in ipairs {"linear", "gimp"} do
    for _, m in ipairs {"mass", "maxvolume/4", "plane/4", "maxvolume/4+patch", "plane/4+patch"} do
      local t, e = {}, {}
      for i, k in ipairs(K) do
        local r = C.block {k = k, method = m, mu = c[2], deg = c[1], shape = shape}
        e[i] = math.abs(r.a - 1)
        t[i] = string.format("%d: %.4f (%.4f, %.4f) [%.1f]", k, e[i], r.rot, r.hop, r.cpu)
      end
      print(string.format("   %2d deg mu %.1f %-6s %-12s %s  order %.2f", c[1], c[2], shape, m,
                          table.concat(t, "  "), order(e)))
    end
  end
end

-- The same block at other angles (linear hats, 8 and 16 cells, or 8,
-- 16, 32): how far the two windowed methods carry beyond 30 and 45
-- degrees.  Signed a / a_ref - 1; with friction the reference is the
-- difference g (sin - mu cos), small at shallow slopes, so a given error
-- in the friction force is a larger one in a.
print("-- block at other angles, linear: a / a_ref - 1 (hop/L) [cpu s]")
for _, deg in ipairs {15, 22, 37, 52, 60} do
  for _, mu in ipairs {0, 0.2} do
    for _, m in ipairs {"maxvolume/4", "plane/4", "plane/8", "maxvolume/4+patch", "plane/4+patch"} do
      local t, e = {}, {}
      for i, k in ipairs(K) do
        local r = C.block {k = k, method = m, mu = mu, deg = deg}
        e[i] = math.abs(r.a - 1)
        t[i] = string.format("%d: %+.4f (%.4f) [%.1f]", k, r.a - 1, r.hop, r.cpu)
      end
      print(string.format("   %2d deg mu %.1f %-12s %s  order %.2f", deg, mu, m, table.concat(t, "  "), order(e)))
    end
  end
end

print("-- two discs: |dE|/E0 (total) head on; glancing: 1 - kept, |orbit kept - 1|, |Jt/Jn|, final spin [cpu s]")
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  for _, m in ipairs {"mass", "maxvolume/4", "plane/4"} do
    for _, gap in ipairs {"touch", "step"} do
      local h, g = {}, {}
      for i, c in ipairs(CELLS) do
        local r0 = C.discs {cells = c, method = m, shape = shape, gap = gap}
        local r1 = C.discs {cells = c, method = m, shape = shape, gap = gap, offset = 0.2}
        h[i] = string.format("%d: %.4f", c, math.abs(r0.total - 1))
        g[i] = string.format("%d: %.4f %.4f %.4f %.3f [%.1f]", c, math.abs(r1.kept - 1),
                             math.abs(r1.orbit - 1), math.abs(r1.jt), r1.spin_end, r0.cpu + r1.cpu)
      end
      print(string.format("   %-6s %-12s %-5s head-on %s", shape, m, gap, table.concat(h, "  ")))
      print(string.format("   %-6s %-12s %-5s glancing %s", shape, m, gap, table.concat(g, "  ")))
    end
  end
end
