"""test_edge_levels.py — known-answer tests of the fabric's edge levels compared in python/canopyfoam/validation_tables.py (edge_levels_lines, studies edgeLength7ft and edgeLength7ftLong).

Run as:  /usr/bin/python3 tests/python/test_edge_levels.py   (./Alltest edge_levels)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic records, D0 = 1 m, 10 cells across D0: an edge of 1.5 finest
cells is 0.150 m. Every level descends at 6.0 ± 0.03 m/s, so C_D0's
95 % relative half-width is 2 x 0.03 / 6 = 1.0 % and a pair's combined
one hypot(1, 1) = 1.4 %. The levels are given fine first and listed
coarse first. C_D0 0.70, 0.80, 0.84 (edge 1.5, 1.0, 0.667): +14.3 % then
+5.0 %, both beyond 1.4 %, ratio 0.35: converging. 0.70, 0.80, 0.70:
+14.3 % then -12.5 %: oscillating. 0.70, 0.80, 0.96: +20.0 % after
+14.3 %, ratio 1.40: diverging. 0.70, 0.705, 0.80: the first change
(+0.7 %) lies within 1.4 %, so no verdict on the order. A level not run
is named with its command; one level alone gives no changes.

A run of another tutorial without an edge edit (the T-10 at 13 cells
across D0, study edgeLengthT10) takes that tutorial's edgeLengthPerCell
(1.25), not the 7 ft one's: with D0 = 10.7 m its edge is 1.25 x 10.7 /
13 = 1.029 m, listed above the 0.54-cell level (0.446 m).

run_setting reads a run's numeric entry: its edit (1 s), none when its
edit removes the entry, else the 7 ft tutorial's own bendingDampingUntil
(2 s).

study_fineness (the refinement `canopy-validate converged` reads): the
edge's inverse for runs on the same cells with edges 1.25 and 0.5417
(0.8 and 1.846 per finest cell), None (cells across D0) for runs on 12
and 18 cells, and a refusal naming the study for runs that share both
(e.g. the markers' spacing varied alone).
"""

from checks import check, finish
from canopyfoam.validation_runs import (MESH_DICT, PROPS, REMOVE, Run, SEVEN,
                                        T10)
from canopyfoam.validation_tables import (edge_levels_lines, fabric_edge_cells,
                                          run_setting, study_fineness)


def run(ident, edge):
    return Run(ident, SEVEN, "synthetic", edits=[
        (MESH_DICT, "cellsPerDiameter", "10"),
        (MESH_DICT, "edgeLengthPerCell", "%g" % edge)])


def record(cd, resolved=True):
    return {"complete": True, "ranks": 2,
            "analysis": {"parameters": {"nominalDiameter": {"value": 1.0}},
                         "descentVelocity": {"mean": 6.0, "ci95": 0.03},
                         "dragCoefficient": {"weightBalance": cd},
                         "projectedDiameter": {"mean": 0.8},
                         "shape": {"available": True,
                                   "skirtRadiusMean": 0.35,
                                   "rings": [{"foldedFraction": 0.0},
                                             {"foldedFraction": 0.2}]},
                         "breathing": {"resolved": resolved,
                                       "frequency": 1.2,
                                       "amplitude": 0.04}}}


levels = [run("t-fine", 0.667), run("t-medium", 1.0), run("t-coarse", 1.5)]


def lines(*cds):
    recs = [None if c is None else record(c) for c in cds]
    return "\n".join(edge_levels_lines(list(zip(levels, recs))))


text = lines(0.84, 0.80, 0.70)
rows = text.splitlines()
check("coarse first: edge, metres, C_D0 ± half-width, Dp/D0, skirt, outer "
      "ring, breathing",
      rows[2] == "| 1.5 | 0.150 | t-coarse | 0.700 ± 1.0 % | 0.800 | 0.350 "
      "| 20 % | 1.20 Hz, 4.0 cm |" and "| 0.667 | 0.067 | t-fine |" in rows[4],
      rows[2])
check("each change against the combined interval",
      "- 1.5 to 1 finest cells: C_D0 +14.3 % (beyond the combined ± 1.4 %)."
      in text and "- 1 to 0.667 finest cells: C_D0 +5.0 % (beyond" in text,
      [r for r in rows if r.startswith("- ")])
check("shrinking changes converge",
      "moves C_D0 less than the one before (ratio 0.35): the levels "
      "converge" in text, rows[-2])

text = lines(0.70, 0.80, 0.70)
check("a change of sign oscillates",
      "opposite directions: the levels oscillate" in text,
      text.splitlines()[-2])

text = lines(0.96, 0.80, 0.70)
check("growing changes diverge",
      "+20.0 %" in text and "(ratio 1.40): the levels diverge" in text,
      text.splitlines()[-2])

text = lines(0.80, 0.705, 0.70)
check("a change within its interval: no verdict",
      "(within the combined ± 1.4 %)" in text
      and "1.5 to 1 lies within the pair's interval" in text
      and "converge or oscillate is not told apart" in text,
      text.splitlines()[-2])

text = lines(None, 0.80, 0.70)
check("a level not run is named with its command",
      "| 0.667 | — | t-fine | not run (`bin/canopy-validate run t-fine`) |"
      in text and "Successive" not in text, text.splitlines()[4])

text = lines(None, None, 0.70)
check("one level: no changes",
      "needs two levels run" in text and "- 1.5 to" not in text,
      text.splitlines()[-2])

ten_default = Run("t-ten-default", T10, "synthetic",
                    ["-cellsPerDiameter", "13"])
ten_fine = Run("t-ten-fine", T10, "synthetic",
                 ["-cellsPerDiameter", "13"],
                 [(MESH_DICT, "edgeLengthPerCell", "0.5417")])
ten_record = record(0.79)
ten_record["analysis"]["parameters"]["nominalDiameter"]["value"] = 10.7
text = "\n".join(edge_levels_lines([(ten_fine, ten_record),
                                      (ten_default, ten_record)]))
rows = text.splitlines()
check("another tutorial's run takes that tutorial's edge",
      fabric_edge_cells(ten_default) == 1.25
      and rows[2].startswith("| 1.25 | 1.029 | t-ten-default |")
      and rows[3].startswith("| 0.5417 | 0.446 | t-ten-fine |"), rows[2:4])

# run_setting: a run's edit of an entry, else the tutorial's value; an
# edit that removes the entry leaves none
edited = Run("t-until1", SEVEN, "synthetic",
               edits=[(PROPS, "fabric/bendingDampingUntil", "1")])
removed = Run("t-throughout", SEVEN, "synthetic",
                edits=[(PROPS, "fabric/bendingDampingUntil", REMOVE)])
tutorial = Run("t-tutorial", SEVEN, "synthetic")
check("run_setting: the edit's value, none when removed, else the "
      "tutorial's (the 7 ft tutorial's bendingDampingUntil 2)",
      [run_setting(r, PROPS, "fabric/bendingDampingUntil")
       for r in (edited, removed, tutorial)] == [1.0, None, 2.0],
      [run_setting(r, PROPS, "fabric/bendingDampingUntil")
       for r in (edited, removed, tutorial)])

fineness = study_fineness("t-edges", [ten_default, ten_fine])
check("study_fineness: the edge's inverse where the cells are shared",
      fineness is not None and abs(fineness(ten_default) - 0.8) < 1e-12
      and abs(fineness(ten_fine) - 1 / 0.5417) < 1e-12,
      fineness and [fineness(ten_default), fineness(ten_fine)])
coarse = Run("t-cpd12", SEVEN, "synthetic", ["-cellsPerDiameter", "12"])
fine = Run("t-cpd18", SEVEN, "synthetic", ["-cellsPerDiameter", "18"])
check("study_fineness: cells across D0 where they differ",
      study_fineness("t-cells", [coarse, fine]) is None, "None")
try:
    study_fineness("t-markers", [coarse, Run(
        "t-markers", SEVEN, "synthetic", ["-cellsPerDiameter", "12"],
        [(PROPS, "coupling/forcing/markerSpacing", "0.0889")])])
    refusal = None
except SystemExit as e:
    refusal = str(e)
check("study_fineness: refuses a study that refines neither",
      refusal is not None and "t-markers" in refusal, refusal)

finish()
