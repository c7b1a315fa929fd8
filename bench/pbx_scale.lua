-- bench/pbx_scale.lua - how the cost of the PBX grain bed
-- (scenarios/pbx9501.lua, with binder and bonds) grows with the number
-- of grains at a fixed resolution: the grain sizes and the cell stay,
-- the square grows.  One bed per process, so that the peak resident
-- size (VmHWM) is the bed's own:
--
--   PBX_SIDE=1.2e-3 ./mvmpm test bench/pbx_scale.lua    (make pbx-scale runs four)
--
-- Grains: coarse mean 150 um, fines mean 20 um, smallest resolved 12 um
-- at 8 cells across (cell 1.5 um), 2 x 2 particles per cell, packing
-- 0.75.  Prints one `pbx` line: grains, cells, particles, seconds per
-- step (median of repeats, after warm-up steps, bench/lib.lua), steps/s,
-- nanoseconds per particle-step, bytes allocated (sim.memory) and the
-- peak resident size, and the steps and wall time a 100 % strain run at
-- the scene's shear rate would take.  Nothing here is a test.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local side = tonumber(os.getenv("PBX_SIDE") or "0.65e-3")
local over = {size = side, fine = 20e-6, min_grain = 12e-6, cells = 8, packing = 0.75,
              images = 0, strain = 1.0}
local function hwm()
  local f = io.open("/proc/self/status")
  if not f then return 0 end
  local s = f:read("a")
  f:close()
  return tonumber(s:match("VmHWM:%s*(%d+)%s*kB") or 0) * 1024
end

local t0 = mvmpm.clock()
local sim = mvmpm.load("scenarios/pbx9501.lua", over)
sim:stable_dt()
local setup = mvmpm.clock() - t0
local st = PBX.bed.stats
local cells = math.floor(side / sim.cell + 0.5) ^ 2
-- wall seconds per step (median of repeats) and, beside it, the process
-- CPU seconds over the same steps: the machine is shared, and CPU time
-- is what other jobs disturb least
local c0 = os.clock()
sim:step(2)
local c1 = os.clock()
local sec, n = B.time_steps(sim, 0)
local cpu = (os.clock() - c1) / (1 + n * B.reps)   -- time_steps: 1 probe step, then reps x n
local _ = c0
local mem = sim.memory
local steps = sim.t_end / sim.dt
print(string.format(
  "pbx side %.3g mm: %d grains (%d coarse, %d fine), %d cells, %d particles, %d shared nodes; "
  .. "setup %.1f s", side * 1e3, st.count, st.coarse, st.fine, cells, sim.n, sim.shared_nodes, setup))
print(string.format(
  "pbx   %6d grains %9d particles  %.4f s/step  %7.2f steps/s  %6.1f ns/particle-step  "
  .. "(CPU %.4f s/step, %6.1f ns)  alloc %.0f MB  peak RSS %.0f MB  (%d steps timed x %d)",
  st.count, sim.n, sec, 1 / sec, 1e9 * sec / sim.n, cpu, 1e9 * cpu / sim.n,
  (mem.particles + mem.grid + mem.contact) / 2^20, hwm() / 2^20, n, B.reps))
print(string.format(
  "pbx   100 %% strain at %.3g/s: t = %.3g s, dt = %.3g s, %.3g steps, %.3g h wall "
  .. "(%.3g h CPU) on one core", 1e5, sim.t_end, sim.dt, steps, steps * sec / 3600,
  steps * cpu / 3600))
