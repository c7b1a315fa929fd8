-- mvmpm.repl: help at the prompt, and readable tables: the prompt shows
-- a result through show(), which prints a table's entries sorted by key,
-- numbers to 6 significant digits, one level deep (short vectors of
-- numbers whole).
local text = [[
sim:step(n)          advance n steps (default 1)
sim:run(t)           advance to time t (default: the scene's t_end)
sim:energy()         kinetic, strain, potential, dissipated, plastic, viscous, boundary_work, thermal_work, removed, total, residual, scale, px, py, angmom
sim:bodies()         the bodies; b:diag(), b:centroid(), b:velocity(), b:omega(), b:mass()
sim:particles(name)  copy of a particle field (sim:particles() lists them)
sim:snapshot(path)   write an HDF5 snapshot now (a relative path: from the current directory); returns the path
sim:temperature(T)   impose a uniform temperature (a number or function(t)); sim:temperature() reads it
sim:render{file = "x.png", by = "pressure"}   a picture now (by body, pressure, sdiff, speed, a field), in the output directory; returns the path
sim.t sim.dt sim.steps sim.n   time, step size, step count, particle count
sim.shape sim.update sim.transfer sim.wall_contact sim.body_contact sim.normals sim.bond_traction   the scheme and contact rules in use
sim.flip = f  sim.cfl = c  sim.dt = d  sim.friction = mu   change settings between steps
show(v)              print a value as the prompt does (tables sorted, one level)
Ctrl-C stops running steps; Ctrl-D leaves.]]
function help() print(text) end

local function fmt(v)
  if math.type(v) == "float" then return string.format("%.6g", v) end
  if type(v) == "string" then return string.format("%q", v) end
  return tostring(v)
end

local function tab(t)
  local keys, parts = {}, {}
  for k in pairs(t) do keys[#keys + 1] = k end
  if #keys == 0 then return "{}" end
  table.sort(keys, function(a, b)
    local ta, tb = type(a), type(b)
    if ta ~= tb then return ta < tb end
    if ta == "number" or ta == "string" then return a < b end
    return tostring(a) < tostring(b)
  end)
  local n = #t
  -- one level deep; a short vector of numbers (a 3-D body's omega,
  -- angmom) is shown whole, since it is the value itself
  local function inner(v)
    if getmetatable(v) then return tostring(v) end
    local m, k = #v, 0
    for _ in pairs(v) do k = k + 1 end
    if m >= 1 and m <= 3 and k == m then
      local p = {}
      for i = 1, m do
        if type(v[i]) ~= "number" then return string.format("{...%d}", m) end
        p[i] = fmt(v[i])
      end
      return "{" .. table.concat(p, ", ") .. "}"
    end
    return string.format("{...%d}", m)
  end
  for _, k in ipairs(keys) do
    local v = t[k]
    local vs = type(v) == "table" and inner(v) or fmt(v)
    if math.type(k) == "integer" and k >= 1 and k <= n then parts[#parts + 1] = vs
    else parts[#parts + 1] = tostring(k) .. " = " .. vs end
  end
  local one = "{" .. table.concat(parts, ", ") .. "}"
  if #one <= 100 then return one end
  return "{\n  " .. table.concat(parts, ",\n  ") .. "\n}"
end

function show(...)
  local out = {}
  for i = 1, select("#", ...) do
    local v = select(i, ...)
    if type(v) == "table" and not getmetatable(v) then out[i] = tab(v)
    elseif type(v) == "string" then out[i] = v  -- as the lua prompt does
    else out[i] = fmt(v) end
  end
  print(table.concat(out, "\t"))
end
