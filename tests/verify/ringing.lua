-- A vibrating body crossing the grid (lua/mvmpm/ringing.lua): a free
-- elastic disc moving at (0.1, 0.1) that carries a standing pattern of
-- velocity of wavelength 0.25 (4 / 8 / 16 cells at 16 / 32 / 64 cells
-- across a unit length; the disc is 0.5 in radius), as the ringing an
-- impact leaves.  Reference: nothing acts on it, so the total energy and
-- the momentum stay what they were.  Error: the energy's change over
-- t = 0 .. 10 over the vibration's energy (the total less the
-- translation's).
--
-- Measured on the default shape (B-splines, pure FLIP): with USAVG the
-- energy is kept within 0.3 % at each size; with MUSL (the default
-- update) it grows while the disc crosses cells, by +0.09 / +13 / +9.5 %
-- of the vibration's energy at 16 / 32 / 64 cells, and at rest it does
-- not (docs/verification.md, "A vibrating body crossing the grid").
-- The momentum is kept to round-off with mass_cutoff = 0; the default
-- cutoff drops the forces of nodes a particle barely reaches (1e-10 of
-- the momentum here; docs/verification.md, open items 1d).
local V = require "mvmpm.verify"
local R = require "mvmpm.ringing"

local CELLS = {16, 32, 64}

local function ladder(o)
  local r = {}
  for i, c in ipairs(CELLS) do
    local p = {cells = c}
    for k, v in pairs(o) do p[k] = v end
    r[i] = R.run(p)
    print(string.format("     %-12s %2d cells: dE / E_vib %+.4f   momentum %.2g   CPU %.1f s",
      o.update, c, r[i].err, r[i].mom, r[i].cpu))
  end
  return r
end

V.case "vibrating disc crossing the grid, USAVG, 16 32 64 cells (energy kept)"
local us = ladder {update = "usavg"}
for i, c in ipairs(CELLS) do
  -- measured +0.0022 / +0.0021 / +0.0003
  V.below(string.format("USAVG %d cells: |dE| / E_vib over t = 0 .. 10", c), math.abs(us[i].err), 0.01)
  V.below(string.format("USAVG %d cells: momentum change (default mass cutoff)", c), us[i].mom, 1e-8)
end
V.info("USAVG: observed order 16 -> 64 cells (not monotone)",
       math.log(math.abs(us[1].err) / math.abs(us[3].err), 4))

V.case "the same with MUSL (the default update): the energy grows"
local mu = ladder {update = "musl"}
for i, c in ipairs(CELLS) do
  V.info(string.format("MUSL %d cells: dE / E_vib (0 wanted)", c), mu[i].err)
  V.below(string.format("MUSL %d cells: momentum change (default mass cutoff)", c), mu[i].mom, 1e-8)
end
-- the defect this case shows (printed, not asserted): MUSL's gain at 32
-- and 64 cells is tens of times USAVG's |error| (measured 46 times)
V.info("MUSL's gain at 32 and 64 cells over USAVG's |error|",
       math.min(mu[2].err, mu[3].err) / math.max(math.abs(us[2].err), math.abs(us[3].err)))

V.case "at rest (the same pattern, no translation), 32 cells: both keep the energy"
for _, u in ipairs {"musl", "usavg"} do
  local r = R.run {cells = 32, update = u, vt = 0}
  -- measured MUSL +0.0012, USAVG +0.0020
  V.below(u .. " at rest: |dE| / E_vib", math.abs(r.err), 0.01)
end

V.case "momentum without the mass cutoff, 16 cells: round-off"
for _, u in ipairs {"musl", "usavg"} do
  local r = R.run {cells = 16, update = u, mass_cutoff = 0}
  -- measured 1.4e-15 (MUSL), 1.8e-15 (USAVG)
  V.below(u .. ", mass_cutoff = 0: momentum change", r.mom, 1e-12)
end
