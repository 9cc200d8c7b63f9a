"""mesh.py — the parachute cases' mesh from system/canopyMeshDict: a wide box in nominal diameters with nested refinement levels around the canopy (blockMesh, then topoSet + refineMesh per level).

system/canopyMeshDict (every length in nominal diameters D0, measured from
the canopy's centre, constant/canopyProperties canopy.centre, which is the
origin of the mesh frame):

    D0                2.134;  // nominal diameter [m]
    cellsPerDiameter  14;     // cells across D0 in the finest level
    edgeLengthPerCell 1.25;   // the canopy's fabric edge in finest cells
    domain
    {
        width       8;        // lateral extent, x and y, centred
        upstream    4;        // from the centre down to the inlet (zMin)
        downstream  10;       // from the centre up to the outlet (zMax)
    }
    refinement                // nested boxes, outermost first; each level
    (                         // halves the cell size of the one before
        { halfWidth 2.5; below 2.5; above 7; }
        { halfWidth 1.5; below 1.5; above 4; }
        { halfWidth 0.9; below 0.9; above 2.2; }
    );

The finest cell is h = D0 / cellsPerDiameter and the box's cell
h0 = h * 2^levels. The box's extents and every refinement box are rounded
outwards to whole cells of the level they refine, so that each level is a
uniform block of cells, and a refinement box is clipped to the domain (a
narrow domain's levels reach its sides). Where a box does not reach the
domain's boundary it must lie inside the one before it with at least one
cell of that one's level to spare, so that neighbouring cells differ by at
most a factor 2.

make() writes system/blockMeshDict.run, system/topoSetDict.level<i> and
system/refineMeshDict.run, runs blockMesh, then topoSet and refineMesh
-overwrite per level (logs log.blockMesh, log.topoSet.level<i>,
log.refineMesh.level<i>), and sets canopy.edgeLength in
constant/canopyProperties to edgeLengthPerCell * h. Bad entries raise
MeshError naming the entry.
"""

import math
import os
import subprocess

# Patch names the tutorials' 0.orig and coupling.frame.inletPatches use.
PATCHES = ("inlet", "outlet", "sides")


class MeshError(Exception):
    """A bad system/canopyMeshDict entry or a failed meshing step."""


def _value(case, dict_path, entry):
    """The entry's value as text (foamDictionary -value), or None when the
    dictionary has no such entry."""
    try:
        result = subprocess.run(
            # (scoped with '/', which both OpenFOAM flavours read)
            ["foamDictionary", "-entry", entry.replace(".", "/"), "-value",
             os.path.join(case, dict_path)],
            capture_output=True, text=True, check=False)
    except FileNotFoundError:
        raise MeshError("foamDictionary not found: source bin/openfoam-env "
                        "first") from None
    if result.returncode != 0:
        if "Cannot find entry" in result.stdout + result.stderr:
            return None
        raise MeshError(f"foamDictionary cannot read {dict_path} (is "
                        "bin/openfoam-env sourced?): "
                        + " ".join((result.stdout + result.stderr).split())[:300])
    return result.stdout.strip()


def _positive(case, dict_path, entry, default=None):
    text = _value(case, dict_path, entry)
    if text is None:
        if default is not None:
            return default
        raise MeshError(f"{dict_path}: entry '{entry}' is missing")
    try:
        value = float(text)
    except ValueError:
        raise MeshError(f"{dict_path}: entry '{entry}' = '{text}' is not a "
                        "number") from None
    if not (value > 0 and math.isfinite(value)):
        raise MeshError(f"{dict_path}: entry '{entry}' = {text} must be a "
                        "finite number > 0")
    return value


class Spec:
    """What system/canopyMeshDict asks for, with the derived cell sizes."""

    def __init__(self, case, cells_per_diameter=None,
                 dict_path="system/canopyMeshDict"):
        if not os.path.isfile(os.path.join(case, dict_path)):
            raise MeshError(f"{os.path.join(case, dict_path)} not found")
        self.dict_path = dict_path
        self.D0 = _positive(case, dict_path, "D0")
        self.cells_per_diameter = (
            float(cells_per_diameter) if cells_per_diameter is not None
            else _positive(case, dict_path, "cellsPerDiameter"))
        if not self.cells_per_diameter > 0:
            raise MeshError(f"-cellsPerDiameter must be > 0, not "
                            f"{cells_per_diameter}")
        self.edge_per_cell = _positive(case, dict_path, "edgeLengthPerCell",
                                       default=1.25)
        self.width = _positive(case, dict_path, "domain.width")
        self.upstream = _positive(case, dict_path, "domain.upstream")
        self.downstream = _positive(case, dict_path, "domain.downstream")
        self.boxes = []
        count = _value(case, dict_path, "refinement")
        if count is None:
            raise MeshError(f"{dict_path}: entry 'refinement' is missing")
        n_boxes = _count_list(count)
        for i in range(n_boxes):
            self.boxes.append(tuple(
                _box_entry(count, i, key, dict_path)
                for key in ("halfWidth", "below", "above")))
        self.levels = len(self.boxes)
        self.h = self.D0 / self.cells_per_diameter
        self.h0 = self.h * 2 ** self.levels

    def domain_box(self):
        """The box's extents [m], whole cells of h0 around the centre."""
        half = _cells(self.width * self.D0 / 2, self.h0) * self.h0
        return ((-half, -half,
                 -_cells(self.upstream * self.D0, self.h0) * self.h0),
                (half, half,
                 _cells(self.downstream * self.D0, self.h0) * self.h0))

    def level_boxes(self):
        """Each refinement box [m] ((x0, y0, z0), (x1, y1, z1)): rounded
        outwards to whole cells of the level it refines (h0 / 2^i), so that
        it selects exactly the cells whose centres lie inside, and clipped
        to the domain (a level may reach the far field)."""
        dlo, dhi = self.domain_box()
        boxes = []
        for i, (half_width, below, above) in enumerate(self.boxes):
            cell = self.h0 / 2 ** i
            x = _cells(half_width * self.D0, cell) * cell
            lo = (-x, -x, -_cells(below * self.D0, cell) * cell)
            hi = (x, x, _cells(above * self.D0, cell) * cell)
            boxes.append((tuple(max(a, b) for a, b in zip(lo, dlo)),
                          tuple(min(a, b) for a, b in zip(hi, dhi))))
        return boxes

    def check_nesting(self):
        """Where a box does not reach the far field, it lies inside the one
        before with at least one cell of that one's level to spare, so that
        neighbouring cells differ by at most a factor 2."""
        dlo, dhi = self.domain_box()
        boxes = self.level_boxes()
        names = ("x", "y", "z")
        for i in range(1, len(boxes)):
            spare = self.h0 / 2 ** i
            (lo, hi), (plo, phi) = boxes[i], boxes[i - 1]
            for k in range(3):
                gaps = (("below", lo[k] - plo[k], lo[k] <= dlo[k]),
                        ("above", phi[k] - hi[k], hi[k] >= dhi[k]))
                for side, gap, at_domain in gaps:
                    if not at_domain and gap < spare * (1 - 1e-9):
                        raise MeshError(
                            f"{self.dict_path}: refinement {i} reaches "
                            f"within {gap / self.D0:.3g} D0 of refinement "
                            f"{i - 1} ({names[k]}, {side}); keep at least "
                            f"one cell ({spare / self.D0:.3g} D0 at "
                            f"{self.cells_per_diameter:g} cells per D0) "
                            "between them")


def _count_list(text):
    """Number of { ... } entries in a list value's text."""
    depth = n = 0
    for ch in text:
        if ch == "{":
            if depth == 0:
                n += 1
            depth += 1
        elif ch == "}":
            depth -= 1
    if n == 0:
        raise MeshError("system/canopyMeshDict: entry 'refinement' must "
                        "list boxes { halfWidth ..; below ..; above ..; }")
    return n


def _box_entry(text, index, key, dict_path):
    """Entry `key` of the index-th { ... } of the list text."""
    depth = n = 0
    start = None
    for pos, ch in enumerate(text):
        if ch == "{":
            if depth == 0:
                if n == index:
                    start = pos + 1
                n += 1
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0 and start is not None:
                body = text[start:pos]
                break
    else:
        body = ""
    for statement in body.split(";"):
        words = statement.split()
        if len(words) == 2 and words[0] == key:
            try:
                value = float(words[1])
            except ValueError:
                value = float("nan")
            if value > 0 and math.isfinite(value):
                return value
            raise MeshError(f"{dict_path}: refinement {index} entry '{key}' "
                            f"= {words[1]} must be a finite number > 0 [D0]")
    raise MeshError(f"{dict_path}: refinement {index} needs an entry "
                    f"'{key}' [D0]")


def _cells(extent, cell):
    """Whole cells covering `extent` (rounded up, at least 1)."""
    return max(1, math.ceil(extent / cell - 1e-9))


def block_mesh_dict(spec):
    """system/blockMeshDict text for the box of cells h0."""
    h0 = spec.h0
    (_, _, z0), (x, _, z1) = spec.domain_box()
    half = round(x / h0)
    below, above = round(-z0 / h0), round(z1 / h0)
    return f"""/*--------------------------------*- C++ -*----------------------------------*\\
  canopyFoam: the box around the parachute, written by bin/canopy-mesh from
  system/canopyMeshDict (do not edit: edit that dictionary)
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      blockMeshDict;
}}

// D0 {spec.D0:g} m, {spec.cells_per_diameter:g} cells across D0 in the
// finest of {spec.levels} refinement levels (h = {spec.h:.6g} m); box cells
// {h0:.6g} m
scale   1;

vertices
(
    ({-x:.9g} {-x:.9g} {z0:.9g}) ({x:.9g} {-x:.9g} {z0:.9g})
    ({x:.9g} {x:.9g} {z0:.9g}) ({-x:.9g} {x:.9g} {z0:.9g})
    ({-x:.9g} {-x:.9g} {z1:.9g}) ({x:.9g} {-x:.9g} {z1:.9g})
    ({x:.9g} {x:.9g} {z1:.9g}) ({-x:.9g} {x:.9g} {z1:.9g})
);

blocks
(
    hex (0 1 2 3 4 5 6 7) ({2 * half} {2 * half} {below + above})
    simpleGrading (1 1 1)
);

boundary
(
    inlet   {{ type patch; faces ((0 3 2 1)); }}
    outlet  {{ type patch; faces ((4 5 6 7)); }}
    sides
    {{
        type patch;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));
    }}
);
"""


def topo_set_dict(spec, i):
    lo, hi = spec.level_boxes()[i]
    fmt = " ".join
    return f"""/*--------------------------------*- C++ -*----------------------------------*\\
  canopyFoam: refinement level {i + 1} of {spec.levels}, written by
  bin/canopy-mesh from system/canopyMeshDict
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      topoSetDict;
}}

actions
(
    {{
        name    refine;
        type    cellSet;
        action  new;
        source  boxToCell;
        box     ({fmt(f'{v:.9g}' for v in lo)}) ({fmt(f'{v:.9g}' for v in hi)});
    }}
);
"""


REFINE_MESH_DICT = """/*--------------------------------*- C++ -*----------------------------------*\\
  canopyFoam: refineMesh settings of bin/canopy-mesh: split every cell of
  the set in all three directions
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      refineMeshDict;
}}

set             refine;
coordinateSystem global;
globalCoeffs
{{
    tan1        (1 0 0);    // OpenFOAM v1912's names
    tan2        (0 1 0);
    e1          (1 0 0);    // OpenFOAM-12's
    e2          (0 1 0);
}}
directions      {directions};
useHexTopology  true;
geometricCut    false;
writeMesh       false;
"""


def _run(case, log_name, args):
    with open(os.path.join(case, log_name), "w") as log:
        result = subprocess.run(args, cwd=case, stdout=log,
                                stderr=subprocess.STDOUT, check=False)
    if result.returncode != 0:
        raise MeshError(f"{args[0]} failed, see {os.path.join(case, log_name)}")


def _write(case, path, text):
    with open(os.path.join(case, path), "w") as out:
        out.write(text)


def cell_count(case):
    """The mesh's cell count, from constant/polyMesh/owner's header note."""
    with open(os.path.join(case, "constant/polyMesh/owner"), "rb") as owner:
        head = owner.read(2048).decode("ascii", "replace")
    for word in head.replace('"', " ").split():
        if word.startswith("nCells:"):
            return int(word[len("nCells:"):])
    raise MeshError("constant/polyMesh/owner has no nCells note")


def make(case, cells_per_diameter=None, say=print):
    """Mesh the case (see the module's docstring); returns the Spec."""
    spec = Spec(case, cells_per_diameter)
    spec.check_nesting()
    _write(case, "system/blockMeshDict.run", block_mesh_dict(spec))
    _run(case, "log.blockMesh",
         ["blockMesh", "-dict", "system/blockMeshDict.run"])
    # the three directions by the names of the OpenFOAM sourced (the
    # Foundation's releases number theirs)
    foundation = not os.environ.get("WM_PROJECT_VERSION", "v").startswith("v")
    _write(case, "system/refineMeshDict.run", REFINE_MESH_DICT.format(
        directions="(e1 e2 e3)" if foundation else "(tan1 tan2 normal)"))
    for i in range(spec.levels):
        _write(case, f"system/topoSetDict.level{i + 1}", topo_set_dict(spec, i))
        _run(case, f"log.topoSet.level{i + 1}",
             ["topoSet", "-dict", f"system/topoSetDict.level{i + 1}"])
        _run(case, f"log.refineMesh.level{i + 1}",
             ["refineMesh", "-overwrite", "-dict", "system/refineMeshDict.run"])
    # refineMesh -overwrite leaves its cell map in the start time's folder
    # (which it makes when there is none: then it goes too)
    cell_map = os.path.join(case, "0", "polyMesh", "cellMap")
    if os.path.isfile(cell_map):
        os.remove(cell_map)
        for folder in (os.path.dirname(cell_map),
                       os.path.join(case, "0")):
            try:
                os.rmdir(folder)
            except OSError:
                break
    spec.n_cells = cell_count(case)
    edge = spec.edge_per_cell * spec.h
    result = subprocess.run(
        ["foamDictionary", "-entry", "canopy/edgeLength", "-set", f"{edge:.6g}",
         os.path.join(case, "constant/canopyProperties")],
        capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise MeshError("cannot set canopy.edgeLength in "
                        "constant/canopyProperties: " + result.stderr.strip())
    lo, hi = (spec.level_boxes()[-1] if spec.levels
              else spec.domain_box())
    say(f"mesh: {spec.n_cells} cells; D0 {spec.D0:g} m, "
        f"{spec.cells_per_diameter:g} cells across D0 "
        f"(finest cell {spec.h:.4g} m, box cell {spec.h0:.4g} m, "
        f"{spec.levels} levels); finest region x, y in [{lo[0]:.3g}, "
        f"{hi[0]:.3g}] m, z in [{lo[2]:.3g}, {hi[2]:.3g}] m; "
        f"canopy.edgeLength {edge:.4g} m")
    return spec


def main(argv=None):
    import argparse
    parser = argparse.ArgumentParser(
        prog="canopy-mesh",
        description="Mesh a parachute case from system/canopyMeshDict.")
    parser.add_argument("case", nargs="?", default=".")
    parser.add_argument("--cells-per-diameter", type=float, default=None,
                        help="cells across D0 in the finest level "
                        "(default: the dictionary's cellsPerDiameter)")
    args = parser.parse_args(argv)
    try:
        make(args.case, args.cells_per_diameter)
    except MeshError as err:
        print(f"canopy-mesh: {err}")
        return 1
    return 0
