-- Bad input gets a clear error: for each rule a small scene breaks it,
-- and the message must name the scene file and line, the field, and the
-- allowed range (or what is allowed).  Each scene is written to a
-- temporary file and loaded as a user's would be.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local path = os.tmpname() .. ".lua"
local name = path:match("[^/]+$")
local head = 'local mvmpm = require "mvmpm"\n'
local sim0 = 'local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1}\n'
local el = 'mvmpm.elastic {K = 1, G = 1, density = 1}'

-- rule: {what, scene text, line of the fault, patterns the message holds}
local rules = {
  {"cell size must be positive", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = -0.1}',
    2, {"'cell'", "> 0", "got %-0.1"}},
  {"cfl in (0, 1]", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, cfl = 2}',
    2, {"'cfl'", "%(0, 1%]", "got 2"}},
  {"unknown key, with the nearest name", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cel = 0.1}',
    2, {"unknown field 'cel'", "did you mean 'cell'"}},
  {"a grid too large for memory, refused before allocating",
    'return mvmpm.sim {domain = {x = {0, 1e6}, y = {0, 1e6}}, cell = 1e-3}',
    2, {"cells would need", "GB", "limit 16 GB"}},
  {"domain extent a whole number of cells", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.3}',
    2, {"whole number of cells", "0.3", "3.33"}},
  {"domain max > min", 'return mvmpm.sim {domain = {x = {1, 0}, y = {0, 1}}, cell = 0.1}',
    2, {"sim.domain", "x = {1, 0}", "max > min"}},
  {"particles per cell in [1, 8]", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, ppc = 9}',
    2, {"'ppc'", "%[1, 8%]", "got 9"}},
  {"shape one of the kinds", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, shape = "cubic"}',
    2, {"'shape'", "linear, gimp, bspline2", "'cubic'"}},
  {"periodic sides in pairs", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = {left = "periodic"}}',
    2, {"sides.left", "sides.right", "both be periodic"}},
  {"Poisson's ratio in (-1, 0.5)", 'local m = mvmpm.elastic {E = 1, nu = 0.5, density = 1}',
    2, {"'nu'", "%(%-1, 0.5%)", "got 0.5"}},
  {"density > 0", 'local m = mvmpm.elastic {E = 1, nu = 0.3, density = 0}',
    2, {"'density'", "> 0", "got 0"}},
  {"yield stress > 0", 'local m = mvmpm.plastic {K = 1, G = 1, density = 1, yield = -1}',
    2, {"'yield'", "> 0", "got %-1"}},
  {"relaxation times > 0", 'local m = mvmpm.viscoelastic {K = 1, density = 1, prony = {{G = 1, tau = 0}}}',
    2, {"prony%[1%]", "'tau'", "> 0"}},
  {"a body outside the domain", sim0 .. 's:body {shape = mvmpm.disk {center = {5, 5}, radius = 0.2}, material = ' .. el .. '}',
    3, {"lies outside the domain", "x 4.8 .. 5.2", "x 0 .. 1"}},
  {"overlapping bodies", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. '}\n' ..
    's:body {shape = mvmpm.disk {center = {0.6, 0.5}, radius = 0.2}, material = ' .. el .. '}',
    4, {"overlaps body", "overlap = \"skip\""}},
  {"a body's own lattice needs its angle", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {origin = {0, 0}}}',
    3, {"lattice", "'angle'"}},
  {"a body's own lattice: angle in [-360, 360]", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {angle = 400}}',
    3, {"lattice", "'angle'", "%[%-360, 360%]", "got 400"}},
  {"a body's own lattice: a misspelt key", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {angel = 10}}',
    3, {"unknown field 'angel'", "did you mean 'angle'"}},
  {"a body's own lattice is not for points", sim0 .. 's:body {points = {x = {0.5}, y = {0.5}}, material = ' .. el .. ', lattice = {angle = 10}}',
    3, {"'lattice'", "'points'"}},
  {"a body's own lattice is not for the rest", sim0 .. 's:body {shape = mvmpm.rest(), material = ' .. el .. ', lattice = {angle = 10}}',
    3, {"'lattice'", "the rest"}},
  {"a body's own lattice does not cross periodic sides", 'local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = {left = "periodic", right = "periodic"}}\n' ..
    's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {angle = 10}}',
    3, {"'lattice'", "periodic sides in x"}},
  {"bodies on their own lattices that overlap", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {angle = 10}}\n' ..
    's:body {shape = mvmpm.disk {center = {0.6, 0.5}, radius = 0.2}, material = ' .. el .. ', lattice = {angle = 20}}',
    4, {"overlaps body", "overlap = \"skip\""}},
  {"a misspelt body key", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, materal = 1}',
    3, {"unknown field 'materal'", "did you mean 'material'"}},
  {"a wall's velocity along its normal", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = {left = {"wall", velocity = {1, 0}}}}',
    2, {"sides.left", "velocity's x component must be 0"}},
  {"a side's kind, misspelt", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = "wal"}',
    2, {"sides.left: the side's kind", "free, wall, periodic, symmetry", "'wal'", "did you mean 'wall'"}},
  {"friction only on walls", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = {"free", friction = 0.3}}',
    2, {"only a wall has friction"}},
  {"friction >= 0", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, contact = {friction = -1}}',
    2, {"'friction'", ">= 0", "got %-1"}},
  {"bond strength >= 0", sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', bond = -1}',
    3, {"'bond'", ">= 0", "got %-1"}},
  {"a callback interval that makes too many calls",
    sim0 .. 's:every {time = 1e-300, fn = function() end}',
    3, {"'time'", "1e%-300", "at most 1e%+09", "give at least"}},
  {"a fixed step too small to reach t_end", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, dt = 1e-300}',
    2, {"'dt'", "1e%-300", "steps", "at most 1e%+15"}},
  {"a density whose wave speed makes the step too small",
    sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = mvmpm.elastic {K = 1, G = 1, density = 1e-300}}',
    3, {"density = 1e%-300", "wave speed", "steps", "at most 1e%+15"}},
  {"a modulus whose wave speed makes the step too small",
    sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = mvmpm.elastic {K = 1e300, G = 1, density = 1}}',
    3, {"K = 1e%+300", "wave speed", "steps"}},
  {"a velocity the step cannot follow",
    sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', velocity = {1e300, 0}}',
    3, {"body 'body1'", "speed of 1e%+300", "steps"}},
  {"a wall velocity the step cannot follow", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, sides = {bottom = {"wall", velocity = {1e300, 0}}}}',
    2, {"sides.bottom", "speed of 1e%+300"}},
  {"a velocity function returning NaN, named where it is defined",
    sim0 .. 's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ',\n' ..
    '  velocity = function(x, y) return 0/0, 0 end}',
    4, {"velocity of body 'body1'", "returned nan"}},
  {"a drive of NaN", sim0 .. 'local b = s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', driven = {0, 0}}\n' ..
    'b:drive(0/0, 0)',
    4, {"drive", "'vx'", "finite", "got nan"}},
  {"a drive speed the step cannot follow", sim0 .. 'local b = s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. ', driven = {1e300, 0}}',
    3, {"'driven'", "speed of 1e%+300"}},
  {"a temperature of inf", sim0 .. 's:temperature(1/0)',
    3, {"temperature", "finite", "got inf"}},
  {"a cell below the normal doubles (1 / cell overflows)",
    'return mvmpm.sim {domain = {x = {0, 1e-310}, y = {0, 1e-310}}, cell = 1e-311}',
    2, {"'cell'", ">= 2.2%d*e%-308", "got 1e%-311"}},
  {"a domain of 1e308 cells, refused before its counts become ints",
    'return mvmpm.sim {domain = {x = {0, 1e308}, y = {0, 1}}, cell = 1}',
    2, {"cells would need", "GB", "coarser 'cell'"}},
  {"a cell of 1e-300", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1e-300}',
    2, {"cells would need", "GB", "coarser 'cell'"}},
  {"a domain wider than the largest double", 'return mvmpm.sim {domain = {x = {-1e308, 1e308}, y = {0, 1}}, cell = 0.5}',
    2, {"cells would need", "GB", "coarser 'cell'"}},
  {"a module function misspelt, with the nearest name",
    'return mvmpm.disc {center = {0.5, 0.5}, radius = 0.2}',
    2, {"mvmpm has no field or function 'disc'", "did you mean 'disk'"}},
  {"a library module read as a function, with its require",
    'return mvmpm.pack.bimodal {}',
    2, {"mvmpm.pack is a module", 'require "mvmpm.pack"'}},
  {"a sim method misspelt, with the nearest name",
    sim0 .. 's:stpe(1)\nreturn s',
    3, {"sim has no field or function 'stpe'", "did you mean 'step'"}},
  {"a sim field misspelt, with the nearest name",
    sim0 .. 'local t = s.tend\nreturn s',
    3, {"sim has no field or function 'tend'", "did you mean 't_end'"}},
  {"a body method misspelt, with the nearest name",
    sim0 .. 'local b = s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. '}\n' ..
    'local c = b:centriod()\nreturn s',
    4, {"body has no field or function 'centriod'", "did you mean 'centroid'"}},
  {"Taylor-Quinney fraction in [0, 1]", 'local m = mvmpm.plastic {K = 1, G = 1, density = 1, yield = 1, beta = 1.5}',
    2, {"'beta'", "%[0, 1%]", "got 1.5"}},
  {"a heat scene's material without a specific heat", sim0 .. 's:heat {}\n' ..
    's:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = ' .. el .. '}',
    4, {"body 'body1'", "cv > 0"}},
  {"a heat side given two conditions", sim0 .. 's:heat {sides = {left = {temperature = 1, h = 2, ambient = 0}}}',
    3, {"heat.sides.left", "either temperature", "h and ambient"}},
  {"APIC needs GIMP or B-splines", 'return mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, shape = "linear", transfer = "apic"}',
    2, {"transfer = \"apic\"", "gimp", "bspline2"}},
}

V.case "each rule names the file, the line, the field and what is allowed"
for _, r in ipairs(rules) do
  local f = assert(io.open(path, "w"))
  f:write(head .. r[2] .. "\n")
  f:close()
  local ok, err = pcall(mvmpm.load, path)
  err = tostring(err):match("^[^\n]*")
  local good = not ok and err:find(name .. ":" .. r[3] .. ":", 1, true) ~= nil
  for _, p in ipairs(r[4]) do good = good and err:find(p) ~= nil end
  V.holds(r[1], good, 0, err)
end
os.remove(path)
