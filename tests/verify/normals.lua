-- Contact normals (sim.normals): each method side by side on two
-- frictionless (and one frictional) contact problems with known answers,
-- at three resolutions.
--   Block on a flat body: a block sliding down a flat driven body tilted
--   theta = 30 degrees accelerates at g (sin theta - mu cos theta), neither
--   spins (tips) nor moves off the slope.  Two geometries: the flat body
--   along the grid with gravity rotated by theta ("aligned"), and the flat
--   body and the block themselves rotated by theta ("rotated").
--   Glancing discs: two elastic discs meet off the line of centres; a
--   frictionless contact pushes only along the line of centres, so their
--   relative velocity across it is kept and neither disc is spun.
-- A method is named "method/R" when its sums are taken over the shared
-- nodes within R cells (sim.normal_window = R; "method" alone: R = 0).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local C = require "mvmpm.normals"

-- ("volume" is left out for time: measured within 0.5 % of "mass" on the
-- block, whose bodies have one density; "plane" on the discs, node by
-- node and over a window: docs/verification.md, studies/normals.lua)
local methods = {"mass", "maxvolume/4"}
local solid = {"mass", "maxvolume"}

-- the cases (lua/mvmpm/normals.lua; the block's "aligned" when deg is
-- nil), as tuples: the block's acceleration
-- over the reference, largest spin, speed across / along, rotation, hop;
-- the discs' tangential velocity kept, largest spin, energy kept
local function block(k, method, mu, deg, shape)
  local r = C.block {k = k, method = method, mu = mu, deg = deg, shape = shape}
  return r.a, r.spin, r.across, r.rot, r.hop, r.friction, r.residual
end
local function discs(cells, method)
  local r = C.discs {cells = cells, method = method, offset = 0.2}
  return r.kept, r.spin, r.energy
end
local opts = C.opts

-- error at each resolution and the observed order between the last two
local function row(name, res, errs)
  local t = {}
  for i, e in ipairs(errs) do t[#t + 1] = string.format("%s %.4f", res[i], e) end
  local p = (errs[2] > 0 and errs[3] > 0) and math.log(errs[2] / errs[3], 2) or 0 / 0
  print(string.format("     %-34s %s   order %.2f", name, table.concat(t, "  "), p))
end

local K = {4, 8, 16}          -- cells per block side
local CELLS = {20, 40, 80}    -- cells across the unit square (4, 8, 16 per disc radius)

-- every method at every resolution: r[method][i] = {values...}
local function sweep(res, fn, only)
  local r = {}
  for _, m in ipairs(only or methods) do
    r[m] = {}
    for i, k in ipairs(res) do r[m][i] = {fn(k, m)} end
  end
  return r
end

local function col(r, m, j, f)
  local t = {}
  for i = 1, #r[m] do t[i] = f and f(r[m][i][j]) or r[m][i][j] end
  return t
end

local function err(x) return math.abs(x - 1) end

-- each of r[m]'s column j at every resolution no worse (by f) than mass's
local function no_worse(r, m, j, f)
  local ok = true
  for i = 1, #r[m] do ok = ok and f(r[m][i][j]) <= f(r.mass[i][j]) end
  return ok
end

for _, mu in ipairs {0, 0.2} do
  V.case(string.format("block on a grid-aligned flat body, gravity rotated 30 degrees, mu = %g", mu))
  local r = sweep(K, function(k, m) return block(k, m, mu, nil) end, solid)
  print("     |a / (g (sin - mu cos)) - 1|, cells per block side 4 8 16:")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 1, err)) end
  print("     largest spin (rad/time):")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 2)) end
  print("     largest speed across the slope / speed along it:")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 3)) end
  local mv = r.maxvolume
  V.holds("maxvolume: acceleration error below mass's at 4, 8, 16",
          no_worse(r, "maxvolume", 1, err), err(mv[2][1]))
  V.holds("maxvolume: spin below mass's at 4, 8, 16",
          no_worse(r, "maxvolume", 2, function(x) return x end), mv[3][2])
  V.below("maxvolume: speed across the slope at 16 cells", mv[3][3], r.mass[3][3],
          "(limit: mass's)")
  if mu == 0 then
    V.below("maxvolume: frictionless acceleration error at 8 cells", err(mv[2][1]), 0.03)
    V.below("maxvolume: spin at 16 cells below that at 4", mv[3][2], mv[1][2])
  else
    V.info("maxvolume: acceleration error at 8 cells (3 % wanted)", err(mv[2][1]))
  end
end

-- The flat body and the block rotated to the grid: their particles,
-- seeded on the grid's lattice, make both faces staircases that
-- interlock.  Node by node no method lets the block slide (a / g sin
-- near 0, below); the normals over a window of 4 cells (normal_window =
-- 4) see the true faces.  Each angle and friction at 4, 8, 16 cells per
-- block side with linear hats, and at 4 and 8 with GIMP (16 with GIMP in
-- studies/normals.lua).
local DIAG = {{30, 0}, {30, 0.2}, {45, 0}, {45, 0.2}}
local WIN = "maxvolume/4"
for _, c in ipairs(DIAG) do
  local deg, mu = c[1], c[2]
  V.case(string.format("block on a flat body rotated %d degrees to the grid, mu = %g", deg, mu))
  local lin, gim, pl = {}, {}, {}
  for i, k in ipairs(K) do
    lin[i] = {block(k, WIN, mu, deg, "linear")}
    pl[i] = {block(k, "plane/4", mu, deg, "linear")}
    if k <= 8 then gim[i] = {block(k, WIN, mu, deg, "gimp")} end
  end
  local node = {block(8, "mass", mu, deg, "linear")}
  local function errs(t) local e = {} for i = 1, #t do e[i] = err(t[i][1]) end return e end
  print("     |a / (g (sin - mu cos)) - 1|, cells per block side 4 8 16:")
  row(WIN .. " linear", K, errs(lin))
  row("plane/4 linear", K, errs(pl))
  print(string.format("     %-34s 4 %.4f  8 %.4f", WIN .. " gimp", err(gim[1][1]), err(gim[2][1])))
  print(string.format("     mass (node by node) at 8 cells: %.4f", err(node[1])))
  print("     block rotation (rad) and hop (normal displacement / L), linear, maxvolume/4 | plane/4:")
  for i, k in ipairs(K) do
    print(string.format("       %2d cells: rotation %.4f  hop %.5f | %.4f %.5f", k, lin[i][4], lin[i][5],
                        pl[i][4], pl[i][5]))
  end
  local e8 = math.max(err(lin[2][1]), err(gim[2][1]))
  if deg == 45 and mu > 0 then
    -- measured 0.033 with linear hats (0.021 with GIMP): short of 3 %
    V.info(WIN .. ": acceleration error at 8 cells, linear and GIMP (3 % wanted)", e8)
    V.below(WIN .. ": acceleration error at 8 cells, linear and GIMP", e8, 0.05)
  else
    V.below(WIN .. ": acceleration error at 8 cells, linear and GIMP", e8, 0.03)
  end
  V.below(WIN .. ": error at 8 cells below node by node's (mass)", err(lin[2][1]), err(node[1]))
  -- maxvolume's error does not fall at 45 degrees (0.06 at 16 and 32
  -- cells, frictionless); the plane over the same window converges there
  V.below("plane/4: acceleration error at 16 cells", err(pl[3][1]), 0.03)
  V.below("plane/4: acceleration error at 16 cells below that at 4", err(pl[3][1]), err(pl[1][1]))
  -- the target is at 8 cells per block side; at 16 the 45 degree block
  -- tips and hops more with maxvolume (measured, frictionless: rotation
  -- 0.011 rad, hop 0.012 L), reported
  local rot, hop = 0, 0
  for i = 1, 2 do
    rot = math.max(rot, lin[i][4], gim[i][4])
    hop = math.max(hop, lin[i][5], gim[i][5])
  end
  V.below(WIN .. ": no tipping, block rotation (rad) at 4 and 8 cells, both shapes", rot, 0.0175,
          "(1 degree)")
  V.below(WIN .. ": no hop, normal displacement / L at 4 and 8 cells, both shapes", hop, 0.01)
  if mu > 0 then
    -- the friction work booked against mu N times the distance slid, and
    -- the energy budget (sim_residual) against the work of gravity
    local fw, res = 0, 0
    for i = 2, 3 do
      fw = math.max(fw, math.abs(lin[i][6] - 1))
      res = math.max(res, math.abs(lin[i][7]))
    end
    fw, res = math.max(fw, math.abs(gim[2][6] - 1)), math.max(res, math.abs(gim[2][7]))
    V.below(WIN .. ": |friction work / (mu N d) - 1| at 8 and 16 cells, both shapes", fw, 0.05)
    V.below(WIN .. ": |budget residual| / gravity's work at 8 and 16 cells", res, 0.02)
  end
  V.info(WIN .. ": rotation (rad) at 16 cells, linear", lin[3][4])
  V.info(WIN .. ": hop / L at 16 cells, linear", lin[3][5])
  -- at 4 cells the window (9 cells) is wider than the block, and the
  -- plane's block hops up to 0.012 L at 45 degrees: reported
  local prot, phop = 0, 0
  for i = 2, #K do prot, phop = math.max(prot, pl[i][4]), math.max(phop, pl[i][5]) end
  V.below("plane/4: no tipping, rotation (rad) at 8 and 16 cells", prot, 0.0175)
  V.below("plane/4: no hop, normal displacement / L at 8 and 16 cells", phop, 0.01)
  V.info("plane/4: hop / L at 4 cells", pl[1][5])
end

-- A wider window on the tilted faces: the pressing nodes' normals turn
-- toward the grid's axis with the staircases (the summed normal force is
-- tilted 1.5 degrees at 15 degrees, 8 cells, plane/4:
-- docs/verification.md), and the tilt's error is large where the
-- reference is a small difference (shallow slopes with friction).  Over
-- 8 cells, measured at 16 cells per side: 15 deg -0.3 %, 22 deg +0.7 %,
-- 45 deg -1.5 % (plane/4: -18 %, -2.6 %, -2.1 %); at 8 cells +0.7 % at
-- 22 deg and -2.7 % at 45 deg (plane/4: -4.7 %, -3.9 %).  At 15 deg and
-- 8 cells it is -30 % (the window is wider than the block, and the
-- reference a tenth of g sin): reported.
V.case "block on a tilted flat body with friction (mu = 0.2), plane over 8 cells"
do
  for _, deg in ipairs {15, 22, 45} do
    local r8 = C.block {k = 8, method = "plane/8", mu = 0.2, deg = deg}
    local r16 = C.block {k = 16, method = "plane/8", mu = 0.2, deg = deg}
    local r4 = C.block {k = 16, method = "plane/4", mu = 0.2, deg = deg}
    print(string.format("     %2d deg: a / a_ref - 1 = %+.4f (8 cells), %+.4f (16); plane/4 at 16: %+.4f",
                        deg, r8.a - 1, r16.a - 1, r4.a - 1))
    if deg == 15 then
      V.info(string.format("plane/8, %d deg: |a / a_ref - 1| at 8 cells (3 %% wanted)", deg), math.abs(r8.a - 1))
    else
      V.below(string.format("plane/8, %d deg: |a / a_ref - 1| at 8 cells", deg), math.abs(r8.a - 1), 0.03)
    end
    V.below(string.format("plane/8, %d deg: |a / a_ref - 1| at 16 cells", deg), math.abs(r16.a - 1), 0.02)
    V.holds(string.format("plane/8, %d deg: below plane/4's error at 16 cells", deg),
            math.abs(r16.a - 1) < math.abs(r4.a - 1), math.abs(r16.a - 1) / math.abs(r4.a - 1))
    V.below(string.format("plane/8, %d deg: no hop at 16 cells (normal displacement / L)", deg), r16.hop, 0.01)
  end
end

-- One normal per contact patch (normal_patch = true): the node rule on
-- the patch's mean normal.  Over a window each node's normal still turns
-- with the interlocked staircases, and the nodes that press lean toward
-- the grid's axis; with one normal the normal forces are parallel.
-- The patch's planes are fitted over a round window (contact.c
-- window()).  Measured (plane/4+patch, linear hats, a / a_ref - 1 at 8 /
-- 16 cells, mu 0 | 0.2): 15 deg -0.063 / +0.005 | -0.324 / -0.025; 22
-- deg -0.002 / +0.005 | +0.011 / +0.010; 30 deg +0.015 / -0.004 | +0.029
-- / -0.003; 45 deg -0.018 / -0.007 | -0.027 / -0.011 (-0.004 at 32); 60
-- deg -0.002 / +0.001 | -0.002 / +0.002.  Over the square window (as
-- before) 15 deg with friction was -0.020 at 16 cells, and B-splines
-- -0.019 where the round window gives -0.005 (the default shape's case
-- below).  Node by node (plane/4) at 16 cells with friction: 15 deg
-- -0.18, 45 deg -0.021.
V.case "block on a tilted flat body, one normal per contact patch (plane/4+patch)"
do
  local PP = "plane/4+patch"
  for _, deg in ipairs {15, 22, 30, 45, 60} do
    for _, mu in ipairs {0, 0.2} do
      local r8 = C.block {k = 8, method = PP, mu = mu, deg = deg}
      local r16 = C.block {k = 16, method = PP, mu = mu, deg = deg}
      local tag = string.format("%s, %d deg, mu %g", PP, deg, mu)
      print(string.format("     %2d deg, mu %.1f: a / a_ref - 1 = %+.4f (8 cells), %+.4f (16)",
                          deg, mu, r8.a - 1, r16.a - 1))
      if deg == 15 then
        V.info(tag .. ": |a / a_ref - 1| at 8 cells (3 % wanted)", math.abs(r8.a - 1))
      else
        V.below(tag .. ": |a / a_ref - 1| at 8 cells", math.abs(r8.a - 1), 0.03)
      end
      if deg == 15 and mu > 0 then
        -- 0.0250 (0.0202 over the square window); B-splines 0.005
        V.info(tag .. ": |a / a_ref - 1| at 16 cells (2.5 % wanted)", math.abs(r16.a - 1))
      else
        V.below(tag .. ": |a / a_ref - 1| at 16 cells", math.abs(r16.a - 1), 0.025)
      end
      V.below(tag .. ": no tipping, rotation (rad) at 8 and 16 cells",
              math.max(r8.rot, r16.rot), 0.0175)
      V.below(tag .. ": no hop, normal displacement / L at 8 and 16 cells",
              math.max(r8.hop, r16.hop), 0.01)
    end
  end
  -- converging where node by node it did not (maxvolume/4 grew 8 -> 16
  -- cells at 45 deg); plane/4 node by node at 15 deg with friction is
  -- 18 % slow at 16 cells
  local e = {}
  for i, k in ipairs {8, 16, 32} do e[i] = math.abs(C.block {k = k, method = PP, mu = 0.2, deg = 45}.a - 1) end
  print(string.format("     45 deg, mu 0.2: |a / a_ref - 1| %.4f / %.4f / %.4f at 8 / 16 / 32 cells, orders %.2f, %.2f",
                      e[1], e[2], e[3], math.log(e[1] / e[2], 2), math.log(e[2] / e[3], 2)))
  V.holds(PP .. ", 45 deg, mu 0.2: the error falls 8 -> 16 -> 32 cells", e[3] < e[2] and e[2] < e[1], e[3])
  V.below(PP .. ", 45 deg, mu 0.2: |a / a_ref - 1| at 32 cells", e[3], 0.01)
  -- 30 deg with friction at 32 cells: pure FLIP on linear hats lets the
  -- block turn (0.010 rad) and errs 5.9 % (+0.030 / -0.010 / +0.059 at 8
  -- / 16 / 32); one per cent of PIC (flip = 0.99) keeps it converging
  -- (+0.028 / -0.010 / -0.003), as in the debond front at 64 cells
  local f = {}
  for i, k in ipairs {8, 16, 32} do
    f[i] = math.abs(C.block {k = k, method = PP, mu = 0.2, deg = 30, flip = 0.99}.a - 1)
  end
  local pure = C.block {k = 32, method = PP, mu = 0.2, deg = 30}
  print(string.format("     30 deg, mu 0.2, flip 0.99: |a / a_ref - 1| %.4f / %.4f / %.4f at 8 / 16 / 32 cells; pure FLIP at 32: %.4f (rotation %.4f rad)",
                      f[1], f[2], f[3], math.abs(pure.a - 1), pure.rot))
  V.holds(PP .. ", 30 deg, mu 0.2, flip 0.99: the error falls 8 -> 16 -> 32 cells", f[3] < f[2] and f[2] < f[1], f[3])
  V.below(PP .. ", 30 deg, mu 0.2, flip 0.99: |a / a_ref - 1| at 32 cells", f[3], 0.01)
  V.info(PP .. ", 30 deg, mu 0.2, pure FLIP: |a / a_ref - 1| at 32 cells (grows from 16)", math.abs(pure.a - 1))
  local node = C.block {k = 16, method = "plane/4", mu = 0.2, deg = 15}
  local pat = C.block {k = 16, method = PP, mu = 0.2, deg = 15}
  V.below(PP .. ", 15 deg, mu 0.2, 16 cells: error below a fifth of node by node's (plane/4)",
          math.abs(pat.a - 1), 0.2 * math.abs(node.a - 1))
  -- the grid-aligned face: the mass normals' mean over the patch is the
  -- face's (node by node "mass" is 15 % and 33 % slow at 8 cells)
  for _, mu in ipairs {0, 0.2} do
    for _, k in ipairs {8, 16} do
      local r = C.block {k = k, method = "mass+patch", mu = mu}
      V.below(string.format("mass+patch, aligned, mu %g: |a / a_ref - 1| at %d cells", mu, k),
              math.abs(r.a - 1), 0.01)
    end
  end
  -- 3-D: the same block and slope extruded two cells along z (periodic),
  -- one normal per patch in 3-D's patches: the 2-D numbers, but for the
  -- round window's weights, which in 3-D fall with the z offset too (the
  -- window sees the 2-cell period's nodes at several z offsets, so its
  -- taper across the face is not the 2-D one): measured 3.8e-4 apart
  -- (over the square window they agreed to 1e-14)
  do
    local a3 = C.block {k = 8, method = PP, mu = 0.2, deg = 45, dim = 3}.a
    local a2 = C.block {k = 8, method = PP, mu = 0.2, deg = 45}.a
    V.below(PP .. ", 3-D (extruded, periodic z), 45 deg, mu 0.2: |a / a_ref - 1| at 8 cells", math.abs(a3 - 1), 0.03)
    V.below(PP .. ", 3-D against 2-D: |a3 - a2|", math.abs(a3 - a2), 0.002)
  end
  -- GIMP at 45 deg: maxvolume/4 node by node grows to 5-7 % at 16 cells
  for _, mu in ipairs {0, 0.2} do
    local r = C.block {k = 16, method = "maxvolume/4+patch", mu = mu, deg = 45, shape = "gimp"}
    V.below(string.format("GIMP maxvolume/4+patch, 45 deg, mu %g: |a / a_ref - 1| at 16 cells", mu),
            math.abs(r.a - 1), 0.02)
  end
end

-- Both bodies seeded on a lattice of their own, turned with the slope
-- (sim:body's lattice): the faces are straight rows of particles, not the
-- grid lattice's staircase.  B-splines (the default shape), plane/4 with
-- the patch, 8 cells per block side.  Measured, a / a_ref on the grid's
-- lattice -> on the bodies' own, mu 0 | mu 0.2: 15 deg 0.966 -> 0.999 |
-- 0.956 -> 1.027; 22 deg 0.974 -> 0.985 | 0.939 -> 0.976; 30 deg 1.003
-- -> 0.995 | 1.006 -> 0.992; 45 deg 0.980 -> 1.000 | 0.971 -> 0.999; 60
-- deg 0.999 -> 1.001 | 0.998 -> 1.003.  At 15 deg with friction the
-- error is not monotone (1.027 / 0.987 / 0.968 at 8 / 16 / 32 cells):
-- reported (docs/verification.md)
V.case "block on a tilted flat body, both seeded on their own lattice (B-splines, plane/4+patch)"
do
  local PP = "plane/4+patch"
  for _, deg in ipairs {15, 22, 30, 45, 60} do
    for _, mu in ipairs {0, 0.2} do
      local own = C.block {k = 8, method = PP, mu = mu, deg = deg, shape = "bspline2", lattice = true}
      local grid = C.block {k = 8, method = PP, mu = mu, deg = deg, shape = "bspline2"}
      local tag = string.format("own lattice, %d deg, mu %g, 8 cells", deg, mu)
      print(string.format("     %2d deg, mu %.1f: a / a_ref %.4f (grid's lattice %.4f), spin %.3f, hop %.4f L",
                          deg, mu, own.a, grid.a, own.spin, own.hop))
      V.below(tag .. ": |a / a_ref - 1|", math.abs(own.a - 1), 0.03)
      if deg <= 22 and mu > 0 then
        V.below(tag .. ": error over the grid lattice's",
                math.abs(own.a - 1) / math.abs(grid.a - 1), 1)
      end
      V.below(tag .. ": no hop (normal displacement / L)", own.hop, 0.01)
      V.below(tag .. ": no tipping (largest spin, rad per unit time)", own.spin, 0.05)
    end
  end
  local e = {}
  for i, k in ipairs {8, 16, 32} do
    e[i] = math.abs(C.block {k = k, method = PP, mu = 0.2, deg = 45, shape = "bspline2", lattice = true}.a - 1)
  end
  print(string.format("     45 deg, mu 0.2, own lattice: |a / a_ref - 1| %.5f / %.5f / %.5f at 8 / 16 / 32 cells",
                      e[1], e[2], e[3]))
  for i, k in ipairs {8, 16, 32} do
    V.below(string.format("own lattice, 45 deg, mu 0.2: |a / a_ref - 1| at %d cells", k), e[i], 0.002)
  end
end

-- The same blocks over a longer run (to t = 1.2, the acceleration fitted
-- over 0.3 .. 1.2), B-splines, grid's lattice, plane/4+patch, mu 0.2.
-- Measured at 8 / 16 cells: 30 deg 0.991 / 0.997, 45 deg 0.997 / 0.999;
-- 15 deg 0.791 / 0.971 (the block slows as it slides over the face's
-- steps), and at 32 cells under pure FLIP it rocks and runs 27 % fast
-- (flip = 0.99: 0.974): reported (docs/verification.md).  Asserted: 30
-- and 45 deg within 2 % at 8 and 16 cells
V.case "block on a tilted flat body over a longer run (B-splines, plane/4+patch, mu 0.2)"
do
  for _, deg in ipairs {15, 30, 45} do
    for _, k in ipairs {8, 16} do
      local r = C.block {k = k, method = "plane/4+patch", mu = 0.2, deg = deg, shape = "bspline2",
                         t_end = 1.2, fit_from = 0.3}
      local tag = string.format("long run, %d deg, %d cells", deg, k)
      print(string.format("     %2d deg, %2d cells: a / a_ref %.4f, spin %.3f, hop %.4f L", deg, k, r.a, r.spin, r.hop))
      if deg == 15 then
        V.info(tag .. ": |a / a_ref - 1| (3 % wanted)", math.abs(r.a - 1))
      else
        V.below(tag .. ": |a / a_ref - 1|", math.abs(r.a - 1), 0.02)
        -- the block lifts off by 1.1 % of L at the run's end at 45 deg
        -- and 8 cells (0.3 % at 30 deg): reported
        V.info(tag .. ": normal displacement / L at the end", r.hop)
      end
    end
  end
end

V.case "glancing frictionless discs (offset 0.2, one radius)"
local r = sweep(CELLS, discs)
print("     1 - kept relative velocity across the line of centres, cells 20 40 80:")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 1, err)) end
print("     largest spin (rad/time; none wanted):")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 2)) end
print("     1 - total energy kept (kinetic + strain):")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 3, err)) end
-- Known gap: no method keeps the tangential velocity within 2 %: node
-- by node the best, "plane", loses 12-14 %, over a window of 4 cells 8-10 %
-- with linear hats (4-5 % with GIMP at 40 and 80 cells), and none
-- converges from 40 to 80 cells (whole discs: the domain is widened for
-- the offset; on the unit square the upper disc was cut at x = 1 and the
-- losses read 2-4 points smaller).
for _, m in ipairs {"maxvolume/4"} do
  V.holds(m .. ": keeps at least mass's tangential velocity at 20, 40, 80",
          no_worse(r, m, 1, err), r[m][2][1])
  V.holds(m .. ": keeps at least mass's energy at 20, 40, 80",
          no_worse(r, m, 3, err), r[m][2][3])
end
for _, m in ipairs(methods) do
  V.info(m .. ": tangential velocity kept at 40 cells (0.98 wanted)", r[m][2][1])
end

V.case "the new normals give the same numbers at any thread count"
for _, meth in ipairs {"volume", "maxvolume/3", "plane/2", "plane/2+patch"} do
  local mth, win, pat = opts(meth)
  local out = {}
  for _, th in ipairs {1, 2} do
    local sim = mvmpm.sim {domain = C.discs_domain(0.2, 60), cell = 1 / 60, ppc = 2,
      sides = "free", t_end = 1.8, normals = mth, normal_window = win, normal_patch = pat,
      threads = th}
    local m = mvmpm.elastic {E = 1000, nu = 0.3, density = 1000}
    local o = 0.2 / math.sqrt(2)
    local a = sim:body {material = m, velocity = {0.1, 0.1},
      shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.2}}
    sim:body {material = m, velocity = {-0.1, -0.1},
      shape = mvmpm.disk {center = {0.8 + o, 0.8 - o}, radius = 0.2}}
    sim:run()
    local d = a:diag()
    out[th] = string.format("%.17g %.17g %.17g", d.x, d.vy, d.omega)
  end
  V.holds(meth .. ": 1 and 2 threads, the same bits", out[1] == out[2], 0)
end

V.case "a normals setting not known is refused, naming the choices"
do
  local ok, msg = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                                    normals = "volumes"})
  V.holds("normals = \"volumes\": an error naming mass, volume, maxvolume, plane",
          not ok and tostring(msg):find("mass, volume, maxvolume, plane", 1, true) ~= nil, 0,
          tostring(msg))
  ok, msg = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                              normal_window = 9})
  V.holds("normal_window = 9: an error naming the range 0 to 8",
          not ok and tostring(msg):find("[0, 8]", 1, true) ~= nil, 0, tostring(msg))
  ok, msg = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                              contact_gap = "near"})
  V.holds("contact_gap = \"near\": an error naming touch, step",
          not ok and tostring(msg):find("touch, step", 1, true) ~= nil, 0, tostring(msg))
  ok, msg = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                              normal_patch = "yes"})
  V.holds("normal_patch = \"yes\": an error naming the field and true or false",
          not ok and tostring(msg):find("normal_patch", 1, true) ~= nil
          and tostring(msg):find("true or false", 1, true) ~= nil, 0, tostring(msg))
end

V.case "the default shape (B-splines): a block on faces tilted 15 and 30 degrees, mu 0.2, per-patch plane/4"
-- linear hats (the cases above) miss 15 degrees at 8 cells by 32 % and
-- turn the block at 30 degrees and 32 cells under pure FLIP (6.4 %);
-- B-splines with the patch's round window: 15 degrees -4.4 / -0.49 /
-- +1.3 % at 8 / 16 / 32 cells, 30 degrees +0.58 / -0.28 / +0.31 %
-- (over the square window -9.6 / -1.9 % and -0.67 / -1.84 / -1.11 %)
do
  local e = {}
  for _, c in ipairs {{15, 8}, {15, 16}, {30, 8}, {30, 16}} do
    local r = C.block {k = c[2], method = "plane/4+patch", mu = 0.2, deg = c[1], shape = "bspline2"}
    e[c[1] .. "/" .. c[2]] = math.abs(r.a - 1)
    V.info(string.format("B-splines, %d degrees, %d cells: a / a_ref - 1", c[1], c[2]), r.a - 1)
    V.below(string.format("B-splines, %d degrees, %d cells: rotation (rad)", c[1], c[2]), r.rot, 0.002)
    V.below(string.format("B-splines, %d degrees, %d cells: hop / L", c[1], c[2]), r.hop, 0.005)
  end
  V.below("B-splines, 15 degrees: the error falls 8 -> 16 cells", e["15/16"], e["15/8"])
  V.below("B-splines, 15 degrees, 16 cells: |a / a_ref - 1|", e["15/16"], 0.01)
  V.below("B-splines, 30 degrees, 8 cells: |a / a_ref - 1|", e["30/8"], 0.03)
  V.below("B-splines, 30 degrees, 16 cells: |a / a_ref - 1|", e["30/16"], 0.01)
  V.info(string.format("B-splines, 15 degrees, 8 cells: within 3 %% (the goal): %s",
    e["15/8"] <= 0.03 and "met" or "NOT met"), e["15/8"])
end

V.case "the default shape (B-splines): a block on a flat body, the defaults against node by node"
-- On B-splines mass normals node by node (the default until "auto")
-- hold a frictionless block on a flat body along the grid: its bottom
-- corners' nodes take normals turned toward the side, and stopping the
-- approach along them stops the slide (measured a / a_ref 0.006 / 0.021
-- / 0.008 at 8 / 16 / 32 cells; "maxvolume" node by node 0.011 / 0.018 /
-- 0.020).  One normal per patch, from the larger volume gradient over 4
-- cells: within 1.6 % at 0, 30 and 45 degrees, with and without
-- friction, at 8, 16 and 32 cells (45 degrees: 1.1 / 0.6 / 0.2 %
-- frictionless).  As the default everywhere (docs/verification.md,
-- contact: normals) it crept in a settled pile of discs, moved a stack's
-- mean contact forces by 4 % and broke the head-on symmetry of two 3-D
-- spheres; so the default, normals = "auto", takes it only where two
-- flat-faced bodies meet (rect, polygon, box, extrude, not bonded) and
-- the mass gradient node by node elsewhere.
do
  for _, k in ipairs {8, 16} do
    local r = C.block {k = k, method = "mass", mu = 0, shape = "bspline2"}
    V.info(string.format("mass node by node, grid-aligned face, mu 0, %d cells: a / a_ref (1 wanted)", k), r.a)
  end
  -- what "auto" does is that option's to the bit between flat faces,
  -- and the mass gradient's to the bit elsewhere (round bodies pay
  -- nothing for it)
  do
    local a = C.block {k = 8, method = "default", mu = 0.2, deg = 45, shape = "bspline2"}
    local b = C.block {k = 8, method = "maxvolume/4+patch", mu = 0.2, deg = 45, shape = "bspline2",
                       body_contact = "node"}
    V.holds("block at 45 degrees, mu 0.2, 8 cells: the defaults' acceleration is maxvolume/4+patch's node by node to the bit",
      a.a == b.a and a.rot == b.rot, a.a)
    local c = C.discs {cells = 20, offset = 0.2}
    local m = C.discs {cells = 20, method = "mass", offset = 0.2, body_contact = "node"}
    V.holds("glancing discs, 20 cells: the defaults are mass normals and the node rule to the bit",
      c.total == m.total and c.orbit == m.orbit and c.spin == m.spin, c.total)
  end
  -- scenes with flat faces meeting node by node, named, get a warning
  -- naming the remedy; the defaults, round bodies, bonded ones, two
  -- driven ones and a window or patch do not
  local dom = {x = {0, 1}, y = {0, 1}}
  local el = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  local function advice(o, bodies)
    local s = mvmpm.sim(setmetatable(o, {__index = {domain = dom, cell = 0.1}}))
    for _, b in ipairs(bodies) do s:body(b) end
    return s.normals_advice
  end
  local slab = {shape = mvmpm.rect {lo = {0, 0}, hi = {1, 0.2}}, material = el, driven = {0, 0}}
  local block = {shape = mvmpm.rect {lo = {0.3, 0.2}, hi = {0.5, 0.4}}, material = el}
  local adv = advice({normals = "mass"}, {slab, block})
  V.holds("a block on a flat body, normals = \"mass\" node by node: warned, naming the remedy",
    adv ~= nil and adv:find("normal_patch = true", 1, true) ~= nil, 0, tostring(adv))
  V.holds("a triangle on it, normals = \"maxvolume\": warned too",
    advice({normals = "maxvolume"}, {slab, {shape = mvmpm.polygon {{0.3, 0.2}, {0.5, 0.2}, {0.4, 0.4}}, material = el}}) ~= nil)
  V.holds("not warned: the defaults (normals = \"auto\" takes the flat faces' normals)",
    advice({}, {slab, block}) == nil)
  V.holds("not warned: a window, or one normal per patch",
    advice({normals = "mass", normal_window = 4}, {slab, block}) == nil and
    advice({normals = "mass", normal_patch = true}, {slab, block}) == nil)
  V.holds("not warned: a disc on the flat body",
    advice({normals = "mass"}, {slab, {shape = mvmpm.disk {center = {0.4, 0.3}, radius = 0.1}, material = el}}) == nil)
  V.holds("not warned: a bonded block, or two driven flat bodies",
    advice({normals = "mass"}, {slab, {shape = block.shape, material = el, bond = 1}}) == nil and
    advice({normals = "mass"}, {slab, {shape = block.shape, material = el, driven = {0, 0}}}) == nil)
  V.holds("not warned: one velocity field (fields = \"single\")",
    advice({normals = "mass", fields = "single"}, {{shape = slab.shape, material = el}, block}) == nil)
  for _, c in ipairs {{nil, 0}, {45, 0}, {45, 0.2}} do
    for _, k in ipairs {8, 16} do
      local r = C.block {k = k, method = "default", mu = c[2], deg = c[1], shape = "bspline2"}
      local what = string.format("the defaults, %s, mu %g, %d cells", c[1] and c[1] .. " degrees" or "along the grid", c[2], k)
      V.below(what .. ": |a / a_ref - 1|", math.abs(r.a - 1), 0.02)
      V.below(what .. ": rotation (rad)", r.rot, 0.002)
      V.below(what .. ": hop / L", r.hop, 0.005)
    end
  end
  -- 3-D: the block extruded along a periodic z, along the grid (last:
  -- the shapes made after a 3-D scene are 3-D until a 2-D one is made)
  local d = C.block {k = 8, method = "default", mu = 0, shape = "bspline2", dim = 3}
  local e = C.block {k = 8, method = "mass", mu = 0, shape = "bspline2", dim = 3}
  V.below("3-D, along the grid, mu 0, 8 cells, the defaults: |a / a_ref - 1|", math.abs(d.a - 1), 0.02)
  V.info("3-D, the same with mass normals node by node: a / a_ref (held)", e.a)
end

-- The contact options read back from the simulation (sim.wall_contact
-- ...): a script can say which rules a run used.  The defaults, then
-- every option set; in 3-D too.
V.case "the contact options read back"
do
  local function opts(s)
    return table.concat({s.wall_contact, s.body_contact, s.normals, tostring(s.normal_window),
      tostring(s.normal_patch), s.contact_gap, tostring(s.separation), s.wall_remap,
      s.bond_traction, tostring(s.bond_length), s.bond_release}, " ")
  end
  local dom = {x = {0, 1}, y = {0, 1}}
  local d = mvmpm.sim {domain = dom, cell = 0.1}
  V.holds("defaults: " .. opts(d),
    opts(d) == "auto auto auto 0 false touch true auto mixture 0.0 open")
  local s = mvmpm.sim {domain = dom, cell = 0.1, wall_contact = "patch", body_contact = "patch",
    normals = "plane", normal_window = 4, normal_patch = true, contact_gap = "step",
    wall_remap = "hold", bond_traction = "fit", bond_length = 0.2, bond_release = "contact",
    contact = {separation = false}}
  V.holds("as set: " .. opts(s),
    opts(s) == "patch patch plane 4 true step false hold fit 0.2 contact")
  s:contact {separation = true}
  V.holds("separation as sim:contact last set it", s.separation == true)
  local t = mvmpm.sim {dim = 3, domain = {x = {0, 1}, y = {0, 1}, z = {0, 1}}, cell = 0.25,
    wall_contact = "spring", normals = "maxvolume"}
  V.holds("3-D: " .. t.wall_contact .. " " .. t.normals,
    t.wall_contact == "spring" and t.normals == "maxvolume" and t.dim == 3)
end
