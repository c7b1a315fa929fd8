-- mvmpm.shear: the granular shear cell of Bardenhagen, Brackbill & Sulsky
-- (1998), Figures 6-8, shared by scenarios/shear_dry.lua and
-- scenarios/shear_binder.lua and by tests/verify/shear.lua.
--
--   local shear = require "mvmpm.shear"
--   local P = mvmpm.params(shear.params {binder = true})
--   local sim, mon = shear.build(P)
--
-- The cell (nondimensional: the report's benchmark units, grain diameter
-- about 1, K = 1, G = 0.5, density 1) is a square of side L = 4, top and
-- bottom periodic.  Nine cylinders, two of them across the periodic seam,
-- so that eleven pieces show, as in the report:
--   attached, radius 0.5, touching the left side:  (0.5, 1), (0.5, 3)
--   attached, radius 0.5, touching the right side: (3.5, 0) [seam], (3.5, 2)
--   free grains, radius 0.45: (1.45, 0) [seam], (1.45, 2), (2.55, 1), (2.55, 3)
--   a smaller free grain, radius 0.35, in the pocket at (1.5, 3)
-- The free grains form a zig-zag between the two attached columns with
-- surface gaps of 0.15 to 0.66 (4 to 16 cells at 100 cells): room to roll,
-- as in the report's dry cell, but not to pass one another without
-- climbing, so shearing a full period (100 %) makes them collide and bind.
-- The side walls move tangentially, the left down and the right up, each
-- at half of rate * L after a smooth start (smoothstep over t_ramp); the
-- attached cylinders are driven bodies with the velocity of their side.
-- Average shear strain: strain(t) = (integral of v_right - v_left) / L.
local mvmpm = require "mvmpm"
local chain = require "mvmpm.chain"
local M = {}

M.L = 4
M.cylinders = {
  {x = 0.5, y = 1.0, r = 0.5, side = "left"},
  {x = 0.5, y = 3.0, r = 0.5, side = "left"},
  {x = 3.5, y = 0.0, r = 0.5, side = "right"},
  {x = 3.5, y = 2.0, r = 0.5, side = "right"},
  {x = 1.25, y = 0.0, r = 0.45},
  {x = 1.25, y = 2.0, r = 0.45},
  {x = 2.75, y = 1.0, r = 0.45},
  {x = 2.75, y = 3.0, r = 0.45},
  {x = 1.55, y = 3.0, r = 0.35},
}

-- The parameters both scenes declare; extra entries override or add.
--   yield: von Mises yield stress of the grains.  0.05 = G/10: an impact
--     at the relative speed of the sides' motion, v = rate * L / 2, gives
--     in one-dimensional strain sigma = rho c_L v and a Mises stress of
--     2G/(lambda + 2G) rho c_L v = 0.039 (v = 0.05), so grains meeting at
--     the shearing speed stay elastic and only sustained binding (force
--     chains) yields them.  (HMX's ratio yield/G is about 0.045.)
--   rate: average shear rate (v_right - v_left) / L; 0.025 moves the
--     sides at 0.05, 1/26 of the grains' longitudinal wave speed.
function M.params(extra)
  local p = {
    cells = 100,         -- cells across the side
    ppc = 2,             -- particles per cell per direction
    rate = 0.025,        -- average shear rate (v_right - v_left) / L
    strain = 1.0,        -- final average shear strain
    t_ramp = 4.0,        -- smooth start of the sides' motion
    friction = 0.3,      -- Coulomb friction, grains with grains and cylinders
    wall_friction = 0.3, -- the sides with whatever touches them
    yield = 0.05,        -- grains' yield stress (see above)
    hardening = 0.0,
    sample = 0.0025,     -- strain between samples of the force and spins
    picture = 0.25,      -- strain between pictures
    width = 600,         -- picture width in pixels
    binder = false,
    bond = 0.0,          -- bond strength grain-binder (0: none)
    binder_K = 0.25,     -- binder bulk modulus
    binder_G = 0.005,    -- binder long-term shear modulus
    binder_G1 = 0.02, binder_tau1 = 1.0,  -- Maxwell elements
    binder_G2 = 0.02, binder_tau2 = 10.0,
    cfl = 0.25,
    flip = 1.0,
    update = "musl",     -- or "usl"
    shape = "linear",    -- or "gimp", "bspline2"
    normals = "mass",    -- contact normals: "volume", "maxvolume", "plane"
    normal_window = 0,   -- ... from the shared nodes within this many cells
  normal_patch = false, -- true: one normal per contact patch (flat faces)
    contact_gap = "touch", -- or "step": contact judged at the step's end
    wall_contact = "node", -- or "patch": the sides act per contact patch
    body_contact = "node", -- or "patch": bodies meet per contact patch
    -- heat (off by default: the scene is then the same, bit for bit).
    -- Nondimensional: temperature in units of energy per unit mass (cv
    -- = 1 makes a particle's temperature rise its heat per unit mass),
    -- T0 = 0.  The grain : binder ratios of cv and k are HMX's to a
    -- polyurethane binder's (about 1000 : 1500 J/(kg K) and 0.45 : 0.15
    -- W/(m K); docs/hotspots.md).  k = 1e-4 makes the diffusion length
    -- over the whole run, sqrt(k t / rho c) = 0.07, a tenth of a grain
    -- radius: nearly adiabatic, as HMX grains of 100 um are at these
    -- strain rates (diffusion time 0.04 s against microseconds).
    heat = false,
    T0 = 0,
    grain_cv = 1.0, grain_k = 1e-4, grain_beta = 0.9,
    binder_cv = 1.5, binder_k = 1e-4 / 3, binder_beta = 0.9,
    friction_split = 0.5,  -- heat's friction_split (share of the first body)
    wall_heat = 1,         -- heat's wall_friction: share of the sides' friction heat kept
    hotspot_threshold = 0.04, -- hot spots: temperature above T0 + this (about the
                              -- 99th percentile at strain 1, 25 cells)
  }
  for k, v in pairs(extra or {}) do p[k] = v end
  return p
end

-- displacement of a side moving at speed v after the smooth start:
-- v s(t / tr) with s(u) = u^2 (3 - 2 u), whose integral over [0, 1] is 1/2
local function ramp(t, tr)
  if t >= tr then return 1 end
  local u = t / tr
  return u * u * (3 - 2 * u)
end
local function ramp_disp(t, tr)
  if t >= tr then return t - tr / 2 end
  local u = t / tr
  return tr * (u ^ 3 - u ^ 4 / 2)
end

-- average shear strain at time t, and the time of a given strain
function M.strain_at(P, t) return P.rate * ramp_disp(t, P.t_ramp) end
function M.time_of(P, g)
  local t = g / P.rate + P.t_ramp / 2
  if t >= P.t_ramp then return t end
  local lo, hi = 0, P.t_ramp   -- within the ramp: bisection
  for _ = 1, 60 do
    local mid = (lo + hi) / 2
    if M.strain_at(P, mid) < g then lo = mid else hi = mid end
  end
  return (lo + hi) / 2
end

-- Build the cell.  Returns the simulation and a monitor (M.monitor).
function M.build(P)
  local L = M.L
  local V = P.rate * L / 2
  local function side(sign)
    local mu = tonumber(P.wall_friction) or P.wall_friction
    return {"wall", friction = mu,
            velocity = function(t) return 0, sign * V * ramp(t, P.t_ramp) end}
  end
  local sim = mvmpm.sim {
    domain = {x = {0, L}, y = {0, L}}, cell = L / P.cells, ppc = P.ppc,
    t_end = M.time_of(P, P.strain), cfl = P.cfl, flip = P.flip,
    update = P.update, shape = P.shape, normals = P.normals, normal_window = P.normal_window,
    normal_patch = P.normal_patch,
    contact_gap = P.contact_gap, wall_contact = P.wall_contact, body_contact = P.body_contact,
    sides = {left = side(-1), right = side(1), bottom = "periodic", top = "periodic"},
    contact = {friction = P.friction},
  }
  local hot = P.heat == true or P.heat == "true"
  if hot then
    sim:heat {friction_split = P.friction_split, wall_friction = P.wall_heat}
    sim:temperature(P.T0)
  end
  local grain = mvmpm.plastic {K = 1, G = 0.5, density = 1, yield = P.yield,
                               hardening = P.hardening, name = "grain",
                               cv = hot and P.grain_cv or nil, k = hot and P.grain_k or nil,
                               beta = hot and P.grain_beta or nil}
  local bodies = {attached = {left = {}, right = {}}, free = {}}
  local bond = P.binder and P.bond > 0 and P.bond or nil
  for k, c in ipairs(M.cylinders) do
    local spec = {shape = mvmpm.disk {center = {c.x, c.y}, radius = c.r},
                  material = grain, bond = bond}
    if c.side then
      local sign = c.side == "left" and -1 or 1
      spec.name = string.format("%s%d", c.side, #bodies.attached[c.side] + 1)
      spec.driven = function(t) return 0, sign * V * ramp(t, P.t_ramp) end
      local b = sim:body(spec)
      table.insert(bodies.attached[c.side], b)
    else
      spec.name = string.format("grain%d", #bodies.free + 1)
      local b = sim:body(spec)
      bodies.free[#bodies.free + 1] = {body = b, r = c.r, x0 = c.x, y0 = c.y}
    end
  end
  if P.binder then
    local binder = mvmpm.viscoelastic {
      K = P.binder_K, G_inf = P.binder_G, density = 1, name = "binder",
      cv = hot and P.binder_cv or nil, k = hot and P.binder_k or nil,
      beta = hot and P.binder_beta or nil,
      prony = {{G = P.binder_G1, tau = P.binder_tau1}, {G = P.binder_G2, tau = P.binder_tau2}}}
    bodies.binder = sim:body {name = "binder", shape = mvmpm.rest(), material = binder,
                              bond = bond}
  end
  bodies.hot = hot
  return sim, M.monitor(sim, P, bodies)
end

----------------------------------------------------------------------------
-- Locking events.  The shear force F(strain) is sampled as its mean over
-- each strain interval P.sample.  Past the ramp, with
--   mean(k)  the running mean of F over the samples before k (from the
--            end of the ramp), and
--   rise(k)  F(k) minus the least F over the window of LOCK_WINDOW strain
--            that ends at k,
-- a locking event starts at the first sample where rise > LOCK_RISE * mean
-- and F > (1 + LOCK_RISE) * mean (the force climbs by more than half its
-- running mean within 2 % strain, to above 1.5 times that mean) and lasts
-- until F falls back below the running mean; its peak is the largest F
-- meanwhile.  A new event needs the previous one ended.
M.LOCK_RISE = 0.5
M.LOCK_WINDOW = 0.02

function M.locking(strain, force, from)
  local events, sum, n, cur = {}, 0, 0, nil
  for k = 1, #force do
    local g, f = strain[k], force[k]
    if g >= from then
      local mean = n > 0 and sum / n or nil
      if mean and mean > 0 then
        if cur then
          if f > cur.peak then cur.peak, cur.peak_strain = f, g end
          if f < mean then cur.end_strain = g; events[#events + 1] = cur; cur = nil end
        else
          local least = f
          for j = k - 1, 1, -1 do
            if strain[j] < g - M.LOCK_WINDOW or strain[j] < from then break end
            if force[j] < least then least = force[j] end
          end
          if f - least > M.LOCK_RISE * mean and f > (1 + M.LOCK_RISE) * mean then
            cur = {strain = g, base = least, mean = mean, peak = f, peak_strain = g}
          end
        end
      end
      sum, n = sum + f, n + 1
    end
  end
  if cur then cur.end_strain = strain[#strain]; events[#events + 1] = cur end
  return events
end

----------------------------------------------------------------------------
-- The monitor: per step, the forces of the sides and the attached
-- cylinders (averaged over each sample); per sample, spins, energies,
-- invariants; files when the run writes output (sim.outdir set).
-- (mvmpm.open writes path.part and renames it on close, also sandboxed)
local function csv_write(path, header, rows)
  local f = assert(mvmpm.open(path))
  f:write(table.concat(header, ","), "\n")
  for _, r in ipairs(rows) do
    local s = {}
    for j, h in ipairs(header) do
      local v = r[h]
      s[j] = type(v) == "number" and string.format("%.9g", v) or tostring(v)
    end
    f:write(table.concat(s, ","), "\n")
  end
  assert(f:close())
end

-- nearest-image separation along the periodic y
local function dy(a, b, L)
  local d = a - b
  if d > L / 2 then d = d - L elseif d < -L / 2 then d = d + L end
  return d
end

function M.monitor(sim, P, bodies)
  local L = M.L
  local mon = {P = P, sim = sim, bodies = bodies, rows = {}, events = {},
               strain = {}, force = {}, rotation = {}, bad = {}}
  local free = bodies.free
  for k = 1, #free do mon.rotation[k] = 0 end
  -- accumulators over the current sample
  local acc = {n = 0, fl = 0, fr = 0, nl = 0, nr = 0, t0 = 0}
  local imp = {0, 0}          -- impulse on the non-driven material, y and x
  local p0                    -- its momentum at the start
  local omega_prev, t_prev    -- spins at the last sample (trapezoid rule)
  local bonded0               -- bonded area after the first step
  local maxres, maxdepth, worst_py, jmin = 0, 0, 0, math.huge
  -- the attached cylinders move rigidly with their sides: their kinetic
  -- energy 1/2 M v(t)^2 is boundary work that never enters the material
  local m_att = 0
  for _, side in ipairs {"left", "right"} do
    for _, b in ipairs(bodies.attached[side]) do m_att = m_att + b:mass() end
  end
  local V = P.rate * L / 2
  -- force chains: from the left side (its wall and attached cylinders)
  -- to the right, through grains (the binder, one body touching
  -- everything, is no link); the sides are vertices of their own
  local lset, rset, skip = {}, {}, {}
  for _, b in ipairs(bodies.attached.left) do lset[b.id] = true end
  for _, b in ipairs(bodies.attached.right) do rset[b.id] = true end
  lset[-1], rset[-2] = true, true
  if bodies.binder then skip[bodies.binder.id] = true end
  local hist = {}             -- per sample: work, deformation (for the share)
  local next_sample, next_picture = P.sample, 0
  local from = M.strain_at(P, P.t_ramp)
  mon.ramp_strain = from

  local function material_momentum()
    local px, py = 0, 0
    for _, g in ipairs(free) do
      local d = g.body:diag()
      px, py = px + d.mass * d.vx, py + d.mass * d.vy
    end
    if bodies.binder then
      local d = bodies.binder:diag()
      px, py = px + d.mass * d.vx, py + d.mass * d.vy
    end
    return px, py
  end

  local function side_force(name)
    local fx, fy = sim:wall_force(name)
    for _, b in ipairs(bodies.attached[name]) do
      local bx, by = b:force()
      fx, fy = fx + bx, fy + by
    end
    return fx, fy
  end

  local function picture(s, g)
    if s.outdir == "" then return end
    local tag = string.format("%03d", math.floor(g * 100 + 0.5))
    s:render {file = "sdiff_" .. tag .. ".png", by = "sdiff",
              range = {0, P.yield}, width = P.width,
              title = string.format("|s1 - s2|, shear strain %.2f", g)}
    s:render {file = "body_" .. tag .. ".png", by = "body",
              width = P.width, title = string.format("bodies, shear strain %.2f", g)}
    if bodies.hot then
      s:render {file = "temperature_" .. tag .. ".png", by = "temperature", width = P.width,
                title = string.format("temperature, shear strain %.2f", g)}
    end
    if bodies.binder and P.bond > 0 then
      s:render {file = "bond_" .. tag .. ".png", by = "bond",
                range = {0, P.bond}, width = P.width,
                title = string.format("bond strength left, shear strain %.2f", g)}
    end
  end

  -- the narrowest surface gap between two grains (free or attached),
  -- from their centroids and seeded radii, in cells
  local all = {}
  for _, g in ipairs(free) do all[#all + 1] = {body = g.body, r = g.r} end
  for _, side in ipairs {"left", "right"} do
    for k, b in ipairs(bodies.attached[side]) do all[#all + 1] = {body = b, r = 0.5, side = side, k = k} end
  end
  local function narrowest(cent)
    local best = math.huge
    for i = 1, #all do
      for j = i + 1, #all do
        if not (all[i].side and all[j].side) then
          local a, b = cent[i], cent[j]
          local ddx, ddy = a[1] - b[1], dy(a[2], b[2], L)
          local gap = math.sqrt(ddx * ddx + ddy * ddy) - all[i].r - all[j].r
          if gap < best then best = gap end
        end
      end
    end
    return best / sim.cell
  end

  local function sample(s)
    local g = M.strain_at(P, s.t)
    local e = s:energy()
    local fl, fr = acc.fl / acc.n, acc.fr / acc.n
    local force = (fr - fl) / 2
    -- spins of the free grains, integrated by the trapezoid rule
    local cent, om = {}, {}
    for k, gr in ipairs(free) do
      local d = gr.body:diag()
      om[k] = d.omega
      cent[k] = {d.x, d.y}
      mon.rotation[k] = mon.rotation[k] + 0.5 * (om[k] + omega_prev[k]) * (s.t - t_prev)
    end
    for k = #free + 1, #all do
      local x, y = all[k].body:centroid()
      cent[k] = {x, y}
    end
    omega_prev, t_prev = om, s.t
    -- the strongest force chain across the cell, and the share of the
    -- work into the material that went into deforming the grains (their
    -- strain energy and plastic work) over the last LOCK_WINDOW of strain
    local con = s:contacts()
    -- a free grain within a cell of a side (its centroid and seeded
    -- radius) presses on it with at most the side's own normal force
    local wl, wr = math.abs((s:wall_force("left"))), math.abs((s:wall_force("right")))
    for k, gr in ipairs(free) do
      if cent[k][1] - gr.r < s.cell and wl > 0 then
        con[#con + 1] = {a = -1, b = gr.body.id, force = wl}
      end
      if cent[k][1] + gr.r > L - s.cell and wr > 0 then
        con[#con + 1] = {a = -2, b = gr.body.id, force = wr}
      end
    end
    local ch = chain.strongest(con, lset, rset, {skip = skip})
    -- pairs pressing, binder aside, and of those the pairs of free grains
    local isfree, npress, ngg = {}, 0, 0
    for _, gr in ipairs(free) do isfree[gr.body.id] = true end
    for _, c in ipairs(con) do
      if not skip[c.a] and not skip[c.b] then
        npress = npress + 1
        if isfree[c.a] and isfree[c.b] then ngg = ngg + 1 end
      end
    end
    local gstrain = 0
    for _, gr in ipairs(free) do gstrain = gstrain + gr.body:diag().strain end
    local rot = 0
    for k = 1, #free do rot = rot + math.abs(mon.rotation[k]) end
    rot = rot / #free
    -- invariants
    local n_ov, depth = s:overlap()
    local px, py = material_momentum()
    local dpy = math.abs(py - p0[2] - imp[1])
    local scale = 0
    for _, gr in ipairs(free) do scale = scale + gr.body:mass() end
    if bodies.binder then scale = scale + bodies.binder:mass() end
    scale = scale * P.rate * L / 2
    local v = V * ramp(s.t, P.t_ramp)
    local work = e.boundary_work - 0.5 * m_att * v * v
    local row = {
      t = s.t, strain = g, work = work, kinetic_free = e.kinetic - 0.5 * m_att * v * v, force = force, normal = (acc.nl - acc.nr) / (2 * acc.n),
      f_left = fl, f_right = fr,
      boundary_work = e.boundary_work, kinetic = e.kinetic, stored = e.strain,
      friction = e.dissipated, plastic = e.plastic, viscous = e.viscous,
      residual = e.residual, mean_abs_rotation = rot,
      bonded_fraction = bonded0 and bonded0 > 0 and e.bonded_area / bonded0 or 0,
      jmin = e.jmin, overlap = n_ov, overlap_depth = depth,
      py_error = dpy / scale, narrowest_gap = narrowest(cent),
      chain_force = ch and ch.force or 0, chain_grains = ch and #ch.path - 2 or 0,
      pressing = npress, grain_grain = ngg,
      grain_strain = gstrain,
    }
    -- the share over the last LOCK_WINDOW of strain, where the work done
    -- in it is at least a tenth of the run's mean over such a window
    -- (else 0: nothing is being done to share)
    hist[#hist + 1] = {g = g, w = work, d = gstrain + e.plastic}
    local j = #hist
    while j > 1 and hist[j - 1].g > g - M.LOCK_WINDOW - 1e-12 do j = j - 1 end
    if j > 1 then j = j - 1 end
    local dw = work - hist[j].w
    row.deform_share = 0
    if j < #hist and g > 0 and dw > 0.1 * M.LOCK_WINDOW * work / g then
      row.deform_share = (hist[#hist].d - hist[j].d) / dw
    end
    row.deformation = gstrain + e.plastic
    for k = 1, #free do row["rot" .. k] = mon.rotation[k] end
    if bodies.hot then
      row.heat_friction, row.heat_plastic, row.heat_viscous = e.heat_friction, e.heat_plastic,
                                                              e.heat_viscous
      row.heat_wall, row.cold_work, row.thermal_energy = e.heat_wall, e.cold_work, e.thermal_energy
      row.heat_residual, row.residual_with_heat = e.heat_residual, e.residual_with_heat
      local hs = s:hotspots {threshold = P.T0 + P.hotspot_threshold}
      row.hotspots, row.hotspot_area_fraction = hs.count, hs.area_fraction
      row.T_max = 0
      for _, T in ipairs(s:particles("temperature")) do
        if T - P.T0 > row.T_max then row.T_max = T - P.T0 end
      end
      if math.abs(e.residual_with_heat) > (mon.max_residual_heat or 0) then
        mon.max_residual_heat = math.abs(e.residual_with_heat)
      end
    end
    mon.rows[#mon.rows + 1] = row
    mon.strain[#mon.strain + 1], mon.force[#mon.force + 1] = g, force
    -- the most locked state: pictures whenever the force reaches a new
    -- high past the ramp (Figure 7's force chain)
    if s.outdir ~= "" and g > from and force > (mon.peak_force or 0) then
      mon.peak_force = force
      s:render {file = "sdiff_peak.png", by = "sdiff", range = {0, P.yield},
                width = P.width,
                title = string.format("|s1 - s2| at the largest shear force, strain %.3f", g)}
      s:render {file = "body_peak.png", by = "body", width = P.width,
                title = string.format("bodies at the largest shear force, strain %.3f", g)}
    end
    -- stability: every number finite, J > 0, nothing buried
    if e.total ~= e.total or force ~= force or e.jmin ~= e.jmin then
      mon.bad[#mon.bad + 1] = string.format("NaN at strain %.4f", g)
    end
    if not (e.jmin > 0) then mon.bad[#mon.bad + 1] = string.format("J <= 0 at strain %.4f", g) end
    if n_ov > 0 then
      mon.bad[#mon.bad + 1] = string.format("%d particles buried %d cells at strain %.4f", n_ov, depth, g)
    end
    if depth > maxdepth then maxdepth = depth end
    if e.jmin < jmin then jmin = e.jmin end
    if dpy / scale > worst_py then worst_py = dpy / scale end
    if not mon.min_gap or row.narrowest_gap < mon.min_gap then mon.min_gap = row.narrowest_gap end
    if math.abs(e.residual) > maxres then maxres = math.abs(e.residual) end
    mon.max_residual, mon.max_depth, mon.jmin, mon.max_py_error = maxres, maxdepth, jmin, worst_py
    acc.n, acc.fl, acc.fr, acc.nl, acc.nr = 0, 0, 0, 0, 0
  end

  sim:every {steps = 1, fn = function(s)
    if not p0 then
      -- after the first step: the material's momentum (zero at rest) and
      -- the bonded area the interfaces start with
      p0 = {0, 0}
      omega_prev, t_prev = {}, 0
      for k = 1, #free do omega_prev[k] = 0 end
      bonded0 = s:energy().bonded_area
      picture(s, 0)
      next_picture = P.picture
    end
    local lx, ly = side_force("left")
    local rx, ry = side_force("right")
    imp[1] = imp[1] + (ly + ry) * s.dt
    imp[2] = imp[2] + (lx + rx) * s.dt
    acc.n, acc.fl, acc.fr = acc.n + 1, acc.fl + ly, acc.fr + ry
    acc.nl, acc.nr = acc.nl + lx, acc.nr + rx
    local g = M.strain_at(P, s.t)
    if g >= next_sample - 1e-12 * P.sample then
      sample(s)
      next_sample = next_sample + P.sample
    end
    local due = g >= next_picture - 1e-9
    if due then
      picture(s, next_picture)
      next_picture = next_picture + P.picture
    end
    -- the files, at each picture and at the end
    if s.outdir ~= "" and #mon.rows > 0 and (due or s.t >= s.t_end) then
      M.report(mon, s.outdir)
    end
  end}
  return mon
end

-- mean equivalent plastic strain over the free grains' particles
function M.plastic_strain(mon)
  local ep, body = mon.sim:particles("plastic_strain"), mon.sim:particles("body")
  local free, sum, n = {}, 0, 0
  for _, g in ipairs(mon.bodies.free) do free[g.body.id] = true end
  for i = 1, #ep do
    if free[body[i]] then sum, n = sum + ep[i], n + 1 end
  end
  return n > 0 and sum / n or 0
end

-- Locking as force chains: past the ramp, the samples where a chain of
-- pressing bodies spans the cell from one side to the other (chain_force
-- > 0), grouped into runs of consecutive samples; and the share of the
-- work into the material that went into deforming the grains (their
-- strain energy and plastic work), in those samples and in the others.
function M.chains(mon)
  local runs, cur, n, nch, fmax = {}, nil, 0, 0, 0
  local dl, wl, du, wu = 0, 0, 0, 0
  local rows = mon.rows
  for k, r in ipairs(rows) do
    if r.strain >= mon.ramp_strain then
      n = n + 1
      local dd = k > 1 and r.deformation - rows[k - 1].deformation or 0
      local dw = k > 1 and r.work - rows[k - 1].work or 0
      if r.chain_force > 0 then
        nch = nch + 1
        dl, wl = dl + dd, wl + dw
        if r.chain_force > fmax then fmax = r.chain_force end
        if not cur then
          cur = {strain = r.strain, peak = 0, grains = 0}
          runs[#runs + 1] = cur
        end
        cur.end_strain = r.strain
        if r.chain_force > cur.peak then
          cur.peak, cur.peak_strain, cur.grains = r.chain_force, r.strain, r.chain_grains
        end
      else
        cur = nil
        du, wu = du + dd, wu + dw
      end
    end
  end
  local last = rows[#rows]
  return {runs = runs, fraction = n > 0 and nch / n or 0, max_force = fmax,
          share_chain = wl > 0 and dl / wl or 0, share_free = wu > 0 and du / wu or 0,
          share = last.work > 0 and last.deformation / last.work or 0}
end

-- Where the heat is (heat on): the shares of the sources in the heat
-- booked, the shares of the thermal energy held by the grains (free and
-- attached) and the binder, and of the particles above the hot-spot
-- threshold: how many, the binder's share of them, and the share whose
-- heat came mostly (over half) from friction.
function M.where(mon)
  local s, P = mon.sim, mon.P
  local e = s:energy()
  local T, m, q, qf, body = s:particles("temperature"), s:particles("mass"),
    s:particles("heat"), s:particles("heat_friction"), s:particles("body")
  local bid = mon.bodies.binder and mon.bodies.binder.id or -1
  local eb, eg, nhot, nbind, nfric, qhot, qfhot = 0, 0, 0, 0, 0, 0, 0
  for i = 1, #T do
    local c = body[i] == bid and P.binder_cv or P.grain_cv
    local th = m[i] * c * (T[i] - P.T0)
    if body[i] == bid then eb = eb + th else eg = eg + th end
    if T[i] > P.T0 + P.hotspot_threshold then
      nhot = nhot + 1
      if body[i] == bid then nbind = nbind + 1 end
      if q[i] > 0 and qf[i] > 0.5 * q[i] then nfric = nfric + 1 end
      qhot, qfhot = qhot + q[i], qfhot + qf[i]
    end
  end
  local src = e.heat_friction + e.heat_plastic + e.heat_viscous
  local r = mon.rows[#mon.rows]
  return {
    share_friction = src > 0 and e.heat_friction / src or 0,
    share_plastic = src > 0 and e.heat_plastic / src or 0,
    share_viscous = src > 0 and e.heat_viscous / src or 0,
    thermal_in_binder = eb + eg > 0 and eb / (eb + eg) or 0,
    hot_particles = nhot,
    hot_in_binder = nhot > 0 and nbind / nhot or 0,
    hot_mostly_friction = nhot > 0 and nfric / nhot or 0,
    hot_heat_friction_share = qhot > 0 and qfhot / qhot or 0,
    heat_residual_over_heat = e.thermal_energy ~= 0 and e.heat_residual / e.thermal_energy or 0,
    residual_with_heat_over_work = r.work > 0 and e.residual_with_heat / r.work or 0,
    max_residual_with_heat_over_work = r.work > 0 and (mon.max_residual_heat or 0) / r.work or 0,
  }
end

-- summary figures of a monitor (for tests and reports)
function M.summary(mon)
  local r = mon.rows[#mon.rows]
  mon.events = M.locking(mon.strain, mon.force, mon.ramp_strain)
  local ch = M.chains(mon)
  mon.chain_runs = ch.runs
  local fsum, n = 0, 0
  for k, g in ipairs(mon.strain) do
    if g >= mon.ramp_strain then fsum, n = fsum + mon.force[k], n + 1 end
  end
  return {
    strain = r.strain, mean_force = n > 0 and fsum / n or 0,
    events = #mon.events, mean_abs_rotation = r.mean_abs_rotation,
    bonded_fraction = r.bonded_fraction, work = r.work,
    max_residual = mon.max_residual / r.work,
    max_depth = mon.max_depth, jmin = mon.jmin, max_py_error = mon.max_py_error,
    boundary_work = r.boundary_work, residual = r.residual,
    min_gap = mon.min_gap, mean_plastic_strain = M.plastic_strain(mon),
    chain_fraction = ch.fraction, chain_runs = #ch.runs, chain_max_force = ch.max_force,
    deform_share = ch.share, deform_share_chain = ch.share_chain,
    deform_share_free = ch.share_free,
  }
end

-- CSV and PNG files into dir
function M.report(mon, dir)
  local P = mon.P
  local s = M.summary(mon)
  mon.written = #mon.rows
  local header = {"t", "strain", "force", "normal", "f_left", "f_right", "boundary_work",
                  "work", "kinetic", "kinetic_free", "stored", "friction", "plastic", "viscous", "residual",
                  "mean_abs_rotation", "bonded_fraction", "jmin", "overlap",
                  "overlap_depth", "py_error", "narrowest_gap", "chain_force", "chain_grains",
                  "pressing", "grain_grain", "grain_strain", "deformation", "deform_share"}
  for k = 1, #mon.bodies.free do header[#header + 1] = "rot" .. k end
  csv_write(dir .. "/shear.csv", header, mon.rows)
  if mon.bodies.hot then
    csv_write(dir .. "/heat.csv", {"t", "strain", "work", "friction", "plastic", "viscous",
                                   "heat_friction", "heat_plastic", "heat_viscous", "heat_wall",
                                   "cold_work", "thermal_energy", "heat_residual", "residual",
                                   "residual_with_heat", "hotspots", "hotspot_area_fraction",
                                   "T_max"}, mon.rows)
    local col = function(name)
      local t = {}
      for k, r in ipairs(mon.rows) do t[k] = r[name] end
      return t
    end
    mvmpm.plot {file = dir .. "/hotspots_strain.png", xlabel = "average shear strain",
                ylabel = "count", title = string.format("Hot spots (T - T0 > %g)", P.hotspot_threshold),
                series = {{x = mon.strain, y = col("hotspots"), label = "hot spots"}}}
    local af = col("hotspot_area_fraction")
    mvmpm.plot {file = dir .. "/hotspot_area_strain.png", xlabel = "average shear strain",
                ylabel = "area fraction", title = string.format("Hot area (T - T0 > %g)", P.hotspot_threshold),
                series = {{x = mon.strain, y = af, label = "area fraction above the threshold"}}}
    mvmpm.plot {file = dir .. "/heat_strain.png", xlabel = "average shear strain", ylabel = "energy",
                title = "Heat by source", series = {
                  {x = mon.strain, y = col("work"), label = "work into the material"},
                  {x = mon.strain, y = col("heat_friction"), label = "friction heat"},
                  {x = mon.strain, y = col("heat_plastic"), label = "plastic heat"},
                  {x = mon.strain, y = col("heat_viscous"), label = "viscous heat"},
                  {x = mon.strain, y = col("thermal_energy"), label = "thermal energy"},
                  {x = mon.strain, y = col("residual_with_heat"), label = "residual with heat"}}}
  end
  csv_write(dir .. "/locking.csv", {"strain", "peak_strain", "end_strain", "base", "peak", "mean"},
            mon.events)
  csv_write(dir .. "/chains.csv", {"strain", "end_strain", "peak_strain", "peak", "grains"},
            mon.chain_runs)
  local col = function(name)
    local t = {}
    for k, r in ipairs(mon.rows) do t[k] = r[name] end
    return t
  end
  local ex, ey = {}, {}
  for k, ev in ipairs(mon.events) do ex[k], ey[k] = ev.peak_strain, ev.peak end
  local series = {{x = mon.strain, y = mon.force, label = "shear force (F_right - F_left)/2"},
                  {x = mon.strain, y = col("normal"), label = "normal force on the sides"}}
  if #ex > 0 then series[#series + 1] = {x = ex, y = ey, style = "points", label = "force-rise events"} end
  series[#series + 1] = {x = mon.strain, y = col("chain_force"),
                         label = "strongest spanning force chain (0: none)"}
  mvmpm.plot {file = dir .. "/force_strain.png", xlabel = "average shear strain",
              ylabel = "force per unit depth", title = "Shear force and locking events",
              series = series}
  local locked = {}
  for k, r in ipairs(mon.rows) do locked[k] = r.chain_force > 0 and 1 or 0 end
  mvmpm.plot {file = dir .. "/deform_share.png", xlabel = "average shear strain",
              ylabel = "share", title = "Work into grain deformation, and spanning chains",
              series = {{x = mon.strain, y = col("deform_share"),
                         label = "(strain + plastic of the grains) / work, over 2 % strain"},
                        {x = mon.strain, y = locked, label = "a chain spans the cell (1)"}}}
  local rs = {}
  for k = 1, #mon.bodies.free do
    rs[k] = {x = mon.strain, y = col("rot" .. k), label = mon.bodies.free[k].body.name}
  end
  rs[#rs + 1] = {x = mon.strain, y = (function()
    local t = {}
    for k, g in ipairs(mon.strain) do t[k] = g / 2 end
    return t
  end)(), label = "affine: strain / 2"}
  mvmpm.plot {file = dir .. "/rotation.png", xlabel = "average shear strain",
              ylabel = "rotation (rad, counter-clockwise)", title = "Grain rotations",
              series = rs}
  mvmpm.plot {file = dir .. "/energy.png", xlabel = "average shear strain", ylabel = "energy",
              title = "Energy budget", series = {
                {x = mon.strain, y = col("work"), label = "work into the material"},
                {x = mon.strain, y = col("stored"), label = "stored (strain)"},
                {x = mon.strain, y = col("kinetic_free"), label = "kinetic"},
                {x = mon.strain, y = col("friction"), label = "friction"},
                {x = mon.strain, y = col("plastic"), label = "plastic"},
                {x = mon.strain, y = col("viscous"), label = "viscous"},
                {x = mon.strain, y = col("residual"), label = "residual"}}}
  if mon.bodies.binder then
    local d = {}
    for k, f in ipairs(col("bonded_fraction")) do d[k] = 1 - f end
    mvmpm.plot {file = dir .. "/debond.png", xlabel = "average shear strain",
                ylabel = "debonded fraction of the interface", yrange = {0, 1},
                title = string.format("Debonding (bond strength %g)", P.bond),
                series = {{x = mon.strain, y = d}}}
  end
  local f = assert(mvmpm.open(dir .. "/summary.txt"))
  local keys = {}
  for k in pairs(s) do keys[#keys + 1] = k end
  table.sort(keys)
  for _, k in ipairs(keys) do f:write(string.format("%-20s %.6g\n", k, s[k])) end
  for _, b in ipairs(mon.bad) do f:write("invariant: ", b, "\n") end
  if mon.bodies.hot then
    local w = M.where(mon)
    local hk = {}
    for k in pairs(w) do hk[#hk + 1] = k end
    table.sort(hk)
    for _, k in ipairs(hk) do f:write(string.format("heat: %-28s %.6g\n", k, w[k])) end
  end
  f:close()
  return s
end

return M
