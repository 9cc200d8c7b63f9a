"""test_over_window.py — known-answer tests of re-reading records over one common window in python/canopyfoam/validation_tables.py (over_window, study edgeLength7ftCpd27).

Run as:  /usr/bin/python3 tests/python/test_over_window.py   (./Alltest over_window)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic records, D0 = 1 m (S0 = pi/4 m^2), rho = 1 kg/m^3, weight
W = 10 N, so C_D0 = W / (rho V^2 S0 / 2) = 80 / (pi V^2). A series at
6 m/s to 8 s and 5 m/s after it has the mean 5 over 8-12 s where its
record's own 5-12 s interval said 5.43: over the window C_D0 is
80 / (25 pi) = 1.019, and the drift 0. The projected diameter and the
shape stay the record's; its breathing peak stays where its interval is
the window and is marked read over another interval where it is not.
A series that ends before the window and a run not run become None;
the original record is not changed.
"""

import math

from checks import check, finish
from canopyfoam.validation_runs import MESH_DICT, Run, SEVEN
from canopyfoam.validation_tables import edge_levels_lines, over_window


def run(ident, edge):
    return Run(ident, SEVEN, "synthetic", edits=[
        (MESH_DICT, "cellsPerDiameter", "10"),
        (MESH_DICT, "edgeLengthPerCell", "%g" % edge)])


def record(start, end=12.0):
    t = [0.05 * i for i in range(int(round(20 * end)) + 1)]
    vel = [6.0 if x < 8 else 5.0 for x in t]
    return {"complete": True, "ranks": 2,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0},
                                        "rho": {"value": 1.0}},
                         "steady": {"start": start, "end": end},
                         "descentVelocity": {"mean": 5.43, "ci95": 0.3,
                                             "drift": -1.0, "std": 0.5},
                         "dragCoefficient": {"weight": 10.0,
                                             "weightBalance": 0.86},
                         "projectedDiameter": {"mean": 0.8},
                         "breathing": {"resolved": True, "frequency": 1.2,
                                       "amplitude": 0.04},
                         "descentSeries": {"t": t, "v": vel}}}


runs = [run("own-5-12", 1.25), run("own-8-12", 0.83), run("short", 0.56),
        run("not-run", 0.4)]
records = [record(5.0), record(8.0), record(5.0, end=6.0), None]
out = dict((r.ident, rec) for r, rec in over_window(
    list(zip(runs, records)), 8.0, 12.0))

a = out["own-5-12"]["analysis"]
cd = 80 / (math.pi * 25)
check("the descent and C_D0 over the window",
      abs(a["descentVelocity"]["mean"] - 5.0) < 1e-9
      and abs(a["descentVelocity"]["drift"]) < 1e-9
      and abs(a["dragCoefficient"]["weightBalance"] - cd) < 1e-9,
      "V %.6f, drift %.6f, C_D0 %.6f (expected %.6f)" % (
          a["descentVelocity"]["mean"], a["descentVelocity"]["drift"],
          a["dragCoefficient"]["weightBalance"], cd))
check("the projected diameter and the series' spread stay the record's",
      a["projectedDiameter"]["mean"] == 0.8
      and a["descentVelocity"]["std"] == 0.5, a["projectedDiameter"])
check("a peak read over another interval is not a resolved one",
      not a["breathing"]["resolved"] and a["breathing"]["overOtherInterval"],
      a["breathing"])
check("a peak read over the window stays",
      out["own-8-12"]["analysis"]["breathing"]["resolved"],
      out["own-8-12"]["analysis"]["breathing"])
check("a short series and a run not run become None",
      out["short"] is None and out["not-run"] is None,
      (out["short"], out["not-run"]))
check("the original record is unchanged",
      records[0]["analysis"]["descentVelocity"]["mean"] == 5.43
      and records[0]["analysis"]["dragCoefficient"]["weightBalance"] == 0.86
      and records[0]["analysis"]["breathing"]["resolved"],
      records[0]["analysis"]["descentVelocity"])
text = "\n".join(edge_levels_lines(over_window(
    list(zip(runs[:2], records[:2])), 8.0, 12.0)))
check("the edge table names a peak read over another interval",
      "read over another interval" in text and "1.20 Hz" in text,
      [r for r in text.splitlines() if r.startswith("| ")])

finish()
