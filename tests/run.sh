#!/usr/bin/env bash
# tests/run.sh BIN UNITDIR - every C unit test, then the Lua verification
# cases; the last line adds them all up: "N passed, M failed".
set -u
bin=$1 unitdir=$2
pass=0 fail=0
count() { # add the "N passed, M failed" line of a log
  local line
  line=$(grep -E '[0-9]+ passed, [0-9]+ failed' "$1" | tail -1)
  if [ -z "$line" ]; then fail=$((fail + 1)); return; fi
  pass=$((pass + $(grep -oE '[0-9]+ passed' <<<"$line" | grep -oE '[0-9]+')))
  fail=$((fail + $(grep -oE '[0-9]+ failed' <<<"$line" | grep -oE '[0-9]+')))
}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for t in "$unitdir"/test_*; do
  [ -x "$t" ] || continue
  "$t" >"$log" 2>&1
  rc=$?
  grep -E '^(FAIL|ok )' "$log" | grep FAIL
  tail -1 "$log"
  count "$log"
  [ $rc -eq 0 ] || grep -q 'failed' "$log" || fail=$((fail + 1))
done
# the REPL, typed at in tmux as a person would
bash tests/repl/check.sh "./$bin" >"$log" 2>&1
grep -E '^FAIL' "$log"
tail -1 "$log"
count "$log"
# runs that fail: checkpoints and restarts, kills, full disks, Ctrl-C,
# untrusted scenes
for t in tests/fault/*.sh; do
  [ "$(basename "$t")" = lib.sh ] && continue
  bash "$t" "$bin" >"$log" 2>&1
  grep -E '^(FAIL|skip)' "$log"
  tail -1 "$log"
  count "$log"
done
"./$bin" test tests/verify/*.lua tests/hard/*.lua tests/random/gen.lua 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
count "$log"
# a sanitizer report exits non-zero even when every check passed
if [ "$rc" -ne 0 ] && ! grep -qE ' [1-9][0-9]* failed$' "$log"; then fail=$((fail + 1)); fi
echo
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
