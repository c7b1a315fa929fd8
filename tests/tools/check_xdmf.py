"""check_xdmf.py - open an mvmpm XDMF series in ParaView and check it.

usage: pvbatch tests/tools/check_xdmf.py SERIES.xmf N0 [N1 ...] [--reader R]
                                        [--dim D]

N0, N1, ... are the particle counts expected at each time step, in order.
For every step the script updates ParaView's reader at that time and
checks: the number of cells is N (one polyvertex per particle); the
number of points is N (an empty step has one placeholder point); the
point coordinates and every array equal, bit for bit, the datasets of
the HDF5 snapshot the step names.  The arrays expected come from the
snapshot itself (read with h5py), not from the .xmf, so a field the
index forgets is caught:
  ncomp 1                              -> array NAME
  components "x,y" (2-D) / "x,y,z"     -> vector NAME: 3 components with
                                          the XDMF 2 reader (z = 0 added),
                                          DIM with the Xdmf3 readers
  other ncomp > 1                      -> array NAME, ncomp components in
                                          the snapshot's order
Extra arrays in ParaView are an error too.  Without h5py, only the names
listed in the .xmf are checked (and the script says so).

--dim D: the series must be D-dimensional (the snapshots' dim), the
points must carry D coordinates from the snapshot (in 3-D z is checked
like x and y), and ParaView must show velocity with D components (3 with
the XDMF 2 reader), stress with its 4 (2-D: xx, yy, xy, zz) or 6 (3-D)
and F with D x D: the arrays a 3-D series is read for, named.

R is the ParaView reader: XDMFReader (the XDMF 2 reader, the default),
Xdmf3ReaderS or Xdmf3ReaderT; each must see every array.
Prints what it found; exit status 0 when everything matches, 1 on a
mismatch, 2 when the file cannot be read or the arguments are wrong.
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

from paraview import servermanager as sm
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

try:
    import h5py
except ImportError:
    h5py = None

failures = []


def fail(msg):
    failures.append(msg)
    print("  MISMATCH: " + msg)


def usage(msg):
    print("check_xdmf: " + msg)
    print("usage: pvbatch check_xdmf.py SERIES.xmf N0 [N1 ...] [--reader R] [--dim D]")
    sys.exit(2)


def parse_args(argv):
    reader = "XDMFReader"
    dim = None
    rest = []
    i = 0
    while i < len(argv):
        if argv[i] == "--reader" and i + 1 < len(argv):
            reader = argv[i + 1]
            i += 2
        elif argv[i] == "--dim" and i + 1 < len(argv):
            if argv[i + 1] not in ("2", "3"):
                usage("--dim must be 2 or 3")
            dim = int(argv[i + 1])
            i += 2
        else:
            rest.append(argv[i])
            i += 1
    if len(rest) < 2:
        usage("need the .xmf and at least one expected count")
    try:
        counts = [int(x) for x in rest[1:]]
    except ValueError:
        usage("expected counts must be integers")
    return rest[0], counts, reader, dim


def steps_of(xmf):
    """[(time, snapshot file or None, [attribute names])] from the .xmf"""
    root = ET.parse(xmf).getroot()
    steps = []
    for g in root.iter("Grid"):
        if g.get("GridType") != "Uniform":
            continue
        t = float(g.find("Time").get("Value"))
        item = g.find("Geometry/DataItem")
        heavy = None
        if item is not None and item.get("Format") == "HDF":
            heavy = item.text.strip().rsplit(":/", 1)[0]
        names = [a.get("Name") for a in g.findall("Attribute")]
        steps.append((t, heavy, names))
    return steps


def expected_arrays(h5path, reader):
    """{array name: (ncomp in VTK, numpy array of the values)}"""
    out = {}
    with h5py.File(h5path, "r") as f:
        dim = int(f.attrs["dim"])
        for name, d in f.items():
            if name in ("position", "scene_source") or not isinstance(d, h5py.Dataset):
                continue
            a = d[()]
            comps = d.attrs.get("components")
            comps = comps.split(",") if comps else None
            if a.ndim == 1:
                out[name] = (1, a)
            elif (comps == ["x", "y", "z"][:dim] and a.shape[1] == dim
                  and reader == "XDMFReader"):
                pad = np.zeros((a.shape[0], 3), dtype=a.dtype)
                pad[:, :dim] = a
                out[name] = (3, pad)
            else:
                out[name] = (a.shape[1], a)
        pos = f["position"][()]
    return out, pos, dim


def same_bits(a, b):
    a = np.ascontiguousarray(a)
    b = np.ascontiguousarray(b).astype(a.dtype, copy=False)
    if a.shape != b.shape:
        return False
    return a.tobytes() == b.tobytes()


def unstructured(data):
    """the grid of one step (a multiblock holds it as its only leaf)"""
    if data.IsA("vtkMultiBlockDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        leaves = []
        while not it.IsDoneWithTraversal():
            leaves.append(it.GetCurrentDataObject())
            it.GoToNextItem()
        return leaves[0] if len(leaves) == 1 else None
    return data


def check_dim(i, want_dim, dim, pos, found, reader):
    """the arrays a series of want_dim dimensions is read for"""
    if dim != want_dim:
        fail("step %d: the snapshot is %d-D, expected %d-D" % (i, dim, want_dim))
        return
    if pos.ndim != 2 or pos.shape[1] != dim:
        fail("step %d: position has shape %s, expected (N, %d)"
             % (i, pos.shape, dim))
    need = {"velocity": 3 if reader == "XDMFReader" else dim,
            "stress": 4 if dim == 2 else 6, "F": dim * dim}
    for nm, nc in sorted(need.items()):
        if found.get(nm) != nc:
            fail("step %d: %s seen with %s components, expected %d"
                 % (i, nm, found.get(nm), nc))


def check_step(i, t, n, heavy, names, grid, base, reader, want_dim):
    npts, ncell = grid.GetNumberOfPoints(), grid.GetNumberOfCells()
    pd = grid.GetPointData()
    found = {pd.GetArrayName(k): pd.GetArray(k).GetNumberOfComponents()
             for k in range(pd.GetNumberOfArrays())}
    print("step %d  t=%g  points=%d cells=%d  arrays=%s" % (
        i, t, npts, ncell,
        ", ".join("%s(%d)" % kv for kv in sorted(found.items())) or "none"))
    if ncell != n:
        fail("step %d: %d cells, expected %d" % (i, ncell, n))
    want_pts = n if n > 0 else 1  # the placeholder point of an empty step
    if npts != want_pts:
        fail("step %d: %d points, expected %d" % (i, npts, want_pts))
    if n == 0:
        if found:
            fail("step %d: empty step has arrays %s" % (i, sorted(found)))
        return
    if heavy is None:
        fail("step %d: no HDF5 file named in the .xmf" % i)
        return
    if h5py is None:
        want = {nm: None for nm in names}
        for nm in sorted(set(want) - set(found)):
            fail("step %d: array %s listed in the .xmf but not loaded" % (i, nm))
        return
    want, pos, dim = expected_arrays(os.path.join(base, heavy), reader)
    if want_dim is not None:
        check_dim(i, want_dim, dim, pos, found, reader)
    for nm in sorted(set(want) - set(found)):
        fail("step %d: array %s missing" % (i, nm))
    for nm in sorted(set(found) - set(want)):
        fail("step %d: unexpected array %s" % (i, nm))
    for nm in sorted(set(want) & set(found)):
        ncomp, ref = want[nm]
        if found[nm] != ncomp:
            fail("step %d: %s has %d components, expected %d"
                 % (i, nm, found[nm], ncomp))
            continue
        got = vtk_to_numpy(pd.GetArray(nm))
        if not same_bits(got, ref):
            fail("step %d: values of %s differ from %s" % (i, nm, heavy))
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    ref = np.zeros((pos.shape[0], 3))
    ref[:, :pos.shape[1]] = pos
    if not same_bits(pts, ref):
        fail("step %d: point coordinates differ from %s:/position" % (i, heavy))


def open_reader(name, xmf):
    factory = getattr(simple, name, None)
    if factory is None:
        usage("no reader %s in this ParaView" % name)
    if name == "XDMFReader":
        return factory(FileNames=[xmf])
    return factory(FileName=[xmf])


def main():
    xmf, counts, reader_name, want_dim = parse_args(sys.argv[1:])
    if not os.path.isfile(xmf):
        usage("%s: no such file" % xmf)
    steps = steps_of(xmf)
    base = os.path.dirname(os.path.abspath(xmf))
    print("%s: %d steps in the .xmf, reader %s%s" % (
        xmf, len(steps), reader_name,
        "" if h5py else " (no h5py: names only)"))
    # absolute: the Xdmf3 readers join a bare relative name wrongly
    reader = open_reader(reader_name, os.path.abspath(xmf))
    times = list(reader.TimestepValues or [])
    if len(times) != len(counts) or len(steps) != len(counts):
        fail("%d time steps in ParaView, %d in the .xmf, %d expected"
             % (len(times), len(steps), len(counts)))
    for i, (t, n) in enumerate(zip(times, counts)):
        reader.UpdatePipeline(t)
        grid = unstructured(sm.Fetch(reader))
        if grid is None:
            fail("step %d: reader gave no single grid" % i)
            continue
        _, heavy, names = steps[i] if i < len(steps) else (t, None, [])
        check_step(i, t, n, heavy, names, grid, base, reader_name, want_dim)
    print("check_xdmf: %s" % ("ok" if not failures else
                              "%d mismatches" % len(failures)))
    sys.exit(1 if failures else 0)


main()
