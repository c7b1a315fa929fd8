#!/usr/bin/env bash
# tests/fuzz/run.sh FUZZER SECONDS - libFuzzer on the scenes (make fuzz).
# The corpus (build-fuzz/corpus) is kept from run to run and seeded with
# scenarios/*.lua and tests/fuzz/seeds/*.lua.  The whole output goes to
# build-fuzz/fuzz.log.  On a finding (a sanitizer report, a crash, a
# leak, a timeout) it prints the report and the reproducer's path and
# exits 1; on a clean run, libFuzzer's last lines (runs, coverage).
set -u
fuzzer=$1 seconds=$2
dir=$(dirname "$fuzzer")
log=$dir/fuzz.log
mkdir -p "$dir/corpus" "$dir/crashes"
cp scenarios/*.lua tests/fuzz/seeds/*.lua "$dir/corpus/"
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1}
# from the tree's root: the scenes' output directory (build-fuzz/out)
# is relative to it
"$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
  -max_len=8192 -print_final_stats=1 -artifact_prefix="$dir/crashes/" \
  "$dir/corpus" >"$log" 2>&1
rc=$?
if [ $rc -eq 0 ]; then
  grep -aE '^#[0-9]+[[:space:]]+DONE|^Done [0-9]+ runs|^stat::' "$log" | tail -12
  exit 0
fi
echo "fuzz: a finding (exit $rc); the full output is $log"
# from the first report to the end, where libFuzzer names the reproducer
first=$(grep -naE '^==[0-9]+==(ERROR|WARNING)|runtime error:|^==[0-9]+== ERROR: libFuzzer' "$log" | head -1 | cut -d: -f1)
if [ -n "$first" ]; then sed -n "$first,\$p" "$log"; else tail -60 "$log"; fi
art=$(grep -aoE "Test unit written to [^ ]+" "$log" | tail -1 | sed 's/Test unit written to //')
[ -n "$art" ] && echo "fuzz: reproducer $art (run: $fuzzer $art)"
exit 1
