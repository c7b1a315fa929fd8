-- mvmpm.plot over extreme values: denormals, 1e308, ranges wider than
-- the largest double, NaN and infinities among the points, fixed ranges
-- far from the data, log axes over hundreds of decades
local mvmpm = require "mvmpm"
local nan, inf = 0 / 0, math.huge
local cases = {
  {{x = {1, 2, 3}, y = {1e-310, 2e-310, 3e-310}}},
  {{x = {0, 5e-324}, y = {0, 5e-324}}},
  {{x = {1e-320, 1e-310}, y = {1, 2}}, xlog = true},
  {{x = {1, 2, 3}, y = {1e308, -1e308, 1.7e308}}},
  {{x = {-1.7e308, 1.7e308}, y = {1.7e308, -1.7e308}}},
  {{x = {1.79e308, 1.79e308}, y = {-1.79e308, -1.79e308}}},
  {{x = {1e-300, 1, 1e300}, y = {1e-308, 1, 1e308}}, xlog = true, ylog = true},
  {{x = {1e-323, 1e308}, y = {5e-324, 1.7e308}}, xlog = true, ylog = true},
  {{x = {1, 2, 3, 4}, y = {nan, inf, -inf, 1}}},
  {{x = {nan, inf}, y = {1, 2}}, {x = {1, 1 + 1e-15}, y = {1e15, 1e15 + 1}}},
  {{x = {1, 2}, y = {1e308, 1e308}}, yrange = {0, 1}},
  {{x = {1, 2}, y = {1, 2}}, xrange = {-1e308, 1e308}, yrange = {1e-310, 2e-310}},
  {{x = {1, 2}, y = {1, 2}}, xrange = {0, 5e-324}, yrange = {1, 1 + 2.3e-16}},
  {{x = {1, 2}, y = {1, 2}}, xrange = {5e-324, 1.7e308}, xlog = true},
  {{x = {1, 2}, y = {1, 2}}, yrange = {1, inf}},
  {{x = {1, 2}, y = {1, 2}}, yrange = {nan, 1}},
  {{x = {1e9, 1e9 + 1}, y = {-1e-9, 1e-9}}},
  {{x = {-1e300, 1e300}, y = {1, 2}, style = "points"}},
}
for k, c in ipairs(cases) do
  local t = {file = "plot_extremes.png", series = {}, width = 300, height = 200}
  for i, s in ipairs(c) do t.series[i] = s end
  for _, f in ipairs {"xlog", "ylog", "xrange", "yrange"} do t[f] = c[f] end
  local ok, err = pcall(mvmpm.plot, t)
  print(k, ok, err)
end
