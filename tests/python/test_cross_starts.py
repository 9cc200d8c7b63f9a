"""test_cross_starts.py — known-answer tests of the cross's flat and folded starts compared in python/canopyfoam/validation_tables.py (cross_starts_lines, study crossStarts).

Run as:  /usr/bin/python3 tests/python/test_cross_starts.py   (./Alltest cross_starts)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic records, D0 = 1 m. The flat start descends at 4.80 ± 0.03
m/s, the folded at 4.84 ± 0.04: they differ by +0.04 m/s, within the
combined interval hypot(0.03, 0.04) = 0.05 m/s. Moved to 4.90 the folded
start differs by +0.10, beyond it. A drift of 0.08 m/s (more than the
folded run's 0.04 interval) makes the verdict say the runs are too short;
a drift of 0.02 does not. A projected diameter of 0.8 m is Dp/D0 0.80.
A missing start is named with its command and no verdict is given.
"""

from checks import check, finish
from canopyfoam.validation_runs import Run
from canopyfoam.validation_tables import cross_starts_lines


def record(mean, ci95, drift=0.0):
    return {"complete": True, "ranks": 2,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0}},
                         "steady": {"start": 2.67, "end": 4.0},
                         "descentVelocity": {"mean": mean, "ci95": ci95,
                                             "drift": drift},
                         "dragCoefficient": {"weightBalance": 0.7},
                         "projectedDiameter": {"mean": 0.8},
                         "swing": {"angleMax": 3.0, "angleRms": 2.0}}}


runs = [Run("test-flat", "parachutes/cross", "synthetic"),
        Run("test-folded", "parachutes/crossFolded", "synthetic")]

text = "\n".join(cross_starts_lines(
    list(zip(runs, [record(4.80, 0.03, 0.02), record(4.84, 0.04, -0.02)]))))
check("the row: descent, drift, C_D, Dp/D0, suspension",
      "| test-flat | 4.80 ± 0.03 (2.67-4 s) | +0.02 | 0.70 | 0.80 | "
      "3.0° / 2.0° |" in text, text.splitlines()[4])
check("within the combined interval, steady",
      "The folded start descends +0.04 m/s from the flat one's, within "
      "their combined interval (± 0.05 m/s)." in text
      and "too short" not in text, text.splitlines()[-1])

text = "\n".join(cross_starts_lines(
    list(zip(runs, [record(4.80, 0.03, 0.02), record(4.90, 0.04)]))))
check("beyond the combined interval",
      "descends +0.10 m/s from the flat one's, beyond their combined "
      "interval (± 0.05 m/s)" in text, text.splitlines()[-1])

text = "\n".join(cross_starts_lines(
    list(zip(runs, [record(4.80, 0.03, 0.02), record(4.84, 0.04, 0.08)]))))
check("a drift beyond the interval: too short to tell",
      "test-folded still drifts by more than its interval over the "
      "reading: the runs are too short" in text
      and "test-flat still" not in text, text.splitlines()[-1])

text = "\n".join(cross_starts_lines(
    list(zip(runs, [record(4.80, 0.03), None]))))
check("a missing start is named, no verdict",
      "not run (`bin/canopy-validate run test-folded`)" in text
      and "needs both starts run" in text and "descends" not in text,
      text.splitlines()[-1])

finish()
