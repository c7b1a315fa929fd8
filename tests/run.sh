#!/usr/bin/env bash
# tests/run.sh BIN UNITDIR - every C unit test, the REPL session, the
# fault tests and each Lua verification file, as separate jobs run
# $JOBS at a time (default: the cores this machine has; every job is
# single-threaded unless it asks for threads itself).  Each job's output
# is printed whole, in the order of the list, as soon as it and all
# before it have finished, so a log reads the same at any JOBS.  The
# last line adds them all up: "N passed, M failed".  Each job's wall
# time follows its output, and the slowest are listed before the count,
# so a log shows where the suite's time goes.
#
# LIGHT=1 (make test SAN=1) leaves out the files named in tests/heavy:
# the convergence ladders whose finest rungs take an hour and more under
# the sanitizers.  Their code runs there all the same, at coarse rungs,
# in tests/verify/paths.lua; make test SAN=1 SAN_FULL=1 runs them too.
set -u
bin=$1 unitdir=$2
jobs=${JOBS:-$(nproc 2>/dev/null || echo 1)}
case $jobs in '' | *[!0-9]* | 0) echo "tests/run.sh: JOBS must be a count >= 1 (got '$jobs')" >&2; exit 2 ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# the jobs: KIND PATH.  The Lua files go first, since they are most of
# the time and a free core then picks up the short ones at the end
items=()
heavy=" $(sed -e 's/#.*//' tests/heavy | tr -s ' \n' '  ') "
skipped=()
for t in tests/verify/*.lua tests/hard/*.lua tests/random/gen.lua; do
  if [ "${LIGHT:-0}" = 1 ] && [[ $heavy == *" $t "* ]]; then skipped+=("$t"); continue; fi
  items+=("lua $t")
done
for t in "$unitdir"/test_*; do [ -x "$t" ] && items+=("unit $t"); done
items+=("repl tests/repl/check.sh")
for t in tests/fault/*.sh; do [ "$(basename "$t")" = lib.sh ] || items+=("fault $t"); done
n=${#items[@]}

job() { # job INDEX KIND PATH: its output in INDEX.log, its status in INDEX.rc
  local i=$1 kind=$2 path=$3 rc t0
  t0=$(date +%s.%N)
  case $kind in
    lua) "./$bin" test "$path" ;;
    unit) "$path" ;;
    repl) bash "$path" "./$bin" ;;
    fault) bash "$path" "$bin" ;;
  esac >"$work/$i.log" 2>&1
  rc=$?
  echo "$t0 $(date +%s.%N)" | awk '{ printf "%.1f\n", $2 - $1 }' >"$work/$i.t"
  echo "$rc" >"$work/$i.rc.tmp" && mv "$work/$i.rc.tmp" "$work/$i.rc"
}
export -f job
export bin work
for i in "${!items[@]}"; do echo "$i ${items[$i]}"; done |
  xargs -P "$jobs" -L 1 bash -c 'job "$@"' _ &
runner=$!

pass=0 fail=0
for i in "${!items[@]}"; do
  while [ ! -e "$work/$i.rc" ]; do
    if ! kill -0 "$runner" 2>/dev/null && [ ! -e "$work/$i.rc" ]; then
      echo "FAIL ${items[$i]}: never ran"; fail=$((fail + 1)); continue 2
    fi
    sleep 0.2
  done
  read -r kind path <<<"${items[$i]}"
  log=$work/$i.log rc=$(cat "$work/$i.rc") secs=$(cat "$work/$i.t")
  echo "$secs $path" >>"$work/times"
  # the Lua files print every check; the others their failures and count
  if [ "$kind" = lua ]; then cat "$log"
  else grep -E '^(FAIL|skip)' "$log"; tail -1 "$log"; fi
  line=$(grep -E '[0-9]+ passed, [0-9]+ failed' "$log" | tail -1)
  if [ -z "$line" ]; then
    echo "FAIL $path: no count line (status $rc)"; tail -20 "$log"; fail=$((fail + 1)); continue
  fi
  p=$(grep -oE '[0-9]+ passed' <<<"$line" | grep -oE '[0-9]+')
  f=$(grep -oE '[0-9]+ failed' <<<"$line" | grep -oE '[0-9]+')
  pass=$((pass + p)) fail=$((fail + f))
  # a sanitizer report exits non-zero even when every check passed
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "FAIL $path: exited with status $rc"; fail=$((fail + 1))
  fi
  echo "time $path: $secs s"
done
wait "$runner"
echo
echo "$n jobs, $jobs at a time; the slowest (wall seconds):"
sort -rn "$work/times" 2>/dev/null | head -8 | sed 's/^/  /'
for t in ${skipped[@]+"${skipped[@]}"}; do echo "skip $t (tests/heavy; SAN_FULL=1 runs it)"; done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
