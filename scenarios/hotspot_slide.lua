-- A frictional hot spot: an HMX block sliding on an HMX slab, heated at
-- its contact by Coulomb friction, in SI units.
--
--   mvmpm run scenarios/hotspot_slide.lua [--set speed=200] [--out out/hotspot_slide]
--   mvmpm render out/hotspot_slide/particles_000010.h5 --by temperature
--
-- Geometry (m): a slab 2 mm long and 0.5 mm thick on a frictionless
-- floor, periodic left and right, and on it a block 0.5 mm by 0.25 mm
-- thrown along it at `speed`.  A body force `g` (downward, m/s^2) stands
-- for a clamping pressure: it presses the block on the slab with
-- rho g h = 1840 * 1e7 * 0.25e-3 = 4.6 MPa.  The contact is Coulomb
-- friction `friction`; heat on with the friction heat split equally
-- between the two sides, so the block's sole heats at a steady rate
-- (friction_split * mu p v = 230 MW/m^2 at 200 m/s) while the slab is
-- heated along the track it passes over.  Conduction (diffusion length
-- sqrt(k t / rho c) = 2 um in 20 us) stays below the cell (25 um at
-- cells = 10): what the run shows is the frictional heat source, held
-- in the first cell at the contact.
--
-- Materials: elastic HMX (E 15 GPa, nu 0.3: mvmpm.materials' HMX moduli;
-- it stays elastic at these pressures), density, cv and k of PBX 9501's
-- reactant in mvmpm.kinetics (1840 kg/m^3, 996 J/(kg K), 0.452 W/(m K),
-- sources in docs/hotspots.md).  Starting temperature T0 = 300 K.
-- The reaction is off by default (`--set react=true` gives the block and
-- slab HMX's published kinetics, K.hmx: nothing reacts below about
-- 500 K on these time scales).
--
-- Contact normals: the block's sole and the slab's face are flat, and
-- node by node the mass-gradient normals turn at the block's corners, so
-- the block rocks and its corners strike the slab (measured at 10 cells,
-- 10 us: the block's spin swings through +-6e4 rad/s, the impacts take
-- 0.14 J/m, and the leading corner reaches 1310 K); with one normal per
-- contact patch (the engine's default between flat faces, normals =
-- "auto", and normal_patch here) the spin stays within 3e4 rad/s, the
-- impacts take 1.4e-3 J/m, and the friction work is mu m g times the
-- distance slid to 1-3 %.
--
-- Snapshots carry temperature, heat (J deposited per particle) and
-- heat_friction; hotspots_NNNNNN.csv lists the regions above
-- `threshold` (K) beside each snapshot; hotspots_critical.png, at the
-- end, draws them over HMX's critical curve (mvmpm.hotspot).
local mvmpm = require "mvmpm"
local K = require "mvmpm.kinetics"

local P = mvmpm.params {
  cells = 10,          -- cells across the block's thickness (0.25 mm)
  ppc = 2,             -- particles per cell per direction
  speed = 200,         -- block's initial speed, m/s
  g = 1e7,             -- body force per unit mass pressing down, m/s^2
  friction = 0.5,      -- Coulomb friction block-slab
  split = 0.5,         -- share of the friction heat the slab (the first body) takes
  T0 = 300,            -- initial temperature, K
  threshold = 350,     -- hot-spot threshold, K
  t_end = 10e-6,       -- s
  snapshots = 10,      -- snapshots over the run
  react = false,       -- true: HMX's kinetics (K.hmx) on both bodies
  shape = "gimp",      -- or "linear", "bspline2"
  update = "usavg",    -- or "musl", "usl"
  normal_patch = true, -- one contact normal per contact patch (false: node by node)
}
local function check(ok, what)
  if not ok then error("hotspot_slide: " .. what, 3) end
end
check(P.cells >= 2, "cells must be >= 2 (got " .. P.cells .. ")")
check(P.speed >= 0, "speed must be >= 0 (got " .. P.speed .. ")")
check(P.friction >= 0, "friction must be >= 0 (got " .. P.friction .. ")")
check(P.split >= 0 and P.split <= 1, "split must be in 0 ... 1 (got " .. P.split .. ")")

local R = K.pbx9501
local sim = mvmpm.sim {
  domain = {x = {0, 2e-3}, y = {0, 1e-3}}, cell = 0.25e-3 / P.cells, ppc = P.ppc,
  t_end = P.t_end, units = "SI", gravity = {0, -P.g}, shape = P.shape, update = P.update,
  contact = {friction = P.friction}, normal_patch = P.normal_patch,
  sides = {left = "periodic", right = "periodic", bottom = "wall", top = "wall"},
}
sim:heat {friction_split = P.split}
local hmx = mvmpm.elastic {E = 15e9, nu = 0.3, density = R.density, cv = R.cv, k = R.k,
                           reaction = P.react and K.hmx or nil, name = "HMX"}
sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {2e-3, 0.5e-3}},
          material = hmx, temperature = P.T0}
sim:body {name = "block", shape = mvmpm.rect {lo = {0.25e-3, 0.5e-3}, hi = {0.75e-3, 0.75e-3}},
          material = hmx, velocity = {P.speed, 0}, temperature = P.T0}
sim:output {dir = "out/hotspot_slide", every = P.t_end / P.snapshots,
            hotspots = {threshold = P.threshold}}
-- at the end: the hot spots at their equivalent radius and peak
-- temperature over HMX's Frank-Kamenetskii critical curve
sim:at_end(function(s)
  if s.outdir == "" then return end
  local H = require "mvmpm.hotspot"
  H.plot {file = s.outdir .. "/hotspots_critical.png", spots = s:hotspots {threshold = P.threshold},
          kinetics = K.hmx, density = R.density, conductivity = R.k, rmin = 1e-7, rmax = 1e-3,
          title = string.format("hot spots above %g K at %g s over HMX's critical curve",
                                P.threshold, s.t)}
end)
return sim
