-- bench/snapshot.lua - what one snapshot costs: sim:snapshot of a disc
-- of 3228 particles, written N times into a scratch directory (removed
-- afterwards), CPU (os.clock) and wall time per snapshot.  The write is
-- the whole durable path: the file built in memory, its checksum block,
-- write, fsync and rename (src/io/out_h5.c).  SNAP_DIR picks the directory
-- (e.g. /dev/shm for tmpfs; default a fresh one under /tmp).
local mvmpm = require "mvmpm"
local quick = os.getenv("BENCH_QUICK") == "1"
local sim = mvmpm.sim {domain = {x = {0, 4}, y = {0, 4}}, cell = 1/16, t_end = 1, shape = "gimp"}
sim:body {shape = mvmpm.disk {center = {1, 2}, radius = 1},
  material = mvmpm.elastic {K = 1, G = 0.5, density = 1}, velocity = {0.1, 0}}
sim:step(1)
local base = os.getenv("SNAP_DIR") or "/tmp"
local dir = string.format("%s/mvmpm-snapbench-%d", base, math.random(1, 1 << 30))
assert(os.execute("mkdir -p '" .. dir .. "'"))
local N = quick and 20 or 60
local c0, w0 = os.clock(), mvmpm.clock()
for k = 1, N do sim:snapshot(string.format("%s/s_%03d.h5", dir, k)) end
local c1, w1 = os.clock(), mvmpm.clock()
os.execute("rm -rf '" .. dir .. "'")
print(string.format("snapshot   %d particles into %s: %.2f ms CPU, %.2f ms wall per snapshot (%d written)",
                    sim.n, base, 1e3 * (c1 - c0) / N, 1e3 * (w1 - w0) / N, N))
