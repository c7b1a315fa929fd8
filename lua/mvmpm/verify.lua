-- mvmpm.verify: checks for verification scripts.  Each check prints its
-- measured value beside the reference and the tolerance, pass or fail;
-- `mvmpm test` adds up the counts kept here.
local M = {passed = 0, failed = 0}

local function report(ok, name, measured, ref, tol, note)
  if ok then M.passed = M.passed + 1 else M.failed = M.failed + 1 end
  local r = type(ref[2]) == "number" and string.format("%.5g", ref[2]) or ref[2]
  print(string.format("%s %-52s measured %-12.5g %s %-12s %s",
    ok and "ok  " or "FAIL", name, measured, ref[1], r, tol or ""))
  if note then print("     " .. note) end
  return ok
end

-- a heading for the checks that follow
function M.case(title) print("-- " .. title) end

-- |measured - reference| <= tol (absolute), or rel = true for relative
function M.near(name, measured, reference, tol, rel, note)
  local err = math.abs(measured - reference)
  local lim = rel and tol * math.abs(reference) or tol
  return report(err <= lim and measured == measured, name, measured,
    {"reference", reference},
    string.format("tol %s%g", rel and "rel " or "", tol), note)
end

-- measured <= limit
function M.below(name, measured, limit, note)
  return report(measured <= limit, name, measured, {"limit <=", limit}, nil, note)
end

-- measured >= limit
function M.above(name, measured, limit, note)
  return report(measured >= limit, name, measured, {"limit >=", limit}, nil, note)
end

-- a condition that is true or false, with the measured number for the record
function M.holds(name, ok, measured, note)
  return report(ok and true or false, name, measured or 0, {"", ""}, nil, note)
end

-- print a measured figure that is reported but not judged
function M.info(name, value, unit)
  print(string.format("info %-52s %-12.5g %s", name, value, unit or ""))
end

return M
