-- mvmpm.lame: the plane-strain Lame solution of the concentric cylinders
-- (an inner disc of radius a with eigenstrain bonded in an annulus to b;
-- K the 3-D bulk modulus, eps_zz = 0, free in-plane eigenstrain
-- e = (1 + nu) alpha dT), and a particle profile measured against it.
--   s = -e / [1/(2K') + (a^2/(2K') + b^2/(2G)) / (b^2 - a^2)],  K' = K + G/3
--   disc:    sigma_rr = sigma_tt = s
--   annulus: sigma_rr = s a^2/(b^2 - a^2) (b^2/r^2 - 1)
--            sigma_tt = -s a^2/(b^2 - a^2) (b^2/r^2 + 1)
local M = {}

-- s per unit |alpha dT| (0.675 for K = 1, G = 0.5)
function M.unit(K, G, a, b)
  local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
  local Kp = K + G / 3
  return (1 + nu) / (1 / (2 * Kp) + (a * a / (2 * Kp) + b * b / (2 * G)) / (b * b - a * a))
end

-- sigma_rr, sigma_tt at radius r for the interface stress s
function M.stress(s, a, b, r)
  if r < a then return s, s end
  local f = s * a * a / (b * b - a * a)
  return f * (b * b / (r * r) - 1), -f * (b * b / (r * r) + 1)
end

-- the worst error over s of the particles' polar stresses, averaged in
-- radial bins of width h about c, against the solution: away from the
-- interface's and the rim's own cells (where two materials, or material
-- and void, share a cell), and in those cells
function M.profile(sim, c, s, a, b, h)
  local x, st = sim:particles("position"), sim:particles("stress")
  local bins = {}
  for i = 1, #x.x do
    local dx, dy = x.x[i] - c[1], x.y[i] - c[2]
    local r = math.sqrt(dx * dx + dy * dy)
    local co, sn = dx / r, dy / r
    local srr = co * co * st.xx[i] + sn * sn * st.yy[i] + 2 * co * sn * st.xy[i]
    local stt = sn * sn * st.xx[i] + co * co * st.yy[i] - 2 * co * sn * st.xy[i]
    local k = math.floor(r / h) + 1
    local bin = bins[k] or {n = 0, rr = 0, tt = 0, r = 0}
    bin.n, bin.rr, bin.tt, bin.r = bin.n + 1, bin.rr + srr, bin.tt + stt, bin.r + r
    bins[k] = bin
  end
  local worst, edge = 0, 0
  for _, bin in pairs(bins) do
    local r = bin.r / bin.n
    local rr, tt = M.stress(s, a, b, r)
    local err = math.max(math.abs(bin.rr / bin.n - rr), math.abs(bin.tt / bin.n - tt)) / s
    if math.abs(r - a) > 1.5 * h and r < b - 1.5 * h and r > h then worst = math.max(worst, err)
    else edge = math.max(edge, err) end
  end
  return worst, edge
end

return M
