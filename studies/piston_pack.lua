-- Study: the energy budget of a random pack of 30 frictional discs
-- pushed by a piston (lua/mvmpm/piston.lua), in every transfer scheme,
-- at three resolutions, with mu = 0.3 and, as the control, mu = 0.
-- Per scheme and resolution: the friction work, the numerical losses the
-- budget books (transfer, impact) and the residual, all over the
-- piston's work.  Target: |residual| < 2 % of the piston's work in every
-- scheme; the friction work's spread over the schemes and its change
-- with resolution are printed.
--
--   ./mvmpm test studies/piston_pack.lua      (STUDY_QUICK=1: 3, 4, 6 cells)
local V = require "mvmpm.verify"
local S = require "mvmpm.slide"
local P = require "mvmpm.piston"

local quick = os.getenv("STUDY_QUICK") == "1"
local cells = quick and {3, 4, 6} or {4, 6, 8}

for _, mu in ipairs {0.3, 0} do
  V.case(string.format("piston pack: 30 discs, mu %g, %s cells per smallest diameter", mu,
                       table.concat(cells, ", ")))
  local fr = {}
  for k, c in ipairs(cells) do
    fr[k] = {}
    for _, sc in ipairs(S.schemes) do
      local e, w, cpu = P.run {cells = c, scheme = sc, mu = mu}
      local n = S.name(sc)
      fr[k][n] = e.dissipated / w
      -- reported, not asserted (target 2 %: APIC and XPIC miss it;
      -- tests/verify/pack_budget.lua asserts it where it is met)
      V.info(string.format("%s, %d cells: residual / piston work", n, c), e.residual / w)
      if mu > 0 then V.info(string.format("%s, %d cells: friction / piston work", n, c), e.dissipated / w) end
      V.info(string.format("%s, %d cells: impact / piston work", n, c), e.impact / w)
      V.info(string.format("%s, %d cells: transfer / piston work", n, c), e.transfer / w)
      V.info(string.format("%s, %d cells: cpu", n, c), cpu, "s")
    end
    if mu > 0 then
      local lo, hi = math.huge, -math.huge
      for _, x in pairs(fr[k]) do lo, hi = math.min(lo, x), math.max(hi, x) end
      V.info(string.format("friction spread over the schemes (max/min - 1), %d cells", c), hi / lo - 1)
    end
  end
end
