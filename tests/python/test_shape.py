"""test_shape.py — known-answer tests of python/canopyfoam/shape.py (the canopy's profile and creases from canopy.h5) on synthetic polar meshes.

Run as:  /usr/bin/python3 tests/python/test_shape.py   (./Alltest shape)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

The cloth is a polar mesh of radius R = 1 m: a centre node and N = 20 rings
of M = 16 nodes (ring i at radius i R / N), a fan of M triangles at the
centre and 2 M triangles per annulus; its springs are the triangles' edges
at their flat lengths; the payload node sits 3 m below the centre. So
  interior edges  M (3 N - 2) = 928 (the outer ring's M are the boundary),
  radial position s of ring i = i / N exactly (the shortest path to the
                  skirt runs along a spoke),
and three shapes have exact answers:
  flat            crown 0, skirt radius R, every fold angle 0;
  spherical cap   the disc wrapped on a sphere of radius rho = 1.5 m keeping
                  the spokes' length: crown rho (1 - cos(R/rho)), skirt
                  radius rho sin(R/rho), nothing folded;
  folded          the disc folded flat along ring 15 (radius r -> 2 r_f - r
                  beyond it): exactly the M edges of ring 15 fold, by 180
                  degrees, 16 of 928 edges; with rings (0, 0.33, 0.66, 1)
                  all of them lie in the outer ring, whose 20 M edges
                  (6 M on rings 14-19, 14 M between rings 13-20) give 5 %;
                  skirt radius 0.5 R, largest radius 0.75 R.
The silhouette's area is that of the regular M-gon of the outermost
ring's radius r (flat: R; cap: rho sin(R/rho); fold: 0.75 R), (M/2) r^2
sin(2 pi / M); sampled at pixel centres, it is off by at most half a
pixel's width times the perimeter, a relative 2 pi r (2.2 r / 256) / 2 /
(3.06 r^2) ~ 1.8 %, and in practice far less (the errors along the
outline cancel): checked to 0.5 % of the area.
A vented disc (rings 5 .. 20, no centre) checks that the skirt is the longer
boundary loop and that s is 0 at the vent's hem. Through canopy.h5 (h5py):
the states in the interval are averaged and the others left out; a case
without canopy.h5 gives a report whose shape is "not read".
"""

import math
import os
import shutil
import tempfile

import numpy as np

from checks import check, finish, write_canopy_h5
from canopyfoam import shape

N, M, R = 20, 16, 1.0


def polar_mesh(first_ring=0):
    """(rest positions, groups, triangles, springs, rest lengths, spring
    groups, ring index per node); first_ring 0 has a centre node, k > 0 a
    vent inside ring k."""
    pts, ring = [], []
    if first_ring == 0:
        pts.append((0.0, 0.0, 0.0))
        ring.append(0)
    start = max(first_ring, 1)
    for i in range(start, N + 1):
        for j in range(M):
            a = 2 * math.pi * j / M
            pts.append((i * R / N * math.cos(a), i * R / N * math.sin(a),
                        0.0))
            ring.append(i)

    def node(i, j):
        return (1 if first_ring == 0 else 0) + (i - start) * M + j % M
    tris = []
    if first_ring == 0:
        tris += [(0, node(1, j), node(1, j + 1)) for j in range(M)]
    for i in range(start, N):
        for j in range(M):
            tris.append((node(i, j), node(i + 1, j), node(i + 1, j + 1)))
            tris.append((node(i, j), node(i + 1, j + 1), node(i, j + 1)))
    payload = len(pts)
    pts.append((0.0, 0.0, -3.0))
    ring.append(-1)
    x = np.array(pts)
    groups = np.zeros(len(pts), dtype=int)
    groups[payload] = shape.GROUP_PAYLOAD
    edges = sorted(shape.edges_of(tris))
    springs = np.array(edges)
    rest = np.linalg.norm(x[springs[:, 0]] - x[springs[:, 1]], axis=1)
    return (x, groups, np.array(tris), springs, rest,
            np.zeros(len(springs), dtype=int), np.array(ring))


x0, groups, tris, springs, rest, sgroups, ring = polar_mesh()
mesh = shape.CanopyMesh(groups, tris, springs, rest, sgroups)
cloth = ring >= 0

# radial position
err = np.max(np.abs(mesh.s[cloth] - ring[cloth] / N))
check("radial position", err < 1e-12,
      "max |s - i/N| over the cloth = %.2g (tolerance 1e-12)" % err)
check("interior edges", len(mesh.edge_s) == M * (3 * N - 2),
      "%d, expected %d" % (len(mesh.edge_s), M * (3 * N - 2)))
check("skirt nodes", sorted(mesh.skirt) == sorted(np.where(ring == N)[0]),
      "%d skirt nodes, all on ring %d" % (len(mesh.skirt), N))

# flat
s = shape.snapshot(mesh, x0)
fold = max(q["foldMean"] for q in s["rings"])
check("flat: crown, skirt, folds",
      abs(s["crownHeight"]) < 1e-12 and abs(s["skirtRadiusMin"] - R) < 1e-12
      and abs(s["skirtRadiusMax"] - R) < 1e-12 and fold < 1e-5
      and s["foldedFraction"] == 0.0,
      "crown %.2g m, skirt radius %.15g .. %.15g m, largest ring fold "
      "angle %.2g deg, folded %.2g (tolerances 1e-12 m, 1e-5 deg)"
      % (s["crownHeight"], s["skirtRadiusMin"], s["skirtRadiusMax"], fold,
         s["foldedFraction"]))



def check_silhouette(name, snap, r):
    exact = 0.5 * M * r * r * math.sin(2 * math.pi / M)
    area = math.pi * snap["silhouetteDiameter"] ** 2 / 4
    check(name + ": silhouette", abs(area / exact - 1) < 5e-3,
          "area %.5f m^2, the %d-gon's %.5f (%.2g %%)"
          % (area, M, exact, 100 * (area / exact - 1)))


check_silhouette("flat", s, R)

# spherical cap
rho = 1.5
r0 = np.hypot(x0[:, 0], x0[:, 1])
phi = np.arctan2(x0[:, 1], x0[:, 0])
cap = x0.copy()
th = r0[cloth] / rho
cap[cloth] = np.column_stack([rho * np.sin(th) * np.cos(phi[cloth]),
                              rho * np.sin(th) * np.sin(phi[cloth]),
                              rho * np.cos(th)])
s = shape.snapshot(mesh, cap)
crown = rho * (1 - math.cos(R / rho))
skirt = rho * math.sin(R / rho)
check("cap: crown height", abs(s["crownHeight"] - crown) < 1e-12,
      "%.15g m, exact %.15g" % (s["crownHeight"], crown))
check("cap: skirt and largest radius",
      abs(s["skirtRadiusMean"] - skirt) < 1e-12
      and abs(s["largestRadius"] - skirt) < 1e-12,
      "skirt %.15g, largest %.15g m, exact %.15g"
      % (s["skirtRadiusMean"], s["largestRadius"], skirt))
check_silhouette("cap", s, skirt)
check("cap: nothing folded", s["foldedFraction"] == 0.0 and
      0.0 < max(q["foldMean"] for q in s["rings"]) < 90.0,
      "folded %.2g, fold angles %s deg" % (
          s["foldedFraction"],
          " ".join("%.3g" % q["foldMean"] for q in s["rings"])))

# folded flat along ring 15
rf = 15 * R / N
folded = x0.copy()
out = cloth & (ring > 15)
scale = (2 * rf - r0[out]) / r0[out]
folded[out, 0] *= scale
folded[out, 1] *= scale
coarse = shape.CanopyMesh(groups, tris, springs, rest, sgroups,
                          ring_edges=(0.0, 0.33, 0.66, 1.0))
s = shape.snapshot(coarse, folded)
fr = [q["foldedFraction"] for q in s["rings"]]
check("fold: fraction of edges folded",
      abs(s["foldedFraction"] - 16.0 / 928.0) < 1e-15,
      "%.6g, exact 16/928 = %.6g" % (s["foldedFraction"], 16.0 / 928.0))
check("fold: in the outer ring", fr[0] == 0.0 and fr[1] == 0.0 and
      abs(fr[2] - 0.05) < 1e-15 and s["rings"][2]["edges"] == 20 * M,
      "ring fractions %s, outer ring %d edges (exact 0, 0, 0.05 of %d)"
      % (" ".join("%.4g" % f for f in fr), s["rings"][2]["edges"], 20 * M))
check("fold: radii",
      abs(s["skirtRadiusMean"] - 0.5 * R) < 1e-12
      and abs(s["largestRadius"] - 0.75 * R) < 1e-12,
      "skirt %.15g m (0.5), largest %.15g m (0.75)"
      % (s["skirtRadiusMean"], s["largestRadius"]))

check_silhouette("fold", s, 0.75 * R)

# vented disc
xv, gv, tv, sv, rv, sgv, ringv = polar_mesh(first_ring=5)
vented = shape.CanopyMesh(gv, tv, sv, rv, sgv)
clothv = ringv >= 0
ok = (sorted(vented.skirt) == sorted(np.where(ringv == N)[0]) and
      np.max(np.abs(vented.s[ringv == 5])) < 1e-12 and
      np.max(np.abs(vented.s[ringv == N] - 1)) < 1e-12)
check("vent: skirt is the outer loop, s 0 at the hem", ok,
      "%d skirt nodes; s at the hem %.2g, at the skirt %.15g"
      % (len(vented.skirt), np.max(np.abs(vented.s[ringv == 5])),
         np.min(vented.s[ringv == N])))

# no payload
try:
    shape.CanopyMesh(np.zeros(len(groups), dtype=int), tris, springs, rest,
                     sgroups)
    check("no payload: refused", False, "no error")
except shape.ShapeError as e:
    check("no payload: refused", "payload" in str(e), str(e))

# through canopy.h5 and the report
try:
    import h5py
except ImportError:
    h5py = None
check("h5py available", h5py is not None,
      "python3-h5py (bin/setup installs it)")
if h5py is not None:
    tmp = tempfile.mkdtemp(prefix="test_shape.")
    try:
        os.makedirs(os.path.join(tmp, "postProcessing", "canopy"))
        # t = 1: flat; t = 2 and 3: the cap; t = 4: folded
        write_canopy_h5(shape.h5_path(tmp), groups, tris, springs, rest,
                        sgroups, [(t, {"x": x}) for t, x in
                                  ((1.0, x0), (2.0, cap), (3.0, cap),
                                   (4.0, folded))])
        a = shape.analyse(tmp, 1.5, 3.5)
        check("h5: interval's states averaged",
              a["states"] == 2 and abs(a["crownHeight"] - crown) < 1e-12,
              "%d states (t = %g .. %g), crown %.15g m (exact %.15g)"
              % (a["states"], a["timeFirst"], a["timeLast"],
                 a["crownHeight"], crown))
        a = shape.analyse(tmp, 0.0, 1.5)
        check("h5: flat state alone", a["states"] == 1 and
              abs(a["crownHeight"]) < 1e-12, "%d state, crown %.2g m"
              % (a["states"], a["crownHeight"]))
        try:
            shape.analyse(tmp, 5.0, 6.0)
            check("h5: empty interval refused", False, "no error")
        except shape.ShapeError as e:
            check("h5: empty interval refused", "no state" in str(e), str(e))
        os.remove(shape.h5_path(tmp))
        try:
            shape.analyse(tmp, 0.0, 6.0)
            check("h5: missing file refused", False, "no error")
        except shape.ShapeError as e:
            check("h5: missing file refused", "canopy.h5" in str(e), str(e))
    finally:
        shutil.rmtree(tmp)

finish()
