-- Study: a block crossing cells.  A block translating rigidly carries no
-- stress and the engine keeps it at round-off on every shape function
-- (tests/verify/accuracy.lua checks it): the nodal velocities are the
-- block's velocity exactly.  Crossing cells matters once the velocity
-- varies, so here the square block (side 0.5, K = 1, G = 0.5, rho = 1,
-- alpha = 1) translates at (0.1, 0.037) while it grows homogeneously at
-- the strain rate beta = 1e-3 in x and y, driven by a temperature ramp that
-- makes the growth free: T(t) = beta t / (1 + nu) (a free body grows in
-- plane by (1 + nu) alpha dT), with the matching initial velocity
-- v = v0 + beta (x - c).  Reference: the exact motion is stress free in
-- plane (sigma_xx = sigma_yy = sigma_xy = 0; sigma_zz = -E alpha dT from
-- eps_zz = 0) at every instant.  Error: the largest in-plane |sigma| of any
-- particle at any step up to t = 10 (the faces cross 1 .. 6 cells), over
-- 2 K' beta t_end (K' = K + G/3), the in-plane stress the same growth would
-- cause if fully confined.  "cells" counts cells across the block.
--
--   ./mvmpm test studies/block.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local K, G, rho, side, beta, t_end = 1, 0.5, 1, 0.5, 1e-3, 10
local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
local scale = 2 * (K + G / 3) * beta * t_end

local case = {
  name = "block",
  title = "block crossing cells",
  length = "the block's side",
  reference = "exact motion free of in-plane stress; error scaled by 2 K' beta t_end",
  metrics = {{key = "stress", label = "max |sigma| / (2 K' beta t)"}},
  grid = {cells = {8, 12, 16, 24, 32}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic"}, flip = {1, 0}, update = {"musl", "usl"}},
  -- PIC only on linear hats; USL only on linear hats with FLIP
  skip = function(s)
    if s.update == "usl" then return s.transfer ~= "flip" or s.flip ~= 1 or s.shape ~= "linear" end
    return s.flip == 0 and s.shape ~= "linear"
  end,
  -- the report's setting: 8 cells across, linear hats, FLIP, MUSL
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local h = side / s.cells
    local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 2}}, cell = h, ppc = s.ppc,
      shape = s.shape, transfer = s.transfer, flip = s.flip, update = s.update, cfl = s.cfl}
    local cx, cy = 0.75, 0.75
    sim:body {shape = mvmpm.rect {lo = {0.5, 0.5}, hi = {1.0, 1.0}},
      material = mvmpm.elastic {K = K, G = G, density = rho, alpha = 1},
      velocity = function(x, y) return 0.1 + beta * (x - cx), 0.037 + beta * (y - cy) end}
    sim:temperature(function(t) return beta * t / (1 + nu) end)
    local mx = 0
    while sim.t < t_end do
      clock.step(sim, 1)
      if clock.rep == 1 then   -- measured once; the repeats only time
        local st = sim:particles("stress")
        local xx, yy, xy = st.xx, st.yy, st.xy
        for i = 1, #xx do
          local a = math.max(math.abs(xx[i]), math.abs(yy[i]), math.abs(xy[i]))
          if a > mx then mx = a end
        end
      end
    end
    return {stress = mx / scale}
  end,
}
return S.main(case)
