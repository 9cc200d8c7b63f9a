"""stabiliser_model.py — the added-mass stabiliser on one vibrating node without air: the amplification per time step of K coupling iterations.

The model (src/canopyFoam/coupling/addedMassStabiliser): a node of mass m
on a spring k, with the stabiliser's lumped mass m_a, integrated exactly
over a time step dt under a balancing force c constant over the step,

    (m + m_a) x'' + k x = c,

and c made of the previous coupling iteration's acceleration,

    balance endOfStep:  c = m_a a(dt)      (the step's end acceleration)
    balance stepMean:   c = m_a (v(dt) - v(0))/dt,

with no air, so that nothing but the balance changes between iterations
(a cloth node the air does not resist: inside a fold, or a node-scale
vibration the immersed boundary's kernel does not see). A step's first
iteration starts from c = 0 (predictor zero) or from the last step's
final c (predictor lastStep); the step is accepted after K iterations.
In the units k = m + m_a = 1 the mode's frequency is 1, so
theta = sqrt(k/(m + m_a)) dt, and mu = m_a/(m + m_a).

The step is linear in (x, v, c_last): amplification() returns the
spectral radius of that map. It is 1 (neutral: the exact oscillator
conserves energy) when K = 1 with predictor zero, since c is then zero,
and above 1 where a partly converged balance pumps energy into the mode.

Run as:  python3 -m canopyfoam.stabiliser_model   (from python/)
prints, per mu, the smallest theta that grows with balance endOfStep and
predictor zero for K = 2 .. 40 iterations, and the largest growth.
"""

import math

import numpy as np


def _exact_step(x0, v0, c, theta):
    """The oscillator x'' + x = c over a step theta from (x0, v0)."""
    s, co = math.sin(theta), math.cos(theta)
    x1 = c + (x0 - c) * co + v0 * s
    v1 = -(x0 - c) * s + v0 * co
    return x1, v1


def step_matrix(theta, mu, iterations, balance="endOfStep",
                predictor="zero", seen=1.0):
    """The 3x3 map (x, v, c) -> (x, v, c) of one accepted time step; seen:
    the share of the mode's acceleration the balance is made of (1: all;
    0: a mode the filter triangleMean removes, whose mass m + m_a is then
    left unbalanced)."""
    if balance not in ("endOfStep", "stepMean"):
        raise ValueError("balance must be endOfStep or stepMean, not %r"
                         % (balance,))
    if predictor not in ("zero", "lastStep"):
        raise ValueError("predictor must be zero or lastStep, not %r"
                         % (predictor,))
    if iterations < 1:
        raise ValueError("iterations must be at least 1")

    def advance(state):
        x0, v0, c_last = state
        c = 0.0 if predictor == "zero" else c_last
        for _ in range(iterations):
            x1, v1 = _exact_step(x0, v0, c, theta)
            if balance == "endOfStep":
                a = c - x1
            else:
                a = (v1 - v0) / theta
            c = seen * mu * a
        # the step ends with the last iteration's state; the balance made
        # of it is what predictor lastStep starts the next step from
        return np.array([x1, v1, c])

    return np.column_stack([advance(e) for e in np.eye(3)])


def amplification(theta, mu, iterations, balance="endOfStep",
                  predictor="zero", seen=1.0):
    """Spectral radius of the step map: > 1 means the mode grows."""
    return float(max(abs(np.linalg.eigvals(
        step_matrix(theta, mu, iterations, balance, predictor, seen)))))


def first_unstable_theta(mu, iterations, balance="endOfStep",
                         predictor="zero", seen=1.0, theta_max=30.0,
                         samples=3000, tolerance=2e-4):
    """The smallest sampled theta in (0, theta_max] whose amplification
    exceeds 1 + tolerance, or None."""
    for theta in np.linspace(theta_max / samples, theta_max, samples):
        if amplification(theta, mu, iterations, balance, predictor,
                         seen) > 1.0 + tolerance:
            return float(theta)
    return None


def main():
    counts = (2, 3, 4, 6, 10, 20, 40)
    print("balance endOfStep, predictor zero: the smallest theta = "
          "sqrt(k/(m + m_a)) dt that grows, per number of iterations K")
    print("%6s %8s  %s" % ("mu", "m_a/m", "  ".join("K=%-5d" % k
                                                   for k in counts)))
    for mu in (0.3, 0.5, 0.55, 0.7, 0.8, 0.9, 0.935):
        firsts = [first_unstable_theta(mu, k) for k in counts]
        print("%6.3f %8.2f  %s" % (mu, mu / (1 - mu), "  ".join(
            "%-7s" % ("-" if f is None else "%.2f" % f) for f in firsts)))
    thetas = np.linspace(0.01, 30, 3000)
    for balance in ("endOfStep", "stepMean"):
        for k in (2, 6, 40):
            worst = max((amplification(t, 0.935, k, balance), t)
                        for t in thetas)
            print("mu 0.935, balance %-9s K=%-2d: largest growth %.3f a "
                  "step at theta %.2f" % (balance, k, worst[0], worst[1]))


if __name__ == "__main__":
    main()
