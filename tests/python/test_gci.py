"""test_gci.py — known-answer tests of python/canopyfoam/gci.py (Roache's grid convergence index, Celik et al. 2008).

Run as:  /usr/bin/python3 tests/python/test_gci.py   (./Alltest gci)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

f(h) = f0 + C h^p sampled exactly at three sizes: the observed order is p
and the extrapolation f0 to the fixed-point iteration's convergence
(1e-12, well below the 1e-9 asked), for a constant ratio (2) and for the
7 ft study's ratios (cells across D0 14, 21, 32: h ratios 1.5 and 1.524),
where q(p) != 0 and a formula that ignores it misses p by ~0.1. The GCI
is then Fs |f1 - f2|/|f1| / (r21^p - 1) with Fs = 1.25 (Celik eq. 7).
Oscillatory and divergent triples fall back to Fs = 3 with the formal
order; equal cell sizes are refused. validation_tables.resolution_estimates
gives the breathing frequency a GCI only when the three levels' peaks
are one mode (within validation_tables.BREATHING_SAME_MODE of each other).
validation_tables.two_level_lines gives two runs Roache's Fs = 3 estimate for
any refinement ratio. validation_tables.scatter_lines pairs each run with its
"-splitx" twin: the difference of their means, its ratio to sqrt(2) times
the larger 95 % half-width, and the pooled scatter rms(d)/sqrt(2).
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, HERE)

from canopyfoam import gci  # noqa: E402
from canopyfoam.validation_runs import Run  # noqa: E402
from canopyfoam.validation_tables import (  # noqa: E402
    STUDY_CAVEATS, resolution_estimates, scatter_lines, two_level_lines)
import test_report as shared  # noqa: E402


def exact(h, f0=5.0, c=-3.0, p=1.7):
    return [f0 + c * x ** p for x in h]


def test_orders():
    for label, h in (("ratio 2", (0.25, 0.5, 1.0)),
                     ("cells 32/21/14 across D0",
                      (2.134 / 32, 2.134 / 21, 2.134 / 14))):
        out = gci.gci(h, exact(h))
        shared.close("observed order, " + label, out["order"], 1.7, 1e-9)
        shared.close("extrapolated value, " + label, out["extrapolated"],
                     5.0, 1e-9)
        f = exact(h)
        want = 1.25 * abs((f[0] - f[1]) / f[0]) / ((h[1] / h[0]) ** 1.7 - 1)
        shared.close("GCI of the finest, " + label, out["gci"], want, 1e-12)
        shared.check("kind, " + label, out["kind"] == "monotone",
                     out["kind"])
    # Ignoring q(p) for the unequal ratios gives the wrong order
    h = (2.134 / 32, 2.134 / 21, 2.134 / 14)
    f = exact(h)
    naive = math.log((f[2] - f[1]) / (f[1] - f[0])) / math.log(h[1] / h[0])
    shared.check("the unequal ratios matter (naive order off by > 1e-3)",
                 abs(naive - 1.7) > 1e-3, "naive order %.6f" % naive)


def test_fallbacks():
    h = (1.0, 1.5, 2.25)
    osc = gci.gci(h, (4.0, 4.2, 3.9))
    shared.check("oscillatory: no order, Fs 3 with the formal order",
                 osc["kind"] == "oscillatory" and osc["order"] is None
                 and osc["safety"] == 3.0 and osc["orderUsed"] == 2.0,
                 "%s, order %s, Fs %s" % (osc["kind"], osc["order"],
                                          osc["safety"]))
    shared.close("oscillatory GCI", osc["gci"],
                 3.0 * (0.2 / 4.0) / (1.5 ** 2 - 1), 1e-12)
    div = gci.gci(h, (4.0, 4.1, 4.15))
    shared.check("divergent: differences grow under refinement",
                 div["kind"] == "divergent" and div["order"] is None,
                 div["kind"])
    try:
        gci.gci((1.0, 1.0, 2.0), (1, 2, 3))
        refused = False
    except ValueError:
        refused = True
    shared.check("equal cell sizes are refused", refused, refused)


def fake_record(breathing_hz, descent=5.0):
    """A complete run's record holding what resolution_estimates reads."""
    return {"complete": True, "analysis": {
        "parameters": {"nominalDiameter": {"value": 2.0}},
        "dragCoefficient": {"weightBalance": 0.8},
        "projectedDiameter": {"mean": 1.8},
        "descentVelocity": {"mean": descent},
        "breathing": {"resolved": breathing_hz is not None,
                      "frequency": breathing_hz}}}


def test_breathing_modes():
    key = "breathing frequency [Hz]"
    levels = (12, 18, 27)
    one = [(n, fake_record(b)) for n, b in zip(levels, (1.4, 1.6, 1.7))]
    _, table = resolution_estimates(one, fineness=lambda n: n)
    shared.check("breathing of one mode has a GCI",
                 key in table and table[key][1] is not None,
                 table.get(key))
    two = [(n, fake_record(b)) for n, b in zip(levels, (25.0, 1.6, 1.4))]
    _, table = resolution_estimates(two, fineness=lambda n: n)
    shared.check("breathing peaks 1.4/1.6/25 Hz: listed, no GCI",
                 key in table and table[key][1] is None
                 and table[key][0] == [1.4, 1.6, 25.0]
                 and table["Dp/D0"][1] is not None, table.get(key))
    unresolved = [(n, fake_record(b))
                  for n, b in zip(levels, (1.4, None, 1.7))]
    _, table = resolution_estimates(unresolved,
                                               fineness=lambda n: n)
    shared.check("a level without a breathing peak: no breathing row",
                 key not in table, sorted(table))


def test_two_levels():
    """Two runs, coarse first: the finer's GCI is 3 |f1 - f2| / |f1| /
    (r - 1) (Roache's Fs = 3, order 1)."""
    coarse = Run("coarse", "parachutes/flatCircular7ft", "c")
    fine = Run("fine", "parachutes/flatCircular7ft", "f")
    lines = two_level_lines(
        [(coarse, fake_record(None, descent=5.0)),
         (fine, fake_record(None, descent=5.5))], "a test", ratio=1.5)
    row = [line for line in lines if line.startswith("| descent")]
    want = 100 * 3 * 0.5 / 5.5 / 0.5
    shared.check("two levels at ratio 1.5: descent GCI %.1f %%" % want,
                 row == ["| descent speed [m/s] | 5.5 | 5 | %.1f %% |"
                         % want], row)
    lines = two_level_lines(
        [(coarse, fake_record(None)), (fine, None)], "a test")
    shared.check("two levels with one run missing: no estimate",
                 lines[0].startswith("Two-level estimate: needs both"),
                 lines[:1])


def test_scatter():
    """Pairs X / X-splitx: d = mean(X-splitx) - mean(X), the ratio |d| /
    (sqrt(2) h) and the pooled s = rms(d) / sqrt(2); a run without a twin
    is left out."""
    def rec(v, half, cd):
        r = fake_record(None, descent=v)
        r["analysis"]["descentVelocity"]["ci95"] = half
        r["analysis"]["dragCoefficient"]["weightBalance"] = cd
        return r
    runs = [(Run(i, "parachutes/flatCircular7ft", i), r)
            for i, r in (("a", rec(5.0, 0.05, 0.80)),
                         ("a-splitx", rec(5.3, 0.10, 0.70)),
                         ("b", rec(6.0, 0.02, 0.60)),
                         ("b-splitx", rec(5.9, 0.02, 0.62)),
                         ("c", rec(7.0, 0.02, 0.50)))]
    lines = scatter_lines(runs)
    rows = [line for line in lines if line.startswith("| a |")
            or line.startswith("| b |") or line.startswith("| c |")]
    shared.check("scatter: two pairs, the run without a twin left out",
                 len(rows) == 2, rows)
    want_a = "| a | 5.000 ± 0.050 | 5.300 ± 0.100 | +0.300 | %.1f |" % (
        0.3 / (math.sqrt(2) * 0.1))
    shared.check("scatter: pair a's difference and ratio",
                 bool(rows) and rows[0].startswith(want_a), rows[:1])
    s_v = math.sqrt((0.3 ** 2 + 0.1 ** 2) / 2) / math.sqrt(2)
    s_cd = math.sqrt((0.1 ** 2 + 0.02 ** 2) / 2) / math.sqrt(2)
    pooled = [line for line in lines if line.startswith("Pooled")]
    shared.check("scatter: pooled s %.3f m/s, %.3f in C_D0" % (s_v, s_cd),
                 pooled and ("s = rms(d) / sqrt(2) = %.3f m/s" % s_v)
                 in pooled[0] and ("and %.3f in C_D0" % s_cd) in pooled[0],
                 pooled)
    shared.check("scatter: no pairs, no lines",
                 scatter_lines(runs[4:]) == [], "")


def test_caveat():
    """A study's caveat travels with its converged values into a run's
    summary line (report._converged_line), from the committed records."""
    from canopyfoam import report
    saved = dict(STUDY_CAVEATS)
    try:
        STUDY_CAVEATS.clear()
        plain = report._converged_line("resolution7ftStiff", 0.8)
        STUDY_CAVEATS["resolution7ftStiff"] = "a test's caveat"
        warned = report._converged_line("resolution7ftStiff", 0.8)
    finally:
        STUDY_CAVEATS.clear()
        STUDY_CAVEATS.update(saved)
    shared.check("a study without a caveat: one line",
                 plain is not None and "caveat" not in plain, plain)
    shared.check("a study's caveat follows its converged line",
                 warned is not None
                 and warned.endswith("\n     caveat: a test's caveat"),
                 warned)


def main():
    test_orders()
    test_fallbacks()
    test_breathing_modes()
    test_two_levels()
    test_scatter()
    test_caveat()
    if shared.failures:
        print("FAIL: %d check(s) failed: %s" % (len(shared.failures),
                                               ", ".join(shared.failures)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
