"""test_tension_field_shape.py — known-answer tests of python/canopyfoam/tension_field_shape.py (a canopy's shape with no hoop stress).

Run as:  /usr/bin/python3 tests/python/test_tension_field_shape.py   (./Alltest tension_field_shape)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

Exact answers:
  Mylar balloon (phi = pi/2 at the rim): r / R0 = 1/A = 0.7627597635 and
      half-thickness / R0 = B/A = 0.4569465810, A = 1.3110287771 and
      B = 0.5990701173 the lemniscate constants (Paulsen 1994). Classical
      Runge-Kutta with 2000 steps on a smooth ODE errs by ~1e-12; 1e-8
      allows for the bisection's and the scan's rounding.
  First integral sin(phi) = k r^2 / 2: the widest radius is sqrt(2/k).
      The profile's largest sampled r lies within half a step (2.5e-4) of
      the widest point, where r is stationary: off by at most
      k (2.5e-4)^2 / 2 ~ 1.4e-7; checked to 1e-6.
  Skirt condition cos(phi_s) = -r_s / L_s: solved by bisection to 1e-13
      in k; checked to 1e-9.
  Lines of infinite length pull the skirt straight down (phi_s -> pi/2):
      the canopy tends to the Mylar half; at L_s = 1e4 R0 the skirt's
      angle is off by r_s / L_s ~ 8e-5 rad, which moves r_max by less
      than 1e-4.
  compare(): a polar cloth (centre node and 16 rings of 16 nodes at rest
      radius i/16, spokes at rest length 1/16) placed on the model's own
      profile (ring i at r(i/16), z(i/16)), a payload on the axis below,
      written as canopy.h5: each ring's mean radius and depth equal the
      model's at the nearest of its 2001 samples (within 5e-4 in s, so
      1e-3 in r and z), and the rest radius is 1.
"""

import math
import os
import shutil
import tempfile

import numpy as np

from checks import check, finish, write_canopy_h5
from canopyfoam import shape
from canopyfoam.tension_field_shape import canopy, compare, mylar_balloon

A = 1.3110287771
B = 0.5990701173


m = mylar_balloon()
check("Mylar balloon's radius", abs(m["r_max"] - 1 / A) < 1e-8,
      "r/R0 = %.10f (1/A = %.10f)" % (m["r_max"], 1 / A))
check("Mylar balloon's half-thickness", abs(m["depth"] - B / A) < 1e-8,
      "z/R0 = %.10f (B/A = %.10f)" % (m["depth"], B / A))

c = canopy(2.0)  # lines of one nominal diameter (the 7 ft tutorial)
widest = math.sqrt(2.0 / c["k"])
check("first integral: widest radius sqrt(2/k)",
      abs(c["r_max"] - widest) < 1e-6,
      "r_max = %.8f, sqrt(2/k) = %.8f" % (c["r_max"], widest))
skirt = math.cos(c["phi_skirt"]) + c["r_skirt"] / 2.0
check("the skirt's tangent runs along the lines", abs(skirt) < 1e-9,
      "cos(phi_s) + r_s/L_s = %.2e" % skirt)
check("lines of one D0: Dp/D0 in the handbook's 0.67-0.70",
      0.67 <= c["r_max"] <= 0.70, "Dp/D0 = %.4f" % c["r_max"])

shorter, longer = canopy(1.7), canopy(3.0)
check("longer lines open the canopy wider",
      shorter["r_max"] < c["r_max"] < longer["r_max"],
      "Dp/D0 %.4f / %.4f / %.4f for lines of 0.85 / 1 / 1.5 D0"
      % (shorter["r_max"], c["r_max"], longer["r_max"]))

far = canopy(1e4)
check("infinitely long lines: the Mylar balloon's half",
      abs(far["r_max"] - 1 / A) < 1e-4,
      "r_max = %.6f at L_s = 1e4 R0" % far["r_max"])

try:
    canopy(0.0)
    check("zero line length refused", False, "no error")
except ValueError as e:
    check("zero line length refused", True, str(e))

# compare() on a cloth placed on the model's profile
try:
    import h5py
except ImportError:
    h5py = None
if h5py is None:
    check("compare: h5py available", False, "python3-h5py is missing")
else:
    rings, per = 16, 16
    profile = c["profile"]
    samples = np.linspace(0.0, 1.0, len(profile))
    rest = [(0.0, 0.0, 0.0)]
    placed = [(0.0, 0.0, 0.0)]
    for i in range(1, rings + 1):
        k = int(np.argmin(np.abs(samples - i / rings)))
        r, z = profile[k, 0], profile[k, 1]
        for j in range(per):
            a = 2 * math.pi * j / per
            rest.append((i / rings * math.cos(a), i / rings * math.sin(a),
                         0.0))
            placed.append((r * math.cos(a), r * math.sin(a), -z))

    def node(i, j):
        return 0 if i == 0 else 1 + (i - 1) * per + j % per
    tris = [(0, node(1, j), node(1, j + 1)) for j in range(per)]
    for i in range(1, rings):
        for j in range(per):
            tris.append((node(i, j), node(i + 1, j), node(i + 1, j + 1)))
            tris.append((node(i, j), node(i + 1, j + 1), node(i, j + 1)))
    payload = len(rest)
    rest.append((0.0, 0.0, -3.0))
    placed.append((0.0, 0.0, -3.0))
    rest, placed = np.array(rest), np.array(placed)
    groups = np.zeros(len(rest), dtype=np.int32)
    groups[payload] = shape.GROUP_PAYLOAD
    springs = np.array(sorted(shape.edges_of(tris)), dtype=np.int32)
    lengths = np.linalg.norm(rest[springs[:, 0]] - rest[springs[:, 1]],
                             axis=1)
    tmp = tempfile.mkdtemp(prefix="test_tension_field_shape.")
    try:
        os.makedirs(os.path.join(tmp, "postProcessing", "canopy"))
        write_canopy_h5(shape.h5_path(tmp), groups, tris, springs, lengths,
                        np.zeros(len(springs), dtype=np.int32),
                        [(1.0, {"x": placed})])
        rows = compare(tmp, 0.0, 2.0)
        worst_r = max(abs(row[2] - row[3]) for row in rows)
        worst_z = max(abs(row[5] - row[6]) for row in rows)
        check("compare: a cloth on the model's profile",
              len(rows) == 9 and worst_r < 1e-3 and worst_z < 1e-3,
              "%d rows, largest |r - model| %.1e, |depth - model| %.1e"
              % (len(rows), worst_r, worst_z))
    finally:
        shutil.rmtree(tmp)

finish()
