-- The report's small granular shear cell with binder (Bardenhagen,
-- Brackbill & Sulsky 1998, Figure 8): the cylinders of shear_dry.lua with
-- every interstitial area filled by a viscoelastic binder (mvmpm.rest), a
-- generalized Maxwell solid much softer than the grains, bonded to the
-- grains with strength `bond` (0: never bonded; the report's two cases
-- are zero and large), Coulomb friction 0.3 once debonded.  Geometry,
-- parameters and the reports: lua/mvmpm/shear.lua and docs/shear.md.
--
--   mvmpm run scenarios/shear_binder.lua [--set bond=0] [--out out/shear_binder]
--
-- Beside the files of shear_dry.lua it writes debond.png (the debonded
-- fraction of the grain-binder interface against strain) and bond_NNN.png.
-- With --set heat=true (grains' and binder's cv, k, beta: the heat
-- parameters in lua/mvmpm/shear.lua) also temperature_NNN.png,
-- heat.csv (heat by source, hot spots, the budget with heat), the
-- hot-spot plots, hotspots_NNNNNN.csv beside the snapshots, and "heat:"
-- lines in summary.txt (docs/hotspots.md).
local mvmpm = require "mvmpm"
local shear = require "mvmpm.shear"

local P = mvmpm.params(shear.params {binder = true, bond = 0.01})
local sim = shear.build(P)
local hot = P.heat == true or P.heat == "true"
sim:output {dir = "out/shear_binder", every = sim.t_end / 20, csv_every = 20,
            hotspots = hot and {threshold = P.T0 + P.hotspot_threshold} or nil}
return sim
