-- Study: a 1-D-like elastic bar ringing in its first free-free mode.
-- A bar 0 < x < L = 1 fills a domain periodic across it (y, 4 cells high),
-- so every section stays plane: uniaxial strain, and the wave speed is the
-- plane-strain longitudinal one, c = sqrt((K + 4G/3) / rho) = 1.2910 (K = 1,
-- G = 0.5, rho = 1).  Its ends are free.  Started with the first mode's
-- velocity v_x = V0 cos(pi x / L) (V0 = 0.01, strain amplitude V0 / c),
-- the exact motion is v_x = V0 cos(pi x / L) cos(2 pi t / T) with the
-- period T = 2 L / c = 1.5492, and the energy stays at its initial value.
-- Measured: the bar is two bodies on one velocity field (its halves, which
-- move as one); the left half's mean velocity is (2 V0 / pi) cos(2 pi t/T),
-- its zero crossings (linear interpolation between steps) over three
-- periods give T (least-squares slope of crossing time against its
-- number = T / 2).  Errors: |T / (2 L / c) - 1| and |E(3T) / E(0) - 1|
-- (E(0) the discrete initial energy).  "cells" counts cells along L.
--
--   ./mvmpm test studies/bar.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local K, G, rho, L, V0 = 1, 0.5, 1, 1, 0.01
local c = math.sqrt((K + 4 * G / 3) / rho)
local T = 2 * L / c

local case = {
  name = "bar",
  title = "bar, first free-free mode",
  length = "L",
  reference = string.format("period 2 L / c = %.5f with c = sqrt((K + 4G/3)/rho) = %.5f; energy E(0)", T, c),
  metrics = {{key = "period", label = "|T/(2L/c) - 1|"}, {key = "energy", label = "|E/E0 - 1| after 3 periods"}},
  extra = {"T_measured", "dE"},
  grid = {cells = {8, 16, 32, 64, 128}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic"}, flip = {1, 0}},
  -- the report's setting: 8 cells across, linear hats, FLIP, MUSL
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local h = L / s.cells
    local sim = mvmpm.sim {domain = {x = {-4 * h, L + 4 * h}, y = {0, 4 * h}}, cell = h, ppc = s.ppc,
      shape = s.shape, transfer = s.transfer, flip = s.flip, update = s.update, cfl = s.cfl,
      sides = {left = "wall", right = "wall", bottom = "periodic", top = "periodic"}}
    local m = mvmpm.elastic {K = K, G = G, density = rho}
    local v = function(x, y) return V0 * math.cos(math.pi * x / L), 0 end
    local left = sim:body {name = "left", field = "bar", material = m, velocity = v,
                           shape = mvmpm.rect {lo = {0, 0}, hi = {L / 2, 4 * h}}}
    sim:body {name = "right", field = "bar", material = m, velocity = v,
              shape = mvmpm.rect {lo = {L / 2, 0}, hi = {L, 4 * h}}}
    local e0 = sim:energy().total
    local crossings, prev, tprev = {}, left:velocity(), 0
    while sim.t < 3 * T do
      clock.step(sim, 1)
      local u = left:velocity()
      if (u > 0) ~= (prev > 0) then
        crossings[#crossings + 1] = tprev + (sim.t - tprev) * prev / (prev - u)
      end
      prev, tprev = u, sim.t
    end
    -- least squares of crossing time on its number: slope = T / 2
    local n, sx, sy, sxx, sxy = #crossings, 0, 0, 0, 0
    for k, t in ipairs(crossings) do sx, sy, sxx, sxy = sx + k, sy + t, sxx + k * k, sxy + k * t end
    local Tm = 2 * (n * sxy - sx * sy) / (n * sxx - sx * sx)
    local d = sim:energy().total / e0 - 1
    return {period = math.abs(Tm / T - 1), T_measured = Tm, energy = math.abs(d), dE = d}
  end,
}
return S.main(case)
