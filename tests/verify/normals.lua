-- Contact normals (sim.normals): each method side by side on two
-- frictionless (and one frictional) contact problems with known answers,
-- at three resolutions.
--   Block on a flat body: a block sliding down a flat driven body tilted
--   theta = 30 degrees accelerates at g (sin theta - mu cos theta), neither
--   spins (tips) nor moves off the slope.  Two geometries: the flat body
--   along the grid with gravity rotated by theta ("aligned"), and the flat
--   body and the block themselves rotated by theta ("rotated").
--   Glancing discs: two elastic discs meet off the line of centres; a
--   frictionless contact pushes only along the line of centres, so their
--   relative velocity across it is kept and neither disc is spun.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local methods = {"mass", "volume", "maxvolume", "plane"}
-- the block and its slope have one density, so their volume gradients
-- are their mass gradients scaled, but for the particles' small volume
-- changes: "volume" is left out of the block's runs (measured: within
-- 0.5 % of "mass" in every figure)
local solid = {"mass", "maxvolume", "plane"}
local TH = math.rad(30)

-- least-squares slope of v(t)
local function slope(ts, vs)
  local n, st, sv, stt, stv = #ts, 0, 0, 0, 0
  for i = 1, n do
    st, sv = st + ts[i], sv + vs[i]
    stt, stv = stt + ts[i] ^ 2, stv + ts[i] * vs[i]
  end
  return (n * stv - st * sv) / (n * stt - st * st)
end

-- the block (side L = 0.2, k cells across it) on the slope; returns the
-- acceleration along the slope over the ratio expected, the largest spin
-- (rad per time) and the largest speed across the slope over the speed
-- along it at the end, both after the block has settled (t > 0.1)
local function block(k, method, mu, rotated)
  local L, T = 0.2, 0.4
  local th = rotated and TH or 0
  local S, N = {math.cos(th), -math.sin(th)}, {math.sin(th), math.cos(th)}
  local P = rotated and {0.05, 0.7} or {0.0, 0.4}
  local function pt(a, b) return {P[1] + a * S[1] + b * N[1], P[2] + a * S[2] + b * N[2]} end
  local sim = mvmpm.sim {
    domain = {x = {0, 1}, y = {0, 1}}, cell = L / k, ppc = 2, sides = "free",
    gravity = rotated and {0, -1} or {math.sin(TH), -math.cos(TH)},
    t_end = T, normals = method, contact = {friction = mu}}
  local m = mvmpm.elastic {E = 200, nu = 0.3, density = 1}
  sim:body {name = "slope", material = m, driven = {0, 0},
    shape = mvmpm.polygon {pt(0, -0.1), pt(0.9, -0.1), pt(0.9, 0), pt(0, 0)}}
  local b = sim:body {name = "block", material = m,
    shape = mvmpm.polygon {pt(0.1, 0), pt(0.1 + L, 0), pt(0.1 + L, L), pt(0.1, L)}}
  -- the slope's frame: along S, across N
  local s0, n0 = S, N
  if not rotated then s0, n0 = {1, 0}, {0, 1} end
  local ts, vs, spin, across, last = {}, {}, 0, 0, 0
  sim:every {steps = 1, fn = function(s)
    if s.t < 0.1 then return end
    local d = b:diag()
    ts[#ts + 1], vs[#vs + 1] = s.t, d.vx * s0[1] + d.vy * s0[2]
    spin = math.max(spin, math.abs(d.omega))
    across = math.max(across, math.abs(d.vx * n0[1] + d.vy * n0[2]))
    last = vs[#vs]
  end}
  sim:run()
  local ref = math.sin(TH) - mu * math.cos(TH)
  return slope(ts, vs) / ref, spin, across / math.max(math.abs(last), 1e-30)
end

-- two discs of radius 0.2 meeting at relative speed 0.28 with their
-- centres' line offset 0.2 across the approach; returns the relative
-- velocity across the line of centres (taken at closest approach) after
-- over before, the largest spin (rad per time; the discs' relative
-- angular momentum about the contact is zero before) and the total
-- energy (kinetic + strain) after over before
local function discs(cells, method)
  local o = 0.2 / math.sqrt(2)
  local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / cells,
    ppc = 2, sides = "free", t_end = 3.0, normals = method}
  local m = mvmpm.elastic {E = 1000, nu = 0.3, density = 1000}
  local a = sim:body {name = "lower", material = m, velocity = {0.1, 0.1},
    shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.2}}
  local b = sim:body {name = "upper", material = m, velocity = {-0.1, -0.1},
    shape = mvmpm.disk {center = {0.8 + o, 0.8 - o}, radius = 0.2}}
  local dmin, nx, ny, spin = math.huge, 0, 0, 0
  local e0 = sim:energy()
  local a0, b0 = a:diag(), b:diag()
  sim:every {steps = 1, fn = function()
    local da, db = a:diag(), b:diag()
    local dx, dy = db.x - da.x, db.y - da.y
    local d = math.sqrt(dx * dx + dy * dy)
    if d < dmin then dmin, nx, ny = d, dx / d, dy / d end
    spin = math.max(spin, math.abs(da.omega), math.abs(db.omega))
  end}
  sim:run()
  local a1, b1, e1 = a:diag(), b:diag(), sim:energy()
  local function across(p, q) return (q.vx - p.vx) * -ny + (q.vy - p.vy) * nx end
  return across(a1, b1) / across(a0, b0), spin,
         (e1.kinetic + e1.strain) / (e0.kinetic + e0.strain)
end

-- error at each resolution and the observed order between the last two
local function row(name, res, errs)
  local t = {}
  for i, e in ipairs(errs) do t[#t + 1] = string.format("%s %.4f", res[i], e) end
  local p = (errs[2] > 0 and errs[3] > 0) and math.log(errs[2] / errs[3], 2) or 0 / 0
  print(string.format("     %-34s %s   order %.2f", name, table.concat(t, "  "), p))
end

local K = {4, 8, 16}          -- cells per block side
local CELLS = {20, 40, 80}    -- cells across the unit square (4, 8, 16 per disc radius)

-- every method at every resolution: r[method][i] = {values...}
local function sweep(res, fn, only)
  local r = {}
  for _, m in ipairs(only or methods) do
    r[m] = {}
    for i, k in ipairs(res) do r[m][i] = {fn(k, m)} end
  end
  return r
end

local function col(r, m, j, f)
  local t = {}
  for i = 1, #r[m] do t[i] = f and f(r[m][i][j]) or r[m][i][j] end
  return t
end

local function err(x) return math.abs(x - 1) end

-- each of r[m]'s column j at every resolution no worse (by f) than mass's
local function no_worse(r, m, j, f)
  local ok = true
  for i = 1, #r[m] do ok = ok and f(r[m][i][j]) <= f(r.mass[i][j]) end
  return ok
end

for _, mu in ipairs {0, 0.2} do
  V.case(string.format("block on a grid-aligned flat body, gravity rotated 30 degrees, mu = %g", mu))
  local r = sweep(K, function(k, m) return block(k, m, mu, false) end, solid)
  print("     |a / (g (sin - mu cos)) - 1|, cells per block side 4 8 16:")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 1, err)) end
  print("     largest spin (rad/time):")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 2)) end
  print("     largest speed across the slope / speed along it:")
  for _, m in ipairs(solid) do row(m, K, col(r, m, 3)) end
  local mv = r.maxvolume
  V.holds("maxvolume: acceleration error below mass's at 4, 8, 16",
          no_worse(r, "maxvolume", 1, err), err(mv[2][1]))
  V.holds("maxvolume: spin below mass's at 4, 8, 16",
          no_worse(r, "maxvolume", 2, function(x) return x end), mv[3][2])
  V.below("maxvolume: speed across the slope at 16 cells", mv[3][3], r.mass[3][3],
          "(limit: mass's)")
  if mu == 0 then
    V.below("maxvolume: frictionless acceleration error at 8 cells", err(mv[2][1]), 0.03)
    V.below("maxvolume: spin at 16 cells below that at 4", mv[3][2], mv[1][2])
  else
    V.info("maxvolume: acceleration error at 8 cells (3 % wanted)", err(mv[2][1]))
  end
end

-- Known gap, reported not asserted: with the flat body and the block
-- rotated 30 degrees to the grid no method lets the block slide (a / g
-- sin theta near 0 with each): the stair-stepped surfaces' normals at the
-- block's leading corner and along the steps hold it.  Given the exact
-- slope normal at every shared node instead, the same scene slides at
-- a / (g sin theta) = 1.0000 (4 and 8 cells): the normals alone are at
-- fault here.
-- (With friction mu = 0.2 no method slides either: a / (g (sin - mu
-- cos)) between -0.14 and 0.01; left out for time.)
do
  local mu = 0
  V.case("block on a flat body rotated 30 degrees to the grid, mu = 0 (reported)")
  local mm = solid
  local r = sweep(K, function(k, m) return block(k, m, mu, true) end, mm)
  print("     |a / (g (sin - mu cos)) - 1|, cells per block side 4 8 16:")
  for _, m in ipairs(mm) do row(m, K, col(r, m, 1, err)) end
  print("     largest spin (rad/time):")
  for _, m in ipairs(mm) do row(m, K, col(r, m, 2)) end
  for _, m in ipairs(mm) do
    V.info(m .. ": a / (g (sin - mu cos)) at 8 cells", r[m][2][1])
  end
end

V.case "glancing frictionless discs (offset 0.2, one radius)"
local r = sweep(CELLS, discs)
print("     1 - kept relative velocity across the line of centres, cells 20 40 80:")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 1, err)) end
print("     largest spin (rad/time; none wanted):")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 2)) end
print("     1 - total energy kept (kinetic + strain):")
for _, m in ipairs(methods) do row(m, CELLS, col(r, m, 3, err)) end
-- Known gap: no method keeps the tangential velocity within 2 % (best,
-- "plane", loses 10-12 %), and none converges from 40 to 80 cells.  With the exact
-- line-of-centres normal at every node it keeps 94-95 %: half the loss
-- is the normals', the rest the contact rule's.
V.holds("volume: keeps at least mass's tangential velocity at 20, 40, 80",
        no_worse(r, "volume", 1, err), r.volume[2][1])
V.holds("volume: spins the discs no more than mass at 20, 40, 80",
        no_worse(r, "volume", 2, function(x) return x end), r.volume[2][2])
V.holds("plane: keeps at least mass's tangential velocity at 20, 40, 80",
        no_worse(r, "plane", 1, err), r.plane[2][1])
V.holds("plane: spins the discs no more than mass at 20, 40, 80",
        no_worse(r, "plane", 2, function(x) return x end), r.plane[2][2])
V.holds("plane: keeps at least mass's energy at 20, 40, 80",
        no_worse(r, "plane", 3, err), r.plane[2][3])
for _, m in ipairs(methods) do
  V.info(m .. ": tangential velocity kept at 40 cells (0.98 wanted)", r[m][2][1])
end

V.case "the new normals give the same numbers at any thread count"
for _, meth in ipairs {"volume", "maxvolume", "plane"} do
  local out = {}
  for _, th in ipairs {1, 2} do
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 60, ppc = 2,
      sides = "free", t_end = 1.8, normals = meth, threads = th}
    local m = mvmpm.elastic {E = 1000, nu = 0.3, density = 1000}
    local o = 0.2 / math.sqrt(2)
    local a = sim:body {material = m, velocity = {0.1, 0.1},
      shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.2}}
    sim:body {material = m, velocity = {-0.1, -0.1},
      shape = mvmpm.disk {center = {0.8 + o, 0.8 - o}, radius = 0.2}}
    sim:run()
    local d = a:diag()
    out[th] = string.format("%.17g %.17g %.17g", d.x, d.vy, d.omega)
  end
  V.holds(meth .. ": 1 and 2 threads, the same bits", out[1] == out[2], 0)
end

V.case "a normals setting not known is refused, naming the choices"
do
  local ok, msg = pcall(mvmpm.sim, {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1,
                                    normals = "volumes"})
  V.holds("normals = \"volumes\": an error naming mass, volume, maxvolume, plane",
          not ok and tostring(msg):find("mass, volume, maxvolume, plane", 1, true) ~= nil, 0,
          tostring(msg))
end
