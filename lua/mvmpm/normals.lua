-- mvmpm.normals: the contact normals' cases with known answers, shared by
-- tests/verify/normals.lua, tests/verify/two_disks.lua and
-- studies/normals.lua.
--   M.block: an elastic block (side L = 0.2, E = 200, nu = 0.3, rho = 1)
--   sliding on a driven flat body 0.1 thick; reference a = g (sin th -
--   mu cos th), no spin, no motion off the surface.
--   M.discs: Sulsky's two elastic discs (E = 1000, nu = 0.3, rho = 1000,
--   radius 0.2, velocities +-(0.1, 0.1)), the upper one offset across the
--   approach; reference (frictionless): the impulse along the line of
--   centres, so the relative velocity across it is kept, no spin, energy
--   kept.
-- A normals method is named "method/R" for normal_window = R ("method"
-- alone: R = 0), with "+patch" after it for normal_patch = true;
-- "default" (or none) gives none of the three: the sim's defaults.
local mvmpm = require "mvmpm"
local M = {}

-- "method/R+patch" -> normals, normal_window, normal_patch
function M.opts(method)
  if method == nil or method == "default" then return nil, nil, nil end
  local base, patch = method:match("^(.-)(%+patch)$")
  base = base or method
  local m, w = base:match("^(%a+)/(%d+)$")
  return m or base, tonumber(w) or 0, patch ~= nil
end

-- least-squares slope of v(t)
local function slope(ts, vs)
  local n, st, sv, stt, stv = #ts, 0, 0, 0, 0
  for i = 1, n do
    st, sv = st + ts[i], sv + vs[i]
    stt, stv = stt + ts[i] ^ 2, stv + ts[i] * vs[i]
  end
  return (n * stv - st * sv) / (n * stt - st * st)
end

-- o: k (cells per block side), method, mu, deg (the slope and the block
-- rotated by deg to the grid, gravity down; nil: the slope along the grid
-- and gravity rotated by 30 degrees), shape ("linear"), gap ("touch"),
-- flip, transfer (the sim's defaults), dim (3: the same section extruded
-- two cells along a periodic z; the answers are the 2-D ones), lattice
-- (true: both bodies seeded on a lattice of their own turned with the
-- slope, through the face's corner, so that the faces are straight rows
-- of particles; with deg only), t_end (0.4) and fit_from (0.1): the run's
-- end and the start of the window the acceleration is fitted over.
-- Returns {a (over the reference), spin (largest |omega| after the block
-- settles, t > 0.1), across (largest speed across the surface over the
-- speed along it at the end), rot (|spin integrated|, rad), hop (how far
-- the centre moved off the surface, over L), friction (the friction work
-- over mu m g cos th times the distance slid; g = 1), residual (the
-- energy budget's residual over the work of gravity, m g sin th times the
-- distance), cpu (os.clock seconds)}
-- a convex polygon {{x, y}, ...} cut to the box [lo, hi] in x and y
-- (Sutherland-Hodgman): the tilted flat body's far corners run past the
-- unit square at 45 and 60 degrees; seeding takes only the part inside
-- anyway, so cut it is the same body, and said to be inside
local function clip(poly, lo, hi)
  local function cut(pts, d, c, keep)
    local out = {}
    for i = 1, #pts do
      local a, b = pts[i], pts[i % #pts + 1]
      local ina, inb = keep(a[d], c), keep(b[d], c)
      if ina then out[#out + 1] = a end
      if ina ~= inb then
        local t = (c - a[d]) / (b[d] - a[d])
        out[#out + 1] = {a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])}
        out[#out][d] = c
      end
    end
    return out
  end
  local ge = function(v, c) return v >= c end
  local le = function(v, c) return v <= c end
  for d = 1, 2 do
    poly = cut(poly, d, lo, ge)
    poly = cut(poly, d, hi, le)
  end
  return poly
end

function M.block(o)
  local L, T, t0fit = 0.2, o.t_end or 0.4, o.fit_from or 0.1
  local th = math.rad(o.deg or 30)
  local meth, win, pat = M.opts(o.method)
  local rot0 = o.deg ~= nil
  local S, N = {math.cos(th), -math.sin(th)}, {math.sin(th), math.cos(th)}
  if not rot0 then S, N = {1, 0}, {0, 1} end
  local P = rot0 and {0.05, 0.75} or {0.0, 0.4}
  local function pt(a, b) return {P[1] + a * S[1] + b * N[1], P[2] + a * S[2] + b * N[2]} end
  local d3, h = o.dim == 3, L / o.k
  local function prism(poly)
    return d3 and mvmpm.extrude {polygon = poly, lo = 0, hi = 2 * h} or mvmpm.polygon(poly)
  end
  local g = rot0 and {0, -1} or {math.sin(th), -math.cos(th)}
  local sim = mvmpm.sim {
    dim = o.dim, domain = {x = {0, 1}, y = {0, 1}, z = d3 and {0, 2 * h} or nil}, cell = h, ppc = 2,
    sides = d3 and {left = "free", right = "free", bottom = "free", top = "free",
                    front = "periodic", back = "periodic"} or "free",
    gravity = d3 and {g[1], g[2], 0} or g, shape = o.shape or "linear",
    flip = o.flip, transfer = o.transfer,
    t_end = T, normals = meth, normal_window = win, normal_patch = pat, contact_gap = o.gap, body_contact = o.body_contact,
    contact = {friction = o.mu}}
  local m = mvmpm.elastic {E = 200, nu = 0.3, density = 1}
  local lat = o.lattice and rot0 and {angle = -(o.deg or 30), origin = d3 and {P[1], P[2], 0} or P} or nil
  sim:body {name = "slope", material = m, driven = d3 and {0, 0, 0} or {0, 0}, lattice = lat,
    shape = prism(clip({pt(0, -0.1), pt(0.9, -0.1), pt(0.9, 0), pt(0, 0)}, 0, 1))}
  local b = sim:body {name = "block", material = m, lattice = lat,
    shape = prism {pt(0.1, 0), pt(0.1 + L, 0), pt(0.1 + L, L), pt(0.1, L)}}
  -- the spin about z (a 3-D body's omega is a vector)
  local function wz(d) return d3 and d.omega[3] or d.omega end
  local ts, vs, spin, across, last, rot, t0 = {}, {}, 0, 0, 0, 0, 0
  local d0 = b:diag()
  sim:every {steps = 1, fn = function(s)
    local d = b:diag()
    rot, t0 = rot + wz(d) * (s.t - t0), s.t
    if s.t < t0fit then return end
    ts[#ts + 1], vs[#vs + 1] = s.t, d.vx * S[1] + d.vy * S[2]
    spin = math.max(spin, math.abs(wz(d)))
    across = math.max(across, math.abs(d.vx * N[1] + d.vy * N[2]))
    last = vs[#vs]
  end}
  local c0 = os.clock()
  sim:run()
  local d1 = b:diag()
  local ref = math.sin(th) - o.mu * math.cos(th)
  local e, dist = sim:energy(), (d1.x - d0.x) * S[1] + (d1.y - d0.y) * S[2]
  -- Coulomb: the friction work is mu times the normal force m g cos th
  -- times the distance slid
  local wref = o.mu * b:mass() * math.cos(th) * math.abs(dist)
  return {a = slope(ts, vs) / ref, spin = spin,
          friction = wref > 0 and e.dissipated / wref or 0,
          residual = e.residual / math.max(b:mass() * math.abs(dist) * math.sin(th), 1e-300),
          across = across / math.max(math.abs(last), 1e-30), rot = math.abs(rot),
          hop = math.abs((d1.x - d0.x) * N[1] + (d1.y - d0.y) * N[2]) / L,
          cpu = os.clock() - c0}
end

-- o: cells (across a unit length), method, offset (0: head on),
-- shape ("linear"), gap ("touch"), threads, E (Young's modulus, 1000:
-- Sulsky's; the closing speed over the wave speed falls as 1 / sqrt E,
-- and 100 times E is the same impact 10 times slower).  Returns {kept (relative
-- velocity across the closest approach's line of centres, after over
-- before; 1 head on), spin (largest |omega| of either disc), spin_end,
-- energy (kinetic + strain, after over before), total (sim:energy().total
-- after over before), jt (the impulse on the upper disc across the
-- instantaneous line of centres, summed over the steps, over the impulse
-- along it), orbit (the relative motion's angular momentum, after over
-- before), cpu, a, b (the discs' diag at the end)}
-- Why orbit: frictionless contact pushes along the contact's normal, which
-- for two equal rigid discs is the line of centres at every instant, so
-- the relative motion is a central-force problem: its angular momentum
-- mu r x v_rel is kept exactly.  Deformable discs may tilt their common
-- contact face (the pair's half-turn symmetry allows any tilt), so for
-- them it is kept only as the impact nears the rigid limit (slow against
-- the wave speed: E large).  Measured at touching distance
-- (|r| = 2R) on the way in and on the way out, that is the tangential
-- relative velocity across the line of centres, kept.  "kept" instead
-- takes both velocities across one fixed line (the closest approach's),
-- exact only for a short, elastic impact.
-- The domain for an offset o (the upper disc's centre moved by (o, -o) /
-- sqrt 2): the unit square head on, as Sulsky's; wide enough for the
-- upper disc with a cell to spare otherwise (at o = 0.2 it reaches x =
-- 1.14: on the unit square its side past x = 1 was not seeded, and the
-- glancing cases met a cut disc), a whole number of cells.
function M.discs_domain(offset, cells)
  local o = offset / math.sqrt(2)
  local function hi(need)
    if need <= 1 then return 1 end
    return math.ceil((need + 1 / cells) * cells - 1e-9) / cells
  end
  return {x = {0, hi(1 + o)}, y = {0, hi(1 - o)}}
end

function M.discs(o)
  local off = (o.offset or 0) / math.sqrt(2)
  local meth, win, pat = M.opts(o.method)
  local sim = mvmpm.sim {domain = M.discs_domain(o.offset or 0, o.cells), cell = 1 / o.cells, ppc = 2,
    sides = "free", t_end = o.t_end or 3.0, shape = o.shape or "linear", normals = meth,
    normal_window = win, normal_patch = pat, contact_gap = o.gap, threads = o.threads, body_contact = o.body_contact}
  local m = mvmpm.elastic {E = o.E or 1000, nu = 0.3, density = 1000}
  local a = sim:body {name = "lower", material = m, velocity = {0.1, 0.1},
    shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.2}}
  local b = sim:body {name = "upper", material = m, velocity = {-0.1, -0.1},
    shape = mvmpm.disk {center = {0.8 + off, 0.8 - off}, radius = 0.2}}
  local e0 = sim:energy()
  local a0, b0 = a:diag(), b:diag()
  -- the total momentum is zero, so this is the relative motion's
  local function orbit(p, q)
    return p.mass * (p.x * p.vy - p.y * p.vx) + q.mass * (q.x * q.vy - q.y * q.vx)
  end
  local dmin, nx, ny, spin, jn, jt, pv = math.huge, 0, 0, 0, 0, 0, {b0.vx, b0.vy}
  sim:every {steps = 1, fn = function()
    local da, db = a:diag(), b:diag()
    local dx, dy = db.x - da.x, db.y - da.y
    local d = math.sqrt(dx * dx + dy * dy)
    local ix, iy = db.vx - pv[1], db.vy - pv[2]
    jn, jt = jn + (ix * dx + iy * dy) / d, jt + (-ix * dy + iy * dx) / d
    pv = {db.vx, db.vy}
    if d < dmin then dmin, nx, ny = d, dx / d, dy / d end
    spin = math.max(spin, math.abs(da.omega), math.abs(db.omega))
  end}
  local c0 = os.clock()
  sim:run()
  local cpu = os.clock() - c0
  local a1, b1, e1 = a:diag(), b:diag(), sim:energy()
  local function across(p, q) return (q.vx - p.vx) * -ny + (q.vy - p.vy) * nx end
  return {kept = off ~= 0 and across(a1, b1) / across(a0, b0) or 1, spin = spin,
          spin_end = math.max(math.abs(a1.omega), math.abs(b1.omega)),
          energy = (e1.kinetic + e1.strain) / (e0.kinetic + e0.strain),
          total = e1.total / e0.total, jt = jn ~= 0 and jt / jn or 0, cpu = cpu,
          orbit = off ~= 0 and orbit(a1, b1) / orbit(a0, b0) or 1,
          a = a1, b = b1}
end

return M
