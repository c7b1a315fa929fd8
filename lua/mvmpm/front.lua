-- mvmpm.front: the debond front of scenarios/debond_front.lua, measured;
-- shared by tests/verify/bonds.lua and studies/debond_front.lua.
--
-- The scene is loaded with the options o (cells, traction, bond_length,
-- shape, flip, energy), run to t = 12.9 (the seed lets go at 13), then to 17.5.  The
-- debonded length is the drop of the bonded area (the grid's measure,
-- which counts the seed's 0.25 and reaches about 2.5 once the whole
-- interface has let go) since t = 12.9; the front's speed is its
-- least-squares slope against time over t = 13.5 .. 17.5.
local mvmpm = require "mvmpm"

local M = {cR = 0.6542}   -- plane strain, K the 3-D bulk modulus (docs/algorithm.md)

-- returns the speed over c_R, the debonded length at t = 17.5 and the
-- CPU seconds of the stepping after t = 12.9
function M.run(o)
  local sim = mvmpm.load("scenarios/debond_front.lua",
    {cells = o.cells, traction = o.traction, bond_length = o.bond_length, shape = o.shape,
     flip = o.flip, energy = o.energy})
  sim:run(12.9)
  local A0 = sim:energy().bonded_area
  local ts, ls = {}, {}
  sim:every {steps = 1, fn = function(s)
    if s.t > 13.5 then ts[#ts + 1], ls[#ls + 1] = s.t, A0 - s:energy().bonded_area end
  end}
  local c0 = os.clock()
  sim:run(17.5)
  M.last = sim
  local n, st, sl, stt, stl = #ts, 0, 0, 0, 0
  for i = 1, n do st, sl = st + ts[i], sl + ls[i]; stt, stl = stt + ts[i]^2, stl + ts[i] * ls[i] end
  return (n * stl - st * sl) / (n * stt - st * st) / M.cR, ls[n], os.clock() - c0
end

return M
