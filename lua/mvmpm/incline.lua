-- mvmpm.incline: a disc on an incline, the incline being the floor wall
-- of a box with gravity rotated by theta (g = 1), periodic along the
-- incline; an elastic disc (K = 100, G = 50, density 1, R = 0.5) starts
-- touching the floor.  Measured: least-squares slopes of the centroid
-- velocity along the incline and of the spin (clockwise = down the
-- incline) over the last three quarters of 40 samples (the first quarter
-- is the settling).  Shared by studies/roll.lua and
-- tests/verify/rolling.lua.
local mvmpm = require "mvmpm"
local M = {g = 1, R = 0.5, T = 2, H = 0.25}

-- o: cells, deg, mu, and optionally ppc (2), shape, transfer, flip,
-- update, cfl (0.25), volume (the disc's, sim:body), wall_contact, body_contact, normals, normal_window, normal_patch, threads, slab (nil: the floor wall is the
-- incline; "driven" or "elastic": a slab of thickness H is), w0 (initial
-- spin), run (function(sim, t), default sim:run).  Returns {a, alpha, hop, e (sim:energy()), th, wmin, wmax}.
function M.run(o)
  local g, R, T = M.g, M.R, M.T
  local th = math.rad(o.deg)
  -- with a slab, the incline is the slab's top face at y = H (a driven,
  -- i.e. rigid and fixed, body, or an elastic one stuck to the floor);
  -- friction is then the contact law between the disc and the slab
  local H = o.slab and M.H or 0
  local sim = mvmpm.sim {
    domain = {x = {0, 4}, y = {0, 1.5 + H}}, cell = 1 / o.cells, ppc = o.ppc or 2,
    shape = o.shape, transfer = o.transfer, flip = o.flip, update = o.update,
    cfl = o.cfl or 0.25, wall_contact = o.wall_contact, body_contact = o.body_contact,
    threads = o.threads, t_end = T,
    normals = o.normals, normal_window = o.normal_window, normal_patch = o.normal_patch,
    gravity = {g * math.sin(th), -g * math.cos(th)},
    sides = {left = "periodic", right = "periodic",
             bottom = {"wall", friction = o.slab and "stick" or o.mu}, top = "wall"},
    contact = o.slab and {friction = o.mu} or nil,
  }
  if o.slab then
    sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {4, H}},
              material = mvmpm.elastic {K = 1000, G = 500, density = 1},
              driven = o.slab == "driven" and {0, 0} or nil}
  end
  local disc = sim:body {shape = mvmpm.disk {center = {1, H + R}, radius = R}, volume = o.volume,
                         material = mvmpm.elastic {K = 100, G = 50, density = 1},
                         angular_velocity = o.w0}
  local run = o.run or function(s, t) s:run(t) end
  local n, ts, vs, ws, hop, wmin, wmax = 40, {}, {}, {}, 0, math.huge, -math.huge
  for k = 1, n do
    run(sim, T * k / n)
    local d = disc:diag()
    ts[k], vs[k], ws[k] = sim.t, d.vx, -d.omega
    hop = math.max(hop, d.y - H - R)
    wmin, wmax = math.min(wmin, -d.omega), math.max(wmax, -d.omega)
  end
  local function slope(y)
    local sx, sy, sxx, sxy, c = 0, 0, 0, 0, 0
    for i = n // 4, n do
      sx, sy, sxx, sxy, c = sx + ts[i], sy + y[i], sxx + ts[i] ^ 2, sxy + ts[i] * y[i], c + 1
    end
    return (c * sxy - sx * sy) / (c * sxx - sx * sx)
  end
  return {a = slope(vs), alpha = slope(ws), hop = hop, e = sim:energy(), th = th,
          wmin = wmin, wmax = wmax}
end

-- The accuracy-cost study case of both inclines (studies/roll.lua: the
-- wall, per contact patch; studies/roll_slab.lua: a driven slab, through
-- body-body contact): rolling at 25 deg (mu 0.5) and sliding at 30 deg
-- (mu 0.1), errors |a / a_ref - 1| and |alpha / alpha_ref - 1| against
-- the rigid disc.  o: name, title, grid, slab (nil: the wall),
-- wall_contact ("patch" unless given)
function M.study(o)
  local g, R = M.g, M.R
  local function incline(s, clock, deg, mu)
    local r = M.run {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer,
                     flip = s.flip, update = s.update, cfl = s.cfl, deg = deg, mu = mu,
                     wall_contact = o.wall_contact or "patch", slab = o.slab, run = clock.run}
    return r.a, r.alpha, r.hop, r.th
  end
  return {
    name = o.name, title = o.title, length = "D",
    reference = "rigid disc: rolling a = 2/3 g sin, alpha = a/R; sliding a = g (sin - mu cos), R alpha = 2 mu g cos",
    metrics = {{key = "roll_a", label = "rolling |a/a_ref - 1|"},
               {key = "roll_alpha", label = "rolling |alpha/alpha_ref - 1|"},
               {key = "slide_a", label = "sliding |a/a_ref - 1|"},
               {key = "slide_alpha", label = "sliding |alpha/alpha_ref - 1|"}},
    extra = {"roll_a_ratio", "roll_alpha_ratio", "slide_a_ratio", "slide_alpha_ratio", "roll_hop"},
    grid = o.grid,
    baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl", ppc = 2},
    skip = function(s) return s.transfer == "apic" and s.shape == "linear" end,
    run = function(s, clock)
      local ra, ral, hop, th = incline(s, clock, 25, 0.5)
      local a_r = 2 / 3 * g * math.sin(th)
      local sa, sal, _, ts = incline(s, clock, 30, 0.1)
      local a_s = g * (math.sin(ts) - 0.1 * math.cos(ts))
      local al_s = 2 * 0.1 * g * math.cos(ts) / R
      return {roll_a = math.abs(ra / a_r - 1), roll_alpha = math.abs(ral / (a_r / R) - 1),
              slide_a = math.abs(sa / a_s - 1), slide_alpha = math.abs(sal / al_s - 1),
              roll_a_ratio = ra / a_r, roll_alpha_ratio = ral / (a_r / R),
              slide_a_ratio = sa / a_s, slide_alpha_ratio = sal / al_s, roll_hop = hop}
    end,
  }
end

return M
