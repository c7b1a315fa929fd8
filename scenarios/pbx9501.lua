-- A PBX 9501-like grain bed under shear (the report's Figure 9 geometry,
-- sheared like its small cell, Figures 6-8).  A 1.2 mm square in SI
-- units, periodic top and bottom; HMX grains as discs from a seeded
-- bimodal bed (mvmpm.pack: coarse mean 150 um, fines 30 um, coarse :
-- fine = 3 : 1 by mass, 75 % by area = 82 % by mass, as the report's
-- "approximately 80 % by weight"); fines under `min_grain` folded into
-- a dirty binder that fills the rest.  The left and right sides are
-- stick walls moving tangentially, left down and right up, after a
-- smooth sin^2 ramp; grains within one gap of a side are driven with
-- it (rigid), like the report's cylinders "fixed to these boundaries".
--
--   mvmpm run scenarios/pbx9501.lua                      -- with binder
--   mvmpm run scenarios/pbx9501.lua --set binder=false    -- dry grains
--   mvmpm run scenarios/pbx9501.lua --set size=0.6e-3 --set min_grain=30e-6
--
-- Materials (lua/mvmpm/materials.lua, sources there): grains are J2
-- elastic-plastic HMX (E 15 GPa, nu 0.3, yield 0.26 GPa, 1900 kg/m^3).
-- The binder is the PLACEHOLDER set (rubbery Maxwell solid, glassy
-- shear modulus 26 MPa, K 2.5 GPa) with the dirty binder's density; it
-- is chosen over the PBX 9501 composite set because that set describes
-- the whole composite (glassy shear modulus 2.6 GPa, a hundred times a
-- rubbery binder's), which as the phase between explicit grains would
-- make the binder nearly as stiff as the crystals.  Neither is binder
-- data; binder_set = "composite" runs the other for comparison.
-- Moduli are not raised for the folded fines.
--
-- Time scale: the step follows the HMX wave speed (about 3.3 km/s), so
-- with a 2 um cell dt is about 0.15 ns.  The default shear rate, 1e5/s,
-- moves the walls at 60 m/s (2 % of the wave speed); 100 % strain then
-- takes 10 us, about 65,000 steps.  See docs/pbx.md for what that costs.
local mvmpm = require "mvmpm"
local pack = require "mvmpm.pack"
local M = require "mvmpm.materials"
local shear = require "mvmpm.shear"

local P = mvmpm.params {
  seed = 1,            -- the bed's seed
  packing = 0.75,      -- area fraction of the resolved grains
  size = 1.2e-3,       -- side of the square, m
  scale = 1.0,         -- multiplies every grain diameter (smaller: more grains)
  coarse = 150e-6,     -- mean coarse diameter, m (times scale)
  fine = 30e-6,        -- mean fine diameter, m (times scale)
  min_grain = 16e-6,   -- smallest resolved diameter, m (times scale); smaller fines are folded
  cells = 8,           -- cells across the smallest resolved grain
  gap = 1,             -- smallest gap between grains at seeding, in cells (>= 1)
  ppc = 2,             -- particles per cell per direction
  binder = true,       -- false: dry grains only
  binder_set = "placeholder", -- or "composite"
  bond = 5e6,          -- grain-binder bond strength, Pa (0: no bonds)
  bond_energy = 0,     -- grain-binder fracture energy, J/m^2 (0: brittle; the
                       -- cohesive law, at most bond x cell / 4)
  friction = 0.3,      -- Coulomb friction between grains, and grain-binder once debonded
  rate = 1e5,          -- nominal shear strain rate (v_right - v_left) / width, 1/s
  strain = 1.0,        -- nominal shear strain to reach
  ramp = 0.02,         -- strain over which the walls reach speed
  t_end = 0,           -- > 0: stop here instead of at `strain`
  record = 20,         -- steps between rows of pbx_history.csv
  images = 0.1,        -- strain between pictures (0: none)
  shape = "linear",    -- or "gimp", "bspline2"
  update = "musl",     -- or "usl", "usavg"
  normals = "mass",    -- contact normals: "volume", "maxvolume", "plane"
  normal_window = 0,   -- ... from the shared nodes within this many cells
  normal_patch = false, -- true: one normal per contact patch (flat faces)
  contact_gap = "touch", -- or "step": contact judged at the step's end
  bond_release = "open", -- or "contact": how a released bond meets again
  body_contact = "node", -- or "patch": bodies meet per contact patch
  -- heat (off by default: the scene is then the same, bit for bit).  SI.
  -- HMX: cv and k of PBX 9501's reactant in mvmpm.kinetics (996 J/(kg K),
  -- 0.452 W/(m K), from the Uintah input cited there); beta 0.9, the
  -- Taylor-Quinney value commonly taken.  Binder: 1500 J/(kg K) and
  -- 0.15 W/(m K), round values typical of polyurethane elastomers such as
  -- Estane (not measured data for PBX 9501's binder; docs/hotspots.md).
  heat = false,
  T0 = 300,            -- initial temperature, K
  hmx_cv = 996, hmx_k = 0.452, hmx_beta = 0.9,
  binder_cv = 1500, binder_k = 0.15, binder_beta = 0.9,
  friction_split = 0.5, -- heat's friction_split
  hotspot_threshold = 400, -- K: hot spots in the snapshots' CSVs and the reports
}

local function check(ok, what)
  if not ok then error("pbx9501: " .. what, 3) end
end
check(P.cells >= 1, "cells must be >= 1 (got " .. P.cells .. ")")
check(P.gap >= 1, "gap must be at least one cell so that grains never share a cell (got "
      .. P.gap .. ")")
check(P.rate > 0, "rate must be > 0 (got " .. P.rate .. ")")
check(P.binder_set == "placeholder" or P.binder_set == "composite",
      "binder_set must be \"placeholder\" or \"composite\" (got " .. P.binder_set .. ")")

-- the cell: `cells` across the smallest resolved grain, rounded down to
-- a whole number of cells across the square
local W = P.size
local dmin = P.min_grain * P.scale
local n = math.ceil(W / (dmin / P.cells) - 1e-9)
local h = W / n

local bed = pack.bed {
  width = W, height = W, packing = P.packing, seed = P.seed,
  coarse = {mean = P.coarse * P.scale, spread = 0.25},
  fine = {mean = P.fine * P.scale, spread = 0.35},
  mass_ratio = 3, min_diameter = dmin, gap = P.gap * h,
  density = M.HMX.density, binder_density = M.BINDER_PLACEHOLDER.density,
}
local st = bed.stats
print(pack.summary(bed))

-- walls: V0 = rate W / 2 each, reached after the ramp with sin^2
local V0 = P.rate * W / 2
local Tr = P.ramp / P.rate
local function speed(t)
  if t < Tr then return V0 * math.sin(0.5 * math.pi * t / Tr) ^ 2 end
  return V0
end
-- nominal strain at t: 2 * integral of speed / W
local function strain_at(t)
  local x
  if t < Tr then x = V0 * (0.5 * t - Tr / (2 * math.pi) * math.sin(math.pi * t / Tr))
  else x = V0 * (t - 0.5 * Tr) end
  return 2 * x / W
end
local t_end = P.t_end > 0 and P.t_end or P.strain / P.rate + 0.5 * Tr

local sim = mvmpm.sim {
  domain = {x = {0, W}, y = {0, W}}, cell = h, ppc = P.ppc,
  t_end = t_end, units = "SI",
  sides = {
    bottom = "periodic", top = "periodic",
    left = {"wall", friction = "stick", velocity = function(t) return 0, -speed(t) end},
    right = {"wall", friction = "stick", velocity = function(t) return 0, speed(t) end},
  },
  contact = {friction = P.friction, bond = false},
  shape = P.shape, update = P.update, normals = P.normals, normal_window = P.normal_window,
  normal_patch = P.normal_patch,
  contact_gap = P.contact_gap, bond_release = P.bond_release, body_contact = P.body_contact,
  bond_energy = P.bond_energy,
}

local hot = P.heat == true or P.heat == "true"
if hot then
  sim:heat {friction_split = P.friction_split}
  sim:temperature(P.T0)
end
local hmx = M.hmx {name = "HMX", cv = hot and P.hmx_cv or nil, k = hot and P.hmx_k or nil,
                   beta = hot and P.hmx_beta or nil}
local grains, left, right = {}, {}, {}
local bond = P.binder and P.bond > 0 and P.bond or nil
for i, g in ipairs(bed.grains) do
  local spec = {name = string.format("%s%d", g.class == "coarse" and "c" or "f", i),
                shape = mvmpm.disk {center = {g.x, g.y}, radius = g.r},
                material = hmx, bond = bond}
  if g.side == "left" then spec.driven = function(t) return 0, -speed(t) end
  elseif g.side == "right" then spec.driven = function(t) return 0, speed(t) end end
  local b = sim:body(spec)
  grains[#grains + 1] = b
  if g.side == "left" then left[#left + 1] = b
  elseif g.side == "right" then right[#right + 1] = b end
end

local binder
if P.binder then
  local over = {name = "binder", density = st.dirty_binder_density}
  if hot then over.cv, over.k, over.beta = P.binder_cv, P.binder_k, P.binder_beta end
  local mat = P.binder_set == "composite" and M.pbx9501_composite(over)
              or M.binder_placeholder(over)
  binder = sim:body {name = "binder", shape = mvmpm.rest(), material = mat, bond = bond}
  -- grains bond to the binder up to `bond`, never to each other
  if bond then
    for _, g in ipairs(grains) do sim:contact(g, binder, {friction = P.friction, bond = true}) end
  end
end

print(string.format(
  "pbx9501: %d x %d cells of %.3g m (%d across the smallest grain), %d particles, %d bodies; "
  .. "walls at %.4g m/s (rate %.3g/s), t_end %.4g s (strain %.3g), dt %.3g s",
  n, n, h, P.cells, sim.n, sim.nbody, V0, P.rate, t_end, strain_at(t_end), sim:stable_dt()))

-- the record: nominal strain, the shear stress the sides carry (wall
-- plus attached grains, per unit thickness over the height), energies,
-- the bonded area left
local function side_force(name, list)
  local _, fy = sim:wall_force(name)
  for _, b in ipairs(list) do
    local _, gy = b:force()
    fy = fy + gy
  end
  return fy
end

-- what the run keeps for its reports: one sample per record, the
-- shear stress averaged over the steps since the last
local hist, area0, written = nil, nil, false
local next_image = 0
local mon = {strain = {}, tau = {}, debond = {}, work = {}, kinetic = {}, stored = {},
             friction = {}, plastic = {}, viscous = {}, residual = {}, bad = {},
             max_depth = 0, jmin = math.huge, max_residual = 0, hot = {}}
local acc, nacc, reported = 0, 0, false

-- at each record: the invariants (no NaN, det F > 0, no particle
-- buried a cell deep in another body: sim:overlap, src/core/diag_overlap.c)
local function sample(s, e, g, tau)
  local n_ov, depth, ob, oh = s:overlap()
  if e.total ~= e.total or tau ~= tau then mon.bad[#mon.bad + 1] = string.format("NaN at strain %.4f", g) end
  if not (e.jmin > 0) then mon.bad[#mon.bad + 1] = string.format("J <= 0 at strain %.4f", g) end
  if n_ov > 0 then
    local bodies = s:bodies()
    mon.bad[#mon.bad + 1] = string.format("%d particles buried %d cells at strain %.4f (deepest: %s in %s)",
      n_ov, depth, g, ob and bodies[ob].name or "?", oh and bodies[oh].name or "?")
  end
  mon.max_depth = math.max(mon.max_depth, depth)
  mon.jmin = math.min(mon.jmin, e.jmin)
  local k = #mon.strain + 1
  mon.strain[k], mon.tau[k] = g, tau
  mon.debond[k] = area0 and 1 - e.bonded_area / area0 or 0
  mon.work[k], mon.kinetic[k], mon.stored[k] = e.boundary_work, e.kinetic, e.strain
  mon.friction[k], mon.plastic[k], mon.viscous[k], mon.residual[k] =
    e.dissipated, e.plastic, e.viscous, e.residual
  if g > 2 * P.ramp and e.boundary_work > 0 then
    mon.max_residual = math.max(mon.max_residual, math.abs(e.residual) / e.boundary_work)
  end
end

-- with heat, at the end: hot spots against strain, the last state's hot
-- spots over HMX's critical curve, where the heat is (sources; grains
-- or binder; friction's share in the hot particles) -> summary lines
local function heat_report(dir)
  local H = require "mvmpm.hotspot"
  local K = require "mvmpm.kinetics"
  local gs, cs, as = {}, {}, {}
  local f = assert(mvmpm.open(dir .. "/pbx_hotspots.csv"))
  f:write("strain,hotspots,area_fraction,heat_friction,heat_plastic,heat_viscous,"
          .. "residual_with_heat,boundary_work\n")
  for k, h in ipairs(mon.hot) do
    gs[k], cs[k], as[k] = h.strain, h.count, h.area_fraction
    f:write(string.format("%.6g,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", h.strain, h.count,
      h.area_fraction, h.heat_friction, h.heat_plastic, h.heat_viscous, h.residual_with_heat,
      h.work))
  end
  assert(f:close())
  mvmpm.plot {file = dir .. "/pbx_hotspots_strain.png", xlabel = "nominal shear strain",
              ylabel = "count", title = string.format("Hot spots above %g K", P.hotspot_threshold),
              series = {{x = gs, y = cs, label = "hot spots"}}}
  mvmpm.plot {file = dir .. "/pbx_hotspot_area_strain.png", xlabel = "nominal shear strain",
              ylabel = "area fraction", title = string.format("Area above %g K", P.hotspot_threshold),
              series = {{x = gs, y = as, label = "hot area fraction"}}}
  local last = mon.hot[#mon.hot]
  H.plot {file = dir .. "/pbx_hotspots_critical.png", spots = last and last.spots or {},
          kinetics = K.hmx, density = M.HMX.density, conductivity = P.hmx_k, rmin = 1e-7, rmax = 1e-3,
          title = string.format("hot spots at strain %.2f over HMX's critical curve",
                                last and last.strain or 0)}
  local e = sim:energy()
  local T, m, q, qf, body = sim:particles("temperature"), sim:particles("mass"),
    sim:particles("heat"), sim:particles("heat_friction"), sim:particles("body")
  local bid = binder and binder.id or -1
  local eb, eg, nhot, nbind, nfric = 0, 0, 0, 0, 0
  for i = 1, #T do
    local c = body[i] == bid and P.binder_cv or P.hmx_cv
    local th = m[i] * c * (T[i] - P.T0)
    if body[i] == bid then eb = eb + th else eg = eg + th end
    if T[i] > P.hotspot_threshold then
      nhot = nhot + 1
      if body[i] == bid then nbind = nbind + 1 end
      if q[i] > 0 and qf[i] > 0.5 * q[i] then nfric = nfric + 1 end
    end
  end
  local src = e.heat_friction + e.heat_plastic + e.heat_viscous
  local tmax = 0
  for i = 1, #T do if T[i] > tmax then tmax = T[i] end end
  return {
    string.format("heat: friction / plastic / viscous  %.4g / %.4g / %.4g of %.4g J/m",
                  e.heat_friction / src, e.heat_plastic / src, e.heat_viscous / src, src),
    string.format("heat: thermal energy in binder    %.4g", eb / (eb + eg)),
    string.format("heat: peak temperature (K)        %.5g", tmax),
    string.format("heat: particles above %g K       %d (binder %.4g, mostly friction %.4g)",
                  P.hotspot_threshold, nhot, nhot > 0 and nbind / nhot or 0,
                  nhot > 0 and nfric / nhot or 0),
    string.format("heat: hot spots at the end        %d (area fraction %.4g)",
                  last and last.count or 0, last and last.area_fraction or 0),
    string.format("heat: residual_with_heat / work   %.4g", e.residual_with_heat / e.boundary_work),
    string.format("heat: heat_residual / thermal     %.4g", e.heat_residual / e.thermal_energy),
  }
end

-- at the end: the force-strain plot with locking events (the detector of
-- mvmpm.shear), the debonding and energy plots, a summary
local function report(dir)
  local events = shear.locking(mon.strain, mon.tau, 2 * P.ramp)
  local f = assert(mvmpm.open(dir .. "/pbx_locking.csv"))
  f:write("strain,peak_strain,end_strain,base,peak,mean\n")
  for _, ev in ipairs(events) do
    f:write(string.format("%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", ev.strain, ev.peak_strain,
                          ev.end_strain, ev.base, ev.peak, ev.mean))
  end
  assert(f:close())
  local ex, ey = {}, {}
  for k, ev in ipairs(events) do ex[k], ey[k] = ev.peak_strain, ev.peak end
  local series = {{x = mon.strain, y = mon.tau, label = "shear stress (F_right - F_left) / 2H"}}
  if #ex > 0 then series[2] = {x = ex, y = ey, style = "points", label = "locking events"} end
  mvmpm.plot {file = dir .. "/pbx_force_strain.png", xlabel = "nominal shear strain",
              ylabel = "shear stress (Pa)", series = series,
              title = string.format("PBX bed, %s: shear stress and locking events",
                                    P.binder and "with binder" or "dry")}
  mvmpm.plot {file = dir .. "/pbx_energy.png", xlabel = "nominal shear strain",
              ylabel = "energy (J per m of thickness)", title = "Energy budget", series = {
                {x = mon.strain, y = mon.work, label = "boundary work"},
                {x = mon.strain, y = mon.kinetic, label = "kinetic"},
                {x = mon.strain, y = mon.stored, label = "stored (strain)"},
                {x = mon.strain, y = mon.friction, label = "friction"},
                {x = mon.strain, y = mon.plastic, label = "plastic"},
                {x = mon.strain, y = mon.viscous, label = "viscous"},
                {x = mon.strain, y = mon.residual, label = "residual"}}}
  if binder and bond then
    mvmpm.plot {file = dir .. "/pbx_debond.png", xlabel = "nominal shear strain",
                ylabel = "debonded fraction of the interface", yrange = {0, 1},
                title = string.format("Debonding (bond strength %g Pa)", P.bond),
                series = {{x = mon.strain, y = mon.debond}}}
  end
  local mean, n = 0, 0
  for k, g in ipairs(mon.strain) do
    if g > 2 * P.ramp then mean, n = mean + mon.tau[k], n + 1 end
  end
  local lines = {
    string.format("strain reached              %.4g", mon.strain[#mon.strain] or 0),
    string.format("mean shear stress (Pa)      %.4g", n > 0 and mean / n or 0),
    string.format("locking events              %d", #events),
    string.format("debonded fraction at end    %.4g", mon.debond[#mon.debond] or 0),
    string.format("max |residual| / work       %.4g (after twice the ramp)", mon.max_residual),
    string.format("least det F                 %.4g", mon.jmin),
    string.format("deepest burial (cells)      %d", mon.max_depth),
    string.format("invariant failures          %d", #mon.bad),
  }
  for _, b in ipairs(mon.bad) do lines[#lines + 1] = "invariant: " .. b end
  if hot then
    for _, l in ipairs(heat_report(dir)) do lines[#lines + 1] = l end
  end
  f = assert(mvmpm.open(dir .. "/pbx_summary.txt"))
  f:write(table.concat(lines, "\n"), "\n")
  assert(f:close())
  print(table.concat(lines, "\n"))
end

sim:every {steps = 1, fn = function(s)
  local dir = s.outdir
  if not written and dir ~= "" then
    written = true
    pack.write_csv(bed, dir .. "/pbx")
    hist = assert(mvmpm.open(dir .. "/pbx_history.csv"))
    hist:write("step,t,strain,tau,fy_left,fy_right,kinetic,strain_energy,plastic,viscous,"
               .. "friction,boundary_work,residual,bonded_area,debonded_fraction,jmin,jmax\n")
  end
  local e = s:energy()
  if not area0 and e.bonded_area > 0 then area0 = e.bonded_area end
  local fl, fr = side_force("left", left), side_force("right", right)
  acc, nacc = acc + (fr - fl) / (2 * W), nacc + 1
  if s.steps % P.record == 0 or s.t >= t_end * (1 - 1e-9) then
    local g = strain_at(s.t)
    sample(s, e, g, acc / nacc)
    acc, nacc = 0, 0
    if hist then
      hist:write(string.format(
        "%d,%.9g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
        s.steps, s.t, g, mon.tau[#mon.tau], fl, fr, e.kinetic, e.strain,
        e.plastic, e.viscous, e.dissipated, e.boundary_work, e.residual, e.bonded_area,
        mon.debond[#mon.debond], e.jmin, e.jmax))
      hist:flush()
    end
  end
  if dir ~= "" and P.images > 0 and strain_at(s.t) >= next_image - 1e-9 * P.strain then
    local tag = string.format("%03d", math.floor(100 * next_image + 0.5))
    s:render {file = "pbx_body_" .. tag .. ".png", by = "body", width = 900,
              title = string.format("grains, strain %.2f", strain_at(s.t))}
    s:render {file = "pbx_sdiff_" .. tag .. ".png", by = "sdiff", width = 900,
              title = string.format("|s1 - s2| (Pa), strain %.2f", strain_at(s.t))}
    if hot then
      s:render {file = "pbx_temperature_" .. tag .. ".png", by = "temperature", width = 900,
                title = string.format("temperature (K), strain %.2f", strain_at(s.t))}
      local hs = s:hotspots {threshold = P.hotspot_threshold}
      local e = s:energy()
      mon.hot[#mon.hot + 1] = {strain = strain_at(s.t), count = hs.count,
                               area_fraction = hs.area_fraction, spots = hs,
                               heat_friction = e.heat_friction, heat_plastic = e.heat_plastic,
                               heat_viscous = e.heat_viscous, residual_with_heat = e.residual_with_heat,
                               work = e.boundary_work}
    end
    next_image = next_image + P.images
  end
  if dir ~= "" and not reported and s.t >= t_end * (1 - 1e-9) then
    reported = true
    if hist then hist:close(); hist = nil end
    report(dir)
  end
end}
sim:output {every = t_end / 10, csv_every = P.record,
            hotspots = hot and {threshold = P.hotspot_threshold} or nil}

-- for scripts that load the scene (tests, bench): the bed and helpers
PBX = {bed = bed, grains = grains, binder = binder, left = left, right = right,
       strain_at = strain_at, side_force = side_force, V0 = V0, cell = h, monitor = mon}
return sim
