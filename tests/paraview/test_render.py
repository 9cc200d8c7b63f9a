"""test_render.py — python/canopyfoam/render.py, bin/canopy-render and etc/paraview/canopyCase.py draw a small case: PNGs with content, the slice at the canopy centre carrying U.

Run as:  xvfb-run -a pvpython tests/paraview/test_render.py
(./Alltest render does). About 10 s. Builds in a temporary directory:
- a 6 x 5 x 8 block mesh (blockMesh, with bin/openfoam-env sourced) of
  x -1.3 .. 2.3, y -1.5 .. 1.5, z -2.5 .. 1.5 m, cells 0.6 x 0.6 x 0.5 m;
  0/U uniform zero and 0.02/U = (x_c, 0.3 y_c, 2 + 0.5 z_c) at the cell
  centres c, so the latest time and the slice position can be read back;
- the canopy: build/canopy/bin/canopyDropDemo (7 ft canopy, centred on the
  z axis, skirt at z = 0, payload at z ~ -1.7) for 0.02 s, written every
  0.01 s as postProcessing/canopy/canopy.{h5,xdmf}, and a canopy.dat in
  the solver's layout whose frame columns say that the mesh follows the
  payload: frame origin z = -0.25 m at t = 0.01, -0.5 m at t = 0.02.
Checks: the scene picks t = 0.02 of [0, 0.02]; the canopy is drawn in the
mesh frame (the written structure moved up by 0.5 m); the slice plane passes
through the canopy centre (x ~ 0, inside the cell column x = -0.1 .. 0.5
whose centre is 0.2: every sliced cell's U_x is 0.2 within the reader's
single precision, 1e-6); the slice holds the 5 x 8 cut cells with U as
cell and point data, U_z = 2 + 0.5 z_c of the 8 layers; bin/canopy-render
writes both PNGs at the asked size, with many colours (shading and colour
maps; a blank or one-colour image fails) and at least 1 % of the pixels
drawn, 20 % for the slice picture (the slice fills ~40 % of it). A case
without fields gives canopy.png only and says so.
etc/paraview/canopyCase.py, executed the way the GUI runs it (no
__file__), builds its pipeline, draws, and at the fields' t = 0.02 shows
the canopy's last write (written as t = 0.02000000000000001: a reader
asked for 0.02 would show the write before). Exit status 1 on any
failure; the temporary directory is kept then.

Everything that draws runs in a pvbatch child on an Xvfb of its own
(bin/canopy-render, and bin/canopy-xrun for the GUI script) that is
started again when it aborts with "bad X server connection", which
happens to about 1 start in 15 on this machine with the X server up, and
to several starts in a row on a loaded machine; this process opens no
window.
"""

import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))

NX, NY, NZ = 6, 5, 8
X0, X1, Y0, Y1, Z0, Z1 = -1.3, 2.3, -1.5, 1.5, -2.5, 1.5
SIZE = (640, 480)

failures = []


def check(name, ok, detail=""):
    print("%s %s%s" % ("PASS" if ok else "FAIL", name,
                       ": " + detail if detail else ""))
    if not ok:
        failures.append(name)
    return ok


def die(message, tmp=None):
    print("FAIL: " + message)
    if tmp:
        print("files kept in %s" % tmp)
    sys.exit(1)


def run(command, tmp, **kw):
    p = subprocess.run(command, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, universal_newlines=True,
                       **kw)
    if p.returncode != 0:
        die("%s exited with %d:\n%s" % (" ".join(command), p.returncode,
                                        p.stdout[-3000:]), tmp)
    return p.stdout


X_FAILURE = "bad X server connection"


def pv_run(command, attempts=3, env=None):
    """Run a drawing child; start it again after an X connection abort.
    Returns (exit status, output)."""
    for attempt in range(1, attempts + 1):
        p = subprocess.run(command, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, universal_newlines=True,
                           env=env)
        if p.returncode == 0 or X_FAILURE not in p.stdout:
            return p.returncode, p.stdout
        print("  (no X connection, attempt %d of %d)" % (attempt, attempts))
    return p.returncode, p.stdout


FOAM_HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
"""


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def centres():
    """Cell centres in blockMesh order (x fastest, then y, then z)."""
    dx, dy, dz = (X1 - X0) / NX, (Y1 - Y0) / NY, (Z1 - Z0) / NZ
    return [(X0 + (i + 0.5) * dx, Y0 + (j + 0.5) * dy, Z0 + (k + 0.5) * dz)
            for k in range(NZ) for j in range(NY) for i in range(NX)]


def velocity(c):
    return (c[0], 0.3 * c[1], 2.0 + 0.5 * c[2])


def make_case(case, tmp):
    write(os.path.join(case, "system", "controlDict"),
          FOAM_HEADER % ("dictionary", "system", "controlDict") + """
application     canopyPimpleFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         0.02;
deltaT          0.01;
writeControl    timeStep;
writeInterval   1;
""")
    write(os.path.join(case, "system", "blockMeshDict"),
          FOAM_HEADER % ("dictionary", "system", "blockMeshDict") + """
scale 1;
vertices
(
    (%(x0)g %(y0)g %(z0)g) (%(x1)g %(y0)g %(z0)g)
    (%(x1)g %(y1)g %(z0)g) (%(x0)g %(y1)g %(z0)g)
    (%(x0)g %(y0)g %(z1)g) (%(x1)g %(y0)g %(z1)g)
    (%(x1)g %(y1)g %(z1)g) (%(x0)g %(y1)g %(z1)g)
);
blocks ( hex (0 1 2 3 4 5 6 7) (%(nx)d %(ny)d %(nz)d) simpleGrading (1 1 1) );
boundary
(
    walls
    {
        type wall;
        faces ((0 3 2 1) (4 5 6 7) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));
    }
);
""" % {"x0": X0, "x1": X1, "y0": Y0, "y1": Y1, "z0": Z0, "z1": Z1,
       "nx": NX, "ny": NY, "nz": NZ})
    run(["bash", "-c", '. "$1/bin/openfoam-env" && blockMesh -case "$2"',
         "_", ROOT, case], tmp)
    boundary = """
boundaryField
{
    walls
    {
        type            fixedValue;
        value           uniform (0 0 0);
    }
}
"""
    write(os.path.join(case, "0", "U"),
          FOAM_HEADER % ("volVectorField", "0", "U")
          + "dimensions [0 1 -1 0 0 0 0];\n"
          + "internalField uniform (0 0 0);\n" + boundary)
    cells = centres()
    values = "\n".join("(%.12g %.12g %.12g)" % velocity(c) for c in cells)
    write(os.path.join(case, "0.02", "U"),
          FOAM_HEADER % ("volVectorField", "0.02", "U")
          + "dimensions [0 1 -1 0 0 0 0];\n"
          + "internalField nonuniform List<vector>\n%d\n(\n%s\n)\n;\n"
          % (len(cells), values) + boundary)
    add_canopy(case, tmp)
    write_frame_series(case)


def frame_z(t):
    """The test's frame origin z [m]: the mesh follows a payload that has
    fallen 25 t m (canopy.dat rows at t = 0.01 and 0.02)."""
    return -25.0 * t


def write_frame_series(case):
    """canopy.dat in the solver's layout with moving frame columns."""
    path = os.path.join(case, "postProcessing", "canopy", "0", "canopy.dat")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("# canopyFoam time series of the canopy (ground frame)\n"
                "# nominalDiameter 2.134\n# totalMass 6.02\n# rho 1.2\n"
                "# gravity 0 0 -9.81\n"
                "# time payload_x payload_y payload_z payload_Ux payload_Uy"
                " payload_Uz force_x force_y force_z projected_diameter"
                " canopy_area kinetic spring gravity coupling_iterations"
                " residual slip substeps frame_x frame_y frame_z\n")
        for t in (0.01, 0.02):
            f.write(" ".join(["%g" % t] + ["0"] * 18
                             + ["0", "0", "%.17g" % frame_z(t)]) + "\n")


def add_canopy(case, tmp):
    demo = os.environ.get("CANOPY_DEMO") or os.path.join(
        ROOT, "build", "canopy", "bin", "canopyDropDemo")
    if not os.access(demo, os.X_OK):
        die("no demo program at %s (build with ./Allwmake, or set "
            "CANOPY_DEMO)" % demo, tmp)
    out = os.path.join(case, "postProcessing", "canopy")
    os.makedirs(out, exist_ok=True)
    run([demo, "-o", os.path.join(out, "canopy"), "-t", "0.02", "-h", "0.25",
         "-w", "0.01", "-q"], tmp)


def image_stats(png):
    """(width, height, fraction of pixels unlike the corner, colours)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    n = scalars.GetNumberOfTuples()
    background = scalars.GetTuple(0)
    drawn = 0
    colours = set()
    for i in range(0, n, 3):
        pixel = scalars.GetTuple(i)
        if pixel != background:
            drawn += 1
        colours.add(pixel[:3])
    return w, h, drawn / float((n + 2) // 3), len(colours)


def check_png(name, png, min_colours, min_drawn=0.01):
    if not check("%s written" % name, png is not None and
                 os.path.isfile(png), str(png)):
        return
    with open(png, "rb") as f:
        check("%s is a PNG" % name, f.read(8) == b"\x89PNG\r\n\x1a\n")
    w, h, drawn, colours = image_stats(png)
    check("%s content" % name,
          (w, h) == SIZE and drawn >= min_drawn and colours >= min_colours,
          "%d x %d pixels, %.1f %% drawn, %d colours (need %s, >= %g %%, "
          ">= %d)" % (w, h, 100 * drawn, colours, SIZE, 100 * min_drawn,
                      min_colours))


def slice_cell_arrays(proxy):
    """[(Ux, Uy, Uz)] of the slice's cells, and the point-data U count."""
    from paraview import servermanager as sm
    data = sm.Fetch(proxy)
    blocks = []

    def collect(d):
        if d is None:
            return
        if d.IsA("vtkMultiBlockDataSet"):
            for b in range(d.GetNumberOfBlocks()):
                collect(d.GetBlock(b))
        elif d.GetNumberOfCells() > 0:
            blocks.append(d)
    collect(data)
    cell_u, point_u = [], 0
    for d in blocks:
        a = d.GetCellData().GetArray("U")
        if a is not None and a.GetNumberOfComponents() == 3:
            cell_u += [a.GetTuple3(i) for i in range(a.GetNumberOfTuples())]
        p = d.GetPointData().GetArray("U")
        if p is not None and p.GetNumberOfComponents() == 3:
            point_u += p.GetNumberOfTuples()
    return cell_u, point_u


def test_full_case(tmp):
    from canopyfoam import render
    case = os.path.join(tmp, "case")
    make_case(case, tmp)

    # The scene, without drawing: times, slice position, the slice's U
    scene = render.build_scene(case, log=lambda s: print("  scene: " + s))
    check("latest field time", abs(scene.time - 0.02) < 1e-12
          and len(scene.field_times) == 2,
          "t = %g (times %s; expected 0.02 of [0, 0.02])"
          % (scene.time, scene.field_times))
    check("canopy time", abs(scene.canopy_time - 0.02) < 1e-12,
          "t = %g (write times %s)" % (scene.canopy_time,
                                       scene.canopy_times))
    check("case.foam created", os.path.isfile(os.path.join(case,
                                                           "case.foam")))
    check("slice origin at the canopy centre",
          abs(scene.origin[0]) < 0.05 and abs(scene.origin[1]) < 0.05,
          "origin (%.3g %.3g %.3g); the 7 ft canopy is centred on the z "
          "axis" % tuple(scene.origin))
    # the canopy in the mesh frame: the ground-frame structure moved by
    # -frame origin = +0.5 m in z at t = 0.02 (double precision: 1e-9)
    from paraview import simple
    reader = simple.FindSource("Xdmf3ReaderS1")
    reader.UpdatePipeline(scene.canopy_time)
    ground = reader.GetDataInformation().GetBounds()
    moved = scene.structure_bounds
    shift = -frame_z(0.02)
    check("canopy moved into the mesh frame",
          abs(moved[4] - (ground[4] + shift)) < 1e-9
          and abs(moved[5] - (ground[5] + shift)) < 1e-9
          and abs(moved[0] - ground[0]) < 1e-9,
          "z %.6f .. %.6f shown, %.6f .. %.6f written + %g"
          % (moved[4], moved[5], ground[4], ground[5], shift))
    cell_u, point_u = slice_cell_arrays(scene.slice)
    check("slice has U", len(cell_u) == NY * NZ and point_u > 0,
          "%d cells with cell U (expected %d x %d), %d points with point U"
          % (len(cell_u), NY, NZ, point_u))
    if cell_u:
        # the reader hands fields over in single precision: 1e-6 covers
        # the float32 rounding (6e-8 relative) of values of order 1
        ux = [u[0] for u in cell_u]
        check("slice cuts the cell column x = -0.1 .. 0.5",
              max(abs(x - 0.2) for x in ux) < 1e-6,
              "U_x from %.9g to %.9g (= the cut cells' x centre; expected "
              "0.2 +- 1e-6)" % (min(ux), max(ux)))
        dz = (Z1 - Z0) / NZ
        want = [2.0 + 0.5 * (Z0 + (k + 0.5) * dz) for k in range(NZ)]
        got = sorted(u[2] for u in cell_u)
        layers = [got[k * NY:(k + 1) * NY] for k in range(NZ)]
        check("slice U_z over the layers",
              len(got) == NY * NZ and all(
                  abs(v - w) < 1e-6 for layer, w in zip(layers, want)
                  for v in layer),
              "%s (expected %s, %d cells each, +- 1e-6)"
              % (sorted(set(round(v, 6) for v in got)), want, NY))

    # The pictures, by bin/canopy-render
    out = os.path.join(tmp, "report")
    rc, output = pv_run([os.path.join(ROOT, "bin", "canopy-render"), case,
                         "--out", out, "--size", str(SIZE[0]),
                         str(SIZE[1])])
    print("  " + output.strip().replace("\n", "\n  "))
    check("bin/canopy-render exits 0", rc == 0, "exit %d" % rc)
    # canopy: shading of the dp colours and lines; slice: a colour ramp.
    # The 3 x 4 m slice fills ~40 % of the frame (the structure alone
    # ~2-12 %): at least 20 % drawn shows that the slice is there.
    check_png("canopy.png", os.path.join(out, "canopy.png"), 20)
    check_png("velocitySlice.png", os.path.join(out, "velocitySlice.png"),
              50, 0.20)
    return case


def test_no_fields(tmp):
    """Only the canopy output: canopy.png alone, and a note saying so."""
    case = os.path.join(tmp, "nofields")
    add_canopy(case, tmp)
    tool = os.path.join(ROOT, "bin", "canopy-render")
    out = os.path.join(tmp, "report-nofields")
    rc, output = pv_run([tool, case, "--out", out, "--size", str(SIZE[0]),
                         str(SIZE[1])])
    print("  " + output.strip().replace("\n", "\n  "))
    check("bin/canopy-render without fields exits 0", rc == 0,
          "exit %d" % rc)
    check("without fields: canopy.png only",
          os.path.isfile(os.path.join(out, "canopy.png"))
          and not os.path.exists(os.path.join(out, "velocitySlice.png")),
          "files %s" % (sorted(os.listdir(out)) if os.path.isdir(out)
                        else "none"))
    check("without fields: says so", "no fields" in output)


GUI_DRIVER = """
import os
from paraview import simple
script = os.path.join(os.environ["CANOPYFOAM_DIR"], "etc", "paraview",
                      "canopyCase.py")
namespace = {"__name__": "__main__"}
with open(script) as f:
    exec(compile(f.read(), "canopyCase.py", "exec"), namespace)
print("SOURCES " + "|".join(sorted(n for n, _ in simple.GetSources())))
scene = namespace["canopyScene"]
print("SLICE " + str(scene.slice is not None))
# the canopy shown at the view's time must be the last write, not the one
# before it (the write times carry round-off: 0.02000000000000001)
t = simple.GetTimeKeeper().Time
scene.lines.UpdatePipeline(t)
shown = scene.lines.GetDataInformation().GetBounds()   # down to the payload
reader = simple.FindSource("Xdmf3ReaderS1")
bounds = []
for tc in scene.canopy_times[-2:]:
    reader.UpdatePipeline(tc)
    bounds.append(reader.GetDataInformation().GetBounds())
print("CANOPYTIME %r %r %r %r" % (t, shown[4], bounds[1][4] + 0.5,
                                  bounds[0][4] + 0.25))
simple.SaveScreenshot(os.environ["CANOPY_TEST_PNG"], simple.GetActiveView(),
                      ImageResolution=[WIDTH, HEIGHT])
""".replace("WIDTH", str(SIZE[0])).replace("HEIGHT", str(SIZE[1]))


def test_gui_script(tmp, case):
    """canopyCase.py as paraview --script runs it: no __file__, the case
    from CANOPY_CASE, the repository from CANOPYFOAM_DIR."""
    driver = os.path.join(tmp, "gui_driver.py")
    png = os.path.join(tmp, "gui.png")
    with open(driver, "w") as f:
        f.write(GUI_DRIVER)
    env = dict(os.environ, CANOPY_CASE=case, CANOPYFOAM_DIR=ROOT,
               CANOPY_TEST_PNG=png)
    # on a display of its own, as bin/canopy-render draws (bin/canopy-xrun
    # starts an Xvfb for it and retries a start that loses the connection)
    rc, output = pv_run([os.path.join(ROOT, "bin", "canopy-xrun"),
                         "pvbatch", driver], env=env)
    lines = [l for l in output.splitlines()
             if l.startswith(("canopyCase.py", "SOURCES", "SLICE",
                              "CANOPYTIME"))]
    print("  " + "\n  ".join(lines))
    names = []
    for line in lines:
        if line.startswith("SOURCES "):
            names = line[len("SOURCES "):].split("|")
    want = ["canopy profile on the slice", "canopy surface",
            "suspension lines", "velocity slice (x = 0)"]
    check("canopyCase.py pipeline", rc == 0 and all(n in names for n in want)
          and "SLICE True" in output,
          "exit %d, sources %s" % (rc, names))
    # (+0.5 and +0.25 m: minus the frame origins at the two writes)
    shown = [l.split()[1:] for l in lines if l.startswith("CANOPYTIME ")]
    if check("canopyCase.py canopy time", len(shown) == 1,
             "the driver printed %d CANOPYTIME line(s)" % len(shown)):
        t, z, z_last, z_before = (float(x) for x in shown[0])
        check("canopyCase.py shows the last canopy write at t = %g" % t,
              # single precision after the extract filter: 1e-6; the
              # payload falls 1.5e-3 m between the two writes
              abs(z - z_last) < 1e-6 and abs(z - z_before) > 1e-4,
              "lowest line point z = %r shown, %r at the last write, %r at "
              "the one before, both in the mesh frame"
              % (z, z_last, z_before))
    # the slice, seen at an angle, fills ~30 % of this view
    check_png("canopyCase.py view", png, 50, 0.15)


def main():
    start = time.time()
    tmp = tempfile.mkdtemp(prefix="canopy-render-")
    try:
        case = test_full_case(tmp)
        test_no_fields(tmp)
        test_gui_script(tmp, case)
    except SystemExit:
        raise
    except Exception as e:
        import traceback
        traceback.print_exc()
        failures.append("exception: %s" % e)
    elapsed = time.time() - start
    # the time is a figure for the log, not a check: speed belongs to the
    # benchmarks, and Alltest's time limit catches a hang
    print("  render checks took %.1f s" % elapsed)
    if failures:
        print("FAIL: %d check(s) failed: %s; files kept in %s"
              % (len(failures), ", ".join(failures), tmp))
        sys.exit(1)
    shutil.rmtree(tmp, ignore_errors=True)
    print("PASS: render checks")


if __name__ == "__main__":
    main()
