-- 3-D bonded interfaces: the energy budget.  A stiff ball (K = 10,
-- G = 5, radius 1/4) bonded in a soft binder (K = 1, G = 0.05) filling
-- a unit cube, periodic in y and z, sheared by two driven grips two
-- cells thick at x = 0 and x = 1 (light, density 0.1, bonded to the
-- binder) moving in -y and +y after a sin^2 ramp, to a shear strain of
-- 0.1.  Linear hats, one particle per cell per direction (the 3-D PBX
-- bed's seeding).  Every bonded node makes its fields' velocities one,
-- an inelastic collision of the fields at the node; that loss, less
-- the stress work bond_remap adds, is booked as sim:energy().bonding
-- (src/core/contact.c, src/core/bond.c).  Checked: the residual against
-- the work the grips did, at 8, 12 and 16 cells across the cube, with
-- GIMP at 12 and with a finite bond that lets part of the interface go;
-- reported, what the residual would be without the bonded nodes' term.
-- And the same numbers with 1 and 2 threads (the bond sums are gathered
-- by bands of node rows, whose rows a 3-D stencil holds nw^2 nodes each).
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local function run(o)
  local cells, h = o.cells, 1 / o.cells
  local rate, strain, ramp = 0.1, 0.1, 0.02
  local V0, Tr = rate / 2, ramp / rate
  local t_end = strain / rate + 0.5 * Tr
  local function speed(t)
    if t < Tr then return V0 * math.sin(0.5 * math.pi * t / Tr) ^ 2 end
    return V0
  end
  local sim = mvmpm.sim {
    dim = 3, domain = {x = {-2 * h, 1 + 2 * h}, y = {0, 1}, z = {0, 1}}, cell = h, ppc = 1,
    t_end = t_end, shape = o.shape or "linear",
    sides = {left = "free", right = "free", bottom = "periodic", top = "periodic",
             back = "periodic", front = "periodic"},
    contact = {friction = 0.3, bond = true}}
  local grip = mvmpm.elastic {K = 1, G = 0.5, density = 0.1}
  local function drive(sign) return function(t) return 0, sign * speed(t), 0 end end
  sim:body {name = "left", shape = mvmpm.box {lo = {-2 * h, 0, 0}, hi = {0, 1, 1}},
            material = grip, driven = drive(-1)}
  sim:body {name = "right", shape = mvmpm.box {lo = {1, 0, 0}, hi = {1 + 2 * h, 1, 1}},
            material = grip, driven = drive(1)}
  local ball = sim:body {name = "ball", shape = mvmpm.ball {center = {0.5, 0.5, 0.5}, radius = 0.25},
                         material = mvmpm.elastic {K = 10, G = 5, density = 1}, bond = 1e9}
  local binder = sim:body {name = "binder", shape = mvmpm.rest(),
                           material = mvmpm.elastic {K = 1, G = 0.05, density = 1}, bond = 1e9}
  sim:contact(ball, binder, {friction = 0.3, bond = o.bond or true})
  if o.threads then  -- every particle field and energy, as hex floats
    sim.threads = o.threads
    sim:step(o.steps)
    local out, names = {}, sim:particles()
    table.sort(names)
    for _, nm in ipairs(names) do
      local f = sim:particles(nm)
      local ks = {}
      if #f > 0 then ks = {false} else for k in pairs(f) do ks[#ks + 1] = k end; table.sort(ks) end
      for _, k in ipairs(ks) do
        local t = k and f[k] or f
        for i = 1, #t do out[#out + 1] = string.format("%a", t[i]) end
      end
    end
    local e, ks = sim:energy(), {}
    for k in pairs(e) do if type(e[k]) == "number" then ks[#ks + 1] = k end end
    table.sort(ks)
    for _, k in ipairs(ks) do out[#out + 1] = string.format("%a", e[k]) end
    return table.concat(out, " "), sim.n
  end
  local r = {worst = 0, unbooked = 0}
  sim:every {steps = 1, fn = function(s)
    local e = s:energy()
    if s.t > 2 * Tr then  -- the grips up to speed
      r.worst = math.max(r.worst, math.abs(e.residual) / e.boundary_work)
      r.unbooked = math.max(r.unbooked, math.abs(e.residual + e.bonding) / e.boundary_work)
    end
  end}
  sim:run()
  r.e = sim:energy()
  return r
end

V.case "3-D bonded ball in a sheared binder: energy budget at 8, 12, 16 cells"
local loss, res = {}, {}
for k, c in ipairs {8, 12, 16} do
  local r = run {cells = c}
  local e = r.e
  V.above(string.format("%d cells: the grips did work", c), e.boundary_work, 0)
  V.below(string.format("%d cells: largest |residual| / work after the ramp", c), r.worst, 0.01)
  V.info(string.format("%d cells: ... without the bonded nodes' term (e.bonding)", c), r.unbooked)
  V.info(string.format("%d cells: e.bonding / work", c), e.bonding / e.boundary_work)
  V.near(string.format("%d cells: numerical = transfer + impact + bonding", c),
         e.numerical, e.transfer + e.impact + e.bonding, 1e-12 * e.boundary_work)
  V.near(string.format("%d cells: nothing debonded (strength 1e9)", c), e.debonded, 0, 0)
  loss[k], res[k] = e.bonding / e.boundary_work, r.worst
end
-- the loss is the fields' velocity differences at the bonded nodes,
-- which shrink with the cell
V.info("observed order of e.bonding / work, 8 -> 16 cells", math.log(loss[1] / loss[3]) / math.log(2))
V.info("observed order of the residual, 8 -> 16 cells", math.log(res[1] / res[3]) / math.log(2))

V.case "3-D bonded ball: GIMP, and a finite bond, at 12 cells"
do
  local r = run {cells = 12, shape = "gimp"}
  V.below("GIMP: largest |residual| / work after the ramp", r.worst, 0.01)
  V.info("GIMP: ... without the bonded nodes' term", r.unbooked)
  local f = run {cells = 12, bond = 0.001}
  V.above("bond 0.001: part of the interface let go (cuts)", f.e.debonded, 1)
  V.below("bond 0.001: largest |residual| / work after the ramp", f.worst, 0.01)
  V.info("bond 0.001: ... without the bonded nodes' term", f.unbooked)
end

V.case "3-D bonded ball: 1 and 2 threads give the same numbers"
do
  local one, n = run {cells = 16, threads = 1, steps = 30}
  local two = run {cells = 16, threads = 2, steps = 30}
  V.holds(string.format("2 threads: every field and energy bit for bit (%d particles)", n),
    one == two, one == two and 1 or 0)
end
