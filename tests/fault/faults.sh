#!/usr/bin/env bash
# tests/fault/faults.sh BIN - output that cannot be written: a full disk,
# a file size limit, an output directory that cannot be made or written,
# damaged HDF5.  Each must give a message naming the file and the reason,
# exit with status 1, and leave no partial file under a final name.
# Without root, a full disk is made by pointing the temp name at
# /dev/full (every write fails with ENOSPC); a real small tmpfs is used
# too where it can be mounted (root with CAP_SYS_ADMIN).
source "$(dirname "$0")/lib.sh" faults "$1"
scene=$PWD/tests/fault/pieces.lua
cd "$tmp"

# every HDF5 file under a final name opens and is whole
whole() {
  local f
  for f in "$1"/particles_*.h5 "$1"/checkpoint_*.h5; do
    [ -e "$f" ] || continue
    h5ls "$f" >/dev/null 2>&1 || return 1
  done
}

# a snapshot write fails with ENOSPC
mkdir full1
ln -s /dev/full full1/particles_000003.h5.tmp
"$bin" run "$scene" --out full1 --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "full1/particles_000003.h5: cannot write file (No space left on device)"
ok $? "disk full on a snapshot: message and status 1" "$(grep -m1 'full1/' out.txt)"
[ ! -e full1/particles_000003.h5 ] && [ ! -L full1/particles_000003.h5.tmp ] && whole full1
ok $? "no snapshot under its final name is partial; the temp is gone"

# a checkpoint write fails with ENOSPC; the one before still continues
mkdir full2
ln -s /dev/full full2/checkpoint_000002.h5.tmp
"$bin" run "$scene" --out full2 --checkpoint-every 0.15 --set dump=true --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "full2/checkpoint_000002.h5: cannot write file (No space left on device)"
ok $? "disk full on a checkpoint: message and status 1" "$(grep -m1 'checkpoint_000002' out.txt)"
has out.txt "continue with: mvmpm run --restart full2/checkpoint_000001.h5"
ok $? "the message names the newest good checkpoint"
[ ! -e full2/checkpoint_000002.h5 ] && whole full2
ok $? "no checkpoint under its final name is partial"
"$bin" run --restart full2/checkpoint_000001.h5 --quiet >/dev/null 2>&1 &&
  "$bin" run "$scene" --out full2ref --set dump=true --quiet >/dev/null 2>&1 &&
  cmp -s full2/fields.txt full2ref/fields.txt
ok $? "with space again the run continues from it, bit for bit"

# the diagnostics table cannot be written
mkdir full3
ln -s /dev/full full3/diagnostics.csv.part
"$bin" run "$scene" --out full3 --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "diagnostics.csv.part: write failed (No space left on device)"
ok $? "disk full on the table: message and status 1" "$(grep -m1 'diagnostics' out.txt)"
[ ! -e full3/diagnostics.csv ]
ok $? "a table that failed is not renamed to its final name"

# RLIMIT_FSIZE: a snapshot larger than 64 KiB fails with EFBIG
( trap '' XFSZ; ulimit -f 64; exec "$bin" run "$scene" --out fsize --quiet ) >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "cannot write file (File too large)"
ok $? "ulimit -f: message and status 1" "$(grep -m1 'fsize/' out.txt)"
whole fsize && [ -z "$(ls fsize/*.tmp 2>/dev/null)" ]
ok $? "no partial snapshot and no temp file left" "$(ls fsize | tr '\n' ' ')"

# the output directory cannot be made: a path through a regular file
touch plain
"$bin" run "$scene" --out plain/out --quiet >out.txt 2>&1
rc=$?
[ "$rc" -eq 1 ] && has out.txt "plain/out: cannot create directory (Not a directory)"
ok $? "output directory through a file: message and status 1" "$(head -1 out.txt)"

# the output directory cannot be written (permissions bind only non-root)
if [ "$(id -u)" -ne 0 ]; then
  mkdir ro && chmod 555 ro
  "$bin" run "$scene" --out ro --quiet >out.txt 2>&1
  rc=$?
  [ "$rc" -eq 1 ] && has out.txt "Permission denied" && [ -z "$(ls ro)" ]
  ok $? "read-only output directory: message, status 1, nothing left" "$(head -1 out.txt)"
else
  echo "skip read-only output directory: running as root, which permissions do not stop"
fi

# a real full disk: a 400 KiB tmpfs
if mkdir mnt && mount -t tmpfs -o size=400k tmpfs mnt 2>/dev/null; then
  "$bin" run "$scene" --out mnt/run --checkpoint-every 0.1 --quiet >out.txt 2>&1
  rc=$?
  [ "$rc" -eq 1 ] && has out.txt "(No space left on device)"
  ok $? "tmpfs full: message and status 1" "$(grep -m1 'No space' out.txt)"
  # a table under its final name ends in a whole row
  whole mnt/run && { [ ! -e mnt/run/diagnostics.csv ] || [ -z "$(tail -c1 mnt/run/diagnostics.csv)" ]; }
  ok $? "tmpfs full: every file under a final name is whole" "$(ls mnt/run | tr '\n' ' ')"
  umount mnt
else
  echo "skip tmpfs disk full: cannot mount a tmpfs here (needs root with CAP_SYS_ADMIN)"
fi

# a damaged snapshot given to render
head -c 2000 fsize/particles_000000.h5 >broken.h5
"$bin" render broken.h5 >out.txt 2>&1
rc=$?
[ "$rc" -ne 0 ] && has out.txt "broken.h5: cannot open file"
ok $? "a damaged snapshot: message names the file and reason" "$(head -1 out.txt)"
finish
