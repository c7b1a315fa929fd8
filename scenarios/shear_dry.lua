-- The report's small granular shear cell, dry (Bardenhagen, Brackbill &
-- Sulsky 1998, Figures 6 and 7): nine elastic-plastic cylinders in a
-- square of side 4, top and bottom periodic (eleven pieces counting the
-- images across the seam), the four touching the left and right sides
-- driven with them; the left side moves down and the right up to 100 %
-- average shear strain.  Coulomb friction 0.3 everywhere.  Geometry,
-- parameters and the reports: lua/mvmpm/shear.lua and docs/shear.md.
--
--   mvmpm run scenarios/shear_dry.lua [--set cells=50] [--out out/shear_dry]
--
-- Beside the snapshots it writes shear.csv (force, energies, spins,
-- invariants per sample), locking.csv, summary.txt, force_strain.png,
-- rotation.png, energy.png, and sdiff_NNN.png / body_NNN.png pictures at
-- every 25 % of strain.
local mvmpm = require "mvmpm"
local shear = require "mvmpm.shear"

local P = mvmpm.params(shear.params {})
local sim = shear.build(P)
local hot = P.heat == true or P.heat == "true"   -- --set heat=true: docs/hotspots.md
sim:output {dir = "out/shear_dry", every = sim.t_end / 20, csv_every = 20,
            hotspots = hot and {threshold = P.T0 + P.hotspot_threshold} or nil}
return sim
