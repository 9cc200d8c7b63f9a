"""test_tilt.py — known-answer tests of the incidence studies' reading in python/canopyfoam/validation_tables.py: tilt_coefficients (a held canopy's force and moment coefficients) and trim_angle.

Run as:  /usr/bin/python3 tests/python/test_tilt.py   (./Alltest tilt)
Prints one PASS/FAIL line per check; exits 1 if any fails.

tilt_coefficients on a synthetic analysis: D0 = 2 m, rho = 1.25 kg/m^3, a
held run's 4 m/s stream (q S0 = 10 pi N), the load's mean (10 pi,
-5 pi, 20 pi) N and its moment's y component -40 pi N m: C_N = 1,
C_Y = -0.5, C_T = 2, C_m = -M_y / (q S0 D0) = 2, the force atan(1/2)
= 26.565° off the axis. On the guide wire in a wind W = 3 m/s with a
descent of 4 m/s: the relative wind 5 m/s at atan(3/4) = 36.870°.
trim_angle: C_m (0, 0.02), (10, 0.01), (20, -0.03) falls through zero
at 12.5° exactly; negative at every angle above 0 says "restoring from"
the smallest; all positive says none is found. tilt_lines: a row per run
(a run not made says why) and the trim of the complete ones.
"""

import math

from checks import check, finish
from canopyfoam.validation_runs import CROSSWIND_T10, Run, T10, TILT_STREAM
from canopyfoam.validation_tables import (tilt_coefficients, tilt_lines,
                                          tilt_stream, trim_angle)


def analysis(descent=0.0):
    pi = math.pi
    return {"parameters": {"nominalDiameter": {"value": 2.0},
                           "rho": {"value": 1.25}},
            "descentVelocity": {"mean": descent},
            "canopyLoad": {"force": [10 * pi, -5 * pi, 20 * pi],
                           "forceCi95": [pi, None, pi],
                           "moment": [0.0, -40 * pi, 0.0],
                           "momentStd": [0.0, 4 * pi, 0.0]}}


held = Run("test-tilt", T10, "synthetic")
TILT_STREAM["test-tilt"] = (4.0, 20.0)
c = tilt_coefficients(held, analysis())
want = {"CN": 1.0, "CY": -0.5, "CT": 2.0, "Cm": 2.0, "CNci": 0.1,
        "CmStd": 0.2, "offAxis": math.degrees(math.atan(0.5)),
        "alpha": 20.0}
check("held: coefficients", all(abs(c[k] - w) < 1e-12 for k, w in
                                want.items()) and c["CYci"] is None,
      ", ".join("%s %.12g" % (k, c[k]) for k in sorted(want)))

wired = Run("test-wind", T10, "synthetic")
CROSSWIND_T10["test-wind"] = 3.0
speed, alpha = tilt_stream(wired, analysis(descent=4.0))
check("wind: relative wind", abs(speed - 5.0) < 1e-12 and
      abs(alpha - math.degrees(math.atan2(3.0, 4.0))) < 1e-12,
      "%.12g m/s at %.12g°" % (speed, alpha))
check("wind: no angle before the run", tilt_stream(wired) is None,
      "%s" % (tilt_stream(wired),))

t = trim_angle([(20, -0.03), (0, 0.02), (10, 0.01)])
check("trim: crossing", t == "12.5°", t)
t = trim_angle([(0, 0.01), (10, -0.02), (20, -0.05)])
check("trim: crossing on the first interval", t == "3.3°", t)
t = trim_angle([(0, -0.005), (10, -0.06), (30, -0.15)])
check("trim: restoring everywhere", t.startswith("C_m < 0") and
      "from 10°" in t, t)
t = trim_angle([(0, 0.0), (10, 0.02), (30, 0.05)])
check("trim: none", t == "none between the angles held", t)

# tilt_lines: the table and the trim from two held angles (the moment's
# y component -40 pi N m at 20° gives C_m = 2, +40 pi at 40° gives -2, so
# C_m falls through zero at 30° exactly)
records = []
for ident, alpha, my in (("test-tilt-a", 20.0, -40.0), ("test-tilt-b", 40.0,
                                                         40.0)):
    run = Run(ident, T10, "synthetic")
    TILT_STREAM[ident] = (4.0, alpha)
    a = analysis()
    a["canopyLoad"]["moment"] = [0.0, my * math.pi, 0.0]
    records.append((run, {"analysis": a, "complete": True,
                          "state": "complete", "wall": 120.0, "ranks": 2},
                    None))
records.append((Run("test-tilt-c", T10, "synthetic"), None,
                "not run"))
TILT_STREAM["test-tilt-c"] = (4.0, 60.0)
lines = tilt_lines(records)
text = "\n".join(lines)
check("table: a row per run", sum(1 for x in lines if x.startswith(
    "| test-tilt-")) == 3 and "| test-tilt-a | complete | 20.0 | 2.000 | "
      "1.000 ± 0.100 | -0.500 ± — | 26.6 | 2.0000 ± 0.2000 | 2.0 min on 2 |"
      in lines and "| test-tilt-c | not run | 60.0 |" in text,
      "rows: %s" % [x for x in lines if x.startswith("| test-tilt-")])
check("table: the trim", "C_m through zero, restoring slope, linear "
      "between the angles held): 30.0°" in text,
      [x for x in lines if "Trim" in x][0][-160:])

finish()
