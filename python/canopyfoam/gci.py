"""gci.py — Roache's grid convergence index from three resolutions: the observed order, the extrapolated value and the uncertainty of the finest (Celik et al. 2008, J. Fluids Eng. 130, 078001, eqs. 1-7).

h1 < h2 < h3 are representative cell sizes (fine to coarse) and f1, f2, f3
the values there. With r21 = h2/h1, r32 = h3/h2, e21 = f2 - f1,
e32 = f3 - f2 and s = sign(e32/e21), the observed order p solves

    p = | ln|e32/e21| + q(p) | / ln r21,   q(p) = ln((r21^p - s)/(r32^p - s))

(fixed-point iteration; q = 0 for a constant ratio). Then

    f_ext  = (r21^p f1 - f2)/(r21^p - 1)
    e_a    = |(f1 - f2)/f1|
    GCI    = Fs e_a/(r21^p - 1),   Fs = 1.25.

Convergence is monotone for 0 < e21/e32 < 1 (s > 0 and the differences
shrink); oscillatory for s < 0; divergent when the differences grow. Only
the monotone case gives an order; for the others (or a p outside
[0.5, p_max]) the estimate uses Roache's safety factor Fs = 3 with the
formal order p_formal instead, and says so.
"""

import math


def gci(h, f, p_formal=2.0, p_max=None):
    """Three-level estimate. h = (h1, h2, h3) fine to coarse, f the values.
    Returns a dict: order (None unless monotone), orderUsed, safety,
    kind ('monotone' | 'oscillatory' | 'divergent' | 'converged'),
    extrapolated, gci (relative, of the finest), gciAbs (absolute), and
    the ratios."""
    h1, h2, h3 = (float(x) for x in h)
    f1, f2, f3 = (float(x) for x in f)
    if not (0 < h1 < h2 < h3):
        raise ValueError("gci: cell sizes must be 0 < h1 < h2 < h3, not %s"
                         % (h,))
    if p_max is None:
        p_max = 2 * p_formal
    r21, r32 = h2 / h1, h3 / h2
    e21, e32 = f2 - f1, f3 - f2
    out = {"r21": r21, "r32": r32, "order": None}
    if e21 == 0 and e32 == 0:
        out.update(kind="converged", orderUsed=p_formal, safety=1.25,
                   extrapolated=f1, gci=0.0, gciAbs=0.0)
        return out
    ratio = e32 / e21 if e21 != 0 else math.inf
    s = 1.0 if ratio > 0 else -1.0
    if ratio > 1:
        kind = "monotone"
    elif ratio < 0:
        kind = "oscillatory"
    else:
        kind = "divergent"
    p = None
    if kind == "monotone":
        p = math.log(abs(ratio)) / math.log(r21)
        for _ in range(200):
            q = math.log((r21 ** p - s) / (r32 ** p - s))
            p_new = abs(math.log(abs(ratio)) + q) / math.log(r21)
            if abs(p_new - p) < 1e-12:
                p = p_new
                break
            p = p_new
        if not (0.5 <= p <= p_max):
            kind = "monotone, order %.2g outside [0.5, %g]" % (p, p_max)
    if p is not None and kind == "monotone":
        used, safety = p, 1.25
        out["order"] = p
    else:
        used, safety = p_formal, 3.0
    rp = r21 ** used
    out.update(kind=kind, orderUsed=used, safety=safety,
               extrapolated=(rp * f1 - f2) / (rp - 1))
    e_a = abs((f1 - f2) / f1) if f1 != 0 else math.inf
    out["gci"] = safety * e_a / (rp - 1)
    out["gciAbs"] = safety * abs(f1 - f2) / (rp - 1)
    return out
