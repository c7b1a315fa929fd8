#!/usr/bin/env bash
# bench/compare.sh OLD NEW [ROUNDS] - the 2-D speed of two builds of
# mvmpm, side by side: for each case of bench/compare_case.lua, OLD and
# NEW are run in turns (A B A B ..., the order swapped each round, one
# process at a time, one thread), ROUNDS rounds (default 5).  A
# neighbour's load then falls on both.  Per case it prints each build's
# median seconds per step, on the process's CPU clock and on the wall
# clock, and the median over the rounds of the per-round ratio
# t(OLD) / t(NEW): NEW's speed as a fraction of OLD's (above 1: NEW is
# faster).  CMP_CASES="a b" picks cases; CMP_STEPS the steps per run.
# Nothing passes or fails; speed is never a test.
set -u
old=${1:?usage: bench/compare.sh OLD NEW [ROUNDS]}
new=${2:?usage: bench/compare.sh OLD NEW [ROUNDS]}
rounds=${3:-5}
old=$(realpath "$old") new=$(realpath "$new")
cd "$(dirname "$0")/.." || exit 1
cases=${CMP_CASES:-block-linear-musl block-linear-usl block-gimp-musl block-bspline2-musl block-gimp-usavg grains-250}
echo "compare: OLD $old ($("$old" --version))"
echo "         NEW $new ($("$new" --version))"
echo "         $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores," \
     "load average $(cut -d' ' -f1-3 /proc/loadavg), $rounds rounds"
tmp=$(mktemp)
trap 'rm -f "$tmp" "$tmp.err"' EXIT
one() { # BIN TAG ROUND CASE
  local out
  out=$(CMP_CASE=$4 MVMPM_THREADS=1 "$1" test bench/compare_case.lua 2>"$tmp.err" | grep '^cmp ') ||
    { echo "compare: $1 failed on $4" >&2; cat "$tmp.err" >&2; exit 1; }
  echo "$2 $3 $out" >>"$tmp"
}
for c in $cases; do
  for r in $(seq 1 "$rounds"); do
    if [ $((r % 2)) = 1 ]; then one "$old" old "$r" "$c"; one "$new" new "$r" "$c"
    else one "$new" new "$r" "$c"; one "$old" old "$r" "$c"; fi
  done
done
# rows: TAG ROUND cmp CASE N STEPS WALL CPU
printf '%-22s %9s %11s %11s %8s %11s %11s %8s\n' case particles "old ms CPU" "new ms CPU" "ratio" \
  "old ms wall" "new ms wall" "ratio"
awk -v cases="$cases" '
function median(a, n,   i, j, t) {
  for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
  return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
{ wall[$4, $1, $2] = $7 / $6; cpu[$4, $1, $2] = $8 / $6; np[$4] = $5; if ($2 > R) R = $2 }
END {
  nc = split(cases, cs, " ")
  for (k = 1; k <= nc; k++) {
    c = cs[k]
    for (r = 1; r <= R; r++) {
      oc[r] = cpu[c, "old", r]; nw[r] = cpu[c, "new", r]; rc[r] = oc[r] / nw[r]
      ow[r] = wall[c, "old", r]; nww[r] = wall[c, "new", r]; rw[r] = ow[r] / nww[r]
    }
    printf "%-22s %9d %11.2f %11.2f %8.3f %11.2f %11.2f %8.3f\n", c, np[c],
      1e3 * median(oc, R), 1e3 * median(nw, R), median(rc, R),
      1e3 * median(ow, R), 1e3 * median(nww, R), median(rw, R)
  }
}' "$tmp"
echo "ratio: median over the rounds of t(OLD)/t(NEW); >= 0.95 is the goal"
