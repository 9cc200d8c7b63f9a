"""test_cross_resolution.py — known-answer tests of the cross's departure against resolution in python/canopyfoam/validation_tables.py (cross_resolution_lines, study crossResolution).

Run as:  /usr/bin/python3 tests/python/test_cross_resolution.py   (./Alltest cross_resolution)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic levels of a cross 1.27 m across with 0.335 m arms at 11, 16
and 22 cells across the span: the arm is 0.335 / (1.27 / n) = 2.9, 4.2
and 5.8 cells wide. D0 = 1 m and the descent over the growth window
4 m/s, so σ D0 / V = σ / 4. When every level departs (σ 2.0, 1.8 and
1.5 /s) the verdict gives both ends' σ and their change, 1.5 / 2.0 - 1
= -25 %, and says the finest does not make the cross stable; when the
finest does not depart it says the coarser levels' departure is the
arms' resolution; a missing level is named with its command and no
verdict is given. A later run at 11 cells on 1 rank beside the first,
on 2, at σ 3.0 against 2.0 /s, gives σ's scatter from round-off:
|3.0 / 2.0 - 1| = 50 %.
"""

from checks import check, finish
from canopyfoam.validation_runs import Run
from canopyfoam.validation_tables import cross_resolution_lines


def record(rate, ranks=2):
    growth = None if rate is None else {"rate": rate, "descent": 4.0}
    return {"complete": True, "ranks": ranks,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0}},
                         "steady": {"start": 4.0, "end": 8.0},
                         "descentVelocity": {"mean": 4.5, "ci95": 0.05},
                         "swing": {"onset": None if rate is None else 2.5,
                                   "growth": growth, "angleMax": 30.0,
                                   "angleRms": 20.0}}}


runs = [Run("test-cpd%d" % n, "parachutes/cross", "synthetic",
              ["-cellsPerDiameter", "%d" % n]) for n in (11, 16, 22)]

text = "\n".join(cross_resolution_lines(
    list(zip(runs, [record(2.0), record(1.8), record(1.5)]))))
check("cells across an arm", "| test-cpd11 | 2.9 |" in text
      and "| test-cpd22 | 5.8 |" in text, text.splitlines()[4][:80])
check("σ D0 / V", "| 2.00 /s | 0.50 |" in text and "| 1.50 /s | 0.38 |"
      in text, text.splitlines()[4][:120])
check("every level departs: both ends and the change",
      "σ 2.00 /s at 11 cells across the span, 1.50 /s at 22: -25 %" in text
      and "does not make the model's cross stable" in text,
      text.splitlines()[-1][:200])

text = "\n".join(cross_resolution_lines(
    list(zip(runs, [record(2.0), record(1.8), record(None)]))))
check("the finest does not depart: the arms' resolution",
      "At 22 cells across the span the payload's speed across gravity stays "
      "below 20 % of the descent to the run's end (the suspension within "
      "30.0°, rms 20.0°)" in text and "| none | — |" in text,
      text.splitlines()[-1][:200])

text = "\n".join(cross_resolution_lines(
    list(zip(runs, [record(2.0), None, record(1.5)]))))
check("a missing level is named, no verdict",
      "not run (`bin/canopy-validate run test-cpd16`)" in text
      and "needs every level run" in text and "stable." not in text,
      text.splitlines()[-1])

twin = Run("test-default", "parachutes/cross", "synthetic, 1 rank",
             ["-cellsPerDiameter", "11"])
text = "\n".join(cross_resolution_lines(
    list(zip(runs + [twin], [record(2.0), record(1.8), record(1.5),
                             record(3.0, ranks=1)]))))
check("the coarsest set-up on other ranks gives σ's scatter",
      "The coarsest set-up on 1 rank (test-default) departs at σ 3.00 /s "
      "against 2.00 on 2: round-off alone moves σ by 50 %." in text
      and "| test-default | 2.9 | 1 |" in text, text.splitlines()[-1][:300])

finish()
