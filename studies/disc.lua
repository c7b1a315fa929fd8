-- Study: a free elastic disc spinning in place (diameter D = 1, K = 1,
-- G = 0.5, rho = 1, omega0 = 0.1, so the rim moves at 0.05 = 0.04 c),
-- far from the walls of a 2 x 2 box, for t = 20 (two radians).
-- References: nothing acts on the disc, so its angular momentum about its
-- centroid must keep its discrete initial value L(0); error
-- |L(20) / L(0) - 1|.  The spin settles about the steady elastic spin
-- omega0 / (1 + dI/I): the centrifugal stretch of a plane-strain disc,
-- u(r) = A r - rho w^2 r^3 / (8 M) with M = lambda + 2G and
-- A = rho w^2 R^2 (3M + lambda) / (16 M (lambda + G)) (sigma_rr(R) = 0),
-- raises its inertia by dI/I = 2A - rho w^2 R^2 / (6M) = 6.6e-4 here.
-- Spin error: |mean omega over t = 10 .. 20 / omega_ref - 1| with
-- omega_ref = omega(0) / (1 + dI/I), omega(0) the discrete initial spin
-- (b:omega(), whose inertia counts each particle's own square).
--
--   ./mvmpm test studies/disc.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local K, G, rho, R, w0, t_end = 1, 0.5, 1, 0.5, 0.1, 20
local lambda = K - 2 * G / 3
local M = lambda + 2 * G
local A = rho * w0 * w0 * R * R * (3 * M + lambda) / (16 * M * (lambda + G))
local dI = 2 * A - rho * w0 * w0 * R * R / (6 * M)

local case = {
  name = "disc",
  title = "spinning disc",
  length = "D",
  reference = string.format("angular momentum L(0); spin omega(0) / (1 + %.3g)", dI),
  metrics = {{key = "angmom", label = "|L/L0 - 1| at t = 20"},
             {key = "spin", label = "|omega/omega_ref - 1|"}},
  extra = {"dL", "omega_mean", "dE"},
  grid = {cells = {8, 12, 16, 24, 32, 48}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic", "spin"}, flip = {1, 0}},
  -- the report's setting: 8 cells across, linear hats, FLIP, MUSL
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local h = 1 / s.cells
    local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 2}}, cell = h, ppc = s.ppc,
      shape = s.shape, transfer = s.transfer, flip = s.flip, update = s.update, cfl = s.cfl}
    local disc = sim:body {shape = mvmpm.disk {center = {1, 1}, radius = R},
      material = mvmpm.elastic {K = K, G = G, density = rho}, angular_velocity = w0}
    local d0, e0 = disc:diag(), sim:energy().total
    local L0, wref = d0.angmom, d0.omega / (1 + dI)
    clock.run(sim, 10)
    local sum, n = 0, 0
    for t = 10, t_end, 0.5 do
      clock.run(sim, t)
      sum, n = sum + disc:omega(), n + 1
    end
    local dL = disc:diag().angmom / L0 - 1
    return {angmom = math.abs(dL), dL = dL, spin = math.abs(sum / n / wref - 1), omega_mean = sum / n,
            dE = sim:energy().total / e0 - 1}
  end,
}
return S.main(case)
