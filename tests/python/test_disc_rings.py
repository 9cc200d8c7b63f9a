"""test_disc_rings.py — known-answer tests of the rigid disc's study reading: the pressure jump by ring a record keeps (validation_results.pressure_jump_rings), its table in dynamic pressures (validation_tables.disc_ring_lines) and the GCI over the study's three levels only (disc_gci_lines with levels).

Run as:  /usr/bin/python3 tests/python/test_disc_rings.py   (./Alltest disc_rings)
Prints one PASS/FAIL line per check; exits 1 if any fails.

pressure_jump_rings on a cloth_stress.analyse that returns rows whose six
columns differ (s, r, sigma_mm, sigma_hh, wrinkled, dp = 100 + k): the
record keeps the ring's mid s (k + 1/2) / n and the sixth column, the
cloth's mean and the state count. disc_ring_lines: at the disc's 5 m/s
and rho = 1.2, q = 15 Pa, so jumps of 15, 30 and 7.5 Pa read 1.000, 2.000
and 0.500; a ring without a value (a record's nan, stored as None) reads
"—", and a ring no run has a value in no row; a run whose record has no
rings gets no column, and none at all no table. disc_gci_lines: C_D = 1.1 + 1.2 / n at n = 12, 18 and 27 converges
at order 1 to 1.100 exactly; a fourth run outside the levels is left out,
and with it counted the study would need three levels and have four.
"""

from checks import check, finish
from canopyfoam import cloth_stress
from canopyfoam import validation_results as vr
from canopyfoam.validation_runs import SEVEN, Run
from canopyfoam.validation_tables import (DISC_SPEED, disc_gci_lines,
                                          disc_ring_lines)

# pressure_jump_rings: the record's columns from cloth_stress.analyse
calls = []


def fake_analyse(case_dir, t0, t1, rings):
    calls.append((case_dir, t0, t1, rings))
    return {"rows": [(0.1 * k, 0.2 * k, 1.0, 2.0, 0.5, 100.0 + k)
                     for k in range(rings)],
            "pressureJump": 104.5, "states": 7}


real = cloth_stress.analyse
cloth_stress.analyse = fake_analyse
try:
    rings = vr.pressure_jump_rings("case", 5.0, 20.0, rings=4)
finally:
    cloth_stress.analyse = real
check("rings: the mid s and the jump column",
      rings == {"s": [0.125, 0.375, 0.625, 0.875],
                "dp": [100.0, 101.0, 102.0, 103.0], "mean": 104.5,
                "states": 7} and calls == [("case", 5.0, 20.0, 4)],
      "%s from %s" % (rings, calls))
check("rings: the study's default count", vr.DISC_RINGS == 20,
      "%d" % vr.DISC_RINGS)


def record(cd=None, rings=None):
    """A complete record with C_D (the disc's force over q S0) and the
    pressure jump by ring."""
    import math
    a = {"parameters": {"nominalDiameter": {"value": 2.0},
                        "rho": {"value": 1.2}}}
    if cd is not None:
        f = cd * 0.5 * 1.2 * DISC_SPEED ** 2 * math.pi
        a["pressureForceAgainstGravity"] = {"mean": f, "std": 0.0,
                                            "drift": 0.0}
    if rings is not None:
        a["pressureJumpRings"] = rings
    return {"analysis": a, "complete": True}


q = 0.5 * 1.2 * DISC_SPEED ** 2
check("rings: q of the disc's stream", abs(q - 15.0) < 1e-12, "%g Pa" % q)
results = [
    (Run("disc-a", SEVEN, "synthetic"),
     record(rings={"s": [0.25, 0.75, 0.9], "dp": [15.0, 30.0, None],
                   "mean": 22.5, "states": 3})),
    (Run("disc-b", SEVEN, "synthetic"), record()),
    (Run("disc-c", SEVEN, "synthetic"),
     record(rings={"s": [0.25, 0.75, 0.9], "dp": [7.5, None, None],
                   "mean": 7.5, "states": 3})),
    (Run("disc-d", SEVEN, "synthetic"), None)]
lines = disc_ring_lines(results)
check("table: a column per run with rings",
      lines[0] == "| s | disc-a: Δp/q | disc-c: Δp/q |" and
      lines[1] == "|---|---|---|", lines[:2])
check("table: jumps in dynamic pressures",
      lines[2:5] == ["| 0.250 | 1.000 | 0.500 |",
                     "| 0.750 | 2.000 | — |",
                     "| mean | 1.500 | 0.500 |"], lines[2:5])
check("table: none without rings",
      disc_ring_lines(results[1:2] + results[3:]) == [], "[]")

# disc_gci_lines: three levels, C_D = 1.1 + 1.2 / n, and a fourth run
levels = []
for n in (12, 18, 27):
    run = Run("disc-l%d" % n, SEVEN, "synthetic",
              ["-cellsPerDiameter", "%d" % n])
    levels.append((run, record(cd=1.1 + 1.2 / n)))
extra = (Run("disc-x", SEVEN, "synthetic", ["-cellsPerDiameter", "18"]),
         record(cd=2.0))
text = " ".join(disc_gci_lines(levels + [extra],
                               levels=("disc-l12", "disc-l18", "disc-l27")))
check("gci: the levels only", "1.144 / 1.167 / 1.200 at 27 / 18 / 12" in text
      and "observed order 1.00" in text and "extrapolated 1.100" in text,
      text)
text = " ".join(disc_gci_lines(levels + [extra]))
check("gci: all runs counted without levels",
      "needs three complete levels, has 4" in text, text)
finish()
