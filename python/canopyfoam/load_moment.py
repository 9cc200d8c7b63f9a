"""load_moment.py — the moment about the payload of the load the structure is given on its cloth, from the states a run wrote to its canopy.h5.

canopy.h5 holds with every state a pressure jump dp per cloth triangle,
acting as dp A n on the triangle (A n = (x1 - x0) x (x2 - x0) / 2, the
triangles' winding as written), and the external nodal forces f_ext: the
sum of the contributions canopyCoupling sets (the fluid's tangential
load, the added-mass stabiliser's balancing force m_a (d.a) d where the
stabiliser is on, the lines' drag where that is on). The moment about
the payload node at each written state is

    M = sum_triangles (c - p) x dp A n + sum_nodes (x - p) x f_ext,

c a triangle's centroid, p the payload's position: a uniform pressure
puts its resultant there. For a canopy held still (fixed nodes, no line
drag) the stabiliser's balance is zero and the sum of the two forces is
canopy.dat's force, the fluid's load; for a moving canopy the balance
adds the stabiliser's inertia m_a a along the normals. Reading needs
h5py (Debian's python3-h5py).
"""

import math
import os

import numpy as np

PAYLOAD_GROUP = 3      # libcanopy's node group of the payload (canopy.h)


class LoadMomentError(Exception):
    """The states needed are not in the file (named in the message)."""


def load_and_moment(x, triangles, dp, f_ext, point):
    """(force, moment about point) of the cloth's load in one state: x the
    nodes (n x 3), triangles (m x 3) with their pressure jumps dp (m), the
    nodal forces f_ext (n x 3)."""
    x = np.asarray(x, dtype=float)
    tri = np.asarray(triangles, dtype=int)
    x0, x1, x2 = x[tri[:, 0]], x[tri[:, 1]], x[tri[:, 2]]
    pressure = np.asarray(dp, dtype=float)[:, None] \
        * 0.5 * np.cross(x1 - x0, x2 - x0)
    centroid = (x0 + x1 + x2) / 3.0
    f_ext = np.asarray(f_ext, dtype=float)
    point = np.asarray(point, dtype=float)
    force = pressure.sum(axis=0) + f_ext.sum(axis=0)
    moment = np.cross(centroid - point, pressure).sum(axis=0) \
        + np.cross(x - point, f_ext).sum(axis=0)
    return force, moment


def analyse(case_dir, t0=-math.inf, t1=math.inf):
    """The load's force [N] and moment about the payload [N m], each state
    written in [t0, t1] and their means: dict with times, force, moment
    (lists of vectors), forceMean, momentMean and states."""
    try:
        import h5py
    except ImportError:
        raise LoadMomentError("python3-h5py is not installed (bin/setup "
                              "installs it)")
    path = os.path.join(case_dir, "postProcessing", "canopy", "canopy.h5")
    if not os.path.isfile(path):
        raise LoadMomentError("no %s" % os.path.relpath(path, case_dir))
    times, forces, moments = [], [], []
    try:
        with h5py.File(path, "r") as f:
            groups = f["mesh/node_group"][:]
            triangles = f["mesh/triangles"][:]
            payload = np.nonzero(groups == PAYLOAD_GROUP)[0]
            if payload.size != 1:
                raise LoadMomentError("%s: %d payload nodes, not one"
                                      % (os.path.relpath(path, case_dir),
                                         payload.size))
            for name in sorted(f["steps"].keys()):
                step = f["steps"][name]
                t = float(step.attrs["time"])
                if not t0 - 1e-9 <= t <= t1 + 1e-9:
                    continue
                x = step["x"][:]
                force, moment = load_and_moment(
                    x, triangles, step["dp"][:], step["f_ext"][:],
                    x[payload[0]])
                times.append(t)
                forces.append(force)
                moments.append(moment)
    except (OSError, KeyError) as e:
        raise LoadMomentError("%s: %s" % (os.path.relpath(path, case_dir),
                                          e))
    if not times:
        raise LoadMomentError("canopy.h5 holds no state in t = %g .. %g s"
                              % (t0, t1))
    return {"times": times,
            "force": [list(map(float, v)) for v in forces],
            "moment": [list(map(float, v)) for v in moments],
            "forceMean": [float(v) for v in np.mean(forces, axis=0)],
            "momentMean": [float(v) for v in np.mean(moments, axis=0)],
            "states": len(times)}
