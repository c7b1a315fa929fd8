# tests/fault/lib.sh - what the fault tests share: a scratch directory,
# checks that print what they measured, and the closing count line.
#   source tests/fault/lib.sh NAME BIN
set -u
name=$1 bin=$2
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
pass=0 fail=0
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT

ok() { # ok CONDITION-STATUS WHAT [MEASURED]
  if [ "$1" -eq 0 ]; then pass=$((pass + 1)); echo "ok   $2${3:+  ($3)}"
  else fail=$((fail + 1)); echo "FAIL $2${3:+  ($3)}"; fi
}
check() { # check WHAT COMMAND...: the command's status decides
  local what=$1; shift
  "$@" >/dev/null 2>&1
  ok $? "$what"
}
has() { # has FILE TEXT: the file holds the text
  grep -qF -- "$2" "$1"
}
finish() {
  echo "$name: $pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
