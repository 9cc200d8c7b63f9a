"""report.py — analysis of a canopyPimpleFoam run's canopy.dat time series (terminal descent velocity, breathing, drag coefficients, swing and glide) and the summary, report.json and plots of bin/canopy-report.

The solver writes postProcessing/canopy/<startTime>/canopy.dat, one row per
time step, whitespace separated, comment lines starting with '#':

     1 time [s]                      11 projected diameter [m]
   2-4 payload position [m]          12 canopy area [m^2]
   5-7 payload velocity [m/s]        13-15 kinetic, spring, gravity energy [J]
       (ground frame)                16 coupling iterations
  8-10 pressure force on the         17 coupling residual
       canopy [N]                    18 slip
                                     19 structure sub-steps
 20-22 the mesh frame's origin [m]   23-25 the lines' drag [N]
 26-28 the canopy's area-weighted centre [m] (ground frame)

and header lines "# nominalDiameter 2.134", "# totalMass 6.02" (canopy +
lines + payload, kg), "# rho 1.2", "# gravity 0 0 -9.81" when it knows them.
Columns are taken by name from the column-name line "# time payload_x ..."
when there is one (later solvers add columns, e.g. frame_x frame_y
frame_z); otherwise by position.

Definitions used throughout (stated in the summary too):
- descent speed V = v . g/|g|, the payload velocity along gravity: positive
  when the payload falls;
- the steady interval is the last fraction (default 1/3) of the run, from
  the run's start time to its last time, or [--steady-start, end];
- means and standard deviations over the interval are time-weighted
  (trapezoidal), so a variable time step does not bias them;
- breathing: the projected diameter over the interval, resampled on a
  uniform grid at the median step, detrended (least-squares line), Hann
  window, FFT; the peak bin k >= 1 gives the frequency, refined between bins
  with the Hann ratio formula; the bin width df = 1/(N dt) is the stated
  resolution. A peak at bin k < 2 (fewer than two periods in the interval)
  is reported as not resolved; the same above f = 0.1 V / Dp (Strouhal
  number f Dp / V >= 0.1, Dp the mean projected diameter), which leaves
  out the descent's slow swings, with the Strouhal number of its peak;
  the descent speed's spectrum the same way in the same band (its peak
  frequency, Strouhal number and amplitude in m/s);
- C_D from the force balance at terminal velocity, W = 1/2 rho V^2 S0 C_D,
  with W = total mass |g|, V the mean descent speed over the interval and
  S0 = pi D0^2 / 4 the nominal area; and C_D from the mean pressure force
  against gravity, -F . g/|g|, with the same V and S0.

- the canopy's shape over the interval (crown height, skirt radius,
  silhouette, creases by ring) from postProcessing/canopy/canopy.h5:
  shape.py states the definitions.
- the load on the cloth over the interval: canopy.dat's force as a mean
  vector with its spread and 95 % intervals, and the moment about the
  payload of the load canopy.h5 holds (load_moment.py states it).
- when the run wrote its structure every time step, the cloth's and the
  lines' velocity change from one step to the next over the interval
  (step_changes.py states it).

Only numpy is needed to analyse the time series; the shape needs h5py and
is reported as not read without it (or without canopy.h5); matplotlib is
imported by plot() alone.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

from . import shape as canopy_shape
from . import step_changes
from . import load_moment

COLUMNS = (
    "time",
    "payload_x", "payload_y", "payload_z",
    "payload_Ux", "payload_Uy", "payload_Uz",
    "force_x", "force_y", "force_z",
    "projected_diameter", "canopy_area",
    "kinetic", "spring", "gravity",
    "coupling_iterations", "residual", "slip", "substeps",
)
NCOLUMNS = len(COLUMNS)
# Columns later solvers add, read by name when the column-name line has
# them (NaN where a file lacks them): the canopy's area-weighted centre
OPTIONAL_COLUMNS = ("canopy_x", "canopy_y", "canopy_z")
COL = {name: i for i, name in enumerate(COLUMNS + OPTIONAL_COLUMNS)}

# Header key -> (command-line option, what it is, unit, number of values)
QUANTITIES = {
    "nominalDiameter": ("--diameter", "nominal diameter D0", "m", 1),
    "totalMass": ("--mass", "total mass (canopy + lines + payload)", "kg", 1),
    "rho": ("--rho", "air density rho", "kg/m^3", 1),
    "gravity": ("--gravity", "gravity vector", "m/s^2", 3),
}

# Published values for comparison (seed 000: Kim 2012, sec. 5.7, ch. 6).
# Every entry has a title and nominalDiameter [m]; the values, each
# optional (only those the seed states):
#   descentVelocityDropTest          measured steady descent [m/s]
#   descentVelocitySimulation        the seed's simulated terminal velocity
#   descentVelocitySimulationSpread  its +- [m/s]
#   descentVelocitySimulationRange   [lo, hi] simulated over payloadRange
#   payloadRange                     [lo, hi] payloads of that range [kg]
#   breathingFrequencyDropTest       measured breathing [Hz]
#   breathingFrequencySimulation     [lo, hi] the seed's simulation [Hz]
#   breathingPeriodExperiment        measured breathing period [s]
#   breathingPeriodSimulation        the seed's simulated period [s]
#   convergedStudy                   the validation study (bin/canopy-
#                                    validate) whose committed runs give
#                                    this tutorial's converged C_D0
REFERENCES = {
    "7ft": {
        "title": "7 ft flat circular canopy, D0 2.134 m, 16 lines, payload "
                 "5.398 kg (Kim 2012, Fig. 5.16)",
        "nominalDiameter": 2.134,
        "descentVelocityDropTest": 4.27,
        "descentVelocitySimulation": 3.9,
        "descentVelocitySimulationSpread": 0.05,
        "breathingFrequencyDropTest": 2.0,
        "breathingFrequencySimulation": [1.6, 2.0],
        "convergedStudy": "levels7ftDamped",
    },
    "T10": {
        "title": "T-10 parabolic canopy with apex vent, D0 10.7 m, 30 lines "
                 "x 7.8 m (Kim 2012, sec. 5.7(1), ch. 6)",
        "nominalDiameter": 10.7,
        "descentVelocitySimulationRange": [3.0, 6.0],
        "payloadRange": [100.0, 600.0],
        "breathingPeriodExperiment": 2.3,
        "breathingPeriodSimulation": 2.0,
        "convergedStudy": "resolutionT10KernelMarkerHalf",
    },
    "G11third": {
        "title": "1/3-scale G-11 flat circular canopy, D0 10.1 m, 30 lines "
                 "x 9.6 m, payload 150 kg (Kim 2012, Fig. 5.13, ch. 6, "
                 "Fig. 6.2)",
        "nominalDiameter": 10.1,
        "descentVelocitySimulation": 3.0,
    },
    "C9": {
        "title": "C-9 flat circular canopy, D0 8.53 m (28 ft) (Kim 2012, "
                 "ch. 6, Fig. 6.3)",
        "nominalDiameter": 8.53,
        "breathingPeriodSimulation": 2.0,
    },
}

DEFAULT_STEADY_FRACTION = 1.0 / 3.0
MIN_STEADY_SAMPLES = 4
MIN_PEAK_BIN = 2
# The breathing band's lower end in Strouhal number f Dp / V: a canopy's
# breathing has f Dp / V of order 0.5 (the seed's measurements: the 7 ft
# canopy about 2 Hz at 4.27 m/s and 1.6 m across, 0.75; the T-10 a period
# of 2.3 s at 6.7 m/s and 7.8 m, 0.51), and a fifth of that leaves out the
# descent's slow swings, periods of ten and more Dp / V
BREATHING_STROUHAL_MIN = 0.1
# The suspension's angle beyond which a run is said to swing: the
# smallest oscillation a handbook lists for a stable canopy's class
# (Knacke, NWC TP 6575, Table 5-1: ribbon and ringslot canopies 0 to ±3°,
# the solid canopies ±10° and more) rounded up
SWING_ONSET_DEG = 5.0
# The window over which a departure from the vertical descent is fitted
# as exp(rate t): the payload's speed across gravity from 1 % to 20 % of
# its descent, above the start's round-off and below the swing's
# saturation
SWING_GROWTH_LOW = 0.01
SWING_GROWTH_HIGH = 0.2


class ReportError(Exception):
    """Something in the data or the options prevents the analysis."""


class MissingQuantityError(ReportError):
    """A quantity is neither in canopy.dat's header nor given as option."""

    def __init__(self, missing):
        self.missing = list(missing)
        lines = []
        for key in self.missing:
            option, what, unit, n = QUANTITIES[key]
            value = "GX GY GZ" if n == 3 else "VALUE"
            lines.append("the %s [%s] is not known: canopy.dat has no "
                         "'# %s' line; give %s %s"
                         % (what, unit, key, option, value))
        ReportError.__init__(self, "\n".join(lines))


# ---- reading ---------------------------------------------------------------

def _floats(tokens):
    try:
        return [float(x) for x in tokens]
    except ValueError:
        return None


def read_dat(path):
    """Read one canopy.dat: (header, rows, skipped).

    header: {key: float or list of floats} from comment lines "# key v [v..]"
    whose values are all numbers; rows: float array (n, 19) in the order of
    COLUMNS; skipped: data lines left out because they do not hold a number
    per column (a line cut short by a crash, say).
    Columns are found by name when the file has the column-name comment
    line ("# time payload_x ..."), which may list more columns than these
    19 (the frame origin, say); without it, the first 19 are taken in the
    order of COLUMNS.
    """
    header = {}
    names = None
    rows = []
    skipped = 0
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            if line.startswith("#"):
                tokens = line[1:].split()
                if len(tokens) >= 2 and tokens[0] == "time" and \
                        _floats(tokens[1:]) is None:
                    names = tokens
                elif len(tokens) >= 2 and tokens[0][:1].isalpha():
                    values = _floats(tokens[1:])
                    if values is not None:
                        header[tokens[0]] = (values[0] if len(values) == 1
                                             else values)
                continue
            values = _floats(line.split())
            width = len(names) if names else None
            if (values is None or not math.isfinite(values[0])
                    or (width is not None and len(values) != width)
                    or len(values) < NCOLUMNS):
                skipped += 1
                continue
            rows.append(values)
    if names:
        missing = [c for c in COLUMNS if c not in names]
        if missing:
            raise ReportError("%s: no column %s in its column-name line"
                              % (path, ", ".join(missing)))
        order = [names.index(c) for c in COLUMNS]
        optional = [names.index(c) if c in names else None
                    for c in OPTIONAL_COLUMNS]
    else:
        order = list(range(NCOLUMNS))
        optional = [None] * len(OPTIONAL_COLUMNS)
    width = NCOLUMNS + len(OPTIONAL_COLUMNS)
    array = np.full((len(rows), width), np.nan)
    if rows:
        raw = np.array(rows, dtype=float)
        array[:, :NCOLUMNS] = raw[:, order]
        for k, i in enumerate(optional):
            if i is not None:
                array[:, NCOLUMNS + k] = raw[:, i]
    return header, array, skipped


class Series(object):
    """The concatenated time series of a run.

    t: times (strictly increasing); data: (n, 19) rows; header: merged
    header (a later file's value wins); files: one dict per canopy.dat
    (path, startTime, rows, used, skipped); start_time: the earliest
    startTime folder; overridden: rows replaced by a later file;
    conflicts: header keys whose value differs between files.
    """

    def __init__(self, data, header, files, start_time, overridden,
                 conflicts):
        self.data = data
        self.t = data[:, COL["time"]]
        self.header = header
        self.files = files
        self.start_time = start_time
        self.overridden = overridden
        self.conflicts = conflicts

    def column(self, name):
        return self.data[:, COL[name]]

    def columns(self, *names):
        return self.data[:, [COL[n] for n in names]]


def find_dat_files(case_dir):
    """[(startTime, path)] of postProcessing/canopy/<time>/canopy.dat,
    by increasing time."""
    base = os.path.join(case_dir, "postProcessing", "canopy")
    found = []
    if os.path.isdir(base):
        for name in os.listdir(base):
            path = os.path.join(base, name, "canopy.dat")
            try:
                start = float(name)
            except ValueError:
                continue
            if os.path.isfile(path):
                found.append((start, path))
    found.sort(key=lambda item: item[0])
    if not found:
        raise ReportError("no postProcessing/canopy/<time>/canopy.dat in %s "
                          "(has canopyPimpleFoam run there?)" % case_dir)
    return found


def _same(a, b):
    return np.allclose(np.atleast_1d(a), np.atleast_1d(b), rtol=1e-12,
                       atol=0.0)


def concatenate(pieces):
    """Concatenate [(startTime, path)] in time order into a Series.

    Restart rule: the files are taken by increasing start time; a later
    file overrides the earlier rows at and after its own first time
    (within 1e-9 relative), so a run restarted from an earlier write time
    replaces what the first run computed after it.
    """
    header = {}
    conflicts = set()
    files = []
    kept = np.zeros((0, NCOLUMNS + len(OPTIONAL_COLUMNS)))
    source = np.zeros(0, dtype=int)
    overridden = 0
    for index, (start, path) in enumerate(pieces):
        h, rows, skipped = read_dat(path)
        for key, value in h.items():
            if key in header and not _same(header[key], value):
                conflicts.add(key)
            header[key] = value
        files.append({"path": path, "startTime": start, "rows": len(rows),
                      "skipped": skipped})
        if len(rows) == 0:
            continue
        first = rows[0, 0]
        eps = 1e-9 * max(1.0, abs(first))
        keep = kept[:, 0] < first - eps
        overridden += int(np.count_nonzero(~keep))
        kept = np.vstack([kept[keep], rows])
        source = np.concatenate([source[keep],
                                 np.full(len(rows), index, dtype=int)])
    if len(kept) == 0:
        raise ReportError("no data rows in %s"
                          % ", ".join(p for _, p in pieces))
    # Within a file times increase; should one not, the last row written
    # for a time wins and the rows are put in order.
    order = np.argsort(kept[:, 0], kind="stable")
    kept, source = kept[order], source[order]
    t = kept[:, 0]
    last = np.ones(len(t), dtype=bool)
    last[:-1] = np.diff(t) > 1e-9 * np.maximum(1.0, np.abs(t[:-1]))
    if not last.all():
        overridden += int(np.count_nonzero(~last))
        kept, source = kept[last], source[last]
    for index, info in enumerate(files):
        info["used"] = int(np.count_nonzero(source == index))
    return Series(kept, header, files, pieces[0][0], overridden,
                  sorted(conflicts))


def load_case(case_dir):
    """The Series of a case directory (all its restarts)."""
    return concatenate(find_dat_files(case_dir))


# ---- parameters ------------------------------------------------------------

def resolve_parameters(header, diameter=None, mass=None, rho=None,
                       gravity=None):
    """{key: (value, source)} for the four quantities.

    An option given overrides the header; a quantity in neither raises
    MissingQuantityError naming every missing one.
    """
    given = {"nominalDiameter": diameter, "totalMass": mass, "rho": rho,
             "gravity": gravity}
    params = {}
    missing = []
    for key, (option, what, unit, n) in QUANTITIES.items():
        if given[key] is not None:
            value, source = given[key], option
        elif key in header:
            value, source = header[key], "canopy.dat header"
        else:
            missing.append(key)
            continue
        if n == 3:
            value = [float(x) for x in np.atleast_1d(value)]
            if len(value) != 3:
                raise ReportError("the %s needs 3 components, got %d (%s)"
                                  % (what, len(value), source))
            if not all(math.isfinite(x) for x in value) or \
                    math.sqrt(sum(x * x for x in value)) == 0.0:
                raise ReportError("the %s must be a non-zero vector (%s)"
                                  % (what, source))
        else:
            value = float(np.atleast_1d(value)[0])
            if not (math.isfinite(value) and value > 0.0):
                raise ReportError("the %s must be positive, got %g (%s)"
                                  % (what, value, source))
        params[key] = (value, source)
    if missing:
        raise MissingQuantityError(missing)
    return params


# ---- analysis --------------------------------------------------------------

def descent_speed(velocity, gravity):
    """Velocity component along gravity, (n, 3) -> (n,): > 0 when falling."""
    g = np.asarray(gravity, dtype=float)
    return np.asarray(velocity, dtype=float) @ (g / np.linalg.norm(g))


def steady_interval(t, run_start, fraction=None, start=None, stop=None):
    """(t0, t1, description) of the steady interval.

    stop: an explicit end time (clipped to the data; default the last
    time). start: an explicit start time (clipped to the data); otherwise
    the last `fraction` (default 1/3) of [run_start, end]. Raises
    ReportError when the interval holds fewer than MIN_STEADY_SAMPLES
    samples.
    """
    t = np.asarray(t, dtype=float)
    end = float(t[-1])
    stop_note = ""
    if stop is not None:
        if stop <= float(t[0]):
            raise ReportError("--steady-end %g is not after the first time "
                              "%g" % (stop, float(t[0])))
        if stop < end:
            end = float(stop)
            stop_note = ", to --steady-end %g" % stop
    if start is not None:
        if start >= end:
            raise ReportError("--steady-start %g is not before the %s %g"
                              % (start, "--steady-end" if stop_note
                                 else "last time", end))
        t0 = max(float(start), float(t[0]))
        how = "from --steady-start %g" % start
        if t0 > start:
            how += " (data start at %g)" % t0
    else:
        f = DEFAULT_STEADY_FRACTION if fraction is None else float(fraction)
        if not 0.0 < f <= 1.0:
            raise ReportError("--steady-fraction must be in (0, 1], got %g"
                              % f)
        t0 = max(end - f * (end - run_start), float(t[0]))
        how = ("last 1/3 of the run (default)" if fraction is None
               else "last %.3g of the run (--steady-fraction)" % f)
    how += stop_note
    n = int(np.count_nonzero(interval_mask(t, t0, end)))
    if n < MIN_STEADY_SAMPLES:
        raise ReportError("the steady interval t = %g .. %g holds %d samples; "
                          "need at least %d (a longer run, or an earlier "
                          "--steady-start)" % (t0, end, n, MIN_STEADY_SAMPLES))
    return t0, end, how


def interval_mask(t, t0, t1):
    tol = 1e-12 * max(1.0, abs(t0), abs(t1))
    return (t >= t0 - tol) & (t <= t1 + tol)


def trapezoid_weights(t):
    """Weights w_i with sum w_i y_i = the trapezoidal integral of y over t."""
    t = np.asarray(t, dtype=float)
    w = np.zeros(len(t))
    if len(t) < 2:
        w[:] = 1.0
        return w
    dt = np.diff(t)
    w[:-1] += 0.5 * dt
    w[1:] += 0.5 * dt
    return w


def time_statistics(t, y):
    """Time-weighted mean and standard deviation, min, max, and the drift
    (least-squares slope times the interval length) of y(t)."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    w = trapezoid_weights(t)
    mean = float(np.sum(w * y) / np.sum(w))
    std = float(math.sqrt(max(0.0, np.sum(w * (y - mean) ** 2) / np.sum(w))))
    slope = float(np.polyfit(t, y, 1)[0]) if len(t) >= 2 else 0.0
    return {"mean": mean, "std": std, "min": float(np.min(y)),
            "max": float(np.max(y)), "drift": slope * float(t[-1] - t[0])}


def mean_confidence(t, y, level_z=1.96):
    """The time mean's 95 % confidence half-width from the series' own
    autocorrelation (a correlated series has fewer independent samples
    than points): y resampled on a uniform grid at the median step,
    rho(k) its autocorrelation, the integral time scale
        T_i = dt (1/2 + sum_{k=1}^{K-1} rho(k)),
    K the first lag where rho <= 0, the effective sample count
    N_eff = T / (2 T_i) over the interval's length T, and the half-width
    level_z sigma / sqrt(N_eff). Returns (half-width, T_i, N_eff), with a
    None half-width when N_eff < 2 (the interval is shorter than two
    integral time scales: no estimate)."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    if len(t) < 4 or t[-1] <= t[0]:
        return None, None, None
    dt = float(np.median(np.diff(t)))
    n = int(round((t[-1] - t[0]) / dt)) + 1
    grid = np.linspace(t[0], t[-1], n)
    u = np.interp(grid, t, y)
    u = u - u.mean()
    var = float(np.mean(u * u))
    if var == 0.0:
        return 0.0, 0.0, float("inf")
    f = np.fft.rfft(u, 2 * n)
    acf = np.fft.irfft(f * np.conj(f))[:n] / (var * n)
    below = np.nonzero(acf[1:] <= 0.0)[0]
    last = int(below[0]) + 1 if below.size else n
    t_int = dt * (0.5 + float(np.sum(acf[1:last])))
    length = float(grid[-1] - grid[0]) + dt
    n_eff = length / (2.0 * t_int)
    if n_eff < 2.0:
        return None, t_int, n_eff
    return level_z * math.sqrt(var) / math.sqrt(n_eff), t_int, n_eff


def spectrum(t, y):
    """One-sided amplitude spectrum of y(t), detrended and Hann-windowed.

    y is resampled linearly on a uniform grid of N points at the median
    step dt; returns (frequencies, amplitudes, df) with df = 1/(N dt) the
    bin width and amplitudes scaled so that a sinusoid of amplitude A on a
    bin shows A.
    """
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    steps = np.diff(t)
    dt = float(np.median(steps))
    n = int(round((t[-1] - t[0]) / dt)) + 1
    n = max(n, 2)
    dt = (t[-1] - t[0]) / (n - 1)
    grid = t[0] + dt * np.arange(n)
    u = np.interp(grid, t, y)
    u = u - np.polyval(np.polyfit(grid, u, 1), grid)
    window = 0.5 - 0.5 * np.cos(2.0 * math.pi * np.arange(n) / n)
    amplitude = 2.0 * np.abs(np.fft.rfft(u * window)) / np.sum(window)
    return np.fft.rfftfreq(n, dt), amplitude, 1.0 / (n * dt)


def breathing(t, diameter, f_min=0.0, quantity="the diameter"):
    """The breathing frequency of the projected diameter over [t0, t1]:
    the spectrum's largest bin (bin 0 excluded), or with f_min > 0 its
    largest local maximum at or above f_min [Hz]. Any other series (the
    descent speed) the same way, quantity naming it in the note.

    Returns a dict: frequency (refined, or None when not resolved),
    binFrequency (the peak bin's centre), resolution (bin width df),
    peakBin, periods (in the interval, at the refined frequency),
    amplitude [m], resolved, note; and, for plots, _frequencies and
    _amplitudes.

    Refinement: for a Hann window the ratio of the larger neighbour to the
    peak, a = |X[k+-1]| / |X[k]|, gives the offset d = (2a - 1)/(a + 1) bins
    of a single tone exactly (large N). The bin itself is within df/2.
    """
    f, a, df = spectrum(t, diameter)
    result = {"frequency": None, "binFrequency": None, "resolution": df,
              "peakBin": None, "periods": None, "amplitude": None,
              "resolved": False, "note": "",
              "_frequencies": f, "_amplitudes": a}
    d = np.asarray(diameter, dtype=float)
    scale = max(abs(float(np.mean(d))), 1e-300)
    if len(a) < 3 or float(np.max(a[1:])) <= 1e-12 * scale:
        result["note"] = "no oscillation of %s" % quantity
        return result
    first = max(1, int(math.ceil(f_min / df - 1e-9)))
    if first >= len(a):
        result["note"] = ("no bin at or above %.3g Hz (Nyquist %.3g Hz)"
                          % (f_min, f[-1]))
        return result
    if f_min > 0.0:
        # above f_min, the largest local maximum: a larger peak below it
        # leaks a falling flank into the band's first bins
        peaks = [j for j in range(first, len(a) - 1)
                 if a[j] > a[j - 1] and a[j] >= a[j + 1]
                 and a[j] > 1e-12 * scale]
        if not peaks:
            result["note"] = ("no peak at or above %.3g Hz: the spectrum "
                              "falls across the band" % f_min)
            return result
        k = max(peaks, key=lambda j: a[j])
    else:
        k = first + int(np.argmax(a[first:]))
    result["peakBin"] = k
    result["binFrequency"] = float(f[k])
    result["amplitude"] = float(a[k])
    if k < MIN_PEAK_BIN:
        result["note"] = ("the peak is at bin %d, fewer than %d "
                          "periods in the interval" % (k, MIN_PEAK_BIN))
        return result
    if k >= len(a) - 1:
        result["note"] = "the peak is at the Nyquist frequency"
        return result
    left, right = a[k - 1], a[k + 1]
    side = 1.0 if right >= left else -1.0
    ratio = max(left, right) / a[k]
    offset = side * (2.0 * ratio - 1.0) / (ratio + 1.0)
    offset = min(max(offset, -0.5), 0.5)
    frequency = (k + offset) * df
    result["frequency"] = float(frequency)
    result["periods"] = float(frequency / df)
    result["resolved"] = True
    return result


def breathing_band(t, diameter, speed, mean_diameter,
                   quantity="the diameter"):
    """The breathing in the band f Dp / V >= BREATHING_STROUHAL_MIN (Dp the
    mean projected diameter, V the mean descent speed): the breathing
    analysis above that frequency, with the Strouhal number f Dp / V of
    the peak found (of the diameter, or of another series such as the
    descent speed, quantity naming it). None when the parachute is not
    descending."""
    if not speed > 0.0 or not mean_diameter > 0.0:
        return None
    f_min = BREATHING_STROUHAL_MIN * speed / mean_diameter
    b = {k: v for k, v in breathing(t, diameter, f_min, quantity).items()
         if not k.startswith("_")}
    b["fMin"] = f_min
    b["strouhalMin"] = BREATHING_STROUHAL_MIN
    b["strouhal"] = (b["frequency"] * mean_diameter / speed
                     if b["resolved"] else None)
    return b


def suspension_angle(offset, ghat):
    """The suspension's angle to the vertical [degrees] and the offset's
    part across gravity, from the canopy's centre's offset from the
    payload (n x 3, ground frame): theta = atan(|offset across gravity| /
    offset against gravity); None when the offsets are not in the data
    (an older solver's canopy.dat)."""
    offset = np.asarray(offset, dtype=float)
    if len(offset) == 0 or not np.all(np.isfinite(offset)):
        return None
    up = -np.asarray(ghat, dtype=float)
    along = offset @ up
    across = offset - np.outer(along, up)
    theta = np.degrees(np.arctan2(np.linalg.norm(across, axis=1), along))
    return theta, across


def swing_onset(t, theta, threshold=SWING_ONSET_DEG):
    """The first time the suspension's angle exceeds threshold degrees,
    or None."""
    above = np.nonzero(np.asarray(theta) > threshold)[0]
    return float(t[above[0]]) if len(above) else None


def swing_growth(t, horizontal, descent, low=SWING_GROWTH_LOW,
                 high=SWING_GROWTH_HIGH):
    """The growth of a departure from the vertical descent, over the
    whole run: the payload's speed across gravity H against its descent
    V, from the last time H/V is below `low` before it first passes
    `high`; H grows there as exp(rate t) when the vertical descent is
    unstable. Returns None when H/V never passes `high` (or the window has
    fewer than 4 samples), else rate [1/s] (the least-squares slope of
    ln H), doublingTime ln 2 / rate [s], the mean descent over the window
    [m/s], and the window's start and end."""
    t = np.asarray(t, dtype=float)
    H = np.asarray(horizontal, dtype=float)
    V = np.asarray(descent, dtype=float)
    ratio = H / np.maximum(np.abs(V), 1e-12)
    above = np.nonzero(ratio > high)[0]
    if not len(above):
        return None
    end = above[0]
    below = np.nonzero(ratio[:end] < low)[0]
    if not len(below):
        return None
    start = below[-1]
    if end - start + 1 < 4 or np.any(H[start:end + 1] <= 0.0):
        return None
    rate = float(np.polyfit(t[start:end + 1], np.log(H[start:end + 1]),
                            1)[0])
    return {"rate": rate,
            "doublingTime": (math.log(2.0) / rate if rate > 0 else None),
            "descent": float(np.mean(V[start:end + 1])),
            "start": float(t[start]), "end": float(t[end]),
            "low": low, "high": high}


def _angle_between(a, b):
    """Row-wise angle between the vectors of a and b (n x 3) [degrees]."""
    na = np.linalg.norm(a, axis=1)
    nb = np.linalg.norm(b, axis=1)
    c = np.sum(a * b, axis=1) / np.maximum(na * nb, 1e-300)
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def incidence(t, offset, velocity, force):
    """The canopy's incidence over the interval, in still air: the angle
    between its axis (the payload-to-canopy offset, n x 3) and the relative
    wind on the payload (minus its velocity), and the angle between the
    canopy's load (canopy.dat's force) and its axis (zero for a canopy whose force is
    all along its axis, whose lift across the wind is then its drag times
    tan(incidence)). Time-weighted means and the largest values
    [degrees]."""
    a = _angle_between(offset, -np.asarray(velocity, dtype=float))
    f = _angle_between(force, offset)
    w = trapezoid_weights(t)
    return {"incidenceMean": float(np.sum(w * a) / np.sum(w)),
            "incidenceMax": float(np.max(a)),
            "forceOffAxisMean": float(np.sum(w * f) / np.sum(w)),
            "forceOffAxisMax": float(np.max(f))}


def glide(t, velocity, ghat, speed):
    """The interval's glide: the payload's mean velocity across gravity
    (a swing about the vertical averages out, a glide does not), its
    magnitude [m/s] and its angle to the vertical atan(glide / descent)
    [degrees]."""
    velocity = np.asarray(velocity, dtype=float)
    ghat = np.asarray(ghat, dtype=float)
    across = velocity - np.outer(velocity @ ghat, ghat)
    w = trapezoid_weights(t)
    mean = np.sum(w[:, None] * across, axis=0) / np.sum(w)
    g = float(np.linalg.norm(mean))
    return {"speed": g,
            "angle": float(np.degrees(math.atan2(g, speed)))}


def suspension_swing(t, offset, ghat):
    """The suspension's angle to the vertical over the interval (see
    suspension_angle). Returns None when the offsets are not in the data,
    else a dict: angleMax, angleMean and angleRms [degrees], and the
    swing's frequency, period and amplitude [m] from the spectrum of the
    offset's component across gravity along which it varies most (the
    breathing analysis's peak finder; frequency None when not resolved)."""
    if len(t) < 2:
        return None
    angle = suspension_angle(offset, ghat)
    if angle is None:
        return None
    theta, across = angle
    w = trapezoid_weights(t)
    # the direction across gravity in which the offset varies most
    dev = across - np.sum(w[:, None] * across, axis=0) / np.sum(w)
    _, _, vt = np.linalg.svd(dev * np.sqrt(w)[:, None], full_matrices=False)
    peak = breathing(t, dev @ vt[0])
    return {"angleMax": float(np.max(theta)),
            "angleMean": float(np.sum(w * theta) / np.sum(w)),
            "angleRms": float(math.sqrt(np.sum(w * theta ** 2)
                                        / np.sum(w))),
            "frequency": peak["frequency"],
            "period": (1.0 / peak["frequency"] if peak["frequency"]
                       else None),
            "amplitude": peak["amplitude"],
            "note": peak["note"]}


def canopy_load(case_dir, t, force, t0, t1):
    """The load on the cloth over the interval: the fluid's (canopy.dat's
    force) time-weighted mean vector [N] with each component's standard
    deviation and the mean's 95 % interval (mean_confidence; None where
    not estimated), and the moment about the payload [N m] of the load
    the structure is given (load_moment.py: the fluid's, plus the
    added-mass stabiliser's balance on a moving cloth), the mean and
    standard deviation over the states canopy.h5 holds in the interval
    (moment None with a note when they cannot be read)."""
    force = np.asarray(force, dtype=float)
    out = {"force": [], "forceStd": [], "forceCi95": []}
    for k in range(3):
        stats = time_statistics(t, force[:, k])
        out["force"].append(stats["mean"])
        out["forceStd"].append(stats["std"])
        out["forceCi95"].append(mean_confidence(t, force[:, k])[0])
    try:
        moment = load_moment.analyse(case_dir, t0, t1)
    except load_moment.LoadMomentError as e:
        out.update(moment=None, momentNote=str(e))
        return out
    out.update(moment=moment["momentMean"],
               momentStd=[float(v) for v in np.std(moment["moment"],
                                                   axis=0)],
               momentStates=moment["states"])
    return out


def drag_coefficients(speed, drag_force, mass, gravity, rho, diameter):
    """C_D = W / (q S0) and C_D = drag / (q S0), q = rho V^2 / 2."""
    g = float(np.linalg.norm(gravity))
    area = math.pi * diameter ** 2 / 4.0
    weight = mass * g
    q = 0.5 * rho * speed ** 2
    out = {"nominalArea": area, "weight": weight, "dynamicPressure": q,
           "weightBalance": None, "pressureForce": None}
    if speed > 0.0:
        out["weightBalance"] = weight / (q * area)
        out["pressureForce"] = drag_force / (q * area)
    return out


def analyse(case_dir, fraction=None, steady_start=None, diameter=None,
            mass=None, rho=None, gravity=None, reference=None, series=None,
            steady_end=None):
    """The whole report as a JSON-ready dict (plus '_series' and
    '_breathing' for plotting, which write_outputs leaves out)."""
    case_dir = os.path.abspath(case_dir)
    if series is None:
        series = load_case(case_dir)
    params = resolve_parameters(series.header, diameter, mass, rho, gravity)
    if reference is not None and reference not in REFERENCES:
        raise ReportError("unknown reference '%s' (known: %s)"
                          % (reference, ", ".join(sorted(REFERENCES))))
    D0 = params["nominalDiameter"][0]
    g = np.array(params["gravity"][0])
    ghat = g / np.linalg.norm(g)
    t = series.t
    if len(t) < 2:
        raise ReportError("only %d time step in the data" % len(t))
    U = series.columns("payload_Ux", "payload_Uy", "payload_Uz")
    V = descent_speed(U, g)
    # the payload's speed across gravity: a swing or a glide
    H = np.linalg.norm(np.asarray(U, dtype=float) - np.outer(V, ghat), axis=1)
    drag = -series.columns("force_x", "force_y", "force_z") @ ghat
    D = series.column("projected_diameter")
    iterations = series.column("coupling_iterations")

    t0, t1, how = steady_interval(t, series.start_time, fraction,
                                  steady_start, steady_end)
    m = interval_mask(t, t0, t1)
    ts = t[m]
    v_stats = time_statistics(ts, V[m])
    ci, t_int, n_eff = mean_confidence(ts, V[m])
    v_stats.update(ci95=ci, integralTime=t_int, effectiveSamples=n_eff)
    h_stats = time_statistics(ts, H[m])
    d_stats = time_statistics(ts, D[m])
    f_stats = time_statistics(ts, drag[m])
    b = breathing(ts, D[m])
    b_band = breathing_band(ts, D[m], v_stats["mean"], d_stats["mean"])
    # the descent speed's spectrum in the same band: the breathing as the
    # payload feels it
    v_band = breathing_band(ts, V[m], v_stats["mean"], d_stats["mean"],
                            "the descent speed")
    offset = series.columns("canopy_x", "canopy_y", "canopy_z") \
        - series.columns("payload_x", "payload_y", "payload_z")
    swing = suspension_swing(ts, offset[m], ghat)
    angle = suspension_angle(offset, ghat)
    theta = None if angle is None else angle[0]
    if swing is not None:
        swing["onset"] = swing_onset(t, theta)
        swing["onsetThreshold"] = SWING_ONSET_DEG
        swing["glide"] = glide(ts, np.asarray(U, dtype=float)[m], ghat,
                               v_stats["mean"])
        swing["growth"] = swing_growth(t, H, V)
        swing.update(incidence(ts, offset[m], np.asarray(U, dtype=float)[m],
                               series.columns("force_x", "force_y",
                                              "force_z")[m]))
    cd = drag_coefficients(v_stats["mean"], f_stats["mean"],
                           params["totalMass"][0], g,
                           params["rho"][0], D0)
    try:
        form = dict(canopy_shape.analyse(case_dir, t0, t1), available=True)
    except canopy_shape.ShapeError as e:
        form = {"available": False, "note": str(e)}
    try:
        changes = dict(step_changes.analyse(case_dir, t0, t1, t),
                       available=True)
    except step_changes.StepChangeError:
        changes = None      # the run did not write every step
    load = canopy_load(case_dir, ts,
                       series.columns("force_x", "force_y", "force_z")[m],
                       t0, t1)
    steady_warning = ""
    if abs(v_stats["drift"]) > max(2.0 * v_stats["std"],
                                   0.01 * abs(v_stats["mean"])):
        steady_warning = ("the descent speed drifts by %+.3g m/s over the "
                          "interval: not steady yet" % v_stats["drift"])

    report = {
        "case": os.path.basename(case_dir),
        "caseDir": case_dir,
        "files": [dict(info, path=os.path.relpath(info["path"], case_dir))
                  for info in series.files],
        "steps": int(len(t)),
        "restarts": max(0, sum(1 for i in series.files if i["rows"]) - 1),
        "overriddenRows": int(series.overridden),
        "skippedLines": int(sum(i["skipped"] for i in series.files)),
        "headerConflicts": series.conflicts,
        "runStart": float(series.start_time),
        "timeFirst": float(t[0]),
        "timeEnd": float(t[-1]),
        "simulatedTime": float(t[-1] - series.start_time),
        "parameters": {key: {"value": value, "source": source}
                       for key, (value, source) in params.items()},
        "descentDirection": [float(x) for x in ghat],
        "steady": {"start": float(t0), "end": float(t1),
                   "duration": float(t1 - t0), "samples": int(len(ts)),
                   "method": how, "warning": steady_warning},
        "descentVelocity": v_stats,
        "horizontalVelocity": h_stats,
        "projectedDiameter": d_stats,
        "pressureForceAgainstGravity": f_stats,
        "canopyLoad": load,
        "breathing": {k: v for k, v in b.items() if not k.startswith("_")},
        "breathingBand": b_band,
        "descentBand": v_band,
        "swing": swing,
        "shape": form,
        "dragCoefficient": cd,
        "coupling": {
            "meanIterations": float(np.mean(iterations)),
            "meanIterationsSteady": float(np.mean(iterations[m])),
            "maxIterations": int(np.max(iterations)),
            "meanResidualSteady": float(np.mean(
                series.column("residual")[m])),
        },
        "reference": None,
        "_series": series,
        "_breathing": b,
        "_descent": V,
        "_angle": theta,
        "_horizontal": H,
    }
    if changes is not None:
        report["stepChanges"] = changes
    if reference is not None:
        report["reference"] = dict(REFERENCES[reference], name=reference)
    return report


# ---- output ----------------------------------------------------------------

def _g(x, digits=4):
    return "-" if x is None else "%.*g" % (digits, x)


def _reference_descent(ref, v_mean):
    """The reference's descent velocities as one phrase ('' if none)."""
    parts = []
    if "descentVelocityDropTest" in ref:
        x = ref["descentVelocityDropTest"]
        parts.append("drop test %.3g m/s (V/ref = %.3f)" % (x, v_mean / x))
    if "descentVelocitySimulation" in ref:
        x = ref["descentVelocitySimulation"]
        text = "seed simulation %.2g" % x
        if "descentVelocitySimulationSpread" in ref:
            text += " +- %.2g" % ref["descentVelocitySimulationSpread"]
        text += " m/s"
        if "descentVelocityDropTest" not in ref:
            text += " (V/ref = %.3f)" % (v_mean / x)
        parts.append(text)
    if "descentVelocitySimulationRange" in ref:
        lo, hi = ref["descentVelocitySimulationRange"]
        text = "seed simulation %.2g-%.2g m/s" % (lo, hi)
        if "payloadRange" in ref:
            text += " for payloads %.4g-%.4g kg" % tuple(ref["payloadRange"])
        parts.append(text)
    return ", ".join(parts)


def _reference_breathing(ref):
    """The reference's breathing values as one phrase ('' if none)."""
    parts = []
    if "breathingFrequencyDropTest" in ref:
        parts.append("drop test about %.2g Hz"
                     % ref["breathingFrequencyDropTest"])
    if "breathingPeriodExperiment" in ref:
        x = ref["breathingPeriodExperiment"]
        parts.append("experiment period %.2g s (%.3g Hz)" % (x, 1.0 / x))
    if "breathingFrequencySimulation" in ref:
        parts.append("seed simulation %.2g-%.2g Hz"
                     % tuple(ref["breathingFrequencySimulation"]))
    if "breathingPeriodSimulation" in ref:
        x = ref["breathingPeriodSimulation"]
        parts.append("seed simulation period about %.2g s (%.3g Hz)"
                     % (x, 1.0 / x))
    return ", ".join(parts)


def _converged_line(study, cd0):
    """This run's C_D0 against the converged value of a resolution study
    (the finest level of its committed runs, with its GCI), or None when
    the study has too few complete runs."""
    from . import validation_tables
    try:
        conv = validation_tables.converged(study)["C_D0 (weight)"]
    except (SystemExit, KeyError, OSError, ValueError):
        return None
    line = ("     converged C_D0 %.3g +- %.1f %% (GCI; %s, study %s); this "
            "run's C_D0 differs by %+.0f %%" % (
                conv["finest"], 100 * conv["gci"], conv["runs"][0], study,
                100 * (cd0 / conv["finest"] - 1)))
    if conv.get("caveat"):
        line += "\n     caveat: " + conv["caveat"]
    return line


def shape_summary(form, D0):
    """The summary's lines on the canopy's shape (shape.py)."""
    if not form or not form.get("available"):
        return "  shape        not read: %s" % (
            form["note"] if form else "no shape in this report")
    rings = form["rings"]
    return "\n".join([
        "  shape        crown %.3g m above the skirt (%.3g D0); skirt radius "
        "%.3g m (%.3g .. %.3g), largest radius %.3g m (%.3g D0) about the "
        "payload-canopy axis%s; mean of %d states written in the interval"
        % (form["crownHeight"], form["crownHeight"] / D0,
           form["skirtRadiusMean"], form["skirtRadiusMin"],
           form["skirtRadiusMax"], form["largestRadius"],
           form["largestRadius"] / D0,
           "; silhouette's diameter %.3g m (%.3g D0)" % (
               form["silhouetteDiameter"], form["silhouetteDiameter"] / D0)
           if "silhouetteDiameter" in form else "", form["states"]),
        "  creases      fold angle between neighbouring cloth triangles by "
        "ring (s = 0 crown .. 1 skirt: %s): %s deg; folded beyond %g deg: "
        "%s %%" % (
            " ".join("%g-%g" % (q["inner"], q["outer"]) for q in rings),
            " / ".join(_g(q["foldMean"], 2) for q in rings),
            canopy_shape.FOLDED_DEGREES,
            " / ".join(_g(100 * q["foldedFraction"], 2) for q in rings))])


def format_summary(r):
    """The one-screen summary of a report dict."""
    p = r["parameters"]
    v, d, b = r["descentVelocity"], r["projectedDiameter"], r["breathing"]
    cd, s, c = r["dragCoefficient"], r["steady"], r["coupling"]
    ref = r.get("reference")
    D0 = p["nominalDiameter"]["value"]

    def src(key):
        return "" if p[key]["source"] == "canopy.dat header" else \
            " (%s)" % p[key]["source"]

    folders = ", ".join(os.path.basename(os.path.dirname(f["path"]))
                        for f in r["files"])
    out = []
    add = out.append
    add("canopy-report: case %s" % r["case"])
    add("  data         postProcessing/canopy/{%s}/canopy.dat: %d steps, "
        "%d restart(s), %d overridden row(s)%s"
        % (folders, r["steps"], r["restarts"], r["overriddenRows"],
           ", %d bad line(s) skipped" % r["skippedLines"]
           if r["skippedLines"] else ""))
    add("  simulated    t = %s .. %s s (%s s)"
        % (_g(r["runStart"]), _g(r["timeEnd"], 6), _g(r["simulatedTime"], 6)))
    gvec = p["gravity"]["value"]
    add("  parameters   D0 %s m%s (S0 %s m^2), total mass %s kg%s, "
        "rho %s kg/m^3%s, g (%s) m/s^2%s"
        % (_g(D0), src("nominalDiameter"), _g(cd["nominalArea"]),
           _g(p["totalMass"]["value"]), src("totalMass"),
           _g(p["rho"]["value"]), src("rho"),
           " ".join(_g(x) for x in gvec), src("gravity")))
    add("  steady       t = %s .. %s s (%s s, %d steps): %s"
        % (_g(s["start"], 6), _g(s["end"], 6), _g(s["duration"]),
           s["samples"], s["method"]))
    if s["warning"]:
        add("  WARNING      %s" % s["warning"])
    line = ("  descent V    %.4g m/s  std %.3g  min %.4g  max %.4g  "
            "(V = v.g/|g|, time-weighted)"
            % (v["mean"], v["std"], v["min"], v["max"]))
    add(line)
    if v.get("ci95") is not None:
        add("  mean's 95 %% interval  +- %.2g m/s (integral time %.3g s, %.0f "
            "independent samples)" % (v["ci95"], v["integralTime"],
                                     v["effectiveSamples"]))
    elif "ci95" in v:
        add("  mean's 95 % interval  none: the interval is shorter than two "
            "integral times of the series")
    if ref and _reference_descent(ref, v["mean"]):
        add("     ref %-5s %s" % (ref["name"],
                                  _reference_descent(ref, v["mean"])))
    h = r["horizontalVelocity"]
    add("  horizontal   %.3g m/s  max %.3g  (the payload's speed across "
        "gravity: a swing or glide)" % (h["mean"], h["max"]))
    sw = r.get("swing")
    if sw:
        add("  swing        suspension at %.3g deg to the vertical at most "
            "(rms %.3g)%s" % (
                sw["angleMax"], sw["angleRms"],
                "; period %.3g s, amplitude %.3g m" % (
                    sw["period"], sw["amplitude"]) if sw["period"]
                else "; no period resolved"))
        if sw.get("glide"):
            add("  glide        %.3g m/s across gravity on average over the "
                "interval (%.3g deg from the vertical); mean suspension "
                "angle %.3g deg; %s" % (
                    sw["glide"]["speed"], sw["glide"]["angle"],
                    sw["angleMean"],
                    "beyond %g deg from %.4g s" % (sw["onsetThreshold"],
                                                   sw["onset"])
                    if sw["onset"] is not None else
                    "never beyond %g deg" % sw["onsetThreshold"]))
        if "incidenceMean" in sw:
            add("  incidence    the relative wind at %.3g deg to the canopy's "
                "axis on average (at most %.3g; still air); the canopy's "
                "force %.3g deg off its axis on average (at most %.3g)" % (
                    sw["incidenceMean"], sw["incidenceMax"],
                    sw["forceOffAxisMean"], sw["forceOffAxisMax"]))
        gr = sw.get("growth")
        if gr:
            add("  departure    the speed across gravity grows as exp(%.3g "
                "t) (doubling in %.3g s) from %.3g to %.3g s (%g to %g of "
                "the descent)" % (gr["rate"], gr["doublingTime"] or
                                  float("inf"), gr["start"], gr["end"],
                                  gr["low"], gr["high"]))
    load = r.get("canopyLoad")
    if load:
        add("  load         on the cloth (%s) N mean over the interval%s" % (
            " ".join("%.4g" % x for x in load["force"]),
            "; its moment about the payload (%s) N m (mean of %d written "
            "states)" % (" ".join("%.4g" % x for x in load["moment"]),
                         load["momentStates"]) if load.get("moment")
            else " (moment not read: %s)" % load.get("momentNote", "")))
    add("  diameter     %.4g m = %.3f D0  std %.3g  min %.4g  max %.4g"
        % (d["mean"], d["mean"] / D0, d["std"], d["min"], d["max"]))
    add(shape_summary(r.get("shape"), D0))
    if b["resolved"]:
        add("  breathing    %.4g Hz  (resolution %.3g Hz, peak bin %d, "
            "%.1f periods, amplitude %.3g m)"
            % (b["frequency"], b["resolution"], b["peakBin"], b["periods"],
               b["amplitude"]))
    else:
        add("  breathing    not resolved (resolution %.3g Hz): %s"
            % (b["resolution"], b["note"]))
    bb = r.get("breathingBand")
    if bb and bb["resolved"]:
        add("  breathing    above St %.2g (f >= %.3g Hz): %.4g Hz, St = f Dp/V "
            "= %.3g, amplitude %.3g m, %.1f periods"
            % (bb["strouhalMin"], bb["fMin"], bb["frequency"], bb["strouhal"],
               bb["amplitude"], bb["periods"]))
    elif bb:
        add("  breathing    above St %.2g (f >= %.3g Hz): not resolved: %s"
            % (bb["strouhalMin"], bb["fMin"], bb["note"]))
    vb = r.get("descentBand")
    if vb and vb["resolved"]:
        add("  descent      its spectrum above St %.2g: %.4g Hz, St = %.3g, "
            "amplitude %.3g m/s, %.1f periods"
            % (vb["strouhalMin"], vb["frequency"], vb["strouhal"],
               vb["amplitude"], vb["periods"]))
    elif vb:
        add("  descent      its spectrum above St %.2g: not resolved: %s"
            % (vb["strouhalMin"], vb["note"]))
    if ref and _reference_breathing(ref):
        add("     ref %-5s %s" % (ref["name"], _reference_breathing(ref)))
    if cd["weightBalance"] is None:
        add("  drag coeff.  not defined: the payload is not descending")
    else:
        add("  C_D weight   %.4g  = W / (rho V^2 S0 / 2), W = %.4g N, "
            "q = %.4g Pa" % (cd["weightBalance"], cd["weight"],
                             cd["dynamicPressure"]))
        add("  C_D force    %.4g  = mean pressure force against gravity "
            "%.4g N / (q S0)" % (cd["pressureForce"],
                                 r["pressureForceAgainstGravity"]["mean"]))
    if ref and ref.get("convergedStudy") and cd["weightBalance"] is not None:
        line = _converged_line(ref["convergedStudy"], cd["weightBalance"])
        if line:
            add(line)
    if ref and abs(D0 - ref["nominalDiameter"]) > \
            1e-3 * ref["nominalDiameter"]:
        add("  NOTE         the reference is for D0 = %.4g m; this case has "
            "%.4g m" % (ref["nominalDiameter"], D0))
    add("  coupling     %.2f iterations per step (steady interval %.2f, "
        "max %d), mean residual over the interval %.3g"
        % (c["meanIterations"], c["meanIterationsSteady"],
           int(c["maxIterations"]), c["meanResidualSteady"]))
    if r["headerConflicts"]:
        add("  NOTE         header values differ between restarts "
            "(the latest used): %s" % ", ".join(r["headerConflicts"]))
    return "\n".join(out) + "\n"


def _finite(value):
    """value with NaN/Inf floats replaced by None (JSON has neither)."""
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def json_ready(report):
    """The report without the private (underscore) entries, JSON-safe."""
    return _finite({k: v for k, v in report.items() if not k.startswith("_")})


def plot(report, out_dir):
    """Write descentVelocity.png, projectedDiameter.png and (when the
    data hold the canopy's and payload's positions) swing.png in out_dir;
    return their paths."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    series = report["_series"]
    t = series.t
    V = report["_descent"]
    D = series.column("projected_diameter")
    s = report["steady"]
    v = report["descentVelocity"]
    ref = report.get("reference")
    D0 = report["parameters"]["nominalDiameter"]["value"]
    restarts = [f["startTime"] for f in report["files"][1:] if f["rows"]]
    paths = []

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(t, V, color="C0", lw=1.2, label="descent speed")
    ax.axvspan(s["start"], s["end"], color="0.9", zorder=0,
               label="steady interval")
    ax.hlines(v["mean"], s["start"], s["end"], color="C3",
              label="mean %.3g m/s (std %.2g)" % (v["mean"], v["std"]))
    if ref and "descentVelocityDropTest" in ref:
        ax.axhline(ref["descentVelocityDropTest"], color="k", ls="--", lw=1,
                   label="drop test %.3g m/s" % ref["descentVelocityDropTest"])
    if ref and "descentVelocitySimulation" in ref:
        ax.axhline(ref["descentVelocitySimulation"], color="0.4", ls=":",
                   lw=1, label="seed simulation %.2g m/s"
                   % ref["descentVelocitySimulation"])
    if ref and "descentVelocitySimulationRange" in ref:
        lo, hi = ref["descentVelocitySimulationRange"]
        ax.axhspan(lo, hi, color="0.4", alpha=0.12, zorder=0,
                   label="seed simulation %.2g-%.2g m/s" % (lo, hi)
                   + (" (%.4g-%.4g kg)" % tuple(ref["payloadRange"])
                      if "payloadRange" in ref else ""))
    for x in restarts:
        ax.axvline(x, color="0.6", ls=":", lw=0.8)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("descent speed [m/s]")
    ax.set_title("%s: payload descent speed" % report["case"])
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    path = os.path.join(out_dir, "descentVelocity.png")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    paths.append(path)

    b = report["_breathing"]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7))
    ax1.plot(t, D, color="C0", lw=1.2, label="projected diameter")
    ax1.axvspan(s["start"], s["end"], color="0.9", zorder=0,
                label="steady interval")
    ax1.axhline(D0, color="k", ls="--", lw=1, label="nominal D0 %.4g m" % D0)
    for x in restarts:
        ax1.axvline(x, color="0.6", ls=":", lw=0.8)
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("projected diameter [m]")
    ax1.set_title("%s: projected diameter" % report["case"])
    ax1.grid(True, alpha=0.3)
    ax1.legend(loc="best", fontsize=8)
    f, a = b["_frequencies"], b["_amplitudes"]
    ax2.plot(f[1:], a[1:], color="C0", lw=1.2, marker=".", ms=3)
    if b["resolved"]:
        ax2.axvline(b["frequency"], color="C3", lw=1,
                    label="breathing %.3g Hz" % b["frequency"])
        ax2.set_xlim(0, min(f[-1], max(5.0 * b["frequency"], 10 *
                                       b["resolution"])))
        ax2.legend(loc="best", fontsize=8)
    ax2.set_xlabel("frequency [Hz]  (resolution %.3g Hz)" % b["resolution"])
    ax2.set_ylabel("amplitude [m]")
    ax2.set_title("spectrum over the steady interval (detrended, Hann)"
                  + ("" if b["resolved"] else
                     ": not resolved, " + b["note"]), fontsize=9)
    ax2.grid(True, alpha=0.3)
    fig.tight_layout()
    path = os.path.join(out_dir, "projectedDiameter.png")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    paths.append(path)

    theta = report.get("_angle")
    if theta is not None:
        fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
        ax1.plot(t, theta, color="C0", lw=1.2)
        ax1.axvspan(s["start"], s["end"], color="0.9", zorder=0,
                    label="steady interval")
        ax1.set_ylabel("suspension's angle\nto the vertical [deg]")
        ax1.set_title("%s: swing and glide" % report["case"])
        ax1.grid(True, alpha=0.3)
        ax1.legend(loc="best", fontsize=8)
        ax2.plot(t, report["_horizontal"], color="C1", lw=1.2)
        ax2.set_ylabel("payload's speed\nacross gravity [m/s]")
        ax2.set_xlabel("time [s]")
        ax2.grid(True, alpha=0.3)
        for x in restarts:
            ax1.axvline(x, color="0.6", ls=":", lw=0.8)
            ax2.axvline(x, color="0.6", ls=":", lw=0.8)
        fig.tight_layout()
        path = os.path.join(out_dir, "swing.png")
        fig.savefig(path, dpi=120)
        plt.close(fig)
        paths.append(path)
    return paths


def write_outputs(report, out_dir, plots=True):
    """summary.txt, report.json (and the plots) in out_dir; the summary."""
    os.makedirs(out_dir, exist_ok=True)
    outputs = plot(report, out_dir) if plots else []
    summary = format_summary(report)
    outputs += [os.path.join(out_dir, "summary.txt"),
                os.path.join(out_dir, "report.json")]
    summary += "  output       %s in %s\n" % (
        " ".join(os.path.basename(p) for p in outputs), out_dir)
    with open(os.path.join(out_dir, "summary.txt"), "w") as f:
        f.write(summary)
    data = json_ready(report)
    data["outputs"] = [os.path.basename(p) for p in outputs]
    tmp = os.path.join(out_dir, "report.json.tmp")
    with open(tmp, "w") as f:
        json.dump(data, f, indent=2, sort_keys=True, allow_nan=False)
        f.write("\n")
    os.replace(tmp, os.path.join(out_dir, "report.json"))
    return summary


# ---- command line ----------------------------------------------------------

def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="canopy-report",
        description="Summarise a canopyPimpleFoam run from "
                    "postProcessing/canopy/*/canopy.dat: terminal descent "
                    "velocity, breathing frequency, drag coefficients, "
                    "coupling iterations, the swing and the glide; writes "
                    "descentVelocity.png, projectedDiameter.png, swing.png, "
                    "summary.txt (also printed) and report.json.")
    p.add_argument("case", metavar="caseDir", help="the case directory")
    p.add_argument("--out", metavar="DIR",
                   help="output directory (default "
                        "<caseDir>/postProcessing/report)")
    steady = p.add_mutually_exclusive_group()
    steady.add_argument("--steady-fraction", type=float, metavar="F",
                        help="steady interval = the last fraction F of the "
                             "run (default 1/3)")
    steady.add_argument("--steady-start", type=float, metavar="T",
                        help="steady interval = [T, end]")
    p.add_argument("--steady-end", type=float, metavar="T",
                   help="end the steady interval at T (default: the last "
                        "time), e.g. before a late swing")
    p.add_argument("--diameter", type=float, metavar="D0",
                   help="nominal diameter [m] (else '# nominalDiameter')")
    p.add_argument("--mass", type=float, metavar="M",
                   help="total mass: canopy + lines + payload [kg] "
                        "(else '# totalMass')")
    p.add_argument("--rho", type=float, metavar="RHO",
                   help="air density [kg/m^3] (else '# rho')")
    p.add_argument("--gravity", type=float, nargs=3,
                   metavar=("GX", "GY", "GZ"),
                   help="gravity [m/s^2] (else '# gravity')")
    p.add_argument("--reference", choices=sorted(REFERENCES),
                   help="print published values beside the results")
    p.add_argument("--no-plots", action="store_true",
                   help="write summary.txt and report.json only")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        if not os.path.isdir(args.case):
            raise ReportError("no case directory %s" % args.case)
        report = analyse(args.case, fraction=args.steady_fraction,
                         steady_start=args.steady_start,
                         steady_end=args.steady_end,
                         diameter=args.diameter, mass=args.mass,
                         rho=args.rho, gravity=args.gravity,
                         reference=args.reference)
        out = args.out or os.path.join(args.case, "postProcessing", "report")
        summary = write_outputs(report, out, plots=not args.no_plots)
    except ReportError as e:
        for line in str(e).splitlines():
            sys.stderr.write("canopy-report: error: %s\n" % line)
        return 1
    sys.stdout.write(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
