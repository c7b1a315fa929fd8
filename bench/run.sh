#!/usr/bin/env bash
# bench/run.sh BIN [--quick] - speed figures of mvmpm on one core, and
# with 1 against 2 threads (bench/threads.lua), in 2-D and in 3-D
# (bench/block3.lua, rows marked (f)) (make bench).
#
# Each bench/*.lua script is a plain Lua script run with `BIN test FILE`
# (that command runs any Lua file with the mvmpm module loaded and writes
# no output files); the scripts print one line per figure:
#   rate       particle-steps per second (particles x steps / wall seconds),
#              in M p-st/s: millions of particle-steps per second
#   ratio      a ratio of two timings
#   memory     bytes per particle
#   reference  the same problem in other MPM codes, for scale
#   machine    memory bandwidth of this machine (bench/stream.c)
# Timings use a monotonic wall clock (mvmpm.clock()) around sim:step(n)
# after warm-up steps; every rate is the median of several repeats.
# Nothing here passes or fails: speed is never a test.  --quick (or
# BENCH_QUICK=1) takes fewer, shorter repeats.  Takes a few minutes.
set -u
bin=${1:-./mvmpm}
[ "${2:-}" = "--quick" ] && export BENCH_QUICK=1
cd "$(dirname "$0")/.." || exit 1
echo "mvmpm bench: $("$bin" --version), $(git rev-parse --short HEAD 2>/dev/null || echo '?')," \
     "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), one core (but (e)):" \
     "$(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ${CC:-cc} -O2 -o "$tmp/stream" bench/stream.c 2>/dev/null; then "$tmp/stream"; fi
for f in bench/block.lua bench/disks.lua bench/grains.lua bench/effects.lua bench/snapshot.lua bench/threads.lua bench/block3.lua; do
  # keep the figures; drop the test runner's headings and counts
  "$bin" test "$f" | grep -Ev '^(== |-- .*passed|[0-9]+ passed)'
done
