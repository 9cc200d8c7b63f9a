"""turn_fit.py — the moments about the payload on a canopy that turns in one plane about the payload, fitted against the angle of turn, its rate and its acceleration.

For a run whose canopy swings about the payload in a plane (the payload
on the guide wire, the canopy free: validation study pivotT10), the
suspension's offset (canopy centre less payload, canopy.dat) gives the
signed angle of turn theta in the plane of gravity and the direction
across gravity along which the offset varies most (the leading singular
vector of its sideways part, as report.suspension_swing); theta' and
theta'' are its time derivatives (numpy.gradient, second order inside).
A moment about the payload at each written state (load_moment.py), taken
about the plane's normal with the sign that turns the axis towards
increasing theta, is fitted by least squares as

    M = k theta + c theta' + i theta'' + m0,

each coefficient with its standard error (the residual variance times
the diagonal of (X^T X)^-1) and the condition number of the scaled
columns. k < 0 restores; c > 0 is a moment along the rate of turn. One
mode A exp(s t) sin(w t) obeys theta'' = 2 s theta' - (s^2 + w^2) theta
exactly, so it cannot separate the three (its condition number is
infinite); a swing that is not one such mode can, and the condition
number and the standard errors say how well.

Three moments are fitted: the air's (the load less the added-mass
stabiliser's balance, given the stabiliser's settings), the balance's
and the weight's. What they show is a balance, not the air's damping: the
canopy's own inertia is small (cloth and lines, a few kg), so at every
instant the air's moment about the payload nearly cancels the weight's,
and its fit returns the weight's stiffness with the sign reversed, not
the air's stiffness, damping and added inertia, which the free motion
ties together; the balance's moment is the inertia m_a a of the
stabiliser's mass, a function of the motion alone. The air's
coefficients need a motion imposed from outside (forced_turn.py).
"""

import numpy as np

from . import load_moment
from . import report as rep


def linear_fit(columns, y):
    """Least squares of y on the columns and a constant: the coefficients
    (the constant last), their standard errors (the residual variance times
    the diagonal of (X^T X)^-1), R^2 and the condition number of the
    columns scaled to unit length."""
    x = np.column_stack(list(columns) + [np.ones(len(y))])
    y = np.asarray(y, dtype=float)
    coef, _, _, _ = np.linalg.lstsq(x, y, rcond=None)
    resid = y - x @ coef
    dof = max(1, len(y) - x.shape[1])
    cov = np.sum(resid ** 2) / dof * np.linalg.inv(x.T @ x)
    total = np.sum((y - y.mean()) ** 2)
    scaled = x / np.linalg.norm(x, axis=0)
    return (coef, np.sqrt(np.diag(cov)),
            float(1.0 - np.sum(resid ** 2) / total) if total > 0 else None,
            float(np.linalg.cond(scaled)))


def fit(theta, rate, acceleration, moment):
    """Least squares of moment on (theta, rate, acceleration, 1): dict of
    the coefficients k, c, i, m0, their standard errors (kErr, cErr,
    iErr), the fit's R^2, the sample count and the condition number of
    the columns scaled to unit length (large: the motion does not
    separate them)."""
    coef, err, r2, cond = linear_fit((theta, rate, acceleration), moment)
    return {"condition": cond,
            "k": float(coef[0]), "c": float(coef[1]), "i": float(coef[2]),
            "m0": float(coef[3]), "kErr": float(err[0]),
            "cErr": float(err[1]), "iErr": float(err[2]),
            "r2": r2, "samples": int(len(moment))}


def analyse(case_dir, t0, t1, stabiliser=None):
    """The fits over [t0, t1] of a run's canopy.dat and canopy.h5: the
    air's moment (keys of fit(); the load's when stabiliser is None, as for
    a run without one), and under "balance" and "weight" the fits of the
    stabiliser's balance (with stabiliser, load_moment.analyse's) and of
    the weights; moment names the first ("air" or "load"); with the
    plane's direction across gravity and the angle's range [degrees]. None
    when fewer than 8 states are written in the interval."""
    series = rep.load_case(case_dir)
    params = rep.resolve_parameters(series.header)
    g = np.array(params["gravity"][0], dtype=float)
    up = -g / np.linalg.norm(g)
    t = series.t
    offset = series.columns("canopy_x", "canopy_y", "canopy_z") \
        - series.columns("payload_x", "payload_y", "payload_z")
    m = rep.interval_mask(t, t0, t1)
    side = offset[m] - np.outer(offset[m] @ up, up)
    _, _, vt = np.linalg.svd(side - side.mean(axis=0), full_matrices=False)
    e = vt[0] - (vt[0] @ up) * up
    e /= np.linalg.norm(e)
    theta = np.arctan2(offset @ e, offset @ up)
    rate = np.gradient(theta, t)
    acceleration = np.gradient(rate, t)
    loads = load_moment.analyse(case_dir, t0, t1, stabiliser=stabiliser,
                                gravity=g)
    if loads["states"] < 8:
        return None
    times = np.array(loads["times"])
    normal = np.cross(up, e)        # turning about it takes up towards e
    columns = (np.interp(times, t, theta), np.interp(times, t, rate),
               np.interp(times, t, acceleration))
    air = "fluidMoment" if stabiliser is not None else "moment"
    out = fit(*columns, np.array(loads[air]) @ normal)
    out["moment"] = "air" if stabiliser is not None else "load"
    if stabiliser is not None:
        out["balance"] = fit(*columns,
                             np.array(loads["balanceMoment"]) @ normal)
    out["weight"] = fit(*columns, np.array(loads["weightMoment"]) @ normal)
    th = np.degrees(theta[m])
    out.update(plane=[float(v) for v in e], angleMin=float(th.min()),
               angleMax=float(th.max()))
    return out
