-- The contact cases of docs/verification.md that the normals' figures
-- (contact.lua) leave out, each against the resolution.  Run by
-- `make figures` (a few minutes).
--   contact_rolling.png  a disc on an incline that is the floor wall
--                        (lua/mvmpm/incline.lua): |a / a_ref - 1| rolling
--                        (25 deg, mu 0.5) and |alpha / alpha_ref - 1|
--                        sliding (30 deg, mu 0.1), linear hats, per wall
--                        rule, at 8, 16, 32 cells per diameter
--   contact_pack.png     the piston pack (lua/mvmpm/piston.lua): the
--                        budget's |residual| over the piston's work per
--                        transfer scheme at 2, 3, 4, 6 cells per smallest
--                        diameter
--   contact_pack_friction.png  the friction work over the piston's work,
--                        the same runs
--   contact_onset.png    the concentric cylinders' debond onset over the
--                        plane-strain Lame value at 25, 35, 50 cells
--                        across the domain, per bond traction, on
--                        linear hats and B-splines (the default shape)
--   contact_friction_work.png  a disc thrown along a frictional floor
--                        (lua/mvmpm/slide.lua): |friction work / the
--                        rigid disc's - 1| at 8, 16, 32 cells per
--                        diameter, per wall rule and scheme
--   contact_body_patch.png  the same disc on a driven slab (contact
--                        between bodies): friction work, and rolling down
--                        an incline that is the slab, per body_contact
local mvmpm = require "mvmpm"
local I = require "mvmpm.incline"
local P = require "mvmpm.piston"
local S = require "mvmpm.slide"
local lame = require "mvmpm.lame"
local dir = arg and arg[1] or "docs/figures"

-- a zero error cannot be drawn on a log axis: the floor of the plot
local function floor(e) return math.max(e, 1e-4) end

-- the disc on the incline, per wall rule
do
  local series = {}
  for _, rule in ipairs {"node", "patch", "couple"} do
    local x, yr, ys = {}, {}, {}
    for _, c in ipairs {8, 16, 32} do
      local th = math.rad(25)
      local r = I.run {cells = c, deg = 25, mu = 0.5, wall_contact = rule, shape = "linear"}
      local s = I.run {cells = c, deg = 30, mu = 0.1, wall_contact = rule, shape = "linear"}
      local ar = 2 / 3 * math.sin(th)
      local sr = 2 * 0.1 * math.cos(math.rad(30)) / I.R
      x[#x + 1] = c
      yr[#yr + 1], ys[#ys + 1] = floor(math.abs(r.a / ar - 1)), floor(math.abs(s.alpha / sr - 1))
      print(string.format("incline %-6s %2d cells: rolling a/ref %.4f, sliding spin-up/ref %.4f",
                          rule, c, r.a / ar, s.alpha / sr))
    end
    series[#series + 1] = {x = x, y = yr, style = "both", label = "rolling a, " .. rule}
    series[#series + 1] = {x = x, y = ys, style = "both", label = "sliding spin-up, " .. rule}
  end
  mvmpm.plot {file = dir .. "/contact_rolling.png", xlog = true, ylog = true,
              title = "Disc on an incline (the floor wall), linear hats",
              xlabel = "cells per diameter", ylabel = "|measured / reference - 1|", series = series}
end

-- the piston pack, per transfer scheme
do
  local res, fric = {}, {}
  for _, sc in ipairs(S.schemes) do
    local x, yr, yf = {}, {}, {}
    for _, c in ipairs {2, 3, 4, 6} do
      local e, w = P.run {cells = c, scheme = sc, mu = 0.3}
      x[#x + 1], yr[#yr + 1], yf[#yf + 1] = c, floor(math.abs(e.residual / w)), e.dissipated / w
      print(string.format("piston pack %-18s %d cells: residual %+.4f, friction %.4f", S.name(sc), c,
                          e.residual / w, e.dissipated / w))
    end
    res[#res + 1] = {x = x, y = yr, style = "both", label = S.name(sc)}
    fric[#fric + 1] = {x = x, y = yf, style = "both", label = S.name(sc)}
  end
  mvmpm.plot {file = dir .. "/contact_pack.png", xlog = true, ylog = true,
              title = "Piston pack, 30 discs, mu 0.3: energy budget",
              xlabel = "cells per smallest diameter", ylabel = "|residual| / piston work",
              series = res}
  mvmpm.plot {file = dir .. "/contact_pack_friction.png", xlog = true,
              title = "Piston pack, 30 discs, mu 0.3: friction work",
              xlabel = "cells per smallest diameter", ylabel = "friction work / piston work",
              series = fric}
end

-- the concentric cylinders' onset, per bond traction (the scene of
-- studies/concentric_onset.lua, run to the first cut)
do
  local K, G, alpha, rate, a, b, sb = 1, 0.5, 1, 4e-4, 0.2, 0.4, 0.005
  local dTc = sb / (lame.unit(K, G, a, b) * alpha)
  local function onset(n, traction, shape)
    local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / n, t_end = 2 * dTc / rate,
      shape = shape,
      sides = "free", bond_traction = traction, bond_length = traction == "fit" and 0.12 or nil}
    local core = mvmpm.elastic {K = K, G = G, density = 1, alpha = alpha, name = "core"}
    local shell = mvmpm.elastic {K = K, G = G, density = 1, alpha = 0, name = "shell"}
    sim:body {name = "inner", shape = mvmpm.disk {center = {0.5, 0.5}, radius = a},
              material = core, bond = sb}
    sim:body {name = "outer", shape = mvmpm.annulus {center = {0.5, 0.5}, inner = a, outer = b},
              material = shell, bond = sb}
    sim:temperature(function(t) return -rate * t end)
    local first
    sim:every {steps = 1, fn = function(x)
      if not first and x:energy().debonded > 0 then first = x.t end
    end}
    while not first and sim.t < 1.5 * dTc / rate do sim:run(sim.t + 0.5) end
    return first and rate * first / dTc or 0 / 0
  end
  local series = {}
  for _, shape in ipairs {"linear", "bspline2"} do
    for _, tr in ipairs {"mixture", "fit"} do
      local x, y = {}, {}
      for _, n in ipairs {25, 35, 50} do
        local q = onset(n, tr, shape)
        x[#x + 1], y[#y + 1] = n, q
        print(string.format("concentric onset %-8s %-7s %d cells: onset / Lame %.4f", shape, tr, n, q))
      end
      series[#series + 1] = {x = x, y = y, style = "both", label = shape .. ", " .. tr}
    end
  end
  series[#series + 1] = {x = {25, 50}, y = {1.03, 1.03}, style = "line", label = "+3 %"}
  series[#series + 1] = {x = {25, 50}, y = {0.97, 0.97}, style = "line", label = "-3 %"}
  mvmpm.plot {file = dir .. "/contact_onset.png",
              title = "Concentric cylinders: debond onset per shape and bond traction",
              xlabel = "cells across the domain", ylabel = "onset / Lame onset", series = series}
end
print("contact cases: pictures in " .. dir)

-- the disc thrown along the floor: friction work against the rigid
-- disc's, per wall rule and scheme (tests/verify/friction_work.lua)
do
  local series = {}
  local cases = {
    {"node", {shape = "linear", transfer = "flip", flip = 1}},
    {"couple", {shape = "linear", transfer = "flip", flip = 1}},
    {"patch", {shape = "linear", transfer = "flip", flip = 1}},
    {"patch", {shape = "gimp", transfer = "apic"}},
    {"patch", {shape = "bspline2", transfer = "flip", flip = 1}},
    {"patch", {shape = "linear", transfer = "xpic"}},
  }
  for _, k in ipairs(cases) do
    local x, y = {}, {}
    for _, c in ipairs {8, 16, 32} do
      local r = S.run {cells = c, scheme = k[2], mu = 0.3, T = 2, n = 40, wall_contact = k[1]}
      x[#x + 1], y[#y + 1] = c, floor(math.abs(r.e.dissipated / r.rigid - 1))
      print(string.format("friction work %-6s %-14s %2d cells: W / W_rigid %.4f", k[1], S.name(k[2]), c,
                          r.e.dissipated / r.rigid))
    end
    series[#series + 1] = {x = x, y = y, style = "both", label = k[1] .. ", " .. S.name(k[2])}
  end
  mvmpm.plot {file = dir .. "/contact_friction_work.png", xlog = true, ylog = true,
              title = "Disc thrown along a floor (mu 0.3): friction work",
              xlabel = "cells per diameter", ylabel = "|W / W_rigid disc - 1|", series = series}
end

-- contact between bodies per rule (tests/verify/body_patch.lua): the disc
-- thrown along a driven slab, friction work against the rigid disc's,
-- and the disc rolling down an incline that is a driven slab
do
  local series = {}
  for _, rule in ipairs {"node", "patch"} do
    local x, yw, yr = {}, {}, {}
    for _, c in ipairs {8, 16, 32} do
      local r = S.run {cells = c, scheme = {shape = "linear", transfer = "flip", flip = 1}, mu = 0.3,
                       T = 2, n = 40, slab = true, body_contact = rule}
      local q = I.run {cells = c, deg = 25, mu = 0.5, slab = "driven", body_contact = rule,
                        shape = "linear"}
      local ar = 2 / 3 * math.sin(math.rad(25))
      x[#x + 1] = c
      yw[#yw + 1], yr[#yr + 1] = floor(math.abs(r.e.dissipated / r.rigid - 1)), floor(math.abs(q.a / ar - 1))
      print(string.format("body_contact %-5s %2d cells: thrown W / W_rigid %.4f, rolling a/ref %.4f",
                          rule, c, r.e.dissipated / r.rigid, q.a / ar))
    end
    series[#series + 1] = {x = x, y = yw, style = "both", label = "thrown: friction work, " .. rule}
    series[#series + 1] = {x = x, y = yr, style = "both", label = "incline: rolling a, " .. rule}
  end
  mvmpm.plot {file = dir .. "/contact_body_patch.png", xlog = true, ylog = true,
              title = "Disc on a driven slab (contact between bodies), linear hats",
              xlabel = "cells per diameter", ylabel = "|measured / rigid disc's - 1|", series = series}
end
