-- Study: the bar of studies/bar.lua (first free-free mode, period 2 L / c
-- with the plane-strain c = 1.2910) over particles per cell and Courant
-- number instead of transfer: linear hats and B-splines with FLIP and MUSL,
-- ppc = 1, 2, 4 per direction, cfl = 0.1 and 0.4.
--
--   ./mvmpm test studies/bar_ppc_cfl.lua
local S = require "mvmpm.study"

local keep = S.load_only
S.load_only = true
local bar = dofile("studies/bar.lua")
S.load_only = keep

local case = {
  name = "bar_ppc_cfl",
  title = "bar: ppc and CFL",
  length = "L",
  reference = bar.reference,
  metrics = bar.metrics,
  extra = bar.extra,
  grid = {cells = {8, 16, 32, 64, 128}, shape = {"linear", "bspline2"}, ppc = {1, 2, 4},
          cfl = {0.1, 0.4}},
  run = bar.run,
}
return S.main(case)
