-- mvmpm.kinetics: published single-step kinetics for the `reaction` key
-- of a material, and the thermal properties they were published with.
--
--   local K = require "mvmpm.kinetics"
--   local hmx = mvmpm.elastic {E = 15e9, nu = 0.3, density = K.pbx9501.density,
--                              cv = K.pbx9501.cv, reaction = K.hmx}
--
-- These are published values, quoted as published; none was fitted or
-- adjusted here.  The numbers were read from the input file named under
-- each set, which cites the model they belong to; the primary papers
-- were not re-checked here.  SI units (s, K, J/kg, W/(m K), kg/m^3).
local K = {}

-- HMX, first-order global decomposition:
--   d lambda/dt = Z (1 - lambda) exp(-Ta/T)
--   Z = 5.0e19 1/s, Ta = E/R = 2.652e4 K (E = 220.5 kJ/mol), Q = 5.5e6 J/kg.
-- Z and E are Rogers' HMX kinetics (R. N. Rogers, "Thermochemistry of
-- explosives", Thermochimica Acta 11 (1975) 131-139), as used with the
-- heat of reaction Q by the ViscoSCRAM model of PBX 9501 (J. G. Bennett,
-- K. S. Haberman, J. N. Johnson, B. W. Asay, B. F. Henson, J. Mech. Phys.
-- Solids 46 (1998) 2303-2322).  The three values as written in Uintah's
-- input StandAlone/inputs/MPMICE/SteadyBurn_2dRT.ups (ViscoSCRAM block:
-- Z 5.0e19, EoverR 2.652e4, delH 5.5e6).
K.hmx = {
  Z = 5.0e19, Ta = 2.652e4, Q = 5.5e6, order = 1,
  name = "HMX, single-step first order",
  source = "Rogers 1975 (Z, E); Bennett et al. 1998 ViscoSCRAM (Q); " ..
           "values as in Uintah SteadyBurn_2dRT.ups",
}

-- PBX 9501 (the reactant material of the same Uintah input): density
-- 1840 kg/m^3, specific heat 996 J/(kg K), thermal conductivity
-- 0.452 W/(m K).  For a material's density, cv and k keys.
K.pbx9501 = {
  density = 1840, cv = 996, k = 0.452,
  source = "Uintah SteadyBurn_2dRT.ups, material 'Reactant' (PBX 9501)",
}

return K
