-- Walls: the rule "auto" (patch for round bodies at walls with friction,
-- node by node elsewhere), the patch rule's budget in resting contact,
-- and the separation check per body where two share a wall's columns
-- (docs/verification.md, "Walls: auto, resting contact, bodies side by
-- side").
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"

local bs = {shape = "bspline2", transfer = "flip", flip = 1}

-- the same scene under two rules: every number the same, to the bit
local function same(name, a, b)
  V.holds(name, a.vx == b.vx and a.vy == b.vy and a.omega == b.omega and a.diss == b.diss and a.E == b.E,
          math.abs(a.vx - b.vx) + math.abs(a.omega - b.omega) + math.abs(a.E - b.E))
end

-- a body thrown along a floor with friction 0.3 (slide.lua's scene; a
-- rect of the disc's size for the flat body), 8 cells per diameter, t = 1
local function thrown(rule, flat, mu)
  local R = S.R
  local sim = mvmpm.sim {domain = {x = {0, 4}, y = {0, 2}}, cell = 2 * R / 8, ppc = 2, shape = "bspline2",
    cfl = 0.25, gravity = {0, -1}, t_end = 1, wall_contact = rule,
    sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = mu}, top = "wall"}}
  local shape = flat and mvmpm.rect {lo = {1 - R, 0}, hi = {1 + R, 2 * R}}
                     or mvmpm.disk {center = {1, R}, radius = R}
  local b = sim:body {shape = shape, material = mvmpm.elastic {K = 400, G = 200, density = 1}, velocity = {1, 0}}
  sim:run(1)
  local d, e = b:diag(), sim:energy()
  return {vx = d.vx, vy = d.vy, omega = d.omega, diss = e.dissipated, E = e.total}
end

V.case "wall_contact = \"auto\": per patch for a round body on a wall with friction, node by node elsewhere"
do
  local a, p, n = thrown("auto", false, 0.3), thrown("patch", false, 0.3), thrown("node", false, 0.3)
  same("disc on a frictional floor: auto = patch", a, p)
  V.info("disc: spin omega R / vx, auto (node by node)", a.omega * S.R / a.vx)
  V.below("disc: it turns (omega R / vx below -0.2; node by node it hardly does)", a.omega * S.R / a.vx, -0.2)
  V.info("disc: omega R / vx node by node", n.omega * S.R / n.vx)
  same("block on a frictional floor: auto = node", thrown("auto", true, 0.3), thrown("node", true, 0.3))
  same("disc on a frictionless floor: auto = node", thrown("auto", false, 0), thrown("node", false, 0))
end

-- A disc resting on a floor under gravity: nothing in it dissipates or
-- makes energy, yet under the patch rule the budget's residual grows in
-- time (-1.3 / -2.3 % of m g R at t = 20 / 40, 8 and 16 cells; -4.7 %
-- at t = 40 while the patch's normal impulses were booked whole on the
-- nodes' velocities).  Holding the patch's mean on the remap either way
-- kept it level (-0.6 / -0.9 %) but made energy in a random scene under
-- "couple", so it is not done: printed here, an open item
-- (docs/verification.md, walls: auto).
V.case "a disc resting on a floor (gravity): the patch rule's budget (printed)"
do
  for _, rule in ipairs {"patch", "auto", "node"} do
    for _, c in ipairs {8, 16} do
      local sim = mvmpm.sim {domain = {x = {0, 4}, y = {0, 2}}, cell = 1 / c, ppc = 2, shape = "bspline2",
        cfl = 0.25, t_end = 40, wall_contact = rule, gravity = {0, -1},
        sides = {left = "periodic", right = "periodic",
                 bottom = {"wall", friction = rule == "patch" and 0 or 0.5}, top = "wall"}}
      sim:body {shape = mvmpm.disk {center = {1.0, 0.5}, radius = 0.5},
                material = mvmpm.elastic {K = 100, G = 50, density = 1}}
      local mgR = math.pi * 0.25 * 0.5
      sim:run(20)
      local r20 = sim:energy().residual / mgR
      sim:run(40)
      local r40 = sim:energy().residual / mgR
      V.info(string.format("%s, %d cells: residual / m g R at t = 20", rule, c), r20)
      V.info(string.format("%s, %d cells: residual / m g R at t = 40", rule, c), r40)
    end
  end
end

-- Two discs side by side on a floor, their near-wall material a cell
-- and a half apart: the columns between them carry both.  The second is
-- dropped from a cell above the floor while the first rests on it; each
-- is judged by its own reach, so the second falls to the floor too (the
-- reach was taken per column over every body, and under the patch rule
-- the second hovered 1.7 cells above the first on B-splines as long as
-- the first touched the floor).  Both ring on the floor (their heights
-- part by up to 0.4 cells at moments), so the mean over t = 2 .. 4 is
-- held to half a cell.
V.case "two discs side by side: each meets the floor by its own reach"
do
  for _, rule in ipairs {"node", "patch"} do
    for _, shape in ipairs {"bspline2", "gimp", "linear"} do
      local h = 0.05
      local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = h, ppc = 2, shape = shape,
        cfl = 0.25, t_end = 10, wall_contact = rule, gravity = {0, -1},
        sides = {left = "wall", right = "wall", bottom = {"wall", friction = 0.5}, top = "wall"}}
      local m = mvmpm.elastic {K = 200, G = 100, density = 1}
      local a = sim:body {shape = mvmpm.disk {center = {0.25, 0.12}, radius = 0.12}, material = m}
      local b = sim:body {shape = mvmpm.disk {center = {0.57, 0.12 + h}, radius = 0.12}, material = m}
      local sum = 0
      for t = 2, 4, 0.25 do
        sim:run(t)
        sum = sum + (b:diag().y - a:diag().y) / h
      end
      V.below(string.format("%s, %s: the dropped disc's centre above the resting one's, mean over t = 2 .. 4, cells",
                            rule, shape), math.abs(sum / 9), 0.5)
    end
  end
end
