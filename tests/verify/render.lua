-- Pictures from Lua: sim:render and mvmpm.plot write real PNG files of
-- the size asked for, between steps and from a callback, and refuse bad
-- tables with the scene line, the field and what is allowed.
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

local base = os.tmpname()
local made = {}
local function tmp(name)
  local p = base .. "_" .. name
  made[#made + 1] = p
  return p
end

-- signature, IHDR width and height of a PNG file (nil if not one)
local function png_size(path)
  local f = io.open(path, "rb")
  if not f then return nil end
  local s = f:read(33)
  f:close()
  if not s or #s < 33 or s:sub(1, 8) ~= "\137PNG\r\n\26\n" or s:sub(13, 16) ~= "IHDR" then
    return nil
  end
  return string.unpack(">I4I4", s, 17)
end

-- the error of f(...) called from a Lua line, as a scene calls it
local function err_of(f, ...)
  local args = table.pack(...)
  local ok, e = pcall(function() f(table.unpack(args, 1, args.n)) end)
  return not ok and tostring(e) or ""
end

V.case "sim:render writes PNGs of the width asked, height from the domain"
local sim = mvmpm.load("scenarios/two_disks.lua")
local p = tmp("body.png")
sim:render {file = p}
local w, h = png_size(p)
V.holds("body picture is a PNG", w ~= nil, 0)
V.near("its width (default 800)", w or 0, 800, 0)
V.holds("square domain: height between 600 and 800 px", h and h > 600 and h < 800, h)
p = tmp("pressure.png")
sim:render {file = p, by = "pressure", width = 400, range = {-1, 1}, colormap = "div",
            title = "p"}
w = png_size(p)
V.near("pressure picture width", w or 0, 400, 0)

local wide = mvmpm.sim {domain = {x = {0, 4}, y = {0, 1}}, cell = 0.25, t_end = 0.1}
wide:body {shape = mvmpm.disk {center = {2, 0.5}, radius = 0.3},
           material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
p = tmp("wide.png")
wide:render {file = p, by = "speed", axes = false}
w, h = png_size(p)
V.holds("4 x 1 domain without axes: height under a third of the width", h and h < w / 3, h)

V.case "sim:render from a callback between steps"
local n = 0
sim:every {steps = 5, fn = function(s)
  n = n + 1
  s:render {file = tmp("step" .. n .. ".png"), by = "sdiff", width = 300}
end}
sim:run(sim.t + 12 * sim.dt)
local ok = true
for k = 1, n do ok = ok and png_size(base .. "_step" .. k .. ".png") == 300 end
V.holds("callback renders, each a 300 px PNG", n >= 2 and ok, n)

V.case "bad render tables are refused with the line, the field and the range"
local e = err_of(sim.render, sim, {file = tmp("x.png"), by = "nosuch"})
V.holds("unknown key names itself and lists keys", e:find("render.lua:%d+:") and
        e:find("'nosuch'") and e:find("stress.xx"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), widht = 300})
V.holds("misspelt field gets a suggestion", e:find("did you mean 'width'"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), width = 10})
V.holds("width below the minimum", e:find("'width' must be a whole number in %[120"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), range = {1, 0}})
V.holds("range with hi < lo", e:find("'range'") and e:find("hi > lo"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), colormap = "rainbow"})
V.holds("unknown colormap lists the maps", e:find("auto, seq, div"), 0, e)
e = err_of(sim.render, sim, {file = "/nonexistent-dir-mvmpm/x.png"})
V.holds("unwritable file names the path and the reason",
        e:find("/nonexistent%-dir%-mvmpm/x.png") and e:find("No such file"), 0, e)
V.holds("nothing left under the name", io.open(tmp("x.png")) == nil, 0)

V.case "sim:render options: svg, log, axes, matrix, automatic ranges"
p = tmp("b.svg")
sim:render {file = p, by = "speed", range = "full", axes = false}
local f = io.open(p, "rb")
local text = f and f:read("a") or ""
if f then f:close() end
local npath = select(2, text:gsub("<path ", ""))
V.holds("an SVG document with one polygon per particle", text:find("^<%?xml") and
        text:find("</svg>") and npath == #sim:particles("mass"), npath)
e = err_of(sim.render, sim, {file = tmp("x.png"), by = "velocity.x", log = true})
V.holds("log over values not all above zero is refused, naming the key",
        e:find("log scale needs values above zero") and e:find("'velocity.x'"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), by = "mass", log = true, range = {0, 1}})
V.holds("log with a range from zero is refused", e:find("range above zero"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), matrix = "nosuch"})
V.holds("a matrix no body is called", e:find("no body named 'nosuch'"), 0, e)
e = err_of(sim.render, sim, {file = tmp("x.png"), range = "wide"})
V.holds("an automatic range other than robust or full", e:find("robust, full"), 0, e)
p = tmp("log.png")
sim:render {file = p, by = "mass", log = true, matrix = sim:bodies()[1].name}
V.holds("log over mass, with a matrix named", png_size(p) == 800, 0)

V.case "mvmpm.plot"
p = tmp("plot.png")
mvmpm.plot {file = p, title = "t", xlabel = "x", ylabel = "y", ylog = true,
            series = {{x = {1, 2, 3}, y = {1, 10, 0 / 0}, label = "a", style = "both"},
                      {y = {5, 5, 5}, label = "flat"}}}
w, h = png_size(p)
V.holds("plot is an 800 x 560 PNG by default", w == 800 and h == 560, w)
e = err_of(mvmpm.plot, {file = tmp("q.png"), series = {{x = {1, 2}, y = {1}}}})
V.holds("x and y of different lengths", e:find("render.lua:%d+:") and
        e:find("same length"), 0, e)
e = err_of(mvmpm.plot, {file = tmp("q.png"), series = {{x = {1}, y = {"a"}}}})
V.holds("a string in y", e:find("'y' entry 1 must be a number"), 0, e)
e = err_of(mvmpm.plot, {file = tmp("q.png"), series = {{y = {1}, style = "dots"}}})
V.holds("unknown style lists the styles", e:find("line, points, both"), 0, e)
e = err_of(mvmpm.plot, {file = tmp("q.png")})
V.holds("series are required", e:find("'series' is required"), 0, e)

V.case "mvmpm.plot and sim:render at the edges of the doubles (make test SAN=1 checks the casts)"
local huge = {
  {name = "denormals", x = {1, 2, 3}, y = {1e-310, 2e-310, 3e-310}},
  {name = "one denormal apart", x = {0, 5e-324}, y = {0, 5e-324}},
  {name = "+-1.7e308 (hi - lo overflows)", x = {-1.7e308, 1.7e308}, y = {1.7e308, -1.7e308}},
  {name = "the largest double, constant", x = {1.79e308, 1.79e308}, y = {-1.79e308, -1.79e308}},
  {name = "NaN and infinities among 1e308", x = {1, 2, 3, 4}, y = {0 / 0, math.huge, -math.huge, 1e308}},
  {name = "log axes from 5e-324 to 1.7e308", x = {1e-323, 1e308}, y = {5e-324, 1.7e308}, log = true},
  {name = "a fixed range of +-1e308", x = {1, 2}, y = {1, 2}, xrange = {-1e308, 1e308}},
  {name = "a fixed range one ulp wide", x = {1, 2}, y = {1, 2}, yrange = {1, 1 + 2.3e-16}},
}
for _, c in ipairs(huge) do
  p = tmp("huge.png")
  local ok, err = pcall(mvmpm.plot, {file = p, width = 300, height = 200, xlog = c.log, ylog = c.log,
    xrange = c.xrange, yrange = c.yrange, series = {{x = c.x, y = c.y, style = "both"}}})
  w, h = png_size(p)
  V.holds("plot of " .. c.name, ok and w == 300 and h == 200, 0, err)
end
local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.25}
s:body {shape = mvmpm.rect {lo = {0, 0}, hi = {0.5, 0.5}}, material = mvmpm.elastic {K = 1, G = 1, density = 1}}
for _, r in ipairs {{-1.7e308, 1.7e308}, {0, 5e-324}, {1e-310, 2e-310}, {1e308, 1.7e308}} do
  p = tmp("huge.png")
  local ok, err = pcall(s.render, s, {file = p, by = "mass", range = r, width = 300})
  w = png_size(p)
  V.holds(string.format("render with the colour range {%g, %g}", r[1], r[2]), ok and w == 300, 0, err)
end

os.remove(base)
for _, f in ipairs(made) do os.remove(f) end
