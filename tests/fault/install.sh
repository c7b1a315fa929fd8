#!/usr/bin/env bash
# tests/fault/install.sh BIN - the program as installed: make install into a
# scratch PREFIX and a DESTDIR, the installed binary run from elsewhere
# (its Lua modules found, the REPL loading them), the engine as a module
# of a stock lua5.4, the manual page, per-command help, and the sources
# compiled by clang as well as gcc, warning-free.
source "$(dirname "$0")/lib.sh" install "$1"
root=$PWD
prefix=$tmp/prefix
# the installed build is the plain one, whatever the suite runs under
mk() { make -s --no-print-directory -C "$root" SAN=0 TSAN=0 FUZZ=0 "$@"; }

mk install PREFIX="$prefix" >"$tmp/install.log" 2>&1
ok $? "make install PREFIX=..." "$(tail -1 "$tmp/install.log")"
for f in bin/mvmpm share/lua/5.4/mvmpm/materials.lua share/lua/5.4/mvmpm/repl.lua \
         lib/lua/5.4/mvmpm.so share/man/man1/mvmpm.1; do
  check "installed: $f" test -e "$prefix/$f"
done
mk install PREFIX=/usr DESTDIR="$tmp/stage" >/dev/null 2>&1
check "DESTDIR stages under DESTDIR/PREFIX" test -x "$tmp/stage/usr/bin/mvmpm"

# the installed binary, from another directory, with no tree to lean on
mkdir -p "$tmp/elsewhere"
cat >"$tmp/elsewhere/mods.lua" <<'EOF'
local V = require "mvmpm.verify"
local M = require "mvmpm.materials"
V.holds("mvmpm.materials found by the installed binary", type(M) == "table")
-- a small physical check through the installed engine: a free disc
-- keeps its momentum
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, t_end = 0.5}
local b = sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
                    material = mvmpm.elastic {K = 10, G = 5, density = 1},
                    velocity = {0.1, 0}}
sim:run(0.5)
V.near("momentum kept", sim:energy().px / (b:diag().mass * 0.1), 1, 1e-12)
EOF
out=$(cd "$tmp/elsewhere" && env -u MVMPM_LUA "$prefix/bin/mvmpm" test mods.lua 2>&1)
grep -q "2 passed, 0 failed" <<<"$out"
ok $? "installed binary finds its modules from another directory" "$(tail -1 <<<"$out")"
out=$(cd "$tmp/elsewhere" && printf 'print("mods", type(require "mvmpm.pack"))\n' |
      env -u MVMPM_LUA "$prefix/bin/mvmpm" repl 2>&1)
grep -q "mods	table" <<<"$out"
ok $? "installed REPL requires mvmpm.pack" "$(grep mods <<<"$out" | head -1)"

# a stock interpreter: require "mvmpm" from the installed module
if command -v lua5.4 >/dev/null; then
  out=$(cd "$tmp/elsewhere" && LUA_PATH="$prefix/share/lua/5.4/?.lua;;" \
        LUA_CPATH="$prefix/lib/lua/5.4/?.so;;" lua5.4 -e '
    local m = require "mvmpm"
    local sim = m.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 0.1, t_end = 0.2}
    sim:body {shape = m.disk {center = {0.5, 0.5}, radius = 0.2},
              material = m.elastic {K = 10, G = 5, density = 1}, velocity = {0, 0.1}}
    local e0 = sim:energy().total
    sim:run(0.2)
    print("stock", m.version, require("mvmpm.materials") ~= nil,
          math.abs(sim:energy().total / e0 - 1) < 1e-2)' 2>&1)
  grep -q "^stock	[^	]*	true	true" <<<"$out"
  ok $? "lua5.4: require \"mvmpm\" runs a scene" "$(grep -m1 '^stock' <<<"$out")"
else
  echo "skip lua5.4 not installed (make deps installs it)"
fi

# the manual
if command -v man >/dev/null; then
  out=$(MANWIDTH=80 man -l "$prefix/share/man/man1/mvmpm.1" 2>&1)
  grep -q "checkpoint-every" <<<"$out" && grep -q "MVMPM_LUA" <<<"$out"
  ok $? "man mvmpm renders (options, environment)" "$(wc -l <<<"$out") lines"
fi
if command -v groff >/dev/null; then
  w=$(groff -man -Tutf8 -ww -z "$root/docs/mvmpm.1" 2>&1 | wc -l)
  ok $([ "$w" -eq 0 ]; echo $?) "the manual has no groff warnings" "$w"
fi

# per-command help: stdout, status 0, that command's options
for c in "run:--checkpoint-every" "repl:--set" "test:passed" "render:--colormap"; do
  out=$("$bin" "${c%%:*}" --help 2>/dev/null); rc=$?
  ok $([ $rc -eq 0 ] && grep -q -- "${c#*:}" <<<"$out" && ! grep -q "unknown option" <<<"$out"; echo $?) \
     "mvmpm ${c%%:*} --help" "status $rc"
done
out=$("$bin" run scene.lua --help 2>/dev/null)
ok $(grep -q -- "--sandbox" <<<"$out"; echo $?) "mvmpm run SCENE --help is help too"

# clang and gcc: every source compiles warning-free under the build's
# warnings (the front end's, which is where they come from)
if command -v clang >/dev/null; then
  # each layer with its own include paths (docs/architecture.md), run
  # from the root as make does
  n=0
  for l in core io render lua app; do
    flags=$(make -s --no-print-directory -C "$root" CC=clang BUILD="$tmp/clang" LAYER=$l print-cflags)
    for f in "$root"/src/$l/*.c; do
      # -I build: version.c's generated header (make writes it there)
      (cd "$root" && clang $flags -I"$root/build" -fsyntax-only "$f") >>"$tmp/clang.log" 2>&1 || n=$((n + 1))
    done
  done
  ok $([ $n -eq 0 ]; echo $?) "clang: every source compiles with -Werror" \
     "$n failed; $(grep -m1 -E 'error|warning' "$tmp/clang.log")"
else
  echo "skip clang not installed"
fi
finish
