#!/usr/bin/env bash
# tests/fault/runs.sh BIN - what a run leaves behind and how it goes on:
# the provenance in every HDF5 file and the table's head, --t-end,
# extending a finished run (bit for bit the run made to the later end
# from the start), restarting from another directory, a directory that
# holds another run's outputs, the state written when a guard stops a
# run, the energy residual's warning, progress lines into a file.
source "$(dirname "$0")/lib.sh" runs "$1"
root=$PWD
cd "$tmp"
attr() { # attr FILE NAME: a root attribute's value, as h5dump prints it
  h5dump -a "/$2" "$1" 2>/dev/null | awk '/^ *DATA \{/ {on = 1; next}
    on && /^ *\}/ {exit} on {sub(/^ *(\(0\): )?"?/, ""); sub(/"$/, ""); print}'
}
same_data() { # every dataset of A equal in B (h5diff)
  local d r=0
  for d in $(h5ls "$1" | awk '{print $1}'); do
    h5diff "$1" "$2" "/$d" "/$d" >/dev/null 2>&1 || r=1
  done
  [ -n "$(h5ls "$1")" ] && [ "$r" -eq 0 ]
}

# --- provenance: a run made with friction = 0.1 says so, everywhere
"$bin" run "$root/scenarios/cylinder_bounce.lua" --set friction=0.1 --t-end 1 \
  --out prov --checkpoint-every 0.5 --quiet >out.txt 2>&1
ok $? "cylinder_bounce with --set friction=0.1 --t-end 1" "$(grep -v warning out.txt | head -1)"
snap=prov/particles_000001.h5 ck=prov/checkpoint_000001.h5
version=$("$bin" --version | head -1 | awk '{print $2}')
for f in "$snap" "$ck"; do
  attr "$f" params | grep -qx "friction = 0.1" && attr "$f" params | grep -qx "cells = 8"
  ok $? "$(basename "$f"): the parameters in force (friction = 0.1, defaults too)" \
     "$(attr "$f" params | tr '\n' ';')"
  attr "$f" command | grep -qF -- "--set friction=0.1 --t-end 1 --out prov"
  ok $? "$(basename "$f"): the command line" "$(attr "$f" command)"
  [ -n "$version" ] && [ "$(attr "$f" version)" = "$version" ]
  ok $? "$(basename "$f"): the engine's version, as --version says" "$version"
  attr "$f" build | grep -q -- "-O"
  ok $? "$(basename "$f"): the compiler and flags" "$(attr "$f" build | cut -c1-60)"
  # the scene leaves the scheme to the engine ("default" in params): the
  # file says what that was
  attr "$f" scheme | grep -qF 'shape = "bspline2", update = "musl", transfer = "flip", flip = 1, ppc = 2, cfl = 0.25'
  ok $? "$(basename "$f"): the scheme as run" "$(attr "$f" scheme)"
done
python3 "$root/tests/tools/h5sum.py" check prov/*.h5 >/dev/null 2>&1
ok $? "the checksum block of every file is still valid" "$(ls prov/*.h5 | wc -l) files"
has prov/diagnostics.csv "#   friction = 0.1" && has prov/diagnostics.csv "# version: $version" &&
  has prov/diagnostics.csv "# command: " && has prov/diagnostics.csv "# build: " &&
  has prov/diagnostics.csv '# scheme: shape = "bspline2"'
ok $? "diagnostics.csv starts with the same as # lines"
head=$(grep -v '^#' prov/diagnostics.csv | head -1)
ncol=$(awk -F, '{print NF}' <<<"$head")
rows=$(grep -v '^#' prov/diagnostics.csv | awk -F, -v n="$ncol" 'NR > 1 && NF == n' | wc -l)
[ "${head%%,*}" = step ] && [ "$rows" -ge 3 ] &&
  [ "$rows" -eq $(($(grep -vc '^#' prov/diagnostics.csv) - 1)) ]
ok $? "past the # lines: the header row and full rows" "${head:0:30}..., $rows rows"
python3 - prov/diagnostics.csv <<'PY' >/dev/null 2>&1
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
assert len(rows) >= 3 and float(rows[0]["t"]) == 0 and 0.8 < float(rows[-1]["t"]) <= 1
PY
ok $? "a CSV reader skipping # lines reads it (rows from t = 0 to near the --t-end 1)"

# --- --t-end: the end of the run; refused when not a time
t=$(attr prov/particles_000002.h5 time)
[ "$t" = "1" ] && [ ! -e prov/particles_000003.h5 ]
ok $? "--t-end 1 ends the run at t = 1 (the scene writes every 0.5)" "last snapshot at t = $t"
"$bin" run "$root/scenarios/cylinder_bounce.lua" --t-end -1 --out bad >out.txt 2>&1
[ $? -eq 2 ] && has out.txt "--t-end needs a time > 0"
ok $? "--t-end -1 is refused" "$(head -1 out.txt)"

# --- extending a finished run: bit for bit the run made to the later end
cat >ext.lua <<'LUA'
local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/16, t_end = 0.5,
  sides = {left = "wall", right = "wall", bottom = "wall", top = "wall"}, gravity = {0, -1}}
sim:body {shape = mvmpm.disk {center = {0.4, 0.6}, radius = 0.15},
          material = mvmpm.elastic {K = 10, G = 5, density = 1}, velocity = {0.3, 0}}
sim:output {every = 0.05}
return sim
LUA
"$bin" run ext.lua --t-end 1 --out ref --quiet >out.txt 2>&1
ok $? "reference: the scene run to t = 1 from the start"
"$bin" run ext.lua --out ext --checkpoint-every 0.25 --quiet >out.txt 2>&1
ok $? "the scene run to its own t_end = 0.5"
"$bin" run --restart ext --set t_end=1 >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "the scene declares no parameter 't_end'" || has out.txt "--t-end"
ok $? "--set t_end on a restart of a scene without that parameter: refused, pointing to --t-end" "$(head -1 out.txt)"
mkdir elsewhere
(cd elsewhere && "$bin" run --restart ../ext --t-end 1 --quiet >../out.txt 2>&1)
ok $? "continued to t = 1 with --restart DIR --t-end 1, from another working directory" "$(grep -v warning out.txt | head -1)"
n=$(ls ext/particles_*.h5 | wc -l)
same_data ref/particles_000020.h5 ext/particles_000020.h5 && [ "$n" -eq 21 ]
ok $? "the last snapshot (t = 1) is bit for bit the reference's" "$n snapshots"
cmp -s <(grep -v '^#' ref/diagnostics.csv) <(grep -v '^#' ext/diagnostics.csv)
ok $? "every row of diagnostics.csv is the reference's" "$(grep -vc '^#' ref/diagnostics.csv) lines"
cmp -s ref/particles.xmf ext/particles.xmf
ok $? "particles.xmf lists the same 21 snapshots"
"$bin" run --restart ext --t-end 0.7 --quiet >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "give a later time"
ok $? "--t-end before the checkpoint's time is refused" "$(head -1 out.txt)"

# --- a directory holding another run's outputs
"$bin" run ext.lua --t-end 0.2 --out ref --quiet >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "holds the outputs of another run" && has out.txt "--overwrite" &&
  [ -e ref/particles_000020.h5 ]
ok $? "refused without --overwrite, and nothing of it touched" "$(head -1 out.txt)"
echo mine >ref/notes.txt
mkdir ref/sub && echo x >ref/sub/particles_000099.h5
"$bin" run ext.lua --t-end 0.2 --out ref --overwrite --quiet >out.txt 2>&1
ok $? "with --overwrite the run goes"
n=$(ls ref/particles_*.h5 | wc -l)
[ "$n" -eq 5 ] && [ -e ref/notes.txt ] && [ -e ref/sub/particles_000099.h5 ] &&
  [ "$(grep -o 'particles_[0-9]*\.h5' ref/particles.xmf | sort -u | wc -l)" -eq 5 ]
ok $? "the older run's snapshots are gone, other files stay, the index lists this run's only" \
   "$n snapshots, notes.txt and sub/ kept"

# --- a guard stops the run: its state is written, the message says where
cat >crush.lua <<'LUA'
local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/16, t_end = 1, dt = 0.03}
sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
  material = mvmpm.elastic {K = 1, G = 0.5, density = 1},
  velocity = function(x, y) return -50 * (x - 0.5), 0 end}
return sim
LUA
"$bin" run crush.lua --out crush --quiet >out.txt 2>&1
rc=$?
[ $rc -eq 1 ] && has out.txt "det F <= 0" && has out.txt "the state it stopped in is crush/failed_000000.h5"
ok $? "det F <= 0: status 1, the message names the failed state's file" "$(grep -m1 'det F' out.txt | cut -c1-160)"
n=$(h5ls crush/failed_000000.h5 2>/dev/null | awk '$1 == "mass" {gsub(/[{}\/A-Za-z]/, "", $3); print $3}')
[ -n "$n" ] && [ "$n" -gt 0 ] && python3 "$root/tests/tools/h5sum.py" check crush/failed_000000.h5 >/dev/null 2>&1
ok $? "failed_000000.h5 is a sealed snapshot with the particles" "$n particles"

# --- the energy residual's warning: once, with the step and time
sed 's/sim:output {every = 0.05}/sim:output {every = 0.05, warn_residual = 1e-13}/' ext.lua >warn.lua
"$bin" run warn.lua --out warn --quiet >out.txt 2>&1
n=$(grep -c "energy budget's residual" out.txt)
[ "$n" -eq 1 ] && grep "energy budget's residual" out.txt | grep -q "at step [0-9]*, t = "
ok $? "warn_residual = 1e-13: warned once, with step and time" "$(grep -m1 residual out.txt | cut -c1-150)"
"$bin" run ext.lua --out nowarn --quiet >out.txt 2>&1
res=$(awk -F, '!/^#/ && NR > 1 {r = $12 < 0 ? -$12 : $12; if (r > m) m = r} END {print m + 0}' nowarn/diagnostics.csv)
! has out.txt "residual"
ok $? "the default (5 % of the energy scale): no warning on a run that keeps its budget" "largest |residual| $res"

# --- progress where stderr is a file
"$bin" run ext.lua --out prog >prog.out 2>prog.err
n=$(grep -c '^progress: step' prog.err)
[ "$n" -ge 10 ] && [ "$n" -le 12 ] && grep '^progress:' prog.err | tail -1 | grep -q '(100 %).*ETA'
ok $? "2>file: a plain progress line every 10 % of the run (step, time, rate, ETA)" "$n lines; last: $(tail -1 prog.err)"
! grep -q $'\r' prog.err
ok $? "  no carriage returns in the file"
"$bin" run ext.lua --out progq --quiet 2>progq.err >/dev/null
! grep -q progress progq.err
ok $? "--quiet: none"

# --- a body whose shape runs past the domain: seeded inside, and said
cat >part.lua <<'LUA'
local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 3}, y = {0, 3}}, cell = 0.125, t_end = 0.01}
sim:body {name = "slab", shape = mvmpm.rect {lo = {0, 0}, hi = {3, 0.5}},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
sim:body {name = "disc", shape = mvmpm.disk {center = {2.9, 1.5}, radius = 0.5},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
return sim
LUA
"$bin" run part.lua --out part --quiet >out.txt 2>&1
st=$?
[ "$st" -eq 0 ] && [ "$(grep -c 'runs past the domain' out.txt)" -eq 1 ] &&
  grep 'runs past the domain' out.txt | grep -q "part.lua:5: body 'disc'.*x 2.4 .. 3.4 against the domain's 0 .. 3"
ok $? "a disc past the right side: one warning naming file, line, body and extents (the slab drawn to the sides: none)" \
   "$(grep -m1 'past the domain' out.txt | cut -c1-160)"
# --- a scene without bodies: the message names the scene
printf 'local mvmpm = require "mvmpm"\nreturn mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, t_end = 0.1}\n' >empty.lua
"$bin" run empty.lua --out empty --quiet >out.txt 2>&1
st=$?
[ "$st" -eq 1 ] && grep -q "empty.lua: the simulation has no particles" out.txt
ok $? "a scene with no body: status 1, the scene named" "$(head -1 out.txt)"

# --- every scene in scenarios/ runs under --sandbox (a few steps)
for s in bond_pull:0.05 concentric_debond:0.05 cylinder_bounce:0.2 debond_front:0.05 \
         two_disks:0.02 shear_dry:1e-7 shear_binder:1e-7; do
  sc=${s%%:*}
  "$bin" run "$root/scenarios/$sc.lua" --sandbox --out "sb_$sc" --t-end "${s#*:}" --quiet >out.txt 2>&1
  ok $? "scenarios/$sc.lua under --sandbox, --t-end ${s#*:}" "$(grep -v warning out.txt | grep -m1 mvmpm:)"
done
"$bin" run "$root/scenarios/pbx9501.lua" --sandbox --out sb_pbx --quiet --set size=0.2e-3 \
  --set scale=0.3 --set cells=3 --set packing=0.6 --set t_end=1e-8 --set images=0 >out.txt 2>&1
ok $? "scenarios/pbx9501.lua (a small bed) under --sandbox" "$(grep -v warning out.txt | grep -m1 'mvmpm:')"
[ -e sb_pbx/pbx_summary.txt ] && [ -e sb_pbx/pbx_locking.csv ] && [ -e sb_pbx/pbx_history.csv ] &&
  [ -e sb_pbx/pbx_grains.csv ] && [ -z "$(ls sb_pbx/*.part 2>/dev/null)" ]
ok $? "  its tables are written through mvmpm.open inside the output directory" \
   "$(cd sb_pbx && ls *.csv *.txt | tr '\n' ' ')"
cat >esc.lua <<'LUA'
local mvmpm = require "mvmpm"
local f, err = pcall(mvmpm.open, "../outside.csv")
assert(not f and tostring(err):find("not allowed under %-%-sandbox"), tostring(err))
f, err = pcall(mvmpm.open, "/tmp/outside.csv")
assert(not f, "absolute path allowed")
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.25, t_end = 0.01}
sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.3},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
local t = assert(mvmpm.open("tables/mine.csv"))
t:write("a,b\n1,2\n")
assert(t:close())
return sim
LUA
mkdir -p box
"$bin" run esc.lua --sandbox --out box/o --quiet >out.txt 2>&1
ok $? "mvmpm.open refuses '..' and absolute paths under --sandbox" "$(head -1 out.txt)"
[ ! -e box/outside.csv ] && [ "$(cat box/o/tables/mine.csv)" = "$(printf 'a,b\n1,2')" ]
ok $? "  nothing was written outside; mvmpm.open(\"tables/mine.csv\") wrote inside" "$(cd box && find . -type f | tr '\n' ' ')"
finish
