-- mvmpm.repl: help at the prompt, and readable energy and body tables.
local text = [[
sim:step(n)          advance n steps (default 1)
sim:run(t)           advance to time t (default: the scene's t_end)
sim:energy()         kinetic, strain, dissipated, boundary_work, total, residual, px, py, angmom
sim:bodies()         the bodies; b:diag(), b:centroid(), b:velocity(), b:omega(), b:mass()
sim:particles(name)  copy of a particle field (sim:particles() lists them)
sim:snapshot(path)   write an HDF5 snapshot now
sim.t sim.dt sim.steps sim.n  time, step size, step count, particle count
sim.flip = f  sim.cfl = c  sim.dt = d  sim.friction = mu   change settings between steps
Ctrl-C stops running steps; Ctrl-D leaves.]]
function help() print(text) end
