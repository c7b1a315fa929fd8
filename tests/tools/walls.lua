-- tests/tools/walls.lua: checks the wall rules share, loaded by the
-- verification files with dofile (run from the project's root).
local W = {}

-- The bounce's first flight (scenarios/cylinder_bounce.lua): the disc's
-- spin averaged over t = 8 .. 16, a sample per time unit (it rings after
-- the impact), and its x velocity at t = 10 (the restitution's).
function W.flight1(sim, disc)
  local sum, n, vx = 0, 0, nil
  for t = 8, 16 do
    sim:run(t)
    sum, n = sum + disc:omega(), n + 1
    if t == 10 then vx = disc:velocity() end
  end
  return sum / n, vx
end

-- The report's frictionless bounce (scenarios/cylinder_bounce.lua) under
-- wall rule `rule`, with the scene's parameters o (speed scales the
-- times): E/E0 - 1 after the first impact (t = 10 at speed 0.1) and after
-- three (t = 36), the first impact's restitution, the particle moves held
-- at a wall line, the budget's residual over E0, and the sim.
function W.bounce(mvmpm, cells, rule, o)
  local p = {cells = cells, t_end = 36, wall_contact = rule}
  for k, v in pairs(o or {}) do p[k] = v end
  local speed = p.speed or 0.1
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", p)
  local disc = sim:bodies()[1]
  local e0 = sim:energy().total
  sim:run(10 * 0.1 / speed)
  local r = {first = sim:energy().total / e0 - 1, rest = -disc:diag().vx / speed}
  sim:run(36 * 0.1 / speed)
  local e = sim:energy()
  r.three, r.held, r.residual = e.total / e0 - 1, e.wall_held, e.residual / e0
  r.sim = sim
  return r
end

-- A disc thrown around a box of walls (four impacts): the walls' forces
-- are the only external ones, so the momentum's change is their impulse,
-- sum of sim:wall_force dt, to round-off without a mass cutoff (with the
-- default cutoff, the dropped nodes' share of the stresses' forces leaks:
-- printed).  rule: sim.wall_contact.
function W.momentum(mvmpm, V, rule)
  for _, cut in ipairs {0, 1e-9} do
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 16, sides = "wall",
                           t_end = 4, wall_contact = rule, mass_cutoff = cut}
    local b = sim:body {shape = mvmpm.disk {center = {0.7, 0.4}, radius = 0.2},
                        material = mvmpm.elastic {K = 10, G = 5, density = 1}, velocity = {0.4, -0.3}}
    local m = b:mass()
    local px0, py0 = b:diag().vx * m, b:diag().vy * m
    local ix, iy, worst, tot = 0, 0, 0, 0
    sim:every {steps = 1, fn = function(s)
      for _, side in ipairs {"left", "right", "bottom", "top"} do
        local wx, wy = s:wall_force(side)
        ix, iy = ix + wx * s.dt, iy + wy * s.dt
        tot = tot + (math.abs(wx) + math.abs(wy)) * s.dt
      end
      local d = b:diag()
      worst = math.max(worst, math.abs(d.vx * m - px0 - ix), math.abs(d.vy * m - py0 - iy))
    end}
    sim:run()
    -- four impacts, each about 2 m v: the impulses' total is no small number
    V.above("sum of the walls' |impulses| / (m v0), mass_cutoff " .. cut, tot / (m * 0.5), 2)
    local what = string.format("mass_cutoff %g: max |momentum change - impulse| / (m v0)", cut)
    if cut == 0 then V.below(what, worst / (m * 0.5), 1e-9)
    else V.info(what, worst / (m * 0.5)) end
  end
end

-- What a rule of springs at the walls refuses, each naming what is
-- wrong: friction (naming the side), a smoothing transfer, a FLIP
-- fraction below 1 at construction and later, a stiffness out of range.
-- Returns refused(o, pat) for the rule's own checks.
function W.refusals(mvmpm, V, rule)
  local function refused(o, pat)
    local p = {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, wall_contact = rule}
    for k, v in pairs(o) do p[k] = v end
    local ok, msg = pcall(mvmpm.sim, p)
    return not ok and msg:find(pat, 1, true) ~= nil, msg
  end
  V.holds(string.format("a %s wall with friction is refused, naming the side", rule),
          (refused({sides = {"wall", friction = 0.2}}, "side 'left' has friction 0.2")))
  V.holds(string.format("a smoothing transfer (APIC) with %s walls is refused", rule),
          (refused({shape = "bspline2", transfer = "apic"}, "needs pure FLIP")))
  V.holds(string.format("a FLIP fraction below 1 with %s walls is refused", rule),
          (refused({flip = 0.99}, "needs pure FLIP")))
  local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, wall_contact = rule, sides = "wall"}
  local ok, msg = pcall(function() s.flip = 0.99 end)
  V.holds("setting sim.flip below 1 later is refused too", not ok and msg:find("'flip' must be 1", 1, true) ~= nil)
  V.holds("wall_stiffness out of range is refused, naming the range",
          (refused({wall_stiffness = 20}, "'wall_stiffness' must be in [0.01, 16]")))
  return refused
end

return W
