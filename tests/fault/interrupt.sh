#!/usr/bin/env bash
# tests/fault/interrupt.sh BIN - a real SIGINT (what Ctrl-C sends) to a
# running `mvmpm run`: it stops at a step boundary with status 130, says
# how to continue, leaves a checkpoint and the table still .part, and the
# continued run ends bit for bit like one never interrupted.
source "$(dirname "$0")/lib.sh" interrupt "$1"
scene=$PWD/tests/fault/pieces.lua
set_=(--set t_end=5 --set dump=true)
cd "$tmp"
"$bin" run "$scene" "${set_[@]}" --out ref --quiet
ok $? "reference run"
"$bin" run "$scene" "${set_[@]}" --out run --quiet >out.txt 2>&1 &
pid=$!
# once it is stepping (its second snapshot is out), however slow the build
for _ in $(seq 600); do [ -e run/particles_000001.h5 ] && break; sleep 0.05; done
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 130 ]; ok $? "SIGINT: exit status 130" "status $rc"
has out.txt "continue with: mvmpm run --restart run/checkpoint_000001.h5"
ok $? "the message says how to continue" "$(grep -m1 interrupted out.txt)"
[ -e run/checkpoint_000001.h5 ] && [ ! -e run/checkpoint_000001.h5.tmp ]
ok $? "a checkpoint was written"
[ -e run/diagnostics.csv.part ] && [ ! -e run/diagnostics.csv ]
ok $? "the unfinished table stays diagnostics.csv.part"
"$bin" run --restart run/checkpoint_000001.h5 --quiet
ok $? "the run continues from it"
cmp -s ref/fields.txt run/fields.txt
ok $? "particle fields and state at t_end match the uninterrupted run bit for bit"
# the rows; the "#" head differs in the command line (--out)
cmp -s <(grep -v "^#" ref/diagnostics.csv) <(grep -v "^#" run/diagnostics.csv)
ok $? "diagnostics.csv matches" "$(wc -l <ref/diagnostics.csv) rows"
cmp -s ref/particles.xmf run/particles.xmf
ok $? "particles.xmf matches"
finish
