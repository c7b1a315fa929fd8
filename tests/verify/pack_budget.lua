-- Contact: the energy budget of frictional grain packs, where the
-- friction work is booked on the particles' motion (src/core/book.c).
--   1. A column of 12 elastic discs (R = 0.5, K = 400, G = 200, density
--      1; 3 across, 4 high, every other row shifted) collapsing under
--      gravity (g = 1) onto a floor with mu = 0.3 at the walls and between
--      grains, to t = 5, at 4, 6 and 8 cells per diameter.  Residual =
--      E0 - friction - transfer - impact - E below 2 % of the energy put
--      in (E0 measured from the floor).  The grains rest on each other:
--      before the booking moved onto the particles' motion, linear FLIP
--      booked twice the friction the particles lost (the 50-disc column
--      of studies/grain_budget.lua: -32 % residual at 6 cells).
--   2. A random pack of 30 frictional discs pushed by a piston at
--      constant speed (lua/mvmpm/piston.lua) at 2, 3 and 4 cells per
--      smallest diameter: residual below 2 % of the piston's work; the
--      same pack without friction as the control.
-- Schemes asserted: FLIP on linear hats, GIMP and B-splines (the blend
-- flip = 0.99 in studies/); APIC and XPIC are printed (2-3.4 % in the
-- piston pack at 4 cells: not met; docs/verification.md).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"
local P = require "mvmpm.piston"

local mu = 0.3

local function column(c, sc)
  local R, W, nx, ny, T = 0.5, 5, 3, 4, 5
  local sim = mvmpm.sim {
    domain = {x = {0, W}, y = {0, 6}}, cell = 2 * R / c, ppc = 2,
    shape = sc.shape, transfer = sc.transfer, flip = sc.flip or 1, cfl = 0.25,
    t_end = T, gravity = {0, -1},
    sides = {bottom = {"wall", friction = mu}, left = {"wall", friction = mu},
             right = {"wall", friction = mu}, top = "wall"},
    contact = {friction = mu},
  }
  local m = mvmpm.elastic {K = 400, G = 200, density = 1}
  local x0 = W / 2 - nx * 0.55
  for j = 0, ny - 1 do
    for i = 0, nx - 1 do
      sim:body {shape = mvmpm.disk {center = {x0 + 0.55 + i * 1.1 + (j % 2) * 0.25, R + 0.02 + j * 1.08},
                                    radius = R}, material = m}
    end
  end
  sim:run(T)
  return sim:energy()
end

local flips = {
  {shape = "linear", transfer = "flip", flip = 1},
  {shape = "linear", transfer = "flip", flip = 0.99},
  {shape = "bspline2", transfer = "flip", flip = 1},
}

V.case "column of 12 frictional discs collapsing (mu 0.3): budget, 4, 6, 8 cells"
for _, sc in ipairs {flips[1], flips[3]} do
  for _, c in ipairs {4, 6, 8} do
    local e = column(c, sc)
    local put = e.initial
    V.below(string.format("%s, %d cells: |residual| / E0", S.name(sc), c), math.abs(e.residual) / put, 0.02)
    V.info(string.format("%s, %d cells:   friction / E0", S.name(sc), c), e.dissipated / put)
  end
end

V.case "piston pack (30 discs, mu 0.3, piston at 0.5): budget, 2, 3, 4 cells"
for _, sc in ipairs {flips[1], {shape = "gimp", transfer = "flip", flip = 1}} do
  for _, c in ipairs {2, 3, 4} do
    local e, w = P.run {cells = c, scheme = sc, mu = mu}
    V.below(string.format("%s, %d cells: |residual| / piston work", S.name(sc), c), math.abs(e.residual) / w, 0.02)
    V.info(string.format("%s, %d cells:   friction / piston work", S.name(sc), c), e.dissipated / w)
  end
end
do
  local e, w = P.run {cells = 4, scheme = flips[1], mu = 0}
  V.below("control, no friction, linear/flip, 4 cells: |residual| / piston work", math.abs(e.residual) / w, 0.02)
  V.near("control: friction work", e.dissipated, 0, 1e-12)
end
-- the lossy transfers: printed (target 2 %, not met)
for _, sc in ipairs {{shape = "linear", transfer = "xpic"}, {shape = "bspline2", transfer = "apic"}} do
  local e, w = P.run {cells = 3, scheme = sc, mu = mu}
  V.info(string.format("%s, 3 cells: residual / piston work (not asserted)", S.name(sc)), e.residual / w)
end
