-- The report's bouncing cylinder (Figures 2-4).  Frictionless: energy loss
-- after three bounces below 5 %, negligible rotation, each impact reverses
-- the normal momentum and keeps the tangential one.  Frictional (mu = 0.1):
-- spin after the first and second impacts against a rigid-disc impulse
-- model computed here for the same geometry, and the friction work in the
-- energy budget.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

-- run the scene, recording momenta between impacts; the spin is also
-- averaged over each flight (a sample every time unit), because the disc
-- rings after an impact and a single sample carries that vibration
local function bounce(mu, cells)
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
                         {friction = mu, t_end = 36, cells = cells or 8})
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
                   {friction = mu, t_end = 36, cells = cells or 8})
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
V.below("largest spin |omega| after 3 impacts", math.max(math.abs(r[1].omega),
  math.abs(r[2].omega), math.abs(r[3].omega), math.abs(r[4].omega)), 0.01)
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
V.near("spin after impact 2 / rigid model (16 cells)", q2, 1, 0.15)
V.below("refining 8 -> 16 cells brings impact 1 closer to the model",
  math.abs(1 - q1), math.abs(1 - r1))
V.near("energy budget residual / E0 (16 cells)", g[4].e.residual / ge0, 0, 0.05)
