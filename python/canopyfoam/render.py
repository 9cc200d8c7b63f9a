"""render.py — ParaView pictures of a canopyFoam case (canopy.png, velocitySlice.png) and the scene set-up that etc/paraview/canopyCase.py shares.

canopy.png: the canopy coloured by its pressure jump, lines drawn;
velocitySlice.png: |U| on a slice through the payload axis, the canopy
drawn over it.

Run by bin/canopy-render as  bin/canopy-xrun pvbatch render.py <caseDir> [options];
also importable from pvpython/pvbatch/the ParaView GUI (needs paraview.simple).

What it opens:
- <caseDir>/case.foam (created empty when missing) with ParaView's
  OpenFOAMReader: the internal mesh, cell fields U (and p, canopyForce when
  written), the 0 directory included; a decomposed case (processor*/ only)
  is read as such;
- <caseDir>/postProcessing/canopy/canopy.xdmf with the Xdmf3ReaderS reader:
  the structure's triangles and line cells, point data `velocity`, cell
  data `cell_dp` and `cell_tension`.
Time: the latest field time, or the one at or before --time; the canopy
is shown at its write time nearest that (they coincide in a normal run).
The slice is the plane normal to x through the centre of the canopy's
bounding box, which holds the payload axis of a symmetric canopy. "Up" is
-gravity from constant/canopyProperties (else canopy.dat's header, else +z).
A case without fields gets canopy.png only; a case without canopy.xdmf
gets velocitySlice.png only (sliced through the mesh centre); both say so.
Frame: the structure is written in the ground frame; when the mesh follows
the payload (canopy.dat has frame_x frame_y frame_z columns that move), the
canopy is drawn moved by minus the frame's origin at its time, so that it
sits where the solver put its markers.
"""

import argparse
import math
import os
import re
import sys

CANOPY_XDMF = os.path.join("postProcessing", "canopy", "canopy.xdmf")
FIELD_NAMES = ("U", "p", "canopyForce")
LINE_TYPES = ("Line", "Polyline")
SURFACE_TYPES = ("Triangle", "Polygon", "Quadrilateral")


class RenderError(Exception):
    """Nothing to render, or a file that cannot be read."""


# ---- what the case holds (no ParaView needed) ------------------------------

def _is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def field_times(directory):
    """Sorted times of the time directories of `directory` that hold U."""
    times = []
    if os.path.isdir(directory):
        for name in os.listdir(directory):
            if _is_time(name) and (
                    os.path.isfile(os.path.join(directory, name, "U"))
                    or os.path.isfile(os.path.join(directory, name, "U.gz"))):
                times.append(float(name))
    return sorted(times)


def has_mesh(directory):
    mesh = os.path.join(directory, "constant", "polyMesh")
    return any(os.path.isfile(os.path.join(mesh, f))
               for f in ("faces", "faces.gz"))


def case_type(case):
    """'Reconstructed Case', 'Decomposed Case' or None (no fields to read):
    the one with the latest field time (reconstructed on a tie)."""
    whole = field_times(case) if has_mesh(case) else []
    proc = os.path.join(case, "processor0")
    parts = field_times(proc) if has_mesh(proc) else []
    if parts and (not whole or parts[-1] > whole[-1]):
        return "Decomposed Case"
    if whole:
        return "Reconstructed Case"
    return None


def ensure_foam_file(case):
    """<case>/case.foam, created empty if missing (what OpenFOAMReader
    opens)."""
    path = os.path.join(os.path.abspath(case), "case.foam")
    if not os.path.exists(path):
        open(path, "a").close()
    return path


def _gravity_from_properties(case):
    path = os.path.join(case, "constant", "canopyProperties")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        text = re.sub(r"//[^\n]*|/\*.*?\*/", "", f.read(), flags=re.S)
    m = re.search(r"(?m)^\s*gravity\s+\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)\s*;",
                  text)
    if not m:
        return None
    try:
        return [float(x) for x in m.groups()]
    except ValueError:
        return None


def _gravity_from_series(case):
    base = os.path.join(case, "postProcessing", "canopy")
    if not os.path.isdir(base):
        return None
    for name in sorted((n for n in os.listdir(base) if _is_time(n)),
                       key=float, reverse=True):
        path = os.path.join(base, name, "canopy.dat")
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            for line in f:
                if not line.startswith("#"):
                    break
                tokens = line[1:].split()
                if len(tokens) == 4 and tokens[0] == "gravity":
                    try:
                        return [float(x) for x in tokens[1:]]
                    except ValueError:
                        return None
    return None


def up_direction(case, up=None):
    """Unit 'up' vector: the given one, or -gravity of the case, or +z."""
    if up is None:
        g = _gravity_from_properties(case) or _gravity_from_series(case)
        up = [-x for x in g] if g else [0.0, 0.0, 1.0]
    norm = math.sqrt(sum(x * x for x in up))
    if norm == 0.0:
        return [0.0, 0.0, 1.0]
    return [x / norm for x in up]


def pick_time(times, wanted=None):
    """The latest time, or the last one at or before `wanted` (the first
    if all are after it)."""
    if not times:
        return None
    if wanted is None:
        return times[-1]
    tol = 1e-9 * max(1.0, abs(wanted))
    before = [t for t in times if t <= wanted + tol]
    return before[-1] if before else times[0]


def nearest_time(times, wanted):
    return min(times, key=lambda t: abs(t - wanted)) if times else None


def frame_table(case):
    """[(t, (x, y, z))] of the mesh frame's origin in the ground frame, from
    the frame_x frame_y frame_z columns of postProcessing/canopy/*/
    canopy.dat (restarts: a later file replaces the rows from its first
    time on); [] when there are no such columns or the origin never moves
    (a fixed frame)."""
    base = os.path.join(case, "postProcessing", "canopy")
    if not os.path.isdir(base):
        return []
    table = []
    for name in sorted((n for n in os.listdir(base) if _is_time(n)),
                       key=float):
        path = os.path.join(base, name, "canopy.dat")
        if not os.path.isfile(path):
            continue
        rows, index = [], None
        with open(path) as f:
            for line in f:
                tokens = line.split()
                if not tokens:
                    continue
                if tokens[0] == "#":
                    if len(tokens) > 1 and tokens[1] == "time" and \
                            "frame_x" in tokens:
                        names = tokens[1:]
                        index = [names.index(c) for c in
                                 ("time", "frame_x", "frame_y", "frame_z")]
                        width = len(names)
                    continue
                if index is None or len(tokens) != width:
                    continue
                try:
                    t, x, y, z = (float(tokens[i]) for i in index)
                except ValueError:
                    continue
                rows.append((t, (x, y, z)))
        if rows:
            first = rows[0][0]
            table = [r for r in table
                     if r[0] < first - 1e-9 * max(1.0, abs(first))] + rows
    if all(o == (0.0, 0.0, 0.0) for _, o in table):
        return []
    return table


def frame_origin(table, t):
    """The frame origin of the table entry nearest t ((0, 0, 0) if none)."""
    if not table:
        return (0.0, 0.0, 0.0)
    return min(table, key=lambda row: abs(row[0] - t))[1]


# The canopy in the mesh's frame at the data's time, for the GUI, whose
# animation steps through the times: each point minus the frame origin.
# (The filter runs its script among numpy_interface.algorithms' names, whose
# min and sum are not the builtins: hence builtins.min.)
_TO_MESH_FRAME = """
import builtins
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

table = TABLE
inp = self.GetInputDataObject(0, 0)
out = self.GetOutputDataObject(0)
info = inp.GetInformation()
t = (info.Get(vtkDataObject.DATA_TIME_STEP())
     if info.Has(vtkDataObject.DATA_TIME_STEP()) else table[-1][0])
origin = builtins.min(table, key=lambda row: abs(row[0] - t))[1]


def shift(src, dst):
    dst.ShallowCopy(src)
    if src.GetPoints() is None:
        return
    x = vtk_to_numpy(src.GetPoints().GetData()).astype(float)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(x - origin, deep=1))
    dst.SetPoints(points)


if inp.IsA("vtkCompositeDataSet"):
    out.CopyStructure(inp)
    it = inp.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        block = it.GetCurrentDataObject()
        moved = block.NewInstance()
        shift(block, moved)
        out.SetDataSet(it, moved)
        it.GoToNextItem()
else:
    shift(inp, out)
"""


# ---- vector helpers --------------------------------------------------------

def _add(a, b, s=1.0):
    return [x + s * y for x, y in zip(a, b)]


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _unit(a):
    n = math.sqrt(_dot(a, a))
    return [x / n for x in a] if n > 0 else a


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def _centre(bounds):
    return [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
            0.5 * (bounds[4] + bounds[5])]


def _diagonal(bounds):
    return math.sqrt(sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2
                         for i in range(3)))


def _valid(bounds):
    return bounds is not None and bounds[0] <= bounds[1]


# ---- the ParaView scene ----------------------------------------------------

class Scene(object):
    """Readers and filters of a case; see build_scene."""

    def __init__(self):
        self.case = None
        self.fields = None          # OpenFOAMReader (or None)
        self.canopy = None          # the Xdmf3ReaderS, time-pinned or -shifted
        self.surface = None         # canopy triangles
        self.lines = None           # suspension lines
        self.slice = None           # slice of the fields (or None)
        self.profile = None         # the canopy cut by the slice plane
        self.time = None            # the fields' time shown
        self.canopy_time = None
        self.field_times = []
        self.canopy_times = []
        self.origin = None          # slice origin (canopy centre)
        self.size = 1.0             # length scale of what is shown
        self.structure_bounds = None
        self.up = [0.0, 0.0, 1.0]
        self.frame = []             # frame_table(): [] for a fixed frame
        self.notes = []


def _times_of(reader):
    values = reader.TimestepValues
    if values is None:
        return []
    try:
        return sorted(float(t) for t in values)
    except TypeError:
        return [float(values)]


def build_scene(case, time=None, up=None, pin_canopy_time=True, log=print):
    """Open the case's fields and canopy and build the filters (no views).

    pin_canopy_time: show the canopy at its chosen write time whatever the
    view's time (a ForceTime filter), as pictures want; the GUI script
    leaves it free so that the canopy follows the animation time.
    Raises RenderError when there is neither a field nor a canopy.
    """
    from paraview import simple

    scene = Scene()
    case = os.path.abspath(case)
    scene.case = case
    scene.up = up_direction(case, up)
    if not os.path.isdir(case):
        raise RenderError("no case directory %s" % case)

    # Fields
    kind = case_type(case)
    if kind is None:
        scene.notes.append("no fields yet (no mesh with a time directory "
                           "holding U): the velocity slice is left out")
    else:
        foam = ensure_foam_file(case)
        reader = simple.OpenFOAMReader(FileName=foam, CaseType=kind,
                                       SkipZeroTime=0)
        # the time list of a reconstructed case is made on opening, with
        # the default SkipZeroTime on: reload to list 0 too
        simple.ReloadFiles(reader)
        reader.MeshRegions = ["internalMesh"]
        reader.UpdatePipelineInformation()
        available = list(reader.GetProperty("CellArrayInfo")[::2])
        reader.CellArrays = [n for n in FIELD_NAMES if n in available]
        reader.Createcelltopointfiltereddata = 1
        reader.UpdatePipelineInformation()
        scene.fields = reader
        scene.field_times = _times_of(reader)
        scene.time = pick_time(scene.field_times, time)
        if scene.time is None:
            scene.time = 0.0
        log("fields: %s (%s), times %s, showing t = %g"
            % (foam, kind, _short(scene.field_times), scene.time))

    # Canopy
    xdmf = os.path.join(case, CANOPY_XDMF)
    if not os.path.isfile(xdmf):
        scene.notes.append("no %s: the canopy is left out" % CANOPY_XDMF)
    else:
        reader = simple.Xdmf3ReaderS(FileName=[xdmf])
        reader.UpdatePipelineInformation()
        scene.canopy_times = _times_of(reader)
        if scene.time is not None:
            scene.canopy_time = nearest_time(scene.canopy_times, scene.time)
        else:
            scene.canopy_time = pick_time(scene.canopy_times, time)
        if scene.canopy_time is None:
            scene.canopy_time = 0.0
        source = reader
        if pin_canopy_time:
            source = simple.ForceTime(Input=reader,
                                      ForcedTime=scene.canopy_time,
                                      IgnorePipelineTime=1)
        elif scene.fields is not None:
            # The reader shows the step at or before the asked time, and
            # the structure's write times carry round-off (0.06 is written
            # 0.06000000000000004): asked 0.06 by the fields' time, it would
            # show the step before. Shift its times down by a thousandth of
            # the write interval and let the fields alone set the steps.
            steps = [b - a for a, b in zip(scene.canopy_times[:-1],
                                           scene.canopy_times[1:])]
            delta = (1e-3 * min(steps) if steps
                     else 1e-9 * max(1.0, abs(scene.canopy_time)))
            source = simple.TemporalShiftScale(Input=reader,
                                               PostShift=-delta)
            keeper = simple.GetTimeKeeper()
            keeper.SuppressedTimeSources.append(source)
            keeper.SuppressedTimeSources.append(reader)
        log("canopy: %s, %d write time(s), showing t = %g"
            % (xdmf, len(scene.canopy_times), scene.canopy_time))
        scene.frame = frame_table(case)
        if scene.frame and pin_canopy_time:
            # the structure is written in the ground frame, the mesh
            # follows the payload: move the canopy into the mesh's frame
            source = simple.Transform(Input=source)
            source.Transform = "Transform"
            source.Transform.Translate = [
                -x for x in frame_origin(scene.frame, scene.canopy_time)]
        elif scene.frame:
            # the same at whatever time the animation shows (ParaView runs
            # the filter's script in __main__, whose min, max, sum ... it
            # replaces with numpy_interface's: fine in the GUI)
            source = simple.ProgrammableFilter(Input=source)
            source.Script = _TO_MESH_FRAME.replace(
                "TABLE", repr([(t, list(o)) for t, o in scene.frame]))
            source.CopyArrays = 0
        if scene.frame:
            log("frame: the mesh follows the payload; the canopy is moved "
                "by -(%s) m at t = %g, the frame's origin in canopy.dat"
                % (" ".join("%.4g" % x for x in
                            frame_origin(scene.frame, scene.canopy_time)),
                   scene.canopy_time))
        scene.canopy = source
        scene.surface = simple.ExtractCellsByType(Input=source)
        scene.surface.CellTypes = list(SURFACE_TYPES)
        scene.lines = simple.ExtractCellsByType(Input=source)
        scene.lines.CellTypes = list(LINE_TYPES)
        if scene.time is not None and abs(scene.canopy_time - scene.time) > \
                1e-6 * max(1.0, abs(scene.time)):
            scene.notes.append("the canopy is shown at t = %g, its write "
                               "time nearest the fields' t = %g"
                               % (scene.canopy_time, scene.time))

    if scene.fields is None and scene.canopy is None:
        raise RenderError("%s holds neither fields nor %s: nothing to render"
                          % (case, CANOPY_XDMF))

    # Where to look and slice
    t_show = scene.time if scene.time is not None else scene.canopy_time
    if scene.canopy is not None:
        scene.surface.UpdatePipeline(t_show)
        scene.lines.UpdatePipeline(t_show)
        canopy_bounds = scene.surface.GetDataInformation().GetBounds()
        all_bounds = scene.canopy.GetDataInformation().GetBounds()
        if not _valid(all_bounds):
            all_bounds = None
        if not _valid(canopy_bounds):
            canopy_bounds = all_bounds
        if not _valid(canopy_bounds):
            raise RenderError("%s holds no cells at t = %g"
                              % (xdmf, scene.canopy_time))
        scene.origin = _centre(canopy_bounds)
        scene.structure_bounds = all_bounds or canopy_bounds
        scene.size = max(_diagonal(scene.structure_bounds), 1e-6)
    else:
        scene.fields.UpdatePipeline(t_show)
        mesh_bounds = scene.fields.GetDataInformation().GetBounds()
        scene.origin = _centre(mesh_bounds)
        scene.size = max(_diagonal(mesh_bounds), 1e-6)

    if scene.fields is not None:
        scene.slice = simple.Slice(Input=scene.fields)
        scene.slice.SliceType = "Plane"
        scene.slice.SliceType.Origin = scene.origin
        scene.slice.SliceType.Normal = [1.0, 0.0, 0.0]
        try:  # ParaView >= 5.10: no triangulation, keeps the cells' shape
            scene.slice.Triangulatetheslice = 0
        except AttributeError:
            pass
        scene.slice.UpdatePipeline(scene.time)
        if scene.canopy is not None:
            scene.profile = simple.Slice(Input=scene.surface)
            scene.profile.SliceType = "Plane"
            scene.profile.SliceType.Origin = scene.origin
            scene.profile.SliceType.Normal = [1.0, 0.0, 0.0]
    return scene


def _short(times):
    if len(times) <= 4:
        return "[%s]" % ", ".join("%g" % t for t in times)
    return "[%g, %g, ... %g] (%d)" % (times[0], times[1], times[-1],
                                      len(times))


def _array_range(source, association, name, time):
    source.UpdatePipeline(time)
    info = source.GetDataInformation()
    arrays = (info.GetCellDataInformation() if association == "CELLS"
              else info.GetPointDataInformation())
    array = arrays.GetArrayInformation(name)
    if array is None:
        return None
    return array.GetComponentRange(-1 if array.GetNumberOfComponents() > 1
                                   else 0)


def _white_view(size, view=None):
    from paraview import simple
    if view is None:
        view = simple.CreateView("RenderView")
    view.ViewSize = list(size)
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView 5.11: the palette's background unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 1
    return view


def _bar(simple, lut, view, title, corner):
    bar = simple.GetScalarBar(lut, view)
    bar.WindowLocation = corner
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0.1, 0.1, 0.1]
    bar.LabelColor = [0.1, 0.1, 0.1]
    bar.Visibility = 1
    return bar


def show_canopy(scene, view, opacity=1.0, bar=True):
    """The canopy coloured by cell_dp (symmetric diverging map), the lines
    dark; returns the two displays."""
    from paraview import simple
    t = scene.time if scene.time is not None else scene.canopy_time
    surface = simple.Show(scene.surface, view)
    surface.Opacity = opacity
    surface.Ambient = 0.2           # a canopy seen edge-on stays readable
    surface.Diffuse = 0.85
    rng = _array_range(scene.surface, "CELLS", "cell_dp", t)
    if rng is not None:
        simple.ColorBy(surface, ("CELLS", "cell_dp"))
        lut = simple.GetColorTransferFunction("cell_dp")
        lut.ApplyPreset("Cool to Warm", True)
        top = max(abs(rng[0]), abs(rng[1]), 1e-12)
        lut.RescaleTransferFunction(-top, top)
        lut.AutomaticRescaleRangeMode = "Never"
        if bar:
            _bar(simple, lut, view, "pressure jump cell_dp",
                 "Upper Right Corner")
    else:
        simple.ColorBy(surface, None)
        surface.AmbientColor = surface.DiffuseColor = [0.85, 0.85, 0.85]
        scene.notes.append("the canopy has no cell_dp array: drawn grey")
    lines = simple.Show(scene.lines, view)
    simple.ColorBy(lines, None)
    lines.AmbientColor = lines.DiffuseColor = [0.15, 0.15, 0.15]
    lines.LineWidth = 2.0
    return surface, lines


def show_slice(scene, view, bar=True):
    """|U| on the slice (point data, interpolated from the cells)."""
    from paraview import simple
    display = simple.Show(scene.slice, view)
    simple.ColorBy(display, ("POINTS", "U", "Magnitude"))
    lut = simple.GetColorTransferFunction("U")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    rng = _array_range(scene.slice, "POINTS", "U", scene.time)
    if rng is not None and rng[1] > rng[0]:
        lut.RescaleTransferFunction(rng[0], rng[1])
    lut.AutomaticRescaleRangeMode = "Never"
    if bar:
        _bar(simple, lut, view, "U magnitude [m/s]", "Lower Right Corner")
    return display


def _frame(scene):
    """(up, across, toward-camera-for-the-slice) unit vectors."""
    up = scene.up
    normal = [1.0, 0.0, 0.0]
    if abs(_dot(up, normal)) > 0.99:        # gravity along x: odd but legal
        up = [0.0, 0.0, 1.0]
    up = _unit(_add(up, normal, -_dot(up, normal)))   # in the slice plane
    across = _cross(up, normal)
    return up, across, normal


def slice_frame(scene):
    """The structure's bounds with half its size of air around, within the
    slice's bounds (None without a canopy)."""
    b = scene.structure_bounds
    if not _valid(b):
        return None
    pad = 0.5 * scene.size
    bounds = [b[0] - pad, b[1] + pad, b[2] - pad, b[3] + pad,
              b[4] - pad, b[5] + pad]
    mesh = (scene.slice.GetDataInformation().GetBounds()
            if scene.slice is not None else None)
    if _valid(mesh):
        for i in range(0, 6, 2):
            bounds[i] = max(bounds[i], mesh[i])
            bounds[i + 1] = min(bounds[i + 1], mesh[i + 1])
            if bounds[i] > bounds[i + 1]:
                bounds[i], bounds[i + 1] = mesh[i], mesh[i + 1]
    return bounds


def slice_camera(scene, view, bounds=None):
    """Look at the slice face-on, from +x, up along -gravity, framing
    `bounds` (default: everything shown)."""
    up, _, normal = _frame(scene)
    focal = _centre(bounds) if _valid(bounds) else list(scene.origin)
    focal[0] = scene.origin[0]
    view.CameraFocalPoint = focal
    view.CameraPosition = _add(focal, normal, 3.0 * scene.size)
    view.CameraViewUp = up
    view.CameraParallelProjection = 1
    view.ResetCamera(False)
    if _valid(bounds):
        # parallel projection: half the visible height is the scale; fit
        # the bounds' extent along up and across, 20 % margin (the title)
        _, across, _ = _frame(scene)
        corners = [[bounds[i], bounds[2 + j], bounds[4 + k]]
                   for i in (0, 1) for j in (0, 1) for k in (0, 1)]
        height = max(_dot(c, up) for c in corners) - \
            min(_dot(c, up) for c in corners)
        width = max(_dot(c, across) for c in corners) - \
            min(_dot(c, across) for c in corners)
        w, h = view.ViewSize
        aspect = float(w) / max(h, 1)
        view.CameraParallelScale = 0.6 * max(height, width / aspect)


def canopy_camera(scene, view):
    """An oblique view from the side, 25 degrees above the horizontal."""
    up, across, normal = _frame(scene)
    bounds = scene.structure_bounds
    focal = _centre(bounds) if _valid(bounds) else scene.origin
    horizontal = _unit(_add([0.55 * x for x in normal], across, -0.85))
    elevation = math.radians(25.0)
    direction = _add([math.cos(elevation) * x for x in horizontal], up,
                     math.sin(elevation))
    view.CameraFocalPoint = focal
    view.CameraPosition = _add(focal, direction, 3.0 * scene.size)
    view.CameraViewUp = up
    view.CameraParallelProjection = 0
    view.ResetCamera(False)


def _title(simple, view, text):
    label = simple.Text(Text=text)
    display = simple.Show(label, view)
    display.Color = [0.1, 0.1, 0.1]
    display.FontSize = 14
    display.WindowLocation = "Upper Left Corner"
    return label


def render_case(case, out=None, time=None, size=(1200, 900), up=None,
                log=print):
    """Write canopy.png and velocitySlice.png (what can be drawn) into out
    (default <case>/postProcessing/report). Returns a dict: scene,
    canopy_png, slice_png (None when not drawn), notes."""
    from paraview import simple

    scene = build_scene(case, time=time, up=up, log=log)
    out = out or os.path.join(scene.case, "postProcessing", "report")
    os.makedirs(out, exist_ok=True)
    name = os.path.basename(scene.case)
    result = {"scene": scene, "canopy_png": None, "slice_png": None,
              "notes": scene.notes, "out": out}

    if scene.canopy is not None:
        view = _white_view(size)
        view.ViewTime = scene.canopy_time
        show_canopy(scene, view)
        canopy_camera(scene, view)
        _title(simple, view, "%s: canopy at t = %g s" % (name,
                                                         scene.canopy_time))
        simple.Render(view)
        path = os.path.join(out, "canopy.png")
        simple.SaveScreenshot(path, view, ImageResolution=list(size))
        result["canopy_png"] = path
        log("wrote %s" % path)
        simple.Delete(view)

    if scene.slice is not None:
        view = _white_view(size)
        view.ViewTime = scene.time
        show_slice(scene, view)
        bounds = None
        if scene.canopy is not None:
            surface, lines = show_canopy(scene, view, opacity=0.25,
                                         bar=False)
            simple.ColorBy(surface, None)
            surface.AmbientColor = surface.DiffuseColor = [1.0, 1.0, 1.0]
            profile = simple.Show(scene.profile, view)
            simple.ColorBy(profile, None)
            profile.AmbientColor = profile.DiffuseColor = [0.0, 0.0, 0.0]
            profile.LineWidth = 3.0
            lines.AmbientColor = lines.DiffuseColor = [0.3, 0.3, 0.3]
            bounds = slice_frame(scene)
        slice_camera(scene, view, bounds)
        _title(simple, view, "%s: velocity magnitude on the plane x = %.4g m, "
               "t = %g s%s"
               % (name, scene.origin[0], scene.time,
                  " (mesh frame, following the payload)" if scene.frame
                  else ""))
        simple.Render(view)
        path = os.path.join(out, "velocitySlice.png")
        simple.SaveScreenshot(path, view, ImageResolution=list(size))
        result["slice_png"] = path
        log("wrote %s" % path)
        simple.Delete(view)

    for note in scene.notes:
        log("note: %s" % note)
    return result


def show_case(case, view=None, time=None, log=print):
    """The interactive set-up (etc/paraview/canopyCase.py): in one view the
    velocity slice and the canopy by pressure jump with its lines, an
    oblique camera, the latest field time. The canopy is not pinned to a
    time, so it follows the animation controls. Returns the Scene."""
    from paraview import simple

    scene = build_scene(case, time=time, pin_canopy_time=False, log=log)
    if view is None:
        view = simple.GetActiveViewOrCreate("RenderView")
    if scene.fields is not None:
        simple.RenameSource("velocity slice (x = %.4g)" % scene.origin[0],
                            scene.slice)
        show_slice(scene, view)
    if scene.canopy is not None:
        simple.RenameSource("canopy surface", scene.surface)
        simple.RenameSource("suspension lines", scene.lines)
        if scene.profile is not None:
            simple.RenameSource("canopy profile on the slice", scene.profile)
        show_canopy(scene, view)
    if scene.slice is not None:
        # the slice face-on around the canopy, then turned a little
        bounds = slice_frame(scene)
        slice_camera(scene, view, bounds)
        view.CameraParallelProjection = 0
        if _valid(bounds):
            view.ResetCamera(*bounds)
        camera = simple.GetActiveCamera()
        camera.Azimuth(-30.0)
        camera.Elevation(15.0)
    else:
        canopy_camera(scene, view)
    t = scene.time if scene.time is not None else scene.canopy_time
    # The time keeper, not the animation scene: in the GUI, a script run
    # by --script that moves the animation scene hangs (ParaView 5.11)
    simple.GetTimeKeeper().Time = t
    view.ViewTime = t
    simple.SetActiveView(view)
    # no slice-plane widget over the picture: activate a source without one
    for proxy in (scene.profile, scene.slice):
        if proxy is not None and hasattr(simple, "Hide3DWidgets"):
            simple.Hide3DWidgets(proxy=proxy)
    simple.SetActiveSource(scene.surface if scene.surface is not None
                           else scene.fields)
    simple.Render(view)
    for note in scene.notes:
        log("note: %s" % note)
    return scene


def quiet_vtk_log():
    """Only VTK warnings and errors on stderr (the OpenFOAM reader's INFO
    lines about list formats are noise here)."""
    try:
        from vtkmodules.vtkCommonCore import vtkLogger
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
    except ImportError:
        pass


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="canopy-render",
        description="Render canopy.png (the canopy coloured by its pressure "
                    "jump, lines drawn) and velocitySlice.png (|U| on the "
                    "plane normal to x through the canopy centre, canopy "
                    "over it) of a canopyFoam case.")
    p.add_argument("case", metavar="caseDir")
    p.add_argument("--out", metavar="DIR",
                   help="output directory (default "
                        "<caseDir>/postProcessing/report)")
    p.add_argument("--time", type=float, metavar="T",
                   help="the field time at or before T (default: latest)")
    p.add_argument("--size", type=int, nargs=2, default=[1200, 900],
                   metavar=("W", "H"), help="image size (default 1200 900)")
    p.add_argument("--up", type=float, nargs=3, metavar=("X", "Y", "Z"),
                   help="up direction (default -gravity of the case, or z)")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    quiet_vtk_log()
    try:
        result = render_case(args.case, args.out, args.time,
                             tuple(args.size), args.up,
                             log=lambda s: print("canopy-render: " + s))
    except RenderError as e:
        sys.stderr.write("canopy-render: error: %s\n" % e)
        return 1
    return 0 if (result["canopy_png"] or result["slice_png"]) else 1


if __name__ == "__main__":
    # Run from the imported module, not from __main__, whose names
    # ParaView's programmable filters overwrite (min, sum, ...)
    sys.path.insert(0, os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    from canopyfoam import render as _render
    sys.exit(_render.main())
