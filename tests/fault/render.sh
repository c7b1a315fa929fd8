#!/usr/bin/env bash
# tests/fault/render.sh BIN - pictures from runs: snapshots and
# checkpoints carry the domain and the bodies' names, `mvmpm render`
# frames and labels with them (and with the particles' extent and
# "body N" for a file without them), draws a checkpoint, writes SVG that
# parses, refuses a log scale over values that are not all positive;
# sim:render's relative file goes in the output directory.
source "$(dirname "$0")/lib.sh" render "$1"
py=/usr/bin/python3
cd "$tmp"
cat >scene.lua <<'LUA'
local mvmpm = require "mvmpm"
local sim = mvmpm.sim {domain = {x = {-1, 3}, y = {0, 2}}, cell = 0.25, t_end = 0.2,
  sides = {left = "periodic", right = "periodic"}, units = "SI"}
local m = mvmpm.elastic {K = 10, G = 5, density = 1}
sim:body {name = "cylinder", shape = mvmpm.disk {center = {0.5, 1}, radius = 0.4}, material = m,
          velocity = {0.5, 0}}
sim:body {name = "block", shape = mvmpm.rect {lo = {1.5, 0.5}, hi = {2.5, 1.5}}, material = m,
          driven = {0, 0}}
sim:output {every = 0.1, checkpoint = 0.1}
sim:every {time = 0.1, fn = function(s)
  s:render {file = "rel.png", by = "speed"}
  s:render {file = "rel.svg"}
end}
return sim
LUA
"$bin" run scene.lua --out out --quiet >run.txt 2>&1
ok $? "the scene runs" "$(tail -c 200 run.txt)"
[ -f out/rel.png ] && [ -f out/rel.svg ] && [ ! -e rel.png ]
ok $? "sim:render's relative file goes in the output directory" "$(ls out | tr '\n' ' ')"

snap=out/particles_000001.h5
$py - "$snap" out/checkpoint_000001.h5 >frame.txt 2>&1 <<'PY'
import sys, h5py
for path in sys.argv[1:]:
    f = h5py.File(path, "r")
    n = [x.decode() if isinstance(x, bytes) else x for x in f["bodies/name"][()]]
    print(path, list(f.attrs["domain_lo"]), list(f.attrs["domain_hi"]),
          list(f.attrs["periodic"]), n, list(f["bodies/driven"][()]))
PY
grep -q "particles_000001.h5 \[-1.0, 0.0\] \[3.0, 2.0\] \[1, 0\] \['cylinder', 'block'\] \[0, 1\]" frame.txt &&
grep -q "checkpoint_000001.h5 \[-1.0, 0.0\] \[3.0, 2.0\] \[1, 0\] \['cylinder', 'block'\] \[0, 1\]" frame.txt
ok $? "snapshot and checkpoint hold domain_lo/hi, periodic and bodies/name, bodies/driven" "$(tr '\n' ';' <frame.txt)"

# the frame: the stored domain, the same picture as --domain gives
"$bin" render $snap --out a.png >/dev/null 2>&1 &&
  "$bin" render $snap --out b.png --domain -1,3,0,2 >/dev/null 2>&1 && cmp -s a.png b.png
ok $? "render frames the stored domain (same bytes as --domain -1,3,0,2)"
"$bin" render $snap --out c.png --domain 0,2.5,0.4,1.6 >/dev/null 2>&1 && ! cmp -s a.png c.png
ok $? "--domain still overrides it"

# the legend: names and the driven flag, as text in the SVG
"$bin" render $snap --out a.svg >/dev/null 2>&1
ok $? "render --out FILE.svg"
$py -c "import xml.dom.minidom as m, sys
d = m.parse('a.svg')
t = [e.firstChild.data for e in d.getElementsByTagName('text') if e.firstChild]
p = len(d.getElementsByTagName('path'))
print(p, '|'.join(t) + '|')" >svg.txt 2>&1
ok $? "the SVG parses as XML" "$(head -c 200 svg.txt)"
has svg.txt "|cylinder|" && has svg.txt "|block (driven)|" && has svg.txt "|x (m)|" &&
  has svg.txt "|y (m)|" && has svg.txt "|0.5 m|"
ok $? "SVG text: body names, the driven flag, axis titles and the scale bar in the scene's unit (SI: m)" "$(head -c 300 svg.txt)"
n=$($py -c "import h5py; print(h5py.File('$snap', 'r')['position'].shape[0])")
[ "$(cut -d' ' -f1 svg.txt)" = "$n" ]
ok $? "one SVG polygon per particle" "$(cut -d' ' -f1 svg.txt) paths, $n particles"
$py -c "import xml.dom.minidom as m; m.parse('out/rel.svg')" >/dev/null 2>&1
ok $? "sim:render's SVG parses too"

# a checkpoint is drawn from its particle fields
"$bin" render out/checkpoint_000001.h5 --by speed --out ck.png >ck.txt 2>&1 && [ -s ck.png ]
ok $? "render draws a checkpoint" "$(head -c 200 ck.txt)"
"$bin" render out/checkpoint_000001.h5 --by nosuch --out ck2.png >ck2.txt 2>&1
[ $? -eq 1 ] && has ck2.txt "'nosuch'" && has ck2.txt "velocity.x"
ok $? "a checkpoint's keys are listed for a bad one" "$(head -c 200 ck2.txt)"

# log scale: refused over values that are not all positive, drawn over mass
"$bin" render $snap --by velocity.y --log --out l.png >l.txt 2>&1
[ $? -eq 1 ] && has l.txt "log scale needs values above zero" && has l.txt "velocity.y"
ok $? "--log over values down to zero or below is refused, naming the key" "$(head -c 200 l.txt)"
"$bin" render $snap --by mass --log --out l2.png >/dev/null 2>&1 && [ -s l2.png ]
ok $? "--log over positive values"
"$bin" render $snap --matrix nosuch --out m.png >mx.txt 2>&1
[ $? -eq 1 ] && has mx.txt "no body named 'nosuch'"
ok $? "--matrix with a name no body has is refused" "$(head -c 200 mx.txt)"

# a snapshot from before the frame was stored: the particles' extent
$py - $snap old.h5 <<'PY'
import sys, h5py, shutil
shutil.copy(sys.argv[1], sys.argv[2])
f = h5py.File(sys.argv[2], "r+")
for a in ("domain_lo", "domain_hi", "periodic"):
    del f.attrs[a]
del f["bodies"]
f.close()
PY
$py "$OLDPWD/tests/tools/h5sum.py" seal old.h5
"$bin" render old.h5 --out old.svg >old.txt 2>&1
ok $? "an older snapshot (no frame, no names) is drawn" "$(head -c 200 old.txt)"
has old.svg ">body 1<" && has old.svg ">body 2<" && ! has old.svg "cylinder"
ok $? "... its legend falls back on 'body N'"
finish
