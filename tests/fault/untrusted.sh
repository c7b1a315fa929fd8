#!/usr/bin/env bash
# tests/fault/untrusted.sh BIN - checkpoints and snapshots are read as
# untrusted input.  Their checksum (tests/tools/h5sum.py) is checked
# before HDF5 parses a byte: random byte flips and an h5py edit are
# refused by it, none crashes.  Files edited and then sealed again pass
# the checksum, and every number in them is judged: each refusal names
# the file, the dataset, the row and the allowed range; render refuses a
# huge body index at once.
source "$(dirname "$0")/lib.sh" untrusted "$1"
scene=$PWD/tests/fault/pieces.lua
sum=$PWD/tests/tools/h5sum.py
py=/usr/bin/python3
cd "$tmp"

"$bin" run "$scene" --out run --set t_end=0.1 --checkpoint-every 0.05 --quiet >out.txt 2>&1
ok $? "a run with checkpoints"
ck=run/checkpoint_000002.h5 snap=run/particles_000001.h5
$py "$sum" check run/*.h5 >out.txt 2>&1
ok $? "every file's block is what tests/tools/h5sum.py computes" "$(ls run/*.h5 | wc -l) files"
h5dump -H $ck >/dev/null 2>&1 && h5dump -H $snap >/dev/null 2>&1
ok $? "h5dump reads a checkpoint and a snapshot (the block is an HDF5 user block)"
$py -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r'); assert f.userblock_size == 512; f['position'][:]" $ck >/dev/null 2>&1
ok $? "h5py reads them"

# a copy of the checkpoint, refused: status 1 (never a signal) and the text
refused() { # refused NAME TEXT: run --restart NAME.h5 is refused with TEXT
  timeout 60 "$bin" run --restart "$1.h5" >"$1.txt" 2>&1
  local rc=$?
  [ "$rc" -eq 1 ] && has "$1.txt" "$1.h5" && has "$1.txt" "$2"
}

# random damage: 50 bytes flipped one at a time, fixed seed
$py - $ck <<'PY'
import random, sys
data = open(sys.argv[1], "rb").read()
rnd = random.Random(7)
for k in range(50):
    b = bytearray(data)
    at = rnd.randrange(len(b))
    b[at] ^= 1 << rnd.randrange(8)
    open("flip%02d.h5" % k, "wb").write(b)
PY
nref=0 bad=
for k in $(seq -w 0 49); do
  if refused flip$k "checksum mismatch (damaged or edited"; then nref=$((nref + 1)); else bad="$bad flip$k"; fi
done
[ "$nref" -eq 50 ]; ok $? "50 single bit flips at random offsets: each refused by the checksum" "$nref of 50${bad:+; not:$bad}"
cp $ck edited.h5
$py -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); f['mass'][0] = f['mass'][0] * 1.5" edited.h5
h5dump -H edited.h5 >/dev/null 2>&1 && refused edited "checksum mismatch (damaged or edited"
ok $? "an h5py edit (still valid HDF5) is refused by the checksum" "$(head -c 150 edited.txt)"
tail -c +513 $ck >old.h5
refused old "it has no checksum"
ok $? "a checkpoint without the block (older format) is refused by name" "$(head -c 150 old.txt)"
head -c 3000 $ck >cut.h5
refused cut "truncated"
ok $? "a truncated checkpoint is refused" "$(head -c 150 cut.txt)"

# edited and sealed again: the checksum passes, the numbers are judged.
# Every case at once, one Python: NAME<TAB>EDIT<TAB>EXPECTED TEXT...
# (state(KEY, V[, 'int']) sets a named number of /state)
cat >cases.txt <<'CASES'
same	f['mass'][0] = f['mass'][0] * 1.5
body99	f['body'][5] = 99	dataset 'body', row 5: 99 is not in [0, 3)
bodymax	f['body'][5] = 2**31 - 1	dataset 'body', row 5: 2147483647 is not in [0, 3)
bodyneg	f['body'][0] = -1	dataset 'body', row 0: -1 is not in [0, 3)
far	f['position'][7, 0] = 1e10	dataset 'position', component 0 (x), row 7: 10000000000 is not in [0, 2)
below	f['position'][7, 1] = -0.01	dataset 'position', component 1 (y), row 7: -0.01 is not in [0, 2)
nanpos	f['position'][3, 1] = np.nan	dataset 'position', component 1 (y), row 3: nan is not finite
mass0	f['mass'][4] = 0	dataset 'mass', row 4: 0 is not in (0, inf)
vol	f['volume0'][4] = -1	dataset 'volume0', row 4: -1 is not in (0, inf)
halfnan	f['halfsize'][2] = np.nan	dataset 'halfsize', row 2: nan is not finite
half	f['halfsize'][2] = 3	dataset 'halfsize', row 2: 3 is not in (0, 0.5] cells
dupid	f['id'][9] = f['id'][8]	dataset 'id', row 9	is not unique
id0	f['id'][9] = 0	dataset 'id', row 9: 0 is not in [1, 
detF	f['F'][6, 0] = -1	dataset 'F', row 6	is not > 0 (that is det F
infstress	f['stress'][1, 2] = np.inf	dataset 'stress', component 2 (xy), row 1: inf is not finite
plastic	f['plastic_strain'][0] = -0.5	dataset 'plastic_strain', row 0: -0.5 is not in [0, inf)
novel	del f['velocity']	it has no dataset 'velocity'
rows	m = f['mass'][:-1]; del f['mass']; f['mass'] = m	dataset 'mass' has 749 rows
time	state('t', -1)	its value 't' in /state is -1, allowed [0
late	state('t', 5)	its value 't' in /state is 5, allowed [0, 0.1
dtnan	state('dt', np.nan)	its value 'dt' in /state/real is nan, allowed: a finite number
flip	state('flip', 2)	its value 'flip' in /state is 2, allowed [0, 1]
grav	state('gravity.y', np.inf)	its value 'gravity.y' in /state/real is inf
wall	state('side.top.v.x', np.nan)	its value 'side.top.v.x' in /state/real is nan
drive	state('body3.vdrive.y', -np.inf)	its value 'body3.vdrive.y' in /state/real is -inf
step	state('step', -5, 'int')	its value 'step' in /state is -5
nmade	state('nmade', 2**40, 'int')	its value 'nmade' in /state is 1099511627776, allowed [
CASES
$py - "$sum" $ck cases.txt <<'PY'
import h5py, numpy as np, runpy, shutil, sys
seal = runpy.run_path(sys.argv[1])["block"]
for line in open(sys.argv[3]):
    name, code = line.rstrip("\n").split("\t")[:2]
    shutil.copy(sys.argv[2], name + ".h5")
    f = h5py.File(name + ".h5", "r+")
    def state(key, v, kind="real"):
        names = bytes(f["state/" + kind + "_names"][:]).decode().split("\n")
        f["state/" + kind][names.index(key)] = v
    exec(code)
    f.close()
    data = open(name + ".h5", "rb").read()
    open(name + ".h5", "r+b").write(seal(data[512:]))
PY
ok $? "the edited checkpoints, sealed again" "$(wc -l <cases.txt) of them"
# accepted: a consistent edit (a checksum is no signature)
cp -r run good && cp same.h5 good/checkpoint_000002.h5
timeout 60 "$bin" run --restart good/checkpoint_000002.h5 --quiet >same.txt 2>&1
ok $? "a consistent edit, sealed again, continues (a checksum is no signature)" "$(head -c 120 same.txt)"
while IFS=$'\t' read -r cs code texts; do
  [ "$cs" = same ] && continue
  timeout 60 "$bin" run --restart "$cs.h5" >"$cs.txt" 2>&1
  rc=$? r=0
  [ "$rc" -eq 1 ] && has "$cs.txt" "$cs.h5: " || r=1
  while [ -n "$texts" ]; do
    t=${texts%%$'\t'*}
    has "$cs.txt" "$t" || r=1
    [ "$t" = "$texts" ] && texts= || texts=${texts#*$'\t'}
  done
  ok $r "$code: refused (status $rc)" "$(head -c 200 "$cs.txt")"
done <cases.txt

# render: what it reads is judged too, and a refusal comes at once
rsnap() { # rsnap NAME PYTHON: a sealed copy of the snapshot, edited
  cp $snap "$1.h5"
  $py -c "import h5py, numpy as np, sys
f = h5py.File(sys.argv[1], 'r+')
$2
f.close()" "$1.h5" && $py "$sum" seal "$1.h5"
}
rsnap rbig "f['body'][0] = 2**31 - 1"
s0=$(date +%s%N)
timeout 60 "$bin" render rbig.h5 --out rbig.png >rbig.txt 2>&1
rc=$? ms=$(( ($(date +%s%N) - s0) / 1000000 ))
[ "$rc" -eq 1 ] && has rbig.txt "rbig.h5: dataset 'body', row 0: 2147483647 is not in [0, 1048576)" &&
  [ ! -e rbig.png ]
ok $? "render: a body index of 2^31-1 is refused before drawing (time printed, not asserted)" "status $rc, $ms ms: $(head -c 120 rbig.txt)"
rsnap rnan "f['position'][2, 0] = np.nan"
timeout 60 "$bin" render rnan.h5 --out rnan.png >rnan.txt 2>&1
[ $? -eq 1 ] && has rnan.txt "dataset 'position', component 0 (x), row 2: nan is not finite"
ok $? "render: a position that is not finite is refused" "$(head -c 120 rnan.txt)"
cp $snap redit.h5
$py -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); f['body'][0] = 2**31 - 1" redit.h5
timeout 60 "$bin" render redit.h5 --out redit.png >redit.txt 2>&1
[ $? -eq 1 ] && has redit.txt "redit.h5: " && has redit.txt "checksum mismatch (damaged or edited"
ok $? "render: an edited snapshot is refused by the checksum" "$(head -c 120 redit.txt)"
tail -c +513 rbig.h5 >rold.h5
timeout 60 "$bin" render rold.h5 --out rold.png >rold.txt 2>&1
[ $? -eq 1 ] && has rold.txt "dataset 'body', row 0: 2147483647 is not in"
ok $? "render: a snapshot without the block (older) is read, and judged" "$(head -c 120 rold.txt)"
tail -c +513 $snap >plain.h5
timeout 60 "$bin" render plain.h5 --out plain.png >plain.txt 2>&1
ok $? "render: an intact snapshot without the block is drawn"
finish
