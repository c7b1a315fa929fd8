-- A free elastic bar stretched and squeezed so far that its particles
-- cross cell faces: the cell-crossing error of the shape functions.
-- The bar 0.5 < x < 2.5 (L = 2) fills a domain periodic across it, so
-- it is in uniaxial strain with the wave speed c = sqrt((K + 4G/3) / rho)
-- (K = 1, G = 0.5, rho = 1), its ends free, started with the velocity
-- v0 = a (x - 1.5), a = 0.02, and no stress.  Reference: the free-free
-- modes, v(x, t) = sum over odd n of -(4 a L / (n pi)^2) cos(n pi s / L)
-- cos(n pi c t / L), s = x - 0.5 (the series of v0; 200 terms), and the
-- energy, which nothing takes.  The ends move up to 0.02 (a third of a
-- cell at 16 cells, a cell at 48): where the particles cross cell faces
-- under stress, linear hats' gradients jump.  Error: the particles'
-- velocities against the series, L2 over the initial velocity's, the
-- largest of t = 2, 4, 6, 8; and |E(8)/E0 - 1|.
-- Measured (2 x 2 particles, MUSL, FLIP, cfl 0.25), at 16 / 32 / 64 /
-- 96 / 128 cells per unit length:
--   GIMP:   0.103 / 0.050 / 0.027 / 0.018 / 0.015, energy +0.71 / +0.24 /
--           +0.29 / +0.13 / +0.18 %: order 1 to 64 cells, then towards a
--           floor of about 1 % (the strain reaches 1 %, which the linear
--           series leaves out);
--   linear: 0.093 / 0.034 / 0.34 / 0.38 / 0.51, energy +0.74 / +0.27 /
--           -0.82 / -1.95 / -4.5 %: from 64 cells (the particles cross
--           cells from t = 0.2 there) the velocity is noise; linear
--           hats diverge, which is why they are no longer the default.
-- GIMP and the default shape (quadratic B-splines) are asserted; linear
-- hats' numbers are printed (docs/verification.md, bar crossing cells;
-- open item 1).
local V = require "mvmpm.verify"
local B = require "mvmpm.crossing"

local CELLS = {16, 32, 64}
local r = {}
for _, shape in ipairs {"gimp", "bspline2", "linear"} do
  r[shape] = {}
  for k, n in ipairs(CELLS) do r[shape][k] = B.run(n, shape) end
end

V.case "free bar crossing cells (a = 0.02, L = 2): velocity against the modes, energy"
for _, shape in ipairs {"gimp", "bspline2", "linear"} do
  local e = r[shape]
  print(string.format("     %-6s velocity error %.4f / %.4f / %.4f at 16 / 32 / 64 cells (orders %.2f, %.2f); E/E0 - 1 %+.4f / %+.4f / %+.4f",
    shape, e[1].err, e[2].err, e[3].err, math.log(e[1].err / e[2].err, 2), math.log(e[2].err / e[3].err, 2),
    e[1].dE, e[2].dE, e[3].dE))
end
local g = r.gimp
V.holds("GIMP: the velocity error falls 16 -> 32 -> 64 cells", g[3].err < g[2].err and g[2].err < g[1].err, g[3].err)
V.below("GIMP: velocity error at 64 cells", g[3].err, 0.05)
V.above("GIMP: observed order 16 -> 64 cells", math.log(g[1].err / g[3].err, 4), 0.7)
V.below("GIMP: |E(8)/E0 - 1| at 32 and 64 cells", math.max(math.abs(g[2].dE), math.abs(g[3].dE)), 0.005)
local b = r.bspline2
V.holds("B-splines: the velocity error falls 16 -> 32 -> 64 cells", b[3].err < b[2].err and b[2].err < b[1].err, b[3].err)
V.below("B-splines: velocity error at 64 cells", b[3].err, 0.05)
V.above("B-splines: observed order 16 -> 64 cells", math.log(b[1].err / b[3].err, 4), 0.7)
V.below("B-splines: |E(8)/E0 - 1| at 32 and 64 cells", math.max(math.abs(b[2].dE), math.abs(b[3].dE)), 0.005)
local l = r.linear
V.info("linear hats: velocity error at 16 cells", l[1].err)
V.info("linear hats: velocity error at 64 cells (grows from 32: linear hats diverge)", l[3].err)
V.info("linear hats: E(8)/E0 - 1 at 64 cells", l[3].dE)
