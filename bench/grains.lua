-- bench/grains.lua - (c) the cost of many velocity fields: 10 grains
-- against 1,000 grains filling the same box with the same number of
-- particles.  Grains are elastic discs on a square lattice, each
-- touching its neighbours, each its own body and velocity field, with
-- frictionless contact; a uniform compression v = -0.05 (x - xc)
-- presses every contact.  10 grains: 5 x 2 discs of radius 40 cells;
-- 1,000 grains: 50 x 20 discs of radius 4 cells; box 400 x 160 cells,
-- 2 x 2 particles per cell, about 201,000 particles either way.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local H = 1 / 400
local W, HT = 400 * H, 160 * H

local packing = B.packing

local per = {}
for _, c in ipairs {{5, 2}, {50, 20}} do
  local sim = packing(c[1], c[2])
  local rate, sec, n = B.rate(sim)
  local ng = c[1] * c[2]
  per[ng] = 1 / rate
  B.line("rate", string.format("(c) %d grains, packed, in contact", ng), rate / 1e6,
    "M p-st/s", string.format("%d particles, %d shared nodes, %.1f ms/step, median of %d x %d steps",
      sim.n, sim.shared_nodes, 1e3 * sec, B.reps, n))
  sim = nil
  collectgarbage()
end
B.line("ratio", "(c) t(1000 grains) / t(10 grains)", per[1000] / per[10], "",
  "per particle-step")

-- The cost of contact accuracy: the 1,000-grain bed with each way of
-- taking the contact normals (sim.normals; "m/R": over a window of R
-- cells, sim.normal_window; "+patch": body_contact = "patch"; "+npatch":
-- normal_patch = true, one normal per contact patch), as a
-- ratio to the default ("mass").  The four scenes are stepped in turns (n steps of each per
-- round, the order rotated each round) so a neighbour's load falls on
-- all of them; the ratio is the median of the rounds'.
do
  -- "+patch": with contact between bodies per patch (body_contact)
  local opts = {"mass", "volume", "maxvolume", "plane", "maxvolume/4", "plane/4", "mass+patch",
                "maxvolume/4+patch", "mass+npatch", "plane/4+npatch"}
  local sims, per = {}, {}
  for k, o in ipairs(opts) do
    local base, suffix = o:match("^([^+]+)%+?(%a*)$")
    local m, w = base:match("^(%a+)/(%d+)$")
    sims[k] = packing(50, 20, {normals = m or base, normal_window = tonumber(w) or 0,
                               body_contact = suffix == "patch" and "patch" or nil,
                               normal_patch = suffix == "npatch"})
    sims[k]:step(3)
    per[k] = {}
  end
  local t0 = mvmpm.clock()
  sims[1]:step(1)
  local n = math.max(1, math.floor(B.target / math.max(mvmpm.clock() - t0, 1e-6) + 0.5))
  local rounds = B.reps
  for r = 1, rounds do
    for j = 0, #opts - 1 do
      local k = (r + j - 1) % #opts + 1
      local t1 = mvmpm.clock()
      sims[k]:step(n)
      per[k][r] = (mvmpm.clock() - t1) / n
    end
  end
  for k, o in ipairs(opts) do
    local q = {}
    for r = 1, rounds do q[r] = per[k][r] / per[1][r] end
    B.line("ratio", string.format("(c) 1000 grains, normals = \"%s\" / \"mass\"", o), B.median(q),
      "x default", string.format("%.1f ms/step, median of %d rounds of %d steps", 1e3 * B.median(per[k]),
        rounds, n))
  end
end
