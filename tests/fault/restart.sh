#!/usr/bin/env bash
# tests/fault/restart.sh BIN - a run continued from a checkpoint is the
# uninterrupted run, bit for bit: every particle field at t_end (hex
# floats, written by the scene), the sim:state series, the diagnostics
# table, the XDMF index and the snapshots written after the checkpoint.
# Also: what a restart refuses (other --set values, a changed scene, a
# snapshot given as a checkpoint, a damaged file).
source "$(dirname "$0")/lib.sh" restart "$1"
scene=$PWD/tests/fault/pieces.lua
pull=$PWD/scenarios/bond_pull.lua
cd "$tmp"

"$bin" run "$scene" --out full --set dump=true --checkpoint-every 0.15 --quiet
ok $? "uninterrupted run with checkpoints"
n=$(ls full/checkpoint_*.h5 | wc -l)
[ "$n" -eq 2 ]; ok $? "the newest two checkpoints are kept" "$n files: $(cd full; echo checkpoint_*.h5)"

# the second piece: the run's directory as it stood at checkpoint 3
# (t ~ 0.45), with what came later taken away
cp -r full piece
rm piece/fields.txt piece/particles_000005.h5 piece/particles_000006.h5 piece/checkpoint_000004.h5
cp piece/diagnostics.csv piece/diagnostics.csv.part && rm piece/diagnostics.csv
"$bin" run --restart piece/checkpoint_000003.h5 --quiet
ok $? "restart from checkpoint 3"
cmp -s full/fields.txt piece/fields.txt
ok $? "every particle field at t_end and the sim:state sums are bit for bit the same" \
   "$(grep -c . full/fields.txt) lines compared"
cmp -s full/diagnostics.csv piece/diagnostics.csv
ok $? "diagnostics.csv is the same, rows cut and appended" "$(wc -l <full/diagnostics.csv) rows"
cmp -s full/particles.xmf piece/particles.xmf
ok $? "particles.xmf is the same"
# every dataset (the root's provenance attributes differ: the command
# line, and restarted_from in the continued run)
same_data() { # same_data A.h5 B.h5
  local d r=0
  for d in $(h5ls "$1" | awk '{print $1}'); do
    h5diff "$1" "$2" "/$d" "/$d" >/dev/null 2>&1 || r=1
  done
  [ -n "$(h5ls "$1")" ] && [ "$r" -eq 0 ]
}
for k in 5 6; do
  same_data full/particles_00000$k.h5 piece/particles_00000$k.h5
  ok $? "snapshot $k written after the restart has the same data (h5diff)"
done
h5dump -a /restarted_from piece/particles_000005.h5 | grep -q "piece/checkpoint_000003.h5"
ok $? "a snapshot of the continued run names the checkpoint it came from"
[ ! -e piece/diagnostics.csv.part ]; ok $? "the finished table is renamed into place"

# a finished run continued again from its directory's newest checkpoint
"$bin" run --restart piece --quiet >/dev/null 2>&1
ok $? "--restart DIR takes the newest checkpoint"

# refusals
"$bin" run --restart full/checkpoint_000003.h5 --set cell=0.05 >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "the run was made with other parameters"
ok $? "other --set values are refused" "$(head -1 out.txt)"
"$bin" run --restart full/checkpoint_000003.h5 --set dump=true --quiet >out.txt 2>&1
ok $? "the same --set values are accepted"
sed 's/radius = 0.3}, material = rubber/radius = 0.29}, material = rubber/' "$scene" >changed.lua
"$bin" run --restart full/checkpoint_000003.h5 changed.lua >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "a changed scene cannot continue the run"
ok $? "a changed scene is refused" "$(head -1 out.txt)"
"$bin" run --restart full/particles_000002.h5 >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "not an mvmpm checkpoint"
ok $? "a snapshot is not a checkpoint" "$(head -1 out.txt)"
head -c 3000 full/checkpoint_000003.h5 >full/checkpoint_000009.h5
"$bin" run --restart full/checkpoint_000009.h5 >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "checkpoint_000009.h5: cannot open file"
ok $? "a truncated checkpoint names the file and the reason" "$(head -1 out.txt)"
echo "not hdf5" >junk.h5
"$bin" run --restart junk.h5 >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "junk.h5: cannot open file"
ok $? "a file that is not HDF5 is refused" "$(head -1 out.txt)"
"$bin" run --restart full/checkpoint_000003.h5 --out elsewhere >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "--out cannot be given with --restart"
ok $? "--out with --restart is refused"
mkdir empty
"$bin" run --restart empty >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "no checkpoint_NNNNNN.h5"
ok $? "a directory without checkpoints is refused"
# a state that cannot be saved is named when the checkpoint is due
cat >badstate.lua <<'LUA'
local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/8, t_end = 0.05}
sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}}
sim:state {a = {1, 2, {fn = print}}}
return sim
LUA
"$bin" run badstate.lua --out bs --checkpoint-every 0.01 --quiet >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "state.a[3].fn is a function"
ok $? "a function in sim:state is refused by its place" "$(head -1 out.txt)"

# piece FULL PIECE CK T: PIECE as FULL's directory stood at checkpoint CK,
# taken at time T: the checkpoint, the index and the table's rows up to T
piece() {
  mkdir "$2" && cp "$1/checkpoint_$3.h5" "$1/particles.xmf" "$2/" &&
    head -n "$(awk -F, -v t="$4" '$2 != "" && $1 ~ /^[0-9]+$/ && $2 + 0 <= t + 1e-7 {n = NR} END {print n}' \
      "$1/diagnostics.csv")" "$1/diagnostics.csv" >"$2/diagnostics.csv.part"
}
# continued FULL PIECE CK WHEN WHAT: PIECE continued from its checkpoint
# CK ends with FULL's diagnostics, byte for byte
continued() {
  "$bin" run --restart "$2/checkpoint_$3.h5" --quiet >/dev/null 2>&1
  ok $? "restart $4"
  cmp -s "$1/diagnostics.csv" "$2/diagnostics.csv"
  ok $? "the diagnostics ($5 among them) are the same" "$(tail -1 "$1/diagnostics.csv" | cut -c1-40)"
}

# the cohesive law's memory (the particles' cut strength and largest
# opening) is in the checkpoint: continued from t = 24, halfway through
# the interface's softening (t = 19 .. 29), the run is the uninterrupted one
set_coh="--set strength=0.005 --set energy=2.5e-5 --set V0=0.0002 --set t_end=30"
"$bin" run "$pull" --out cfull $set_coh --checkpoint-every 8 --quiet >/dev/null 2>&1
ok $? "cohesive pull with checkpoints"
piece cfull cpiece 000003 24
continued cfull cpiece 000003 "mid-softening" "the work of separation"

# spring walls keep each column's compression between steps: continued
# from t = 5.6, in the middle of the first impact (t = 5.0 .. 6.9), the
# run is the uninterrupted one
bounce=${pull%/*}/cylinder_bounce.lua
"$bin" run "$bounce" --set wall_contact=spring --set t_end=7 --out sfull --checkpoint-every 2.8 --quiet
ok $? "bounce on spring walls with checkpoints"
strings sfull/checkpoint_000002.h5 | grep -q "side.right.dl."
ok $? "the checkpoint in the impact holds the springs' compression"
cp -r sfull spiece
continued sfull spiece 000002 "in the impact" "the springs' energy"

# a body sliding down a periodic incline keeps the wraps' part of its
# potential (sim_energy.wrap) in the checkpoint: continued from t = 2,
# after it went through the seam, the run is the uninterrupted one
cat >chute.lua <<'LUA'
local mvmpm = require "mvmpm"
local th = math.rad(30)
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 0.6}}, cell = 0.05, t_end = 3,
  gravity = {math.sin(th), -math.cos(th)},
  sides = {left = "periodic", right = "periodic", bottom = "wall", top = "wall"}}
sim:body {shape = mvmpm.disk {center = {0.5, 0.2}, radius = 0.2},
          material = mvmpm.elastic {K = 100, G = 50, density = 1}}
sim:output {every = 1, csv_every = 10}
return sim
LUA
"$bin" run chute.lua --out pfull --checkpoint-every 1 --quiet
ok $? "disc on a periodic incline with checkpoints"
piece pfull ppiece 000002 2
continued pfull ppiece 000002 "after the seam" "the potential and the residual"
# a table with other columns (another version's: here its last column
# taken out of the header) is refused, and nothing is touched
mkdir pother && cp pfull/checkpoint_000002.h5 pother/ &&
  sed '/^step,/s/,[a-z_]*$//' pfull/diagnostics.csv >pother/diagnostics.csv &&
  cp pother/diagnostics.csv before.csv
"$bin" run --restart pother/checkpoint_000002.h5 --quiet >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "the diagnostics table has other columns" &&
  cmp -s before.csv pother/diagnostics.csv && [ ! -e pother/diagnostics.csv.part ]
ok $? "a table with other columns is refused, left as it was" "$(head -1 out.txt | cut -c1-120)"
finish
