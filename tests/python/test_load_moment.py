"""test_load_moment.py — known-answer tests of python/canopyfoam/load_moment.py (the force and moment about the payload of the cloth's load, from canopy.h5).

Run as:  /usr/bin/python3 tests/python/test_load_moment.py   (./Alltest load_moment)
Prints one PASS/FAIL line per check; exits 1 if any fails.

1. One triangle (0,0,1), (1,0,1), (0,1,1), A n = (0, 0, 1/2), with a
   pressure jump of 2 Pa, and a nodal force (0, 2, 0) at (1, 0, 1): about
   the origin the force is (0, 2, 1) and the moment
   (1/3, 1/3, 1) x (0, 0, 1) + (1, 0, 1) x (0, 2, 0) = (1/3 - 2, -1/3, 2)
   exactly (to 1e-15).
2. A uniform pressure jump on a closed, consistently wound surface (a
   tetrahedron) has zero force and zero moment about any point (the
   integral of r x n dA over a closed surface vanishes): to 1e-12 of
   dp A r. This holds only with the resultant at each triangle's
   centroid, where a uniform pressure puts it.
3. Through canopy.h5 (h5py): three written states at t = 1, 2, 3 s with
   the payload (node group 3) at different places; the interval 1.5-3 s
   takes the last two, whose force and moment about each state's payload
   are those of check 1 translated (the moment about a moved point changes
   by the lever times the force); a file without a payload node, a
   missing file and an empty interval are refused with LoadMomentError.
4. The added-mass stabiliser's balance and the weights, in the same file
   with accelerations (1,0,0), (0,1,0), (0,0,2) at the cloth's nodes and
   masses 0.1, 0.2, 0.3 kg (payload 5 kg), 3 kg/m^2 of added mass (a third
   of the 0.5 m^2 triangle, 0.5 kg, to each node) and gravity (0,0,-10):
   about the payload (0,0,-3) at t = 2 s, worked by hand, the balance's
   moment is (-1, 2, 0.5) N m with direction all and (1, 0, 0) with
   direction normal (only the third node's acceleration is along the
   normal (0,0,1)), the weights' (-3, 2, 0), and the air's moment is the
   load's less the balance's; an unknown direction is refused.
"""

import os
import shutil
import tempfile

import numpy as np


from checks import check, finish
from canopyfoam import load_moment


# 1. one triangle and one nodal force
x = np.array([[0.0, 0, 1], [1, 0, 1], [0, 1, 1]])
tri = np.array([[0, 1, 2]])
f_ext = np.array([[0.0, 0, 0], [0, 2, 0], [0, 0, 0]])
force, moment = load_moment.load_and_moment(x, tri, [2.0], f_ext, [0, 0, 0])
want_m = np.array([1.0 / 3 - 2, -1.0 / 3, 2])
check("triangle: force", np.allclose(force, [0, 2, 1], atol=1e-15, rtol=0),
      "%s N (exact (0, 2, 1))" % force)
check("triangle: moment", np.allclose(moment, want_m, atol=1e-15, rtol=0),
      "%s N m (exact %s)" % (moment, want_m))

# 2. closed tetrahedron, outward winding, uniform dp
tet = np.array([[0.1, 0.2, 0.3], [1.3, 0.1, 0.2], [0.2, 1.1, 0.4],
                [0.3, 0.4, 1.5]])
faces = []
centre = tet.mean(axis=0)
for f in ([0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]):
    a, b, c = tet[f]
    if np.dot(np.cross(b - a, c - a), a - centre) < 0:
        f = [f[0], f[2], f[1]]
    faces.append(f)
for point in ([0.0, 0, 0], [5.0, -3, 2]):
    force, moment = load_moment.load_and_moment(
        tet, faces, [7.0] * 4, np.zeros((4, 3)), point)
    scale = 7.0 * 1.0 * np.linalg.norm(np.asarray(point) - centre + 1.0)
    check("closed surface about %s" % point,
          np.max(np.abs(force)) < 1e-12 * 7 and
          np.max(np.abs(moment)) < 1e-12 * scale,
          "|F| %.2g N, |M| %.2g N m" % (np.max(np.abs(force)),
                                         np.max(np.abs(moment))))

# 3. through canopy.h5
import h5py  # noqa: E402

tmp = tempfile.mkdtemp()
try:
    os.makedirs(os.path.join(tmp, "postProcessing", "canopy"))
    path = os.path.join(tmp, "postProcessing", "canopy", "canopy.h5")
    payloads = {1.0: [0, 0, 0], 2.0: [0, 0, -3.0], 3.0: [1.0, 0, -3.0]}
    with h5py.File(path, "w") as f:
        f["mesh/triangles"] = np.array([[0, 1, 2]], dtype=np.int32)
        f["mesh/node_group"] = np.array([0, 0, 0, 3], dtype=np.int32)
        f["mesh/node_mass"] = np.array([0.1, 0.2, 0.3, 5.0])
        for k, (t, p) in enumerate(sorted(payloads.items())):
            s = f.create_group("steps/%06d" % k)
            s.attrs["time"] = t
            s["x"] = np.vstack([x, p])
            s["f_ext"] = np.vstack([f_ext, [0, 0, 0]])
            s["dp"] = np.array([2.0])
            s["acc"] = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 2],
                                 [0, 0, 0]])
    a = load_moment.analyse(tmp, 1.5, 3.0)
    want = []
    for t in (2.0, 3.0):
        p = np.array(payloads[t])
        # the moment about p: about the origin less p x F
        want.append(want_m - np.cross(p, [0, 2, 1]))
    check("h5: the states in the interval", a["times"] == [2.0, 3.0],
          "times %s" % a["times"])
    check("h5: moment about each state's payload",
          np.allclose(a["moment"], want, atol=1e-14, rtol=0) and
          np.allclose(a["momentMean"], np.mean(want, axis=0), atol=1e-14,
                      rtol=0),
          "%s (exact %s)" % (np.round(a["moment"], 6).tolist(),
                             np.round(want, 6).tolist()))
    check("h5: force", np.allclose(a["forceMean"], [0, 2, 1], atol=1e-15,
                                   rtol=0), "%s N" % a["forceMean"])
    for direction, want_b in (("all", [-1.0, 2, 0.5]),
                              ("normal", [1.0, 0, 0])):
        b = load_moment.analyse(tmp, 2.0, 2.0, stabiliser={
            "mass": 3.0, "direction": direction}, gravity=[0, 0, -10.0])
        check("h5: the stabiliser's balance, direction %s" % direction,
              np.allclose(b["balanceMoment"][0], want_b, atol=1e-14, rtol=0)
              and np.allclose(b["fluidMoment"][0],
                              np.subtract(b["moment"][0], want_b),
                              atol=1e-14, rtol=0),
              "%s N m (by hand %s)" % (b["balanceMoment"][0], want_b))
    check("h5: the weights' moment",
          np.allclose(b["weightMoment"][0], [-3.0, 2, 0], atol=1e-14,
                      rtol=0), "%s N m (by hand (-3, 2, 0))"
          % b["weightMoment"][0])
    try:
        load_moment.analyse(tmp, stabiliser={"mass": 1.0,
                                             "direction": "tangential"})
        check("h5: unknown stabiliser direction refused", False, "no error")
    except load_moment.LoadMomentError as e:
        check("h5: unknown stabiliser direction refused",
              "direction" in str(e), str(e))
    for name, args in (("empty interval", (5.0, 6.0)),):
        try:
            load_moment.analyse(tmp, *args)
            check("h5: %s refused" % name, False, "no error")
        except load_moment.LoadMomentError as e:
            check("h5: %s refused" % name, "no state" in str(e), str(e))
    with h5py.File(path, "a") as f:
        del f["mesh/node_group"]
        f["mesh/node_group"] = np.array([0, 0, 0, 0], dtype=np.int32)
    try:
        load_moment.analyse(tmp)
        check("h5: no payload refused", False, "no error")
    except load_moment.LoadMomentError as e:
        check("h5: no payload refused", "payload" in str(e), str(e))
    os.remove(path)
    try:
        load_moment.analyse(tmp)
        check("h5: missing file refused", False, "no error")
    except load_moment.LoadMomentError as e:
        check("h5: missing file refused", "canopy.h5" in str(e), str(e))
finally:
    shutil.rmtree(tmp)

finish()
