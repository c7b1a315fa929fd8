-- mvmpm.materials: parameter sets for PBX-like grain beds, in SI units
-- (Pa, kg/m^3, s).  Each entry is a function taking optional overrides
-- (any constructor field, e.g. name = "grain", alpha = 1e-4) and returning
-- a material:
--
--   local M = require "mvmpm.materials"
--   local hmx = M.hmx {name = "coarse"}
--   local binder = M.pbx9501_composite()
--
-- Sources and their status are given beside each set.  None of the values
-- below was checked against the primary papers here: they are the values
-- commonly quoted for these materials; check them before relying on them.
local mvmpm = require "mvmpm"
local M = {}

local function with(base, over)
  local t = {}
  for k, v in pairs(base) do t[k] = v end
  for k, v in pairs(over or {}) do t[k] = v end
  return t
end

-- HMX grains, J2 elastic-perfectly-plastic.
--   density 1.90 g/cm^3: the beta-HMX crystal density (LASL Explosive
--     Property Data, Gibbs and Popolato, 1980, gives 1.903 g/cm^3).
--   E = 15 GPa, nu = 0.3, yield = 0.26 GPa: values commonly used for HMX
--     in grain-scale PBX models; unverified here.  Measured isotropic
--     averages of beta-HMX scatter widely (molecular-dynamics and
--     nanoindentation studies give E of roughly 15-25 GPa), and the
--     crystal is anisotropic and brittle, so J2 plasticity is itself an
--     approximation (as in the seed report, which models the crystals as
--     elastic-plastic).
M.HMX = {E = 15e9, nu = 0.3, density = 1900, yield = 0.26e9, hardening = 0,
         name = "HMX"}
function M.hmx(over) return mvmpm.plastic(with(M.HMX, over)) end

-- PBX 9501 *composite* (HMX + binder as one homogenized material),
-- generalized Maxwell.  The 5-element set used with the ViscoSCRAM model
-- (Bennett, Haberman, Johnson, Asay and Henson, J. Mech. Phys. Solids 46,
-- 1998): shear moduli G = 3.5e8, 1.739e8, 5.212e8, 9.085e8, 6.875e8 Pa
-- with relaxation rates 0, 7.32e3, 7.32e4, 7.32e5, 2.0e6 1/s; nu = 0.3,
-- density 1840 kg/m^3.  The rate-0 element is the long-term modulus G_inf;
-- tau = 1 / rate for the others.  Unverified here against the paper.
-- The bulk modulus is our reading: K from nu and the glassy (total) shear
-- modulus, K = 2 G (1 + nu) / (3 (1 - 2 nu)) = 5.72 GPa.
local rates = {7.32e3, 7.32e4, 7.32e5, 2.0e6}
local moduli = {1.739e8, 5.212e8, 9.085e8, 6.875e8}
local function prony(scale)
  local p = {}
  for k = 1, #rates do p[k] = {G = moduli[k] * scale, tau = 1 / rates[k]} end
  return p
end
local Gglassy = 3.5e8
for k = 1, #moduli do Gglassy = Gglassy + moduli[k] end
M.PBX9501_COMPOSITE = {K = 2 * Gglassy * 1.3 / (3 * 0.4), G_inf = 3.5e8,
                       prony = prony(1), density = 1840, name = "PBX9501"}
function M.pbx9501_composite(over)
  return mvmpm.viscoelastic(with(M.PBX9501_COMPOSITE, over))
end

-- PBX 9501 binder (Estane 5703 + BDNPA/F 1:1 by weight, density about
-- 1.28 g/cm^3 -- unverified).  We found no published Prony set for the
-- binder itself that we could check, so this is a PLACEHOLDER, not data:
-- the composite's relaxation times with every shear modulus divided by
-- 100 (glassy 26 MPa, long-term 3.5 MPa: the order of a rubbery
-- polyurethane above its glass transition) and K = 2.5 GPa (a typical
-- rubber bulk modulus, so the binder is nearly incompressible).  The
-- shape of the relaxation spectrum is borrowed, not measured; replace it
-- with fitted binder data before drawing conclusions that depend on it.
M.BINDER_PLACEHOLDER = {K = 2.5e9, G_inf = 3.5e6, prony = prony(0.01),
                        density = 1280, name = "binder"}
function M.binder_placeholder(over)
  return mvmpm.viscoelastic(with(M.BINDER_PLACEHOLDER, over))
end

return M
