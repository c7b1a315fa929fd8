-- tests/verify/scenes/threads_mix.lua - a scene for threads.lua (not a case
-- itself): a plastic disc thrown onto a viscoelastic slab, periodic in x,
-- with gravity and friction, crossing the periodic side as it lands.
local mvmpm = require "mvmpm"
local P = mvmpm.params {cells = 60, shape = "linear", update = "musl", transfer = "flip",
                        t_end = 1, friction = 0.3}
local sim = mvmpm.sim {
  domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / P.cells, ppc = 2,
  shape = P.shape, update = P.update, transfer = P.transfer, t_end = P.t_end,
  gravity = {0, -1},
  sides = {left = "periodic", right = "periodic", bottom = "wall", top = "wall"},
  contact = {friction = P.friction},
}
sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {1, 0.3}},
          material = mvmpm.viscoelastic {K = 1, G_inf = 0.5, density = 1, prony = {{G = 0.3, tau = 0.05}}}}
sim:body {name = "disc", shape = mvmpm.disk {center = {0.93, 0.55}, radius = 0.2},
          material = mvmpm.plastic {K = 1, G = 0.5, density = 1, yield = 0.002},
          velocity = {0.3, -0.6}}
return sim
