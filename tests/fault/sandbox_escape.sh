#!/usr/bin/env bash
# tests/fault/sandbox_escape.sh BIN - ways out of `mvmpm run --sandbox`
# that must stay shut: a restart of a sandboxed run (the printed command,
# and one without --sandbox), an empty or unusable output root, engine
# objects freed by hand or passed to another simulation, symbolic links
# planted in the output directory, and a changed scene on restart (run
# before it was compared).  Each ends in a message and status 1 or 2,
# never a crash, and nothing outside the output directory is touched.
source "$(dirname "$0")/lib.sh" sandbox_escape "$1"
cd "$tmp"
base='local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/8, t_end = 0.05}
local disk = sim:body {name = "disk", shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}, velocity = {0.1, 0}}'
crashed() { [ "$1" -ge 128 ] || grep -q "PANIC\|AddressSanitizer\|runtime error" "$2"; }

# --- a sandboxed run that checkpoints, then fails: its restart -------------
cat >ck.lua <<LUA
$base
local ok, f = pcall(function() return io.open("$tmp/escaped", "w") end)
print(ok and "io: allowed" or "io: refused: " .. tostring(f))
if ok and f then f:write("out"); f:close() end
sim:output {checkpoint = 0.01}
sim:every {time = 0.03, fn = function() error("planned failure") end}
return sim
LUA
"$bin" run ck.lua --sandbox --out ck --quiet >out.txt 2>&1
rc=$?
cmd=$(sed -n 's/.*continue with: mvmpm \(run [^)]*\)).*/\1/p' out.txt)
[ "$rc" -eq 1 ] && has out.txt "planned failure" && [ -n "$cmd" ] && [ ! -e escaped ]
ok $? "a sandboxed scene checkpoints, then fails" "status $rc"
case " $cmd " in *" --sandbox "*) true ;; *) false ;; esac
ok $? "the printed continue command keeps --sandbox" "mvmpm $cmd"
# shellcheck disable=SC2086
"$bin" $cmd >out2.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out2.txt "io: refused: " && has out2.txt "io is not available under --sandbox" && [ ! -e escaped ]
ok $? "the printed command restarts it sandboxed: io still refused" "$(grep -m1 'io:' out2.txt | cut -c1-90)"
ck=$(ls ck/checkpoint_*.h5 | tail -1)
"$bin" run --restart "$ck" --quiet >out3.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out3.txt "io: refused: " && [ ! -e escaped ] &&
  has out3.txt "was written by a run under --sandbox, so this one is too (--sandbox applies)"
ok $? "restarted without --sandbox, the sandbox is implied and said" "$(grep -m1 'applies' out3.txt | cut -c1-120)"
has out3.txt "continue with: mvmpm run --restart ck/checkpoint_" && grep -q "continue with: .* --sandbox" out3.txt
ok $? "its own continue command keeps --sandbox"

# Ctrl-C on a sandboxed run: the command it prints keeps --sandbox
printf '%s\nsim.t_end = 1000\nsim:output {every = 0.02}\nreturn sim\n' "$base" >long.lua
"$bin" run long.lua --sandbox --out long --quiet >int.txt 2>&1 &
pid=$!
for _ in $(seq 600); do [ -e long/particles_000001.h5 ] && break; sleep 0.05; done
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 130 ] && grep -q "continue with: mvmpm run --restart long/checkpoint_000001.h5 --sandbox" int.txt
ok $? "interrupted: the continue command keeps --sandbox" "$(grep -m1 'continue with' int.txt)"

# --- the output root -------------------------------------------------------
printf '%s\nsim:snapshot("tmp/mvmpm_escape_%s/y.h5")\nreturn sim\n' "$base" "$$" >root.lua
"$bin" run root.lua --sandbox --out "" --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 2 ] && has out.txt "--out needs a directory (the name given is empty)" && [ ! -e "/tmp/mvmpm_escape_$$" ]
ok $? "--sandbox --out \"\": refused, nothing written at /tmp" "status $rc: $(head -1 out.txt)"
rm -rf "/tmp/mvmpm_escape_$$"
printf '%s\nprint("the scene ran")\nreturn sim\n' "$base" >plain.lua
"$bin" run plain.lua --out "" --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 2 ] && has out.txt "--out needs a directory"
ok $? "--out \"\" without --sandbox: refused (it wrote nothing and said output: /)" "status $rc: $(head -1 out.txt)"
touch afile
"$bin" run plain.lua --sandbox --out afile --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "afile: the output directory is not a directory" && ! has out.txt "the scene ran"
ok $? "--out naming a file: refused before the scene runs" "$(head -1 out.txt)"
"$bin" run plain.lua --out afile/sub --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "afile/sub: cannot create directory (Not a directory)" && ! has out.txt "the scene ran"
ok $? "--out that cannot be made: refused before the scene runs" "$(head -1 out.txt)"

# --- engine objects freed by hand ------------------------------------------
n=0
gc() { # WHAT FLAGS LINES TEXT
  n=$((n + 1))
  printf '%s\n%s\nreturn sim\n' "$base" "$3" >gc$n.lua
  # shellcheck disable=SC2086
  "$bin" run gc$n.lua $2 --out gc$n --quiet >out.txt 2>&1
  local rc=$?
  ! crashed $rc out.txt && [ "$rc" -eq 1 ] && has out.txt "$4"
  ok $? "$1" "status $rc: $(grep -m1 -o "gc$n.lua:.*" out.txt | cut -c1-110)"
}
gc "getmetatable(sim).__gc(sim) under --sandbox" --sandbox 'getmetatable(sim).__gc(sim)' \
   "attempt to call a nil value (field '__gc')"
gc "getmetatable(sim).__gc(sim) without --sandbox" "" 'getmetatable(sim).__gc(sim)' \
   "attempt to call a nil value (field '__gc')"
gc "every engine metatable is hidden" --sandbox \
   'for _, o in ipairs{sim, disk, mvmpm.elastic{K = 1, G = 1, density = 1}, mvmpm.disk{center = {0, 0}, radius = 1}} do
      assert(type(getmetatable(o)) == "string", tostring(o)) end
    error("all hidden")' "all hidden"
gc "debug.getmetatable(sim).__gc(sim) twice, then sim used: an error" "" \
   'local mt = debug.getmetatable(sim); mt.__gc(sim); mt.__gc(sim); print(tostring(sim)); sim:energy()' \
   "the simulation was closed (its __gc ran and its memory is released)"
gc "a body of a closed simulation: an error" "" \
   'debug.getmetatable(sim).__gc(sim); disk:mass()' \
   "body 1: its simulation was closed"
gc "through the registry, then the scene returns the closed sim" "" \
   'debug.getregistry()["mvmpm.sim"].__gc(sim)' \
   "the scene closed its simulation"
gc "closed by a callback while it runs: refused" "" \
   'sim:every {steps = 2, fn = function(s) debug.getmetatable(s).__gc(s) end}' \
   "the simulation is running (a callback, drive or velocity function is under way): it cannot be closed now"
gc "closed by a body's velocity function: refused" "" \
   'sim:body {shape = mvmpm.disk {center = {0.1, 0.1}, radius = 0.05}, material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
              velocity = function() debug.getmetatable(sim).__gc(sim); return 0, 0 end}' \
   "it cannot be closed now"
gc "__gc of another type given the sim: refused by type" "" \
   'debug.getregistry()["mvmpm.seedbox"].__gc(sim); sim:energy(); error("still whole")' \
   "bad argument #1 to '__gc' (mvmpm.seedbox expected, got mvmpm.sim)"

# --- bodies passed to another simulation -----------------------------------
two="$base"'
local other = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/8, t_end = 0.05}
local o1 = other:body {name = "o1", shape = mvmpm.disk {center = {0.2, 0.2}, radius = 0.1},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
local o2 = other:body {name = "o2", shape = mvmpm.disk {center = {0.8, 0.8}, radius = 0.1},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
local mine = sim:body {name = "mine", shape = mvmpm.disk {center = {0.1, 0.1}, radius = 0.05},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}'
mix() { # WHAT LINE
  n=$((n + 1))
  printf '%s\n%s\nreturn sim\n' "$two" "$2" >mix$n.lua
  "$bin" run mix$n.lua --sandbox --out mix$n --quiet >out.txt 2>&1
  local rc=$?
  ! crashed $rc out.txt && [ "$rc" -eq 1 ] && has out.txt "contact: body 'o2' belongs to another simulation"
  ok $? "$1" "status $rc: $(grep -m1 -o "mix$n.lua:[0-9]*: .*" out.txt | cut -c1-100)"
}
mix "sim:contact(mine, other's body): refused" 'sim:contact(mine, o2, {friction = 0.3})'
mix "sim:contact(other's body, mine): refused" 'sim:contact(o2, disk, {friction = 0.3})'
mix "sim:contact with both of another's: refused" 'sim:contact(o2, o1, {friction = 0.3})'

# --- symbolic links planted in the output directory ------------------------
honest="$base"'
sim:output {checkpoint = 0.02}
sim:every {time = 0.02, fn = function(s)
  s:snapshot("mine/snap.h5")
  s:render {file = "pic.png"}
  mvmpm.plot {file = "plots/p.png", series = {{x = {0, 1}, y = {0, 1}}}}
end}
return sim'
printf '%s\n' "$honest" >links.lua
mkdir outside && echo keep >outside/target && mkdir outside/dir
sum() { (cd outside && find . -type f -exec md5sum {} + | sort; find . | sort) | md5sum; }
before=$(sum)
link() { # WHAT NAME [LINK TARGET]
  rm -rf L; mkdir L
  mkdir -p "L/$(dirname "$2")"
  ln -s "${3:-$tmp/outside/target}" "L/$2"
  "$bin" run links.lua --sandbox --out L --quiet >out.txt 2>&1
  local rc=$?
  [ "$rc" -eq 1 ] && has out.txt "L/$2 is a symbolic link; under --sandbox no link" && [ "$(sum)" = "$before" ]
  ok $? "refused: a link at $1" "status $rc: $(grep -m1 -o 'mvmpm: .*' out.txt | cut -c1-120)"
}
link "the first snapshot"   particles_000000.h5
link "a later snapshot"     particles_000002.h5
link "a snapshot's temp"    particles_000001.h5.tmp
link "particles.xmf"        particles.xmf
link "particles.xmf's temp" particles.xmf.tmp
link "diagnostics.csv.part" diagnostics.csv.part
link "diagnostics.csv"      diagnostics.csv
link "a checkpoint"         checkpoint_000001.h5
link "a checkpoint's temp"  checkpoint_000002.h5.tmp
link "sim:snapshot's file"  mine/snap.h5
link "sim:render's file"    pic.png
link "mvmpm.plot's file"    plots/p.png
link "a render's temp"      pic.png.tmp
link "a subdirectory"       mine "$tmp/outside/dir"
link "a plot's subdirectory" plots "$tmp/outside/dir"
# a restart in a directory where a link was put after the checkpoint
rm -rf R && "$bin" run links.lua --sandbox --out R --quiet >/dev/null 2>&1
rm -f R/diagnostics.csv && ln -s "$tmp/outside/target" R/diagnostics.csv.part
"$bin" run --restart R/checkpoint_000001.h5 --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "R/diagnostics.csv.part is a symbolic link" && [ "$(sum)" = "$before" ]
ok $? "refused: a link at the table a restart continues" "status $rc: $(grep -m1 -o 'mvmpm: .*symbolic' out.txt | cut -c1-110)"

# --- a changed scene on restart is not run ---------------------------------
printf '%s\nsim:output {checkpoint = 0.02}\nreturn sim\n' "$base" >scene.lua
"$bin" run scene.lua --out sc --quiet >/dev/null 2>&1
ok $? "a run with checkpoints (no sandbox)"
cp scene.lua scene.orig
printf 'io.open("%s/marker", "w"):close()\n' "$tmp" | cat - scene.orig >scene.lua
"$bin" run --restart sc/checkpoint_000001.h5 --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && [ ! -e marker ] && has out.txt "scene.lua is not the scene sc/checkpoint_000001.h5 was written from (its text differs)"
ok $? "a changed scene is refused before any of it runs" "status $rc, marker $([ -e marker ] && echo made || echo absent)"
rm -f marker
printf '%s\nreturn sim\n' "$base" >other.lua
printf 'io.open("%s/marker", "w"):close()\n' "$tmp" >evil.lua
"$bin" run --restart sc/checkpoint_000001.h5 evil.lua --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && [ ! -e marker ] && has out.txt "its text differs"
ok $? "another file named on the command line is not run either" "status $rc"
finish
