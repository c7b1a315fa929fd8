-- sim:contacts() (src/core/diag_contact.c) and force chains (mvmpm.chain).
--   1. Three discs stacked in a frictionless channel under gravity: the
--      force between discs 1 and 2 is the weight of discs 2 and 3, and
--      between 2 and 3 the weight of disc 3 (the masses are density x
--      the particles' volume).  The stack rings after it is let go; FLIP
--      0.9 damps it and the force is the mean over the second half.
--      Three resolutions.
--   2. A column of three discs squeezed between two driven plates:
--      quasi-static (the plates move at 1/400 of the wave speed), so
--      every contact along the column carries the plates' force, and a
--      chain spans from one plate to the other through every disc.
--   3. The same column with a gap of 0.1 (four cells or more) between
--      the second and third discs, which the plates do not close: no
--      chain spans at any sample, though discs touch the plates.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local chain = require "mvmpm.chain"

local R = 0.25
local elastic = {K = 10, G = 5, density = 1}

local function stack(n, shape, update)
  local sim = mvmpm.sim {domain = {x = {0, 2 * R}, y = {0, 8 * R}}, cell = 2 * R / n,
    sides = {"wall", friction = 0}, gravity = {0, -1}, t_end = 12,
    contact = {friction = 0}, flip = 0.9, shape = shape, update = update}
  local m = mvmpm.elastic(elastic)
  local b = {}
  for k = 1, 3 do
    b[k] = sim:body {shape = mvmpm.disk {center = {R, (2 * k - 1) * R}, radius = R}, material = m}
  end
  local f12, f23, ns, pairs_ok = 0, 0, 0, true
  sim:every {time = 0.1, fn = function(s)
    if s.t < s.t_end / 2 then return end
    local c = s:contacts()
    for _, p in ipairs(c) do
      if p.a == b[1].id and p.b == b[2].id then f12 = f12 + p.force
      elseif p.a == b[2].id and p.b == b[3].id then f23 = f23 + p.force
      else pairs_ok = false end
    end
    ns = ns + 1
  end}
  sim:run()
  return f12 / ns / (b[2]:mass() + b[3]:mass()), f23 / ns / b[3]:mass(), pairs_ok
end

V.case "three discs stacked under gravity: contact force / weight carried"
do
  local shape, e12 = "linear", {}
  for _, n in ipairs {8, 16, 24} do
    local r12, r23, only = stack(n, shape)
    V.near(string.format("%s, %d cells per diameter: disc 1-2 force / weight of discs 2, 3", shape, n),
           r12, 1, 0.03, true)
    V.near(string.format("%s, %d cells per diameter: disc 2-3 force / weight of disc 3", shape, n),
           r23, 1, 0.03, true)
    V.holds(string.format("%s, %d cells: only the pairs 1-2 and 2-3 press", shape, n), only)
    e12[#e12 + 1] = math.abs(r12 - 1)
  end
  -- the error is what is left of the ringing in the mean, not a
  -- discretization error that falls with h: no order is claimed
  V.info(shape .. ": |error| 1-2 at 8, 16, 24 cells (%)", 100 * e12[1])
  V.info(shape .. ":   at 16", 100 * e12[2])
  V.info(shape .. ":   at 24", 100 * e12[3])
end
-- under USAVG, whose forces are scattered after the step's first half
-- stress update: sim:contacts takes them from the stresses as they stand
do
  local r12, r23 = stack(16, "linear", "usavg")
  V.near("linear USAVG, 16 cells per diameter: disc 1-2 force / weight of discs 2, 3", r12, 1, 0.03, true)
  V.near("linear USAVG, 16 cells per diameter: disc 2-3 force / weight of disc 3", r23, 1, 0.03, true)
end
-- uGIMP, reported: its mean reads 7 % high at 16 cells (see docs/shear.md)
for _, n in ipairs {8, 16} do
  local r12, r23 = stack(n, "gimp")
  V.info(string.format("gimp, %d cells: disc 1-2 force / weight of discs 2, 3", n), r12)
  V.info(string.format("gimp, %d cells: disc 2-3 force / weight of disc 3", n), r23)
end

-- a column of discs between two driven plates; gap between discs 2 and 3
local function column(n, gap, quiet)
  local W, v = 0.1, 0.01
  -- the plates start smoothly (over t = 0.5), so the column barely rings
  local function drive(sign)
    return function(t)
      local u = math.min(t / 0.5, 1)
      return sign * v * u * u * (3 - 2 * u), 0
    end
  end
  local h = R / n
  local Lx = math.ceil((2 * W + 6 * R + gap) / h) * h
  local sim = mvmpm.sim {domain = {x = {0, Lx}, y = {0, 1}}, cell = h, sides = "free",
    t_end = 2, contact = {friction = 0}, flip = 0.9}
  local m = mvmpm.elastic(elastic)
  local pl = sim:body {name = "left", shape = mvmpm.rect {lo = {0, 0.3}, hi = {W, 0.7}},
                       material = m, driven = drive(1)}
  local d, x = {}, W + R
  for k = 1, 3 do
    d[k] = sim:body {shape = mvmpm.disk {center = {x, 0.5}, radius = R}, material = m}
    x = x + 2 * R + (k == 2 and gap or 0)
  end
  local pr = sim:body {name = "right", shape = mvmpm.rect {lo = {x - R, 0.3}, hi = {x - R + W, 0.7}},
                       material = m, driven = drive(-1)}
  local res = {spans = 0, samples = 0, touched = 0, f = {0, 0, 0, 0}, plate = 0, path = ""}
  local ids = {pl.id, d[1].id, d[2].id, d[3].id, pr.id}
  sim:every {time = 0.05, fn = function(s)
    if quiet then return end
    local c = s:contacts()
    local ch = chain.strongest(c, {[pl.id] = true}, {[pr.id] = true})
    res.samples = res.samples + 1
    if #c > 0 then res.touched = res.touched + 1 end
    if ch then res.spans = res.spans + 1; res.path = table.concat(ch.path, "-") end
    if s.t >= 1 then -- past the start's transient: the means of the forces
      for _, p in ipairs(c) do
        for k = 1, 4 do
          if p.a == ids[k] and p.b == ids[k + 1] then res.f[k] = res.f[k] + p.force end
        end
      end
      local fx = pl:force()
      res.plate, res.nmean = res.plate + fx, (res.nmean or 0) + 1
    end
  end}
  sim:run()
  res.ids = table.concat(ids, "-")
  res.x, res.v = sim:particles("position"), sim:particles("velocity")
  return res
end

V.case "a column of three discs squeezed between two plates: a chain spans it"
for _, n in ipairs {4, 6, 8} do
  local r = column(n, 0)
  local plate = r.plate / r.nmean
  V.holds(string.format("%d cells per radius: a chain spans plate to plate at every sample from t = 0.1", n),
          r.spans >= r.samples - 2, r.spans)
  V.holds(string.format("%d cells per radius: the chain runs through every disc in order", n),
          r.path == r.ids, 0, r.path)
  for k = 1, 4 do
    V.near(string.format("%d cells per radius: mean force of contact %d / the plate's", n, k),
           r.f[k] / r.nmean / plate, 1, 0.05, true)
  end
end

V.case "the same column with a gap of 0.1 between discs 2 and 3: no chain"
for _, n in ipairs {4, 6, 8} do
  local r = column(n, 0.1)
  V.holds(string.format("%d cells per radius: no sample has a spanning chain", n), r.spans == 0, r.spans)
  V.above(string.format("%d cells per radius: samples with some contact", n), r.touched, 1)
end

V.case "asking for the contacts between steps leaves the run as it was"
do
  local a, b = column(4, 0), column(4, 0, true)
  local same = #a.x.x == #b.x.x
  for i = 1, #a.x.x do
    for _, c in ipairs {"x", "y"} do
      if a.x[c][i] ~= b.x[c][i] or a.v[c][i] ~= b.v[c][i] then same = false end
    end
  end
  V.holds("column, 4 cells per radius: positions and velocities bit for bit, asked 40 times or never",
          same, #a.x.x)
end
