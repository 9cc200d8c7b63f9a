"""test_disc_edge.py — known-answer tests of study discEdge7ft's reading: the retraction a run sets (validation_tables.edge_retraction) and where two levels' drags agree (edge_crossings, disc_edge_lines).

Run as:  /usr/bin/python3 tests/python/test_disc_edge.py   (./Alltest disc_edge)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Records whose drag is the first-order model F_n(r) = F (1 + 2 k (c - r)/n)
with F = 200 N, k = 1.3, c = 1.1 cells at n = 8, 12 and 18 cells across
D0 and r = 0 and 1: each consecutive pair of levels agrees at r = c
exactly (to round-off) and the drop from r = 0 to 1 is 1/n's ratio
(1.5); a level without both retractions gives no pair, and one level
alone no table. A run without the entry sets no retraction; the last
edit of the entry counts.
"""

import math

from checks import check, finish
from canopyfoam.validation_runs import PROPS, SEVEN, Run
from canopyfoam.validation_tables import (disc_edge_lines, edge_crossings,
                                          edge_retraction)

ENTRY = "coupling/forcing/freeEdgeRetractionCells"
F, K, C = 200.0, 1.3, 1.1


def run(n, r):
    edits = [] if r == 0 else [(PROPS, ENTRY, "%g" % r)]
    return Run("disc-n%d-r%g" % (n, r), SEVEN, "test disc",
               ["-cellsPerDiameter", "%d" % n], edits)


def record(force):
    """A complete record of the disc's mean force against the stream."""
    return {"complete": True, "analysis": {
        "parameters": {"nominalDiameter": {"value": 2.134},
                       "rho": {"value": 1.2}},
        "pressureForceAgainstGravity": {"mean": force, "std": 0.0,
                                        "drift": 0.0}}}


def model(n, r):
    return F * (1 + 2 * K * (C - r) / n)


check("retraction: none without the entry", edge_retraction(run(12, 0)) == 0,
      "%g" % edge_retraction(run(12, 0)))
twice = Run("x", SEVEN, "x", [], [(PROPS, ENTRY, "0.5"), (PROPS, ENTRY, "1.5")])
check("retraction: the last edit counts", edge_retraction(twice) == 1.5,
      "%g" % edge_retraction(twice))

results = [(run(n, r), record(model(n, r))) for n in (8, 12, 18)
           for r in (0, 1)]
pairs = edge_crossings(results)
check("crossings: two pairs of consecutive levels",
      [(p[0], p[1]) for p in pairs] == [(8, 12), (12, 18)], "%s" % pairs)
for n_a, n_b, r0, r1, fa0, fb0, fa1, fb1, crossing, ratio in pairs:
    check("crossings %g/%g: the drags agree at c" % (n_a, n_b),
          abs(crossing - C) < 1e-12, "%.15g" % crossing)
    check("crossings %g/%g: the drop scales as 1/n" % (n_a, n_b),
          abs(ratio - n_b / n_a) < 1e-12, "%.15g" % ratio)
    check("crossings %g/%g: the forces as given" % (n_a, n_b),
          (fa0, fb1) == (model(n_a, 0), model(n_b, 1)), "%g %g" % (fa0, fb1))

lines = disc_edge_lines(results)
check("table: a row per pair with the crossing",
      sum(1 for line in lines if line.startswith("| 8, 12 |")
          and "| 1.10 |" in line) == 1
      and sum(1 for line in lines if line.startswith("| 12, 18 |")) == 1,
      "\n".join(lines))

# the 18-cell level without its r = 1 run: one pair left
partial = [(r_, rec) for r_, rec in results
           if not (r_.ident == "disc-n18-r1")]
check("crossings: a level without both retractions pairs with none",
      [(p[0], p[1]) for p in edge_crossings(partial)] == [(8, 12)],
      "%s" % edge_crossings(partial))
alone = [(r_, rec) for r_, rec in results if "-n12-" in r_.ident]
check("table: one level alone gives none",
      disc_edge_lines(alone)[0].startswith("The crossing needs"),
      "%s" % disc_edge_lines(alone))
# the model's levels differ without the retraction (else the crossing
# would not be defined)
check("model: the drags differ without the retraction",
      not math.isclose(model(8, 0), model(18, 0)),
      "%g %g" % (model(8, 0), model(18, 0)))

finish()
