"""test_forced_turn.py — known-answer tests of python/canopyfoam/forced_turn.py (the air's moment on a canopy turned by an imposed oscillation, split into its parts in phase with the angle and with the rate).

Run as:  /usr/bin/python3 tests/python/test_forced_turn.py   (./Alltest forced_turn)
Prints one PASS/FAIL line per check; exits 1 if any fails.

1. angle(): theta = A sin(w (t - t0)) and its rate, zero before t0, at
   quarter periods exactly (to 1e-15 rad).
2. Through canopy.h5 (h5py): a payload at the origin and one cloth node
   at (0, 0, 1) carrying the force (M, 0, 0), so that the moment about
   the payload along y is M; M = a theta + c theta' + m0 with a = -3000
   N m, c = 1500 N m s, m0 = 200 N m for A = 10°, T = 10 s, t0 = 10 s,
   written every 0.25 s over 20-110 s: the whole-interval fit and every
   period's give a and c to 1e-8 of their size, nine whole periods, the
   work per period pi c w A^2 and C_mq = c / (q S0 D0 D0 / 2U) as
   computed by hand for U = 6.66 m/s, D0 = 10.7 m, rho = 1.2.
3. The same with a deterministic wake-like disturbance (a sum of
   sinusoids at frequencies unrelated to the forcing's, 800 N m): the
   per-period means lie within their 95 % intervals of the truth and the
   intervals are not empty; fewer than 8 states in the interval give
   None.
4. spectrum_peaks: two force components carrying 0.10 Hz (amplitude 2)
   and 0.30 Hz (amplitude 1) over 100 s sampled unevenly about 0.05 s:
   the two largest peaks lie within one resolution (0.01 Hz) of 0.10 and
   0.30 Hz, the second's power a quarter of the first's (0.15-0.35: the
   window's leakage between bins), and the resolution is 1/100 Hz.
"""

import math
import os
import shutil
import tempfile

import numpy as np

from checks import check, finish
from canopyfoam import forced_turn

A, T, T0 = 10.0, 10.0, 10.0
W = 2 * math.pi / T
AR = math.radians(A)

# 1. the angle
t = np.array([5.0, 10.0, 12.5, 15.0, 17.5, 20.0])
theta, rate = forced_turn.angle(t, A, T, T0)
want_theta = np.array([0, 0, AR, 0, -AR, 0])
want_rate = np.array([0, 0, 0, -AR * W, 0, AR * W])
check("angle at quarter periods",
      np.allclose(theta, want_theta, atol=1e-15, rtol=0),
      "%s rad (exact %s)" % (theta, want_theta))
check("rate at quarter periods (zero before the start)",
      np.allclose(rate, want_rate, atol=1e-15, rtol=0),
      "%s rad/s (exact %s)" % (rate, want_rate))

import h5py  # noqa: E402


def write_case(path, times, moments):
    """A canopy.h5 whose load's moment about the payload along y is
    moments[k] at times[k]."""
    os.makedirs(os.path.join(path, "postProcessing", "canopy"))
    with h5py.File(os.path.join(path, "postProcessing", "canopy",
                                "canopy.h5"), "w") as f:
        x = np.array([[0.0, 0, 1], [1, 0, 1], [0, 1, 1], [0, 0, 0]])
        f["mesh/triangles"] = np.array([[0, 1, 2]], dtype=np.int32)
        f["mesh/node_group"] = np.array([0, 0, 0, 3], dtype=np.int32)
        for k, (tk, mk) in enumerate(zip(times, moments)):
            s = f.create_group("steps/%06d" % k)
            s.attrs["time"] = tk
            s["x"] = x
            s["dp"] = np.array([0.0])
            s["f_ext"] = np.array([[mk, 0, 0], [0, 0, 0], [0, 0, 0],
                                   [0, 0, 0]])


a_true, c_true, m0_true = -3000.0, 1500.0, 200.0
times = np.arange(20.0, 110.0 + 1e-9, 0.25)
th, rt = forced_turn.angle(times, A, T, T0)
clean = a_true * th + c_true * rt + m0_true
U, D0, RHO = 6.66, 10.7, 1.2
qsd = 0.5 * RHO * U ** 2 * math.pi * D0 ** 2 / 4 * D0

tmp = tempfile.mkdtemp()
try:
    # 2. exact
    case = os.path.join(tmp, "exact")
    write_case(case, times, clean)
    o = forced_turn.analyse(case, A, T, T0, (0, 1, 0), 20, 110, U, D0, RHO)
    check("exact: whole-interval fit",
          abs(o["a"] - a_true) < 1e-8 * 3000 and
          abs(o["c"] - c_true) < 1e-8 * 3000 and
          abs(o["m0"] - m0_true) < 1e-8 * 3000,
          "a %.10g, c %.10g, m0 %.10g" % (o["a"], o["c"], o["m0"]))
    check("exact: nine whole periods, each the truth",
          o["periods"] == 9 and
          max(abs(v - a_true) for v in o["aPeriods"]) < 1e-8 * 3000 and
          max(abs(v - c_true) for v in o["cPeriods"]) < 1e-8 * 3000,
          "%d periods, a %.6g..%.6g, c %.6g..%.6g"
          % (o["periods"], min(o["aPeriods"]), max(o["aPeriods"]),
             min(o["cPeriods"]), max(o["cPeriods"])))
    want_work = math.pi * c_true * W * AR ** 2
    want_cmq = c_true / (qsd * D0 / (2 * U))
    check("exact: work per period and C_mq by hand",
          abs(o["work"] - want_work) < 1e-8 * want_work and
          abs(o["Cmq"] - want_cmq) < 1e-8 * want_cmq and
          abs(o["Cma"] - a_true / qsd) < 1e-8 * abs(a_true / qsd) and
          abs(o["reducedFrequency"] - W * D0 / (2 * U)) < 1e-12,
          "W %.6g J (by hand %.6g), C_mq %.6g (%.6g), C_ma %.6g (%.6g)"
          % (o["work"], want_work, o["Cmq"], want_cmq, o["Cma"],
             a_true / qsd))

    # 3. with a disturbance
    noise = 800.0 * (0.6 * np.sin(0.731 * times + 0.3)
                     + 0.5 * np.sin(2.913 * times + 1.1)
                     + 0.4 * np.sin(1.377 * times + 2.0))
    case = os.path.join(tmp, "noisy")
    write_case(case, times, clean + noise)
    o = forced_turn.analyse(case, A, T, T0, (0, 1, 0), 20, 110, U, D0, RHO)
    check("disturbed: a within its 95 % interval, interval not empty",
          o["a95"] > 0 and abs(o["aMean"] - a_true) <= o["a95"],
          "a %.0f ± %.0f (truth %.0f)" % (o["aMean"], o["a95"], a_true))
    check("disturbed: c within its 95 % interval, interval not empty",
          o["c95"] > 0 and abs(o["cMean"] - c_true) <= o["c95"],
          "c %.0f ± %.0f (truth %.0f)" % (o["cMean"], o["c95"], c_true))
    o = forced_turn.analyse(case, A, T, T0, (0, 1, 0), 20, 21.5, U, D0, RHO)
    check("too few states give None", o is None, "%s" % o)
finally:
    shutil.rmtree(tmp)

# 4. the spectrum's peaks
rng = np.random.default_rng(7)
ts = np.cumsum(0.05 + 0.01 * rng.random(2000))
ts = ts[ts <= ts[0] + 100.0]
fs = np.column_stack([2 * np.sin(2 * math.pi * 0.1 * ts) +
                      np.sin(2 * math.pi * 0.3 * ts + 0.4),
                      2 * np.cos(2 * math.pi * 0.1 * ts)
                      + np.cos(2 * math.pi * 0.3 * ts)])
peaks, resolution = forced_turn.spectrum_peaks(ts, fs)
check("spectrum: peaks at 0.10 and 0.30 Hz, power ratio about 1/4",
      abs(peaks[0][0] - 0.1) <= resolution and
      abs(peaks[1][0] - 0.3) <= resolution and
      0.15 <= peaks[1][1] <= 0.35 and abs(resolution - 0.01) < 2e-4,
      "%s, resolution %.4f Hz" % ([(round(f, 4), round(p, 3))
                                   for f, p in peaks[:2]], resolution))

finish()
