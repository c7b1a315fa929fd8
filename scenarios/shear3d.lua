-- A 3-D granular shear cell: the 2-D cell of shear_dry.lua and
-- shear_binder.lua (docs/shear.md) made a box of spheres.  A cube of
-- side L = 4 in the same nondimensional units (K = 1, G = 0.5, density
-- 1), periodic in y and z; the left and right sides (x) are stick walls
-- moving tangentially, the left in -y and the right in +y, each at
-- rate * L / 2 after a smoothstep start.  The spheres come from the
-- seeded bimodal bed of mvmpm.pack (dim = 3): coarse and fine classes,
-- `packing` of the volume; a sphere within one gap of a side is driven
-- with it (rigid), as the 2-D cell's attached cylinders.  Grains are
-- elastic-plastic (mvmpm.plastic, yield G/10 as in 2-D), Coulomb friction
-- `friction` between all bodies; with binder = true the rest of the box
-- is the 2-D cell's viscoelastic binder (mvmpm.rest()).
--
--   mvmpm run scenarios/shear3d.lua                        -- dry, about 10 s
--   mvmpm run scenarios/shear3d.lua --set binder=true      -- about 45 s
--   mvmpm run scenarios/shear3d.lua --set cells=24 --set strain=1
--
-- Writes shear3d.csv (per `record` steps: strain, the shear stress
-- tau = (F_right - F_left) / 2 over the wall area L^2, with the walls'
-- and the attached spheres' forces, the energies, the residual, the
-- y momentum of the free material against the impulse of the sides)
-- and shear3d_bed.csv (the spheres), prints a summary at the end.
-- Pictures: mvmpm render on the snapshots (docs/shear.md, 3-D cell).
local mvmpm = require "mvmpm"
local pack = require "mvmpm.pack"

local P = mvmpm.params {
  cells = 16,          -- cells across the side L = 4
  ppc = 2,             -- particles per cell per direction
  seed = 1,            -- the bed's seed
  packing = 0.35,      -- volume fraction of the spheres
  coarse = 1.2,        -- mean coarse diameter (log-normal, spread 0.1)
  fine = 0.6,          -- mean fine diameter (spread 0.1)
  min_grain = 0.45,    -- drawn spheres below this are not placed
  mass_ratio = 3,      -- coarse : fine by volume
  gap = 0.25,          -- smallest surface gap at seeding, in cells (> 0)
  binder = false,      -- true: viscoelastic binder in the rest of the box
  bond = 0.0,          -- grain-binder bond strength (0: none)
  rate = 0.025,        -- shear rate (v_right - v_left) / L
  strain = 0.5,        -- shear strain to reach
  t_ramp = 4.0,        -- smoothstep start of the walls
  friction = 0.3,      -- Coulomb friction between bodies
  yield = 0.05,        -- grains' von Mises yield stress (G/10)
  binder_K = 0.25, binder_G = 0.005,   -- the 2-D cell's binder
  binder_G1 = 0.02, binder_tau1 = 1.0, binder_G2 = 0.02, binder_tau2 = 10.0,
  shape = "linear",    -- or "gimp", "bspline2"
  update = "musl",     -- or "usl", "usavg"
  record = 5,          -- steps between rows of shear3d.csv
  snapshots = 4,       -- snapshots over the run
}
local function check(ok, what)
  if not ok then error("shear3d: " .. what, 3) end
end
check(P.cells >= 4, "cells must be >= 4 (got " .. P.cells .. ")")
check(P.gap > 0, "gap must be > 0 cells (got " .. P.gap .. ")")
check(P.rate > 0, "rate must be > 0 (got " .. P.rate .. ")")
check(P.strain > 0, "strain must be > 0 (got " .. P.strain .. ")")
local binder_on = P.binder == true or P.binder == "true"

local L = 4
local h = L / P.cells
local bed = pack.bed {
  dim = 3, width = L, height = L, depth = L, packing = P.packing, seed = P.seed,
  coarse = {mean = P.coarse, spread = 0.1}, fine = {mean = P.fine, spread = 0.1},
  mass_ratio = P.mass_ratio, min_diameter = P.min_grain, gap = P.gap * h,
  density = 1, binder_density = 1,
}
print(pack.summary(bed))

-- the sides: v(t) = V s(t / t_ramp), s(u) = u^2 (3 - 2u); strain is the
-- integral of v_right - v_left over L
local V = P.rate * L / 2
local function speed(t)
  if t >= P.t_ramp then return V end
  local u = t / P.t_ramp
  return V * u * u * (3 - 2 * u)
end
local function strain_at(t)
  local d
  if t >= P.t_ramp then d = t - P.t_ramp / 2
  else local u = t / P.t_ramp; d = P.t_ramp * (u ^ 3 - u ^ 4 / 2) end
  return P.rate * d
end
local t_end = P.strain / P.rate + P.t_ramp / 2
if P.strain < strain_at(P.t_ramp) then   -- within the ramp: bisection
  local lo, hi = 0, P.t_ramp
  for _ = 1, 60 do
    local mid = (lo + hi) / 2
    if strain_at(mid) < P.strain then lo = mid else hi = mid end
  end
  t_end = hi
end

local sim = mvmpm.sim {
  dim = 3, domain = {x = {0, L}, y = {0, L}, z = {0, L}}, cell = h, ppc = P.ppc,
  t_end = t_end, shape = P.shape, update = P.update,
  sides = {
    left = {"wall", friction = "stick", velocity = function(t) return 0, -speed(t), 0 end},
    right = {"wall", friction = "stick", velocity = function(t) return 0, speed(t), 0 end},
    bottom = "periodic", top = "periodic", back = "periodic", front = "periodic",
  },
  contact = {friction = P.friction, bond = false},
}

local grain = mvmpm.plastic {K = 1, G = 0.5, density = 1, yield = P.yield, name = "grain"}
local bond = binder_on and P.bond > 0 and P.bond or nil
local free, attached = {}, {left = {}, right = {}}
for i, g in ipairs(bed.grains) do
  local spec = {name = string.format("%s%d", g.class == "coarse" and "c" or "f", i),
                shape = mvmpm.ball {center = {g.x, g.y, g.z}, radius = g.r},
                material = grain, bond = bond}
  if g.side == "left" then spec.driven = function(t) return 0, -speed(t), 0 end
  elseif g.side == "right" then spec.driven = function(t) return 0, speed(t), 0 end end
  local b = sim:body(spec)
  if g.side then table.insert(attached[g.side], b) else free[#free + 1] = b end
end
local binder
if binder_on then
  local mat = mvmpm.viscoelastic {
    K = P.binder_K, G_inf = P.binder_G, density = 1, name = "binder",
    prony = {{G = P.binder_G1, tau = P.binder_tau1}, {G = P.binder_G2, tau = P.binder_tau2}}}
  binder = sim:body {name = "binder", shape = mvmpm.rest(), material = mat, bond = bond}
  free[#free + 1] = binder
  if bond then
    for _, g in ipairs(sim:bodies()) do
      if g ~= binder then sim:contact(g, binder, {friction = P.friction, bond = true}) end
    end
  end
end

print(string.format(
  "shear3d: %d^3 cells of %.4g, %d particles, %d bodies (%d attached left, %d right)%s; "
  .. "walls at +-%.4g, t_end %.4g (strain %.3g), dt %.3g",
  P.cells, h, sim.n, sim.nbody, #attached.left, #attached.right,
  binder_on and ", binder" or ", dry", V, t_end, P.strain, sim:stable_dt()))

-- the force a side puts on the free material: its wall and its attached
-- spheres (x, y, z)
local function side_force(name)
  local fx, fy, fz = sim:wall_force(name)
  for _, b in ipairs(attached[name]) do
    local bx, by, bz = b:force()
    fx, fy, fz = fx + bx, fy + by, fz + bz
  end
  return fx, fy, fz
end
-- momentum of the free material (every body not driven)
local function free_momentum()
  local px, py, pz = 0, 0, 0
  for _, b in ipairs(free) do
    local d = b:diag()
    px, py, pz = px + d.mass * d.vx, py + d.mass * d.vy, pz + d.mass * d.vz
  end
  return px, py, pz
end
local free_mass = 0
for _, b in ipairs(free) do free_mass = free_mass + b:mass() end

-- the monitor: per step the sides' impulse; per record a row
local mon = {rows = {}, imp = {0, 0, 0}, max_py_error = 0, max_residual = 0,
             bad = {}, max_depth = 0, jmin = math.huge}
local acc, nacc = 0, 0
local out, reported = nil, false
local function finite(x) return x == x and x ~= math.huge and x ~= -math.huge end

local function sample(s)
  local e = s:energy()
  local g = strain_at(s.t)
  local fl = select(2, side_force("left"))
  local fr = select(2, side_force("right"))
  local _, py = free_momentum()
  -- y momentum of the free material against the impulse the sides gave
  -- it, on the scale of the free mass moving at the walls' speed
  local py_err = math.abs(py - mon.imp[2]) / (free_mass * V)
  local n_ov, depth = s:overlap()
  local row = {step = s.steps, t = s.t, strain = g, tau = nacc > 0 and acc / nacc or 0,
               fy_left = fl, fy_right = fr, kinetic = e.kinetic, strain_energy = e.strain,
               plastic = e.plastic, viscous = e.viscous, friction = e.dissipated,
               boundary_work = e.boundary_work, residual = e.residual, py = py,
               py_impulse = mon.imp[2], py_error = py_err, jmin = e.jmin, overlap = n_ov}
  mon.rows[#mon.rows + 1] = row
  acc, nacc = 0, 0
  for _, k in ipairs {"kinetic", "strain_energy", "plastic", "viscous", "friction",
                      "boundary_work", "residual"} do
    if not finite(row[k]) then mon.bad[#mon.bad + 1] = string.format("%s not finite at step %d", k, s.steps) end
  end
  if not (e.jmin > 0) then mon.bad[#mon.bad + 1] = string.format("det F <= 0 at step %d", s.steps) end
  if n_ov > 0 then mon.bad[#mon.bad + 1] = string.format("%d particles buried %d cells at step %d", n_ov, depth, s.steps) end
  mon.max_depth = math.max(mon.max_depth, depth)
  mon.jmin = math.min(mon.jmin, e.jmin)
  mon.max_py_error = math.max(mon.max_py_error, py_err)
  if s.t > P.t_ramp and e.boundary_work > 0 then
    mon.max_residual = math.max(mon.max_residual, math.abs(e.residual) / e.boundary_work)
  end
  if out then
    if not out.header then
      out.header = {"step", "t", "strain", "tau", "fy_left", "fy_right", "kinetic",
                    "strain_energy", "plastic", "viscous", "friction", "boundary_work",
                    "residual", "py", "py_impulse", "py_error", "jmin", "overlap"}
      out.f:write(table.concat(out.header, ","), "\n")
    end
    local v = {}
    for j, k in ipairs(out.header) do v[j] = string.format("%.9g", row[k]) end
    out.f:write(table.concat(v, ","), "\n")
    out.f:flush()
  end
end

local function summary()
  local mean, n = 0, 0
  for _, r in ipairs(mon.rows) do
    if r.t > P.t_ramp then mean, n = mean + r.tau, n + 1 end
  end
  local e = sim:energy()
  local lines = {
    string.format("strain reached                 %.4g", strain_at(sim.t)),
    string.format("mean shear stress past ramp    %.4g", n > 0 and mean / n or 0),
    string.format("boundary work                  %.4g", e.boundary_work),
    string.format("friction / plastic / viscous   %.4g / %.4g / %.4g", e.dissipated, e.plastic, e.viscous),
    string.format("max |residual| / work past ramp %.4g", mon.max_residual),
    string.format("max |py - impulse| / (M V)     %.4g", mon.max_py_error),
    string.format("least det F                    %.4g", mon.jmin),
    string.format("deepest burial (cells)         %d", mon.max_depth),
    string.format("invariant failures             %d", #mon.bad),
  }
  for k = 1, math.min(5, #mon.bad) do lines[#lines + 1] = "invariant: " .. mon.bad[k] end
  return table.concat(lines, "\n")
end

sim:every {steps = 1, fn = function(s)
  if not out and s.outdir ~= "" then
    out = {f = assert(mvmpm.open(s.outdir .. "/shear3d.csv"))}
    pack.write_csv(bed, s.outdir .. "/shear3d_bed")
  end
  -- the sides' force on the free material over the step just taken
  local lx, ly, lz = side_force("left")
  local rx, ry, rz = side_force("right")
  mon.imp[1] = mon.imp[1] + (lx + rx) * s.dt
  mon.imp[2] = mon.imp[2] + (ly + ry) * s.dt
  mon.imp[3] = mon.imp[3] + (lz + rz) * s.dt
  acc, nacc = acc + (ry - ly) / (2 * L * L), nacc + 1
  local last = s.t >= t_end * (1 - 1e-9)
  if s.steps % P.record == 0 or last then sample(s) end
  if last and not reported then
    reported = true
    if out then assert(out.f:close()); out.f = nil end
    print(summary())
  end
end}
sim:output {dir = "out/shear3d", every = t_end / P.snapshots, csv_every = P.record}

SHEAR3D = {bed = bed, free = free, attached = attached, binder = binder, monitor = mon,
           strain_at = strain_at, side_force = side_force, free_momentum = free_momentum,
           summary = summary, V = V, L = L, cell = h}
return sim
