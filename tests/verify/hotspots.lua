-- Hot-spot diagnostics on imposed temperature fields with known answers,
-- and the Frank-Kamenetskii critical curve against its formula.
-- The regions' areas are compared with the seeded particles counted here
-- (lattice points inside each disc times the particle area), which the
-- seeding rule fixes independently of the search.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local H = require "mvmpm.hotspot"
local K = require "mvmpm.kinetics"

local cell, ppc = 0.05, 2
local sp = cell / ppc          -- particle spacing
local pa = sp * sp             -- particle area

-- seeding points inside a disc (lattice of spacing sp, centred in cells)
local function count_in(cx, cy, r, taken)
  local n = 0
  for i = 0, math.floor(1 / sp) - 1 do
    for j = 0, math.floor(1 / sp) - 1 do
      local x, y = (i + 0.5) * sp, (j + 0.5) * sp
      local key = i * 100000 + j
      if (x - cx) ^ 2 + (y - cy) ^ 2 <= r * r and not taken[key] then
        taken[key] = true
        n = n + 1
      end
    end
  end
  return n
end

-- two hot discs (900) in a cold matrix (300)
local function scene(c1, c2, r)
  local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = cell, ppc = ppc,
                         shape = "gimp", update = "usavg"}
  local mat = mvmpm.elastic {K = 1e3, G = 5e2, density = 1}
  sim:body {name = "hot1", shape = mvmpm.disk {center = c1, radius = r}, material = mat,
            temperature = 900}
  sim:body {name = "hot2", shape = mvmpm.disk {center = c2, radius = r}, material = mat,
            temperature = 900}
  sim:body {name = "matrix", shape = mvmpm.rest(), material = mat, temperature = 300}
  return sim
end

V.case "two separate hot discs: 2 regions, their areas"
do
  local r = 0.1
  local sim = scene({0.3, 0.5}, {0.7, 0.5}, r)
  local taken = {}
  local n1 = count_in(0.3, 0.5, r, taken)
  local n2 = count_in(0.7, 0.5, r, taken)
  local hs = sim:hotspots {threshold = 600}
  V.near("regions", #hs, 2, 0)
  V.near("count field", hs.count, 2, 0)
  V.near("area of region 1 (seeded points x particle area)", hs[1].area, n1 * pa, 1e-12)
  V.near("area of region 2", hs[2].area, n2 * pa, 1e-12)
  V.near("area of region 1 against pi r^2, within a particle's area x perimeter/spacing",
         hs[1].area, math.pi * r * r, 2 * math.pi * r / sp * pa)
  V.near("peak temperature", hs[1].T_max, 900, 0)
  V.near("mean temperature", hs[1].T_mean, 900, 1e-9)
  local xs = {hs[1].x, hs[2].x}
  table.sort(xs)
  V.near("centroid x of the left disc", xs[1], 0.3, 1e-9)
  V.near("centroid x of the right disc", xs[2], 0.7, 1e-9)
  V.near("area fraction", hs.area_fraction, (n1 + n2) * pa / 1.0, 1e-12)
  V.near("reacted fraction without reaction", hs[1].reacted, 0, 0)
end

V.case "touching hot discs: 1 region"
do
  local r = 0.1
  local sim = scene({0.4, 0.5}, {0.6, 0.5}, r)
  local taken = {}
  local n = count_in(0.4, 0.5, r, taken) + count_in(0.6, 0.5, r, taken)
  local hs = sim:hotspots {threshold = 600}
  V.near("regions", #hs, 1, 0)
  V.near("its area", hs[1].area, n * pa, 1e-12)
  -- discs one particle gap apart (a column of cold particles) stay apart
  local sim2 = scene({0.3875, 0.5}, {0.6125, 0.5}, 0.1)
  V.near("rims one spacing apart (cold particles between): regions", #sim2:hotspots {threshold = 600}, 2, 0)
end

V.case "threshold above the peak: no region"
do
  local sim = scene({0.3, 0.5}, {0.7, 0.5}, 0.1)
  local hs = sim:hotspots {threshold = 901}
  V.near("regions", #hs, 0, 0)
  V.near("area fraction", hs.area_fraction, 0, 0)
  local ok, err = pcall(sim.hotspots, sim, {threshold = 600, link = -1})
  local ok2, err2 = pcall(sim.hotspots, sim, 600)
  V.holds("a number instead of the table is refused, saying what to give",
          not ok2 and tostring(err2):find("threshold = T") ~= nil, 0, tostring(err2))
  V.holds("link <= 0 is refused, naming the field", not ok and
          tostring(err):find("link") ~= nil, 0, tostring(err))
end

V.case "Frank-Kamenetskii critical curve (disc, delta_c = 2) against the formula"
do
  local kin, rho, k = K.hmx, K.pbx9501.density, K.pbx9501.k
  for _, T in ipairs {600, 800, 1000} do
    local rc = H.critical_radius(kin, rho, k, T)
    -- the formula written out here
    local delta = kin.Q * rho * kin.Z * kin.Ta * rc ^ 2 * math.exp(-kin.Ta / T) / (k * T ^ 2)
    V.near(string.format("T = %d K: delta at the critical radius (%.3g m)", T, rc),
           delta, 2, 1e-12, true)
    V.near(string.format("T = %d K: critical T of that radius", T),
           H.critical_T(kin, rho, k, rc), T, 1e-9, true)
  end
  local path = os.tmpname() .. ".png"
  local sim = scene({0.3, 0.5}, {0.7, 0.5}, 0.1)
  local n = H.plot {file = path, spots = sim:hotspots {threshold = 600}, kinetics = kin,
                    density = rho, conductivity = k}
  local f = io.open(path, "rb")
  local sig = f and f:read(8) or ""
  if f then f:close() end
  os.remove(path)
  V.holds("the size-temperature plot is a PNG with both spots", sig == "\137PNG\r\n\26\n" and n == 2, n)
end

V.case "bad reaction input: clear errors naming the field"
do
  local function err(t)
    local ok, e = pcall(mvmpm.elastic, t)
    return not ok and tostring(e) or ""
  end
  local base = {K = 1, G = 0.5, density = 1, cv = 1}
  local function with(r, extra)
    local t = {}
    for k, v in pairs(base) do t[k] = v end
    for k, v in pairs(extra or {}) do t[k] = v end
    t.reaction = r
    return t
  end
  V.holds("Z <= 0", err(with {Z = 0, Ta = 1e4, Q = 1}):find("'Z'") ~= nil, 0,
          err(with {Z = 0, Ta = 1e4, Q = 1}))
  V.holds("both Ta and Ea", err(with {Z = 1, Ta = 1e4, Ea = 1e5, Q = 1}):find("not both") ~= nil, 0)
  V.holds("order 4", err(with {Z = 1, Ta = 1e4, Q = 1, order = 4}):find("'order'") ~= nil, 0,
          err(with {Z = 1, Ta = 1e4, Q = 1, order = 4}))
  V.holds("a misspelt key", err(with {Z = 1, Ta = 1e4, Qq = 1}):find("Qq") ~= nil, 0,
          err(with {Z = 1, Ta = 1e4, Qq = 1}))
  local t = with {Z = 1, Ta = 1e4, Q = 1}
  t.cv = nil
  V.holds("no cv", err(t):find("cv > 0") ~= nil, 0, err(t))
end
