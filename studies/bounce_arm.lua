-- Study: the frictional bounce's spins and the rigid model's arm.  The
-- report's frictional bounce (scenarios/cylinder_bounce.lua, mu = 0.1) is
-- held against a rigid disc (the impulse model of
-- tests/verify/cylinder_bounce.lua: Coulomb impulse mu (1 + e) m v_n at
-- the contact, R from the centre, I = m R^2 / 2, e the run's restitution).
-- The report's disc is soft (K = 1, G = 0.5, struck at 0.08 of its wave
-- speed) and flattens against the wall, so friction turns it about a
-- shorter arm than R.  Measured here, per impact: the friction impulse's
-- mean arm, sum_steps F_t (x_wall - x_c) dt / sum_steps F_t dt, from the
-- wall's force (sim:wall_force) and the disc's centroid at each step; the
-- largest indentation R - (x_wall - x_c); the spin (mean over the flight
-- after the impact, a sample per time unit) over the rigid model's.  The
-- same for a disc 100 times stiffer (K = 100, G = 50), whose indentation
-- is about 1 % of R, so that the rigid model is its limit.  Wall rules:
-- the defaults ("auto": per patch here), "node" and "couple"; and GIMP
-- with the defaults on the report's disc, a second shape.
--
--   ./mvmpm test studies/bounce_arm.lua    (STUDY_QUICK=1: to 32 cells)
-- writes docs/figures/bounce_arm.png.
local mvmpm = require "mvmpm"

local quick = os.getenv("STUDY_QUICK") == "1"
local mu, R = 0.1, 0.5

-- the rigid disc's spin after an impact with restitution e, sliding
-- throughout (mu < slip / (3 (1 + e) v_n) at both impacts here): the
-- Coulomb impulse per unit mass mu (1 + e) v_n at arm R over R^2 / 2
local function rigid(vn, e) return 2 * mu * (1 + e) * vn / R end

-- one run to t = 28: impacts 1 (right wall, about t = 5) and 2 (top wall,
-- about t = 17), flights t = 8..16 and 20..28
local function run(cells, o)
  local p = {cells = cells, friction = mu, t_end = 28}
  for k, v in pairs(o) do p[k] = v end
  local sim = mvmpm.load("scenarios/cylinder_bounce.lua", p)
  local disc = sim:bodies()[1]
  local acc = {{j = 0, m = 0, dmax = 0}, {j = 0, m = 0, dmax = 0}}
  sim:every {steps = 1, fn = function(s)
    local d = disc:diag()
    local fxr, fyr = s:wall_force("right")
    local fxt, fyt = s:wall_force("top")
    -- the tangential force at the wall line, the normal one, the arm
    -- from the wall to the centroid
    for k, f in ipairs {{fyr, fxr, 3 - d.x}, {fxt, fyt, 3 - d.y}} do
      local ft, fn, arm = f[1], f[2], f[3]
      if fn ~= 0 then
        acc[k].j = acc[k].j + ft * s.dt
        acc[k].m = acc[k].m + ft * arm * s.dt
        acc[k].dmax = math.max(acc[k].dmax, R - arm)
      end
    end
  end}
  local spin, v = {0, 0}, {}
  local c0 = mvmpm.cpu()
  for t = 1, 28 do
    sim:run(t)
    local d = disc:diag()
    if t >= 8 and t <= 16 then spin[1] = spin[1] + d.omega / 9 end
    if t >= 20 then spin[2] = spin[2] + d.omega / 9 end
    if t == 10 or t == 20 then v[t] = d end
  end
  local e1, e2 = -v[10].vx / 0.1, -v[20].vy / v[10].vy
  -- impact 1: the disc slides up the right wall, friction turns it
  -- clockwise (omega < 0); impact 2: it slides left along the top wall,
  -- friction turns it the same way
  local w1 = -rigid(0.1, e1)
  local w2 = w1 - rigid(v[10].vy, e2)
  -- impact 2 as the test reads it: the spin after it over the model's
  return {e = {e1, e2}, q = {spin[1] / w1, spin[2] / w2},
          arm = {acc[1].m / acc[1].j / R, acc[2].m / acc[2].j / R},
          dmax = {acc[1].dmax / R, acc[2].dmax / R}, cpu = mvmpm.cpu() - c0}
end

local sets = {
  {label = "K = 1, defaults", K = 1, o = {}},
  {label = "K = 1, node", K = 1, o = {shape = "bspline2", wall_contact = "node"}},
  {label = "K = 1, couple", K = 1, o = {wall_contact = "couple"}},
  {label = "K = 1, GIMP defaults", K = 1, o = {shape = "gimp"}},
  {label = "K = 100, defaults", K = 100, o = {}},
  {label = "K = 100, node", K = 100, o = {shape = "bspline2", wall_contact = "node"}},
  {label = "K = 100, couple", K = 100, o = {wall_contact = "couple"}},
}
local series, arms = {}, {}
for _, st in ipairs(sets) do
  local cells = {8, 16, 32}
  if st.K == 1 and not quick then cells[4] = 64 end
  local x, y, arm = {}, {}, {}
  for _, c in ipairs(cells) do
    local o = {K = st.K, G = st.K / 2}
    for k, val in pairs(st.o) do o[k] = val end
    local r = run(c, o)
    print(string.format("%-22s %2d cells: restitution %.3f / %.3f  arm/R %.4f / %.4f  indentation/R %.4f / %.4f  spin/rigid %.4f / %.4f  (%.1f s CPU)",
      st.label, c, r.e[1], r.e[2], r.arm[1], r.arm[2], r.dmax[1], r.dmax[2], r.q[1], r.q[2], r.cpu))
    x[#x + 1], y[#y + 1], arm[#arm + 1] = c, r.q[1], r.arm[1]
  end
  series[#series + 1] = {x = x, y = y, label = st.label, style = "both"}
  if st.label:find("defaults", 1, true) and not st.label:find("GIMP", 1, true) then
    arms[#arms + 1] = {x = x, y = arm, label = string.format("K = %g: friction's arm / R", st.K),
                       style = "line"}
  end
end
for _, a in ipairs(arms) do series[#series + 1] = a end
mvmpm.plot {file = "docs/figures/bounce_arm.png",
            title = "Frictional bounce: spin after impact 1 over the rigid model",
            xlabel = "cells across the disc", ylabel = "spin / rigid model (arm R); arm / R",
            xlog = true, series = series}
