#!/usr/bin/env python3
"""tests/tools/layers.py [OBJDIR] - the layers of src/ (docs/architecture.md)
checked by name.

Every file src/LAYER/*.[ch] may include the headers of the layers in
ALLOWED[LAYER] and the libraries in LIBS[LAYER], nothing else; a break is
reported as file:line, the header and the rule.  The units (a file's name
without .c or .h) and their includes form a graph: a cycle through units of
different layers is reported too.  With OBJDIR (the build's objects,
OBJDIR/LAYER/*.o) the same is checked on what the objects call: every symbol
an object takes from another must be defined in a layer it may use, and the
objects' call graph has no cycle across layers.  Exit status 1 on any
break; the last line says how many.
"""
import os
import re
import subprocess
import sys

# a layer may use the layers listed (itself included), never one above
ALLOWED = {
    "core": ["core"],
    "io": ["core", "io"],
    "render": ["core", "io", "render"],
    "lua": ["core", "io", "render", "lua"],
    "app": ["core", "io", "render", "lua", "app"],
}
# the libraries' headers each layer may include
LIBS = {
    "core": [],
    "io": ["hdf5"],
    "render": ["zlib"],
    "lua": ["lua"],
    "app": ["lua", "hdf5", "zlib", "editline"],
}
# headers of the libraries, by name
LIBHDR = [
    (re.compile(r"^(lua|lauxlib|lualib|luaconf)\.h$"), "lua"),
    (re.compile(r"^(hdf5|H5[A-Za-z0-9_]*)\.h$"), "hdf5"),
    (re.compile(r"^zlib\.h$"), "zlib"),
    (re.compile(r"^(editline/.*|histedit\.h|readline/.*)$"), "editline"),
]
# made by the build, not under src/ (the Makefile's version_gen.h)
GENERATED = {"version_gen.h": "lua"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def layer_files(src):
    files = {}
    for layer in ALLOWED:
        d = os.path.join(src, layer)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            if name.endswith((".c", ".h")):
                files[os.path.join(d, name)] = (layer, name)
    return files


def libof(hdr):
    for pat, lib in LIBHDR:
        if pat.match(hdr):
            return lib
    return None


def sccs(graph):
    """Tarjan's strongly connected components, iteratively."""
    index, low, onstack, stack, out = {}, {}, set(), [], []
    counter = [0]
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        onstack.add(root)
        while work:
            v, it = work[-1]
            pushed = False
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    onstack.add(w)
                    work.append((w, iter(sorted(graph.get(w, ())))))
                    pushed = True
                    break
                if w in onstack:
                    low[v] = min(low[v], index[w])
            if pushed:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    onstack.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                out.append(sorted(comp))
    return out


def cycles_across(graph, layer_of, what):
    """Report each cycle of graph whose members lie in more than one layer."""
    errs = []
    for comp in sccs(graph):
        layers = sorted({layer_of[u] for u in comp})
        if len(comp) > 1 and len(layers) > 1:
            errs.append("%s cycle across layers %s: %s" % (
                what, ", ".join(layers),
                " ".join("%s/%s" % (layer_of[u], u) for u in comp)))
    return errs


def check_includes(src):
    files = layer_files(src)
    header_layer = {}      # header name -> layer
    errs = []
    # a source left in src/ itself (one merged from before the layers) is
    # compiled by nobody: it must move to its layer
    for name in sorted(os.listdir(src)):
        if name.endswith((".c", ".h")):
            errs.append("%s: in no layer: move it (git mv) to src/%s/" % (
                os.path.join(src, name), "|".join(ALLOWED)))
    for path, (layer, name) in files.items():
        if name.endswith(".h"):
            if name in header_layer:
                errs.append("%s: header name also in src/%s/ (names are "
                            "unique across layers)" % (path, header_layer[name]))
            header_layer[name] = layer
    unit_layer = {}
    graph = {}
    for path, (layer, name) in files.items():
        unit = name[:-2]
        unit_layer[unit] = layer
        graph.setdefault(unit, set())
    for path, (layer, name) in sorted(files.items()):
        unit = name[:-2]
        with open(path, encoding="utf-8", errors="replace") as f:
            for ln, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                hdr = m.group(2)
                lib = libof(hdr)
                if lib:
                    if lib not in LIBS[layer]:
                        errs.append("%s:%d: includes %s (%s): %s may include "
                                    "%s" % (path, ln, hdr, lib, layer,
                                            "the headers of " +
                                            ", ".join(LIBS[layer]) + " only"
                                            if LIBS[layer] else
                                            "no library's header"))
                    continue
                if m.group(1) == "<":
                    continue        # the C library and the system's
                if hdr in GENERATED:
                    if GENERATED[hdr] != layer:
                        errs.append("%s:%d: includes %s, made for %s" % (
                            path, ln, hdr, GENERATED[hdr]))
                    continue
                to = header_layer.get(hdr)
                if to is None:
                    errs.append("%s:%d: includes \"%s\", a header of no layer "
                                "under src/" % (path, ln, hdr))
                    continue
                if to not in ALLOWED[layer]:
                    errs.append("%s:%d: includes %s of %s: %s may include %s "
                                "only" % (path, ln, hdr, to, layer,
                                          ", ".join(ALLOWED[layer])))
                if hdr[:-2] != unit:
                    graph[unit].add(hdr[:-2])
    errs += cycles_across(graph, unit_layer, "include")
    return errs, len(files)


def check_objects(objdir):
    """What each object takes from the others (nm), by layer."""
    defs, undef, layer_of = {}, {}, {}
    for layer in ALLOWED:
        d = os.path.join(objdir, layer)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            unit = name[:-2]
            # an object left from a source moved or removed is not looked at
            if not (name.endswith(".o") and
                    os.path.exists(os.path.join("src", layer, unit + ".c"))):
                continue
            layer_of[unit] = layer
            out = subprocess.run(["nm", os.path.join(d, name)], check=True,
                                 capture_output=True, text=True).stdout
            undef[unit] = set()
            for line in out.splitlines():
                parts = line.split()
                if len(parts) == 2 and parts[0] == "U":
                    undef[unit].add(parts[1])
                elif len(parts) == 3 and parts[1] in "TDBRCV":
                    defs[parts[2]] = unit
    errs = []
    graph = {u: set() for u in layer_of}
    for unit in sorted(undef):
        for sym in sorted(undef[unit]):
            to = defs.get(sym)
            if to is None or to == unit:
                continue
            graph[unit].add(to)
            if layer_of[to] not in ALLOWED[layer_of[unit]]:
                errs.append("%s/%s.o calls %s of %s/%s.c: %s may use %s only" % (
                    layer_of[unit], unit, sym, layer_of[to], to,
                    layer_of[unit], ", ".join(ALLOWED[layer_of[unit]])))
    errs += cycles_across(graph, layer_of, "call")
    return errs, len(layer_of)


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    objdir = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else None
    os.chdir(root)          # file names as the compiler gives them
    errs, nfiles = check_includes("src")
    what = "%d files" % nfiles
    if objdir:
        oerrs, nobj = check_objects(objdir)
        errs += oerrs
        what += ", %d objects" % nobj
    for e in errs:
        print(e)
    print("layers: %s checked, %d broken" % (what, len(errs)))
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
