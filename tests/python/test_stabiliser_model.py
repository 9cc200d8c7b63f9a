"""test_stabiliser_model.py — known-answer tests of python/canopyfoam/stabiliser_model.py (the added-mass stabiliser on one node without air).

Run as:  /usr/bin/python3 tests/python/test_stabiliser_model.py   (./Alltest stabiliser_model)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

Exact answers of the model (x'' + x = c over a step theta, units
k = m + m_a = 1, c = mu a from the previous iteration):
  K = 1, predictor zero: c = 0, the exact oscillator: every eigenvalue of
      the step map has modulus 1 (the third, c's, is 0).
  converged end balance (K large): m a = -k x at the step's end with a
      constant c: no mode grows (modulus at most 1, to the iteration's
      remainder (mu cos theta)^K, below 2e-12 at K = 400).
  seen = 0 (a mode the filter removes): c = 0 whatever K: modulus 1.
  K = 2, predictor zero, end balance: c = mu a1 of the unbalanced first
      iteration, a1 = -(x0 cos theta + v0 sin theta) (k = M = 1), so the
      step map is known in closed form; its modulus at theta = 8.35,
      mu = 0.935 (the growth the 7 ft cloth's node-scale modes met at 18
      cells) is computed independently below.
  mu <= 1/2 (m_a <= m): no theta grows for any K (sampled).
"""

import math

import numpy as np

from checks import check, finish
from canopyfoam.stabiliser_model import (amplification, first_unstable_theta,
                                         step_matrix)


# K = 1 with predictor zero: the exact oscillator, neutral for every theta
worst = max(abs(amplification(t, 0.935, 1) - 1.0)
            for t in np.linspace(0.1, 30, 300))
check("one iteration, predictor zero is neutral", worst < 1e-12,
      "largest |amplification - 1| = %.2e over theta 0.1-30" % worst)

# seen = 0: the balance is zero whatever the iterations
worst = max(abs(amplification(t, 0.935, k, seen=0.0) - 1.0)
            for t in np.linspace(0.1, 30, 100) for k in (2, 6))
check("a mode the filter removes is neutral", worst < 1e-12,
      "largest |amplification - 1| = %.2e (K 2 and 6)" % worst)

# K = 2 in closed form: iteration 1 (c = 0) ends at x1 = x0 cos + v0 sin,
# a1 = -x1; iteration 2 has c = -mu x1(1) and ends at
# x = c + (x0 - c) cos + v0 sin, v = -(x0 - c) sin + v0 cos
theta, mu = 8.35, 0.935
s, co = math.sin(theta), math.cos(theta)
# c as a function of (x0, v0): c = -mu (x0 co + v0 s)
cx, cv = -mu * co, -mu * s
closed = np.array([
    [cx * (1 - co) + co, cv * (1 - co) + s, 0.0],
    [-(1 - cx) * s, cv * s + co, 0.0],
    [mu * (cx - (cx * (1 - co) + co)), mu * (cv - (cv * (1 - co) + s)), 0.0],
])
model = step_matrix(theta, mu, 2)
diff = float(np.max(np.abs(model - closed)))
check("two iterations: the step map in closed form", diff < 1e-12,
      "largest entry difference %.2e" % diff)
growth = float(max(abs(np.linalg.eigvals(closed))))
check("two iterations at theta 8.35, mu 0.935 grow",
      abs(amplification(theta, mu, 2) - growth) < 1e-12 and growth > 1.2,
      "amplification %.4f a step (closed form %.4f)"
      % (amplification(theta, mu, 2), growth))

# many iterations: the end balance converges to a neutral scheme
# (the iteration's remainder after K = 400 is at most 0.935^400 = 2e-12)
amps = [amplification(t, 0.935, 400) for t in np.linspace(0.1, 30, 300)]
check("a converged end balance does not grow", max(amps) < 1.0 + 1e-9,
      "amplification with 400 iterations %.6f to %.12f" % (min(amps), max(amps)))

# m_a <= m: nothing grows
firsts = [first_unstable_theta(0.5, k, samples=600) for k in (2, 3, 6, 20)]
check("m_a = m: stable for every theta and K", all(f is None for f in firsts),
      "first unstable theta per K 2/3/6/20: %s" % firsts)
first = first_unstable_theta(0.935, 2, samples=3000)
check("m_a = 14.4 m, two iterations: grows from theta ~1.65",
      first is not None and abs(first - 1.65) < 0.02,
      "first unstable theta %s (sampled every 0.01)" % first)

# the step-mean balance is not neutral even when converged
worst = max(amplification(t, 0.935, 200, balance="stepMean")
            for t in np.linspace(0.1, 30, 300))
check("a converged step-mean balance grows", worst > 2.0,
      "largest amplification with 200 iterations %.3f" % worst)

finish()
