-- Study: the frictional bouncing cylinder (mu = 0.1), first impact, the
-- walls acting per contact patch (wall_contact = "patch"; WALL_CONTACT=couple
-- in the environment: friction at the wall line, "couple").
-- Reference: a rigid disc hitting a wall with restitution e (the one the
-- run measures: the elastic disc keeps some energy as vibration) takes a
-- Coulomb impulse mu (1 + e) m v_n while it slides (it slides throughout
-- here: mu < slip / (3 (1 + e) v_n)), so its spin after the impact is
-- omega = 2 mu (1 + e) v_n / R about the contact's sense (the impulse acts
-- at R; I = m R^2 / 2), as in tests/verify/cylinder_bounce.lua.  Measured:
-- the spin averaged over the flight t = 8 .. 16 (a sample per time unit;
-- the disc rings after the impact).  Error: |omega / omega_rigid - 1|.
--
--   ./mvmpm test studies/bounce_friction.lua
local mvmpm = require "mvmpm"
local S = require "mvmpm.study"

local mu, R, v0 = 0.1, 0.5, 0.1
local rule = os.getenv("WALL_CONTACT") or "patch"

local case = {
  name = rule == "patch" and "bounce_friction" or "bounce_friction_" .. rule,
  title = "frictional bounce, spin after impact 1",
  length = "D",
  reference = "rigid-disc impulse model given the measured restitution: omega = 2 mu (1 + e) v_n / R",
  metrics = {{key = "spin", label = "|omega/omega_rigid - 1|"}},
  extra = {"omega", "omega_rigid", "restitution", "energy_left", "dissipated"},
  grid = {cells = {8, 12, 16, 24, 32, 48}, shape = {"linear", "gimp", "bspline2"},
          transfer = {"flip", "apic", "spin"}, flip = {1, 0}},
  baseline = {cells = 8, shape = "linear", transfer = "flip", flip = 1, update = "musl"},
  skip = function(s) return s.flip == 0 and s.shape ~= "linear" end,   -- PIC only on linear hats
  run = function(s, clock)
    local sim = mvmpm.load("scenarios/cylinder_bounce.lua",
      {cells = s.cells, ppc = s.ppc, shape = s.shape, transfer = s.transfer, flip = s.flip,
       update = s.update, cfl = s.cfl, friction = mu, t_end = 16, wall_contact = rule})
    local disc = sim:bodies()[1]
    local e0 = sim:energy().total
    local sum, n, vx = 0, 0, nil
    clock.run(sim, 8)
    for t = 8, 16 do
      clock.run(sim, t)
      sum, n = sum + disc:omega(), n + 1
      if t == 10 then vx = disc:velocity() end
    end
    local e = -vx / v0                  -- restitution of impact 1 (right wall)
    -- right wall, n = +x; the disc slides up (+y), friction pushes down at
    -- the contact point (R, 0): torque R x (-J) < 0, so omega < 0
    local w_rigid = -2 * mu * (1 + e) * v0 / R
    local w = sum / n
    local en = sim:energy()
    return {spin = math.abs(w / w_rigid - 1), omega = w, omega_rigid = w_rigid, restitution = e,
            energy_left = en.total / e0, dissipated = en.dissipated / e0}
  end,
}
return S.main(case)
