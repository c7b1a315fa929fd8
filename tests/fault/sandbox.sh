#!/usr/bin/env bash
# tests/fault/sandbox.sh BIN - mvmpm run --sandbox: an honest scene runs
# and writes its pictures and snapshots inside the output directory;
# each forbidden thing fails with a clear message and status 1, and
# nothing appears outside the output directory.
source "$(dirname "$0")/lib.sh" sandbox "$1"
cd "$tmp"
base='local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {0, 1}, y = {0, 1}}, cell = 1/8, t_end = 0.05}
sim:body {shape = mvmpm.disk {center = {0.5, 0.5}, radius = 0.2},
          material = mvmpm.elastic {K = 1, G = 0.5, density = 1}, velocity = {0.1, 0}}'

cat >honest.lua <<LUA
$base
local M = require "mvmpm.materials"
local t0, now, day = os.clock(), os.time(), os.date("%Y")
local f = load("return 6 * 7")
assert(f() == 42 and type(M) == "table" and math.sqrt(4) == 2 and string.format("%d", 3) == "3")
sim:output {dir = "out/honest", every = 0.025}
sim:every {time = 0.025, fn = function(s)
  s:snapshot("mine/snap.h5")
  s:render {file = "pic.png"}
  mvmpm.plot {file = "plots/p.png", series = {{x = {0, 1}, y = {0, 1}}}}
end}
return sim
LUA
"$bin" run honest.lua --sandbox --out o --quiet >out.txt 2>&1
ok $? "an honest scene runs under --sandbox" "$(head -1 out.txt)"
[ -e o/mine/snap.h5 ] && [ -e o/pic.png ] && [ -e o/plots/p.png ] && [ -e o/particles_000000.h5 ] && [ ! -e out ]
ok $? "its files are inside the output directory" "$(cd o && find . -type f | sort | tr '\n' ' ')"

# forbidden: WHAT, the line to add, the text the message must hold
n=0
forbid() {
  n=$((n + 1))
  printf '%s\n%s\nreturn sim\n' "$base" "$2" >bad$n.lua
  "$bin" run bad$n.lua --sandbox --out b$n --quiet >out.txt 2>&1
  local rc=$?
  [ "$rc" -eq 1 ] && has out.txt "$3" && [ ! -e escaped ] && [ ! -e /tmp/mvmpm_escaped ]
  ok $? "refused: $1" "$(grep -m1 -o "bad$n.lua:[0-9]*: .*" out.txt | cut -c1-150)"
}
forbid "io.open"             'io.open("escaped", "w")'              "io is not available under --sandbox"
forbid "os.execute"          'os.execute("touch escaped")'          "os.execute is not available under --sandbox (only os.clock, os.time and os.date are)"
forbid "os.remove"           'os.remove("honest.lua")'              "os.remove is not available under --sandbox"
forbid "os.getenv"           'os.getenv("HOME")'                    "os.getenv is not available under --sandbox"
forbid "require of a library" 'require "io"'                        'require "io": under --sandbox only the mvmpm modules'
forbid "require of a path"   'require "mvmpm/../../x"'              'only the mvmpm modules'
forbid "package.loadlib"     'package.loadlib("libc.so.6", "*")'    "package is not available under --sandbox"
forbid "dofile"              'dofile("honest.lua")'                 "dofile is not available under --sandbox"
forbid "loadfile"            'loadfile("honest.lua")'               "loadfile is not available under --sandbox"
forbid "load of bytecode"    'assert(load("\27Lua"))'               "attempt to load a binary chunk"
forbid "load with mode b"    'load("return 1", "x", "b")'           'load: mode "b" is not allowed under --sandbox'
forbid "string.dump"         'string.dump(print)'                   "string.dump is not available under --sandbox"
forbid "debug"               'debug.getinfo(1)'                     "debug is not available under --sandbox"
forbid "mvmpm.load"          'mvmpm.load("honest.lua")'             'not allowed under --sandbox (it reads other files)'
forbid "absolute snapshot"   'sim:snapshot("/tmp/mvmpm_escaped")'   "snapshot: path '/tmp/mvmpm_escaped' is not allowed under --sandbox"
forbid "snapshot with .."    'sim:snapshot("../escaped")'           "snapshot: path '../escaped' is not allowed under --sandbox (no '..'"
forbid "render with .."      'sim:render{file = "a/../../escaped"}' "render: path 'a/../../escaped' is not allowed"
forbid "plot absolute"       'mvmpm.plot{file = "/tmp/mvmpm_escaped", series = {{x = {0}, y = {0}}}}' "plot: path '/tmp/mvmpm_escaped' is not allowed"
forbid "output dir elsewhere" 'sim:output{dir = "/tmp/mvmpm_escaped"}' "output: path '/tmp/mvmpm_escaped' is not allowed"

# a precompiled scene: bytecode is refused before it runs
printf '%s\nreturn sim\n' "$base" >plain.lua
cat >dump.lua <<'LUA'
local f = assert(io.open("compiled.lua", "wb"))
f:write(string.dump(assert(loadfile("plain.lua")))); f:close()
LUA
"$bin" test dump.lua >/dev/null 2>&1
"$bin" run compiled.lua --sandbox --out c --quiet >out.txt 2>&1
[ $? -eq 1 ] && has out.txt "compiled.lua: a precompiled scene (bytecode) is not allowed under --sandbox"
ok $? "refused: a precompiled scene" "$(head -1 out.txt | cut -c1-120)"
finish
