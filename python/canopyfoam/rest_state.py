"""rest_state.py — a run's last canopy state, at rest where its mesh is, written as the initial state of another run (canopyProperties initialState).

A run's postProcessing/canopy/canopy.h5 (libcanopy's output layout,
canopy.h) holds the structure (/mesh) and one group per written step
(/steps/NNNNNN) with the nodes' ground-frame positions x, their positions
in the run's frame x_frame (x less the frame's origin: where the mesh is),
and their velocities v. canopyStructure reads an initial state's last step
(positions and velocities, after checking that the file holds the same
triangles, springs and rest lengths), so the file written here has the
source's /mesh and a single step at t = 0 whose positions are the last
step's x_frame and whose velocities are zero: the inflated canopy of one
run placed, still, in a fresh case built like it (the same tutorial and
resolution) — e.g. held there (fixedNodes) in a stream.

Reading and writing need h5py (Debian's python3-h5py).
"""

import os

import numpy as np


class RestStateError(RuntimeError):
    """The source file cannot give a rest state (named in the message)."""


def write_rest_state(source, dest):
    """Write dest (HDF5) from source's last step, at rest in its frame;
    returns that step's time [s]. dest is replaced only once it is
    complete; a bad source raises RestStateError and leaves dest as it
    was."""
    import h5py
    if not os.path.isfile(source):
        raise RestStateError("%s: no such file (has its run been run?)"
                             % source)
    with h5py.File(source, "r") as src:
        if "mesh" not in src or "steps" not in src:
            raise RestStateError("%s holds no /mesh and /steps: not a "
                                 "canopyFoam structure output" % source)
        names = sorted(src["steps"].keys())
        if not names:
            raise RestStateError("%s holds no steps" % source)
        last = src["steps"][names[-1]]
        where = "x_frame" if "x_frame" in last else "x"
        x = np.asarray(last[where][...], dtype=float)
        if x.ndim != 2 or x.shape[1] != 3 or not np.all(np.isfinite(x)):
            raise RestStateError("%s: step %s's %s is not a finite n x 3 "
                                 "array" % (source, names[-1], where))
        time = float(last.attrs["time"])
        tmp = dest + ".tmp"
        with h5py.File(tmp, "w") as out:
            src.copy(src["mesh"], out, "mesh")
            step = out.create_group("steps").create_group("%06d" % 0)
            step.attrs.create("time", 0.0, dtype="float64")
            step.attrs.create("acc_valid", 0, dtype="int32")
            step["x"] = x
            step["x_frame"] = x
            step["frame_origin"] = np.zeros(3)
            zero = np.zeros_like(x)
            step["v"] = zero
            step["acc"] = zero
            step["f_ext"] = zero
            for name in ("dp", "cell_dp", "tension", "cell_tension"):
                if name in last:
                    step[name] = np.zeros_like(last[name][...])
    os.replace(tmp, dest)
    return time
