-- Contact between bodies per contact patch (body_contact = "patch",
-- src/core/contact_patch.c; the default "auto" takes it where a round
-- body meets a flat one with friction) against the node rule
-- (contact.c), on a disc
-- meeting a driven (rigid, still) slab, the cases
-- whose references are rigid-body mechanics:
--   1. free fall beside the slab: nothing may act before the surfaces
--      touch (a slot without mass is no partner);
--   2. frictionless sliding along the slab: the speed is kept;
--   3. thrown along the slab with mu = 0.3: friction takes the rigid
--      disc's W = 1/2 m v0^2 I / (I + m R^2) (slide.lua's M.rigid) and
--      the disc ends rolling;
--   4. on an incline that is the slab (gravity rotated): rolling at
--      25 deg, mu 0.5, a = 2/3 g sin th; sliding at 30 deg, mu 0.1,
--      a = g (sin th - mu cos th), R alpha = 2 mu g cos th.
-- Each at 8, 16 (and 32) cells per diameter, with the observed order.
-- Printed, not asserted, where the patch rule is worse (docs/
-- verification.md, "Contact between bodies per patch"): the head-on
-- collision of two discs loses more energy, and a block with friction on
-- a flat face rocks (a uniform velocity change cannot shift the pressure
-- toward the leading edge).
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"
local I = require "mvmpm.incline"
local C = require "mvmpm.normals"

local flip = {shape = "linear", transfer = "flip", flip = 1}
local function order(e, c)
  return math.log(e[#e - 1] / e[#e]) / math.log(c[#c] / c[#c - 1])
end

V.case "free fall beside a driven slab: nothing acts before the surfaces touch"
-- the disc starts one cell (at 8 cells) above the slab, moving along it
-- at 1; it falls 0.045 by t = 0.3 and touches at t = 0.5
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  local r = S.run {cells = 8, y0 = 0.625, v0 = {1, 0}, mu = 0, T = 0.3, n = 3, slab = true,
                   scheme = {shape = shape, transfer = "flip", flip = 1}}
  V.near(shape .. ": vx at t = 0.3 (free flight)", r.d.vx, 1, 1e-9)
  V.near(shape .. ": vy at t = 0.3 (free flight, -g t)", r.d.vy, -0.3, 1e-9)
end

V.case "frictionless disc thrown along a driven slab: the speed kept, 8 16 cells"
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  for _, rule in ipairs {"node", "patch"} do
    for _, c in ipairs {8, 16} do
      local r = S.run {cells = c, v0 = {1, 0}, mu = 0, T = 1, n = 10, slab = true, body_contact = rule,
                       scheme = {shape = shape, transfer = "flip", flip = 1}}
      local name = string.format("%s %s %d cells", shape, rule, c)
      -- measured 0.9997-1.0000 per patch; node by node 1.0000 with the
      -- slab face's normal (normals "auto", contact.c face()), where the
      -- difference of the two gradients leaned with the disc's radial
      -- one ahead of the contact point: 0.92-0.94 (linear, GIMP),
      -- 0.63-0.69 (B-splines)
      V.near(name .. ": vx / v0 at t = 1", r.d.vx, 1, 0.003)
      V.below(name .. ": |spin| at t = 1", math.abs(r.d.omega), 0.01)
    end
  end
end

V.case "disc thrown along a driven slab, mu 0.3: friction work against the rigid disc's"
local function thrown(c, sc, rule)
  local r = S.run {cells = c, scheme = sc, mu = 0.3, T = 2, n = 40, slab = true, body_contact = rule}
  local e = r.e
  return {w = e.dissipated / r.rigid, imp = e.impact / r.rigid,
          roll = r.d.vx / (1 - 2 * r.rigid / r.m),
          res = e.residual / (e.initial + e.boundary_work)}
end
for _, run in ipairs {
  {name = "patch, linear FLIP", sc = flip, rule = "patch", cells = {8, 16, 32}},
  {name = "patch, GIMP APIC", sc = {shape = "gimp", transfer = "apic"}, rule = "patch", cells = {8, 16}},
  {name = "node, linear FLIP", sc = flip, rule = "node", cells = {8, 16}},
} do
  local err = {}
  for i, c in ipairs(run.cells) do
    local r = thrown(c, run.sc, run.rule)
    local name = string.format("%s, %d cells", run.name, c)
    err[i] = math.abs(r.w - 1)
    V.info(name .. ": friction work / W", r.w)
    V.info(name .. ": impact / W", r.imp)
    V.info(name .. ": end speed / rolling speed", r.roll)
    V.below(name .. ": |residual| / (E0 + W_b)", math.abs(r.res), 0.005)
    if run.rule == "patch" then
      -- measured: linear 1.080 / 1.018 / 1.002, GIMP APIC 1.038 / 1.013
      if c == 16 then V.below(name .. ": |W / W_rigid - 1|", err[i], 0.02) end
      if c == 32 then V.below(name .. ": |W / W_rigid - 1|", err[i], 0.01) end
      -- the disc ends rolling (measured 0.95 / 0.98 / 0.995 linear)
      if c >= 16 then V.near(name .. ": end speed / rolling speed", r.roll, 1, 0.03) end
      -- the impacts book next to nothing (node rule: 0.15-0.31 W)
      V.below(name .. ": |impact| / W", math.abs(r.imp), 0.02)
    end
  end
  if run.rule == "patch" then
    V.holds(run.name .. ": the error falls at each refinement", err[2] < err[1] and (not err[3] or err[3] < err[2]),
            err[#err] / err[1])
    V.info(run.name .. ": observed order", order(err, run.cells))
  end
end

V.case "disc on an incline that is a driven slab: rolling (25 deg, mu 0.5) and sliding (30 deg, mu 0.1)"
local g = 1
for _, reg in ipairs {{deg = 25, mu = 0.5, roll = true}, {deg = 30, mu = 0.1}} do
  local th = math.rad(reg.deg)
  local aref = reg.roll and 2 / 3 * g * math.sin(th) or g * (math.sin(th) - reg.mu * math.cos(th))
  local alref = reg.roll and aref / I.R or 2 * reg.mu * g * math.cos(th) / I.R
  local kind = reg.roll and "rolling" or "sliding"
  for _, rule in ipairs {"node", "patch"} do
    local ea, eal, cs = {}, {}, rule == "patch" and {8, 16, 32} or {8, 16}
    for i, c in ipairs(cs) do
      local r = I.run {cells = c, deg = reg.deg, mu = reg.mu, slab = "driven", shape = "linear",
                       body_contact = rule}
      local name = string.format("%s, %s, %d cells", kind, rule, c)
      ea[i], eal[i] = math.abs(r.a / aref - 1), math.abs(r.alpha / alref - 1)
      V.info(name .. ": a / a_ref", r.a / aref)
      V.info(name .. ": alpha / alpha_ref", r.alpha / alref)
      V.below(name .. ": |residual| / E0", math.abs(r.e.residual / r.e.initial), 0.01)
      if rule == "patch" then
        V.below(name .. ": hop / R", r.hop / I.R, 0.01)
        if reg.roll then
          -- measured 0.932 / 0.981 / 0.986 (goal 2 % at 8 cells, 1 % at
          -- 16: not met; the wall's patch rule gives 0.934 at 8)
          if c >= 16 then V.below(name .. ": |a / a_ref - 1|", ea[i], 0.025) end
        else
          -- measured a 0.997 / 1.000 / 0.996, spin-up 0.825 / 0.955 / 1.004
          V.below(name .. ": |a / a_ref - 1|", ea[i], 0.01)
          if c >= 16 then V.below(name .. ": |spin-up / friction torque's - 1|", eal[i], 0.05) end
        end
      end
    end
    if rule == "patch" then
      V.holds(kind .. ", patch: the acceleration's error falls 8 -> 16 cells", reg.roll and ea[2] < ea[1] or eal[2] < eal[1],
              reg.roll and ea[2] or eal[2])
    end
  end
end

V.case "the defaults (body_contact = \"auto\"): a disc on a flat body is taken per patch"
-- "auto" takes the patch rule where a body with flat faces (rect,
-- polygon, box, extrude, not bonded) meets one that is not with
-- friction between them, and the node rule elsewhere (two discs head
-- on, a block on a slab: normals.lua; without friction: driven_walls.lua).
-- On the default shape (B-splines) the node rule held a disc on a slab
-- before the face's normal: measured at 8 / 16 cells, frictionless
-- speed kept 0.63 / 0.69, rolling a / a_ref -0.04 / 0.46, sliding
-- a / a_ref -0.10 / 0.56 (with it 1.0000 / 1.0000, 0.55 / 0.84,
-- 0.95 / 1.00).
-- Under "auto", measured: speed 1.0000; sliding a 0.998 / 1.000 /
-- 0.996 and spin-up 0.80 / 0.958 / 1.034 at 8 / 16 / 32 cells; rolling
-- 0.914 / 0.984 / 1.000; thrown, friction work 1.107 / 1.023 / 1.000 of
-- the rigid disc's (falling; linear hats 1.080 / 1.018 / 1.002).  With
-- the slab's mass-gradient normals leaning with the disc's and the
-- patch taking the disc's nodes a cell inside, these read 0.68 / 0.89 /
-- 0.985, 0.78 / 0.93 / 0.96 and 1.39 / 1.16 / 1.065.
do
  local function node_and_auto(c)
    local r = {}
    for _, rule in ipairs {"node", "default"} do
      local br = rule ~= "default" and rule or nil
      local f = S.run {cells = c, v0 = {1, 0}, mu = 0, T = 1, n = 10, slab = true, body_contact = br, scheme = {}}
      local sl = I.run {cells = c, deg = 30, mu = 0.1, slab = "driven", body_contact = br}
      local ro = I.run {cells = c, deg = 25, mu = 0.5, slab = "driven", body_contact = br}
      r[rule] = {vx = f.d.vx, slide = sl.a / (g * (math.sin(math.rad(30)) - 0.1 * math.cos(math.rad(30)))),
                 spin = sl.alpha / (2 * 0.1 * g * math.cos(math.rad(30)) / I.R),
                 roll = ro.a / (2 / 3 * g * math.sin(math.rad(25)))}
    end
    return r
  end
  local thrown_w = {}
  for i, c in ipairs {8, 16} do
    local r = node_and_auto(c)
    local name = string.format("B-splines, %d cells", c)
    V.near(name .. ", the defaults: frictionless speed kept, vx / v0 at t = 1", r.default.vx, 1, 0.003)
    V.info(name .. ", node rule: the same", r.node.vx)
    V.near(name .. ", the defaults: sliding a / a_ref (30 deg, mu 0.1)", r.default.slide, 1, 0.01)
    V.info(name .. ", node rule: the same", r.node.slide)
    if c == 16 then
      V.near(name .. ", the defaults: spin-up / friction torque's (5 % wanted)", r.default.spin, 1, 0.05)
    else
      V.info(name .. ", the defaults: spin-up / friction torque's (5 % wanted at 16 cells)", r.default.spin)
    end
    V.info(name .. ", the defaults: rolling a / a_ref (25 deg, mu 0.5; 2 % wanted at 8, 1 % at 16)", r.default.roll)
    V.info(name .. ", node rule: the same", r.node.roll)
    local t = S.run {cells = c, scheme = {}, mu = 0.3, T = 2, n = 40, slab = true}
    thrown_w[i] = t.e.dissipated / t.rigid
    V.info(name .. ", the defaults: thrown, friction work / rigid disc's", thrown_w[i])
    V.below(name .. ", the defaults: thrown, |residual| / (E0 + W_b)",
            math.abs(t.e.residual / (t.e.initial + t.e.boundary_work)), 0.005)
  end
  V.below("the defaults: the friction work's error falls 8 -> 16 cells", math.abs(thrown_w[2] - 1), math.abs(thrown_w[1] - 1))
  local a = S.run {cells = 8, scheme = {}, mu = 0.3, T = 0.5, n = 5, slab = true}
  local b = S.run {cells = 8, scheme = {}, mu = 0.3, T = 0.5, n = 5, slab = true, body_contact = "patch"}
  V.holds("the defaults are the patch rule to the bit on a disc and a slab", a.e.dissipated == b.e.dissipated and
          a.d.vx == b.d.vx, a.e.dissipated)
end

V.case "hard: the disc thrown into the slab at vy = -5 (0.2 of the wave speed), patch rule, 16 cells"
-- measured: nothing buried, largest (kinetic + strain) / E0 1.049 /
-- 1.053 / 0.892 (linear, GIMP, B-splines; the node rule 1.008 / 1.018 /
-- 0.913: linear hats and GIMP under FLIP gain energy in impacts either
-- way), residual -5.6 / -12.8 / -3.7 % of E0 (node rule -6.1 / -11.4 /
-- -4.7 %: the same impacts' loss that FLIP overshoots, open items 8)
for _, shape in ipairs {"linear", "gimp", "bspline2"} do
  local worst, emax, e0, bad = 0, 0, nil, false
  local r = S.run {cells = 16, y0 = 0.5 + 1 / 16, v0 = {0.5, -5}, mu = 0.3, T = 0.6, n = 60, slab = true,
                   body_contact = "patch", scheme = {shape = shape, transfer = "flip", flip = 1},
                   run = function(sim, t)
                     sim:run(t)
                     local _, d = sim:overlap()
                     local e = sim:energy()
                     e0 = e0 or e.initial
                     worst = math.max(worst, d or 0)
                     emax = math.max(emax, (e.kinetic + e.strain) / e0)
                     bad = bad or e.kinetic ~= e.kinetic
                   end}
  V.holds(shape .. ": no NaN", not bad, emax)
  V.below(shape .. ": deepest burial (cells)", worst, 0.5)
  V.below(shape .. ": largest (kinetic + strain) / E0", emax, 1.1)
  V.info(shape .. ": residual / E0", r.e.residual / r.e.initial)
end

V.case "3-D: a ball thrown along a driven slab, mu 0.3"
-- the ball of tests/verify/friction_work.lua (R = 0.5, K = 400, G =
-- 200) on a driven box 0.25 thick; the rigid ball's W from the seeded
-- particles (slide.lua's M.rigid, about z).  Measured: patch 1.062 /
-- 1.033 at 8 / 12 cells (the walls' patch rule 1.083 / 1.038), impacts
-- 0.004 W; node by node 1.200 / 1.064 with another 0.17 / 0.24 W
-- booked as impacts.  On linear hats: with B-splines (the default shape)
-- the patch gave 0.92 / 1.27 with impacts 0.20 W at 12 cells (open item
-- in docs/verification.md)
do
  local mvmpm = require "mvmpm"
  local function ball(c, rule)
    local R, cell, H = 0.5, 1 / c, 0.25
    local sim = mvmpm.sim {dim = 3, domain = {x = {0, 3}, y = {0, 2.25}, z = {0, 1.5}}, cell = cell,
      ppc = 2, cfl = 0.25, shape = "linear", t_end = 2, gravity = {0, -1, 0}, body_contact = rule, contact = {friction = 0.3},
      sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = 0}, top = "wall",
               back = "wall", front = "wall"}}
    sim:body {name = "slab", shape = mvmpm.box {lo = {0, 0, 0}, hi = {3, H, 1.5}},
              material = mvmpm.elastic {K = 1000, G = 500, density = 1}, driven = {0, 0, 0}}
    sim:body {shape = mvmpm.ball {center = {0.8, H + R, 0.75}, radius = R},
              material = mvmpm.elastic {K = 400, G = 200, density = 1}, velocity = {1, 0, 0}}
    local W = S.rigid(sim, 1, cell, 2, 2)
    sim:run(2)
    local e = sim:energy()
    return e.dissipated / W, e.impact / W, e.residual / (e.initial + e.boundary_work)
  end
  local p8, i8, r8 = ball(8, "patch")
  local p12, i12, r12 = ball(12, "patch")
  local n8, j8 = ball(8, "node")
  V.info("3-D patch, 8 cells: friction work / rigid ball's", p8)
  V.info("3-D patch, 12 cells: friction work / rigid ball's", p12)
  V.info("3-D node, 8 cells: friction work / rigid ball's", n8)
  V.info("3-D node, 8 cells: impact / rigid ball's friction work", j8)
  V.below("3-D patch: the error falls 8 -> 12 cells", math.abs(p12 - 1), math.abs(p8 - 1))
  V.below("3-D patch, 12 cells: |W / W_rigid - 1|", math.abs(p12 - 1), 0.05)
  V.below("3-D patch: |impact| / W at 8 and 12 cells", math.max(math.abs(i8), math.abs(i12)), 0.02)
  V.below("3-D patch: |residual| / (E0 + W_b) at 8 and 12 cells", math.max(math.abs(r8), math.abs(r12)), 0.005)
end

V.case "printed: where the patch rule is worse"
-- Two discs colliding head on (Sulsky's geometry, mass normals, linear
-- hats): measured total energy after over before, node 0.986 / 0.990 /
-- 0.9996, patch 0.912 / 0.926 / 0.942 at 20 / 40 / 80 cells
for _, rule in ipairs {"node", "patch"} do
  for _, c in ipairs {20, 40} do
    local r = C.discs {cells = c, offset = 0, method = "mass/0", body_contact = rule}
    V.info(string.format("head-on, %s, %d cells: energy after / before", rule, c), r.total)
  end
end
-- A block (8 cells per side) sliding with mu 0.2 on a driven flat body,
-- gravity rotated 30 deg: measured a / a_ref node 0.999, patch 0.971,
-- largest spin 0.04 and 0.54, friction work over Coulomb's 0.98 and 0.46
-- (maxvolume/4 normals)
for _, rule in ipairs {"node", "patch"} do
  local r = C.block {k = 8, method = "maxvolume/4", mu = 0.2, body_contact = rule}
  V.info(string.format("block, mu 0.2, %s: a / a_ref", rule), r.a)
  V.info(string.format("block, mu 0.2, %s: largest spin", rule), r.spin)
  V.info(string.format("block, mu 0.2, %s: friction work / Coulomb's", rule), r.friction)
end

V.case "the same numbers on 1 and 2 threads (the patch pass is serial)"
do
  local function once(threads)
    local r = I.run {cells = 8, deg = 25, mu = 0.5, slab = "driven", body_contact = "patch", threads = threads}
    return r.a, r.e.friction
  end
  local a1, f1 = once(1)
  local a2, f2 = once(2)
  V.holds("rolling on the slab: a and friction work bit for bit", a1 == a2 and f1 == f2, a2 - a1)
end
