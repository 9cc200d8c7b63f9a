"""forced_turn.py — the air's moment on a canopy turned about the payload by an imposed oscillation (fixedNodes.motion), split into its parts in phase with the angle and with the rate of turn.

A run whose cloth is held rigid and turned about the held payload by

    theta(t) = A sin(w (t - t0)),   w = 2 pi / T   (t > t0),

(prescribedRotation.H) gives the air's moment about the payload along the
axis of turn at each written state (load_moment.py: the pressure jump's
and the tangential load's; the cloth is fixed, so its carried
acceleration and any added-mass stabiliser's balance are zero). Over an
interval of whole periods it is fitted by least squares as

    M = a theta + c theta' + m0,

a linear air with M = k theta + c theta' + i theta'' gives
a = k - i w^2 at this frequency (two frequencies separate k and i) and c
its rate coefficient. The wake's own unsteadiness is broadband and
correlated in time, so the least squares' standard errors understate the
uncertainty: the same fit is made over each whole period in the interval
as well, and the periods' mean with its 95 % interval (Student's t on
their spread, the periods taken as independent samples) is the estimate
the report gives. c > 0 is a moment along the rate of turn: over a
period the air does the work W = pi c w A^2 on the canopy's turn, a
negative damping; c < 0 damps it. In coefficients on the stream's
q = rho U^2 / 2, S0 = pi D0^2 / 4 and D0: C_ma = a / (q S0 D0) per radian
and C_mq = c / (q S0 D0 * D0 / (2 U)), the rate made dimensionless by the
reduced frequency's time D0 / (2 U).
"""

import math

import numpy as np

from . import load_moment
from . import report as rep
from . import turn_fit


def angle(t, amplitude, period, start):
    """theta [rad] and theta' [rad/s] at times t [s] for amplitude
    [degrees], period [s] and start t0 [s]."""
    t = np.asarray(t, dtype=float)
    a = math.radians(amplitude)
    w = 2.0 * math.pi / period
    on = t > start
    theta = np.where(on, a * np.sin(w * (t - start)), 0.0)
    rate = np.where(on, a * w * np.cos(w * (t - start)), 0.0)
    return theta, rate


# Student's t, two-sided 95 %, by degrees of freedom (1-20)
T95 = (12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262,
       2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101,
       2.093, 2.086)


def mean_interval(values):
    """(mean, half-width of its 95 % interval by Student's t, count); the
    half-width is None for fewer than two values."""
    v = np.asarray(values, dtype=float)
    if len(v) < 2:
        return (float(v.mean()) if len(v) else None), None, len(v)
    t = T95[min(len(v) - 1, len(T95)) - 1]
    return float(v.mean()), float(t * v.std(ddof=1) / math.sqrt(len(v))), \
        len(v)


def fit(theta, rate, moment):
    """Least squares of moment on (theta, rate, 1): a, c, m0 with the
    standard errors of a and c, R^2 and the condition number."""
    coef, err, r2, cond = turn_fit.linear_fit((theta, rate), moment)
    return {"a": float(coef[0]), "c": float(coef[1]), "m0": float(coef[2]),
            "aErr": float(err[0]), "cErr": float(err[1]), "r2": r2,
            "condition": cond, "samples": int(len(moment))}


def analyse(case_dir, amplitude, period, start, axis, t0, t1, speed,
            diameter, rho):
    """The fit over the written states in [t0, t1] of a run turned by
    amplitude [degrees] sin(2 pi (t - start) / period) about axis, in a
    stream of speed [m/s], for a canopy of nominal diameter [m] in air of
    density rho: fit()'s keys over the whole interval; per whole period
    the fitted a and c (aPeriods, cPeriods), their means aMean, cMean with
    95 % half-widths a95, c95; from those the coefficients Cma, Cmq (with
    Cma95, Cmq95), the work per period W [J] (pi c w A^2, work95) and the
    reduced frequency w D0 / (2 U); the times and the moment fitted. None
    with fewer than 8 states."""
    loads = load_moment.analyse(case_dir, t0, t1)
    if loads["states"] < 8:
        return None
    e = np.asarray(axis, dtype=float)
    e /= np.linalg.norm(e)
    times = np.array(loads["times"])
    moment = np.array(loads["moment"]) @ e
    theta, rate = angle(times, amplitude, period, start)
    out = fit(theta, rate, moment)
    # period by period, over the whole periods in [t0, t1]
    # (an interval's ends a sample's spacing inside a period's are taken
    # as that period's: 5 % of it)
    slack = 0.05 * period
    first = start + period * max(0, math.ceil((t0 - start - slack) / period))
    per = []
    while first + period <= t1 + slack:
        m = (times >= first - 1e-9) & (times < first + period - 1e-9)
        if m.sum() >= 6:
            per.append(fit(theta[m], rate[m], moment[m]))
        first += period
    w = 2.0 * math.pi / period
    a = math.radians(amplitude)
    qsd = 0.5 * rho * speed ** 2 * math.pi * diameter ** 2 / 4.0 * diameter
    rate_scale = diameter / (2.0 * speed)
    a_mean, a_half, n = mean_interval([p["a"] for p in per])
    c_mean, c_half, _ = mean_interval([p["c"] for p in per])
    out.update(periods=n, aPeriods=[p["a"] for p in per],
               cPeriods=[p["c"] for p in per], aMean=a_mean, a95=a_half,
               cMean=c_mean, c95=c_half,
               Cma=a_mean / qsd if n else None,
               Cma95=a_half / qsd if a_half is not None else None,
               Cmq=c_mean / (qsd * rate_scale) if n else None,
               Cmq95=(c_half / (qsd * rate_scale) if c_half is not None
                      else None),
               work=math.pi * c_mean * w * a ** 2 if n else None,
               work95=(math.pi * c_half * w * a ** 2 if c_half is not None
                       else None),
               reducedFrequency=w * rate_scale,
               times=[float(v) for v in times],
               moment=[float(v) for v in moment])
    return out


def spectrum_peaks(t, forces, count=3, band=(0.02, 1.0)):
    """The largest local maxima of the summed power spectrum of the
    columns of forces (n x k) sampled at times t [s] (resampled uniformly
    at the median spacing, mean removed, Hann window) in band [Hz]: a list
    of (frequency [Hz], power over the largest's), largest first, and the
    resolution 1/(duration) [Hz]."""
    t = np.asarray(t, dtype=float)
    forces = np.asarray(forces, dtype=float).reshape(len(t), -1)
    dt = float(np.median(np.diff(t)))
    tu = np.arange(t[0], t[-1], dt)
    window = np.hanning(len(tu))
    power = 0.0
    for k in range(forces.shape[1]):
        y = np.interp(tu, t, forces[:, k])
        power = power + np.abs(np.fft.rfft((y - y.mean()) * window)) ** 2
    freq = np.fft.rfftfreq(len(tu), dt)
    inside = np.nonzero((freq >= band[0]) & (freq <= band[1]))[0]
    peaks = [i for i in inside if 0 < i < len(power) - 1
             and power[i] >= power[i - 1] and power[i] >= power[i + 1]]
    peaks.sort(key=lambda i: -power[i])
    top = power[peaks[0]] if peaks else 1.0
    return ([(float(freq[i]), float(power[i] / top)) for i in peaks[:count]],
            1.0 / (tu[-1] - tu[0]))


def wake_peaks(case_dir, t0, t1, count=3, band=(0.02, 1.0)):
    """spectrum_peaks of the force across the stream (canopy.dat's force_x
    and force_y over [t0, t1]) on a canopy held still in a stream along
    z: the frequencies of its wake's unsteadiness."""
    series = rep.load_case(case_dir)
    m = (series.t >= t0) & (series.t <= t1)
    return spectrum_peaks(series.t[m],
                          series.columns("force_x", "force_y")[m], count,
                          band)
