-- bench/effects.lua - what effects cost.  The same 200 x 200-cell
-- elastic block (160,000 particles, linear hats, MUSL) is timed plain,
-- then with one effect declared but idle, then with effects at work:
--   declared, idle: a temperature imposed and held (no alpha anywhere),
--     a bond strength on the body (no interface to bond), a plastic
--     material whose yield stress is never reached
--   at work: the block split in two bodies bonded along a line (contact,
--     bonds), a thermal ramp with alpha, a viscoelastic binder, and the
--     frictional split block with heat on (friction heat; and conduction)
-- Ratios are t(case) / t(plain), all measured in this one run.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local CELLS = 200
local elastic = {K = 1, G = 0.5, density = 1}

local function block(opt)
  local h = 1 / CELLS
  local sim = mvmpm.sim {domain = {x = {-2 * h, 1 + 2 * h}, y = {-2 * h, 1 + 2 * h}},
                         cell = h, ppc = 2, sides = "free", t_end = 1e9}
  if opt.heat then sim:heat {} end
  local m = opt.material or mvmpm.elastic(elastic)
  local v = function(x, y) return 0.01 * math.sin(2 * math.pi * y), 0 end
  if opt.split then
    local a = sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {0.5, 1}}, material = m,
                        velocity = v, bond = opt.bond}
    local b = sim:body {shape = mvmpm.rect {lo = {0.5, 0}, hi = {1, 1}}, material = m,
                        velocity = v, bond = opt.bond}
    sim:contact(a, b, {friction = 0.3})
  else
    sim:body {shape = mvmpm.rect {lo = {0, 0}, hi = {1, 1}}, material = m, velocity = v,
              bond = opt.bond}
  end
  if opt.temperature then sim:temperature(opt.temperature) end
  return sim
end

local cases = {
  {"plain elastic block", {}},
  {"idle: temperature held, no alpha", {temperature = 0}},
  {"idle: bond strength, no interface", {bond = 1}},
  {"idle: plastic, yield never reached", {material = mvmpm.plastic {K = 1, G = 0.5,
      density = 1, yield = 1e6}}},
  {"at work: thermal ramp with alpha", {material = mvmpm.elastic {K = 1, G = 0.5,
      density = 1, alpha = 1e-3}, temperature = function(t) return -t end}},
  {"at work: viscoelastic (3 Prony terms)", {material = mvmpm.viscoelastic {K = 1,
      G_inf = 0.2, density = 1, prony = {{G = 0.1, tau = 0.01}, {G = 0.1, tau = 0.1},
      {G = 0.1, tau = 1}}}}},
  {"at work: two bodies, frictional contact", {split = true}},
  {"at work: two bodies bonded", {split = true, bond = 1}},
  {"at work: two bodies, friction heat (k = 0)", {split = true, heat = true,
      material = mvmpm.elastic {K = 1, G = 0.5, density = 1, cv = 1}}},
  {"at work: two bodies, friction heat, conduction", {split = true, heat = true,
      material = mvmpm.elastic {K = 1, G = 0.5, density = 1, cv = 1, k = 1e-4}}},
}
-- the first timed scene of a process runs slow (page faults of fresh
-- allocations, the clock ramping up): a plain block is timed once first
-- and thrown away, or it would make every later case look cheaper
B.rate(block({}))
collectgarbage()
local base
for _, c in ipairs(cases) do
  local sim = block(c[2])
  local rate, sec = B.rate(sim)
  base = base or sec
  B.line("ratio", "effects: " .. c[1], sec / base, "x plain",
    string.format("%.2f M p-st/s", rate / 1e6))
end
