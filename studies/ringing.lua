-- Study: a vibrating disc crossing the grid (lua/mvmpm/ringing.lua, the
-- case of tests/verify/ringing.lua): a free elastic disc moving at
-- (0.1, 0.1) with a standing pattern of velocity of wavelength 0.25, as
-- an impact leaves it ringing.  Reference: its energy is kept.  Error:
-- |E(10) - E(0)| over the vibration's energy.  Per shape and update
-- (pure FLIP), 16 to 64 cells across a unit length.
--
--   ./mvmpm test studies/ringing.lua
local S = require "mvmpm.study"
local R = require "mvmpm.ringing"

local case = {
  name = "ringing",
  title = "vibrating disc crossing the grid",
  length = "unit length",
  reference = "the initial energy: nothing acts on the disc",
  metrics = {{key = "energy", label = "|dE| / E_vib over t = 0 .. 10"}},
  extra = {"dE"},
  grid = {cells = {16, 24, 32, 48, 64}, shape = {"linear", "gimp", "bspline2"},
          update = {"musl", "usavg"}},
  baseline = {cells = 16, shape = "bspline2", transfer = "flip", flip = 1, update = "musl"},
  run = function(s, clock)
    local r = R.run({cells = s.cells, ppc = s.ppc, shape = s.shape, update = s.update,
                     transfer = s.transfer, flip = s.flip, cfl = s.cfl}, clock.run)
    return {energy = math.abs(r.err), dE = r.err}
  end,
}
return S.main(case)
