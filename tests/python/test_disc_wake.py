"""test_disc_wake.py — known-answer tests of study discWake7ft's reading: the stream's angle to the disc's axis a run sets (validation_tables.stream_incidence) and the drag along the stream (disc_wake_lines).

Run as:  /usr/bin/python3 tests/python/test_disc_wake.py   (./Alltest disc_wake)
Prints one PASS/FAIL line per check; exits 1 if any fails.

A stream (U sin a, 0, U cos a) is at a to the axis +z, whatever U; a run
without the edit streams along the axis. A disc of D0 = 2.134 m in air of
1.2 kg/m^3 at 5 m/s has q S0 = 15 pi 2.134^2 / 4 = 53.6500 N. A force
(F_x, F_y, F_z) on it at a to the stream has the drag F_z cos a + F_x
sin a along the stream: for (10, 3, 60) N at 30 degrees, 56.962 N, C_D
1.0617; along the axis at 0 degrees the drag is F_z alone, and a run
without a record is listed as not run.
"""

import math

from checks import check, finish
from canopyfoam.validation_runs import DISC_TILTED_RUNS, SEVEN, Run
from canopyfoam.validation_tables import (disc_reference_force,
                                          disc_wake_lines, stream_incidence)


def run(ident, stream=None):
    edits = [] if stream is None else [("0.orig/U", "internalField",
                                        "uniform (%r %r %r)" % stream)]
    return Run(ident, SEVEN, "test disc", [], edits, steady_start=20,
               steady_end=40)


def record(force):
    return {"complete": True, "analysis": {
        "parameters": {"nominalDiameter": {"value": 2.134},
                       "rho": {"value": 1.2}},
        "canopyLoad": {"force": list(force), "forceStd": [1.0, 2.0, 3.0],
                       "forceCi95": [0.1, 0.2, 0.5]}}}


a = math.radians(30.0)
tilted = run("tilted", (7.0 * math.sin(a), 0.0, 7.0 * math.cos(a)))
check("incidence: 30 degrees from the stream's components",
      abs(stream_incidence(tilted) - 30.0) < 1e-9,
      "%.12g" % stream_incidence(tilted))
check("incidence: 0 without the edit", stream_incidence(run("axis")) == 0.0,
      "%g" % stream_incidence(run("axis")))
check("incidence: the study's tilted run is at 2 degrees",
      abs(stream_incidence(DISC_TILTED_RUNS[0]) - 2.0) < 1e-4,
      "%.8g" % stream_incidence(DISC_TILTED_RUNS[0]))

q_s0 = disc_reference_force(record((0, 0, 0))["analysis"])
check("q S0 of the 7 ft disc at 5 m/s", abs(q_s0 - 53.6500) < 5e-4,
      "%.6f" % q_s0)

force = (10.0, 3.0, 60.0)
drag = 60.0 * math.cos(a) + 10.0 * math.sin(a)
lines = disc_wake_lines([(tilted, record(force)),
                         (run("axis"), record(force)),
                         (run("absent"), None)])
rows = {line.split("|")[1].strip(): line for line in lines
        if line.startswith("| ") and not line.startswith("| run")}
check("drag along a tilted stream: F_z cos a + F_x sin a",
      "| %.3f ± 0.009 |" % (drag / q_s0) in rows["tilted"]
      and abs(drag / q_s0 - 1.0617) < 5e-5,
      "%.5f %s" % (drag / q_s0, rows["tilted"]))
check("drag along the axis: F_z alone",
      "| %.3f ± 0.009 |" % (60.0 / q_s0) in rows["axis"], rows["axis"])
check("the interval and the side forces are listed",
      "| 20-40 s | 60.00 ± 0.50; 3.00 | 10.00 ± 1.00 | 3.00 ± 2.00 |"
      in rows["axis"], rows["axis"])
check("a run without a record is not run", "not run" in rows["absent"],
      rows["absent"])

finish()
