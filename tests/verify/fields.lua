-- Particle fields as a user reads them: every component of every field
-- has a name in sim:particles and in snapshots, and APIC's affine matrix
-- C (the particle's velocity gradient) is kept in snapshots.  A disc
-- spinning rigidly at omega has C = [[0, -omega], [omega, 0]].
local mvmpm = require "mvmpm"
local V = require "mvmpm.verify"

V.case "APIC's affine field: named components, the rigid spin, in snapshots"
local w = 1.0
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.05,
                       shape = "gimp", transfer = "apic"}
sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
          material = mvmpm.elastic {K = 100, G = 50, density = 1},
          angular_velocity = w}
sim:step(3)
local a = sim:particles("affine")
local names = {}
for k in pairs(a) do names[#names + 1] = k end
table.sort(names)
V.holds("components xx, xy, yx, yy", table.concat(names, " ") == "xx xy yx yy", #names,
  table.concat(names, " "))
local function mean(t) local s = 0 for _, v in ipairs(t) do s = s + v end return s / #t end
V.near("mean C_xy = -omega", mean(a.xy), -w, 0.01)
V.near("mean C_yx = omega", mean(a.yx), w, 0.01)
V.near("mean C_xx = 0", mean(a.xx), 0, 0.01)

-- every field's components are named (no "?")
local unnamed = 0
for _, f in ipairs {"position", "velocity", "stress", "F", "affine", "mass"} do
  local ok, t = pcall(sim.particles, sim, f)
  if ok and type(t) == "table" then
    for k in pairs(t) do if k == "?" then unnamed = unnamed + 1 end end
  end
end
V.holds("no component is unnamed", unnamed == 0, unnamed)

local path = os.tmpname() .. ".h5"
sim:snapshot(path)
local h5 = io.popen("h5dump -A -d /affine " .. path .. " 2>&1"):read("a")
os.remove(path)
V.holds("the snapshot holds /affine with its components",
  h5:find("DATASET \"/affine\"") ~= nil and h5:find("\"xx,xy,yx,yy\"") ~= nil, 0)
