-- Heat (src/core/heat.c, src/core/conduct.c): sources, the temperature update and
-- conduction (docs/verification.md, "Heat").
--   (a) friction heat: a block thrown along a slab body (contact friction,
--       split 0.3 / 0.7) and along a frictional floor: the particles'
--       heat sum m c (T - T0) equals the friction work the budget booked,
--       and the block's share is the split, to 1e-10
--   (b) adiabatic plastic heating: a J2 block dropped on the floor, mean
--       temperature rise = beta W_p / (m c), and a Maxwell block's
--       heat = its viscous dissipation, to 1e-10
--   (c) conduction in one body: the erfc profile of a step (started at
--       t0 = 0.0025 from the exact solution), error at t1 = 0.0125
--   (d) the same across two bodies of conductivities 1 and 4 in perfect
--       thermal contact: the exact two-media solution (contact
--       temperature by effusivity)
--   (e) interface conductance between two blocks: the mean temperatures'
--       difference decays as exp(-2 h t / (rho c L)), within 2 %
--   (f) heat is passive when alpha = 0: the same scene with heat on and
--       off gives bit-identical motion, stresses and energies
-- (c)-(e) at three resolutions with the observed order, in GIMP and
-- quadratic B-splines.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

-- erfc to ~1e-7 (Numerical Recipes' Chebyshev fit form, written out)
local function erfc(x)
  local z = math.abs(x)
  local t = 1 / (1 + 0.5 * z)
  local r = t * math.exp(-z * z - 1.26551223 + t * (1.00002368 + t * (0.37409196 +
    t * (0.09678418 + t * (-0.18628806 + t * (0.27886807 + t * (-1.13520398 +
    t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))))
  return x >= 0 and r or 2 - r
end
local function erf(x) return 1 - erfc(x) end

local function order(e, n)
  return math.log(e[1] / e[3]) / math.log(n[3] / n[1])
end

-- sum m c (T - T0) over the particles of a body (all if b is nil)
local function heat_of(sim, c, T0, b)
  local T, m, body = sim:particles("temperature"), sim:particles("mass"), sim:particles("body")
  local E = 0
  for i = 1, #T do
    if not b or body[i] == b then E = E + m[i] * c * (T[i] - T0) end
  end
  return E
end

V.case "(a) friction heat = the budget's friction work (block on a slab, and on a floor)"
for _, n in ipairs {8, 16, 32} do
  local h = 1 / n
  local sim = mvmpm.sim {
    domain = {x = {0, 2}, y = {0, 1}}, cell = h, ppc = 2, shape = "gimp",
    update = "usavg", gravity = {0, -1}, t_end = 1, contact = {friction = 0.4},
    sides = {left = "periodic", right = "periodic", bottom = "wall", top = "wall"},
  }
  sim:heat {friction_split = 0.3}
  local steel = mvmpm.elastic {K = 400, G = 200, density = 1, cv = 2}
  local slab = sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {2, 0.5}},
                         material = steel, temperature = 300}
  local block = sim:body {name = "block", shape = mvmpm.rect {lo = {1, 0.5}, hi = {1.5, 0.75}},
                          material = steel, velocity = {1, 0}, temperature = 300}
  sim:run(0.25)
  local e = sim:energy()
  local E = heat_of(sim, 2, 300)
  V.near(string.format("on a slab, %d cells/unit: sum m c dT / friction work", n),
         E / e.dissipated, 1, 1e-10)
  -- the slab's field is the first: it takes 0.3, the block 0.7
  V.near(string.format("on a slab, %d cells/unit: block's share of it", n),
         heat_of(sim, 2, 300, 2) / E, 0.7, 1e-10)
  V.near(string.format("on a slab, %d cells/unit: heat_friction / friction work", n),
         e.heat_friction / e.dissipated, 1, 1e-10)
  V.info(string.format("on a slab, %d cells/unit: friction work", n), e.dissipated)
  -- sum m c T - sum m c T0 at T0 = 300 cancels about 5 of the digits
  V.below(string.format("on a slab, %d cells/unit: |heat residual| / heat", n),
          math.abs(e.heat_residual) / E, 1e-9)
end
for _, n in ipairs {5, 10, 20} do
  local sim = mvmpm.sim {
    domain = {x = {0, 3}, y = {0, 1}}, cell = 1 / n, ppc = 2, shape = "bspline2",
    gravity = {0, -1}, t_end = 1,
    sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = 0.3}, top = "wall"},
  }
  sim:heat {wall_friction = 0.75}
  local mat = mvmpm.elastic {K = 400, G = 200, density = 1, cv = 3}
  sim:body {shape = mvmpm.rect {lo = {1, 0}, hi = {2, 0.5}}, material = mat,
            velocity = {1, 0}, temperature = 20}
  sim:run(0.5)
  local e = sim:energy()
  V.near(string.format("on a floor, %d cells: sum m c dT / (0.75 friction work)", n),
         heat_of(sim, 3, 20) / (0.75 * e.dissipated), 1, 1e-10)
  V.near(string.format("on a floor, %d cells: heat_wall / (0.25 friction work)", n),
         e.heat_wall / (0.25 * e.dissipated), 1, 1e-10)
end

V.case "(b) adiabatic heating: plastic (beta = 0.8) and viscous"
for _, n in ipairs {8, 16, 32} do
  local sim = mvmpm.sim {
    domain = {x = {0, 3}, y = {0, 1.5}}, cell = 1 / n, ppc = 2, shape = "gimp",
    update = "usavg", t_end = 0.5,
    sides = {bottom = "wall", top = "wall", left = "wall", right = "wall"},
  }
  sim:heat {}
  local mat = mvmpm.plastic {K = 400, G = 200, density = 1, yield = 2, cv = 3, beta = 0.8}
  sim:body {shape = mvmpm.rect {lo = {1, 0.1}, hi = {2, 0.6}}, material = mat,
            velocity = {0, -2}, temperature = 10}
  sim:run(0.3)
  local e = sim:energy()
  local m, M = sim:particles("mass"), 0
  for i = 1, #m do M = M + m[i] end
  local rise = heat_of(sim, 3, 10) / (M * 3)
  V.near(string.format("plastic, %d cells: mean dT / (beta W_p / m c)", n),
         rise / (0.8 * e.plastic / (M * 3)), 1, 1e-10)
  V.near(string.format("plastic, %d cells: cold work / ((1 - beta) W_p)", n),
         e.cold_work / (0.2 * e.plastic), 1, 1e-10)
  V.info(string.format("plastic, %d cells: W_p", n), e.plastic)
end
for _, n in ipairs {8, 16, 32} do
  local sim = mvmpm.sim {
    domain = {x = {0, 3}, y = {0, 1.5}}, cell = 1 / n, ppc = 2, shape = "bspline2",
    t_end = 0.5, sides = {bottom = "wall", top = "wall", left = "wall", right = "wall"},
  }
  sim:heat {}
  local mat = mvmpm.viscoelastic {K = 400, G_inf = 50, prony = {{G = 150, tau = 0.02}},
                                  density = 1, cv = 5}
  sim:body {shape = mvmpm.rect {lo = {1, 0.1}, hi = {2, 0.6}}, material = mat,
            velocity = {0, -2}, temperature = 0}
  sim:run(0.3)
  local e = sim:energy()
  V.near(string.format("viscous, %d cells: sum m c dT / viscous dissipation", n),
         heat_of(sim, 5, 0) / e.viscous, 1, 1e-10)
end

-- a strip periodic in y, insulated ends; T0(x) given, particles' T
-- against the exact solution at the end
local function strip(o)
  local h = 1 / o.n
  local sim = mvmpm.sim {
    domain = {x = {0, o.L}, y = {0, 2 * h}}, cell = h, ppc = 2, shape = o.shape,
    sides = {left = "wall", right = "wall", bottom = "periodic", top = "periodic"},
  }
  sim:heat(o.heat or {})
  for _, b in ipairs(o.bodies) do
    sim:body {shape = mvmpm.rect {lo = {b.x0, 0}, hi = {b.x1, 2 * h}},
              material = mvmpm.elastic {K = 1, G = 1, density = 1, cv = 1, k = b.k},
              temperature = b.T, hold_temperature = b.hold}
  end
  sim:run(o.t)
  local T, x = sim:particles("temperature"), sim:particles("position")
  local e2, emax = 0, 0
  for i = 1, #T do
    local d = T[i] - o.exact(x.x[i])
    e2 = e2 + d * d
    emax = math.max(emax, math.abs(d))
  end
  local en = sim:energy()
  return math.sqrt(e2 / #T), emax, en, sim
end

local t0, t1 = 0.0025, 0.0125
local cells = {10, 20, 40}

V.case "(c) conduction in one body: erfc profile from t0 = 0.0025 to 0.0125 (D = 1)"
for _, shape in ipairs {"gimp", "bspline2"} do
  local errs = {}
  for k, n in ipairs(cells) do
    local rms, emax, en = strip {
      n = n, L = 2, shape = shape, t = t1 - t0,
      bodies = {{x0 = 0, x1 = 2, k = 1,
                 T = function(x) return 0.5 * erfc((x - 1) / (2 * math.sqrt(t0))) end}},
      exact = function(x) return 0.5 * erfc((x - 1) / (2 * math.sqrt(t1))) end}
    errs[k] = rms
    V.info(string.format("%s, %d cells: rms error / jump", shape, n), rms)
    V.info(string.format("%s, %d cells: max error / jump", shape, n), emax)
    V.below(string.format("%s, %d cells: |heat residual| (insulated: 0)", shape, n),
            math.abs(en.heat_residual), 1e-12)
    if n == 20 then V.below(string.format("%s, 20 cells: rms error / jump", shape), rms, 0.01) end
  end
  V.above(string.format("%s: observed order of the rms error", shape), order(errs, cells), 1.5)
end

V.case "(d) two bodies (k = 1 | k = 4) in perfect thermal contact"
-- medium 1 (x < 1, T = 1) and 2 (x > 1, T = 0), rho c = 1: the contact
-- temperature is (e1 T1 + e2 T2) / (e1 + e2) = 1/3 with e = sqrt(k rho c)
local Tc = 1 / 3
local function two(x, t)
  if x < 1 then return Tc + (1 - Tc) * erf((1 - x) / (2 * math.sqrt(t))) end
  return Tc * erfc((x - 1) / (2 * math.sqrt(4 * t)))
end
for _, shape in ipairs {"gimp", "bspline2"} do
  local errs = {}
  for k, n in ipairs(cells) do
    local rms, emax, en = strip {
      n = n, L = 3, shape = shape, t = t1 - t0,
      bodies = {{x0 = 0, x1 = 1, k = 1, T = function(x) return two(x, t0) end},
                {x0 = 1, x1 = 3, k = 4, T = function(x) return two(x, t0) end}},
      exact = function(x) return two(x, t1) end}
    errs[k] = rms
    V.info(string.format("%s, %d cells: rms error / jump", shape, n), rms)
    V.info(string.format("%s, %d cells: max error / jump", shape, n), emax)
    V.below(string.format("%s, %d cells: |heat residual|", shape, n),
            math.abs(en.heat_residual), 1e-12)
    if n == 20 then V.below(string.format("%s, 20 cells: rms error / jump", shape), rms, 0.01) end
  end
  V.above(string.format("%s: observed order of the rms error", shape), order(errs, cells), 1)
end

V.case "(e) interface conductance h = 0.1 between two blocks (k = 5: Biot 0.02)"
-- blocks [0, 1] at T = 1 and [1, 2] at T = 0, rho c = 1: the mean
-- temperatures' difference decays as exp(-2 h t / L) (lumped: Biot
-- h L / k = 0.02 adds about Bi / 3 to the time constant)
for _, shape in ipairs {"gimp", "bspline2"} do
  local errs, ecells = {}, {4, 8, 16}
  for k, n in ipairs(ecells) do
    local hc, tend = 0.1, 2
    local _, _, en, sim = strip {
      n = n, L = 2, shape = shape, t = tend, heat = {contact = {conductance = hc}},
      bodies = {{x0 = 0, x1 = 1, k = 5, T = 1}, {x0 = 1, x1 = 2, k = 5, T = 0}},
      exact = function() return 0 end}
    local T, body, m = sim:particles("temperature"), sim:particles("body"), sim:particles("mass")
    local s, w = {0, 0}, {0, 0}
    for i = 1, #T do s[body[i]] = s[body[i]] + m[i] * T[i]; w[body[i]] = w[body[i]] + m[i] end
    local dT = s[1] / w[1] - s[2] / w[2]
    local ref = math.exp(-2 * hc * tend)
    -- the quasi-steady parabolic profile in each block adds L / (3 k)
    -- to each side's resistance: rate 2 / (L (1 / h + 2 L / (3 k)))
    local refb = math.exp(-2 / (1 / hc + 2 / 15) * tend)
    errs[k] = math.abs(dT / refb - 1)
    V.near(string.format("%s, %d cells: dT(t) / exp(-2 h t / rho c L)", shape, n), dT / ref, 1, 0.02)
    V.info(string.format("%s, %d cells: dT(t) / the same with Biot's term - 1", shape, n), dT / refb - 1)
    V.below(string.format("%s, %d cells: |heat residual|", shape, n), math.abs(en.heat_residual), 1e-12)
  end
  V.info(string.format("%s: observed order of the error against Biot's", shape), order(errs, ecells))
end

V.case "(g) a wall at a fixed temperature, a held body, a heat-transfer coefficient"
-- a wall at T = 1 on x = 0 (or a body [0, 0.5] held at 1) against a
-- strip that starts from the exact solution at t0: erfc(x / 2 sqrt(D t))
for _, shape in ipairs {"gimp", "bspline2"} do
  local ew, eh = {}, {}
  for k, n in ipairs(cells) do
    local rms, _, en = strip {
      n = n, L = 2, shape = shape, t = t1 - t0, heat = {sides = {left = {temperature = 1}}},
      bodies = {{x0 = 0, x1 = 2, k = 1, T = function(x) return erfc(x / (2 * math.sqrt(t0))) end}},
      exact = function(x) return erfc(x / (2 * math.sqrt(t1))) end}
    ew[k] = rms
    V.info(string.format("%s, %d cells: wall at T = 1: rms error", shape, n), rms)
    V.below(string.format("%s, %d cells: wall: |heat residual|", shape, n), math.abs(en.heat_residual), 1e-12)
    V.info(string.format("%s, %d cells: wall: heat in", shape, n), en.heat_boundary)
    local rmsh, _, enh, simh = strip {
      n = n, L = 2.5, shape = shape, t = t1 - t0, hold = true,
      bodies = {{x0 = 0, x1 = 0.5, k = 1, hold = 1},
                {x0 = 0.5, x1 = 2.5, k = 1,
                 T = function(x) return erfc((x - 0.5) / (2 * math.sqrt(t0))) end}},
      exact = function(x) return x < 0.5 and 1 or erfc((x - 0.5) / (2 * math.sqrt(t1))) end}
    eh[k] = rmsh
    V.info(string.format("%s, %d cells: held body at T = 1: rms error", shape, n), rmsh)
    V.below(string.format("%s, %d cells: held: |heat residual|", shape, n), math.abs(enh.heat_residual), 1e-12)
    -- the heat in: 2 sqrt(D / pi) (sqrt(t1) - sqrt(t0)) per unit area, x 2 h of strip
    local q = 2 * math.sqrt(1 / math.pi) * (math.sqrt(t1) - math.sqrt(t0)) * 2 / n
    V.info(string.format("%s, %d cells: held: heat in / exact", shape, n), enh.heat_boundary / q)
    -- first order: the wall's nodes, not the material's face, are held
    -- (1.6 % / 2.6 % at 20 cells, GIMP / B-splines; docs/verification.md)
    if n == 20 then
      V.below(string.format("%s, 20 cells: wall: rms error", shape), rms, 0.03)
      V.below(string.format("%s, 20 cells: held body: rms error", shape), rmsh, 0.03)
    end
  end
  V.above(string.format("%s: wall: observed order", shape), order(ew, cells), 1)
  V.above(string.format("%s: held body: observed order", shape), order(eh, cells), 1)
end
-- a block [0, 1] at T = 1 cooled through the left wall, h = 0.1 to 0:
-- its mean temperature decays as exp(-h t / (rho c L)) (Biot 0.02)
for _, shape in ipairs {"gimp", "bspline2"} do
  for _, n in ipairs {4, 8, 16} do
    local tend, hw = 3, 0.1
    local _, _, en, sim = strip {
      n = n, L = 1, shape = shape, t = tend, heat = {sides = {left = {h = hw, ambient = 0}}},
      bodies = {{x0 = 0, x1 = 1, k = 5, T = 1}}, exact = function() return 0 end}
    local T, m, s, w = sim:particles("temperature"), sim:particles("mass"), 0, 0
    for i = 1, #T do s = s + m[i] * T[i]; w = w + m[i] end
    V.near(string.format("%s, %d cells: film: mean T / exp(-h t / rho c L)", shape, n),
           s / w / math.exp(-hw * tend), 1, 0.02)
    V.info(string.format("%s, %d cells: film: the same with Biot's term - 1", shape, n),
           s / w / math.exp(-tend / (1 / hw + 1 / 15)) - 1)
    V.below(string.format("%s, %d cells: film: |heat residual|", shape, n), math.abs(en.heat_residual), 1e-12)
  end
end

V.case "(f) heat is passive with alpha = 0: motion and energies bit-identical with heat on and off"
local function slide(heat)
  local sim = mvmpm.sim {
    domain = {x = {0, 4}, y = {0, 1.5}}, cell = 0.1, ppc = 2, shape = "gimp",
    update = "usavg", gravity = {0, -1}, t_end = 1, contact = {friction = 0.4},
    sides = {left = "periodic", right = "periodic", bottom = {"wall", friction = 0.2}, top = "wall"},
  }
  if heat then sim:heat {} end
  local mat = mvmpm.plastic {K = 400, G = 200, density = 1, yield = 5, cv = 2, k = 0.5}
  sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {4, 0.5}}, material = mat, velocity = {0.3, 0}}
  sim:body {shape = mvmpm.rect {lo = {1, 0.5}, hi = {1.5, 0.75}}, material = mat, velocity = {1, -0.5}}
  sim:run(0.3)
  return sim
end
local off, on = slide(false), slide(true)
local diff = 0
for _, f in ipairs {"position", "velocity", "stress"} do
  local a, b = off:particles(f), on:particles(f)
  for c, arr in pairs(a) do
    for i = 1, #arr do if arr[i] ~= b[c][i] then diff = diff + 1 end end
  end
end
V.holds("particles whose position, velocity or stress differ", diff == 0, diff)
local eo, en = off:energy(), on:energy()
V.holds("kinetic, friction, plastic work equal to the bit",
        eo.kinetic == en.kinetic and eo.dissipated == en.dissipated and eo.plastic == en.plastic,
        en.kinetic - eo.kinetic)
V.above("heat on: the thermal energy the particles took", en.thermal_energy, 0.5 * (en.dissipated + en.plastic))

V.case "(i) a disc (R = 0.5, D = 1) at 0 whose surface is held at 1 by a held annulus, t = 0.1"
-- T(r, t) = 1 - sum 2 J0(l_n r / R) / (l_n J1(l_n)) exp(-l_n^2 D t / R^2),
-- l_n the zeros of J0 (three terms: the fourth is below 1e-9 here)
local function J0(x)
  local s, t = 0, 1
  for k = 1, 40 do s = s + t; t = -t * (x / 2) ^ 2 / (k * k) end
  return s
end
local zeros = {{2.404825557695773, 0.5191474972894669}, {5.520078110286311, -0.3402648065731330},
               {8.653727912911013, 0.2714522999283819}}
local function disc_T(r, t)
  local T = 1
  for _, z in ipairs(zeros) do
    T = T - 2 * J0(z[1] * r / 0.5) / (z[1] * z[2]) * math.exp(-z[1] ^ 2 * t / 0.25)
  end
  return T
end
do
  local errs, dc = {}, {10, 20, 40}
  for k, n in ipairs(dc) do
    local sim = mvmpm.sim {domain = {x = {-0.75, 0.75}, y = {-0.75, 0.75}}, cell = 1 / n,
                           shape = "gimp", sides = "free"}
    sim:heat {}
    local m = mvmpm.elastic {K = 1, G = 1, density = 1, cv = 1, k = 1}
    sim:body {shape = mvmpm.disk {center = {0, 0}, radius = 0.5}, material = m, temperature = 0}
    sim:body {shape = mvmpm.annulus {center = {0, 0}, inner = 0.5, outer = 0.7}, material = m,
              hold_temperature = 1, overlap = "skip"}
    sim:run(0.1)
    local T, x, b = sim:particles("temperature"), sim:particles("position"), sim:particles("body")
    local e2, np = 0, 0
    for i = 1, #T do
      if b[i] == 1 then
        local d = T[i] - disc_T(math.sqrt(x.x[i] ^ 2 + x.y[i] ^ 2), 0.1)
        e2 = e2 + d * d; np = np + 1
      end
    end
    errs[k] = math.sqrt(e2 / np)
    V.info(string.format("%d cells per unit: rms error over the disc", n), errs[k])
    V.below(string.format("%d cells per unit: |heat residual| / heat in", n),
            math.abs(sim:energy().heat_residual) / sim:energy().heat_boundary, 1e-12)
  end
  V.below("20 cells per unit (10 across the radius): rms error", errs[2], 0.03)
  V.above("observed order", order(errs, dc), 1)
end

V.case "(h) threads: a frictional, plastic, conducting scene with 1 and 2 threads"
local function th(n)
  local sim = mvmpm.sim {
    domain = {x = {0, 2}, y = {0, 1}}, cell = 0.1, ppc = 2, shape = "gimp", threads = n,
    gravity = {0, -1}, t_end = 1, contact = {friction = 0.3},
    sides = {left = "wall", right = "wall", bottom = {"wall", friction = 0.2}, top = "wall"},
  }
  sim:heat {contact = {conductance = 2}, sides = {left = {temperature = 400}}}
  local mat = mvmpm.plastic {K = 400, G = 200, density = 1, yield = 5, cv = 2, k = 0.05, alpha = 1e-4}
  sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {2, 0.3}}, material = mat, temperature = 300}
  sim:body {shape = mvmpm.rect {lo = {0.5, 0.3}, hi = {1, 0.6}}, material = mat,
            velocity = {1, -0.5}, temperature = 300}
  sim:body {shape = mvmpm.rect {lo = {1.3, 0.3}, hi = {1.5, 0.5}}, material = mat, hold_temperature = 500}
  sim:run(0.2)
  return sim
end
local t1s, t2s = th(1), th(2)
local T1, T2, nd = t1s:particles("temperature"), t2s:particles("temperature"), 0
for i = 1, #T1 do if T1[i] ~= T2[i] then nd = nd + 1 end end
V.holds("particles whose temperature differs (1 vs 2 threads)", nd == 0, nd)
V.holds("thermal energy equal to the bit", t1s:energy().thermal_energy == t2s:energy().thermal_energy,
        t2s:energy().thermal_energy - t1s:energy().thermal_energy)
