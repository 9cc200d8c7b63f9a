"""canopyCase.py — ParaView script that opens a canopyFoam case with the canopy, its lines and a velocity slice in one click.

Usage, from inside a case directory (or with CANOPY_CASE=<caseDir>):

    paraview --script=<repository>/etc/paraview/canopyCase.py

It opens <case>/case.foam (created empty when missing) and
<case>/postProcessing/canopy/canopy.xdmf, shows |U| on the plane normal to
x through the canopy centre, the canopy coloured by its pressure jump
(cell_dp) with the suspension lines, sets an oblique camera with -gravity
up, and goes to the latest field time; the animation controls then step
through the write times. The set-up itself is
python/canopyfoam/render.py's show_case(), shared with bin/canopy-render;
this script finds that directory from its own path (paraview --script
gives the script no __file__, so the path is read from the command line),
else from $CANOPYFOAM_DIR. Also runs under pvpython/pvbatch.
"""

import os
import sys


def _python_dir():
    """The repository's python/ directory, or None."""
    places = []
    here = globals().get("__file__")
    if here:
        places.append(os.path.dirname(os.path.abspath(here)))
    try:
        with open("/proc/self/cmdline", "rb") as f:
            args = [a.decode("utf-8", "replace")
                    for a in f.read().split(b"\0") if a]
    except OSError:
        args = []
    for i, arg in enumerate(args):
        if arg.startswith("--script="):
            path = arg[len("--script="):]
        elif arg == "--script" and i + 1 < len(args):
            path = args[i + 1]
        elif arg.endswith("canopyCase.py"):
            path = arg
        else:
            continue
        places.append(os.path.dirname(os.path.abspath(path)))
    if os.environ.get("CANOPYFOAM_DIR"):
        places.append(os.path.join(os.environ["CANOPYFOAM_DIR"], "etc",
                                   "paraview"))
    for place in places:
        python = os.path.normpath(os.path.join(place, "..", "..", "python"))
        if os.path.isfile(os.path.join(python, "canopyfoam", "render.py")):
            return python
    return None


def _open_case():
    python = _python_dir()
    if python is None:
        raise RuntimeError("canopyCase.py: cannot find the canopyFoam "
                           "python/ directory; set CANOPYFOAM_DIR to the "
                           "repository")
    if python not in sys.path:
        sys.path.insert(0, python)
    from canopyfoam import render

    case = os.environ.get("CANOPY_CASE") or os.getcwd()
    print("canopyCase.py: opening %s" % os.path.abspath(case))
    try:
        return render.show_case(case,
                                log=lambda s: print("canopyCase.py: " + s))
    except render.RenderError as e:
        raise RuntimeError("canopyCase.py: %s (run it from inside a case "
                           "directory, or set CANOPY_CASE)" % e)


canopyScene = _open_case()
