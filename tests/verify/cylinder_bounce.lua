-- The report's bouncing cylinder (Figures 2-4).  Frictionless: energy loss
-- after three bounces below 5 %, negligible rotation, each impact reverses
-- the normal momentum and keeps the tangential one.  Frictional (mu = 0.1):
-- spin after the first and second impacts against a rigid-disc impulse
-- model computed here for the same geometry, and the friction work in the
-- energy budget, with the node rule at the walls (the report's scene) and
-- with the patch rule (wall_contact = "patch"), linear hats and GIMP.
-- The report's scheme is kept here: linear hats, MUSL, FLIP (the
-- engine's default shape is B-splines, whose wider stencil takes more at
-- each impact at 8 cells: tests/verify/bounce_convergence.lua).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

-- run the scene, recording momenta between impacts; the spin is also
-- averaged over each flight (a sample every time unit), because the disc
-- rings after an impact and a single sample carries that vibration
local function bounce(mu, cells)
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
                         {friction = mu, t_end = 36, cells = cells or 8, shape = "linear"})
  local disc = sim:bodies()[1]
  local e0 = sim:energy().total
  local flights = {{8, 16}, {20, 28}}
  local marks, out = {10, 20, 30, 36}, {}
  for _, t in ipairs(marks) do
    sim:run(t)
    local d, e = disc:diag(), sim:energy()
    out[#out + 1] = {t = t, vx = d.vx, vy = d.vy, omega = d.omega, e = e}
  end
  -- the same scene again for the flight averages (cheap at this size)
  sim = mvmpm.load("scenarios/cylinder_bounce.lua",
                   {friction = mu, t_end = 36, cells = cells or 8, shape = "linear"})
  disc = sim:bodies()[1]
  for k, fl in ipairs(flights) do
    local sum, n = 0, 0
    for t = fl[1], fl[2] do
      sim:run(t)
      sum, n = sum + disc:omega(), n + 1
    end
    out[k].wmean = sum / n
  end
  return out, e0
end

-- Rigid disc between walls, event driven: impacts are instantaneous, the
-- normal velocity is reversed with restitution e[k] (impact k), and the
-- Coulomb impulse mu (1 + e) v_n per unit mass acts at the contact point,
-- limited to what stops the slip (|slip| / 3 for a disc, I = m R^2 / 2).
-- The elastic disc's restitution is below 1 (vibration keeps some of the
-- energy), so the model is given the restitution the run measured: the
-- friction impulse is mu times the normal impulse whatever e is.
local function rigid(mu, e, t_end)
  local R, x, y, vx, vy, w = 0.5, 2.0, 1.0, 0.1, 0.1, 0
  local lo, hi, t, spins = R, 3 - R, 0, {}
  while #spins < #e do
    local tx = vx > 0 and (hi - x) / vx or (lo - x) / vx
    local ty = vy > 0 and (hi - y) / vy or (lo - y) / vy
    local dt = math.min(tx, ty)
    if t + dt > t_end then break end
    t, x, y = t + dt, x + vx * dt, y + vy * dt
    -- wall normal n (outward from the disc), tangent s = (-ny, nx)
    local nx, ny = 0, 0
    if tx <= ty then nx = vx > 0 and 1 or -1 else ny = vy > 0 and 1 or -1 end
    local sx, sy = -ny, nx
    local vn, ek = vx * nx + vy * ny, e[#spins + 1]
    -- slip of the contact point R n along s: v.s + (w x R n).s
    local slip = (vx * sx + vy * sy) + w * R * (nx * sy - ny * sx)
    local J = math.min(mu * (1 + ek) * vn, math.abs(slip) / 3)
    local sgn = slip > 0 and 1 or -1
    vx = vx - (1 + ek) * vn * nx - sgn * J * sx
    vy = vy - (1 + ek) * vn * ny - sgn * J * sy
    -- torque of the friction impulse -sgn J s at R n, over I / m = R^2 / 2
    w = w - sgn * J * R * (nx * sy - ny * sx) / (R * R / 2)
    spins[#spins + 1] = {t = t, w = w, side = tx <= ty and "x" or "y"}
  end
  return spins
end

-- the frictional case at one resolution: measured spins against the model
-- given the measured restitution of each impact
local function frictional(cells)
  local f, fe0 = bounce(0.1, cells)
  local e1 = -f[1].vx / 0.1           -- impact 1: right wall
  local e2 = -f[2].vy / f[1].vy       -- impact 2: top wall
  local m = rigid(0.1, {e1, e2}, 36)
  return f, fe0, m, e1, e2
end

V.case "frictionless bounce (mu = 0)"
local r, e0 = bounce(0.0)
local loss = 1 - r[4].e.total / e0
V.below("energy loss after 3 bounces (fraction)", loss, 0.05,
  string.format("E0 = %.5f (discrete, 208 particles), E = %.5f", e0, r[4].e.total))
V.below("energy gain after 3 bounces (fraction)", -loss, 0.02)
-- the spin as the frictional case reads it, averaged over each flight:
-- a single sample carries the disc's ringing, at this resolution the
-- method's noise (-0.018 to +0.016 after the third impact over cfl
-- 0.15 - 0.3, docs/stability.md)
V.info("largest single-sample spin |omega| at t = 10, 20, 30, 36", math.max(math.abs(r[1].omega),
  math.abs(r[2].omega), math.abs(r[3].omega), math.abs(r[4].omega)))
V.below("largest flight-mean spin |omega| (flights 1 and 2)",
  math.max(math.abs(r[1].wmean), math.abs(r[2].wmean)), 0.01)
V.below("impact 1 (right wall): vx after / vx before", r[1].vx / 0.1, -0.75)
V.near("impact 1: vy kept", r[1].vy, 0.1, 0.05, true)
V.below("impact 2 (top wall): vy after / vy before", r[2].vy / r[1].vy, -0.75)
V.near("impact 2: vx kept", r[2].vx, r[1].vx, 0.05, true)
V.below("impact 3 (left wall): vx after / vx before", r[4].vx / r[3].vx, -0.75)

V.case "frictional bounce (mu = 0.1), 8 cells per diameter (the report's)"
local f, fe0, model, e1, e2 = frictional(8)
V.info("restitution measured, impact 1 (right wall)", e1)
V.info("restitution measured, impact 2 (top wall)", e2)
V.info("rigid model: spin after impact 1", model[1].w)
V.info("rigid model: spin after impact 2", model[2].w)
V.info("spin after impact 1 (mean over the flight t = 8..16)", f[1].wmean)
V.info("spin after impact 2 (mean over the flight t = 20..28)", f[2].wmean)
-- The wall applies Coulomb's law exactly: the tangential impulse is mu
-- times the normal impulse, here (1 + e) m v_n.
V.near("impact 1: tangential velocity lost / (mu (1 + e) v_n)",
  (0.1 - f[1].vy) / (0.1 * (1 + e1) * 0.1), 1, 0.03)
-- The spin falls short of the model because the nodal friction impulse
-- reaches the particles at their mass centre about a third of a cell
-- inside the surface (lever arm R - h/3 instead of R under FLIP), FLIP
-- slowly loses spin in flight (0.097 -> 0.092 between impacts 2 and 3),
-- and the soft disc (impact at 0.08 c_L) flattens so the contact acts
-- inside R.  All shrink with refinement; at the report's 8 cells the
-- ratios are reported, and the 16-cell case below is held to 15 %.
local r1, r2 = f[1].wmean / model[1].w, f[2].wmean / model[2].w
V.info("spin after impact 1 / rigid model (8 cells)", r1)
V.info("spin after impact 2 / rigid model (8 cells)", r2)
V.above("spin after impact 2 grows (same sense as impact 1)", f[2].omega / f[1].omega, 1.3)
V.above("friction work dissipated (> 0)", f[4].e.dissipated, 0)
V.below("total energy after 3 bounces / initial", f[4].e.total / fe0, 1 - 0.5 * f[4].e.dissipated / fe0)
V.near("energy budget residual / E0", f[4].e.residual / fe0, 0, 0.05)

V.case "frictional bounce (mu = 0.1), 16 cells per diameter"
local g, ge0, gm = frictional(16)
local q1, q2 = g[1].wmean / gm[1].w, g[2].wmean / gm[2].w
V.near("spin after impact 1 / rigid model (16 cells)", q1, 1, 0.15)
-- impact 2 under the node rule: 0.82 of the model (0.86 with the stress
-- rate written for the Cauchy stress); the node rule hardly turns round
-- bodies (docs/verification.md, open item 2), the patch and couple rules
-- below meet 10 % and 5 %
V.info(string.format("spin after impact 2 / rigid model (16 cells), within 0.15: %s",
  math.abs(q2 - 1) <= 0.15 and "met" or "NOT met"), q2)
V.below("refining 8 -> 16 cells brings impact 1 closer to the model",
  math.abs(1 - q1), math.abs(1 - r1))
V.below("refining 8 -> 16 cells brings impact 2 closer to the model",
  math.abs(1 - q2), math.abs(1 - r2))
V.near("energy budget residual / E0 (16 cells)", g[4].e.residual / ge0, 0, 0.05)

-- The patch rule (docs/algorithm.md §9): the friction impulse is one
-- velocity change over the contact patch, so its torque reaches the disc
-- (the node rule stops each node alone and the flat of the lattice disc
-- takes some of it back).  Targets: spins after impacts 1 and 2 within
-- 10 % of the model at 8 cells, 5 % at 16.  Measured at 8, 12 and 16
-- cells in one run each (flights t = 8..16 and 20..28).
local function patched(cells, shape, rule, volume)
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
                         {friction = 0.1, t_end = 28, cells = cells, shape = shape,
                          wall_contact = rule or "patch", volume = volume})
  local disc = sim:bodies()[1]
  local e0 = sim:energy().total
  local s1, s2, d10, d20 = 0, 0, nil, nil
  for t = 1, 28 do
    sim:run(t)
    local d = disc:diag()
    if t >= 8 and t <= 16 then s1 = s1 + d.omega end
    if t >= 20 then s2 = s2 + d.omega end
    if t == 10 then d10 = d end
    if t == 20 then d20 = d end
  end
  local e1, e2 = -d10.vx / 0.1, -d20.vy / d10.vy
  local m = rigid(0.1, {e1, e2}, 36)
  local en = sim:energy()
  return s1 / 9 / m[1].w, s2 / 9 / m[2].w, en.residual / e0, en.dissipated
end

for _, shape in ipairs {"linear", "gimp"} do
  V.case("frictional bounce (mu = 0.1), patch rule, " .. shape)
  local err1, err2 = {}, {}
  for k, c in ipairs {8, 12, 16} do
    local q1p, q2p, res, diss = patched(c, shape)
    err1[k], err2[k] = math.abs(1 - q1p), math.abs(1 - q2p)
    V.info(string.format("spin after impact 1 / rigid model, %d cells", c), q1p)
    V.info(string.format("spin after impact 2 / rigid model, %d cells", c), q2p)
    if c == 8 or c == 16 then
      local tol = c == 8 and 0.10 or 0.05
      for i, e in ipairs {err1[k], err2[k]} do
        V.info(string.format("impact %d, %d cells: error %.3f, target %g: %s", i, c, e, tol,
                             e <= tol and "met" or "NOT met"), e)
      end
    end
    if c >= 12 then
      V.near(string.format("spin after impact 1 / rigid model, %d cells", c), q1p, 1, 0.10)
      V.near(string.format("spin after impact 2 / rigid model, %d cells", c), q2p, 1, 0.10)
      V.near(string.format("energy budget residual / E0, %d cells", c), res, 0, 0.05)
    else
      -- impact 2 at 8 cells loses more at the grid than under the node
      -- rule (restitution 0.73 against 0.84): the residual is that loss
      V.info(string.format("energy budget residual / E0, %d cells", c), res)
    end
    V.above(string.format("friction work dissipated (> 0), %d cells", c), diss, 0)
  end
  V.info("impact 1 error, observed order (8 -> 16)", math.log(err1[1] / err1[3], 2))
  V.info("impact 2 error, observed order (8 -> 16)", math.log(err2[1] / err2[3], 2))
  if shape == "linear" then
    V.below("patch rule closer to the model than the node rule, impact 1, 8 cells", err1[1],
            math.abs(1 - r1))
    V.below("patch rule closer to the model than the node rule, impact 1, 16 cells", err1[3],
            math.abs(1 - q1))
  end
end

-- The defaults: B-splines, pure FLIP and wall_contact = "auto", which
-- takes the patch rule for the disc at the frictional walls, against the
-- node rule on the same shape.  Printed against the targets (10 % at 8
-- cells, 5 % at 16); asserted: the defaults closer to the model than the
-- node rule at both impacts, at 8 and 16 cells, and the budget's
-- residual within 5 % of E0.
V.case "frictional bounce (mu = 0.1), the defaults (B-splines, FLIP, auto) against the node rule"
local defq = {}
for _, c in ipairs {8, 16} do
  local q1, q2, res = patched(c, nil, "default")
  defq[c] = {q1, q2}
  local n1, n2 = patched(c, "bspline2", "node")
  local tol = c == 8 and 0.10 or 0.05
  for i, q in ipairs {q1, q2} do
    local e = math.abs(1 - q)
    V.info(string.format("defaults: spin after impact %d / rigid model, %d cells: error %.3f, target %g: %s",
                         i, c, e, tol, e <= tol and "met" or "NOT met"), q)
  end
  V.info(string.format("node rule: spin after impact 1 / rigid model, %d cells", c), n1)
  V.info(string.format("node rule: spin after impact 2 / rigid model, %d cells", c), n2)
  V.below(string.format("defaults closer to the model than the node rule, impact 1, %d cells", c),
          math.abs(1 - q1), math.abs(1 - n1))
  V.below(string.format("defaults closer to the model than the node rule, impact 2, %d cells", c),
          math.abs(1 - q2), math.abs(1 - n2))
  V.near(string.format("defaults: energy budget residual / E0, %d cells", c), res, 0, 0.05)
end

-- The defaults with the disc seeded by volume = "cut" (sim:body): its
-- particles take the disc's area inside their sub-cells, so the disc has
-- the continuum's mass and polar inertia (the lattice count: 3.5 % too
-- much mass and I = 0.516 m R^2 at 8 cells, against the model's m R^2 /
-- 2).  Asserted at 8 cells: nearer the model than the lattice count at
-- both impacts; the budget's residual within 5 % at both sizes.
V.case "frictional bounce (mu = 0.1), the defaults with volume = \"cut\""
for _, c in ipairs {8, 16} do
  local q1, q2, res = patched(c, nil, "default", "cut")
  local tol = c == 8 and 0.10 or 0.05
  for i, q in ipairs {q1, q2} do
    local e = math.abs(1 - q)
    V.info(string.format("cut: spin after impact %d / rigid model, %d cells: error %.3f, target %g: %s",
                         i, c, e, tol, e <= tol and "met" or "NOT met"), q)
    if c == 8 then
      V.below(string.format("cut: nearer the model than the lattice count, impact %d, 8 cells", i),
              e, math.abs(1 - defq[8][i]))
    end
  end
  V.near(string.format("cut: energy budget residual / E0, %d cells", c), res, 0, 0.05)
end

-- wall_contact = "couple": the patch rule with sliding friction put at the
-- wall line (a couple on the first node line inside, docs/algorithm.md
-- §9).  On the patch alone friction acts at the mass centre of the
-- material the wall line's nodes move, about 0.4 cell above the contact
-- with linear hats, so its torque falls short by that arm (above: 0.85 /
-- 0.82 at 8 cells).  Targets: 10 % at 8 cells, 5 % at 16 (asserted).
for _, shape in ipairs {"linear", "gimp"} do
  V.case("frictional bounce (mu = 0.1), friction at the wall line (couple), " .. shape)
  local err1, err2 = {}, {}
  for k, c in ipairs {8, 12, 16} do
    local q1c, q2c, res, diss = patched(c, shape, "couple")
    err1[k], err2[k] = math.abs(1 - q1c), math.abs(1 - q2c)
    V.info(string.format("spin after impact 1 / rigid model, %d cells", c), q1c)
    V.info(string.format("spin after impact 2 / rigid model, %d cells", c), q2c)
    if c ~= 12 then
      local tol = c == 8 and 0.10 or 0.05
      V.near(string.format("spin after impact 1 / rigid model, %d cells", c), q1c, 1, tol)
      V.near(string.format("spin after impact 2 / rigid model, %d cells", c), q2c, 1, tol)
    end
    if c >= 12 then
      V.near(string.format("energy budget residual / E0, %d cells", c), res, 0, 0.05)
    else
      V.info(string.format("energy budget residual / E0, %d cells", c), res)
    end
    V.above(string.format("friction work dissipated (> 0), %d cells", c), diss, 0)
  end
  V.info("impact 1 error, observed order (8 -> 16)", math.log(err1[1] / err1[3], 2))
  V.info("impact 2 error, observed order (8 -> 16)", math.log(err2[1] / err2[3], 2))
end

-- What the rigid model leaves out.  The report's disc is soft (K = 1, G =
-- 0.5, struck at 0.08 of its wave speed): it flattens against the wall by
-- 11-14 % of its radius at the height of the impact, so friction, which
-- acts at the wall, turns it about an arm shorter than the rigid disc's R
-- (the friction impulse's mean arm, from the disc's centroid to the wall
-- over the impact: about 0.91 R).  Its spin then converges below the
-- rigid model: the wall rules, far apart at 8 cells, come together near
-- 0.92-0.93 of it (docs/verification.md).  A disc 100 times stiffer
-- flattens by about 1 %, and its spin converges to the rigid model.
-- Impact 1 only (flight t = 8 .. 16), the defaults and the node rule.
-- Asserted: the stiff disc's error falls at each refinement and is within
-- 2 % at 32 cells; the rules' spread on the report's disc falls at each
-- refinement and is below 3 % at 32 cells; there the report's disc spins
-- at least 3 % less (over the rigid model) than the stiff one.
local W = dofile("tests/tools/walls.lua")
local function impact1(cells, o)
  local p = {friction = 0.1, t_end = 16, cells = cells}
  for k, v in pairs(o) do p[k] = v end
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", p)
  local disc = sim:bodies()[1]
  local jt, mom = 0, 0
  sim:every {steps = 1, fn = function(s)
    local _, fy = s:wall_force("right")
    jt = jt + fy * s.dt
    mom = mom + (3 - disc:diag().x) * fy * s.dt -- its moment, at the wall line x = 3
  end}
  local w, vx = W.flight1(sim, disc)
  local m = rigid(0.1, {-vx / 0.1}, 16)
  return w / m[1].w, mom / jt / 0.5
end

V.case "frictional bounce (mu = 0.1): a stiff disc (K = 100) and the rigid model, the defaults"
local stiff, serr = {}, {}
for k, c in ipairs {8, 16, 32} do
  local q, arm = impact1(c, {K = 100, G = 50})
  stiff[c], serr[k] = q, math.abs(1 - q)
  V.info(string.format("stiff disc: spin after impact 1 / rigid model, %d cells", c), q)
  V.info(string.format("stiff disc: friction's mean arm / R, %d cells", c), arm)
  if c <= 16 then
    local tol = c == 8 and 0.10 or 0.05
    V.info(string.format("stiff disc, %d cells: error %.3f, target %g: %s", c, serr[k], tol,
                         serr[k] <= tol and "met" or "NOT met"), serr[k])
  end
end
V.below("stiff disc: error falls 8 -> 16 cells", serr[2], serr[1])
V.below("stiff disc: error falls 16 -> 32 cells", serr[3], serr[2])
V.below("stiff disc: error at 32 cells", serr[3], 0.02)
V.info("stiff disc: observed order 8 -> 16", math.log(serr[1] / serr[2], 2))
V.info("stiff disc: observed order 16 -> 32", math.log(serr[2] / serr[3], 2))

V.case "frictional bounce (mu = 0.1): the report's disc, the wall rules converge below the rigid model"
local spread, soft = {}, {}
for k, c in ipairs {8, 16, 32} do
  local qd, arm = impact1(c, {})
  local qn = impact1(c, {shape = "bspline2", wall_contact = "node"})
  spread[k], soft[c] = math.abs(qd - qn), math.max(qd, qn)
  V.info(string.format("defaults: spin after impact 1 / rigid model, %d cells", c), qd)
  V.info(string.format("node rule: spin after impact 1 / rigid model, %d cells", c), qn)
  V.info(string.format("friction's mean arm / R, %d cells (the disc flattens)", c), arm)
end
V.below("the rules' spread falls 8 -> 16 cells", spread[2], spread[1])
V.below("the rules' spread falls 16 -> 32 cells", spread[3], spread[2])
V.below("the rules' spread at 32 cells", spread[3], 0.03)
V.above("32 cells: the stiff disc's spin over the model less the report's disc's (either rule)",
        stiff[32] - soft[32], 0.03)
