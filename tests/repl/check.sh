#!/usr/bin/env bash
# tests/repl/check.sh BIN - drive the REPL in tmux as a person would
# (tests/tools/repl_session.sh) and check what the screen showed: steps
# advance, expressions print, multi-line input continues, an error leaves
# the session alive, a setting changes between steps, Ctrl-C stops a long
# run and returns to the prompt, Ctrl-D leaves.  Ends "N passed, M failed".
set -u
bin=$1
here=$(dirname "$0")
screen=$(mktemp)
hist=$(mktemp -d)
trap 'rm -rf "$screen" "$hist"' EXIT
HOME=$hist bash "$here/../tools/repl_session.sh" -t 60 "$here/session.txt" \
  "$bin" repl scenarios/cylinder_bounce.lua >"$screen" 2>&1
rc=$?
pass=0 fail=0
check() { # name, extended regexp the screen must show
  if grep -qE -- "$2" "$screen"; then echo "ok   $1"; pass=$((pass + 1))
  else echo "FAIL $1 (no line matching /$2/)"; fail=$((fail + 1)); fi
}
check "the prompt shows the scene" "^mvmpm .*cylinder_bounce.lua"
check "sim:step(10) then sim.steps prints 10" "^10$"
# the disc's discrete initial energy: 208 particles of (1/16)^2 at v = (0.1, 0.1)
# ten steps of free flight keep the budget closed to round-off, or exactly
check "energy printed: E0 of the seeded disc, budget closed" "E0 0\.00812 residual/E0 (-?[0-9.]+e-(0[4-9]|1[0-9])|-?0\.0e\+00)"
check "an unfinished line continues on the second prompt" "^ +>> 2$"
check "the continued chunk ran (x * 10 = 30)" "^30$"
check "an error prints and the session lives on" "stdin:1: boom"
check "body diagnostics (mass 208/256)" "^mass 0\.8125$"
check "a setting changed between steps" "^0\.5$"
check "Ctrl-C stops a running sim:run" "interrupted at step"
check "the run stopped early, at the prompt again" "^true$"
if [ "$rc" -eq 0 ]; then echo "ok   the session ended with Ctrl-D"; pass=$((pass + 1))
else echo "FAIL the session did not end cleanly (status $rc)"; sed 's/^/   | /' "$screen"; fail=$((fail + 1)); fi
echo "repl: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
