-- Orderings the accuracy study (docs/accuracy.md, studies/*.lua) found,
-- held as physics checks on small, fast versions of its cases: no times
-- are asserted, only which scheme is the more accurate.  Each case and its
-- reference are described in its studies/ script.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"
local S = require "mvmpm.study"

S.load_only = true
local disc = dofile("studies/disc.lua")
local bar = dofile("studies/bar.lua")
local block = dofile("studies/block.lua")
local bounce = dofile("studies/bounce.lua")
S.load_only = false

V.case "spinning disc, 16 cells per diameter, t = 20: APIC against PIC"
for _, shape in ipairs {"gimp", "bspline2"} do
  local apic = S.once(disc, {cells = 16, shape = shape, transfer = "apic"})
  local pic = S.once(disc, {cells = 16, shape = shape, flip = 0})
  V.info(shape .. " PIC: L(20)/L(0) - 1", pic.dL)
  V.info(shape .. " PIC: E(20)/E(0) - 1", pic.dE)
  V.info(shape .. " APIC: E(20)/E(0) - 1", apic.dE)
  V.below(shape .. " APIC: |L(20)/L(0) - 1|, limit 1/4 of PIC's", apic.angmom, 0.25 * pic.angmom,
    string.format("reference: L(0), conserved (nothing acts on the disc); PIC %.4g", pic.angmom))
  V.below(shape .. " APIC: energy lost, limit 1/4 of PIC's", -apic.dE, -0.25 * pic.dE,
    string.format("reference: E(0), conserved; PIC lost %.4g", -pic.dE))
end

V.case "block crossing cells (16 cells across), in-plane stress of a stress-free motion"
do
  -- rigid translation: the nodal velocities are the block's own, no stress
  for _, shape in ipairs {"linear", "gimp", "bspline2"} do
    local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 2}}, cell = 1 / 32, shape = shape}
    sim:body {shape = mvmpm.rect {lo = {0.5, 0.5}, hi = {1.0, 1.0}}, velocity = {0.1, 0.037},
              material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
    local mx = 0
    sim:every {steps = 10, fn = function(s)
      local st = s:particles("stress")
      for i = 1, #st.xx do mx = math.max(mx, math.abs(st.xx[i]), math.abs(st.yy[i]), math.abs(st.xy[i])) end
    end}
    sim:run(3)
    V.below(shape .. ": rigid translation, max |sigma| (reference 0)", mx, 1e-10)
  end
  -- homogeneous free growth while translating (studies/block.lua)
  local lin = S.once(block, {cells = 16, shape = "linear"})
  local bsp = S.once(block, {cells = 16, shape = "bspline2"})
  local gimp = S.once(block, {cells = 16, shape = "gimp"})
  V.info("linear: max |sigma| / (2 K' beta t), reference 0", lin.stress)
  V.info("GIMP: the same", gimp.stress)
  V.below("B-spline: max |sigma| / (2 K' beta t), reference 0", bsp.stress, 0.02)
  V.below("B-spline / linear (cell-crossing spikes on linear hats)", bsp.stress / lin.stress, 0.25)
end

V.case "bar, first free-free mode: period against 2 L / c (plane-strain c)"
do
  local prev
  for _, cells in ipairs {8, 16, 32} do
    local r, sim = S.once(bar, {cells = cells, shape = "linear"})
    if cells == 8 then
      -- 8 x 4 cells, 2 x 2 per cell: the whole periodic height is seeded
      V.near("bar of 8 x 4 cells: particles seeded", sim.n, 128, 0)
    end
    V.info(string.format("linear FLIP, %d cells: T measured (exact %.5f)", cells, 2 / math.sqrt(1 + 2 / 3)),
      r.T_measured)
    if prev then
      V.below(string.format("|T/T_exact - 1| at %d cells, limit 1/2 of %d cells'", cells, cells // 2),
        r.period, 0.5 * prev)
    end
    prev = r.period
  end
  V.below("|T/T_exact - 1| at 32 cells", prev, 0.005)
end

V.case "frictionless bounce, 32 cells per diameter, cfl 0.25: energy after 3 bounces"
do
  local lin = S.once(bounce, {cells = 32, shape = "linear"})
  local bsp = S.once(bounce, {cells = 32, shape = "bspline2"})
  V.info("linear FLIP MUSL: E(36)/E(0) - 1 (reference 0; gains in free ringing)", lin.dE)
  V.below("B-spline FLIP MUSL: |E(36)/E(0) - 1| (reference 0)", bsp.energy, 0.02)
  V.below("B-spline error / linear hats' error", bsp.energy / lin.energy, 0.25)
end
