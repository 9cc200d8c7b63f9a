"""test_air_levels.py — known-answer tests of a resolution study whose levels continue one source run (python/canopyfoam/validation_tables.py: study_levels, air_levels_lines; study resolution7ftMapped).

Run as:  /usr/bin/python3 tests/python/test_air_levels.py   (./Alltest air_levels)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic records, D0 = 1 m: levels at 40, 27 and 18 cells across D0
continuing a source run (rest_state_of "t-source"), listed fine first
with the source (18 cells, from rest) last, as the study lists them.
Every level descends at 6.0 ± 0.03 m/s (drift +0.01), so C_D0's 95 %
relative half-width is 2 x 0.03 / 6 = 1.0 % and a pair's combined one
hypot(1, 1) = 1.4 %; Dp = 0.8 D0, so C_Dp = C_D0 / 0.64. C_D0 0.80,
0.76, 0.74 at 18, 27, 40 cells: -5.0 % then -2.6 %, both beyond 1.4 %,
ratio 0.53: converging. study_levels keeps the three levels and drops
the source, whose C_D0 (0.99) must appear nowhere; the GCI is computed
over 40 / 27 / 18 cells. Levels that each continue a source of their own
(not in the study) are all kept. A level not run is named with its command.

start_transient_lines on descent series held constant in each 0.5 s
bin: 5.0, 4.0, 5.5, 6.0, 5.8 m/s gives the bins, "lowest 4.00 m/s at
0.5-1 s, then highest 6.00 at 1.5-2 s; last 5.80"; a series falling bin
by bin (6.0, 5.9, 5.8) has its lowest in the last bin and says so.
"""

from checks import check, finish
from canopyfoam.validation_runs import Run, SEVEN
from canopyfoam.validation_tables import (air_levels_lines,
                                          start_transient_lines, study_levels)


def level(ident, cells, source="t-source"):
    return Run(ident, SEVEN, "synthetic",
                 ["-cellsPerDiameter", "%d" % cells], rest_state_of=source)


def record(cd, iterations=1.05, wall=600.0, cells=1000):
    return {"complete": True, "ranks": 2, "wall": wall, "cells": cells,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0}},
                         "descentVelocity": {"mean": 6.0, "ci95": 0.03,
                                             "drift": 0.01},
                         "dragCoefficient": {"weightBalance": cd},
                         "projectedDiameter": {"mean": 0.8},
                         "breathing": {"resolved": True, "frequency": 1.2,
                                       "amplitude": 0.04},
                         "coupling": {"meanIterationsSteady": iterations}}}


runs = [level("t-40", 40), level("t-27", 27), level("t-18", 18),
        level("t-source", 18, source=None)]


def study(*cds):
    return [(r, None if c is None else record(c))
            for r, c in zip(runs, cds)]


kept = study_levels(study(0.74, 0.76, 0.80, 0.99))
check("study_levels keeps the levels and drops the source",
      [r.ident for r, _ in kept] == ["t-40", "t-27", "t-18"],
      [r.ident for r, _ in kept])

own = [level("o-27", 27, source="s-27"), level("o-18", 18, source="s-18"),
       level("o-12", 12, source="s-12")]
check("levels that each continue their own source are all kept",
      [r.ident for r, _ in study_levels([(r, None) for r in own])]
      == ["o-27", "o-18", "o-12"], "")

text = "\n".join(air_levels_lines(kept))
rows = text.splitlines()
check("coarse first: cells, mesh cells, descent, C_D0 ± half-width, Dp/D0, "
      "C_Dp, breathing, iterations, wall time",
      rows[2] == "| 18 | 1000 | t-18 | 6.00 ± 0.03 (+0.01) | 0.800 ± 1.0 % "
      "| 0.800 | 1.250 | 1.20 Hz, 4.0 cm | 1.05 | 10 min |"
      and "| 40 | 1000 | t-40 |" in rows[4], rows[2])
check("each refinement against the combined interval",
      "- 18 to 27 cells across D0: C_D0 -5.0 % (beyond the combined ± 1.4 %)."
      in text and "- 27 to 40 cells across D0: C_D0 -2.6 % (beyond" in text,
      [r for r in rows if r.startswith("- ")])
check("shrinking changes converge",
      "(ratio 0.53): the levels converge" in text,
      [r for r in rows if r.startswith("- Successive")])
check("the GCI over the three levels",
      "from t-40, t-27, t-18 (40 / 27 / 18 cells across D0)" in text
      and "| C_D0 (weight) | 0.74, 0.76, 0.8 |" in text,
      [r for r in rows if "C_D0 (weight)" in r or "Grid" in r])
check("the source appears nowhere", "0.99" not in text and "t-source"
      not in text, "t-source" in text)

text = "\n".join(air_levels_lines(study_levels(
    study(None, 0.76, 0.80, 0.99))))
check("a level not run is named with its command",
      "| 40 | — | t-40 | not run (`bin/canopy-validate run t-40`) |" in text
      and "needs three complete runs, has 2" in text,
      [r for r in text.splitlines() if "t-40" in r])



def series_record(bins, width=0.5, per_bin=10):
    """A record whose descent series holds bins[k] over bin k."""
    t = [k * width + (j + 0.5) * width / per_bin
         for k in range(len(bins)) for j in range(per_bin)]
    v_ = [b for b in bins for _ in range(per_bin)]
    return {"complete": True, "analysis": {"steady": {"start": 1.0},
                                           "descentSeries": {"t": t,
                                                             "v": v_}}}


text = "\n".join(start_transient_lines(
    [(runs[0], series_record([5.0, 4.0, 5.5, 6.0, 5.8]))], 0.5, "Title:"))
check("a dip and a recovery: the bins, the lowest, the highest after it",
      text.startswith("Title:") and "5.00, 4.00, 5.50, 6.00, 5.80 m/s in 0.5 "
      "s bins; lowest 4.00 m/s at 0.5-1 s, then highest 6.00 at 1.5-2 s; "
      "last 5.80." in text, [l for l in text.splitlines() if l.startswith("- ")])
text = "\n".join(start_transient_lines(
    [(runs[0], series_record([6.0, 5.9, 5.8]))]))
check("the lowest in the last bin", "lowest 5.80 m/s at 1-1.5 s, the last "
      "bin." in text and "highest" not in text,
      [l for l in text.splitlines() if l.startswith("- ")])

finish()
