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
adds the stabiliser's inertia m_a a along the normals.

That balance is no load of the air's: the structure carries the same
m_a a as inertia on its side of the equation, and the two cancel at the
coupling's convergence. Given the stabiliser's settings (coupling.addedMass:
its mass per area, direction all or normal; lumped, without filter, as
addedMassStabiliser.H describes), analyse also returns the balance's
moment, rebuilt from the written accelerations as m_i a_i (all) or
m_i (d_i.a_i) d_i (normal), m_i a third of the node's triangles' areas in
the run's first written state times the mass per area (the stabiliser
takes the areas it is built with) and d_i the node's area-weighted normal
in the state written (the stabiliser's is the step's start), and the
air's own moment, the load's less the balance's. It also returns the
moment of the weights of the nodes other than the payload. Reading needs
h5py (Debian's python3-h5py).
"""

import math
import os

import numpy as np

from . import canopy_h5


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


def node_areas(x, triangles):
    """A third of the areas of each node's triangles [m^2] and the nodes'
    area-weighted unit normals (zero away from the cloth)."""
    x = np.asarray(x, dtype=float)
    tri = np.asarray(triangles, dtype=int)
    cross = np.cross(x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]])
    area = 0.5 * np.linalg.norm(cross, axis=1)
    third = np.zeros(len(x))
    normal = np.zeros_like(x)
    for k in range(3):
        np.add.at(third, tri[:, k], area / 3.0)
        np.add.at(normal, tri[:, k], 0.5 * cross)
    length = np.linalg.norm(normal, axis=1)
    cloth = length > 0
    normal[cloth] /= length[cloth][:, None]
    return third, normal


def balance_forces(mass, normal, acc, direction):
    """The stabiliser's balancing nodal forces: m a (direction all) or
    m (d.a) d (normal), mass the nodes' added masses."""
    acc = np.asarray(acc, dtype=float)
    mass = np.asarray(mass, dtype=float)
    if direction == "all":
        return mass[:, None] * acc
    if direction == "normal":
        along = np.einsum("ij,ij->i", normal, acc)
        return (mass * along)[:, None] * normal
    raise LoadMomentError("the added-mass stabiliser's direction %r is not "
                          "all or normal" % direction)


def analyse(case_dir, t0=-math.inf, t1=math.inf, stabiliser=None,
            gravity=None):
    """The load's force [N] and moment about the payload [N m], each state
    written in [t0, t1] and their means: dict with times, force, moment
    (lists of vectors), forceMean, momentMean and states; with gravity
    [m/s^2] weightMoment, the moment of the nodes' weights (the payload's
    aside); with
    stabiliser ({"mass": kg/m^2, "direction": "all" or "normal"}, the
    run's coupling.addedMass) also balanceMoment and fluidMoment (the
    load's less the balance's)."""
    path = canopy_h5.path(case_dir)
    times, forces, moments, weights, balances = [], [], [], [], []
    try:
        with canopy_h5.open_file(case_dir, LoadMomentError) as f:
            groups = f["mesh/node_group"][:]
            triangles = f["mesh/triangles"][:]
            node_mass = f["mesh/node_mass"][:] if gravity is not None \
                else None
            payload = np.nonzero(groups == canopy_h5.GROUP_PAYLOAD)[0]
            if payload.size != 1:
                raise LoadMomentError("%s: %d payload nodes, not one"
                                      % (os.path.relpath(path, case_dir),
                                         payload.size))
            names = sorted(f["steps"].keys())
            added = None
            if stabiliser is not None and names:
                third, _ = node_areas(f["steps"][names[0]]["x"][:],
                                      triangles)
                added = float(stabiliser["mass"]) * third
            others = np.arange(len(groups)) != payload[0]
            if gravity is not None:
                gravity = np.asarray(gravity, dtype=float)
            for name in names:
                step = f["steps"][name]
                t = float(step.attrs["time"])
                if not t0 - 1e-9 <= t <= t1 + 1e-9:
                    continue
                x = step["x"][:]
                p = x[payload[0]]
                force, moment = load_and_moment(
                    x, triangles, step["dp"][:], step["f_ext"][:], p)
                times.append(t)
                forces.append(force)
                moments.append(moment)
                if gravity is not None:
                    weights.append(np.cross(
                        x[others] - p,
                        node_mass[others][:, None] * gravity).sum(axis=0))
                if added is not None:
                    normal = node_areas(x, triangles)[1] \
                        if stabiliser["direction"] == "normal" else None
                    fb = balance_forces(added, normal, step["acc"][:],
                                        stabiliser["direction"])
                    balances.append(np.cross(x - p, fb).sum(axis=0))
    except (OSError, KeyError) as e:
        raise LoadMomentError("%s: %s" % (os.path.relpath(path, case_dir),
                                          e))
    if not times:
        raise LoadMomentError("canopy.h5 holds no state in t = %g .. %g s"
                              % (t0, t1))
    out = {"times": times,
           "force": [list(map(float, v)) for v in forces],
           "moment": [list(map(float, v)) for v in moments],
           "forceMean": [float(v) for v in np.mean(forces, axis=0)],
           "momentMean": [float(v) for v in np.mean(moments, axis=0)],
           "states": len(times)}
    if weights:
        out["weightMoment"] = [list(map(float, v)) for v in weights]
    if balances:
        out["balanceMoment"] = [list(map(float, v)) for v in balances]
        out["fluidMoment"] = [list(map(float, m - b))
                              for m, b in zip(moments, balances)]
    return out
