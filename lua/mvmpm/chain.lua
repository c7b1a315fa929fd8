-- mvmpm.chain: force chains on the contact graph of sim:contacts().
--
-- The graph: bodies are vertices, and two bodies pressing on each other
-- (a compressive normal force at some shared node) are joined by an edge
-- weighted by that force.  A force chain between two sets of bodies is a
-- path of such edges from one set to the other; its strength is the
-- least force along it, and the strongest chain is the path whose least
-- force is largest (a bottleneck path).  It is found by joining the
-- edges in falling order of force (union-find) until the two sets meet:
-- the force of the edge that joins them is the chain's strength.
--
--   local chain = require "mvmpm.chain"
--   local c = chain.strongest(sim:contacts(), {[1] = true}, {[4] = true},
--                             {skip = {[5] = true}})
--   -- c == nil: no chain; else c.force, c.path (body ids, from -> to)
local M = {}

-- the strongest chain from a body in `from` to a body in `to` (sets of
-- body ids), through bodies not in opt.skip, over edges of at least
-- opt.min force (default 0); nil if none
function M.strongest(contacts, from, to, opt)
  opt = opt or {}
  local skip, fmin = opt.skip or {}, opt.min or 0
  local edges = {}
  for _, c in ipairs(contacts) do
    if c.force > fmin and not skip[c.a] and not skip[c.b] then edges[#edges + 1] = c end
  end
  -- a fixed order: by force, falling, then by the pair
  table.sort(edges, function(x, y)
    if x.force ~= y.force then return x.force > y.force end
    if x.a ~= y.a then return x.a < y.a end
    return x.b < y.b
  end)
  local up = {}
  local function find(v)
    local r = v
    while up[r] and up[r] ~= r do r = up[r] end
    while up[v] and up[v] ~= r do
      local nxt = up[v]
      up[v] = r
      v = nxt
    end
    return r
  end
  -- the two sets as two roots of their own
  local SRC, DST = "from", "to"
  for v in pairs(from) do up[v] = SRC end
  for v in pairs(to) do
    if from[v] then return {force = math.huge, path = {v}} end
    up[v] = DST
  end
  up[SRC], up[DST] = SRC, DST
  local bottleneck
  for _, e in ipairs(edges) do
    local ra, rb = find(e.a), find(e.b)
    if ra ~= rb then
      up[ra] = rb
      if find(SRC) == find(DST) then
        bottleneck = e.force
        break
      end
    end
  end
  if not bottleneck then return nil end
  -- the path: breadth-first over the edges at least that strong
  local adj = {}
  for _, e in ipairs(edges) do
    if e.force < bottleneck then break end
    adj[e.a] = adj[e.a] or {}
    adj[e.b] = adj[e.b] or {}
    table.insert(adj[e.a], e.b)
    table.insert(adj[e.b], e.a)
  end
  local prev, queue, head = {}, {}, 1
  local starts = {}
  for v in pairs(from) do starts[#starts + 1] = v end
  table.sort(starts)
  for _, v in ipairs(starts) do prev[v] = false; queue[#queue + 1] = v end
  while head <= #queue do
    local v = queue[head]
    head = head + 1
    if to[v] then
      local path = {}
      while v do table.insert(path, 1, v); v = prev[v] end
      return {force = bottleneck, path = path}
    end
    for _, w in ipairs(adj[v] or {}) do
      if prev[w] == nil then prev[w] = v; queue[#queue + 1] = w end
    end
  end
  return {force = bottleneck, path = {}}
end

-- whether any chain joins the sets (edges above opt.min)
function M.spans(contacts, from, to, opt)
  return M.strongest(contacts, from, to, opt) ~= nil
end

return M
