-- mvmpm.spheres3: two elastic spheres colliding in 3-D, each on its own
-- velocity field (frictionless multi-field contact).  Two unit-diameter
-- spheres (K = 1, G = 0.5, density 1) close at 0.2 along x with 0.2
-- between their surfaces, free sides; `off` shifts the second along y
-- (0.5: the line of centres at touching 30 degrees from x).  Used by
-- tests/verify/d3_spheres.lua and studies/d3_spheres.lua.
local mvmpm = require "mvmpm"
local M = {}

local function norm3(w) return math.sqrt(w[1]^2 + w[2]^2 + w[3]^2) end

-- run(cells, off, t_end, o): o may give shape, transfer, update, cfl,
-- normals, normal_window, contact_gap, and shift (the grid moved along x
-- by that fraction of a cell).  Returns {energy (E(t_end)/E0 - 1), dp
-- (the largest departure of each momentum component over all steps, over
-- the momentum of one sphere), gaps (the nearest-particle gap in a slab
-- about the mid-plane at t = 1 .. t_end), overlap (the largest count of
-- particles inside the other body, sim:overlap, at those times), spin
-- (|omega| R / |v|, the larger of the two), vrel, vn (the relative
-- velocity along the line of centres, > 0 separating), cpu}
function M.run(cells, off, t_end, o)
  o = o or {}
  local c0 = os.clock()
  local sh = (o.shift or 0) / cells
  local lo = sh ~= 0 and -sh or 0
  local sim = mvmpm.sim {dim = 3, domain = {x = {lo, 3 + lo}, y = {0, 1.5 + off}, z = {0, 1.5}},
    cell = 1 / cells, ppc = 2, sides = "free", shape = o.shape, transfer = o.transfer,
    update = o.update, normals = o.normals, normal_window = o.normal_window, normal_patch = o.normal_patch,
    contact_gap = o.contact_gap, cfl = o.cfl}
  local m = mvmpm.elastic {K = 1, G = 0.5, density = 1}
  local a = sim:body {name = "a", material = m, velocity = {0.1, 0, 0},
                      shape = mvmpm.ball {center = {0.9, 0.75, 0.75}, radius = 0.5}}
  local b = sim:body {name = "b", material = m, velocity = {-0.1, 0, 0},
                      shape = mvmpm.ball {center = {2.1, 0.75 + off, 0.75}, radius = 0.5}}
  -- the nearest pair of particles of a and b, among those in a slab
  -- about the plane halfway between the centres, normal to their line
  local function gap()
    local x, body = sim:particles("position"), sim:particles("body")
    local da, db = a:diag(), b:diag()
    local n = {db.x - da.x, db.y - da.y, db.z - da.z}
    local dist = norm3(n)
    local mid = {0.5 * (da.x + db.x), 0.5 * (da.y + db.y), 0.5 * (da.z + db.z)}
    local A, B = {}, {}
    for i = 1, #body do
      local s = ((x.x[i] - mid[1]) * n[1] + (x.y[i] - mid[2]) * n[2] + (x.z[i] - mid[3]) * n[3]) / dist
      if math.abs(s) < 0.2 then
        if body[i] == 1 then A[#A + 1] = i else B[#B + 1] = i end
      end
    end
    local d2 = math.huge
    for _, i in ipairs(A) do
      for _, j in ipairs(B) do
        d2 = math.min(d2, (x.x[i] - x.x[j])^2 + (x.y[i] - x.y[j])^2 + (x.z[i] - x.z[j])^2)
      end
    end
    return d2 < math.huge and math.sqrt(d2) or 0.4
  end
  local e0 = sim:energy()
  local p0, dp = {e0.px, e0.py, e0.pz}, {0, 0, 0}
  sim:every {steps = 1, fn = function(s)
    local e = s:energy()
    local p = {e.px, e.py, e.pz}
    for d = 1, 3 do dp[d] = math.max(dp[d], math.abs(p[d] - p0[d])) end
  end}
  local r = {gaps = {}, overlap = 0}
  for t = 1, t_end do
    sim:run(t)
    r.overlap = math.max(r.overlap, (sim:overlap()))
    r.gaps[t] = gap()
  end
  r.energy = sim:energy().total / e0.total - 1
  local da, db = a:diag(), b:diag()
  local pa = a:mass() * 0.1
  r.dp = {dp[1] / pa, dp[2] / pa, dp[3] / pa}
  r.spin = math.max(norm3(da.omega), norm3(db.omega)) * 0.5 / 0.1
  r.vrel = {db.vx - da.vx, db.vy - da.vy, db.vz - da.vz}
  -- the relative velocity along the line of centres (> 0: separating)
  local n = {db.x - da.x, db.y - da.y, db.z - da.z}
  r.vn = (r.vrel[1] * n[1] + r.vrel[2] * n[2] + r.vrel[3] * n[3]) / norm3(n)
  r.cpu = os.clock() - c0
  return r
end

return M
