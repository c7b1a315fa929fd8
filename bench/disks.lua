-- bench/disks.lua - (b) the two-disk collision (scenarios/two_disks.lua)
-- at 160 x 160 cells, one velocity field per disk, frictionless contact.
-- The disks first share grid nodes near t = 1.55 and part near t = 2.75;
-- the timing starts at t = 1.7 and ends well before they part.
local mvmpm = require "mvmpm"
local B = dofile("bench/lib.lua")

local sim = mvmpm.load("scenarios/two_disks.lua",
                       {cells = 160, fields = "body", t_end = 1e9})
sim:run(1.7)
local shared0 = sim.shared_nodes
B.target = B.target * 0.6 -- keep the timed window inside the contact
local rate, sec, n = B.rate(sim, 1)
B.line("rate", "(b) two disks 160x160, in contact", rate / 1e6, "M p-st/s",
  string.format("%d particles, %.2f ms/step, median of %d x %d steps, " ..
    "t %.2f-%.2f, shared nodes %d..%d", sim.n, 1e3 * sec, B.reps, n, 1.7, sim.t,
    shared0, sim.shared_nodes))
B.line("reference", "two disks in contact (codes A, B, one core)", 0.53, "M p-st/s",
  "to 0.8")
