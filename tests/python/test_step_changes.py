"""test_step_changes.py — known-answer tests of python/canopyfoam/step_changes.py (the canopy's velocity change from one time step to the next, from canopy.h5).

Run as:  /usr/bin/python3 tests/python/test_step_changes.py   (./Alltest step_changes)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

A cloth of one triangle in the plane z = 0 (normal +z), two line nodes and
a payload node, seven states 10 ms apart (t_k = 0.01 k):
  cloth   every node at v = (b t, 0, a t), a = 3, b = 4 m/s^2: each step
          changes the triangle's velocity by (b, 0, a) dt, so the rms
          change is 5 dt = 0.05 m/s, 0.03 along the normal and 0.04 in the
          plane, and consecutive changes are equal (correlation +1);
  lines   v = (c (-1)^k, 0, 0), c = 0.5 m/s: each change is -+2c, rms 1 m/s,
          consecutive changes opposite (correlation -1).
The run's step times are the states' times; a run with a step between
every two states (step times 5 ms apart), or an interval with fewer than
three states, is refused.
"""

import os
import shutil
import tempfile

import numpy as np

from checks import check, finish, refused
from canopyfoam import step_changes

try:
    import h5py
except ImportError:
    h5py = None
check("h5py available", h5py is not None,
      "python3-h5py (bin/setup installs it)")
if h5py is None:
    finish()

a, b, c, dt, n = 3.0, 4.0, 0.5, 0.01, 7
x0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0],
               [0.2, 0.2, -1], [0.1, 0.1, -2], [0, 0, -3]], dtype=float)
groups = np.array([0, 0, 0, 2, 2, 3], dtype=np.int32)
times = [dt * k for k in range(n)]
tmp = tempfile.mkdtemp(prefix="test_step_changes.")
try:
    os.makedirs(os.path.join(tmp, "postProcessing", "canopy"))
    path = os.path.join(tmp, "postProcessing", "canopy", "canopy.h5")
    with h5py.File(path, "w") as f:
        m = f.create_group("mesh")
        m["node_group"] = groups
        m["triangles"] = np.array([[0, 1, 2]], dtype=np.int32)
        for k, t in enumerate(times):
            v = np.zeros_like(x0)
            v[:3] = (b * t, 0, a * t)
            v[3:5] = (c * (-1) ** k, 0, 0)
            g = f.create_group("steps/%06d" % k)
            g.attrs["time"] = t
            g["x"] = x0
            g["v"] = v
    r = step_changes.analyse(tmp, 0.0, 1.0, times)
    exact = dict(clothRms=5 * dt, clothNormalRms=a * dt,
                 clothInPlaneRms=b * dt, clothCorrelation=1.0,
                 clothInPlaneCorrelation=1.0, linesRms=2 * c,
                 linesCorrelation=-1.0)
    worst = max(abs(r[k] - v) for k, v in exact.items())
    check("smooth cloth, alternating lines", worst < 1e-12 and
          r["states"] == n and r["lineNodes"] == 2 and
          r["clothTriangles"] == 1,
          ", ".join("%s %.15g (exact %g)" % (k, r[k], v)
                    for k, v in exact.items())
          + "; %d states" % r["states"])
    r = step_changes.analyse(tmp, 0.015, 0.045, times)
    check("interval's states only", r["states"] == 3 and
          abs(r["timeFirst"] - 0.02) < 1e-12 and
          abs(r["timeLast"] - 0.04) < 1e-12,
          "%d states, t = %g .. %g" % (r["states"], r["timeFirst"],
                                       r["timeLast"]))
    refused("every other step refused",
            lambda: step_changes.analyse(tmp, 0.0, 1.0, [dt / 2 * k for k
                                                         in range(2 * n)]),
            step_changes.StepChangeError, "consecutive")
    refused("two states refused",
            lambda: step_changes.analyse(tmp, 0.015, 0.035, times),
            step_changes.StepChangeError, "at least 3")
    os.remove(path)
    refused("missing file refused",
            lambda: step_changes.analyse(tmp, 0.0, 1.0, times),
            step_changes.StepChangeError, "canopy.h5")
finally:
    shutil.rmtree(tmp)

finish()
