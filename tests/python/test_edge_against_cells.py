"""test_edge_against_cells.py — known-answer tests of the fabric's edge against the air's resolution in python/canopyfoam/validation_tables.py (window_mean, edge_against_cells_lines, study edgeAgainstCells7ft).

Run as:  /usr/bin/python3 tests/python/test_edge_against_cells.py   (./Alltest edge_against_cells)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic records, D0 = 1 m (S0 = pi/4 m^2), rho = 1 kg/m^3, weight
W = 10 N. Each descent series is a constant V over 0-12 s except where
stated, so its mean over 8-12 s is V, its interval 0 and its drift 0,
and C_D0 = W / (rho V^2 S0 / 2) = 80 / (pi V^2): 1.019 at V = 5, 0.7074
at V = 6. A series rising linearly by 0.4 m/s over 8-12 s has the
drift +0.40 and the mean of its ends. Runs at 10 and 15 cells across D0
with edges 1.5 and 1 finest cells: edge 0.150 m at 10 cells and 1.5,
0.100 m at 10 cells and 1 or at 15 cells and 1.5, 0.0667 m at 15 and 1.
So (10, 1) against (15, 1.5) share 0.100 m; (10, 1.5) against (15, 1.5)
share 1.5 cells. A series that ends before the window is named so; a
run not run is named with its command. The verdict: C_D0 changed only
at the same length follows the ratio; changed only at the same ratio,
the length; changed at both (5 to 5.5 m/s at 0.100 m: -17.4 %; 6 to 5.5
at 1.5 cells and 5 to 4.2 at 1 cell: +19.0 % and +41.7 %), neither alone,
with the largest change of each kind.
"""

import math

from checks import check, finish
from canopyfoam.validation_runs import MESH_DICT, Run, SEVEN
from canopyfoam.validation_tables import edge_against_cells_lines, window_mean


def run(ident, cells, edge):
    return Run(ident, SEVEN, "synthetic", edits=[
        (MESH_DICT, "cellsPerDiameter", "%g" % cells),
        (MESH_DICT, "edgeLengthPerCell", "%g" % edge)])


def record(speed, rise=0.0, end=12.0):
    t = [0.1 * i for i in range(int(round(10 * end)) + 1)]
    vel = [speed + (rise * (x - 8) / 4 if x > 8 else 0.0) for x in t]
    return {"complete": True, "ranks": 2,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0},
                                        "rho": {"value": 1.0}},
                         "dragCoefficient": {"weight": 10.0},
                         "descentSeries": {"t": t, "v": vel}}}


w = window_mean(record(5.0, rise=0.4)["analysis"], 8, 12)
check("window mean and drift of a ramp",
      abs(w["mean"] - 5.2) < 1e-9 and abs(w["drift"] - 0.4) < 1e-9,
      "mean %.6f, drift %.6f" % (w["mean"], w["drift"]))
check("a series short of the window has no mean",
      window_mean(record(5.0, end=6.0)["analysis"], 8, 12) is None,
      "series to 6 s")

runs = [run("c10-e1.5", 10, 1.5), run("c10-e1", 10, 1),
        run("c15-e1.5", 15, 1.5), run("c15-e1", 15, 1)]
text = "\n".join(edge_against_cells_lines(list(zip(runs, [
    record(6.0), record(5.0), record(6.0, end=6.0), None]))))
rows = text.splitlines()
cd5 = 80 / (math.pi * 25)
check("a row: cells, edge in cells and metres, descent, C_D0",
      "| c10-e1 | 10 | 1 | 0.100 | 5.00 ± 0.00 (drift +0.00) | %.3f |"
      % cd5 in text, [r for r in rows if r.startswith("| c10-e1 ")])
check("a series short of the window and a run not run are named",
      "| c15-e1.5 | 15 | 1.5 | — | its series does not cover 8-12 s | |"
      in text and "not run (`bin/canopy-validate run c15-e1`)" in text,
      rows[5:7])
check("no complete pair across resolutions: said so",
      "No pair of runs at two air resolutions" in text, rows[-2])

text = "\n".join(edge_against_cells_lines(list(zip(runs, [
    record(6.0), record(5.0), record(6.0), record(5.0)]))))
change_metres = 100 * (25.0 / 36 - 1)     # 5 m/s to 6 m/s: C_D0 x 25/36
check("the same edge in metres across resolutions",
      "- edge 0.100 m: c10-e1 (10 cells) to c15-e1.5 (15 cells): C_D0 "
      "%+.1f %% (beyond the combined ± 0.0 %%)" % change_metres in text,
      [r for r in text.splitlines() if r.startswith("- edge 0.1")])
check("the same edge in cells across resolutions, no change",
      "- edge 1.5 finest cells: c10-e1.5 (10 cells) to c15-e1.5 (15 "
      "cells): C_D0 +0.0 % (within the combined ± 0.0 %)" in text
      and "- edge 1 finest cells: c10-e1 (10 cells) to c15-e1 (15 cells)"
      in text, [r for r in text.splitlines() if "finest cells:" in r])
check("runs at one resolution are not paired",
      "c10-e1.5 (10 cells) to c10-e1" not in text, "")
check("moved at the same length only: follows the ratio",
      "C_D0 follows the edge's ratio to the cells" in text,
      text.splitlines()[-2])

text = "\n".join(edge_against_cells_lines(list(zip(runs, [
    record(6.0), record(5.0), record(5.0), record(4.0)]))))
check("moved at the same ratio only: follows the length",
      "C_D0 follows the edge's length" in text, text.splitlines()[-2])

text = "\n".join(edge_against_cells_lines(list(zip(runs, [
    record(6.0), record(5.0), record(5.5), record(4.2)]))))
check("moved at both: neither alone, with the largest changes",
      "neither the edge's length nor its ratio to the cells alone sets "
      "C_D0: refining the air moves it by up to %.1f %% at the same "
      "length and %.1f %% at the same ratio"
      % (100 * (1 - 25 / 30.25), 100 * (25 / 4.2 ** 2 - 1)) in text,
      text.splitlines()[-2])

finish()
