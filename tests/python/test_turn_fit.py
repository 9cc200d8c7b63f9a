"""test_turn_fit.py — known-answer test of the least-squares fit in python/canopyfoam/turn_fit.py (the moment about the payload against the angle of turn, its rate and acceleration).

Run as:  /usr/bin/python3 tests/python/test_turn_fit.py   (./Alltest turn_fit)
Prints one PASS/FAIL line per check; exits 1 if any fails.

A swing of two modes theta = A1 sin(w1 t) + A2 exp(s t) sin(w2 t + p)
(A1 = 0.3 rad, w1 = 0.7 rad/s; A2 = 0.1 rad, s = 0.1 /s, w2 = 1.9 rad/s,
p = 0.4; 0 <= t <= 15 s, 61 samples) with its exact derivatives, and the
moment M = k theta + c theta' + i theta'' + m0 with k = -3000, c = 1500,
i = 8000, m0 = 120: the fit returns the four coefficients to 1e-8
relative (round-off of a well-posed 61 x 4 least-squares problem), R^2
= 1 and standard errors below 1e-6 of each coefficient. One mode alone
cannot be fitted: A exp(s t) sin(w t) obeys theta'' = 2 s theta' - (s^2
+ w^2) theta exactly, so the three columns are dependent: the scaled
columns' condition number is above 1e8 (round-off), against below 100
for the two modes. With noise
of standard deviation 50 N m (seeded) on the two-mode moment the
coefficients stay within 4 standard errors of the truth and the rate
coefficient's error is of the size the noise predicts (between 0.3 and
3 times sigma / sqrt(sum of the rate's squared deviations)).
"""

import math

import numpy as np

from checks import check, finish
from canopyfoam import turn_fit

A1, W1, A2, S, W2, P = 0.3, 0.7, 0.1, 0.1, 1.9, 0.4
K, C, I, M0 = -3000.0, 1500.0, 8000.0, 120.0
t = np.linspace(0.0, 15.0, 61)


def mode(amp, s, w, p):
    """A exp(s t) sin(w t + p) and its first two derivatives."""
    e = amp * np.exp(s * t)
    sn, cs = np.sin(w * t + p), np.cos(w * t + p)
    return (e * sn, e * (s * sn + w * cs),
            e * ((s * s - w * w) * sn + 2 * s * w * cs))


one = mode(A1, 0.0, W1, 0.0)
two = mode(A2, S, W2, P)
theta, rate, acc = (a + b for a, b in zip(one, two))
moment = K * theta + C * rate + I * acc + M0

f = turn_fit.fit(theta, rate, acc, moment)
err = max(abs(f["k"] / K - 1), abs(f["c"] / C - 1), abs(f["i"] / I - 1),
          abs(f["m0"] / M0 - 1))
check("exact model", err < 1e-8 and abs(f["r2"] - 1) < 1e-12 and
      max(f["kErr"] / abs(K), f["cErr"] / C, f["iErr"] / I) < 1e-6,
      "k %.10g c %.10g i %.10g m0 %.10g (largest relative error %.2g), "
      "R^2 %.15g" % (f["k"], f["c"], f["i"], f["m0"], err, f["r2"]))

single = mode(A1, S, W1, 0.0)
h = turn_fit.fit(*single, K * single[0] + C * single[1] + I * single[2])
check("one mode is not separable", h["condition"] > 1e8 and
      f["condition"] < 100,
      "condition number %.3g (two modes: %.3g)" % (h["condition"],
                                                   f["condition"]))

rng = np.random.default_rng(3)
sigma = 50.0
g = turn_fit.fit(theta, rate, acc, moment + rng.normal(0.0, sigma,
                                                        len(t)))
within = all(abs(g[n] - v) < 4 * g[n + "Err"] for n, v in
             (("k", K), ("c", C), ("i", I)))
scale = sigma / math.sqrt(np.sum((rate - rate.mean()) ** 2))
check("noisy model", within and 0.3 * scale < g["cErr"] < 3 * scale,
      "k %.1f ± %.1f, c %.1f ± %.1f, i %.1f ± %.1f (truth %g, %g, %g); "
      "c's error against sigma/|rate| %.1f" % (
          g["k"], g["kErr"], g["c"], g["cErr"], g["i"], g["iErr"], K, C,
          I, scale))
finish()
