#!/usr/bin/env bash
# tests/fault/kill.sh BIN - SIGKILL while checkpoints are being written.
# A scene of ~12000 particles checkpoints after every step (most of the
# wall time goes to writing them); it is killed at a random moment, the
# checkpoints under their final names must all open, the run continues
# from the newest, and this is done four times.  The run that finally
# finishes must equal, bit for bit, one that was never interrupted.
source "$(dirname "$0")/lib.sh" kill "$1"
scene=$PWD/tests/fault/pieces.lua
set_=(--set cell=0.015625 --set t_end=0.04 --set dump=true)
cd "$tmp"
"$bin" run "$scene" "${set_[@]}" --out ref --quiet
ok $? "reference run"
midwrite=0
for round in 1 2 3 4; do
  if [ "$round" -eq 1 ]; then
    "$bin" run "$scene" "${set_[@]}" --out run --checkpoint-every 1e-9 --quiet >/dev/null 2>&1 &
  else
    "$bin" run --restart run --quiet >/dev/null 2>&1 &
  fi
  pid=$!
  # wait for a checkpoint newer than the round started with (so every
  # round makes progress, however slow the build), then a random moment
  before=$(ls run/checkpoint_*.h5 2>/dev/null | tail -1)
  for _ in $(seq 600); do
    now=$(ls run/checkpoint_*.h5 2>/dev/null | tail -1)
    [ -n "$now" ] && [ "$now" != "$before" ] && break
    sleep 0.05
  done
  sleep "$(awk -v s="$RANDOM" 'BEGIN { printf "%.2f", (s % 50) / 100 }')"
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  tmps=$(ls run/*.tmp 2>/dev/null | wc -l)
  [ "$tmps" -gt 0 ] && midwrite=$((midwrite + 1))
  rm -f run/*.tmp # so the next round counts only its own
  bad=0 n=0
  for f in run/checkpoint_*.h5; do
    [ -e "$f" ] || continue
    n=$((n + 1))
    h5ls "$f/state" >/dev/null 2>&1 || bad=$((bad + 1))
  done
  [ "$n" -ge 1 ] && [ "$bad" -eq 0 ]
  ok $? "kill $round: every checkpoint under its final name opens" \
     "$n checkpoint(s), $tmps temp file(s) left by the killed write"
done
"$bin" run --restart run --quiet >/dev/null 2>&1
ok $? "the run continues from its newest checkpoint to the end"
cmp -s ref/fields.txt run/fields.txt
ok $? "the run killed four times ends bit for bit like the uninterrupted one" \
   "$midwrite of 4 kills landed while a checkpoint was being written"
# the rows; the "#" head differs in the command line (--out)
cmp -s <(grep -v "^#" ref/diagnostics.csv) <(grep -v "^#" run/diagnostics.csv)
ok $? "and so does its diagnostics table"
finish
