-- Hard cases: impacts.  A head-on collision of two discs at 0.4 c_L
-- closing speed; a mass ratio of 1000 between touching bodies; a square
-- landing on its corner; a block sliding down an incline diagonal to the
-- grid.  Each: no NaN, det F > 0, energy never above what came in, no
-- body inside another, momentum kept where nothing outside acts.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local H = require "mvmpm.hard"

local soft = mvmpm.elastic {K = 1, G = 0.5, density = 1}
local cL = soft.c

V.case "fast head-on impact, closing speed 0.4 c_L"
do
  local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 1}}, cell = 1 / 32, sides = "free",
                         t_end = 1.2}
  local v = 0.2 * cL
  sim:body {shape = mvmpm.disk {center = {0.7, 0.5}, radius = 0.2}, material = soft, velocity = {v, 0}}
  sim:body {shape = mvmpm.disk {center = {1.3, 0.5}, radius = 0.2}, material = soft, velocity = {-v, 0}}
  local rec = H.watch(sim)
  sim:run()
  -- strains reach 0.4 at the contact; the stored energy is exact there
  -- (the stress rate is written for the Kirchhoff stress,
  -- docs/algorithm.md section 12): the total never rises above what came
  -- in (written for the Cauchy stress it peaked 6.7 % above, and 10 %
  -- was allowed here)
  H.check(rec, {energy = 0.02, momentum = 1e-12})
end

V.case "mass ratio 1000: a dense disc strikes a light block"
do
  local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 1}}, cell = 1 / 32, sides = "free",
                         t_end = 3}
  local heavy = mvmpm.elastic {K = 1000, G = 500, density = 1000}
  sim:body {shape = mvmpm.disk {center = {0.4, 0.5}, radius = 0.15}, material = heavy, velocity = {0.2, 0}}
  sim:body {shape = mvmpm.rect {lo = {0.6, 0.3}, hi = {0.9, 0.7}}, material = soft}
  local rec = H.watch(sim)
  sim:run()
  H.check(rec, {energy = 0.02, momentum = 1e-9 * 1000})
end

V.case "a square lands on its corner on a block"
do
  -- K = 10: the corner digs in to det F 0.79 at 0.07 c_L; with K = 1 the
  -- block sags under gravity to strains near 0.3 and the square's corner
  -- crushes to det F 0.42: asserted too since the stored energy is exact
  -- at any strain (it read 4-6 % high when the stress rate was written
  -- for the Cauchy stress, docs/stability.md)
  local function corner(K)
    local m = mvmpm.elastic {K = K, G = K / 2, density = 1}
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 32, sides = "wall",
                           gravity = {0, -1}, t_end = 2}
    local c, r = {0.5, 0.55}, 0.12
    sim:body {shape = mvmpm.polygon {{c[1], c[2] - r}, {c[1] + r, c[2]}, {c[1], c[2] + r},
              {c[1] - r, c[2]}}, material = m, velocity = {0, -0.3}}
    sim:body {shape = mvmpm.rect {lo = {0.1, 0}, hi = {0.9, 0.3}}, material = m}
    local rec = H.watch(sim)
    sim:run()
    return rec
  end
  H.check(corner(10), {energy = 0.02})
  local soft_rec = corner(1)
  V.info("K = 1 (strains near 0.3): smallest det F", soft_rec.jmin)
  V.below("K = 1: peak of total energy above what came in / energy scale",
          soft_rec.excess / soft_rec.scale, 0.02)
  V.below("K = 1: at the end: total energy above what came in / energy scale",
          soft_rec.final / soft_rec.scale, 0.01)
end

V.case "a stiff block resting on a floor under gravity, 13,000 steps"
do
  -- MUSL holds the walls in the remap when gravity is on (wall_remap =
  -- "auto", src/boundary.c); "free" pumps this block (kinetic energy
  -- 2e-8 -> 2e-3 over 8 time units), reported below
  local function rest(remap, update)
    local m = mvmpm.elastic {K = 100, G = 50, density = 1}
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 32, sides = "wall",
                           gravity = {0, -1}, t_end = 8, wall_remap = remap, update = update}
    sim:body {shape = mvmpm.rect {lo = {0.3, 0}, hi = {0.7, 0.3}}, material = m}
    local rec = H.watch(sim)
    local kmax = 0
    sim:every {steps = 10, fn = function(s) kmax = math.max(kmax, s:energy().kinetic) end}
    sim:run()
    return rec, kmax, sim
  end
  local rec, kmax, sim = rest("auto")
  V.info("steps", sim.steps)
  H.check(rec, {energy = 0.01})
  -- the settling itself: released unstressed, the block sags by a mean
  -- rho g H^2 / (3 (K + 4G/3)) (a column on a fixed base), losing the
  -- potential M g rho g H^2 / (3 (K + 4G/3)) = 2.16e-5 on the way to rest;
  -- without losses it oscillates about the sag with at most half of
  -- that as kinetic energy, so the whole of it bounds any run that does
  -- not pump
  local sag = 0.12 * 1 * (1 * 1 * 0.3 ^ 2) / (3 * (100 + 4 * 50 / 3))
  V.below("largest kinetic energy / potential lost sagging", kmax / sag, 1)
  local _, kfree = rest("free")
  V.info("largest kinetic energy with wall_remap = \"free\"", kfree)
  -- USAVG holds the walls in its first half too (src/usf.c); without
  -- that this block was pumped to 1.23 times the bound
  local urec, kus = rest("auto", "usavg")
  H.check(urec, {energy = 0.01})
  V.below("USAVG: largest kinetic energy / potential lost sagging", kus / sag, 1)
end

V.case "a block sliding down an incline at 30 degrees to the grid"
do
  local sim = mvmpm.sim {domain = {x = {0, 2}, y = {0, 1.25}}, cell = 1 / 32, sides = "wall",
                         gravity = {0, -1}, t_end = 2, contact = {friction = 0.2}}
  local a = math.rad(30)
  local function rot(x, y, x0, y0) return {x0 + x * math.cos(a) - y * math.sin(a), y0 + x * math.sin(a) + y * math.cos(a)} end
  -- the ramp: a long slab tilted by 30 degrees; the block on its surface
  sim:body {name = "ramp", shape = mvmpm.polygon {rot(0, 0, 0.2, 0.1), rot(1.8, 0, 0.2, 0.1),
            rot(1.8, 0.15, 0.2, 0.1), rot(0, 0.15, 0.2, 0.1)}, material = mvmpm.elastic {K = 20, G = 10, density = 1},
            driven = {0, 0}}
  local b = sim:body {name = "block", shape = mvmpm.polygon {rot(1.2, 0.17, 0.2, 0.1),
            rot(1.5, 0.17, 0.2, 0.1), rot(1.5, 0.37, 0.2, 0.1), rot(1.2, 0.37, 0.2, 0.1)},
            material = soft}
  local rec = H.watch(sim)
  local x0 = b:diag()
  sim:run()
  local x1 = b:diag()
  -- sliding with mu = 0.2 < tan 30: it must have moved down the slope
  local s = ((x1.x - x0.x) * math.cos(a) + (x1.y - x0.y) * math.sin(a))
  V.below("displacement along the slope (down is negative)", s, -0.1)
  H.check(rec, {energy = 0.02})
end
