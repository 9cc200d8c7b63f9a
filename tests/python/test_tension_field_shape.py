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
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "python"))
from canopyfoam.tension_field_shape import canopy, mylar_balloon  # noqa: E402

A = 1.3110287771
B = 0.5990701173
failures = 0


def check(name, ok, detail):
    global failures
    print("%s  %s: %s" % ("PASS" if ok else "FAIL", name, detail))
    if not ok:
        failures += 1


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

print("%d failure(s)" % failures)
sys.exit(1 if failures else 0)
