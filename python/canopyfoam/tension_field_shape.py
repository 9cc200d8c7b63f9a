"""tension_field_shape.py — the inflated shape of a flat circular canopy whose cloth carries no hoop stress (wrinkled, tension-field membrane) under a uniform pressure jump.

The model. A flat circular canopy of nominal radius R0 is cut from a flat
disc: the cloth at arclength s from the apex had a hoop length 2 pi s, and
an inflated meridian with |dr/ds| <= 1 puts it at a radius r(s) <= s. So
the whole canopy is shorter in hoop than its cloth: the cloth gathers
into wrinkles and carries no hoop stress (tension-field theory; canopy
cloth buckles under a compressive load of order pi^2 B / L^2, a few
1e-4 N/m for MIL-C-7020 over 0.2 m, against a meridional tension of
order 10 N/m). The cloth is taken inextensible in the meridian (E t =
2919 N/m stretches it by ~0.5 %). An axisymmetric membrane with zero hoop
stress and meridional tension T per unit hoop length, under a uniform
pressure jump dp, balances

    along the meridian:  d(r T)/ds = 0        so  r T = C, a constant,
    across it:           T dphi/ds = dp       so  dphi/ds = k r,  k = dp/C,

with phi the meridian's angle below the outward horizontal (0 at the
apex), dr/ds = cos(phi), dz/ds = sin(phi) (z downward from the apex).
d(sin phi)/ds = k r dr/ds integrates to sin(phi) = k r^2 / 2, so the
widest section, where phi = pi/2, has r_max = sqrt(2/k). The canopy's
total meridional force 2 pi C leaves the skirt along its lines: with
lines of length L_s from the skirt to a confluence point on the axis,
the meridian continues into the line, cos(phi_s) = -r_s / L_s at s = R0.
That fixes k, and with it the projected diameter Dp = 2 r_max.

This is the assumption of the Aeronautical Research Council's approximate
theory of gore shape (tension across axial sections negligible, pressure
uniform; R&M, reports.aerade.cranfield.ac.uk/handle/1826.2/3410) for a
canopy without radial cords; with phi(R0) = pi/2 instead of the lines it
is Paulsen's Mylar balloon (two discs sewn at the rim: r_max / R0 =
1 / A and half-thickness / R0 = B / A, A and B the lemniscate constants;
Paulsen, Amer. Math. Monthly 101 (1994) 953-958), which the tests check.
A real canopy's pressure jump is larger at the crown than at the skirt,
and its lines gather the meridional force into gores that bulge between
them; the model has neither.

Run as:  python3 -m canopyfoam.tension_field_shape   (from python/)
prints Dp/D0, the skirt's diameter and the crown's depth above the skirt
for line lengths of 0.85 to 1.5 D0;
         python3 -m canopyfoam.tension_field_shape CASE T0 T1 [LINES/D0]
compares a run's mean profile over [T0, T1] (its canopy.h5, shape.py's
axis and radial position s, which follows the cloth at rest) with the
model's, ring by ring: the cloth's mean radius and depth below the crown
against r(s) and z(s) (lines of 1 D0 unless given; needs h5py).
"""

import math
import sys

import numpy as np


def _profile(k, length=1.0, steps=2000):
    """The meridian r(s), z(s), phi(s) for curvature factor k over
    s in [0, length], by classical Runge-Kutta (the ODE is smooth)."""
    h = length / steps
    y = np.zeros(3)  # r, z, phi

    def f(y):
        return np.array([math.cos(y[2]), math.sin(y[2]), k * y[0]])

    path = [y.copy()]
    for _ in range(steps):
        k1 = f(y)
        k2 = f(y + 0.5 * h * k1)
        k3 = f(y + 0.5 * h * k2)
        k4 = f(y + h * k3)
        y = y + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        path.append(y.copy())
    return np.array(path)


def _bisect(g, lo, hi, tol=1e-13):
    glo = g(lo)
    if glo * g(hi) > 0:
        raise ValueError("no sign change in [%g, %g]" % (lo, hi))
    while hi - lo > tol * max(1.0, hi):
        mid = 0.5 * (lo + hi)
        gm = g(mid)
        if (gm > 0) == (glo > 0):
            lo, glo = mid, gm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _first_root(g, k_max=20.0, samples=80):
    """The smallest k > 0 with g(k) = 0 (g > 0 for small k)."""
    ks = np.linspace(0.05, k_max, samples)
    prev = g(ks[0])
    for a, b in zip(ks[:-1], ks[1:]):
        gb = g(b)
        if prev * gb <= 0:
            return _bisect(g, a, b)
        prev = gb
    raise ValueError("no root below k = %g" % k_max)


def _summary(k, steps):
    p = _profile(k, 1.0, steps)
    r, z = p[:, 0], p[:, 1]
    return {"k": k, "r_max": float(r.max()), "r_skirt": float(r[-1]),
            "depth": float(z[-1]), "phi_skirt": float(p[-1, 2]),
            "profile": p}


def canopy(line_length, steps=2000):
    """The shape of a canopy of nominal radius 1 with lines of length
    line_length (in R0) to a confluence point on the axis: a dict with
    k, r_max (= Dp/D0), r_skirt, depth (crown above skirt), phi_skirt and
    the profile (rows r, z, phi), all in units of R0."""
    if not line_length > 0:
        raise ValueError("line_length must be positive")

    def skirt(k):
        p = _profile(k, 1.0, steps)[-1]
        return math.cos(p[2]) + p[0] / line_length

    return _summary(_first_root(skirt), steps)


def mylar_balloon(steps=2000):
    """Paulsen's Mylar balloon with the same equations: phi = pi/2 at the
    rim s = 1. Returns r_max (the rim's radius) and depth (half the
    thickness) in units of the disc's radius."""
    def rim(k):
        return math.cos(_profile(k, 1.0, steps)[-1, 2])

    return _summary(_first_root(rim), steps)


def compare(case_dir, t0, t1, line_length=2.0):
    """Rows (s, nodes, r, r_model, largest r, depth, depth_model) in R0 of
    a run's profile averaged over the states in [t0, t1], by ring of the
    cloth (s bins of 1/8 about the rings' mean s)."""
    from . import shape
    mesh, states = shape.read_case(case_dir, t0, t1)
    model = canopy(line_length)["profile"]
    s_model = np.linspace(0.0, 1.0, len(model))
    radius, depth = [], []
    for _, x in states:
        _, _, h, r = shape.axial_coordinates(mesh, x)
        radius.append(r)
        depth.append(h[mesh.cloth_nodes].max() - h)
    radius, depth = np.mean(radius, axis=0), np.mean(depth, axis=0)
    rest = mesh.s  # 0 at the crown, 1 at the skirt
    r0 = mesh.rest_radius  # the cloth's radius at rest
    rows = []
    for centre_s in np.arange(0.0, 1.0 + 1e-9, 0.125):
        m = np.isfinite(rest) & (np.abs(rest - centre_s) < 0.0625)
        if not m.any():
            continue
        s_mean = float(rest[m].mean())
        i = int(np.argmin(np.abs(s_model - s_mean)))
        rows.append((s_mean, int(m.sum()), float(radius[m].mean()) / r0,
                     float(model[i, 0]), float(radius[m].max()) / r0,
                     float(depth[m].mean()) / r0, float(model[i, 1])))
    return rows


def main():
    if len(sys.argv) > 1:
        case_dir, t0, t1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
        lines = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
        print("%s over %g-%g s against the cloth without hoop stress "
              "(lines %g D0); lengths in R0" % (case_dir, t0, t1, lines))
        print("%6s %6s %8s %8s %8s %8s %8s" % ("s", "nodes", "r", "model",
                                               "r max", "depth", "model"))
        for row in compare(case_dir, t0, t1, 2.0 * lines):
            print("%6.2f %6d %8.3f %8.3f %8.3f %8.3f %8.3f" % row)
        return
    print("flat circular canopy, cloth without hoop stress, uniform "
          "pressure jump (lengths in D0)")
    print("%10s %8s %10s %10s %10s" % ("lines/D0", "k R0", "Dp/D0",
                                         "skirt/D0", "depth/D0"))
    for lines in (0.85, 1.0, 1.25, 1.5):
        c = canopy(2.0 * lines)
        print("%10.2f %8.4f %10.4f %10.4f %10.4f" % (
            lines, c["k"], c["r_max"], c["r_skirt"], 0.5 * c["depth"]))
    m = mylar_balloon()
    print("Mylar balloon (rim vertical): r/R0 = %.6f, half-thickness/R0 = "
          "%.6f" % (m["r_max"], m["depth"]))


if __name__ == "__main__":
    main()
