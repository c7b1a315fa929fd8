-- Walls: a round body on a tilted frictional floor, in this build's
-- dimension (boundary.c; docs/algorithm.md §8).  The floor is the bottom
-- wall, periodic along it; gravity (g = 1) is tilted by theta from the
-- floor's normal, its tangential part along x in 2-D and, in 3-D, 30 deg
-- from x toward z, so that friction is a vector the wall must put along
-- the slip.  An elastic disc (2-D) or ball (3-D), R = 0.5, K = 100,
-- G = 50, density 1, starts on the floor; GIMP, FLIP, MUSL, 2 particles
-- per cell along each axis, at 6, 8 and 12 cells per diameter.
-- Reference, the rigid body with inertia k m R^2 (k = 1/2 disc, 2/5 ball):
--   sliding (theta 30 deg, mu 0.1, wall_contact = "couple"):
--     a = g (sin - mu cos) along the tangential gravity, R alpha = mu g cos / k
--   rolling (theta 25 deg, mu 0.5, wall_contact = "patch"):
--     a = g sin / (1 + k), R alpha = a
--     (targets a within 4 %, R alpha / a within 5 %, printed, not
--     asserted: in 3-D met at 8 cells (0.980, 0.980), not at 6 (0.918,
--     1.090) nor 12 (1.038, 0.840: the ball slips); in 2-D a is 0.930,
--     0.935, 0.984 and R alpha / a 1.076, 1.046, 1.074 (the disc rolls
--     on a shorter radius, tests/verify/rolling.lua); asserted are the
--     direction of a and R alpha / a > 0.75)
-- Slopes fitted over t = 0.3 .. 1.2 (the first quarter is the settling).
-- alpha is the spin about n x t (n the floor's normal into the body, t
-- the unit tangential gravity): positive is rolling down.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local D = mvmpm.dim
local R, T = 0.5, 1.2
local phi = D == 3 and math.rad(30) or 0
local k = D == 3 and 2 / 5 or 1 / 2

local function comp(o, i)
  if type(o) ~= "table" then return o end
  return o[i] or o[({"x", "y", "z"})[i]]
end

local function run(cells, deg, mu, rule)
  local th = math.rad(deg)
  local gt, gn = math.sin(th), math.cos(th)
  local dom, grav, sides, c
  if D == 3 then
    dom = {x = {0, 3}, y = {0, 1.5}, z = {0, 2}}
    grav = {gt * math.cos(phi), -gn, gt * math.sin(phi)}
    sides = {left = "periodic", right = "periodic", back = "periodic", front = "periodic",
             bottom = {"wall", friction = mu}, top = "wall"}
    c = {1, R, 1}
  else
    dom = {x = {0, 3}, y = {0, 1.5}}
    grav = {gt, -gn}
    sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = mu}, top = "wall"}
    c = {1, R}
  end
  local sim = mvmpm.sim {domain = dom, cell = 1 / cells, ppc = 2, shape = "gimp",
                         wall_contact = rule, t_end = T, cfl = 0.25, gravity = grav, sides = sides}
  local b = sim:body {shape = mvmpm.disk {center = c, radius = R},
                      material = mvmpm.elastic {K = 100, G = 50, density = 1}}
  local n, ts, vx, vz, al = 24, {}, {}, {}, {}
  for j = 1, n do
    sim:run(T * j / n)
    local d = b:diag()
    ts[j], vx[j], vz[j] = sim.t, d.vx, D == 3 and d.vz or 0
    -- the spin about n x t: in 2-D -omega_z (clockwise rolls down +x)
    if D == 3 then
      al[j] = comp(d.omega, 1) * math.sin(phi) - comp(d.omega, 3) * math.cos(phi)
    else
      al[j] = -comp(d.omega, 1)
    end
  end
  local function slope(y)
    local sx, sy, sxx, sxy, m = 0, 0, 0, 0, 0
    for i = n // 4, n do
      sx, sy, sxx, sxy, m = sx + ts[i], sy + y[i], sxx + ts[i] ^ 2, sxy + ts[i] * y[i], m + 1
    end
    return (m * sxy - sx * sy) / (m * sxx - sx * sx)
  end
  local ax, az = slope(vx), slope(vz)
  return {a = math.sqrt(ax ^ 2 + az ^ 2), dir = math.deg(math.atan(az, ax)), alpha = slope(al),
          gt = gt, gn = gn, e = sim:energy()}
end

local function order(e)
  if e[1] > 0 and e[3] > 0 then return math.log(e[1] / e[3]) / math.log(12 / 6) end
  return 0 / 0
end

local cells = {6, 8, 12}

-- a target the method does not meet at every resolution: printed with
-- its measured value beside it, not asserted
local function target(name, ratio, tol)
  local err = math.abs(ratio - 1)
  V.info(string.format("%s: %.4f, target 1 +- %g: %s", name, ratio, tol,
                       err <= tol and "met" or "NOT met"), ratio)
end

V.case(string.format("%d-D: sliding (theta 30 deg, mu 0.1, couple): acceleration, its direction, spin-up", D))
local ea, es = {}, {}
for i, n in ipairs(cells) do
  local r = run(n, 30, 0.1, "couple")
  local a_ref = r.gt - 0.1 * r.gn
  local al_ref = 0.1 * r.gn / k / R
  ea[i] = math.abs(r.a / a_ref - 1)
  es[i] = math.abs(r.alpha / al_ref - 1)
  V.near(string.format("a / (g (sin - mu cos)), %d cells", n), r.a / a_ref, 1, 0.03)
  V.near(string.format("direction of a (deg), %d cells", n), r.dir, math.deg(phi), 1)
  V.near(string.format("spin-up alpha / (mu g cos / (k R)), %d cells", n), r.alpha / al_ref, 1, 0.15)
  V.above(string.format("friction work dissipated (> 0), %d cells", n), r.e.dissipated, 1e-4)
end
V.info("sliding a error, observed order (6 -> 12)", order(ea))
V.info("sliding spin-up error, observed order (6 -> 12)", order(es))

V.case(string.format("%d-D: rolling (theta 25 deg, mu 0.5, patch): acceleration, no slip", D))
local er = {}
for i, n in ipairs(cells) do
  local r = run(n, 25, 0.5, "patch")
  local a_ref = r.gt / (1 + k)
  er[i] = math.abs(r.a / a_ref - 1)
  target(string.format("a / (g sin / (1 + k)), %d cells", n), r.a / a_ref, 0.04)
  target(string.format("rolling without slip: R alpha / a, %d cells", n), R * r.alpha / r.a, 0.05)
  V.near(string.format("direction of a (deg), %d cells", n), r.dir, math.deg(phi), 1)
  V.above(string.format("rolls: R alpha / a above 0.75, %d cells", n), R * r.alpha / r.a, 0.75)
end
V.info("rolling a error, observed order (6 -> 12)", order(er))
