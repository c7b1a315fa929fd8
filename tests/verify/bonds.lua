-- Bonded interfaces (scenarios/bond_pull.lua): two blocks bonded face to
-- face in uniaxial strain, pulled apart slowly.  While bonded the pair
-- behaves as one block (stress = (K + 4G/3) eps against the grips'
-- displacement); the bond lets go when the normal traction reaches its
-- strength, at the time the quasi-static solution gives; the whole
-- interface lets go at once (the traction is uniform); the damage stays
-- on the particles beside the interface and never heals; the energy
-- budget closes through it all.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local M = 1 + 4 * 0.5 / 3           -- P-wave modulus K + 4G/3
local V0, T, h = 0.002, 8, 1 / 16

-- grip displacement (each side) for the ramped speed
local function u(t)
  return t < T and V0 * t * t / (2 * T) or V0 * (T / 2 + (t - T))
end

-- the mean stress xx in the middle of block A, and the interface opening:
-- the gap between A's rightmost and B's leftmost particle beyond the
-- particles' spacing (zero while the blocks move as one)
local function probe(sim)
  local x, s, body = sim:particles("position"), sim:particles("stress"), sim:particles("body")
  local sum, n, amax, bmin = 0, 0, -1e9, 1e9
  for i = 1, #x.x do
    if body[i] == 2 then
      amax = math.max(amax, x.x[i])
      if x.x[i] > 0.8 and x.x[i] < 1.2 then sum, n = sum + s.xx[i], n + 1 end
    elseif body[i] == 3 then bmin = math.min(bmin, x.x[i]) end
  end
  return sum / n, bmin - amax - h / 2
end

local function run(strength, t_end)
  local sim = mvmpm.load("scenarios/bond_pull.lua", {strength = strength, t_end = t_end})
  local r = {worst = 0, first = nil, last = nil, maxres = 0, maxin = 0}
  sim:every {steps = 1, fn = function(s)
    local e = s:energy()
    if e.debonded > 0 and not r.first then r.first = s.t end
    if e.debonded ~= (r.count or 0) then r.last, r.count = s.t, e.debonded end
    r.maxres = math.max(r.maxres, math.abs(e.residual))
    r.maxin = math.max(r.maxin, e.boundary_work)
  end}
  r.sim = sim
  return r
end

V.case "bonded: the pair moves as one block (strength 10, never reached)"
local r = run(10, 8)
for _, t in ipairs {4, 6, 8} do
  r.sim:run(t)
  local sxx, open = probe(r.sim)
  V.near(string.format("stress xx in A at t = %g / (K + 4G/3) u", t), sxx / (M * u(t)), 1, 0.02)
  V.below(string.format("interface opening at t = %g / cell", t), math.abs(open) / h, 0.01)
end
V.holds("no node debonded", r.first == nil, r.count or 0)

V.case "debonding at the strength (0.01)"
local d = run(0.01, 10.5)
local tc = math.sqrt(2 * T * 0.01 / (M * V0))  -- M u(tc) = strength
-- where each particle began, by id (the sort by cell reorders them)
local x0 = {}
do
  local x, id = d.sim:particles("position").x, d.sim:particles("id")
  for i = 1, #x do x0[id[i]] = x[i] end
end
d.sim:run(6.5)
local s65 = probe(d.sim)
local b65 = {}
do
  local b, id = d.sim:particles("bond"), d.sim:particles("id")
  for i = 1, #b do b65[id[i]] = b[i] end
end
-- after the release A rings about zero stress, as a bar free at one end
-- and held at the other, with the period 4 L / c_L: average over one
local period = 4 * 1.0 / math.sqrt(M)
local ssum, sn, t0 = 0, 0, nil
d.sim:every {steps = 1, fn = function(sm)
  if d.first and not t0 then t0 = sm.t end
  if t0 and sm.t > t0 and sm.t <= t0 + period then
    local sx = probe(sm)
    ssum, sn = ssum + sx, sn + 1
  end
end}
d.sim:run(10.5)
local sxx, open = probe(d.sim)
V.info("quasi-static onset time sqrt(2 T sigma_b / (M V0))", tc)
V.near("first debonding time / analytic onset", d.first / tc, 1, 0.03)
V.below("time from the first to the last node let go", d.last - d.first, 0.05)
V.above("interface opening after debonding / cell", open / h, 0.1)
V.below("|mean stress xx in A over one ringing period| / strength", math.abs(ssum / sn) / 0.01, 0.2)
V.info("stress xx in A at t = 10.5 / strength (ringing)", sxx / 0.01)
V.near("stress xx in A just before (t = 6.5) / (K + 4G/3) u", s65 / (M * u(6.5)), 1, 0.02)
-- damage: the particles whose nearest node is on the interface (within
-- half a cell of it) lost their strength, the rest kept it
do
  local body, bond, id = d.sim:particles("body"), d.sim:particles("bond"), d.sim:particles("id")
  local near, nearlost, far, farkept = 0, 0, 0, 0
  for i = 1, #id do
    if body[i] == 2 or body[i] == 3 then
      if b65[id[i]] > 0 then
        local dist = math.abs(x0[id[i]] - 1.5)
        if dist < h / 2 then near = near + 1; nearlost = nearlost + (bond[i] == 0 and 1 or 0)
        elseif dist > 2 * h then far = far + 1; farkept = farkept + (bond[i] == 1 and 1 or 0) end
      end
    end
  end
  V.near("particles within half a cell of the interface debonded (fraction)", nearlost / near, 1, 0)
  V.near("particles beyond two cells keep their strength (fraction)", farkept / far, 1, 0)
end
V.holds("no healing: nodes cut once, none again after the interface opened",
  d.count == 8, d.count)
V.below("largest |energy residual| / largest boundary work", d.maxres / d.maxin, 0.05)

V.case "no bond (strength 0): tension opens the interface at once"
local z = run(0, 3)
z.sim:run(3)
local sz, oz = probe(z.sim)
V.near("interface opening at t = 3 / both grips' travel 2 u", oz / (2 * u(3)), 1, 0.2)
V.below("|stress xx in A| at t = 3 / what a bonded pair carries", math.abs(sz) / (M * u(3)), 0.5)

V.case "a debond front along a loaded interface (scenarios/debond_front.lua)"
do
  local F = require "mvmpm.front"
  local speed, len = F.run {cells = 16}
  V.info("front speed / c_R", speed)
  V.below("front speed / c_R (must not exceed 1)", speed, 1.0)
  V.above("front speed / c_R (a front runs: > 0.5)", speed, 0.5)
  V.above("debonded length at t = 17.5 (of 2.5, the seed included)", len, 1.5)
end
