-- A 3-D PBX 9501-like bed: HMX spheres from mvmpm.pack (dim = 3) in a
-- placeholder binder, sheared like scenarios/pbx9501.lua (the 2-D bed).
-- SI units.  A cube of side `size`, periodic in y and z; the left and
-- right sides are stick walls moving tangentially, left in -y and right
-- in +y, after a sin^2 ramp; spheres within one gap of a side are driven
-- with it.  The bed is bimodal (coarse : fine = 3 : 1 by mass) at
-- `packing` of the volume in resolved spheres; PBX 9501's 95 % HMX by
-- weight (hmx_mass) is reached by adding unresolved HMX to the binder
-- ("dirty binder", its density raised, its moduli not): with HMX at
-- 1900 and binder at 1280 kg/m^3, 95 % by weight is 92.7 % by volume,
-- and random packings of resolved spheres reach about 0.5 here
-- (docs/pbx.md, 3-D beds).
--
--   mvmpm run scenarios/pbx3d.lua                          -- small, about a minute
--   mvmpm run scenarios/pbx3d.lua --set size=0.3e-3 --set ppc=2 --set strain=0.5
--
-- Writes pbx3d_history.csv (strain, shear stress, energies, residual,
-- bonded area) and pbx3d_bed_*.csv (the spheres, sizes, statistics);
-- prints the bed's statistics at load and a summary at the end.
local mvmpm = require "mvmpm"
local pack = require "mvmpm.pack"
local M = require "mvmpm.materials"

local P = mvmpm.params {
  seed = 1,
  size = 0.15e-3,      -- side of the cube, m
  packing = 0.45,      -- volume fraction of the resolved spheres
  hmx_mass = 0.95,     -- HMX mass fraction of the composite (PBX 9501: 0.95)
  coarse = 50e-6,      -- mean coarse diameter, m (log-normal, spread 0.1)
  fine = 25e-6,        -- mean fine diameter, m (spread 0.1)
  min_grain = 18e-6,   -- smallest resolved diameter, m
  cells = 3,           -- cells across min_grain
  gap = 0.25,          -- smallest gap between spheres at seeding, in cells (> 0)
  ppc = 1,             -- particles per cell per direction
  shape = "linear",    -- or "gimp", "bspline2" (docs/pbx.md was measured on linear hats)
  binder = true,
  bond = 5e6,          -- grain-binder bond strength, Pa (0: none)
  friction = 0.3,
  rate = 1e6,          -- nominal shear rate (v_right - v_left) / size, 1/s
  strain = 0.2,        -- nominal shear strain to reach
  ramp = 0.02,         -- strain over which the walls reach speed
  record = 5,          -- steps between rows of pbx3d_history.csv
  snapshots = 2,       -- snapshots over the run
}
local function check(ok, what)
  if not ok then error("pbx3d: " .. what, 3) end
end
check(P.cells >= 1, "cells must be >= 1 (got " .. P.cells .. ")")
check(P.gap > 0, "gap must be > 0 cells (got " .. P.gap .. ")")
check(P.rate > 0, "rate must be > 0 (got " .. P.rate .. ")")
local binder_on = P.binder == true or P.binder == "true"

local W = P.size
local n = math.ceil(W / (P.min_grain / P.cells) - 1e-9)
local h = W / n
local bed = pack.bed {
  dim = 3, width = W, height = W, depth = W, packing = P.packing, seed = P.seed,
  coarse = {mean = P.coarse, spread = 0.1}, fine = {mean = P.fine, spread = 0.1},
  mass_ratio = 3, min_diameter = P.min_grain, gap = P.gap * h,
  hmx_mass = binder_on and P.hmx_mass or nil,
  density = M.HMX.density, binder_density = M.BINDER_PLACEHOLDER.density,
}
local st = bed.stats
print(pack.summary(bed))

local V0 = P.rate * W / 2
local Tr = P.ramp / P.rate
local function speed(t)
  if t < Tr then return V0 * math.sin(0.5 * math.pi * t / Tr) ^ 2 end
  return V0
end
local function strain_at(t)
  local x
  if t < Tr then x = V0 * (0.5 * t - Tr / (2 * math.pi) * math.sin(math.pi * t / Tr))
  else x = V0 * (t - 0.5 * Tr) end
  return 2 * x / W
end
local t_end = P.strain / P.rate + 0.5 * Tr

local sim = mvmpm.sim {
  dim = 3, domain = {x = {0, W}, y = {0, W}, z = {0, W}}, cell = h, ppc = P.ppc, shape = P.shape,
  t_end = t_end, units = "SI",
  sides = {
    left = {"wall", friction = "stick", velocity = function(t) return 0, -speed(t), 0 end},
    right = {"wall", friction = "stick", velocity = function(t) return 0, speed(t), 0 end},
    bottom = "periodic", top = "periodic", back = "periodic", front = "periodic",
  },
  contact = {friction = P.friction, bond = false},
}

local hmx = M.hmx {name = "HMX"}
local bond = binder_on and P.bond > 0 and P.bond or nil
local grains, left, right = {}, {}, {}
for i, g in ipairs(bed.grains) do
  local spec = {name = string.format("%s%d", g.class == "coarse" and "c" or "f", i),
                shape = mvmpm.ball {center = {g.x, g.y, g.z}, radius = g.r},
                material = hmx, bond = bond}
  if g.side == "left" then spec.driven = function(t) return 0, -speed(t), 0 end
  elseif g.side == "right" then spec.driven = function(t) return 0, speed(t), 0 end end
  local b = sim:body(spec)
  grains[#grains + 1] = b
  if g.side == "left" then left[#left + 1] = b
  elseif g.side == "right" then right[#right + 1] = b end
end
local binder
if binder_on then
  binder = sim:body {name = "binder", shape = mvmpm.rest(), bond = bond,
                     material = M.binder_placeholder {name = "binder",
                                                      density = st.dirty_binder_density}}
  if bond then
    for _, g in ipairs(grains) do sim:contact(g, binder, {friction = P.friction, bond = true}) end
  end
end

print(string.format(
  "pbx3d: %d^3 cells of %.3g m, %d particles, %d bodies; walls at %.4g m/s (rate %.3g/s), "
  .. "t_end %.4g s (strain %.3g), dt %.3g s",
  n, h, sim.n, sim.nbody, V0, P.rate, t_end, strain_at(t_end), sim:stable_dt()))

local function side_force(name, list)
  local _, fy = sim:wall_force(name)
  for _, b in ipairs(list) do
    local _, gy = b:force()
    fy = fy + gy
  end
  return fy
end

local mon = {max_residual = 0, jmin = math.huge, max_depth = 0, bad = 0, rows = 0}
local hist, acc, nacc, area0, done = nil, 0, 0, nil, false
sim:every {steps = 1, fn = function(s)
  if not hist and s.outdir ~= "" then
    pack.write_csv(bed, s.outdir .. "/pbx3d_bed")
    hist = assert(mvmpm.open(s.outdir .. "/pbx3d_history.csv"))
    hist:write("step,t,strain,tau,kinetic,strain_energy,plastic,viscous,friction,"
               .. "boundary_work,residual,bonded_area,jmin,overlap\n")
  end
  local e = s:energy()
  if not area0 and e.bonded_area > 0 then area0 = e.bonded_area end
  local fl, fr = side_force("left", left), side_force("right", right)
  -- shear stress: (F_right - F_left) / 2 over the wall's area
  acc, nacc = acc + (fr - fl) / (2 * W * W), nacc + 1
  local last = s.t >= t_end * (1 - 1e-9)
  if s.steps % P.record == 0 or last then
    local n_ov, depth = s:overlap()
    if e.total ~= e.total or not (e.jmin > 0) or n_ov > 0 then mon.bad = mon.bad + 1 end
    mon.jmin, mon.max_depth = math.min(mon.jmin, e.jmin), math.max(mon.max_depth, depth)
    if s.t > 2 * Tr and e.boundary_work > 0 then
      mon.max_residual = math.max(mon.max_residual, math.abs(e.residual) / e.boundary_work)
    end
    mon.rows = mon.rows + 1
    mon.tau = acc / nacc
    if hist then
      hist:write(string.format("%d,%.9g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d\n",
        s.steps, s.t, strain_at(s.t), acc / nacc, e.kinetic, e.strain, e.plastic, e.viscous,
        e.dissipated, e.boundary_work, e.residual, e.bonded_area, e.jmin, n_ov))
      hist:flush()
    end
    acc, nacc = 0, 0
  end
  if last and not done then
    done = true
    if hist then assert(hist:close()); hist = nil end
    local e2 = s:energy()
    print(string.format("strain reached              %.4g", strain_at(s.t)))
    print(string.format("shear stress at the end     %.4g Pa", mon.tau or 0))
    print(string.format("boundary work               %.4g J", e2.boundary_work))
    print(string.format("max |residual| / work       %.4g (after twice the ramp)", mon.max_residual))
    print(string.format("debonded fraction           %.4g", area0 and 1 - e2.bonded_area / area0 or 0))
    print(string.format("least det F                 %.4g", mon.jmin))
    print(string.format("deepest burial (cells)      %d", mon.max_depth))
    print(string.format("invariant failures          %d", mon.bad))
  end
end}
sim:output {dir = "out/pbx3d", every = t_end / P.snapshots, csv_every = P.record}

PBX3D = {bed = bed, grains = grains, binder = binder, left = left, right = right,
         strain_at = strain_at, monitor = mon, cell = h}
return sim
