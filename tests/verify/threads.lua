-- Threads do not change the numbers: each scene runs with 1, 2 and 3
-- threads (3 is more than this machine's cores: parts wait on each
-- other) and every particle field must agree bit for bit, and so must
-- the energy sums.  The scenes are large enough (several thousand
-- particles) for the scatter to be cut into parts, and run past sorts
-- by cell (every 20 steps) so the parts follow the particles.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

-- every field and energy of sim as one string of hex floats
local function state(sim)
  local b, names = {}, sim:particles()
  table.sort(names)
  local function put(t)
    for i = 1, #t do b[#b + 1] = string.format("%a", t[i]) end
  end
  for _, n in ipairs(names) do
    local f = sim:particles(n)
    if #f > 0 then put(f)
    else
      local ks = {}
      for k in pairs(f) do ks[#ks + 1] = k end
      table.sort(ks)
      for _, k in ipairs(ks) do put(f[k]) end
    end
  end
  local e, ks = sim:energy(), {}
  for k in pairs(e) do ks[#ks + 1] = k end
  table.sort(ks)
  for _, k in ipairs(ks) do b[#b + 1] = string.format("%a", e[k]) end
  return table.concat(b, " "), sim.n
end

local function run(path, over, steps, threads)
  local sim = mvmpm.load(path, over)
  sim.threads = threads
  sim:step(steps)
  return state(sim)
end

local function same(title, path, over, steps)
  V.case(title)
  local one, n = run(path, over, steps, 1)
  for _, t in ipairs {2, 3} do
    local other = run(path, over, steps, t)
    V.holds(string.format("%d threads: every field bit for bit (%d particles)", t, n),
      other == one, other == one and 1 or 0)
  end
end

same("multi-field contact: two disks, uGIMP, MUSL", "scenarios/two_disks.lua",
  {cells = 100, shape = "gimp"}, 45)
same("bonds across a periodic side: bond_pull", "scenarios/bond_pull.lua",
  {cells = 48}, 45)
same("walls, B-splines, APIC: cylinder_bounce", "scenarios/cylinder_bounce.lua",
  {cells = 40, shape = "bspline2", transfer = "apic"}, 45)
same("plastic onto viscoelastic, periodic, gravity, friction, USL",
  "tests/verify/scenes/threads_mix.lua", {update = "usl", shape = "linear"}, 45)
same("the same, MUSL with uGIMP and APIC", "tests/verify/scenes/threads_mix.lua",
  {shape = "gimp", transfer = "apic"}, 45)
same("the same, USAVG with uGIMP (stresses first and last)",
  "tests/verify/scenes/threads_mix.lua", {update = "usavg", shape = "gimp"}, 45)
same("frictional grains pressed by a driven plate, walls, gravity",
  "tests/verify/scenes/threads_grains.lua", {}, 45)
-- cooled fast, the disc lets go of the annulus within the run: cuts in
-- the threaded contact pass, strengths gathered and scattered by threads
same("bonds cut: concentric cylinders cooled fast", "scenarios/concentric_debond.lua",
  {rate = 0.02}, 60)
-- the cohesive law mid-softening (8 nodes cut, about half the work of
-- separation spent): the openings' memory written by the threaded
-- contact pass and read back per particle
same("the cohesive law: bond_pull softening", "scenarios/bond_pull.lua",
  {cells = 16, strength = 5e-4, energy = 5e-6}, 400)
