-- Shapes and seeding (lua_shape.c, lua_body.c), in 2-D, then in 3-D
-- (mvmpm.sim{dim = 3} switches the mvmpm functions to the 3-D half),
-- then in 2-D again.
--   1. The seeded measure (area in 2-D, volume in 3-D) of each shape is
--      the count of lattice points inside it times the point's share of
--      a cell; it converges to the shape's exact measure as the cell
--      shrinks.  Three resolutions, the error and observed order at
--      each.  The exact measures are the formulas (pi r^2, 4/3 pi r^3,
--      the shoelace area ...), not the code's own lshape_area, which is
--      checked against them separately.
--   2. The other names of a shape (ball = disk, shell = annulus, box =
--      rect) seed the very same points.
--   3. A body given angular_velocity w spins rigidly: its particles'
--      angular momentum about the centroid is w sum m r^2 (2-D,
--      b:diag()), and its centre of mass is at rest.
--      Any dimension: each particle moves at v0 + w x (x - c), c the
--      seeded centroid, and the centre of mass at v0.
--   4. A ball across a periodic seam seeds its image (the whole ball's
--      measure); a body from points (x, y[, z]) has the points' mass.
--   5. Bad shapes are refused with the field and the expected count.
--   6. volume = "cut": each particle takes the shape's
--      measure inside its sub-cell, and the slivers in sub-cells whose
--      centres are outside go to the nearest particles: the body's mass
--      is the shape's (every size, each shape, below the lattice count's
--      error), a disc's or ball's inertia is the continuum's, a symmetric
--      shape's volumes are symmetric to the bit, and bodies with the rest
--      around them fill the domain's measure.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local pi = math.pi

-- one pass in dimension D: a first simulation of that dimension makes
-- the mvmpm functions (shapes, vectors) that dimension's
local function pass(D)
V.case(string.format("%d-D", D))
do
  local dom = D == 2 and {x = {0, 1}, y = {0, 1}} or {x = {0, 1}, y = {0, 1}, z = {0, 1}}
  mvmpm.sim {domain = dom, cell = 0.5, dim = D}
  V.near("mvmpm.dim", mvmpm.dim, D, 0)
end

-- a point of D coordinates from the first D of x, y, z
local function P(x, y, z) if D == 2 then return {x, y} end return {x, y, z} end

local function domain()
  if D == 2 then return {x = {0, 1}, y = {0, 1}} end
  return {x = {0, 1}, y = {0, 1}, z = {0, 1}}
end

-- the seeded measure of shape at cell 1 / n (density 1; volume "cell":
-- the lattice count, unless given)
local function seeded(n, shape, volume)
  local s = mvmpm.sim {domain = domain(), cell = 1 / n, ppc = 2, dim = D}
  local b = s:body {shape = shape(), material = mvmpm.elastic {K = 1, G = 1, density = 1},
                    volume = volume or "cell"}
  return b:mass(), b
end

local shapes = {}
if D == 2 then
  shapes = {
    {"disk r = 0.3", function() return mvmpm.disk {center = P(0.5, 0.5), radius = 0.3} end,
     pi * 0.09},
    {"annulus 0.15 .. 0.3", function()
       return mvmpm.annulus {center = P(0.5, 0.5), inner = 0.15, outer = 0.3} end,
     pi * (0.09 - 0.0225)},
    {"polygon (triangle)", function()
       return mvmpm.polygon {{0.1, 0.1}, {0.9, 0.2}, {0.3, 0.8}} end,
     0.5 * math.abs((0.9 - 0.1) * (0.8 - 0.1) - (0.3 - 0.1) * (0.2 - 0.1))},
    {"cylinder (tilted strip)", function()
       return mvmpm.cylinder {from = P(0.2, 0.3), to = P(0.8, 0.7), radius = 0.1} end,
     2 * 0.1 * math.sqrt(0.36 + 0.16)},
  }
else
  shapes = {
    {"ball r = 0.3", function() return mvmpm.ball {center = P(0.5, 0.5, 0.5), radius = 0.3} end,
     4 / 3 * pi * 0.027},
    {"shell 0.15 .. 0.3", function()
       return mvmpm.shell {center = P(0.5, 0.5, 0.5), inner = 0.15, outer = 0.3} end,
     4 / 3 * pi * (0.027 - 0.003375)},
    {"extrude (triangle along y)", function()
       return mvmpm.extrude {polygon = {{0.1, 0.1}, {0.9, 0.2}, {0.3, 0.8}}, axis = "y",
                             lo = 0.2, hi = 0.7} end,
     0.5 * math.abs((0.9 - 0.1) * (0.8 - 0.1) - (0.3 - 0.1) * (0.2 - 0.1)) * 0.5},
    {"cylinder (tilted)", function()
       return mvmpm.cylinder {from = P(0.25, 0.3, 0.2), to = P(0.75, 0.6, 0.8), radius = 0.15} end,
     pi * 0.0225 * math.sqrt(0.25 + 0.09 + 0.36)},
  }
end

V.case(string.format("%d-D: the seeded measure converges to the exact one", D))
local ns = D == 2 and {10, 20, 40} or {8, 16, 32}
for _, sh in ipairs(shapes) do
  local name, make, exact = sh[1], sh[2], sh[3]
  local errs = {}
  for i, n in ipairs(ns) do
    errs[i] = math.abs(seeded(n, make) - exact) / exact
    V.info(string.format("%s: relative error at cell 1/%d", name, n), errs[i])
  end
  V.info(name .. ": observed order (finest pair)", math.log(errs[2] / errs[3], 2))
  V.below(name .. ": relative error at the finest cell", errs[3], 0.02)
  V.below(name .. ": error shrinks (finest / coarsest)", errs[3] / errs[1], 0.6)
  V.near(name .. ": s:area() is the exact measure", make():area(), exact, 1e-12, true)
end

V.case(string.format('%d-D: volume = "cut" seeds the exact measure', D))
for _, sh in ipairs(shapes) do
  local name, make, exact = sh[1], sh[2], sh[3]
  local errs = {}
  for i, n in ipairs(ns) do
    local cut = seeded(n, make, "cut")
    local cell = seeded(n, make)
    errs[i] = math.abs(cut - exact) / exact
    V.info(string.format("%s, cut: relative error at cell 1/%d", name, n), errs[i])
    V.below(string.format("%s, cut: error below the lattice count's at cell 1/%d", name, n),
            errs[i], math.abs(cell - exact) / exact)
  end
  V.below(name .. ", cut: relative error at the finest cell", errs[3], 2e-3)
end
do -- the default is the lattice count ("cell")
  local s = mvmpm.sim {domain = domain(), cell = 1 / ns[1], ppc = 2, dim = D}
  local b = s:body {shape = shapes[1][2](), material = mvmpm.elastic {K = 1, G = 1, density = 1}}
  V.near("the default volume is the lattice count: " .. shapes[1][1], b:mass(),
         seeded(ns[1], shapes[1][2]), 0, true)
end
-- a disc's polar inertia (m R^2 / 2) or a ball's about z (2 m R^2 / 5),
-- from the particles (b:diag(): sum m r^2 and each particle's own
-- m a^2 / 6 about its centre)
for i, n in ipairs(ns) do
  local k = {}
  for _, vol in ipairs {"cell", "cut"} do
    local m, b = seeded(n, shapes[1][2], vol)
    local d = b:diag()
    k[vol] = (D == 2 and d.inertia or d.inertia[3][3]) / (m * 0.09)
  end
  local ref = D == 2 and 0.5 or 0.4
  V.info(string.format("%s: I / (m R^2) at cell 1/%d, lattice count", shapes[1][1], n), k.cell)
  V.info(string.format("%s, cut: I / (m R^2) at cell 1/%d", shapes[1][1], n), k.cut)
  if 0.6 * n >= 8 then -- from 8 cells across the diameter
    V.near(string.format("%s, cut: I / (m R^2) at cell 1/%d (continuum %g)", shapes[1][1], n, ref),
           k.cut, ref, 0.005, true)
  end
  if i == 1 then
    V.below(string.format("%s: cut nearer the continuum inertia than the count, cell 1/%d",
                          shapes[1][1], n), math.abs(k.cut - ref), math.abs(k.cell - ref))
  end
end
do -- mirror images: a disc (ball) centred on a lattice line through a site
  -- boundary has its particles' volumes the same to the bit at x and 1 - x
  local s = mvmpm.sim {domain = domain(), cell = 1 / 10, ppc = 2, dim = D}
  s:body {shape = D == 2 and mvmpm.disk {center = P(0.5, 0.5), radius = 0.33}
                  or mvmpm.ball {center = P(0.5, 0.5, 0.5), radius = 0.33},
          material = mvmpm.elastic {K = 1, G = 1, density = 1}, volume = "cut"}
  local x, v = s:particles("position"), s:particles("volume0")
  local key = {}
  local function k3(a, b, c) return string.format("%.6f %.6f %.6f", a, b, c or 0) end
  for i = 1, #v do key[k3(x.x[i], x.y[i], x.z and x.z[i])] = v[i] end
  local worst, found = 0, 0
  for i = 1, #v do
    local w = key[k3(1 - x.x[i], x.y[i], x.z and x.z[i])]
    if w then
      found = found + 1
      worst = math.max(worst, math.abs(w - v[i]))
    end
  end
  V.near("cut: every particle has a mirror image in x", found, #v, 0)
  V.near("cut: the mirror images' volumes are the same to the bit", worst, 0, 0)
end
do -- two bodies with the rest around them fill the domain's measure
  local s = mvmpm.sim {domain = domain(), cell = 1 / ns[1], ppc = 2, dim = D}
  local mat = mvmpm.elastic {K = 1, G = 1, density = 1}
  local r1, r2 = 0.23, 0.17
  local a = s:body {shape = D == 2 and mvmpm.disk {center = P(0.31, 0.33), radius = r1}
                    or mvmpm.ball {center = P(0.31, 0.33, 0.3), radius = r1}, material = mat,
                    volume = "cut"}
  local b = s:body {shape = D == 2 and mvmpm.disk {center = P(0.7, 0.69), radius = r2}
                    or mvmpm.ball {center = P(0.7, 0.69, 0.66), radius = r2}, material = mat,
                    volume = "cut"}
  local r = s:body {shape = mvmpm.rest(), material = mat}
  local va = D == 2 and pi * r1 * r1 or 4 / 3 * pi * r1 ^ 3
  local vb = D == 2 and pi * r2 * r2 or 4 / 3 * pi * r2 ^ 3
  V.near("cut: first body's measure", a:mass(), va, 5e-3, true)
  V.near("cut: second body's measure", b:mass(), vb, 5e-3, true)
  V.near("cut: the bodies and the rest fill the domain", a:mass() + b:mass() + r:mass(), 1, 1e-12,
         true)
end

V.case("the other names seed the same points")
local function count(shape)
  local s = mvmpm.sim {domain = domain(), cell = 0.05, dim = D}
  return s:body {shape = shape, material = mvmpm.elastic {K = 1, G = 1, density = 1}}:mass()
end
local c = P(0.5, 0.5, 0.5)
V.near("ball = disk", count(mvmpm.ball {center = c, radius = 0.3}),
       count(mvmpm.disk {center = c, radius = 0.3}), 0)
V.near("shell = annulus", count(mvmpm.shell {center = c, inner = 0.1, outer = 0.3}),
       count(mvmpm.annulus {center = c, inner = 0.1, outer = 0.3}), 0)
V.near("box = rect", count(mvmpm.box {lo = P(0.2, 0.2, 0.2), hi = P(0.7, 0.6, 0.9)}),
       count(mvmpm.rect {lo = P(0.2, 0.2, 0.2), hi = P(0.7, 0.6, 0.9)}), 0)
V.near("box measure", count(mvmpm.box {lo = P(0.2, 0.2, 0.2), hi = P(0.7, 0.6, 0.9)}),
       D == 2 and 0.5 * 0.4 or 0.5 * 0.4 * 0.7, 1e-12, true)

V.case("a shape across a periodic seam seeds its image")
do
  local sides = {left = "periodic", right = "periodic"}
  local sp = mvmpm.sim {domain = domain(), cell = 0.05, dim = D, sides = sides}
  local m = mvmpm.elastic {K = 1, G = 1, density = 1}
  -- shifted by 9 cells from the middle: the same lattice offsets
  local seam = sp:body {shape = mvmpm.ball {center = P(0.95, 0.5, 0.5), radius = 0.2}, material = m}
  local whole = count(mvmpm.ball {center = P(0.5, 0.5, 0.5), radius = 0.2})
  V.near("the ball across the seam has the whole ball's measure", seam:mass(), whole, 1e-12, true)
  local cx = seam:centroid()
  V.near("its centroid is where the ball is, across the seam", cx, 0.95, 1e-9)
end

V.case("a body from points")
do
  local sp = mvmpm.sim {domain = domain(), cell = 0.05, dim = D}
  local pts = {x = {0.1, 0.2, 0.3}, y = {0.4, 0.5, 0.6}, volume = 0.01}
  if D == 3 then pts.z = {0.7, 0.8, 0.9} end
  local b = sp:body {points = pts, material = mvmpm.elastic {K = 1, G = 1, density = 2}}
  V.near("mass = density x volume x points", b:mass(), 2 * 0.01 * 3, 1e-12, true)
  local c = {b:centroid()}
  V.near("centroid x", c[1], 0.2, 1e-12)
  V.near("centroid " .. (D == 2 and "y" or "z"), c[D], D == 2 and 0.5 or 0.8, 1e-12)
  V.holds("centroid has one number per axis", #c == D, #c)
end

if D == 2 then
  V.case("angular_velocity: a rigid spin, L = w sum m r^2")
  local s = mvmpm.sim {domain = domain(), cell = 0.05}
  local b = s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.3},
                    material = mvmpm.elastic {K = 1, G = 1, density = 1},
                    angular_velocity = 2}
  -- the diagnostics' inertia counts each particle's square (side a =
  -- cell / ppc) as well, a^2 / 6 per unit mass, which the point spin
  -- does not carry: L = w (I - m a^2 / 6)
  local d, a = b:diag(), 0.05 / 2
  V.near("angmom = 2 (inertia - mass a^2 / 6)", d.angmom,
         2 * (d.inertia - d.mass * a * a / 6), 1e-12, true)
  V.near("centre-of-mass velocity x", d.vx, 0, 1e-14)
  V.near("centre-of-mass velocity y", d.vy, 0, 1e-14)
end

V.case("angular_velocity: every particle moves at v + w x (x - c)")
do
  local sp = mvmpm.sim {domain = domain(), cell = 0.1, dim = D}
  local v0, w = P(0.1, -0.2, 0.3), D == 2 and 1.5 or {1, -2, 3}
  local b = sp:body {shape = mvmpm.ball {center = P(0.4, 0.5, 0.6), radius = 0.3},
                     material = mvmpm.elastic {K = 1, G = 1, density = 1},
                     velocity = v0, angular_velocity = w}
  local x, v = sp:particles("position"), sp:particles("velocity")
  local n, c = #x.x, {0, 0, 0}
  local ax = {"x", "y", "z"}
  for d = 1, D do
    for k = 1, n do c[d] = c[d] + x[ax[d]][k] / n end
  end
  local w3 = D == 2 and {0, 0, w} or w
  local worst = 0
  for k = 1, n do
    local r = {0, 0, 0}
    for d = 1, D do r[d] = x[ax[d]][k] - c[d] end
    local cross = {w3[2] * r[3] - w3[3] * r[2], w3[3] * r[1] - w3[1] * r[3],
                   w3[1] * r[2] - w3[2] * r[1]}
    for d = 1, D do
      worst = math.max(worst, math.abs(v[ax[d]][k] - v0[d] - cross[d]))
    end
  end
  V.holds("particles seeded", n > 0 and b:mass() > 0, n)
  V.below("largest |v - v0 - w x r|", worst, 1e-12)
  local vc = {b:velocity()}
  V.near("centre-of-mass velocity x", vc[1], v0[1], 1e-12)
  V.near("centre-of-mass velocity " .. ax[D], vc[D], v0[D], 1e-12)
end

V.case("angular_velocity under APIC: the affine field is the spin, C = [w]x")
do
  local sp = mvmpm.sim {domain = domain(), cell = 0.1, dim = D, transfer = "apic", shape = "gimp"}
  local w = D == 2 and 1.5 or {1, -2, 3}
  sp:body {shape = mvmpm.ball {center = P(0.4, 0.5, 0.6), radius = 0.3},
           material = mvmpm.elastic {K = 1, G = 1, density = 1}, angular_velocity = w}
  local C, w3 = sp:particles("affine"), D == 2 and {0, 0, w} or w
  local ax = {"x", "y", "z"}
  -- [w]x: C_ab = -e_abc w_c
  local want = {xy = -w3[3], yx = w3[3], xz = w3[2], zx = -w3[2], yz = -w3[1], zy = w3[1]}
  local worst = 0
  for a = 1, D do
    for b = 1, D do
      local key = ax[a] .. ax[b]
      for k = 1, #C[key] do
        worst = math.max(worst, math.abs(C[key][k] - (want[key] or 0)))
      end
    end
  end
  V.below("largest |C - [w]x| over the particles", worst, 0)
end

V.case("a body on a lattice of its own (lattice = {angle, origin})")
do
  -- a square of side 0.3 turned by 20 degrees about its corner o, on a
  -- lattice turned with it through o: the points are the square's own
  -- grid, (0.3 / (h / 2))^2 of them (in 3-D times the slab's rows), each
  -- at a half-integer multiple of h / 2 from both faces through o
  local h, th, o = 0.05, math.rad(20), {0.3, 0.2}
  local ca, sa = math.cos(th), math.sin(th)
  local function pt(a, b) return {o[1] + ca * a - sa * b, o[2] + sa * a + ca * b} end
  local corners = {pt(0, 0), pt(0.3, 0), pt(0.3, 0.3), pt(0, 0.3)}
  local m = mvmpm.elastic {K = 1, G = 1, density = 1}
  local function square()
    if D == 2 then return mvmpm.polygon(corners) end
    return mvmpm.extrude {polygon = corners, lo = 0.2, hi = 0.7}
  end
  local origin = D == 2 and o or {o[1], o[2], 0.2}
  local sp = mvmpm.sim {domain = domain(), cell = h, dim = D}
  local b = sp:body {shape = square(), material = m, lattice = {angle = 20, origin = origin}}
  local want = (0.3 / (h / 2)) ^ 2 * (D == 2 and 1 or 0.5 / (h / 2))
  V.near("points: the square's own grid", b:diag().n, want, 1e-9)
  V.near("mass: exactly the square's measure", b:mass(), D == 2 and 0.09 or 0.09 * 0.5, 1e-12, true)
  local pos, worst = sp:particles("position"), 0
  for i = 1, #pos.x do
    local dx, dy = pos.x[i] - o[1], pos.y[i] - o[2]
    for _, u in ipairs {(ca * dx + sa * dy) / (h / 2), (-sa * dx + ca * dy) / (h / 2)} do
      worst = math.max(worst, math.abs(u - 0.5 - math.floor(u)))
    end
  end
  V.below("every point on the turned lattice: largest offset (in spacings)", worst, 1e-9)
  -- on the grid's lattice the same square is a staircase: its count differs
  local sg = mvmpm.sim {domain = domain(), cell = h, dim = D}
  local bg = sg:body {shape = square(), material = m}
  V.info("the same square on the grid's lattice: points", bg:diag().n)
  -- the rest fills around it without taking its place, and a body on the
  -- grid's lattice sharing a face with it is no overlap
  local rest = sp:body {shape = mvmpm.rest(), material = m, overlap = "skip"}
  V.near("the rest takes every grid point but those inside the turned square",
         rest:mass(), 1 - bg:mass(), 1e-12, true)
  local st = mvmpm.sim {domain = domain(), cell = h, dim = D}
  st:body {shape = square(), material = m, lattice = {angle = 20, origin = origin}}
  local below = {pt(0, 0), pt(0.3, 0), pt(0.3, -0.1), pt(0, -0.1)}
  local ok, err = pcall(function()
    st:body {shape = D == 2 and mvmpm.polygon(below) or mvmpm.extrude {polygon = below, lo = 0.2, hi = 0.7},
             material = m}
  end)
  V.holds("a grid-lattice body under its face is no overlap", ok, 0, tostring(err))
  local ok2, err2 = pcall(function()
    st:body {shape = D == 2 and mvmpm.disk {center = pt(0.15, 0.15), radius = 0.05}
                             or mvmpm.ball {center = {pt(0.15, 0.15)[1], pt(0.15, 0.15)[2], 0.45}, radius = 0.05},
             material = m}
  end)
  V.holds("a body inside it is an overlap", not ok2 and tostring(err2):find("overlaps body", 1, true) ~= nil, 0,
          tostring(err2))
  if D == 3 then
    -- across a periodic z seam: each image once, the whole slab's points
    local sides = {left = "free", right = "free", bottom = "free", top = "free",
                   back = "periodic", front = "periodic"}
    local sz = mvmpm.sim {domain = domain(), cell = h, dim = D, sides = sides}
    local across = sz:body {shape = mvmpm.extrude {polygon = corners, lo = 0.8, hi = 1.3}, material = m,
                            lattice = {angle = 20, origin = {o[1], o[2], 0.8}}}
    V.near("across a periodic seam: the slab's own grid, each point once", across:diag().n, want, 1e-9)
    local whole = mvmpm.sim {domain = domain(), cell = h, dim = D, sides = sides}
    local all = whole:body {shape = mvmpm.extrude {polygon = corners, lo = -1, hi = 2}, material = m,
                            lattice = {angle = 20, origin = origin}}
    V.near("a slab longer than the period: one period's points", all:diag().n,
           (0.3 / (h / 2)) ^ 2 * (1 / (h / 2)), 1e-9)
  end
end

V.case("bad shapes: the field and the expected count")
local function refuses(name, fn, pattern)
  local ok, err = pcall(fn)
  err = tostring(err)
  V.holds(name, not ok and err:find(pattern, 1, true) ~= nil, 0, err)
end
local wrong = D == 2 and {0.5, 0.5, 0.5} or {0.5, 0.5}
refuses("disk with the wrong count", function() mvmpm.disk {center = wrong, radius = 0.1} end,
        string.format("disk: field 'center' must be a list of %d numbers", D))
refuses("box with the wrong count", function() mvmpm.box {lo = wrong, hi = wrong} end,
        string.format("box: field 'lo' must be a list of %d numbers", D))
refuses("cylinder with equal ends", function()
  mvmpm.cylinder {from = P(0.5, 0.5, 0.5), to = P(0.5, 0.5, 0.5), radius = 0.1} end,
  "cylinder: fields 'from' and 'to' must be distinct points")
-- (a scene of the other dimension is run by that dimension's half of
-- the program, so only dimensions no half simulates are refused here)
refuses("a sim of dimension 4", function()
  mvmpm.sim {domain = domain(), cell = 0.1, dim = 4} end, "sim: field 'dim'")
refuses("a sim of dimension 2.5", function()
  mvmpm.sim {domain = domain(), cell = 0.1, dim = 2.5} end, "sim: field 'dim'")
-- a material or shape made before the simulation switched dimension
-- (a script, not a scene file): named as such, not "must be a material
-- (got userdata)"
do
  local O = 5 - D
  local odom = O == 2 and {x = {0, 1}, y = {0, 1}} or {x = {0, 1}, y = {0, 1}, z = {0, 1}}
  mvmpm.sim {domain = odom, cell = 0.5, dim = O}
  local omat = mvmpm.elastic {K = 1, G = 1, density = 1}
  local oshape = O == 2 and mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}
                 or mvmpm.ball {center = {0.5, 0.5, 0.5}, radius = 0.2}
  local s = mvmpm.sim {domain = domain(), cell = 0.25, dim = D}
  local mat = mvmpm.elastic {K = 1, G = 1, density = 1}
  local shp = D == 2 and mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}
              or mvmpm.ball {center = {0.5, 0.5, 0.5}, radius = 0.2}
  refuses("a material of the other dimension", function() s:body {shape = shp, material = omat} end,
          string.format("field 'material' is a %d-D material, made before this %d-D simulation", O, D))
  refuses("a shape of the other dimension", function() s:body {shape = oshape, material = mat} end,
          string.format("field 'shape' is a %d-D shape, made before this %d-D simulation", O, D))
end
do
  local s = mvmpm.sim {domain = domain(), cell = 0.1, ppc = 2, dim = D}
  local mat = mvmpm.elastic {K = 1, G = 1, density = 1}
  local shp = D == 2 and mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}
              or mvmpm.ball {center = {0.5, 0.5, 0.5}, radius = 0.2}
  refuses('volume = "cut" on the rest', function()
    s:body {shape = mvmpm.rest(), material = mat, volume = "cut"} end,
    "body 'body1': volume = \"cut\" cuts a shape seeded on the grid's lattice: not the rest")
  if D == 2 then
    refuses('volume = "cut" on a lattice of its own', function()
      s:body {shape = shp, material = mat, volume = "cut", lattice = {angle = 10}} end,
      "volume = \"cut\" cuts a shape seeded on the grid's lattice: not a body with a lattice of its own")
  end
  refuses('volume = "cut" for points', function()
    s:body {points = D == 2 and {x = {0.5}, y = {0.5}} or {x = {0.5}, y = {0.5}, z = {0.5}},
            material = mat, volume = "cut"} end,
    "volume = \"cut\" cuts a shape; 'points' carry their own volumes")
  refuses("volume = \"box\"", function()
    s:body {shape = shp, material = mat, volume = "box"} end, "field 'volume'")
end
if D == 2 then
  refuses("extrude in 2-D", function()
    mvmpm.extrude {polygon = {{0, 0}, {1, 0}, {0, 1}}, lo = 0, hi = 1} end,
    "extrude: the scene is 2-D")
else
  refuses("polygon in 3-D", function() mvmpm.polygon {{0, 0}, {1, 0}, {0, 1}} end,
          "polygon: a polygon is plane")
  refuses("extrude with hi <= lo", function()
    mvmpm.extrude {polygon = {{0, 0}, {1, 0}, {0, 1}}, lo = 1, hi = 1} end,
    "extrude: field 'hi' must exceed 'lo'")
end
end

pass(2)
pass(3)
pass(2) -- and back: the 2-D functions again
