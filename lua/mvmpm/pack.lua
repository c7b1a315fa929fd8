-- mvmpm.pack: seeded beds of discs for PBX-like grain models.
--
--   local pack = require "mvmpm.pack"
--   local bed = pack.bed {width = 1.2e-3, height = 1.2e-3, packing = 0.75,
--                         coarse = {mean = 150e-6, spread = 0.25},
--                         fine = {mean = 30e-6, spread = 0.35},
--                         min_diameter = 16e-6, gap = 2e-6, seed = 7}
--   for _, g in ipairs(bed.grains) do ... g.x, g.y, g.r, g.class ... end
--   print(pack.summary(bed)); pack.write_csv(bed, "out/bed")
--
-- The rectangle [x0, x0 + width] x [y0, y0 + height] is periodic in y
-- (a disc across the seam continues on the other side) and walled in x
-- (every disc lies inside).  Grain diameters are drawn from two
-- log-normal classes, coarse and fine, in the requested coarse : fine
-- mass ratio; a drawn grain smaller than min_diameter is not placed but
-- folded into the binder ("dirty binder"), its mass reported.  Drawing
-- stops when the placed discs cover `packing` of the area.
--
-- Placement: random sequential addition of discs of this polydispersity
-- jams near 0.55 (monodisperse discs: 0.547), far below the 0.7-0.8 of
-- a PBX, so the discs are first placed at a reduced size where random
-- addition is easy, then grown to full size in stages, each followed by
-- sweeps of overlap relaxation that push apart every pair closer than
-- the sum of radii plus `gap` (the lighter disc moving more).  Bimodal
-- beds with fines relax to about 0.8 with a one-cell gap; the error
-- message says where growth stalled when a target is out of reach.
--
-- Everything random comes from the generator below (splitmix64), never
-- from math.random, whose algorithm is not part of Lua's definition:
-- one seed gives one bed, bit for bit, on a given machine and libm.
local M = {}

local pi, sqrt, log, exp, cos, floor, max, min, abs =
  math.pi, math.sqrt, math.log, math.exp, math.cos, math.floor,
  math.max, math.min, math.abs

---------------------------------------------------------------- the RNG

-- splitmix64 (Steele, Lea and Flood, 2014): a 64-bit counter scrambled
-- by two multiply-xorshift rounds.  Lua 5.4 integers wrap modulo 2^64
-- and '>>' is a logical shift, which is what the algorithm needs.
local function rng(seed)
  local s = seed
  local r = {}
  function r.u64()
    s = s + 0x9e3779b97f4a7c15
    local z = s
    z = (z ~ (z >> 30)) * 0xbf58476d1ce4e5b9
    z = (z ~ (z >> 27)) * 0x94d049bb133111eb
    return z ~ (z >> 31)
  end
  -- uniform in [0, 1): the top 53 bits
  function r.uniform() return (r.u64() >> 11) * 0x1p-53 end
  -- standard normal (Box-Muller; the sine half is dropped so that one
  -- draw always takes two uniforms, which keeps the stream simple)
  function r.normal()
    local u1 = 1 - r.uniform()   -- (0, 1]: log(u1) is finite
    local u2 = r.uniform()
    return sqrt(-2 * log(u1)) * cos(2 * pi * u2)
  end
  return r
end
M.rng = rng

------------------------------------------------------ checking the input

local DEFAULTS = {
  x0 = 0, y0 = 0, width = 1.2e-3, height = 1.2e-3,
  packing = 0.75,
  coarse = {mean = 150e-6, spread = 0.25},
  fine = {mean = 30e-6, spread = 0.35},
  mass_ratio = 3,
  min_diameter = 16e-6,
  gap = 2e-6,
  attach = nil,          -- default: gap
  density = 1900, binder_density = 1280,
  seed = 1,
  bins = 12,             -- histogram bins
}

-- the caller's position is added by error(msg, level): a scene's
-- mistake is reported at the scene's line
local function bad(level, fmt, ...)
  error("pack.bed: " .. string.format(fmt, ...), level + 1)
end

local function number(spec, key, lo, hi, level, open_lo)
  local v = spec[key]
  if v == nil then v = DEFAULTS[key] end
  if type(v) ~= "number" or v ~= v then
    bad(level + 1, "field '%s' must be a number (got %s)", key, tostring(v))
  end
  if (open_lo and v <= lo) or v < lo or v > hi then
    bad(level + 1, "field '%s' must be in %s%g, %g] (got %g)", key,
        open_lo and "(" or "[", lo, hi, v)
  end
  return v
end

local function class(spec, key, level)
  local c = spec[key] or DEFAULTS[key]
  if type(c) ~= "table" then
    bad(level + 1, "field '%s' must be a table {mean = d, spread = s}", key)
  end
  for k in pairs(c) do
    if k ~= "mean" and k ~= "spread" then
      bad(level + 1, "field '%s': unknown key '%s' (keys: mean, spread)", key, tostring(k))
    end
  end
  local m, s = c.mean, c.spread or 0
  if type(m) ~= "number" or not (m > 0) or m == math.huge then
    bad(level + 1, "field '%s.mean' must be a diameter > 0 (got %s)", key, tostring(m))
  end
  if type(s) ~= "number" or not (s >= 0 and s <= 1) then
    bad(level + 1, "field '%s.spread' must be in [0, 1] (got %s)", key, tostring(s))
  end
  return {mean = m, spread = s}
end

local KEYS = {}
for k in pairs(DEFAULTS) do KEYS[k] = true end
-- 3-D only (see the 3-D part below)
local KEYS3 = {z0 = true, depth = true, hmx_mass = true}
KEYS.dim = true
for k in pairs(KEYS3) do KEYS[k] = true end

local function check(spec, level)
  if type(spec) ~= "table" then bad(level + 1, "expects a table of fields") end
  for k in pairs(spec) do
    if not KEYS[k] then
      local names = {}
      for n in pairs(KEYS) do names[#names + 1] = n end
      table.sort(names)
      bad(level + 1, "unknown field '%s' (fields: %s)", tostring(k), table.concat(names, ", "))
    end
  end
  local p = {}
  p.dim = spec.dim or require("mvmpm").dim
  if p.dim ~= 2 and p.dim ~= 3 then
    bad(level + 1, "field 'dim' must be 2 or 3 (got %s)", tostring(spec.dim))
  end
  if p.dim == 2 then
    for k in pairs(KEYS3) do
      if spec[k] ~= nil then bad(level + 1, "field '%s' is for 3-D beds only (dim = 3)", k) end
    end
  end
  p.x0 = number(spec, "x0", -math.huge, math.huge, level + 1)
  p.y0 = number(spec, "y0", -math.huge, math.huge, level + 1)
  p.width = number(spec, "width", 0, math.huge, level + 1, true)
  p.height = number(spec, "height", 0, math.huge, level + 1, true)
  if p.dim == 3 then
    p.z0 = spec.z0 == nil and 0 or number(spec, "z0", -math.huge, math.huge, level + 1)
    p.depth = spec.depth == nil and p.width or number(spec, "depth", 0, math.huge, level + 1, true)
    if spec.hmx_mass ~= nil then
      p.hmx_mass = number(spec, "hmx_mass", 0, 1, level + 1, true)
      if p.hmx_mass >= 1 then bad(level + 1, "field 'hmx_mass' must be in (0, 1) (got %g)", p.hmx_mass) end
    end
  end
  p.packing = number(spec, "packing", 0, 0.9, level + 1, true)
  p.coarse = class(spec, "coarse", level + 1)
  p.fine = class(spec, "fine", level + 1)
  p.mass_ratio = number(spec, "mass_ratio", 0, 1e6, level + 1)
  p.min_diameter = number(spec, "min_diameter", 0, math.huge, level + 1)
  p.gap = number(spec, "gap", 0, math.huge, level + 1)
  p.attach = spec.attach == nil and p.gap or number(spec, "attach", 0, math.huge, level + 1)
  p.density = number(spec, "density", 0, math.huge, level + 1, true)
  p.binder_density = number(spec, "binder_density", 0, math.huge, level + 1, true)
  p.bins = number(spec, "bins", 4, 64, level + 1)
  if p.bins ~= floor(p.bins) then bad(level + 1, "field 'bins' must be an integer (got %g)", p.bins) end
  local seed = spec.seed == nil and DEFAULTS.seed or spec.seed
  if math.type(seed) ~= "integer" then
    if type(seed) == "number" and seed == floor(seed) and abs(seed) < 2^53 then
      seed = floor(seed)
    else
      bad(level + 1, "field 'seed' must be an integer (got %s)", tostring(seed))
    end
  end
  p.seed = math.tointeger(seed)
  -- the largest grain a class can draw (log-normal cut at 3 sigma) must
  -- fit in the rectangle with room to move
  for _, key in ipairs {"coarse", "fine"} do
    local c = p[key]
    local dmax = c.mean * exp(3 * c.spread)
    local short = min(p.width, p.height, p.depth or math.huge)
    if dmax + 2 * p.gap > 0.5 * short then
      bad(level + 1, "%s grains (mean %g, spread %g) reach %g, too large for a %s "
          .. "(the largest must be under half the shortest side)",
          key, c.mean, c.spread, dmax,
          p.dim == 3 and string.format("%g x %g x %g box", p.width, p.height, p.depth)
                      or string.format("%g x %g rectangle", p.width, p.height))
    end
  end
  if p.mass_ratio == 0 and p.packing > 0 and p.coarse.mean < p.min_diameter then
    bad(level + 1, "every grain would be folded: coarse mean %g < min_diameter %g",
        p.coarse.mean, p.min_diameter)
  end
  local fine_big = p.fine.mean * exp(3 * p.fine.spread)
  local coarse_big = p.coarse.mean * exp(3 * p.coarse.spread)
  if max(fine_big, coarse_big) < p.min_diameter then
    bad(level + 1, "min_diameter %g is above every grain that can be drawn: nothing to place",
        p.min_diameter)
  end
  return p
end

------------------------------------------------------------- the sizes

-- a diameter of a class: log-normal with arithmetic mean c.mean and
-- standard deviation c.spread of ln d, cut at 3 standard deviations
local function draw(r, c)
  if c.spread == 0 then return c.mean end
  local mu = log(c.mean) - 0.5 * c.spread * c.spread
  while true do
    local z = r.normal()
    if abs(z) <= 3 then return exp(mu + c.spread * z) end
  end
end

-- Draw grains until the placed ones cover the target area.  A coarse
-- grain is drawn while coarse mass < ratio x fine mass (folded fines
-- count), else a fine one, so the ratio holds to within one grain all
-- along.  Areas (in 3-D volumes: measure(d) of a grain of diameter d,
-- the box's depth given) stand for masses: both classes are HMX.
local function disc_area(d) return 0.25 * pi * d * d end
local function sizes(p, r, depth, measure)
  local target = p.packing * p.width * p.height
  if depth then target = target * depth end
  measure = measure or disc_area
  local grains, folded = {}, {coarse = {n = 0, area = 0}, fine = {n = 0, area = 0}, list = {}}
  local area = {coarse = 0, fine = 0}
  local placed = 0
  while placed < target do
    local key
    if p.mass_ratio == 0 then key = "fine"
    elseif area.fine == 0 and area.coarse == 0 then key = "coarse"
    else key = area.coarse < p.mass_ratio * area.fine and "coarse" or "fine" end
    local d = draw(r, p[key])
    local a = measure(d)
    -- the last grain: only if the packing comes nearer the target with it
    if d >= p.min_diameter and placed + a > target and placed + a - target > target - placed then
      break
    end
    area[key] = area[key] + a
    if d < p.min_diameter then
      folded[key].n = folded[key].n + 1
      folded[key].area = folded[key].area + a
      folded.list[#folded.list + 1] = {d = d, class = key, folded = true}
    else
      grains[#grains + 1] = {r = 0.5 * d, class = key}
      placed = placed + a
    end
  end
  return grains, folded, area
end

----------------------------------------------------------- the placement

-- bins over the rectangle; a disc is listed in every bin its box
-- (radius at its current scale + reach) touches, across the seam in y
local function binner(p, size)
  local b = {}
  b.nx = max(1, floor(p.width / size))
  b.ny = max(1, floor(p.height / size))
  b.sx, b.sy = p.width / b.nx, p.height / b.ny
  function b.build(g, reach)
    local cells = {}
    for i = 1, #g do
      local d = g[i]
      local rr = d.s * d.r + reach
      local i0 = max(0, floor((d.x - rr - p.x0) / b.sx))
      local i1 = min(b.nx - 1, floor((d.x + rr - p.x0) / b.sx))
      local j0 = floor((d.y - rr - p.y0) / b.sy)
      local j1 = floor((d.y + rr - p.y0) / b.sy)
      if j1 - j0 >= b.ny then j1 = j0 + b.ny - 1 end
      for j = j0, j1 do
        local row = (j % b.ny) * b.nx
        for ii = i0, i1 do
          local k = row + ii + 1
          local c = cells[k]
          if not c then c = {}; cells[k] = c end
          c[#c + 1] = i
        end
      end
      d.i0, d.i1, d.j0, d.j1 = i0, i1, j0, j1
    end
    return cells
  end
  return b
end

-- the y separation of two centres by the nearest periodic image
local function dy_min(dy, h)
  return dy - h * floor(dy / h + 0.5)
end

-- keep a disc inside the x walls and its centre in [y0, y0 + h)
local function confine(p, d)
  -- (a hair inside, so that rounding never puts a disc through a wall)
  local lo = p.x0 + d.s * d.r + 1e-12 * p.width
  local hi = p.x0 + p.width - d.s * d.r - 1e-12 * p.width
  if d.x < lo then d.x = lo elseif d.x > hi then d.x = hi end
  d.y = p.y0 + (d.y - p.y0) % p.height
end

-- One Gauss-Seidel sweep: every pair closer than s_i r_i + s_j r_j + gap
-- is pushed apart along the line of centres, each disc taking half the
-- push (a fixed disc, none).  Returns the number of such pairs.
local function sweep(p, g, b, gap, stamp, pass)
  local cells = b.build(g, 0.5 * gap)
  b.cells, b.list = cells, g
  local n = 0
  local h = p.height
  -- pushing a pair exactly to contact leaves its neighbours' pushes to
  -- undo it by a little, sweep after sweep; over-pushing by one more gap
  -- (1e-4 of the distance with no gap) ends that at once, and was the
  -- best of 0.02 .. 2 gaps tried
  local slack0 = gap
  for i = 1, #g do
    local a = g[i]
    local mark = pass * (#g + 1) + i
    for j = a.j0, a.j1 do
      local row = (j % b.ny) * b.nx
      for ii = a.i0, a.i1 do
        local c = cells[row + ii + 1]
        if c then
          for q = 1, #c do
            local k = c[q]
            local o = g[k]
            if k > i and stamp[k] ~= mark and not (a.fixed and o.fixed) then
              stamp[k] = mark
              local dx, dy = o.x - a.x, dy_min(o.y - a.y, h)
              local want = a.s * a.r + o.s * o.r + gap
              local d2 = dx * dx + dy * dy
              if d2 < want * want then
                local d = sqrt(d2)
                local push = want - d + (slack0 > 0 and slack0 or 1e-4 * want)
                n = n + 1
                a.hit, o.hit = pass, pass
                local ux, uy = 1, 0
                if d > 0 then ux, uy = dx / d, dy / d end
                local fa, fo
                if a.fixed then fa, fo = 0, 1
                elseif o.fixed then fa, fo = 1, 0
                else fa, fo = 0.5, 0.5 end
                a.x, a.y = a.x - fa * push * ux, a.y - fa * push * uy
                o.x, o.y = o.x + fo * push * ux, o.y + fo * push * uy
                confine(p, a)
                confine(p, o)
              end
            end
          end
        end
      end
    end
  end
  return n
end

-- Grow the movable discs of g from the scale at which they cover 0.3 of
-- the free area (the fixed ones at full size) up to full size, in stages
-- of relaxation.  A disc caught in a pocket too small for it (against a
-- fixed disc or a wall) is pushed back and forth for ever, so every 25
-- sweeps that do not settle a stage, the discs still overlapping are
-- moved to new random places by `relocate`.  Returns true, or nil and
-- the scale reached.
local function grow(p, g, b, gap, free, st, relocate)
  local eff = 0
  for _, d in ipairs(g) do
    if d.grows then eff = eff + pi * (d.r + 0.5 * gap) ^ 2 end
  end
  eff = eff / free
  local s = min(1, sqrt(0.3 / max(eff, 1e-12)))
  for _, d in ipairs(g) do
    if d.grows then d.s = s; confine(p, d) end
  end
  local step = 0.02
  while true do
    st.stages = st.stages + 1
    local ok = false
    for k = 1, (s < 1 and 100 or 2000) do
      st.pass = st.pass + 1
      st.sweeps = st.sweeps + 1
      local n = sweep(p, g, b, gap, st.stamp, st.pass)
      if n == 0 then ok = true; break end
      if relocate and k % 25 == 0 then
        for _, d in ipairs(g) do
          if d.hit == st.pass and d.grows and relocate(d) then
            confine(p, d)
            st.relocated = st.relocated + 1
          end
        end
      end
    end
    if ok and s >= 1 then return true end
    if ok then
      s = min(1, s + step)
      for _, d in ipairs(g) do
        if d.grows then d.s = s; confine(p, d) end
      end
    elseif s < 1 and step > 0.0025 then
      step = step / 2   -- stalled: grow more slowly
    else
      return nil, s, eff
    end
  end
end

-- the room around (x, y): the distance to the nearest disc surface
-- (discs listed in the 3 x 3 bins around it, at their current size) or
-- wall, at most one bin across
local function room(p, b, x, y, self)
  local best = min(x - p.x0, p.x0 + p.width - x, b.sx, b.sy)
  local cells, g = b.cells, b.list
  if not cells then return best end
  local i = min(b.nx - 1, floor((x - p.x0) / b.sx))
  local j = floor((y - p.y0) / b.sy)
  for jj = j - 1, j + 1 do
    local row = (jj % b.ny) * b.nx
    for ii = max(0, i - 1), min(b.nx - 1, i + 1) do
      local c = cells[row + ii + 1]
      if c then
        for q = 1, #c do
          local o = g[c[q]]
          if o ~= self then
            local dx, dy = x - o.x, dy_min(y - o.y, p.height)
            local r = sqrt(dx * dx + dy * dy) - o.s * o.r
            if r < best then best = r end
          end
        end
      end
    end
  end
  return best
end

-- a new centre for d: the one with the most room of a few uniform
-- random candidates (Mitchell's best candidate), so that a disc goes
-- into one of the larger holes rather than anywhere
local function seed_position(p, b, d, r, tries)
  local bx, by, broom = nil, nil, -math.huge
  for _ = 1, tries do
    local lo, span = p.x0 + d.s * d.r, p.width - 2 * d.s * d.r
    local x, y = lo + span * r.uniform(), p.y0 + p.height * r.uniform()
    local q = room(p, b, x, y, d)
    if q > broom then bx, by, broom = x, y, q end
  end
  d.x, d.y = bx, by
end

-- All grains grow together, largest first in the sweep order.  (Growing
-- the coarse grains first and then the fines in their voids stalls near
-- 0.7: the coarse bed, once fixed, leaves throats and pockets no fine
-- fits; so does weighting the pushes by area, which leaves a fine caught
-- between two coarse grains pushed back and forth while they, a hundred
-- times heavier, barely move apart.  Equal shares let the fines wedge
-- the coarse grains apart.)
local function place(p, g, r)
  for i, d in ipairs(g) do d.order = i end
  table.sort(g, function(a, b)
    if a.r ~= b.r then return a.r > b.r end
    return a.order < b.order
  end)
  local gap = p.gap * (1 + 1e-6)   -- a hair more, so the gap holds strictly
  local A = p.width * p.height
  local st = {stages = 0, sweeps = 0, pass = 0, stamp = {}, relocated = 0}
  if #g == 0 then return true, nil, nil, st end
  local fine = 0
  for _, d in ipairs(g) do fine = fine + 2 * d.r end
  fine = fine / #g
  local b = binner(p, max(2 * fine, sqrt(A / (4 * #g))))
  for _, d in ipairs(g) do d.s, d.grows = 0.5, true end
  for _, d in ipairs(g) do seed_position(p, b, d, r, 1) end
  -- only fines are moved out of a pocket: moving a coarse grain would
  -- undo the relaxation of everything around it
  local ok, s, eff = grow(p, g, b, gap, A, st, function(d)
    if d.class == "fine" then seed_position(p, b, d, r, 16) return true end
  end)
  if not ok then return nil, s, eff, st end
  return true, nil, nil, st
end

---------------------------------------------------------------- the bed

-- (measure: a grain's area, or its volume in 3-D, from its diameter)
local function histogram(all, nb, measure)
  local lo, hi = math.huge, 0
  for _, d in ipairs(all) do lo, hi = min(lo, d.d), max(hi, d.d) end
  if hi <= lo then hi = lo * 1.0001 end
  local l0, l1 = log(lo), log(hi)
  local h = {}
  for k = 1, nb do
    h[k] = {lo = exp(l0 + (l1 - l0) * (k - 1) / nb), hi = exp(l0 + (l1 - l0) * k / nb),
            coarse = 0, fine = 0, folded = 0, area = 0}
  end
  for _, d in ipairs(all) do
    local k = min(nb, 1 + floor(nb * (log(d.d) - l0) / (l1 - l0)))
    local bin = h[k]
    bin[d.class] = bin[d.class] + 1
    if d.folded then bin.folded = bin.folded + 1 end
    bin.area = bin.area + (measure and measure(d.d) or 0.25 * pi * d.d * d.d)
  end
  return h
end

------------------------------------------------------------ 3-D beds
--
-- With dim = 3 (a field, or the module's dimension: mvmpm.sim{dim = 3}
-- switches it) the bed is one of spheres in the box [x0, x0 + width] x
-- [y0, y0 + height] x [z0, z0 + depth], periodic in y and z (a sphere
-- across a seam continues on the other side, as the engine seeds it)
-- and walled in x.  Drawing, folding and growth are those of the discs
-- with volumes for areas; the sweeps push along the line of centres in
-- three dimensions.  The optional hmx_mass asks for the HMX mass
-- fraction of the whole composite: what the resolved spheres and the
-- folded fines leave short of it is added to the binder as unresolved
-- HMX (more "dirty binder"), reported as `extra`; a target the resolved
-- grains already pass is refused.  Random close packing of equal
-- spheres is about 0.64, and a bimodal bed with a size ratio of five
-- reaches about 0.7 in this method (docs/pbx.md), so a PBX 9501 loading
-- (0.93 by volume) is reached only with the unresolved fines.

-- the separation of two centres along a periodic axis of length L
local function near(d, L) return d - L * floor(d / L + 0.5) end

local function ball_volume(d) return pi / 6 * d * d * d end

-- bins over the box; a sphere is listed in every bin its cube (radius at
-- its scale + reach) touches, across the seams in y and z
local function binner3(p, size)
  local b = {}
  b.nx = max(1, floor(p.width / size))
  b.ny = max(1, floor(p.height / size))
  b.nz = max(1, floor(p.depth / size))
  b.sx, b.sy, b.sz = p.width / b.nx, p.height / b.ny, p.depth / b.nz
  function b.build(g, reach)
    local cells = {}
    local nx, ny, nz = b.nx, b.ny, b.nz
    for i = 1, #g do
      local d = g[i]
      local rr = d.s * d.r + reach
      local i0 = max(0, floor((d.x - rr - p.x0) / b.sx))
      local i1 = min(nx - 1, floor((d.x + rr - p.x0) / b.sx))
      local j0 = floor((d.y - rr - p.y0) / b.sy)
      local j1 = floor((d.y + rr - p.y0) / b.sy)
      local k0 = floor((d.z - rr - p.z0) / b.sz)
      local k1 = floor((d.z + rr - p.z0) / b.sz)
      if j1 - j0 >= ny then j1 = j0 + ny - 1 end
      if k1 - k0 >= nz then k1 = k0 + nz - 1 end
      for k = k0, k1 do
        local plane = (k % nz) * ny
        for j = j0, j1 do
          local row = (plane + j % ny) * nx
          for ii = i0, i1 do
            local c = row + ii + 1
            local list = cells[c]
            if not list then list = {}; cells[c] = list end
            list[#list + 1] = i
          end
        end
      end
      d.i0, d.i1, d.j0, d.j1, d.k0, d.k1 = i0, i1, j0, j1, k0, k1
    end
    return cells
  end
  return b
end

local function confine3(p, d)
  local lo = p.x0 + d.s * d.r + 1e-12 * p.width
  local hi = p.x0 + p.width - d.s * d.r - 1e-12 * p.width
  if d.x < lo then d.x = lo elseif d.x > hi then d.x = hi end
  d.y = p.y0 + (d.y - p.y0) % p.height
  d.z = p.z0 + (d.z - p.z0) % p.depth
end

-- one Gauss-Seidel sweep of the disc version, in 3-D
local function sweep3(p, g, b, gap, stamp, pass)
  local cells = b.build(g, 0.5 * gap)
  b.cells, b.list = cells, g
  local n = 0
  local H, D = p.height, p.depth
  local nx, ny, nz = b.nx, b.ny, b.nz
  for i = 1, #g do
    local a = g[i]
    local mark = pass * (#g + 1) + i
    for kk = a.k0, a.k1 do
      local plane = (kk % nz) * ny
      for j = a.j0, a.j1 do
        local row = (plane + j % ny) * nx
        for ii = a.i0, a.i1 do
          local c = cells[row + ii + 1]
          if c then
            for q = 1, #c do
              local k = c[q]
              local o = g[k]
              if k > i and stamp[k] ~= mark and not (a.fixed and o.fixed) then
                stamp[k] = mark
                local dx = o.x - a.x
                local dy, dz = near(o.y - a.y, H), near(o.z - a.z, D)
                local want = a.s * a.r + o.s * o.r + gap
                local d2 = dx * dx + dy * dy + dz * dz
                if d2 < want * want then
                  local d = sqrt(d2)
                  local push = want - d + (gap > 0 and gap or 1e-4 * want)
                  n = n + 1
                  a.hit, o.hit = pass, pass
                  local ux, uy, uz = 1, 0, 0
                  if d > 0 then ux, uy, uz = dx / d, dy / d, dz / d end
                  local fa, fo = 0.5, 0.5
                  if a.fixed then fa, fo = 0, 1 elseif o.fixed then fa, fo = 1, 0 end
                  a.x, a.y, a.z = a.x - fa * push * ux, a.y - fa * push * uy, a.z - fa * push * uz
                  o.x, o.y, o.z = o.x + fo * push * ux, o.y + fo * push * uy, o.z + fo * push * uz
                  confine3(p, a)
                  confine3(p, o)
                end
              end
            end
          end
        end
      end
    end
  end
  return n
end

-- the room around (x, y, z): distance to the nearest sphere surface in
-- the 3 x 3 x 3 bins around it, or to a wall, at most one bin
local function room3(p, b, x, y, z, self)
  local best = min(x - p.x0, p.x0 + p.width - x, b.sx, b.sy, b.sz)
  local cells, g = b.cells, b.list
  if not cells then return best end
  local i = min(b.nx - 1, floor((x - p.x0) / b.sx))
  local j = floor((y - p.y0) / b.sy)
  local k = floor((z - p.z0) / b.sz)
  for kk = k - 1, k + 1 do
    local plane = (kk % b.nz) * b.ny
    for jj = j - 1, j + 1 do
      local row = (plane + jj % b.ny) * b.nx
      for ii = max(0, i - 1), min(b.nx - 1, i + 1) do
        local c = cells[row + ii + 1]
        if c then
          for q = 1, #c do
            local o = g[c[q]]
            if o ~= self then
              local dx = x - o.x
              local dy, dz = near(y - o.y, p.height), near(z - o.z, p.depth)
              local rr = sqrt(dx * dx + dy * dy + dz * dz) - o.s * o.r
              if rr < best then best = rr end
            end
          end
        end
      end
    end
  end
  return best
end

local function seed_position3(p, b, d, r, tries)
  local bx, by, bz, broom = nil, nil, nil, -math.huge
  for _ = 1, tries do
    local lo, span = p.x0 + d.s * d.r, p.width - 2 * d.s * d.r
    local x = lo + span * r.uniform()
    local y = p.y0 + p.height * r.uniform()
    local z = p.z0 + p.depth * r.uniform()
    local q = room3(p, b, x, y, z, d)
    if q > broom then bx, by, bz, broom = x, y, z, q end
  end
  d.x, d.y, d.z = bx, by, bz
end

-- growth in stages, as grow() for discs: from the scale at which the
-- spheres fill 0.25 of the box (random addition of spheres jams near
-- 0.38) to full size
local function grow3(p, g, b, gap, V, st, relocate)
  local eff = 0
  for _, d in ipairs(g) do eff = eff + pi / 6 * (2 * d.r + gap) ^ 3 end
  eff = eff / V
  local s = min(1, (0.25 / max(eff, 1e-12)) ^ (1 / 3))
  for _, d in ipairs(g) do d.s = s; confine3(p, d) end
  local step = 0.02
  while true do
    st.stages = st.stages + 1
    local ok = false
    for k = 1, (s < 1 and 100 or 2000) do
      st.pass = st.pass + 1
      st.sweeps = st.sweeps + 1
      local n = sweep3(p, g, b, gap, st.stamp, st.pass)
      if n == 0 then ok = true; break end
      if k % 25 == 0 then
        for _, d in ipairs(g) do
          if d.hit == st.pass and relocate(d) then
            confine3(p, d)
            st.relocated = st.relocated + 1
          end
        end
      end
    end
    if ok and s >= 1 then return true end
    if ok then
      s = min(1, s + step)
      for _, d in ipairs(g) do d.s = s; confine3(p, d) end
    elseif s < 1 and step > 0.0025 then
      step = step / 2
    else
      return nil, s, eff
    end
  end
end

local function place3(p, g, r)
  for i, d in ipairs(g) do d.order = i end
  table.sort(g, function(a, b)
    if a.r ~= b.r then return a.r > b.r end
    return a.order < b.order
  end)
  local gap = p.gap * (1 + 1e-6)
  local V = p.width * p.height * p.depth
  local st = {stages = 0, sweeps = 0, pass = 0, stamp = {}, relocated = 0}
  if #g == 0 then return true, nil, nil, st end
  local mean = 0
  for _, d in ipairs(g) do mean = mean + 2 * d.r end
  mean = mean / #g
  local b = binner3(p, max(2 * mean, (V / (8 * #g)) ^ (1 / 3)))
  for _, d in ipairs(g) do d.s = 0.5 end
  for _, d in ipairs(g) do seed_position3(p, b, d, r, 1) end
  local ok, s, eff = grow3(p, g, b, gap, V, st, function(d)
    if d.class == "fine" then seed_position3(p, b, d, r, 16) return true end
  end)
  if not ok then return nil, s, eff, st end
  return true, nil, nil, st
end

local function bed3(p)
  local r = rng(p.seed)
  local g, folded, drawn = sizes(p, r, p.depth, ball_volume)
  local ok, s, eff, st = place3(p, g, r)
  if not ok then
    bad(3, "could not place %d spheres at packing %g with gap %g: growth stalled at %.3f of "
        .. "full size (at full size, with half the gap on every radius, the spheres would fill "
        .. "%.3f of the box); lower packing or gap, or change the classes", #g, p.packing,
        p.gap, s, eff)
  end
  local V = p.width * p.height * p.depth
  local bed = {dim = 3, x0 = p.x0, y0 = p.y0, z0 = p.z0, width = p.width, height = p.height,
               depth = p.depth, gap = p.gap, seed = p.seed, grains = {}, params = p}
  local n, vol = {coarse = 0, fine = 0}, {coarse = 0, fine = 0}
  local all, attached = {}, {left = 0, right = 0}
  for i, d in ipairs(g) do
    local side
    if d.x - d.r - p.x0 < p.attach then side = "left"
    elseif p.x0 + p.width - d.x - d.r < p.attach then side = "right" end
    if side then attached[side] = attached[side] + 1 end
    bed.grains[i] = {x = d.x, y = d.y, z = d.z, r = d.r, d = 2 * d.r, class = d.class,
                     side = side}
    n[d.class] = n[d.class] + 1
    vol[d.class] = vol[d.class] + pi / 6 * (2 * d.r) ^ 3
    all[#all + 1] = {d = 2 * d.r, class = d.class}
  end
  for _, d in ipairs(folded.list) do all[#all + 1] = d end
  local placed = vol.coarse + vol.fine
  local fold = folded.coarse.area + folded.fine.area
  local rhoH, rhoB = p.density, p.binder_density
  local binder_vol = V - placed                    -- binder + unresolved HMX
  -- HMX the hmx_mass target adds to the binder: m_H / (m_H + m_B) = w
  -- with m_H = rhoH (placed + fold + x), m_B = rhoB (binder_vol - fold - x)
  local extra = 0
  if p.hmx_mass then
    local w = p.hmx_mass
    local x = (w * rhoB * (binder_vol - fold) - (1 - w) * rhoH * (placed + fold))
              / ((1 - w) * rhoH + w * rhoB)
    if x < -1e-9 * V then
      local have = rhoH * (placed + fold) / (rhoH * (placed + fold) + rhoB * (binder_vol - fold))
      bad(3, "field 'hmx_mass' %g is below the %.4f the resolved and folded grains already "
          .. "make; lower packing or raise hmx_mass", w, have)
    end
    extra = max(0, x)
  end
  local unresolved = fold + extra
  local pure_binder = binder_vol - unresolved
  if pure_binder < 0 then
    bad(3, "the unresolved HMX (volume fraction %.3f) does not fit in the binder's %.3f: "
        .. "raise packing or lower min_diameter", unresolved / V, binder_vol / V)
  end
  local mass_grains = rhoH * placed
  local mass_dirty = rhoH * unresolved + rhoB * pure_binder
  local total = mass_grains + mass_dirty
  local stats = {
    count = #g, coarse = n.coarse, fine = n.fine,
    folded_coarse = folded.coarse.n, folded_fine = folded.fine.n,
    packing_target = p.packing,
    packing = placed / V,                          -- resolved spheres, by volume
    packing_hmx = (placed + unresolved) / V,       -- every HMX grain, by volume
    mass_fraction = mass_grains / total,
    mass_fraction_hmx = rhoH * (placed + unresolved) / total,
    hmx_mass_target = p.hmx_mass or 0,
    folded = fold / V,                             -- folded fines, by volume
    extra = extra / V,                             -- HMX added to reach hmx_mass, by volume
    folded_mass = rhoH * fold,                     -- kg
    folded_mass_fraction = rhoH * fold / total,
    mass_ratio_target = p.mass_ratio,
    mass_ratio = drawn.fine > 0 and drawn.coarse / drawn.fine or math.huge,
    mass_ratio_resolved = vol.fine > 0 and vol.coarse / vol.fine or math.huge,
    dirty_binder_density = binder_vol > 0 and mass_dirty / binder_vol or rhoB,
    dirty_binder_hmx = binder_vol > 0 and unresolved / binder_vol or 0,
    density = rhoH, binder_density = rhoB,
    attached_left = attached.left, attached_right = attached.right,
    stages = st.stages, sweeps = st.sweeps, relocated = st.relocated,
    min_diameter = p.min_diameter,
  }
  local dmin, dmax = math.huge, 0
  for _, d in ipairs(bed.grains) do dmin, dmax = min(dmin, d.d), max(dmax, d.d) end
  stats.smallest, stats.largest = dmin, dmax
  bed.stats = stats
  bed.histogram = histogram(all, p.bins, function(d) return pi / 6 * d * d * d end)
  bed.drawn = all
  return bed
end

-- the smallest surface gap between two discs (nearest image in y) and
-- between a disc and a side; O(n^2), for checks and statistics
function M.min_gap(bed)
  if bed.dim == 3 then
    local g, H, D = bed.grains, bed.height, bed.depth
    local worst, pair = math.huge, nil
    for i = 1, #g do
      local a = g[i]
      for k = i + 1, #g do
        local o = g[k]
        local dx, dy, dz = o.x - a.x, near(o.y - a.y, H), near(o.z - a.z, D)
        local s = sqrt(dx * dx + dy * dy + dz * dz) - a.r - o.r
        if s < worst then worst, pair = s, {i, k} end
      end
    end
    local wall = math.huge
    for i = 1, #g do
      local a = g[i]
      wall = min(wall, a.x - a.r - bed.x0, bed.x0 + bed.width - a.x - a.r)
    end
    return worst, wall, pair
  end
  local g, H = bed.grains, bed.height
  local worst, pair = math.huge, nil
  for i = 1, #g do
    local a = g[i]
    for k = i + 1, #g do
      local o = g[k]
      local dx, dy = o.x - a.x, dy_min(o.y - a.y, H)
      local s = sqrt(dx * dx + dy * dy) - a.r - o.r
      if s < worst then worst, pair = s, {i, k} end
    end
  end
  local wall = math.huge
  for i = 1, #g do
    local a = g[i]
    wall = min(wall, a.x - a.r - bed.x0, bed.x0 + bed.width - a.x - a.r)
  end
  return worst, wall, pair
end

-- pack.bed{...} -> bed: {grains = {{x, y, r, d, class, side}, ...},
-- stats = {...}, histogram = {...}, params}.  See the top of the file.
function M.bed(spec)
  local p = check(spec, 2)
  if p.dim == 3 then
    local bed = bed3(p)   -- (not a tail call: errors name the caller's line)
    return bed
  end
  local r = rng(p.seed)
  local g, folded, drawn = sizes(p, r)
  local ok, s, eff, st = place(p, g, r)
  if not ok then
    bad(2, "could not place %d grains at packing %g with gap %g: growth stalled at %.3f of "
        .. "full size (at full size, with half the gap on every radius, the grains would cover "
        .. "%.3f of the area; this method stalls near 0.8 of effective packing); lower packing or gap, "
        .. "or change the classes", #g, p.packing, p.gap, s, eff)
  end
  local A = p.width * p.height
  local bed = {x0 = p.x0, y0 = p.y0, width = p.width, height = p.height, gap = p.gap,
               seed = p.seed, grains = {}, params = p}
  local n = {coarse = 0, fine = 0}
  local area = {coarse = 0, fine = 0}
  local all = {}
  local attached = {left = 0, right = 0}
  for i, d in ipairs(g) do
    local side
    if d.x - d.r - p.x0 < p.attach then side = "left"
    elseif p.x0 + p.width - d.x - d.r < p.attach then side = "right" end
    if side then attached[side] = attached[side] + 1 end
    bed.grains[i] = {x = d.x, y = d.y, r = d.r, d = 2 * d.r, class = d.class, side = side}
    n[d.class] = n[d.class] + 1
    area[d.class] = area[d.class] + pi * d.r * d.r
    all[#all + 1] = {d = 2 * d.r, class = d.class}
  end
  for _, d in ipairs(folded.list) do all[#all + 1] = d end
  local placed = area.coarse + area.fine
  local fold = folded.coarse.area + folded.fine.area
  local rhoH, rhoB = p.density, p.binder_density
  local binder_area = A - placed                   -- binder + folded fines
  local pure_binder = binder_area - fold
  if pure_binder < 0 then
    bad(2, "the folded fines (area fraction %.3f) do not fit in the binder's %.3f: "
        .. "raise packing or lower min_diameter", fold / A, binder_area / A)
  end
  local mass_grains = rhoH * placed
  local mass_dirty = rhoH * fold + rhoB * pure_binder
  local total = mass_grains + mass_dirty
  local stats = {
    count = #g, coarse = n.coarse, fine = n.fine,
    folded_coarse = folded.coarse.n, folded_fine = folded.fine.n,
    packing_target = p.packing,
    packing = placed / A,                          -- resolved grains, by area
    packing_hmx = (placed + fold) / A,             -- every HMX grain, by area
    mass_fraction = mass_grains / total,           -- resolved grains, by mass
    mass_fraction_hmx = rhoH * (placed + fold) / total,
    folded_mass = rhoH * fold,                     -- per unit thickness, kg/m
    folded_mass_fraction = rhoH * fold / total,
    mass_ratio_target = p.mass_ratio,
    mass_ratio = drawn.fine > 0 and drawn.coarse / drawn.fine or math.huge,
    mass_ratio_resolved = area.fine > 0 and area.coarse / area.fine or math.huge,
    dirty_binder_density = binder_area > 0 and mass_dirty / binder_area or rhoB,
    dirty_binder_hmx = binder_area > 0 and fold / binder_area or 0,
    density = rhoH, binder_density = rhoB,
    attached_left = attached.left, attached_right = attached.right,
    stages = st.stages, sweeps = st.sweeps, relocated = st.relocated,
    min_diameter = p.min_diameter,
  }
  local dmin, dmax = math.huge, 0
  for _, d in ipairs(bed.grains) do dmin, dmax = min(dmin, d.d), max(dmax, d.d) end
  stats.smallest, stats.largest = dmin, dmax
  bed.stats = stats
  bed.histogram = histogram(all, p.bins)
  bed.drawn = all       -- every diameter drawn, placed or folded
  return bed
end

------------------------------------------------------------ reporting

local function summary3(bed)
  local s = bed.stats
  local t = {}
  t[#t + 1] = string.format(
    "bed %.4g x %.4g x %.4g, seed %d: %d spheres (%d coarse, %d fine), diameters %.3g .. %.3g",
    bed.width, bed.height, bed.depth, bed.seed, s.count, s.coarse, s.fine, s.smallest, s.largest)
  t[#t + 1] = string.format(
    "resolved spheres: %.4f by volume (target %.4f), %.4f by mass",
    s.packing, s.packing_target, s.mass_fraction)
  t[#t + 1] = string.format(
    "all HMX (with %.4f folded and %.4f added to reach hmx_mass %s, by volume): "
    .. "%.4f by volume, %.4f by mass",
    s.folded, s.extra,
    s.hmx_mass_target > 0 and string.format("%.4g", s.hmx_mass_target) or "(none)",
    s.packing_hmx, s.mass_fraction_hmx)
  t[#t + 1] = string.format(
    "coarse:fine mass %.3f (target %.3f; resolved spheres only %.3f); dirty binder %.0f kg/m^3 "
    .. "(%.1f %% HMX by volume)", s.mass_ratio, s.mass_ratio_target, s.mass_ratio_resolved,
    s.dirty_binder_density, 100 * s.dirty_binder_hmx)
  t[#t + 1] = string.format(
    "attached to the sides: %d left, %d right; %d growth stages, %d sweeps, %d relocations",
    s.attached_left, s.attached_right, s.stages, s.sweeps, s.relocated)
  return table.concat(t, "\n")
end

function M.summary(bed)
  if bed.dim == 3 then return summary3(bed) end
  local s = bed.stats
  local t = {}
  t[#t + 1] = string.format(
    "bed %.4g x %.4g, seed %d: %d grains (%d coarse, %d fine), diameters %.3g .. %.3g",
    bed.width, bed.height, bed.seed, s.count, s.coarse, s.fine, s.smallest, s.largest)
  t[#t + 1] = string.format(
    "packing by area %.4f (target %.4f), by mass %.4f; with the folded fines %.4f by area, %.4f by mass",
    s.packing, s.packing_target, s.mass_fraction, s.packing_hmx, s.mass_fraction_hmx)
  t[#t + 1] = string.format(
    "coarse:fine mass %.3f (target %.3f; resolved grains only %.3f)",
    s.mass_ratio, s.mass_ratio_target, s.mass_ratio_resolved)
  t[#t + 1] = string.format(
    "folded into the binder: %d fines + %d coarse below %.3g, %.4g kg/m (%.2f %% of the mass); "
    .. "dirty binder %.0f kg/m^3 (%.1f %% HMX by area)",
    s.folded_fine, s.folded_coarse, s.min_diameter, s.folded_mass,
    100 * s.folded_mass_fraction, s.dirty_binder_density, 100 * s.dirty_binder_hmx)
  t[#t + 1] = string.format(
    "attached to the sides: %d left, %d right; %d growth stages, %d sweeps, %d relocations",
    s.attached_left, s.attached_right, s.stages, s.sweeps, s.relocated)
  return table.concat(t, "\n")
end

-- write PREFIX_grains.csv (one row per disc), PREFIX_sizes.csv (the
-- histogram) and PREFIX_stats.csv (name,value); through mvmpm.open, so
-- also under --sandbox (inside the output directory)
function M.write_csv(bed, prefix)
  local function open(name)
    local f, err = require("mvmpm").open(prefix .. name)
    if not f then error("pack.write_csv: " .. err, 3) end
    return f
  end
  local f = open("_grains.csv")
  if bed.dim == 3 then
    f:write("id,class,x,y,z,diameter,side\n")
    for i, d in ipairs(bed.grains) do
      f:write(string.format("%d,%s,%.17g,%.17g,%.17g,%.17g,%s\n", i, d.class, d.x, d.y, d.z,
        d.d, d.side or ""))
    end
  else
    f:write("id,class,x,y,diameter,side\n")
    for i, d in ipairs(bed.grains) do
      f:write(string.format("%d,%s,%.17g,%.17g,%.17g,%s\n", i, d.class, d.x, d.y, d.d,
        d.side or ""))
    end
  end
  f:close()
  f = open("_sizes.csv")
  f:write("d_lo,d_hi,coarse,fine,area\n")
  for _, b in ipairs(bed.histogram) do
    f:write(string.format("%.6g,%.6g,%d,%d,%.6g\n", b.lo, b.hi, b.coarse, b.fine, b.area))
  end
  f:close()
  f = open("_stats.csv")
  f:write("name,value\n")
  local names = {}
  for k in pairs(bed.stats) do names[#names + 1] = k end
  table.sort(names)
  for _, k in ipairs(names) do
    f:write(string.format("%s,%.10g\n", k, bed.stats[k]))
  end
  f:close()
end

return M
