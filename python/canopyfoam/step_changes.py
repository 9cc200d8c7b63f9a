"""step_changes.py — how much the canopy's velocity changes from one time step to the next, from a run that wrote its structure every step.

The strong coupling's first iteration in a step imposes the interface
velocity of the step's start; its residual is the change of that velocity
over the step (python/canopyfoam/report.py's "coupling"). This module reads
the states canopy.h5 holds in an interval and, when they are consecutive
time steps of the run (the run wrote every step: writeControl timeStep,
writeInterval 1), gives for consecutive states n-1, n:
- the canopy's triangles' velocity (the mean of their three nodes', the
  fabric's and the tapes' alike), its change
  dv_n between the states: the root mean square of |dv_n| over the
  triangles and the steps, split into its part along the triangle's normal
  (at state n) and the rest, in the cloth's plane;
- the same for the suspension lines' interior nodes;
- the correlation of consecutive changes, sum(dv_n . dv_(n-1)) /
  sqrt(sum |dv_n|^2 sum |dv_(n-1)|^2): near +1 a motion smooth over a few
  steps (a step's change foretells the next), near 0 or below a vibration
  the steps alias (each change undoes part of the last).

Reading needs h5py (Debian's python3-h5py); the rest is numpy.
"""

import math
import os

import numpy as np

from . import canopy_h5


class StepChangeError(Exception):
    pass


def read_states(case_dir, t0, t1, step_times):
    """(node_group, triangles, [(time, x, v), ...]) for the states canopy.h5
    holds in [t0, t1], at least three, consecutive time steps of the run
    (step_times: its series' times); StepChangeError otherwise."""
    path = canopy_h5.path(case_dir)
    try:
        with canopy_h5.open_file(case_dir, StepChangeError) as f:
            names = []
            for name in sorted(f["steps"].keys()):
                t = float(f["steps"][name].attrs["time"])
                if t0 - 1e-9 <= t <= t1 + 1e-9:
                    names.append((t, name))
            if len(names) < 3:
                raise StepChangeError(
                    "canopy.h5 holds %d state(s) in t = %g .. %g s: at least "
                    "3 consecutive steps are needed" % (len(names), t0, t1))
            if not consecutive([t for t, _ in names], step_times):
                raise StepChangeError(
                    "the states canopy.h5 holds in t = %g .. %g s are not "
                    "consecutive time steps (write every step: writeControl "
                    "timeStep, writeInterval 1)" % (t0, t1))
            groups = f["mesh"]["node_group"][:]
            triangles = f["mesh"]["triangles"][:]
            states = [(t, f["steps"][name]["x"][:], f["steps"][name]["v"][:])
                      for t, name in names]
    except (OSError, KeyError) as e:
        raise StepChangeError("%s: %s" % (os.path.relpath(path, case_dir), e))
    return groups, triangles, states


def consecutive(state_times, step_times, tolerance=1e-6):
    """Are the states' times consecutive entries of the run's step times
    (to tolerance, in s: the series prints fewer digits than canopy.h5
    holds)?"""
    steps = np.asarray(step_times, dtype=float)
    index = []
    for t in state_times:
        i = int(np.argmin(np.abs(steps - t)))
        if abs(steps[i] - t) > tolerance:
            return False
        index.append(i)
    return all(b - a == 1 for a, b in zip(index, index[1:]))


def lag_correlation(changes):
    """sum(dv_n . dv_(n-1)) / sqrt(sum |dv_n|^2 sum |dv_(n-1)|^2) over the
    steps and items of changes[step, item, 3]."""
    a, b = changes[1:], changes[:-1]
    norm = math.sqrt(float(np.sum(a * a)) * float(np.sum(b * b)))
    return float(np.sum(a * b)) / norm if norm > 0 else float("nan")


def rms(changes):
    return float(np.sqrt(np.mean(np.sum(changes * changes, axis=-1))))


def analyse(case_dir, t0, t1, step_times):
    """The step-to-step changes over the states in [t0, t1] (see the module's
    docstring); StepChangeError unless there are at least three and they
    are consecutive time steps of the run (step_times: its series' times)."""
    groups, triangles, states = read_states(case_dir, t0, t1, step_times)
    times = [s[0] for s in states]
    x = np.array([s[1] for s in states])
    v = np.array([s[2] for s in states])
    if not len(triangles):
        raise StepChangeError("no triangles in canopy.h5's mesh")
    tv = v[:, triangles].mean(axis=2)
    xt = x[:, triangles]
    normal = np.cross(xt[:, :, 1] - xt[:, :, 0], xt[:, :, 2] - xt[:, :, 0])
    normal /= np.linalg.norm(normal, axis=2)[..., None]
    dv = np.diff(tv, axis=0)
    along = np.sum(dv * normal[1:], axis=2)[..., None] * normal[1:]
    out = {
        "states": len(states),
        "timeFirst": times[0],
        "timeLast": times[-1],
        "meanStep": (times[-1] - times[0]) / (len(states) - 1),
        "clothTriangles": int(len(triangles)),
        "clothRms": rms(dv),
        "clothNormalRms": rms(along),
        "clothInPlaneRms": rms(dv - along),
        "clothCorrelation": lag_correlation(dv),
        "clothInPlaneCorrelation": lag_correlation(dv - along),
    }
    lines = np.flatnonzero(groups == canopy_h5.GROUP_LINE)
    if len(lines):
        dl = np.diff(v[:, lines], axis=0)
        out.update(lineNodes=int(len(lines)), linesRms=rms(dl),
                   linesCorrelation=lag_correlation(dl))
    return out
