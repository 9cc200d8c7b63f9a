"""test_rest_state.py — tests of python/canopyfoam/rest_state.py (a run's last canopy state, at rest in its frame, as another run's initial state) on a synthetic canopy.h5.

Run as:  /usr/bin/python3 tests/python/test_rest_state.py   (./Alltest rest_state)
Prints one PASS/FAIL line per check; exits 1 if any fails.

The source holds a 4-node structure (/mesh: triangles, springs, rest
lengths, counts as attributes) and two steps whose positions x are the
frame-relative positions x_frame plus the frame's origin (0, 0, -100 t),
with non-zero velocities. The rest state must hold exactly the same /mesh
(every dataset and attribute), one step at t = 0 whose x and x_frame are
the source's last x_frame, bit for bit, and zero velocities; the source
must be left unchanged. A source without steps, or missing, is refused
with RestStateError and an existing destination is left as it was.
"""

import os
import shutil
import tempfile

import h5py
import numpy as np

from checks import check, finish
from canopyfoam import rest_state


def write_source(path, steps):
    """A synthetic output with the given number of steps."""
    rng = np.random.default_rng(7)
    with h5py.File(path, "w") as f:
        m = f.create_group("mesh")
        m.attrs["nodes"] = 4
        m.attrs["triangles"] = 2
        m["triangles"] = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32)
        m["springs"] = np.array([[0, 1], [1, 2], [2, 0], [2, 3], [3, 0]],
                                dtype=np.int32)
        m["spring_rest_length"] = rng.uniform(0.5, 1.0, 5)
        m["node_group"] = np.array([0, 0, 0, 3], dtype=np.int32)
        g = f.create_group("steps")
        for k in range(steps):
            s = g.create_group("%06d" % k)
            t = 0.5 * (k + 1)
            s.attrs["time"] = t
            s.attrs["acc_valid"] = np.int32(1)
            xf = rng.normal(size=(4, 3))
            origin = np.array([0.0, 0.0, -100.0 * t])
            s["x_frame"] = xf
            s["frame_origin"] = origin
            s["x"] = xf + origin
            s["v"] = rng.normal(size=(4, 3))
            s["acc"] = rng.normal(size=(4, 3))
            s["f_ext"] = rng.normal(size=(4, 3))
            s["dp"] = rng.normal(size=2)


tmp = tempfile.mkdtemp()
try:
    src = os.path.join(tmp, "canopy.h5")
    dst = os.path.join(tmp, "restState.h5")
    write_source(src, 2)
    before = open(src, "rb").read()
    t = rest_state.write_rest_state(src, dst)
    check("time of the step taken", t == 1.0, "t = %g s (the last, 1 s)" % t)
    with h5py.File(src, "r") as s, h5py.File(dst, "r") as d:
        last = s["steps/000001"]
        names = sorted(d["steps"].keys())
        check("one step", names == ["000000"], "steps %s" % names)
        step = d["steps/000000"]
        check("positions are the last x_frame",
              np.array_equal(step["x"][:], last["x_frame"][:])
              and np.array_equal(step["x_frame"][:], last["x_frame"][:]),
              "max |x - x_frame(src)| = %g m"
              % np.max(np.abs(step["x"][:] - last["x_frame"][:])))
        check("at rest", not np.any(step["v"][:]) and
              not np.any(step["acc"][:]) and step.attrs["acc_valid"] == 0,
              "max |v| = %g m/s, acc_valid %d"
              % (np.max(np.abs(step["v"][:])), step.attrs["acc_valid"]))
        check("at t = 0, frame at the origin", step.attrs["time"] == 0.0 and
              not np.any(step["frame_origin"][:]),
              "t %g, origin %s" % (step.attrs["time"],
                                   step["frame_origin"][:]))
        same = all(np.array_equal(s["mesh"][k][:], d["mesh"][k][:])
                   for k in s["mesh"]) and \
            set(s["mesh"]) == set(d["mesh"]) and \
            dict(s["mesh"].attrs) == dict(d["mesh"].attrs)
        check("same structure", same, "/mesh datasets %s, attributes %s"
              % (sorted(d["mesh"]), dict(d["mesh"].attrs)))
    check("source unchanged", open(src, "rb").read() == before,
          "%d bytes" % len(before))

    kept = open(dst, "rb").read()
    empty = os.path.join(tmp, "empty.h5")
    write_source(empty, 0)
    for name, path in (("no steps", empty),
                       ("missing source", os.path.join(tmp, "none.h5"))):
        try:
            rest_state.write_rest_state(path, dst)
            check(name + " refused", False, "no error")
        except rest_state.RestStateError as e:
            check(name + " refused", open(dst, "rb").read() == kept,
                  "%s; destination unchanged" % e)
finally:
    shutil.rmtree(tmp)

finish()
