-- Gravity along a periodic axis (a chute: the slope's direction made
-- periodic, gravity rotated): material that falls through the seam is
-- put back a period L up the slope, and the potential -sum m g.x, taken
-- over the wrapped positions, would jump by m g L each time.  The
-- potential is taken over the unwrapped positions (the wraps' m L summed
-- per axis, sim_energy.wrap), so it stays the work gravity did.
--
-- 1. A frictionless elastic disc sliding down a periodic incline (2-D,
--    30 deg, g = 1) through the seam four times.  References: the rigid
--    disc's slide, a = g sin(30 deg), so the potential falls by
--    M g sin(30 deg) a t^2 / 2 (the potential's change over the centroid's
--    unwrapped path, from its velocity); the budget closes (frictionless
--    static walls do no work: what the slide gains in kinetic energy is
--    what the potential lost).  Taken wrapped, the potential lost read
--    0.0005 of that and the residual 2,000 times the budget's scale.
-- 2. One and two threads: the same bits.
-- 3. The same in 3-D: a sphere sliding down a periodic incline.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local deg = 30
local th = math.rad(deg)

-- o: dim (2 or 3), cells per diameter, t_end, threads, shape
local function slide(o)
  local R, L = 0.2, 1
  local h = 2 * R / o.cells
  local d3 = o.dim == 3
  local sim = mvmpm.sim {
    dim = o.dim,
    domain = d3 and {x = {0, L}, y = {0, 0.6}, z = {0, 0.4}} or {x = {0, L}, y = {0, 0.6}},
    cell = h, t_end = o.t_end, threads = o.threads, shape = o.shape,
    gravity = d3 and {math.sin(th), -math.cos(th), 0} or {math.sin(th), -math.cos(th)},
    sides = {left = "periodic", right = "periodic", bottom = "wall", top = "wall",
             back = d3 and "wall" or nil, front = d3 and "wall" or nil},
  }
  local shape = d3 and mvmpm.ball {center = {0.5, R, 0.2}, radius = R}
                    or mvmpm.disk {center = {0.5, R}, radius = R}
  local body = sim:body {shape = shape, material = mvmpm.elastic {K = 100, G = 50, density = 1}}
  local e0 = sim:energy()
  local n, worst, wraps, path, lastx = 40, 0, 0, 0, body:diag().x
  local vprev, tprev = 0, 0
  for k = 1, n do
    sim:run(o.t_end * k / n)
    local d, e = body:diag(), sim:energy()
    if d.x < lastx then wraps = wraps + 1 end
    lastx = d.x
    -- the centroid's unwrapped path along the slope, by the trapezoid rule
    path = path + 0.5 * (vprev + d.vx) * (sim.t - tprev)
    vprev, tprev = d.vx, sim.t
    -- after the first quarter, the settling of a body set on the floor
    -- (as mvmpm.incline's slopes), before the first wrap
    if k > n // 4 then worst = math.max(worst, math.abs(e.residual) / e.scale) end
  end
  local e = sim:energy()
  local M = body:diag().mass
  return {sim = sim, e = e, e0 = e0, wraps = wraps, worst = worst, M = M,
          drop = -(e.potential - e0.potential), path = path}
end

V.case "2-D: a frictionless disc sliding through the seam of a periodic incline"
local r = slide {dim = 2, cells = 8, t_end = 4}
local a = math.sin(th)
V.info("wraps through the seam", r.wraps)
V.above("the disc went through the seam at least three times", r.wraps, 2.5)
-- the potential lost is gravity's work along the unwrapped path
local want = r.M * math.sin(th) * r.path
V.info("potential lost / (M g sin(theta) x path)", r.drop / want)
V.near("potential lost over the unwrapped path (1 %)", r.drop, want, 0.01 * want)
V.near("potential lost against the rigid slide's M g sin a t^2 / 2 (3 %)", r.drop,
       r.M * math.sin(th) * 0.5 * a * 16, 0.03 * r.M * math.sin(th) * 0.5 * a * 16)
V.below("largest |budget residual| / scale over the run", r.worst, 0.01)
V.near("kinetic energy gained = potential lost (1 %)", r.e.kinetic - r.e0.kinetic, r.drop, 0.01 * r.drop)

V.case "2-D: three resolutions, two shapes"
do
  -- the potential's bookkeeping must hold at any grid and shape: its
  -- error against the path (the trapezoid rule's, 40 samples) and the
  -- residual stay small at each; neither is a discretization error that
  -- should fall, so no order is asserted
  for _, shape in ipairs {"bspline2", "linear"} do
    for _, c in ipairs {6, 8, 12} do
      local q = slide {dim = 2, cells = c, t_end = 4, shape = shape}
      local err = q.drop / (q.M * math.sin(th) * q.path) - 1
      V.info(string.format("%s, %d cells: wraps", shape, c), q.wraps)
      V.below(string.format("%s, %d cells: |potential lost / path's - 1|", shape, c), math.abs(err), 0.01)
      V.below(string.format("%s, %d cells: largest |residual| / scale", shape, c), q.worst, 0.01)
    end
  end
end

V.case "one and two threads: the potential's bits"
do
  local r1 = slide {dim = 2, cells = 8, t_end = 2.5, threads = 1}
  local r2 = slide {dim = 2, cells = 8, t_end = 2.5, threads = 2}
  V.holds("potential and residual the same, 1 and 2 threads",
          r1.e.potential == r2.e.potential and r1.e.residual == r2.e.residual,
          r1.e.potential - r2.e.potential)
  V.above("the runs went through the seam", r1.wraps, 0.5)
end

V.case "3-D: a frictionless sphere sliding through the seam of a periodic incline"
do
  local r3 = slide {dim = 3, cells = 8, t_end = 3.2}
  V.info("wraps through the seam", r3.wraps)
  V.above("the sphere went through the seam at least twice", r3.wraps, 1.5)
  local want3 = r3.M * math.sin(th) * r3.path
  V.info("potential lost / (M g sin(theta) x path)", r3.drop / want3)
  V.near("potential lost over the unwrapped path (1 %)", r3.drop, want3, 0.01 * want3)
  V.below("largest |budget residual| / scale over the run", r3.worst, 0.01)
end
