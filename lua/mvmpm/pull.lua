-- mvmpm.pull: the cohesive law on scenarios/bond_pull.lua, measured;
-- shared by tests/verify/cohesive.lua, studies/cohesive.lua and
-- docs/figures/cohesive.lua.
--
-- Two blocks in uniaxial strain (periodic top and bottom), 1 long each,
-- pulled apart by grips at V0 = 0.0002 / 3 after a ramp of 8 (slow
-- enough that the bars' ringing about the quasi-static curve shrinks
-- with the cell: at three times that speed it stays at 4 % of the
-- strength from 24 cells on), the interface between cells (shift 0.3 of
-- a cell).  Reference, quasi-static: the pair is one bar of stiffness
-- M / L per block (M = K + 4G/3, L = 1) until the traction reaches the
-- strength sigma at grip travel u = sigma L / M (each grip); then the
-- bars unload as the opening delta = 2u - 2 L t / M grows, with
-- t = sigma (1 - delta / delta_c), delta_c = 2 G_c / sigma:
--   t(u) = sigma (1 - 2u / delta_c) / (1 - 2 sigma L / (M delta_c)),
-- zero from 2u = delta_c on (no snap-back, as delta_c > 2 sigma L / M).
-- The work of separation booked (sim:energy().cohesion) must reach G_c
-- times the interface's area, 0.5 (unit depth), whatever the grid.
local mvmpm = require "mvmpm"

local P = {M = 1 + 4 * 0.5 / 3, V0 = 0.0002 / 3, T = 8, sigma = 0.005, dc = 0.01, area = 0.5}
P.gc = 0.5 * P.sigma * P.dc

-- each grip's travel at time t
function P.u(t)
  return t < P.T and P.V0 * t * t / (2 * P.T) or P.V0 * (P.T / 2 + (t - P.T))
end

-- the quasi-static traction at grip travel u (energy 0: brittle, it drops
-- to zero at the strength)
function P.tref(u, gc)
  gc = gc or P.gc
  if u <= P.sigma / P.M then return P.M * u end
  if not (gc > 0) then return 0 end
  local dc = 2 * gc / P.sigma
  return math.max(0, P.sigma * (1 - 2 * u / dc) / (1 - 2 * P.sigma / (P.M * dc)))
end

-- the smallest gap between block A's and block B's particles beyond
-- their spacing, in cells (negative: they overlap)
function P.gap(sim, cells)
  local x, body = sim:particles("position"), sim:particles("body")
  local amax, bmin = -1e9, 1e9
  for i = 1, #x.x do
    if body[i] == 2 then amax = math.max(amax, x.x[i])
    elseif body[i] == 3 then bmin = math.min(bmin, x.x[i]) end
  end
  return (bmin - amax) * cells - 0.5
end

-- o: cells, shape, transfer, energy (default P.gc), dim (3: the blocks 0.25 deep,
-- the area 0.125), run (a study's clock.run).
-- Returns w (work of separation / G_c A), curve (mean |grip traction -
-- quasi-static| / sigma over 12 windows, each a tenth of the softening's
-- time, from the peak, u = sigma L / M, to past its end, 2u = delta_c),
-- res (residual / work put in), late (|mean traction| / sigma once
-- apart, over the last 20 % of the run: the bars ring with what the
-- softening left in them, about that mean), gap (the smallest gap
-- between the blocks' particles beyond their spacing, in cells), onset
-- (grip travel at the first cut / sigma L / M), bad (a NaN in the
-- energy), us / ts (the windows' mid travel and mean traction) and sim
function P.run(o)
  local gc = o.energy or P.gc
  -- the peak and the end of the softening, in time
  local t1 = P.sigma / P.M / P.V0 + P.T / 2
  local t2 = P.dc / 2 / P.V0 + P.T / 2
  local w, tend = (t2 - t1) / 10, t2 + 0.5 * (t2 - t1)
  local sim = mvmpm.load("scenarios/bond_pull.lua", {strength = P.sigma, energy = gc,
    cells = o.cells, shape = o.shape, transfer = o.transfer, update = o.update, V0 = P.V0, shift = 0.3, t_end = tend, dim = o.dim})
  local area = P.area * (o.dim == 3 and 0.25 or 1)
  local run = o.run or function(s, t) s:run(t) end
  local grip
  for _, b in ipairs(sim:bodies()) do if b.name == "gripR" then grip = b end end
  local sum, k, late, nl, bad, first = 0, 0, 0, 0, false, nil
  local tlate = tend - 0.2 * (tend - t2 - w)
  sim:every {steps = 1, fn = function(s)
    local tr = grip:force() / area
    sum, k = sum + tr, k + 1
    if s.t > tlate then late, nl = late + tr, nl + 1 end
    local e = s:energy()
    if not first and e.debonded > 0 then first = P.u(s.t) / (P.sigma / P.M) end
    if e.total ~= e.total then bad = true end
  end}
  run(sim, t1)
  local err, n, us, ts = 0, 0, {}, {}
  for i = 1, 12 do
    sum, k = 0, 0
    run(sim, t1 + i * w)
    local u = P.u(t1 + (i - 0.5) * w)
    us[#us + 1], ts[#ts + 1] = u, sum / k
    err, n = err + math.abs(sum / k - P.tref(u, gc)) / P.sigma, n + 1
  end
  run(sim, tend)
  local e = sim:energy()
  return {w = gc > 0 and e.cohesion / (gc * area) or e.cohesion, curve = err / n,
          res = e.residual / e.boundary_work, late = math.abs(late / nl) / P.sigma,
          gap = P.gap(sim, o.cells), onset = first, bad = bad,
          us = us, ts = ts, sim = sim}
end

return P
