#!/usr/bin/env bash
# tests/fault/limits.sh BIN - numbers the engine cannot honour are refused
# where they enter, with a message that names the scene line, and nothing
# hangs: intervals that would make more events than a run can hold, steps
# that would never reach t_end, NaN and inf from the API, from scene
# functions and from --set, scene files that are no regular files.  Each
# run has a timeout: a hang fails the check instead of blocking.
source "$(dirname "$0")/lib.sh" limits "$1"
cd "$tmp"
run() { timeout 20 "$bin" "$@" >out.txt 2>&1; }
# scene SIM-EXTRA MATERIAL BODY-EXTRA TAIL: a disk in a box; line 5 is TAIL
scene() {
  rm -rf o # each case is a new run (a directory holding one is refused)
  cat >s.lua <<EOF
local mvmpm = require "mvmpm"
local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, t_end = 0.05${1-}}
local el = mvmpm.elastic {${2:-K = 1, G = 1, density = 1}}
local b = s:body {name = "disk", shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = el${3-}}
${4-}
return s
EOF
}
# refused: the run ends with status 1 (not a timeout) and the message
# holds every text given
refused() { # refused WHAT TEXT... (after run)
  local what=$1 t good=0; shift
  for t in "$@"; do has out.txt "$t" || good=1; done
  ok $good "$what" "$(grep -m1 -v '^stack traceback' out.txt | cut -c1-150)"
}
st() { echo "status $1"; }

scene
run run s.lua --quiet --out o --checkpoint-every 1e-300; rc=$?
[ $rc -eq 1 ]; ok $? "--checkpoint-every 1e-300: refused, no hang" "$(st $rc)"
refused "  says why and what is allowed" "--checkpoint-every 1e-300" "at most" "give at least"

scene "" "" "" 's:every {time = 1e-300, fn = function() end}'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "sim:every{time = 1e-300}: refused, no hang" "$(st $rc)"
refused "  names the line and the field" "s.lua:5:" "'time'" "at most"

scene "" "" "" 's:output {every = 1e-12}'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "sim:output{every = 1e-12}: refused, no hang" "$(st $rc)"
refused "  names the line and the field" "s.lua:5:" "'every'" "at most"

scene "" "" "" 's:run(-math.huge)'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "sim:run(-math.huge): refused, no hang" "$(st $rc)"
refused "  names the line" "s.lua:5:" "must be finite"

scene "" "" "" 's:run(0.01); s:run(0.005)'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "sim:run(t) before now: refused" "$(st $rc)"
refused "  names the line" "s.lua:5:" "lies before"

scene ", dt = 1e-300"
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "dt = 1e-300: refused, no hang" "$(st $rc)"
refused "  names the line, the field and the step count" "s.lua:2:" "'dt'" "steps"

scene "" "" "" 's:every {steps = 2, fn = function(sim) sim.cfl = 1e-300 end}'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "sim.cfl = 1e-300 while running: refused, no hang" "$(st $rc)"
refused "  names the callback's line and the step count" "s.lua:5:" "cfl" "steps"

scene "" "K = 1, G = 1, density = 1e-300"
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "density = 1e-300: refused, no hang" "$(st $rc)"
refused "  names the density, the wave speed and the step count" "s.lua:4:" "density = 1e-300" "wave speed" "steps"

scene "" "K = 1e300, G = 1, density = 1"
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "K = 1e300: refused, no hang" "$(st $rc)"
refused "  names K and the step count" "s.lua:4:" "K = 1e+300" "steps"

scene "" "" ", velocity = {1e300, 0}"
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "a velocity of 1e300: refused, no hang" "$(st $rc)"
refused "  names the line and the speed" "s.lua:4:" "speed of 1e+300" "steps"

scene "" "" ", driven = {0, 0}" 'b:drive(0/0, 0)'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "b:drive(0/0, 0): refused" "$(st $rc)"
refused "  names the line and nan" "s.lua:5:" "'vx' must be finite (got nan)"
! grep -qi nan o/diagnostics.csv* 2>/dev/null
ok $? "  no NaN written"

scene "" "" ", driven = {0, 0}" 's:every {steps = 2, fn = function() b:drive(1e300, 0) end}'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "b:drive(1e300, 0) in a callback: refused" "$(st $rc)"
refused "  names the callback's line" "s.lua:5:" "speed of 1e+300"
! grep -qi inf o/diagnostics.csv* 2>/dev/null
ok $? "  no inf written"

scene "" "" ", driven = {1e300, 0}"
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "driven = {1e300, 0}: refused" "$(st $rc)"
refused "  names the line and the field" "s.lua:4:" "'driven'" "speed of 1e+300"

scene "" "" ', driven = function(t)
  return t < 0.01 and 0 or nil, 0 end'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "a drive function returning nil: refused" "$(st $rc)"
refused "  names where the function is and the body" "s.lua:4:" "drive of body 'disk'" "returned nil"

scene "" "" ', velocity = function(x, y)
  return 0/0, 0 end'
run run s.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "a velocity function returning NaN: refused" "$(st $rc)"
refused "  says so, where the function is, not det F" "s.lua:4:" "velocity of body 'disk'" "returned nan"
! has out.txt "det F"
ok $? "  not reported as a crushed material"

cat >w.lua <<'EOF'
local mvmpm = require "mvmpm"
local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, t_end = 0.05,
  sides = {bottom = {"wall", velocity = function(t)
    return t < 0.01 and 0 or "fast", 0 end}}}
local el = mvmpm.elastic {K = 1, G = 1, density = 1}
s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2}, material = el}
return s
EOF
run run w.lua --quiet --out o; rc=$?
[ $rc -eq 1 ]; ok $? "a side's velocity function returning a string: refused" "$(st $rc)"
refused "  names the side and where the function is" "w.lua:3:" "side 'bottom'" "returned string"

scene "" "" "" 's:state {f = print}'
run run s.lua --quiet --out o --checkpoint-every 0.01; rc=$?
[ $rc -eq 1 ]; ok $? "a function in sim:state, found at checkpoint time: refused" "$(st $rc)"
refused "  names where sim:state was called" "s.lua:5:" "sim:state" "state.f"

scene
sed -i '1a local P = mvmpm.params {x = 1}' s.lua
run run s.lua --quiet --out o --set x=1e400; rc=$?
[ $rc -eq 1 ]; ok $? "--set x=1e400: refused" "$(st $rc)"
refused "  says it must be finite" "--set x=1e400" "finite"

# a t_end never meant to be reached, stepped by hand: accepted (sim:step
# always ends); only a run to that t_end is refused
cat >hand.lua <<'EOF'
local mvmpm = require "mvmpm"
local s = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1 / 400, t_end = 1e9, sides = "free"}
s:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.01},
        material = mvmpm.elastic {K = 1, G = 0.5, density = 1}, velocity = {0.1, 0}}
s:step(3)
print("stepped", s.t > 0)
local ok, err = pcall(s.run, s)
print(ok and "ran" or err)
EOF
run test hand.lua; rc=$?
has out.txt "stepped	true"; ok $? "t_end = 1e9 (2e12 steps away) stepped by hand: accepted" "$(grep -m1 stepped out.txt)"
has out.txt "run: from t ="; ok $? "  a run to that t_end: refused with its step count" "$(grep -m1 -o 'run: from.*' out.txt | cut -c1-120)"

mkfifo f.lua f.h5
run run f.lua --quiet; rc=$?
[ $rc -eq 1 ]; ok $? "a FIFO as the scene: refused, no hang" "$(st $rc)"
refused "  says why" "not a regular file"
run run --restart f.h5 --quiet; rc=$?
[ $rc -eq 1 ]; ok $? "a FIFO as the checkpoint: refused, no hang" "$(st $rc)"
refused "  says why" "not a regular file"
mkdir d && mkfifo d/checkpoint_000001.h5
run run --restart d --quiet; rc=$?
[ $rc -eq 1 ]; ok $? "a FIFO as the newest checkpoint of a directory: refused, no hang" "$(st $rc)"
refused "  says why" "not a regular file"
run test f.lua; rc=$?
[ $rc -eq 1 ]; ok $? "a FIFO as a verification script: refused, no hang" "$(st $rc)"
finish
