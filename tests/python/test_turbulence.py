"""test_turbulence.py — known-answer tests of the laminar-against-LES verdict in python/canopyfoam/validation_tables.py (turbulence_lines, study turbulence7ftConverged).

Run as:  /usr/bin/python3 tests/python/test_turbulence.py   (./Alltest turbulence)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic pair: D0 = 2 m; laminar 6.0 ± 0.05 m/s, C_D0 0.70, Dp 1.6 m;
LES 5.7 ± 0.05 m/s, C_D0 0.77 (+10.0 % exactly), Dp 1.5 m. C_D0's
combined relative half-width is hypot(2 0.05/6.0, 2 0.05/5.7) = 2.4 %,
so the change is told apart. Against a GCI of 5 % it lies beyond it (LES
to be the default); against 20 % inside it (the tutorials stay laminar).
A pair whose LES run is missing says which runs it needs.
"""

from checks import check, finish
from canopyfoam.validation_runs import Run, SEVEN
from canopyfoam.validation_tables import turbulence_lines


def record(speed, cd0, dp):
    return {"complete": True,
            "analysis": {"parameters": {"nominalDiameter": {"value": 2.0}},
                         "descentVelocity": {"mean": speed, "ci95": 0.05},
                         "dragCoefficient": {"weightBalance": cd0},
                         "projectedDiameter": {"mean": dp},
                         "breathingBand": {"frequency": 0.5}}}


lam = Run("test-laminar", SEVEN, "synthetic laminar; interval 10-40 s")
les = Run("test-LES", SEVEN, "synthetic LES; interval 10-40 s")
pair = [(lam, record(6.0, 0.70, 1.6)), (les, record(5.7, 0.77, 1.5))]

text = "\n".join(turbulence_lines(pair, gci_cd0=0.05))
check("change and its interval", "+10.0 %, the pair's combined interval "
      "± 2.4 %: told apart" in text, text.splitlines()[-3][:200])
check("Dp/D0 of both", "Dp/D0 0.750 against 0.800" in text,
      "Dp/D0 0.750 against 0.800" in text)
check("beyond a 5 % GCI: LES to be the default",
      "The change is beyond the GCI" in text
      and "LES is to be the tutorials' default" in text,
      text.splitlines()[-1])

text = "\n".join(turbulence_lines(pair, gci_cd0=0.20))
check("inside a 20 % GCI: the tutorials stay laminar",
      "The change is inside the GCI" in text
      and "the tutorials stay laminar" in text, text.splitlines()[-1])

text = "\n".join(turbulence_lines([pair[0], (les, None)], gci_cd0=0.05))
check("a missing LES run is named", "needs test-laminar and test-LES "
      "complete" in text and "default" not in text, text.strip())

finish()
