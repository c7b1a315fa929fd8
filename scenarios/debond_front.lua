-- A debond front running along a straight bonded interface.  Two elastic
-- blocks (K = 1, G = 0.5, density 1) bonded face to face are pulled apart
-- by rigid grips, smoothly, to a load below the bond's strength (load =
-- 0.8 of it), and held.  At t = release a short seed at the foot of the
-- interface lets go; the traction it carried concentrates at the seed's
-- tip and the debonding runs up the interface.  A front driven by its
-- own tip cannot outrun the Rayleigh wave (c_R = 0.6542 here, plane
-- strain with K the 3-D bulk modulus).
--
--   mvmpm run scenarios/debond_front.lua --set cells=32
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  strength = 0.01,     -- bond strength of the A-B interface
  load = 0.8,          -- the held tension, as a fraction of the strength
  T = 12,              -- time the grips take to reach it
  release = 13,        -- when the seed lets go
  cells = 16,          -- cells per unit length
  t_end = 18,
  traction = "mixture", -- the traction the bond test reads ("fit": fitted, averaged over bond_length)
  bond_length = 0,     -- with "fit": the length of interface it is averaged over
  shape = "linear",    -- shape functions ("linear", "gimp", "bspline2")
  flip = 1,            -- FLIP fraction; 0.99 at 64 cells and finer, where pure
                       -- FLIP's noise cuts the held interface early (docs/verification.md)
  energy = 0,          -- fracture energy per area (the cohesive law; 0: brittle)
}

local sim = mvmpm.sim {
  domain = {x = {0, 3}, y = {0, 2.5}},
  cell = 1 / P.cells,
  t_end = P.t_end,
  sides = "free",
  shape = P.shape,
  flip = P.flip,
  bond_traction = P.traction,
  bond_length = P.bond_length,
  bond_energy = P.energy,
}
local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
-- each grip travels u = load strength / (K + 4G/3) with the speed
-- V0 sin^2(pi t / T), which starts and stops without a jerk
local u = P.load * P.strength / (1 + 4 * 0.5 / 3)
local V0 = 2 * u / P.T
local function v(t) return t < P.T and V0 * math.sin(math.pi * t / P.T) ^ 2 or 0 end
sim:body {name = "gripL", shape = mvmpm.rect {lo = {0.25, 0}, hi = {0.5, 2.5}},
          material = m, driven = function(t) return -v(t), 0 end}
local a = sim:body {name = "A", shape = mvmpm.rect {lo = {0.5, 0.25}, hi = {1.5, 2.5}},
                    material = m, bond = 1}
local seed = sim:body {name = "seed", shape = mvmpm.rect {lo = {0.5, 0}, hi = {1.5, 0.25}},
                       material = m, bond = 1}
local b = sim:body {name = "B", shape = mvmpm.rect {lo = {1.5, 0}, hi = {2.5, 2.5}},
                    material = m, bond = 1}
sim:body {name = "gripR", shape = mvmpm.rect {lo = {2.5, 0}, hi = {2.75, 2.5}},
          material = m, driven = function(t) return v(t), 0 end}
-- A and its seed are bonded to each other without limit; to B, up to the
-- strength under study, until the seed is let go
sim:contact(a, b, {bond = P.strength})
sim:contact(seed, b, {bond = P.strength})
sim:every {time = P.release, fn = function(s)
  if s.t < P.release + s.dt then s:contact(seed, b, {bond = false}) end
end}
sim:output {dir = "out/debond_front", every = 0.25, csv_every = 10}
return sim
