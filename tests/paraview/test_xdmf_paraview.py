"""test_xdmf_paraview.py — acceptance test 9: ParaView 5.11 opens the demo's HDF5 + XDMF output with the points, cells, times and arrays written.

Run as:  xvfb-run -a pvpython tests/paraview/test_xdmf_paraview.py
(./Alltest does this). Runs build/canopy/bin/canopyDropDemo (or $CANOPY_DEMO)
for a tiny case into a temporary directory, reads what the .h5 holds with
h5dump (hdf5-tools; pvpython has no h5py), opens the .xdmf with ParaView's
Xdmf3 reader (the one File > Open picks) and with its legacy XDMF reader,
and checks: points, cells (triangles and 2-node lines), time steps and their
values, the geometry of the last step, and the arrays velocity, cell_dp and
cell_tension. Renders one screenshot to prove the data draws. Then the
same with -f (each step also written in the frame that follows the
payload): both readers open drop-frame.xdmf with every step, and the last
step's bounds are those of x - frame_origin. Exits non-zero with a message
on any mismatch; the temporary directory is kept then.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
VTK_POLY_LINE = 4
VTK_TRIANGLE = 5

failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("MISMATCH: " + message)
    return ok


def die(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command):
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, universal_newlines=True)
    if result.returncode != 0:
        die("%s exited with %d:\n%s" % (" ".join(command), result.returncode,
                                        result.stdout))
    return result.stdout


def h5dump(*args):
    if shutil.which("h5dump") is None:
        die("h5dump not found (package hdf5-tools; run bin/setup)")
    return run(["h5dump", "-m", "%.17g"] + list(args))


def int_attribute(dump, name):
    m = re.search(r'ATTRIBUTE "%s" \{.*?DATA \{\s*\(0\):\s*(-?\d+)' % name,
                  dump, re.S)
    if not m:
        die("no attribute %s in h5dump output:\n%s" % (name, dump[:2000]))
    return int(m.group(1))


def expected_from_h5(h5):
    """Counts, step names and times, and the last step's positions."""
    mesh = h5dump("-A", "-g", "/mesh", h5)
    nodes = int_attribute(mesh, "nodes")
    triangles = int_attribute(mesh, "triangles")
    lines = int_attribute(mesh, "lines")
    steps_dump = h5dump("-A", "-g", "/steps", h5)
    steps = []
    for chunk in steps_dump.split('GROUP "')[1:]:
        name = re.match(r'(\d+)"', chunk)
        time = re.search(r'ATTRIBUTE "time" \{.*?DATA \{\s*\(0\):\s*(\S+)',
                         chunk, re.S)
        if name and time:
            steps.append((name.group(1), time.group(1)))
    if not steps:
        die("no steps with a time attribute in %s" % h5)
    steps = sorted((int(name), float(t)) for name, t in steps)
    last = "/steps/%06d/x" % steps[-1][0]
    values = re.findall(r'\(\d+,\d+\):\s*([-+0-9.eEinfa]+)',
                        h5dump("-d", last, h5))
    x = [float(v) for v in values]
    if len(x) != 3 * nodes:
        die("%s holds %d values, expected %d" % (last, len(x), 3 * nodes))
    return nodes, triangles, lines, steps, x


def bounds(x):
    return [f(x[c::3]) for c in range(3) for f in (min, max)]


def close(a, b, tol):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def check_reader(name, reader, nodes, triangles, lines, steps, x):
    from paraview import servermanager as sm
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else []
    check(len(times) == len(steps),
          "%s: %d time steps, the file has %d" % (name, len(times), len(steps)))
    for (number, t), seen in zip(steps, times):
        check(close(t, seen, 1e-12),
              "%s: step %06d at t = %.17g, the file says %.17g"
              % (name, number, seen, t))
    reader.UpdatePipeline(times[-1] if times else 0.0)
    data = sm.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    points, cells = data.GetNumberOfPoints(), data.GetNumberOfCells()
    print("%s: %d points, %d cells, %d time steps (t = %g .. %g)"
          % (name, points, cells, len(times), times[0] if times else 0,
             times[-1] if times else 0))
    check(points == nodes, "%s: %d points, the file has %d nodes"
          % (name, points, nodes))
    check(cells == triangles + lines,
          "%s: %d cells, the file has %d triangles + %d lines"
          % (name, cells, triangles, lines))
    types = [data.GetCellType(i) for i in range(cells)]
    check(types.count(VTK_TRIANGLE) == triangles,
          "%s: %d triangles, expected %d"
          % (name, types.count(VTK_TRIANGLE), triangles))
    check(types.count(VTK_POLY_LINE) == lines,
          "%s: %d lines, expected %d" % (name, types.count(VTK_POLY_LINE), lines))
    pd, cd = data.GetPointData(), data.GetCellData()
    velocity = pd.GetArray("velocity")
    check(velocity is not None and velocity.GetNumberOfComponents() == 3
          and velocity.GetNumberOfTuples() == nodes,
          "%s: point array velocity (3 components per node) missing" % name)
    for array in ("cell_dp", "cell_tension"):
        a = cd.GetArray(array)
        check(a is not None and a.GetNumberOfTuples() == cells,
              "%s: cell array %s missing" % (name, array))
    for array in ("node_group", "node_mass"):
        check(pd.GetArray(array) is not None,
              "%s: point array %s missing" % (name, array))
    got = data.GetBounds()
    want = bounds(x)
    check(all(close(g, w, 1e-12) for g, w in zip(got, want)),
          "%s: bounds at the last time %s, the file's last step %s"
          % (name, list(got), want))
    return data


def screenshot(reader, png):
    from paraview import simple
    view = simple.CreateView("RenderView")
    view.ViewSize = [640, 480]
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView 5.11: a palette background unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = simple.Show(reader, view)
    simple.ColorBy(display, ("CELLS", "cell_tension"))
    view.CameraPosition = [4.0, -6.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, -1.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=[640, 480])
    if not os.path.isfile(png) or os.path.getsize(png) == 0:
        die("no screenshot written to %s" % png)
    with open(png, "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", "%s is not a PNG" % png)
    # Something was drawn: not every pixel has the background colour.
    from vtkmodules.vtkIOImage import vtkPNGReader
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    scalars = r.GetOutput().GetPointData().GetScalars()
    n = scalars.GetNumberOfTuples()
    background = scalars.GetTuple(0)
    drawn = sum(1 for i in range(0, n, 7) if scalars.GetTuple(i) != background)
    print("screenshot %s: %d bytes, %d of %d sampled pixels drawn"
          % (png, os.path.getsize(png), drawn, (n + 6) // 7))
    check(drawn > 0, "the screenshot shows only the background")


def main():
    demo = os.environ.get("CANOPY_DEMO") or os.path.join(
        ROOT, "build", "canopy", "bin", "canopyDropDemo")
    if not os.access(demo, os.X_OK):
        die("no demo program at %s (build with ./Allwmake, or set CANOPY_DEMO)"
            % demo)
    tmp = tempfile.mkdtemp(prefix="canopy-paraview-")
    prefix = os.path.join(tmp, "drop")
    run([demo, "-o", prefix, "-t", "0.05", "-h", "0.25", "-w", "0.01", "-q"])
    h5, xdmf = prefix + ".h5", prefix + ".xdmf"
    for f in (h5, xdmf):
        if not os.path.isfile(f):
            die("the demo wrote no %s" % f)
    nodes, triangles, lines, steps, x = expected_from_h5(h5)
    print("%s: %d nodes, %d triangles, %d lines, %d steps"
          % (h5, nodes, triangles, lines, len(steps)))
    check(triangles > 0 and lines > 0, "the demo wrote no triangles or lines")
    check(len(steps) == 6, "%d steps written, expected 6 (t = 0, 0.01 .. 0.05)"
          % len(steps))

    from paraview import simple
    xdmf = os.path.abspath(xdmf)  # the XDMF readers want an absolute path
    default = simple.OpenDataFile(xdmf)
    print("File > Open picks %s" % default.GetXMLName())
    reader = simple.Xdmf3ReaderS(FileName=[xdmf])
    check_reader("Xdmf3ReaderS", reader, nodes, triangles, lines, steps, x)
    legacy = simple.XDMFReader(FileNames=[xdmf])
    check_reader("XDMFReader", legacy, nodes, triangles, lines, steps, x)
    screenshot(reader, os.path.join(tmp, "drop.png"))

    # The moving frame (-f: the frame follows the payload): drop-frame.xdmf
    # shows every step at x - origin, the payload at the origin
    framed = os.path.join(tmp, "framed")
    run([demo, "-o", framed, "-t", "0.05", "-h", "0.25", "-w", "0.01", "-q",
         "-f"])
    fh5, fxdmf = framed + ".h5", os.path.abspath(framed + "-frame.xdmf")
    if not os.path.isfile(fxdmf):
        die("the demo with -f wrote no %s" % fxdmf)
    nodes, triangles, lines, steps, x = expected_from_h5(fh5)
    origin = [float(v) for v in re.findall(
        r'\(\d+\):\s*([-+0-9.eEinfa]+)',
        h5dump("-d", "/steps/%06d/frame_origin" % steps[-1][0], fh5))]
    check(len(origin) == 3, "no frame_origin in the last step of %s" % fh5)
    print("frame origin at the last step: %s" % origin)
    check(origin[2] < -1.0, "the frame's origin %s is not at the payload "
          "(about 1.7 m below the skirt)" % origin)
    moved = [v - origin[k % 3] for k, v in enumerate(x)]
    for label, r in (("Xdmf3ReaderS (frame)", simple.Xdmf3ReaderS(
            FileName=[fxdmf])), ("XDMFReader (frame)", simple.XDMFReader(
                FileNames=[fxdmf]))):
        check_reader(label, r, nodes, triangles, lines, steps, moved)

    if failures:
        print("FAIL: %d mismatch(es); files kept in %s" % (len(failures), tmp))
        sys.exit(1)
    shutil.rmtree(tmp, ignore_errors=True)
    print("PASS: ParaView reads %d points, %d cells, %d time steps"
          % (nodes, triangles + lines, len(steps)))


if __name__ == "__main__":
    main()
