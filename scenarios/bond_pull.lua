-- Two elastic blocks bonded face to face, pulled apart by rigid grips
-- whose speed ramps up smoothly (so the load is nearly quasi-static).
-- Top and bottom are periodic, so the blocks are in uniaxial strain and
-- the stress in them is sigma_xx = (K + 4G/3) eps_xx.  The interface
-- between A and B holds until its normal traction reaches the bond
-- strength, then lets go at once along its whole length; with a fracture
-- energy (energy > 0, the cohesive law) its traction then falls linearly
-- with the opening, to nothing once the energy per area is spent.
--
--   mvmpm run scenarios/bond_pull.lua --set strength=0.02
--   mvmpm run scenarios/bond_pull.lua --set energy=2e-4
local mvmpm = require "mvmpm"

local P = mvmpm.params {
  strength = 0.01,     -- bond strength of the A-B interface (stress)
  V0 = 0.002,          -- grip speed after the ramp
  ramp = 8,            -- ramp time of the grip speed
  cells = 16,          -- cells per unit length
  energy = 0,          -- fracture energy per area of the A-B interface
  shape = "linear",
  transfer = "flip",   -- or "apic", "xpic"
  update = "default",  -- or "usl", "musl", "usavg"
  shift = 0,           -- the bodies moved along x by this fraction of a cell
  dim = 2,             -- 3: the same blocks 0.25 deep, periodic back and front
  t_end = 12,
}

local d3 = P.dim == 3
local sim = mvmpm.sim {
  dim = P.dim,
  domain = {x = {0, 3}, y = {0, 0.5}, z = d3 and {0, 0.25} or nil},
  cell = 1 / P.cells,
  shape = P.shape,
  transfer = P.transfer,
  update = P.update ~= "default" and P.update or nil,
  bond_energy = P.energy,
  t_end = P.t_end,
  sides = {left = "free", right = "free", bottom = "periodic", top = "periodic",
           back = d3 and "periodic" or nil, front = d3 and "periodic" or nil},
}
local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
local dx = P.shift / P.cells
local function block(lo, hi)
  if d3 then return mvmpm.rect {lo = {lo + dx, 0, 0}, hi = {hi + dx, 0.5, 0.25}} end
  return mvmpm.rect {lo = {lo + dx, 0}, hi = {hi + dx, 0.5}}
end
local function grip(sign)
  return function(t) return sign * P.V0 * math.min(1, t / P.ramp), 0, 0 end
end
-- the blocks carry a strong bond (1) to their grips; the A-B pair's law
-- caps their interface at the strength under study
sim:body {name = "gripL", shape = block(0.25, 0.5),
          material = m, driven = grip(-1)}
local a = sim:body {name = "A", shape = block(0.5, 1.5),
                    material = m, bond = 1}
local b = sim:body {name = "B", shape = block(1.5, 2.5),
                    material = m, bond = 1}
sim:body {name = "gripR", shape = block(2.5, 2.75),
          material = m, driven = grip(1)}
sim:contact(a, b, {bond = P.strength})
sim:output {dir = "out/bond_pull", every = 0.5, csv_every = 10}
return sim
