"""validation_tables.py — the validation report's tables, estimates (GCI, windows, breathing, swing, incidence, forced turns) and figures, computed from the runs' records."""

import math
import os
import subprocess
import textwrap

import numpy as np

from . import forced_turn
from . import report as rep
from . import validation_archive as archive
from . import validation_paths as paths
from .validation_runs import (CROSSWIND_T10, DISC_SPEED,
                              DISC_TUTORIAL_LEVELS, FORCED_HELD,
                              FORCED_TURN, FORCED_TURN_START, MAIN_JOB_RUN,
                              MESH_DICT, PROPS, REMOVE, RUN_BY_ID, TILT_STREAM,
                              TILT_T10_SPEED, narrow, tutorial_entry)
from .validation_studies import STUDIES
from .validation_case import (last_time, run_state)
from .validation_notes import BREATHING_CLOTH_PROSE


def _f(x, fmt="%.3g"):
    return "—" if x is None or (isinstance(x, float) and
                                not math.isfinite(x)) else fmt % x


# Studies whose report gets the canopy's shape over each run's interval
SHAPE_STUDIES = ("default7ft", "retraction7ft", "retraction7ftLES",
                 "resolution7ft", "resolution7ftHeld",
                 "edgeLength7ftLong", "edgeLength7ftTutorial",
                 "edgeLength7ftTutorialTo80", "markers7ftTutorial",
                 "numerics7ftMarkerHalf", "resolution7ftStiff",
                 "resolution7ftSteady", "damping7ft", "hingeDamping7ft",
                 "materialDamping7ft", "tapes7ft",
                 "tolerance7ftLong",
                 "resolution7ftLong", "wrinkling7ft",
                 "turbulence7ftConverged", "damping7ftTutorial",
                 "resolution7ftDamped", "levels7ftDamped",
                 "turbulence7ftDamped", "load7ftSampled")


# Studies whose report gets the breathing in the Strouhal band (issue 34
# item 4: long windows, many periods)
BREATHING_STUDIES = ("domain7ftLong", "damping7ftLong", "resolution7ftHeld",
                     "edgeLength7ftLong", "edgeLength7ftTutorial",
                     "edgeLength7ftTutorialTo80", "markers7ftTutorial",
                     "domain7ftTutorial", "timeStep7ftTutorial",
                     "resolution7ftUntil2Long", "resolution7ftMarkerHalf",
                     "numerics7ftMarkerHalf", "resolutionT10Skirt",
                     "payloadT10SkirtLong",
                     "turbulence7ftConverged", "mainJobLevel7ft",
                     "damping7ftTutorial", "payloadT10Tutorial",
                     "resolution7ftDamped", "levels7ftDamped",
                     "turbulence7ftDamped")


def breathing_band_lines(results):
    """The table of each run's breathing above f Dp / V = 0.1 (report.py's
    breathing_band: the projected diameter's spectrum over the run's
    interval, its largest peak in the band, the Strouhal number f Dp / V)
    and of its descent speed's spectrum in the same band (descentBand) for
    the runs whose records hold them."""
    rows = []
    for run, rec in results:
        b = rec and rec["analysis"] and rec["analysis"].get("breathingBand")
        if not b:
            continue
        a = rec["analysis"]
        v = a.get("descentBand")
        if not v:
            descent = "—"
        elif v["resolved"]:
            descent = "%.3g (St %.3f; %.2g m/s)" % (
                v["frequency"], v["strouhal"], v["amplitude"])
        else:
            descent = "not resolved"
        if b["resolved"]:
            rows.append("| %s | %.3g-%.3g s | %.3g | %.3g | %.3f | %.3g | %.0f "
                        "| %s |"
                        % (run.ident, a["steady"]["start"], a["steady"]["end"],
                           b["fMin"], b["frequency"], b["strouhal"],
                           b["amplitude"], b["periods"], descent))
        else:
            rows.append("| %s | %.3g-%.3g s | %.3g | not resolved: %s | | | "
                        "| %s |"
                        % (run.ident, a["steady"]["start"], a["steady"]["end"],
                           b["fMin"], b["note"], descent))
    if not rows:
        return []
    return ["The breathing: the largest peak of the projected diameter's "
            "spectrum (detrended, Hann window) over each run's interval at "
            "or above a Strouhal number f Dp / V of 0.1 (python/canopyfoam/"
            "report.py, breathing_band: below it lie the descent's slow "
            "swings, periods of ten and more Dp / V), with its Strouhal "
            "number; beside it the descent speed's spectrum in the same "
            "band, its largest peak (the breathing as the payload feels "
            "it; — where the record was made before it was recorded). The "
            "seed's measurements: the 7 ft canopy about 2 Hz "
            "(St ≈ 0.75 at the drop test's 4.27 m/s and about 1.6 m across), "
            "the T-10 a period of 2.3 s (St ≈ 0.51 at 6.7 m/s and 7.8 m).",
            "", "| run | interval | band from [Hz] | frequency [Hz] | "
            "St = f Dp / V | amplitude [m] | periods in the interval | "
            "descent speed's peak [Hz] (St; amplitude) |",
            "|---|---|---|---|---|---|---|---|"] + rows + [""]


# Studies whose report gets the swing and glide table and the
# suspension's angle over time (issue 34 item 5)
SWING_STUDIES = ("freeFlight", "departureT10", "pivotT10", "crossResolution",
                 "freeT10Tutorial", "dashpotsT10Free")

# Published oscillation of each parachute's class: Knacke, Parachute
# Recovery Systems Design Manual, NWC TP 6575 (1991), Table 5-1
# (mediawiki.aerodecelerator.org, "Parachute Performance")
PUBLISHED_OSCILLATION = {
    "parachutes/flatCircular7ft": "flat circular, solid: ±10° to ±40°",
    "parachutes/C9": "flat circular, solid: ±10° to ±40°",
    "parachutes/T10": "extended skirt (10 % flat): ±10° to ±15°",
    "parachutes/G11third": "flat circular, solid: ±10° to ±40°",
    "parachutes/cross": "cross: 0° to ±3°",
}


# Studies of a canopy held in a tilted stream: the force and moment table
# (tilt_lines) and the coefficients against the angle (plot_tilt)
# Studies of a canopy turned by an imposed oscillation: the in-phase and
# rate table (forced_turn_lines) and the moment against the angle
FORCED_STUDIES = ("forcedTurnT10",)

TILT_STUDIES = ("incidenceT10", "incidenceT10Resolution",
                "incidenceT10Free", "incidence7ft")


def tilt_stream(run, a=None):
    """(speed [m/s], angle to the axis [degrees]) of the relative wind on a
    run of a tilt study: the held runs' stream (TILT_STREAM); on the guide
    wire in a wind W (CROSSWIND_T10), the wind less the payload's descent
    V over the interval: sqrt(V^2 + W^2) at atan(W / V) (None before the
    run has an analysis)."""
    if run.ident in TILT_STREAM:
        return TILT_STREAM[run.ident]
    wind = CROSSWIND_T10[run.ident]
    if a is None:
        return None
    v = a["descentVelocity"]["mean"]
    return math.hypot(v, wind), math.degrees(math.atan2(wind, v))


def tilt_coefficients(run, a):
    """A held run's coefficients from its analysis (report.py canopyLoad)
    and its stream (TILT_STREAM): with q = rho V^2 / 2, S0 = pi D0^2 / 4,
    the axis z (payload to canopy: the state's payload and apex were, or
    are, on a vertical guide wire) and the relative wind at alpha towards
    +x (tilt_stream):
    C_T = F_z / (q S0) along the axis, C_N = F_x / (q S0) across it
    towards the stream's side (a force that turns the axis into the
    stream), C_Y = F_y / (q S0) out of that plane, the force's angle off
    the axis atan(C_N / C_T) in the plane, and C_m = -M_y / (q S0 D0) about
    the payload (positive increases alpha: restoring where it is negative
    at a positive alpha). Returns a dict, or None when the record has no
    load."""
    load = a.get("canopyLoad")
    if not load:
        return None
    speed, alpha = tilt_stream(run, a)
    p = a["parameters"]
    d0, rho = p["nominalDiameter"]["value"], p["rho"]["value"]
    qs = 0.5 * rho * speed ** 2 * math.pi * d0 ** 2 / 4.0
    f, ci = load["force"], load["forceCi95"]
    out = {"alpha": alpha, "CT": f[2] / qs, "CN": f[0] / qs,
           "CY": f[1] / qs,
           "CNci": None if ci[0] is None else ci[0] / qs,
           "CYci": None if ci[1] is None else ci[1] / qs,
           "offAxis": math.degrees(math.atan2(f[0], f[2])),
           "Cm": None, "CmStd": None}
    if load.get("moment"):
        out["Cm"] = -load["moment"][1] / (qs * d0)
        out["CmStd"] = load["momentStd"][1] / (qs * d0)
    return out


def trim_angle(points):
    """The trim the held angles (alpha, C_m) show, as text: the smallest
    angle at which C_m, linear between them in order, falls through zero
    (positive to negative: a restoring slope); else, when C_m < 0 at every
    angle held above 0, that it is restoring from the smallest of them (the
    trim lies below it); else that none is found."""
    pts = sorted((al, cm) for al, cm in points if cm is not None)
    for (a0, c0), (a1, c1) in zip(pts, pts[1:]):
        if c0 > 0.0 >= c1:
            return "%.1f°" % (a0 + (a1 - a0) * c0 / (c0 - c1))
    positive = [(al, cm) for al, cm in pts if al > 0.0]
    if positive and all(cm < 0.0 for _, cm in positive):
        return ("C_m < 0 at every angle held above 0°: restoring from "
                "%g°, the trim below it" % positive[0][0])
    return "none between the angles held"


def tilt_lines(records):
    """The held runs' table: per angle the coefficients (tilt_coefficients)
    and the trim angle, beside the class's published oscillation."""
    rows = ["| run | state | α [°] | C_T | C_N (± 95 %) | C_Y (± 95 %) | "
            "force off axis in the plane [°] | C_m about the payload (± "
            "std) | wall time on ranks |",
            "|---|---|---|---|---|---|---|---|---|"]
    points = []
    tutorial = None
    for run, rec, why in records:
        tutorial = run.tutorial
        a = rec and rec["analysis"]
        c = a and tilt_coefficients(run, a)
        if not c:
            stream = tilt_stream(run, a)
            rows.append("| %s | %s | %s |  |  |  |  |  |  |" % (
                run.ident, why if rec is None else rec["state"],
                "—" if stream is None else "%.1f" % stream[1]))
            continue
        if rec["complete"]:
            points.append((c["alpha"], c["Cm"]))
        wall = rec["wall"]
        rows.append("| %s | %s | %.1f | %.3f | %.3f ± %s | %.3f ± %s | %.1f | "
                    "%s | %s |" % (
                        run.ident, rec["state"], c["alpha"], c["CT"],
                        c["CN"], _f(c["CNci"], "%.3f"), c["CY"],
                        _f(c["CYci"], "%.3f"), c["offAxis"],
                        "—" if c["Cm"] is None else "%.4f ± %.4f" % (
                            c["Cm"], c["CmStd"]),
                        "%s on %s" % (_f(wall / 60 if wall else None,
                                         "%.1f min"), rec["ranks"])
                        if wall else "—"))
    trim = trim_angle(points)
    return rows + ["", "Coefficients on S0 = π D0²/4 and q = ρV²/2 of the "
                   "stream (C_m on S0 D0), means over each run's "
                   "interval (C_N, C_Y with the mean's 95 %% interval from "
                   "the series' autocorrelation; C_m's spread over the "
                   "states written in the interval; "
                   "python/canopyfoam/validation_tables.py "
                   "tilt_coefficients). "
                   "C_N > 0 pushes the canopy towards the stream's side, "
                   "turning its axis into the stream; C_m < 0 at α > 0 "
                   "is restoring. Trim (C_m through zero, restoring "
                   "slope, linear between the angles held): %s; "
                   "published oscillation of the class (Knacke, NWC TP "
                   "6575, Table 5-1): %s." % (
                       trim, PUBLISHED_OSCILLATION.get(tutorial, "—")), ""]


def save_figure(fig, ax, name):
    """Grid and legend on ax, fig written to FIG_DIR/name.png and closed;
    its path relative to the report."""
    import matplotlib.pyplot as plt
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    path = os.path.join(paths.FIG_DIR, name + ".png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return os.path.relpath(path, os.path.dirname(paths.DOC))


def plot_tilt(name, title, results):
    """C_N and C_m against the angle for a held study, in FIG_DIR/name.png;
    its path relative to the report, or None without data."""
    pts = []
    for run, rec in results:
        a = rec and rec["analysis"]
        c = a and tilt_coefficients(run, a)
        if c:
            pts.append(c)
    if not pts:
        return None
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(paths.FIG_DIR, exist_ok=True)
    pts.sort(key=lambda c: c["alpha"])
    al = [c["alpha"] for c in pts]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.errorbar(al, [c["CN"] for c in pts],
                yerr=[c["CNci"] or 0.0 for c in pts], marker="o",
                label="C_N (across the axis, towards the stream's side)")
    ax.errorbar(al, [c["CY"] for c in pts],
                yerr=[c["CYci"] or 0.0 for c in pts], marker="s",
                label="C_Y (out of the plane)")
    ax.plot(al, [c["Cm"] if c["Cm"] is not None else float("nan")
                 for c in pts], marker="^",
            label="C_m about the payload (< 0 restoring)")
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("angle of the stream to the canopy's axis α [°]")
    ax.set_ylabel("coefficient")
    ax.set_title(textwrap.fill(title, 90), fontsize=9)
    return save_figure(fig, ax, name)


def turn_fit_lines(results):
    """The pivoting runs' moments about the payload fitted as M = k theta
    + c theta' + i theta'' + m0 over each run's interval (turn_fit.py): the
    air's (the load less the added-mass stabiliser's balance), the
    weights' stiffness and the balance's rate coefficient, which the
    load's moment carried."""
    rows = []
    for run, rec in results:
        a = rec and rec["analysis"]
        f = a and a.get("turnFit")
        if not f or "k" not in f or "balance" not in f:
            continue
        b, g = f["balance"], f["weight"]
        rows.append("| %s | %.3g-%.3g s | %.3g to %.3g | %.0f ± %.0f | "
                    "%.0f ± %.0f | %.0f ± %.0f | %.2f | %.0f ± %.0f | "
                    "%.0f ± %.0f | %.0f ± %.0f |" % (
                        run.ident, a["steady"]["start"], a["steady"]["end"],
                        f["angleMin"], f["angleMax"], f["k"], f["kErr"],
                        f["c"], f["cErr"], f["i"], f["iErr"], f["r2"],
                        g["k"], g["kErr"], b["c"], b["cErr"], b["i"],
                        b["iErr"]))
    if not rows:
        return []
    return ["The moments about the payload fitted as M = k θ + c θ' + i θ'' "
            "+ m0 over the written states of each interval "
            "(python/canopyfoam/turn_fit.py; θ the canopy's angle of turn "
            "in its plane of swing [rad], ± standard errors; k < 0 "
            "restores, c > 0 is a moment along the rate of turn): the "
            "air's (the load on the cloth less the added-mass "
            "stabiliser's balance m_a a, rebuilt from the written "
            "accelerations, load_moment.py), the stiffness of the weights' "
            "(cloth and lines; the payload is the point), and the "
            "balance's rate and inertia coefficients:", "",
            "| run | interval | θ [°] | air: k [N m] | air: c [N m s] | "
            "air: i [kg m²] | air: R² | weights: k [N m] | balance: c "
            "[N m s] | balance: i [kg m²] |",
            "|---|---|---|---|---|---|---|---|---|---|"] + rows + [""]


def forced_turn_lines(records):
    """The forced runs' table: per run the air's moment split into its
    part in phase with the angle and with the rate (forced_turn.py), per
    period mean with its 95 % interval, as coefficients and as work."""
    rows = ["| run | state | A [°] | T [s] | k_r = ωD0/2U | periods | a = "
            "k - i ω² [N m] (± 95 %) | C_ma [1/rad] | c [N m s] (± 95 %) | "
            "C_mq | work on the turn per period [J] | whole-interval R² | "
            "wall time on ranks |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    held = []
    for run, rec, why in records:
        a = rec and rec["analysis"]
        if run.ident == FORCED_HELD:
            held = wake_line(run, rec, why)
            continue
        f = a and a.get("forcedTurn")
        amplitude, period = FORCED_TURN[run.ident]
        if not f or "a" not in f:
            rows.append("| %s | %s | %g | %g |  |  |  |  |  |  |  |  |  |"
                        % (run.ident, why if rec is None else rec["state"],
                           amplitude, period))
            continue
        wall = rec["wall"]
        rows.append("| %s | %s | %g | %g | %.2f | %d | %.0f ± %s | %.3f ± "
                    "%s | %.0f ± %s | %.3f ± %s | %.0f ± %s | %.2f | %s |" % (
                        run.ident, rec["state"], amplitude, period,
                        f["reducedFrequency"], f["periods"], f["aMean"],
                        _f(f["a95"], "%.0f"), f["Cma"],
                        _f(f["Cma95"], "%.3f"), f["cMean"],
                        _f(f["c95"], "%.0f"), f["Cmq"],
                        _f(f["Cmq95"], "%.3f"), f["work"],
                        _f(f["work95"], "%.0f"), f["r2"],
                        "%s on %s" % (_f(wall / 60 if wall else None,
                                         "%.1f min"), rec["ranks"])
                        if wall else "—"))
    return rows + ["", "The air's moment about the payload along the axis "
                   "of turn (the pressure jump's and the tangential load's "
                   "on the held cloth; load_moment.py) fitted as M = a θ + "
                   "c θ' + m0 over each whole period of θ = A sin(2π (t - "
                   "%g s) / T) in the interval (python/canopyfoam/"
                   "forced_turn.py); the periods' mean with its 95 %% "
                   "interval (Student's t on their spread). A linear air, "
                   "M = k θ + c θ' + i θ'', gives a = k - i ω²: the "
                   "static stiffness less the added inertia's part. c > 0 "
                   "is a moment along the rate of turn, a negative "
                   "damping: the air does the work π c ω A² on the turn in "
                   "each period. C_ma = a / (q S0 D0), C_mq = c / (q S0 D0 "
                   "· D0/2U) on the stream's q = ρU²/2 and S0 = π D0²/4."
                   % FORCED_TURN_START, ""] + held


def wake_line(run, rec, why):
    """The held reference run's wake frequencies (forced_turn.wake_peaks),
    as a paragraph."""
    a = rec and rec["analysis"]
    w = a and a.get("wakePeaks")
    if not w or "peaks" not in w:
        return ["Held still (%s, the same set-up without the turn): %s."
                % (run.ident, why if rec is None else
                   (w or {}).get("note", rec["state"])), ""]
    d0 = a["parameters"]["nominalDiameter"]["value"]
    return ["Held still (%s, the same set-up without the turn, over its "
            "interval): the spectrum of the force across the stream "
            "(python/canopyfoam/forced_turn.py wake_peaks) has its largest "
            "peaks at %s (f D0 / U; relative power), resolution %.3f Hz."
            % (run.ident, ", ".join(
                "%.3f Hz (%.2f; %.2g)" % (f, f * d0 / TILT_T10_SPEED, p)
                for f, p in w["peaks"]), w["resolution"]), ""]


def forced_stiffness_inertia(results):
    """k [N m] and i [kg m²] from the 13-cell forced runs of one amplitude
    at two or more periods, a = k - i w^2 fitted by least squares (exact
    for two): {amplitude: (k, i, runs)} for each amplitude with two or
    more."""
    by_amp = {}
    for run, rec in results:
        a = rec and rec["analysis"]
        f = a and a.get("forcedTurn")
        if not f or "aMean" not in f or run.ident.endswith("-cpd20"):
            continue
        amplitude, period = FORCED_TURN[run.ident]
        by_amp.setdefault(amplitude, []).append((period, f["aMean"],
                                                 run.ident))
    out = {}
    for amplitude, pts in sorted(by_amp.items()):
        if len(pts) < 2:
            continue
        w2 = np.array([(2 * math.pi / t) ** 2 for t, _, _ in pts])
        coef, _, _, _ = np.linalg.lstsq(
            np.column_stack([np.ones(len(w2)), -w2]),
            np.array([v for _, v, _ in pts]), rcond=None)
        out[amplitude] = (float(coef[0]), float(coef[1]),
                          sorted(r for _, _, r in pts))
    return out


def wake_comparison(results, band, d0):
    """The sentence comparing the band of negative damping (band [Hz]) of
    a canopy of nominal diameter d0 [m] with the held run's wake
    frequencies (its three largest peaks), or a full stop without them."""
    for run, rec in results:
        a = rec and rec["analysis"]
        w = a and run.ident == FORCED_HELD and a.get("wakePeaks")
        if w and w.get("peaks"):
            peaks = w["peaks"][:3]
            res = w["resolution"]
            listed = ", ".join("%.3f Hz (f D0 / U = %.2f, power %.2f)"
                               % (f, f * d0 / TILT_T10_SPEED, p)
                               for f, p in peaks)
            inside = [f for f, _ in peaks if band[0] <= f <= band[1]]
            near = [(k, f) for k, (f, _) in enumerate(peaks)
                    if band[0] - res <= f <= band[1] + res]
            if inside:
                verdict = ("the band lies at the wake's peak at %.3f Hz: a "
                           "turn at the wake's own frequency may lock its "
                           "shedding to the motion and be fed by it, as a "
                           "bluff body's wake does; the runs do not show "
                           "the lock" % inside[0])
            elif near:
                verdict = ("the band lies within one resolution of the "
                           "peak at %.3f Hz (the %s largest), not at the "
                           "largest: a lock of the turn to that mode of the "
                           "wake is possible, not shown, and the band's "
                           "cause stays open" % (
                               near[0][1], ("", "second ", "third ")[
                                   near[0][0]].strip() or "first"))
            else:
                verdict = ("the band lies beside them, so the held wake's "
                           "own frequencies do not explain it, and its "
                           "cause stays open")
            return ("; the canopy held still (%s) has the largest peaks of "
                    "its side force's spectrum at %s, resolution %.3f Hz: "
                    "%s." % (run.ident, listed, res, verdict))
    return "."


def forced_turn_notes(results):
    """The forced study's discussion, with the numbers its records hold."""
    f = {}
    for run, rec in results:
        a = rec and rec["analysis"]
        if a and a.get("forcedTurn") and "aMean" in a["forcedTurn"]:
            f[run.ident] = a["forcedTurn"]
    if "T10-turn10-T10" not in f:
        return []
    p = dict(results)[RUN_BY_ID["T10-turn10-T10"]]["analysis"]["parameters"]
    d0, rho = p["nominalDiameter"]["value"], p["rho"]["value"]
    u = TILT_T10_SPEED
    qsd = 0.5 * rho * u ** 2 * math.pi * d0 ** 2 / 4 * d0

    def cmq(ident):
        g = f.get(ident)
        return ("C_mq %+.2f ± %.2f" % (g["Cmq"], g["Cmq95"])) if g else "—"

    md = ["The inflated T-10 of T10-skirt-cpd13-m163 (its state at 80 s) "
          "held rigid in a 6.66 m/s stream along its axis, the payload "
          "held, the cloth turned about the payload by θ = A sin(2π (t - "
          "10 s)/T) about a horizontal axis (fixedNodes.motion, "
          "src/canopyFoam/structure/prescribedRotation): a forced "
          "oscillation in pitch, as wind tunnels measure dynamic "
          "stability, which gives the air's moment with the canopy's "
          "motion imposed instead of balanced against its weight (study "
          "pivotT10). At the period of the free pivoting canopy's swing "
          "(T = 10 s, reduced frequency ωD0/2U = 0.50) the part of the "
          "moment in phase with the rate of turn is positive at both "
          "amplitudes, %s at 10° and %s at 20°: the air feeds the turn, "
          "a negative damping%s. At twice the frequency (T = 5 s, ωD0/2U "
          "= 1.0) it is %s, a positive damping." % (
              cmq("T10-turn10-T10"), cmq("T10-turn20-T10"),
              (", %.0f ± %.0f J per period at 20°" % (
                  f["T10-turn20-T10"]["work"],
                  f["T10-turn20-T10"]["work95"] or 0.0))
              if "T10-turn20-T10" in f else "", cmq("T10-turn10-T5"))]
    sweep = sorted((FORCED_TURN[r][1], r) for r in f
                   if FORCED_TURN[r][0] == 20.0 and not r.endswith("-cpd20"))
    if len(sweep) > 2:
        # each reduced frequency by what its 95 % interval says
        feeds = [f[r]["reducedFrequency"] for _, r in sweep
                 if f[r]["Cmq"] - f[r]["Cmq95"] > 0]
        damps = [f[r]["reducedFrequency"] for _, r in sweep
                 if f[r]["Cmq"] + f[r]["Cmq95"] < 0]
        nil = [f[r]["reducedFrequency"] for _, r in sweep
               if abs(f[r]["Cmq"]) <= f[r]["Cmq95"]]
        md[-1] += (" At 20° over the periods %s s (ωD0/2U %s): %s." % (
            ", ".join("%g" % t for t, _ in sweep),
            ", ".join("%.2f" % f[r]["reducedFrequency"] for _, r in sweep),
            ", ".join(cmq(r) for _, r in sweep)))
        if feeds:
            band = (min(feeds) * u / (math.pi * d0),
                    max(feeds) * u / (math.pi * d0))
            md[-1] += (" The air feeds the turn at ωD0/2U %s (%.3f-%.3f "
                       "Hz, f D0 / U = %.2f-%.2f), is nil within its "
                       "interval at %s and damps at %s: not the monotone "
                       "lag of a quasi-steady air with a delay but a "
                       "resonance%s" % (
                           ", ".join("%.2f" % v for v in sorted(feeds)),
                           band[0], band[1], band[0] * d0 / u,
                           band[1] * d0 / u,
                           ", ".join("%.2f" % v for v in sorted(nil))
                           or "none",
                           ", ".join("%.2f" % v for v in sorted(damps))
                           or "none",
                           wake_comparison(results, band, d0)))
    fits = forced_stiffness_inertia(results)
    other = [("%g°: k = %.0f N m, -i = %.0f kg m² (%s)"
              % (amp, kk, -ii, ", ".join(rr)))
             for amp, (kk, ii, rr) in sorted(fits.items())]
    if fits:
        amplitude = max(fits, key=lambda amp: (len(fits[amp][2]), amp))
        k, i, runs = fits[amplitude]
        periods = sorted(FORCED_TURN[r][1] for r in runs)
        md[-1] += (" The parts in phase with the angle at %g° and the "
                   "periods %s s (%s), a = k - i ω² fitted over them, give "
                   "the static stiffness k = %.0f N m per radian (C_mα = "
                   "%.2f per radian; the held study's slopes from 0° to "
                   "10°, 20° and 30° are -0.34, -0.20 and -0.29, "
                   "incidenceT10) and the added inertia -i = %.0f kg m² "
                   "about the payload, %.0f kg of air at the 8.6 m from "
                   "the payload to the cloth's centroid (a flat disc of the "
                   "projected 8.2 m diameter carries (8/3) ρ R³ = 220 kg; a "
                   "cupped canopy more), if k and i do not depend on the "
                   "frequency (by amplitude: %s)."
                   % (amplitude, ", ".join("%g" % t for t in periods),
                      ", ".join(runs), k, k / qsd, -i, -i / 8.6 ** 2,
                      "; ".join(other)))
        md[-1] += (" A quasi-steady air, whose restoring moment follows "
                   "the incidence the canopy's sideways speed L θ' adds (L "
                   "about 8.6 m from the payload), would damp: c = k L / "
                   "U, C_mq %.2f with this k." % (
                       k * 8.6 / u / (qsd * d0 / (2 * u))))
        md[-1] += (" The model's moment lags the motion instead, at "
                   "10 s: a restoring moment delayed by τ adds -k τ to c, "
                   "positive once τ exceeds L / U = 1.3 s, about the time "
                   "D0 / U = 1.6 s the air takes to pass the canopy. With "
                   "that stiffness and inertia the undamped "
                   "pivoting canopy would swing with a period of %.0f s; "
                   "the free one (pivotT10) swings with about 10-12 s, "
                   "where the air damps negatively: the forced runs "
                   "account for the free canopy's departure." % (
                       2 * math.pi / math.sqrt(-k / -i)
                       if k < 0 and i < 0 else float("nan")))
    md[-1] += (" Published pitch damping for extended-skirt canopies was "
               "not found in the sources the project can reach, so this is "
               "the model's finding, not a comparison.")
    if "T10-turn20-T10-cpd20" in f:
        g = f["T10-turn20-T10-cpd20"]
        md[-1] += (" At 20 cells across D0 (T10-turn20-T10-cpd20, from "
                   "T10-skirt-cpd20's state) the 20° oscillation at T = "
                   "10 s gives %s and C_ma (in phase with the angle) "
                   "%.2f ± %.2f against %s and %.2f ± %.2f at 13 cells: "
                   "the negative damping holds at 20 cells, its size is "
                   "not converged (two levels; a GCI needs a third)." % (
                       cmq("T10-turn20-T10-cpd20"), g["Cma"], g["Cma95"],
                       cmq("T10-turn20-T10"), f["T10-turn20-T10"]["Cma"],
                       f["T10-turn20-T10"]["Cma95"])
                   if "T10-turn20-T10" in f else "")
    return md + [""]


def plot_forced_turn(name, title, results):
    """Left: the air's moment coefficient against the angle of turn for
    the runs at the free swing's period and at 5 s (the states in the
    interval and the fitted ellipse); right: C_mq against the reduced
    frequency for every forced run; in FIG_DIR/name.png, its path
    relative to the report, or None."""
    curves = []
    for run, rec in results:
        a = rec and rec["analysis"]
        f = a and a.get("forcedTurn")
        if f and "a" in f:
            curves.append((run, a, f))
    if not curves:
        return None
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(paths.FIG_DIR, exist_ok=True)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    for run, a, f in curves:
        amplitude, period = FORCED_TURN[run.ident]
        if period not in (5.0, 10.0) or amplitude != 20.0:
            continue
        p = a["parameters"]
        d0, rho = p["nominalDiameter"]["value"], p["rho"]["value"]
        qsd = 0.5 * rho * TILT_T10_SPEED ** 2 * math.pi * d0 ** 2 / 4 * d0
        th, rate = forced_turn.angle(f["times"], amplitude, period,
                                     FORCED_TURN_START)
        line, = ax.plot(np.degrees(th), np.array(f["moment"]) / qsd, ".",
                        ms=3, alpha=0.5,
                        label="%s (A %g°, T %g s)" % (run.ident, amplitude,
                                                     period))
        phase = np.linspace(0, 2 * math.pi, 200)
        ar = math.radians(amplitude)
        w = 2 * math.pi / period
        fit_m = (f["aMean"] * ar * np.sin(phase)
                 + f["cMean"] * ar * w * np.cos(phase) + f["m0"]) / qsd
        ax.plot(np.degrees(ar * np.sin(phase)), fit_m, "-",
                color=line.get_color(), lw=1.5)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("angle of turn θ [°]")
    ax.set_ylabel("C_m about the payload, along the turn")
    ax.set_title(textwrap.fill("The air's moment against the angle (dots: "
                               "the states written; lines: the fit; a "
                               "loop run clockwise gives the turn energy)",
                               60), fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=7)
    for label, keep, marker in (
            ("20°, 13 cells", lambda r, amp: amp == 20.0
             and not r.endswith("-cpd20"), "o"),
            ("10°, 13 cells", lambda r, amp: amp == 10.0, "s"),
            ("20°, 20 cells", lambda r, amp: r.endswith("-cpd20"), "^")):
        pts = sorted((f["reducedFrequency"], f["Cmq"], f["Cmq95"] or 0.0)
                     for run, a, f in curves
                     if keep(run.ident, FORCED_TURN[run.ident][0]))
        if pts:
            bx.errorbar([p[0] for p in pts], [p[1] for p in pts],
                        yerr=[p[2] for p in pts], marker=marker,
                        capsize=3, label=label)
    bx.axhline(0.0, color="k", lw=0.8)
    bx.set_xlabel("reduced frequency ω D0 / 2U")
    bx.set_ylabel("C_mq (> 0: the air feeds the turn)")
    bx.set_title("The rate coefficient against the frequency (± 95 %)",
                 fontsize=9)
    return save_figure(fig, bx, name)


def swing_lines(results):
    """The table of each run's swing and glide (report.py's swing: the
    suspension's angle over the interval, its period when resolved, the
    payload's mean velocity across gravity) beside its class's published
    oscillation, for the runs whose records hold them."""
    rows = []
    for run, rec in results:
        a = rec and rec["analysis"]
        sw = a and a.get("swing")
        if not sw or "glide" not in sw:
            continue
        v = a["descentVelocity"]
        gr = sw.get("growth")
        D0 = a["parameters"]["nominalDiameter"]["value"]
        # the departure's rate in the canopy's own time D0 / V, with V the
        # descent where the fit's window starts
        growth = "—" if not gr else "%.2f (%.2f s; %.2f) over %.3g-%.3g s" % (
            gr["rate"], gr["doublingTime"] or float("inf"),
            gr["rate"] * D0 / gr["descent"] if gr.get("descent") else
            float("nan"), gr["start"], gr["end"])
        inc = ("%.0f / %.0f° (%.1f°)" % (sw["incidenceMean"],
                                          sw["incidenceMax"],
                                          sw["forceOffAxisMean"])
               if "incidenceMean" in sw else "—")
        rows.append("| %s | %s | %.3g-%.3g s | %.2f ± %.2f | %.3g | %s | "
                    "%.1f / %.1f / %.1f | %s | %.2f (%.1f°) | %s | %s | %s |"
                    % (
                        run.ident, rec["state"], a["steady"]["start"],
                        a["steady"]["end"],
                        v["mean"], v["ci95"] if v.get("ci95") else v["std"],
                        a["dragCoefficient"]["weightBalance"], growth,
                        sw["angleMax"], sw["angleMean"], sw["angleRms"],
                        "%.3g s" % sw["period"] if sw["period"] else "—",
                        sw["glide"]["speed"], sw["glide"]["angle"],
                        "%.4g s" % sw["onset"] if sw["onset"] is not None
                        else "never", inc,
                        PUBLISHED_OSCILLATION.get(run.tutorial, "—")))
    if not rows:
        return []
    return ["The swing and the glide over each run's interval "
            "(python/canopyfoam/report.py: the suspension's angle is that "
            "of the canopy's centre seen from the payload, to the "
            "vertical; the period is the spectral peak of that offset "
            "across gravity; the glide is the payload's mean velocity "
            "across gravity over the interval, which a swing about the "
            "vertical averages out, and its angle atan(glide / descent); "
            "'beyond 5°' is the first time the angle passes 5°; the "
            "departure is the growth rate σ of the payload's speed across "
            "gravity, fitted as exp(σ t) from 1 % to 20 % of the descent, "
            "with its doubling time and σ D0 / V; the incidence is the "
            "angle between the canopy's axis, payload to canopy, and the "
            "relative wind in still air, mean / largest, with the mean "
            "angle of the canopy's force off that axis). The descent's ± "
            "is the 95 % interval of its mean from the series' integral time "
            "(the std where the interval is too short); a failed run is "
            "read over its interval up to where it stopped.", "",
            "| run | state | interval | descent [m/s] | C_D0 | departure σ "
            "[1/s] (doubling; σ D0/V) | angle max / mean / rms [°] | "
            "period | glide [m/s] (angle) | beyond 5° from | incidence "
            "(force off axis) | published oscillation (Knacke, Table 5-1) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|"] + rows + [
                ""]


def plot_swing(name, title, runs_results):
    """The suspension's angle to the vertical over time of the runs whose
    records hold it; the figure's path relative to the report, or None."""
    return plot_series(name + "-swing", title, runs_results, "swingSeries",
                       "suspension's angle to the vertical [°]",
                       label=lambda run: run.ident, title_size=9)


def _available(results, key):
    """(run, analysis, analysis[key]) for each run whose record holds the
    entry key as available (the entries read from canopy.h5)."""
    for run, rec in results:
        r = rec and rec["analysis"]
        entry = r and r.get(key)
        if entry and entry.get("available"):
            yield run, r, entry


def shape_lines(results):
    """The table of the canopy's shape (report.analyse's "shape", from
    canopy.h5) of the runs whose records hold it."""
    rows = []
    for run, r, form in _available(results, "shape"):
        D0 = r["parameters"]["nominalDiameter"]["value"]
        rings = form["rings"]
        sil = form.get("silhouetteDiameter")
        rows.append("| %s | %s-%s s (%d states) | %.3f | %.3f (%.3f-%.3f) | "
                    "%.3f | %s | %s | %s |" % (
                        run.ident, _f(form["timeFirst"], "%.4g"),
                        _f(form["timeLast"], "%.4g"), form["states"],
                        form["crownHeight"] / D0,
                        form["skirtRadiusMean"] / D0,
                        form["skirtRadiusMin"] / D0,
                        form["skirtRadiusMax"] / D0,
                        form["largestRadius"] / D0,
                        _f(sil / D0 if sil is not None else None, "%.3f"),
                        " / ".join("%.0f" % q["foldMean"] for q in rings),
                        " / ".join("%.0f" % (100 * q["foldedFraction"])
                                   for q in rings)))
    if not rows:
        return []
    ring_names = " / ".join("%g-%g" % (q["inner"], q["outer"]) for q in
                            rings)
    return ["The canopy's shape over each run's interval (`bin/canopy-"
            "report`, python/canopyfoam/shape.py; the states canopy.h5 "
            "holds, at the run's field writes; the states column counts "
            "them): the crown's height above the skirt, "
            "the skirt's and the largest radius about the payload-canopy "
            "axis, and the silhouette's diameter (the circle of the area "
            "the cloth covers seen along the axis), in D0; the fold angle between neighbouring cloth "
            "triangles and the share of edges folded beyond 90 degrees "
            "by ring of the cloth (s = %s, 0 at the crown, 1 at the "
            "skirt, along the cloth at rest). Runs made before the shape "
            "was recorded, or whose canopy.h5 is not on this machine, "
            "are not listed." % ring_names, "",
            "| run | states | crown height / D0 | skirt radius / D0 (min-"
            "max) | largest radius / D0 | silhouette diameter / D0 | "
            "fold angle by ring [deg] | folded beyond 90 deg [%] |",
            "|---|---|---|---|---|---|---|---|"] + rows + [""]


def step_change_lines(results):
    """The table of the cloth's and the lines' velocity change from one
    time step to the next (report.analyse's "stepChanges") of the runs
    whose records hold it (runs that wrote their structure every step)."""
    rows = []
    for run, _, ch in _available(results, "stepChanges"):
        rows.append("| %s | %s-%s s (%d states, %s s apart) | %s | %s | %s "
                    "| %s | %s | %s |" % (
                        run.ident, _f(ch["timeFirst"], "%.4g"),
                        _f(ch["timeLast"], "%.4g"), ch["states"],
                        _f(ch["meanStep"], "%.2g"), _f(ch["clothRms"],
                                                       "%.3f"),
                        _f(ch["clothNormalRms"], "%.3f"),
                        _f(ch["clothInPlaneRms"], "%.3f"),
                        _f(ch["clothCorrelation"], "%+.2f"),
                        _f(ch.get("linesRms"), "%.3f"),
                        _f(ch.get("linesCorrelation"), "%+.2f")))
    if not rows:
        return []
    return ["The velocity's change from one time step to the next over "
            "each run's interval, for the runs that wrote their structure "
            "every step (python/canopyfoam/step_changes.py): the root mean "
            "square of |dv| over the cloth's triangles (the mean of their "
            "nodes' velocities) and the steps, split along the triangle's "
            "normal and in its plane, and over the lines' interior nodes; "
            "the correlation of consecutive changes (+1: a motion smooth "
            "over the steps, each change foretelling the next; 0 and below: "
            "a vibration the steps alias). The strong coupling's first "
            "iteration imposes the step's start, so its residual is the "
            "cloth's change over the step relative to Uref.", "",
            "| run | states | cloth rms dv [m/s] | along the normal | in the "
            "plane | correlation | lines rms dv [m/s] | lines correlation |",
            "|---|---|---|---|---|---|---|---|"] + rows + [""]


def run_row(run, rec, why):
    """The table row of a run from its record (or why there is none)."""
    if rec is None:
        return "| %s | %s | — | %s |  |  |  |  |  |" % (run.ident, run.label,
                                                     why)
    wall, ranks, cells = rec["wall"], rec["ranks"], rec["cells"]
    r, state = rec["analysis"], rec["state"]
    if r is None:
        return "| %s | %s | %s | %s |  |  |  |  |  |" % (
            run.ident, run.label, _f(cells, "%d"), state)
    v = r["descentVelocity"]
    b = r["breathing"]
    cd = r["dragCoefficient"]
    note = r["steady"]["warning"]
    freq = "%s (period %s, amplitude %s)" % (
        _f(b.get("frequency"), "%.2f Hz"), _f(1 / b["frequency"], "%.2g s"),
        _f(b.get("amplitude"), "%.2g m")) \
        if b.get("resolved") and b.get("frequency") else "not resolved"
    s = r["steady"]
    h = r.get("horizontalVelocity")
    ci = v.get("ci95")
    return ("| %s | %s | %s | %s to %.2f s | %.2f ± %.2f%s%s (%s–%s s%s) | %s "
            "| %.2f | %s | %s |" % (
                run.ident, run.label, _f(cells, "%d"),
                "" if state == "complete" else state + ",",
                r["timeEnd"], v["mean"], v["std"],
                "" if ci is None else ", mean ± %.2f (95 %%)" % ci,
                " (drifting)" if note else "", _f(s["start"], "%.3g"),
                _f(s["end"], "%.3g"),
                ("; horizontal ≤ %.2f" % h["max"] if h else "")
                + ("; suspension ≤ %.0f°" % r["swing"]["angleMax"]
                   if r.get("swing") else ""), freq,
                r["projectedDiameter"]["mean"],
                _f(cd.get("weightBalance")), "%s / %s" % (
                    _f(r["coupling"]["meanIterationsSteady"], "%.1f"),
                    "%s on %s" % (_f(wall / 60 if wall else None, "%.1f min"),
                                  ranks) if wall else "—")))


TABLE_HEAD = ("| run | setting | cells | simulated | terminal velocity "
              "[m/s] (mean ± std; steady interval; the payload's largest "
              "horizontal speed in it) | breathing | mean "
              "projected D [m] | C_D (weight) | coupling it./step; wall "
              "time on ranks |\n|---|---|---|---|---|---|---|---|---|")


def run_setting(run, dictionary, entry):
    """A numeric entry of a run's case: its last edit of `entry` (a
    foamDictionary path) in `dictionary`, else the tutorial's own value
    (tutorial_entry); None if neither is a number or if the last edit
    removes the entry."""
    edited = [e[2] for e in run.edits if e[0] == dictionary and e[1] == entry]
    if edited:
        return None if edited[-1] == REMOVE else float(edited[-1])
    own = tutorial_entry(run.tutorial, dictionary, entry)
    try:
        return float(own)
    except (TypeError, ValueError):
        return None


def cells_per_diameter(run):
    """Cells across D0 in the finest level of a run on a tutorial meshed
    from system/canopyMeshDict: its -cellsPerDiameter option, else its
    last edit of the dictionary's entry, else the tutorial's dictionary;
    None for a narrow-box run."""
    if narrow(run):
        return None
    if "-cellsPerDiameter" in run.options:
        return float(run.options[run.options.index("-cellsPerDiameter") + 1])
    return run_setting(run, MESH_DICT, "cellsPerDiameter")


def flat_circular_handbook(total_mass, rho=1.2, g=9.81, d0=2.134):
    """The descent speeds that flat circular canopies' handbook drag
    coefficients give this parachute, (C_D0, V) for C_D0 0.75 and 0.80."""
    s0 = math.pi * d0 ** 2 / 4
    return [(c, math.sqrt(2 * total_mass * g / (rho * s0 * c)))
            for c in (0.75, 0.80)]


HANDBOOK_FLAT_CIRCULAR = (
    "Published values for solid flat circular canopies: C_D0 = 0.75–0.80 "
    "on the nominal area with an inflated (projected) diameter Dp/D0 = "
    "0.67–0.70 and oscillation of ±10° to ±40° (Knacke, *Parachute "
    "Recovery Systems Design Manual*, NWC TP 6575, 1991, Table 5-1, "
    "mediawiki.aerodecelerator.org \"Parachute Performance\" §5.1); "
    "C_D ≈ 0.75 for a canopy without slots (J. Potvin, Parks College "
    "Parachute Research Group, \"Calculating the descent rate of a round "
    "parachute\", pcprg.com); ~0.85 for flat circular models above "
    "6 m/s in a wind tunnel, rising with the lines' length (Vu Dinh Quy et "
    "al., JST Smart Systems and Devices 31(2), 2021, 067-074). For this "
    "parachute's %.2f kg these give %s. The drop test's 4.27 m/s would "
    "need C_D0 ≈ 1.35 (and the seed's own simulation, at ~35 times air's "
    "viscosity, 5 kg/m² cloth and a 1.9 D0 periodic box, 3.9 m/s: 1.62), "
    "beyond any flat circular canopy in these sources.")

# The T-10's published figures, and the C_D0 they imply at the rated 163 kg
# (C_D0 = 2 m g / (rho V^2 S0), rho = 1.2 kg/m^3, S0 = pi 10.7^2 / 4)
HANDBOOK_T10 = (
    "Published T-10 figures: nominal diameter 35 ft (10.7 m), 30 lines of "
    "25.5 ft (7.8 m), inflated diameter 25.7 ft (7.8 m, Dp/D0 = 0.73), "
    "average descent 22 ft/s (6.7 m/s) with at most 360 lb (163 kg) "
    "suspended (Mills Manufacturing, T-10 series characteristics, "
    "millsmanufacturing.com); 19–23 ft/s depending on the jumper's weight "
    "and the air's density (globalsecurity.org, \"T-10 Parachute\"); 22–24 "
    "ft/s (en.wikipedia.org, \"T-10 parachute\"). None gives the weight or "
    "altitude at which the rates were measured. At 163 kg and sea-level "
    "density, 6.7 m/s means C_D0 = %.2f and 7.3 m/s %.2f; a lighter jumper "
    "at the same rates, or thinner air, means less.")


def t10_handbook_cd0(mass=163.0, rho=1.2, g=9.81, d0=10.7):
    """C_D0 at 6.7 and 7.3 m/s for the T-10 at mass (HANDBOOK_T10)."""
    s0 = math.pi * d0 ** 2 / 4
    return tuple(2 * mass * g / (rho * v * v * s0) for v in (6.7, 7.3))


def fabric_edge_cells(run):
    """The fabric's edge in finest cells of a run (its edgeLengthPerCell
    edit, else its tutorial's canopyMeshDict entry)."""
    return run_setting(run, MESH_DICT, "edgeLengthPerCell")


# The breathing peaks of three levels are one mode, and so have a GCI,
# when they lie within this factor of each other; a larger spread is
# different motions (e.g. the canopy's breathing on one level, a
# cell-scale vibration of the cloth on another) whose "order" means
# nothing, and the table lists them without a GCI.
BREATHING_SAME_MODE = 2.0


def resolution_estimates(results, fineness=None):
    """Roache's GCI of descent speed, C_D0, C_Dp, Dp/D0 (and the breathing
    frequency, where every level resolves it) from the three finest
    complete runs of a resolution study (gci.py). fineness(run) is the
    resolution, larger finer (default cells across D0; the GCI takes the
    sizes 1/fineness). Returns (runs, table): runs [(fineness, run)]
    finest first, table {quantity: (values finest first, gci.gci's
    dict, or None for breathing peaks too far apart to be one mode,
    BREATHING_SAME_MODE)}; runs has fewer than three entries and table is
    empty when the study is not complete enough."""
    from . import gci as gci_mod
    fineness = fineness or cells_per_diameter
    done = []
    for run, rec in results:
        n = fineness(run)
        if (n is None or rec is None or not rec["complete"]
                or rec["analysis"] is None):
            continue
        done.append((n, run, rec["analysis"]))
    done.sort(key=lambda x: -x[0])
    if len(done) < 3:
        return [(n, r) for n, r, _ in done], {}
    done = done[:3]
    d0 = done[0][2]["parameters"]["nominalDiameter"]["value"]
    h = [1.0 / n for n, _, _ in done]

    def quantities(a):
        cd0 = a["dragCoefficient"].get("weightBalance")
        dp = a["projectedDiameter"]["mean"]
        return {"descent speed [m/s]": a["descentVelocity"]["mean"],
                "C_D0 (weight)": cd0,
                "C_Dp = C_D0 (D0/Dp)^2": cd0 * (d0 / dp) ** 2,
                "Dp/D0": dp / d0}
    values = [quantities(a) for _, _, a in done]
    breathing = None
    if all(a["breathing"].get("resolved") for _, _, a in done):
        breathing = [a["breathing"]["frequency"] for _, _, a in done]
        if max(breathing) <= BREATHING_SAME_MODE * min(breathing):
            for v, b in zip(values, breathing):
                v["breathing frequency [Hz]"] = b
    table = {}
    for key in values[0]:
        f = [v[key] for v in values]
        # formal order 1: the IB's regularised delta function is first
        # order at the interface (Lai & Peskin 2000, J. Comput. Phys. 160)
        table[key] = (f, gci_mod.gci(h, f, p_formal=1.0, p_max=3.0))
    if breathing is not None and "breathing frequency [Hz]" not in values[0]:
        table["breathing frequency [Hz]"] = (breathing, None)
    return [(n, r) for n, r, _ in done], table


# Studies of a body held still in a stream: a table of the force on it
# (disc_table) instead of the parachute's
FORCE_STUDIES = ("disc7ft", "discLES7ft", "discTutorial7ft", "discEdge7ft",
                 "discRetracted7ft", "discWake7ft")


def disc_reference_force(a):
    """rho U^2 S0 / 2 [N] of a disc run's analysis (U the stream's speed,
    S0 the disc's area)."""
    p = a["parameters"]
    d0, rho = p["nominalDiameter"]["value"], p["rho"]["value"]
    return 0.5 * rho * DISC_SPEED ** 2 * math.pi * d0 ** 2 / 4.0


def disc_coefficient(a):
    """(mean force against the stream [N], its std, drift, C_D, std of
    C_D) of a disc run's analysis: C_D = F / (rho U^2 S0 / 2)."""
    q_s0 = disc_reference_force(a)
    f = a["pressureForceAgainstGravity"]
    return f["mean"], f["std"], f["drift"], f["mean"] / q_s0, f["std"] / q_s0


def disc_table(records):
    """The disc runs' table: the force on the disc and its C_D per run."""
    rows = ["| run | setting | cells | simulated | force against the "
            "stream [N] (mean ± std; drift over the interval) | C_D (± std) "
            "| wall time on ranks |", "|---|---|---|---|---|---|---|"]
    for run, rec, why in records:
        if rec is None or rec["analysis"] is None:
            rows.append("| %s | %s | %s | %s |  |  |  |" % (
                run.ident, run.label,
                "—" if rec is None else _f(rec["cells"], "%d"),
                why if rec is None else rec["state"]))
            continue
        a, wall = rec["analysis"], rec["wall"]
        force, std, drift, cd, cd_std = disc_coefficient(a)
        rows.append("| %s | %s | %s | %s to %.2f s | %.2f ± %.2f (%+.2f) | "
                    "%.3f ± %.3f | %s |" % (
                        run.ident, run.label, _f(rec["cells"], "%d"),
                        "" if rec["state"] == "complete" else
                        rec["state"] + ",", a["timeEnd"], force, std, drift,
                        cd, cd_std, "%s on %s" % (
                            _f(wall / 60 if wall else None, "%.1f min"),
                            rec["ranks"]) if wall else "—"))
    return rows


def disc_gci_lines(results, levels=None):
    """The GCI of the disc's C_D over its three levels (the runs whose ids
    are in levels, default all), as markdown."""
    from . import gci as gci_mod
    done = []
    for run, rec in results:
        a = rec and rec["analysis"]
        if a and rec["complete"] and (levels is None
                                      or run.ident in levels):
            done.append((cells_per_diameter(run), disc_coefficient(a)[3]))
    if len(done) != 3:
        return ["Grid convergence of C_D: needs three complete levels, "
                "has %d." % len(done), ""]
    done.sort(key=lambda x: -x[0])
    out = gci_mod.gci([1.0 / n for n, _ in done], [c for _, c in done],
                      p_formal=1.0, p_max=3.0)
    return ["Grid convergence of C_D (%s at %s cells across D0): %s, "
            "observed order %s, extrapolated %.3f, GCI of the finest "
            "%.1f %%." % (
                " / ".join("%.3f" % c for _, c in done),
                " / ".join("%g" % n for n, _ in done), out["kind"],
                "—" if out["order"] is None else "%.2f" % out["order"],
                out["extrapolated"], 100 * out["gci"]), ""]


def disc_lines(results):
    """What the disc's table means, and the GCI of C_D over three
    levels."""
    lines = ["C_D = F / (rho U^2 S0 / 2) with F the mean force of the "
             "immersed boundary on the disc against the stream over 4-12 s "
             "(canopy.dat's force, the pressure jump's resultant), U = %g "
             "m/s and S0 = pi D0^2 / 4. Published for a flat circular disc "
             "normal to the stream above Re ~ 1e4: 1.1 (Cengel & Cimbala, "
             "*Fluid Mechanics*, Table 11-2), 1.12 at Re = 1e6 (Engineers "
             "Edge, circular flat disk drag coefficient), 1.17 (Hoerner, "
             "*Fluid-Dynamic Drag*, 1965, as usually quoted; the Aeronautical "
             "Engineer's Data Book, Fig. 5.13(b), gives 1.17 for a square "
             "plate and 1.42 for a hollow hemisphere opening into the "
             "stream, the shape a canopy approaches). The wake is laminar "
             "and starts symmetric here (no turbulence model); a real "
             "disc's wake at Re 7e5 is turbulent. In these runs the "
             "sideways force stays below 0.03 N (12 cells) and 0.1 N (18) "
             "over 4-12 s, an axisymmetric wake; on 27 cells it reaches 1.3 "
             "N, 2 %% of the drag, from about 8 s, as the wake's symmetry "
             "breaks. The drag is not converged in the mesh and the finest "
             "level gives the most: the laminar vortex ring behind the "
             "disc, less damped by the mesh as it is refined, may hold a "
             "lower base pressure than a turbulent wake does; with the "
             "LES option the drag rises instead (study discLES7ft). For comparison, the 7 ft "
             "canopy's drag on its silhouette's area, C_D0 (D0/D_sil)^2, "
             "is 1.16-1.27 over 5-12 s (7ft-relax1, 7ft-cpd18-compression0) "
             "and 1.37-1.53 over 10-40 s on 12 cells (7ft-tol1e-3-relax1-40s, "
             "7ft-compression0-40s); the handbook's C_D0 and Dp/D0 for "
             "flat circular canopies imply 1.5-1.8." % DISC_SPEED, ""]
    return lines + disc_gci_lines(results)


def _per(value, scale):
    """value / scale, None where value is None (a record's nan)."""
    return None if value is None else value / scale


def disc_ring_lines(results):
    """The pressure jump on the disc by ring (the records'
    pressureJumpRings), in dynamic pressures of the stream, one column a
    run and a row a ring that holds some run's triangles, as markdown; []
    when no record holds it."""
    cols = []
    for run, rec in results:
        a = rec and rec["analysis"] or {}
        rings = a.get("pressureJumpRings")
        if rings and "dp" in rings:
            q = 0.5 * a["parameters"]["rho"]["value"] * DISC_SPEED ** 2
            cols.append((run, dict(rings, q=q)))
    if not cols:
        return []
    rows = ["| s | " + " | ".join("%s: Δp/q" % run.ident
                                     for run, _ in cols) + " |",
            "|---|" + "---|" * len(cols)]
    for k, s in enumerate(cols[0][1]["s"]):
        values = [_per(rings["dp"][k], rings["q"]) for _, rings in cols]
        if all(v is None or not math.isfinite(v) for v in values):
            continue        # no run's triangle has its mean s in the ring
        rows.append("| %.3f | %s |" % (s, " | ".join(
            _f(v, "%.3f") for v in values)))
    rows.append("| mean | %s |" % " | ".join(
        _f(_per(rings["mean"], rings["q"]), "%.3f") for _, rings in cols))
    return rows + ["", "Δp: the pressure jump the solver hands the cloth "
                   "(canopy.h5's dp, one value a triangle), area-weighted "
                   "in rings of equal width in s (shape.py's radial "
                   "position: 1 - d / d_max, d a node's path to the rim "
                   "along the cloth's springs; on the flat disc close to "
                   "r/R0) and averaged over the "
                   "states written in the interval (python/canopyfoam/"
                   "validation_results.py pressure_jump_rings, "
                   "`python3 -m canopyfoam.cloth_stress <case> 5 20 20`); "
                   "q = ρU²/2 = %s Pa." % " / ".join(sorted(set(
                       "%.1f" % rings["q"] for _, rings in cols))), ""]


def disc_tutorial_lines(results):
    """Study discTutorial7ft's GCI of C_D over its three levels (the
    sampled run left out) and the pressure jump by ring."""
    return (disc_gci_lines(results, levels=[
                run.ident for run in DISC_TUTORIAL_LEVELS])
            + disc_ring_lines(results))


def edge_retraction(run):
    """The free edges' retraction in cells a run sets (0 if none)."""
    value = 0.0
    for path, entry, v in run.edits:
        if entry == "coupling/forcing/freeEdgeRetractionCells":
            value = float(v)
    return value


def edge_crossings(results):
    """The retraction at which two levels' drags agree: per pair of
    consecutive levels holding runs at two retractions r0 < r1, (n_a, n_b,
    r0, r1, F_a(r0), F_b(r0), F_a(r1), F_b(r1), crossing, slope ratio).
    To first order F_n(r) = F (1 + 2 k (c - r)/n), so the drags agree at
    r = c and the drop from r0 to r1 scales as 1/n (slope ratio n_b/n_a)."""
    force = {}
    for run, rec in results:
        a = rec and rec["analysis"]
        if a and rec["complete"]:
            force[(cells_per_diameter(run), edge_retraction(run))] = \
                disc_coefficient(a)[0]
    levels = sorted(set(n for n, _ in force))
    out = []
    for n_a, n_b in zip(levels, levels[1:]):
        rs = sorted(set(r for n, r in force if n == n_a)
                    & set(r for n, r in force if n == n_b))
        if len(rs) < 2:
            continue
        r0, r1 = rs[0], rs[-1]
        fa0, fb0 = force[(n_a, r0)], force[(n_b, r0)]
        fa1, fb1 = force[(n_a, r1)], force[(n_b, r1)]
        d0, d1 = fa0 - fb0, fa1 - fb1
        crossing = r0 + (r1 - r0) * d0 / (d0 - d1) if d0 != d1 else None
        ratio = (fa0 - fa1) / (fb0 - fb1) if fb0 != fb1 else None
        out.append((n_a, n_b, r0, r1, fa0, fb0, fa1, fb1, crossing, ratio))
    return out


def disc_edge_lines(results):
    """Study discEdge7ft: where the IB disc's edge acts, from the
    retraction at which consecutive levels' drags agree."""
    rows = edge_crossings(results)
    if not rows:
        return ["The crossing needs two levels at two retractions each.", ""]
    lines = ["Where the drags of two levels agree (F_n(r) linear in the "
             "retraction r between the two retractions run):", "",
             "| levels (cells across D0) | F at r = %s: coarse, fine [N] "
             "| F at r = %s: coarse, fine [N] | drags agree at r [cells] "
             "| drop r0 → r1, coarse / fine (first order: n_fine/n_coarse) "
             "|" % ("r0", "r1"), "|---|---|---|---|---|"]
    for n_a, n_b, r0, r1, fa0, fb0, fa1, fb1, crossing, ratio in rows:
        lines.append("| %g, %g | %.2f, %.2f (r0 = %g) | %.2f, %.2f (r1 = %g) "
                     "| %s | %s (%.2f) |" % (
                         n_a, n_b, fa0, fb0, r0, fa1, fb1, r1,
                         _f(crossing, "%.2f"), _f(ratio, "%.2f"),
                         n_b / n_a))
    return lines + [""]


def stream_incidence(run):
    """The angle [deg] between a run's stream (its 0.orig/U internalField
    edit, uniform (ux uy uz)) and the disc's axis +z; 0 without the edit."""
    angle = 0.0
    for path, entry, value in run.edits:
        if path == "0.orig/U" and entry == "internalField":
            ux, uy, uz = (float(x) for x in
                          value.split("(")[1].split(")")[0].split())
            angle = math.degrees(math.atan2(math.hypot(ux, uy), uz))
    return angle


def disc_wake_lines(results):
    """Whether the disc's wake stays axisymmetric (study discWake7ft):
    per run the stream's angle to the axis, the force along the axis (mean
    with its 95 % interval from the series' autocorrelation, and std) and
    across it (x, in the stream's plane, and y: mean ± std) over the
    interval, and C_D along the stream, (F_z cos a + F_x sin a) / (q S0),
    with the 95 % interval of F_z."""
    lines = ["The force on the disc along its axis and across it over each "
             "run's interval (the records' canopyLoad; x lies in the plane "
             "of the axis and the stream; ± is the 95 % interval of the "
             "mean from the series' autocorrelation, std the spread), and "
             "C_D along the stream:", "",
             "| run | stream to axis [deg] | interval | along the axis [N] "
             "(mean ± 95 %; std) | across, x [N] (mean ± std) | across, y "
             "[N] (mean ± std) | C_D along the stream |",
             "|---|---|---|---|---|---|---|"]
    for run, rec in results:
        a = rec and rec.get("complete") and rec.get("analysis")
        if not a:
            lines.append("| %s | %.1f | | not run (`%s`) | | | |"
                         % (run.ident, stream_incidence(run), run.command()))
            continue
        load = a["canopyLoad"]
        f, std, ci = load["force"], load["forceStd"], load["forceCi95"]
        angle = math.radians(stream_incidence(run))
        q_s0 = disc_reference_force(a)
        cd = (f[2] * math.cos(angle) + f[0] * math.sin(angle)) / q_s0
        lines.append("| %s | %.1f | %g-%g s | %.2f ± %s; %.2f | %.2f ± %.2f "
                     "| %.2f ± %.2f | %.3f ± %s |" % (
                         run.ident, math.degrees(angle), run.steady_start,
                         run.steady_end, f[2], _f(ci[2], "%.2f"), std[2],
                         f[0], std[0], f[1], std[1], cd,
                         _f(ci[2] / q_s0 if ci[2] is not None else None,
                            "%.3f")))
    return lines + [""]


def disc_les_lines(results):
    """What the disc's LES runs show against the laminar ones, and their
    GCI."""
    return ["The same disc, C_D defined as in study disc7ft, with the WALE "
            "eddy viscosity (Nicoud & Ducros 1999; Δ the cell's cube-root "
            "volume) and 75 % central convection (LUST) instead of the "
            "laminar linear upwind. The LES raises the drag: C_D 1.302 "
            "and 1.263 at 12 and 18 cells across D0, against 1.235 and "
            "1.214 laminar, further from the published 1.1-1.17, and it "
            "drifts as much within 4-12 s (12 cells: 67.8 N over 4-8 s, "
            "71.9 N over 8-12 s). The wake stays axisymmetric as in the "
            "laminar runs (side force at most 0.03 and 0.14 N). The model "
            "is active: on 18 cells its eddy viscosity reaches 0.05 m²/s, "
            "3300 times air's, in the wake's shear layer at t = 12 s "
            "(`postProcess -func \"fieldMinMax(nut)\"`), so at D0/18 the "
            "filter is the mesh and the LES resolves little of the "
            "turbulence. Neither the turbulence model nor the convection "
            "scheme brings the disc's drag to the published values on "
            "these meshes; what both runs share is a symmetric start that "
            "keeps the wake axisymmetric, where a real disc's wake at "
            "this Reynolds number is three-dimensional, so a perturbed "
            "inflow is the next test. The 27-cell LES level "
            "(disc-LES-cpd27, about 35 minutes) is not run yet. Study "
            "discWake7ft shows the window is the issue: the symmetric "
            "start's wake stays axisymmetric until 12-18 s and then sheds, "
            "so 4-12 s reads the start alone.", ""
            ] + disc_gci_lines(results)


def gci_lines(results, fineness=None, unit="cells across D0"):
    """The resolution study's GCI table (resolution_estimates) as
    markdown."""
    done, table = resolution_estimates(results, fineness)
    if not table:
        return ["Grid convergence index: needs three complete runs, has "
                "%d (%s)." % (len(done), ", ".join(r.ident for _, r in
                                                  done) or "none"), ""]
    lines = ["Grid convergence (Roache's GCI, Celik et al. 2008; "
             "python/canopyfoam/gci.py; formal order 1, the IB's delta "
             "function, where the observed order is not usable) from %s "
             "(%s %s):"
             % (", ".join(r.ident for _, r in done),
                " / ".join("%g" % n for n, _ in done), unit), "",
             "| quantity | finest, medium, coarse | convergence | observed "
             "order | extrapolated | GCI of the finest |",
             "|---|---|---|---|---|---|"]
    for key, (f, out) in table.items():
        if out is None:
            lines.append("| %s | %s | different modes (spread over a "
                         "factor %g): no GCI | — | — | — |" % (
                             key, ", ".join("%.4g" % x for x in f),
                             BREATHING_SAME_MODE))
            continue
        lines.append("| %s | %s | %s | %s | %.4g | %.1f %% (Fs %.3g) |" % (
            key, ", ".join("%.4g" % x for x in f), out["kind"],
            "—" if out["order"] is None else "%.2f" % out["order"],
            out["extrapolated"], 100 * out["gci"], out["safety"]))
    return lines + [""]


def two_level_lines(results, what, ratio=2.0):
    """Roache's two-level estimate of a refinement by ratio r with formal
    order 1: the finer run's uncertainty Fs |f1 - f2| / (r - 1) with Fs =
    3 (Roache 1998, for two levels), as markdown; results coarse first."""
    done = [(run, rec["analysis"]) for run, rec in results
            if rec is not None and rec["complete"]
            and rec["analysis"] is not None]
    if len(done) != 2:
        return ["Two-level estimate: needs both runs complete, has %d."
                % len(done), ""]
    (run2, a2), (run1, a1) = done      # coarse first, as the study lists
    lines = ["Two-level estimate of %s (Roache: GCI = 3 |f1 - f2| / |f1| "
             "/ (r - 1) for a ratio r = %g and order 1), %s against %s:" % (
                 what, ratio, run1.ident, run2.ident), "",
             "| quantity | %s | %s | GCI of %s |" % (run1.ident, run2.ident,
                                                      run1.ident),
             "|---|---|---|---|"]
    d0 = a1["parameters"]["nominalDiameter"]["value"]
    for key, get in (
            ("descent speed [m/s]", lambda a: a["descentVelocity"]["mean"]),
            ("C_D0 (weight)",
             lambda a: a["dragCoefficient"]["weightBalance"]),
            ("Dp/D0", lambda a: a["projectedDiameter"]["mean"] / d0)):
        f1, f2 = get(a1), get(a2)
        lines.append("| %s | %.4g | %.4g | %.1f %% |" % (
            key, f1, f2, 100 * 3 * abs(f1 - f2) / abs(f1) / (ratio - 1)))
    return lines + [""]


def complete_against_first(results):
    """The (run, analysis) pairs of the complete runs, when the first run
    and at least one other are complete; else None."""
    done = [(run, rec["analysis"]) for run, rec in results
            if rec is not None and rec["complete"]
            and rec["analysis"] is not None]
    if len(done) < 2 or done[0][0] is not results[0][0]:
        return None
    return done


def against_gci_lines(results, what, study="resolution7ftHeld"):
    """The change of each run's descent speed, C_D0 and Dp/D0 from the
    first run's, against the resolution study's GCI of the same quantity
    (an effect inside the GCI is not distinguishable from the
    discretisation's uncertainty), as markdown."""
    done = complete_against_first(results)
    if done is None:
        return ["%s: needs %s and another run complete." % (
            what, results[0][0].ident), ""]
    try:
        gci = converged(study)
    except SystemExit:
        gci = {}
    base_run, base = done[0]
    d0 = base["parameters"]["nominalDiameter"]["value"]
    get = (("descent speed [m/s]", lambda a: a["descentVelocity"]["mean"]),
           ("C_D0 (weight)",
            lambda a: a["dragCoefficient"]["weightBalance"]),
           ("Dp/D0", lambda a: a["projectedDiameter"]["mean"] / d0))
    lines = ["%s, each run against %s; the last column is the GCI of the "
             "study %s's finest level:" % (what, base_run.ident, study), "",
             "| quantity | %s | %s | GCI |" % (base_run.ident, " | ".join(
                 "%s (change)" % run.ident for run, _ in done[1:])),
             "|---|---|%s---|" % ("---|" * (len(done) - 1))]
    for key, f in get:
        g = gci.get(key)
        lines.append("| %s | %.4g | %s | %s |" % (
            key, f(base), " | ".join(
                "%.4g (%+.1f %%)" % (f(a), 100 * (f(a) - f(base)) / f(base))
                for _, a in done[1:]),
            "%.1f %%" % (100 * g["gci"]) if g and g["gci"] is not None
            else "—"))
    return lines + [""]


SCATTER_SUFFIX = "-splitx"


def scatter_lines(results):
    """The runs' own scatter, as markdown: each run X whose study also has
    X-splitx (the same run with the box split across the flow between the
    ranks, so that the linear solvers' answers differ at their tolerances
    from the first step on) is compared with it. Two runs that differ only
    in such a perturbation sample the same statistics, so their means'
    difference d has the standard deviation sqrt(2) s of one run's mean;
    each run's stated 95 % half-width h (report.mean_confidence) claims
    s = h / 1.96, so |d| / (sqrt(2) h) exceeds 1 in one pair in twenty if
    the half-widths are right, in most pairs if they understate it; the pooled
    s = rms(d) / sqrt(2) over the pairs is the scatter measured directly."""
    done = dict((run.ident, rec["analysis"]) for run, rec in results
                if rec is not None and rec["complete"]
                and rec["analysis"] is not None)
    pairs = [(i, i + SCATTER_SUFFIX) for i in done
             if i + SCATTER_SUFFIX in done]
    if not pairs:
        return []
    lines = ["The runs' scatter: each run against the same run with the box "
             "split across the flow (its linear solvers' answers differ at "
             "their tolerances from the first step on). d is the "
             "difference of the means; the ratio |d| / (sqrt(2) h), with h "
             "the larger of the two runs' 95 % half-widths, exceeds 1 in one "
             "pair in twenty if the half-widths are right; in most pairs, "
             "if they understate the scatter.", "",
             "| run | descent [m/s] | split across | d [m/s] | ratio | "
             "C_D0 | split across | d C_D0 |",
             "|---|---|---|---|---|---|---|---|"]
    diffs, cd_diffs = [], []
    for a_id, b_id in pairs:
        a, b = done[a_id], done[b_id]
        va, vb = a["descentVelocity"], b["descentVelocity"]
        ca = a["dragCoefficient"]["weightBalance"]
        cb = b["dragCoefficient"]["weightBalance"]
        d = vb["mean"] - va["mean"]
        diffs.append(d)
        cd_diffs.append(cb - ca)
        halves = [v.get("ci95") for v in (va, vb)]
        ratio = ("%.1f" % (abs(d) / (math.sqrt(2) * max(halves)))
                 if None not in halves and max(halves) > 0 else "-")
        lines.append("| %s | %.3f ± %s | %.3f ± %s | %+.3f | %s | %.3f | "
                     "%.3f | %+.3f |" % (
                         a_id, va["mean"], fmt_half(halves[0]), vb["mean"],
                         fmt_half(halves[1]), d, ratio, ca, cb, cb - ca))
    rms = lambda xs: math.sqrt(sum(x * x for x in xs) / len(xs))
    lines += ["", "Pooled over the %d pair(s): one run's mean scatters by "
              "s = rms(d) / sqrt(2) = %.3f m/s in the descent and %.3f in "
              "C_D0." % (len(pairs), rms(diffs) / math.sqrt(2),
                          rms(cd_diffs) / math.sqrt(2)), ""]
    return lines


def fmt_half(h):
    """A 95 % half-width for a table, '-' when there is none."""
    return "-" if h is None else "%.3f" % h


def window_change_lines(results, what):
    """Each run's change from the first run's means against the two
    means' combined 95 % interval, as markdown: the descent's half-widths
    h add as sqrt(h1^2 + h2^2); C_D0 goes as 1/V^2, so its relative
    half-width is 2 h / V. A change inside the combined interval is not
    told apart from the window's own scatter."""
    done = complete_against_first(results)
    if done is None:
        return ["%s: needs %s and another run complete." % (
            what, results[0][0].ident), ""]
    base_run, base = done[0]
    d0 = base["parameters"]["nominalDiameter"]["value"]
    vb = base["descentVelocity"]
    lines = ["%s, each run against %s (95 %% intervals combined; C_D0's "
             "relative half-width is twice the descent's):" % (
                 what, base_run.ident), "",
             "| run | descent change [m/s] | C_D0 change | Dp/D0 change | "
             "suspension angle rms [deg] | change told apart? |",
             "|---|---|---|---|---|---|"]
    for run, a in done[1:]:
        va = a["descentVelocity"]
        if va.get("ci95") is None or vb.get("ci95") is None:
            lines.append("| %s | %+.3f | - | - | - | no interval |" % (
                run.ident, va["mean"] - vb["mean"]))
            continue
        dv = va["mean"] - vb["mean"]
        hv = math.hypot(va["ci95"], vb["ci95"])
        ca = a["dragCoefficient"]["weightBalance"]
        cb = base["dragCoefficient"]["weightBalance"]
        dc = (ca - cb) / cb
        hc = math.hypot(2 * va["ci95"] / va["mean"],
                        2 * vb["ci95"] / vb["mean"])
        dp = (a["projectedDiameter"]["mean"]
              - base["projectedDiameter"]["mean"]) / d0
        swing = (a.get("swing") or {}).get("angleRms")
        lines.append("| %s | %+.3f ± %.3f | %+.1f %% ± %.1f %% | %+.3f | %s "
                     "| %s |" % (run.ident, dv, hv, 100 * dc, 100 * hc, dp,
                                 "-" if swing is None else "%.2f" % swing,
                                 "yes" if abs(dv) > hv else "no"))
    swing = (base.get("swing") or {}).get("angleRms")
    lines += ["", "%s: descent %.3f ± %.3f m/s, C_D0 %.3f, Dp/D0 %.3f, "
              "suspension angle rms %s deg." % (
                  base_run.ident, vb["mean"], vb.get("ci95") or 0.0,
                  base["dragCoefficient"]["weightBalance"],
                  base["projectedDiameter"]["mean"] / d0,
                  "-" if swing is None else "%.2f" % swing), ""]
    return lines


def cd_change(c1, h1, c2, h2):
    """C_D0's relative change from c1 to c2 against the pair's combined
    95 % relative half-width hypot(h1, h2) (None when either is None):
    (change, told apart, the markdown "C_D0 +x % (beyond|within the
    combined ± y %)")."""
    change = (c2 - c1) / c1
    both = math.hypot(h1, h2) if h1 is not None and h2 is not None else None
    told = both is not None and abs(change) > both
    text = "C_D0 %+.1f %%%s" % (100 * change, "" if both is None else
                                " (%s the combined ± %.1f %%)" % (
                                    "beyond" if told else "within",
                                    100 * both))
    return change, told, text


def level_values(a):
    """What a level's row shows of a record's analysis a: (D0, the descent
    dict, C_D0, its 95 % relative half-width (twice the descent's; None
    without an interval), the breathing peak as text)."""
    v = a["descentVelocity"]
    b = a.get("breathing") or {}
    breathing = ("%.2f Hz, %.1f cm" % (b["frequency"], 100 * b["amplitude"])
                 if b.get("resolved") else "read over another interval"
                 if b.get("overOtherInterval") else "none resolved")
    return (a["parameters"]["nominalDiameter"]["value"], v,
            a["dragCoefficient"]["weightBalance"],
            2 * v["ci95"] / v["mean"] if v.get("ci95") else None, breathing)


def edge_levels_lines(results):
    """The fabric's edge varied at one air resolution (studies
    edgeLength7ft, edgeLength7ftLong, edgeLength7ftCpd27 through
    over_window, and edgeLengthT10), from the records, as markdown: per
    level, coarse to fine, the edge in finest cells and in metres (edge
    cells times D0 over cells across D0), C_D0 with its 95 % relative
    half-width (twice the descent's), Dp/D0, the skirt's mean radius and
    the outer ring's hinges folded beyond 90 degrees, and the breathing
    peak where the spectrum resolves one; then each refinement's change
    in C_D0 against the pair's combined interval, and whether the changes
    shrink (the levels converge), grow, or change sign (oscillate)."""
    rows, done = [], []
    for run, rec in sorted(results, key=lambda x: -fabric_edge_cells(x[0])):
        a = rec and rec.get("complete") and rec.get("analysis")
        edge = fabric_edge_cells(run)
        if not a:
            rows.append("| %g | — | %s | not run (`%s`) | | | | |"
                        % (edge, run.ident, run.command()))
            continue
        d0, v, cd, half, breathing = level_values(a)
        shape = a.get("shape") or {}
        skirt = ("%.3f" % (shape["skirtRadiusMean"] / d0)
                 if shape.get("available") else "—")
        outer = ("%.0f %%" % (100 * shape["rings"][-1]["foldedFraction"])
                 if shape.get("available") and shape.get("rings") else "—")
        cpd = cells_per_diameter(run)
        rows.append("| %g | %s | %s | %.3f%s | %.3f | %s | %s | %s |" % (
            edge, "%.3f" % (edge * d0 / cpd) if cpd else "—", run.ident, cd,
            " ± %.1f %%" % (100 * half) if half is not None else "",
            a["projectedDiameter"]["mean"] / d0, skirt, outer, breathing))
        done.append((edge, cd, half))
    lines = ["| edge [finest cells] | edge [m] | run | C_D0 (95 %) | Dp/D0 | "
             "skirt radius / D0 | outer ring folded beyond 90 deg | "
             "breathing |", "|---|---|---|---|---|---|---|---|"] + rows + [""]
    return lines + successive_change_lines(done, "finest cells",
                                           "The edge's effect")


def successive_change_lines(done, unit, what):
    """Each refinement's change in C_D0 against the pair's combined
    interval (cd_change), and whether the changes shrink (the levels
    converge), grow, or change sign (oscillate), as markdown; done [(level,
    C_D0, its 95 % relative half-width or None)] coarse to fine, level in
    `unit`; `what` names the effect when fewer than two levels are run."""
    if len(done) < 2:
        return ["%s needs two levels run." % what, ""]
    lines, steps = [], []
    for (e1, c1, h1), (e2, c2, h2) in zip(done, done[1:]):
        change, told, text = cd_change(c1, h1, c2, h2)
        steps.append((change, told, "%g to %g" % (e1, e2)))
        lines.append("- %g to %g %s: %s." % (e1, e2, unit, text))
    if len(steps) >= 2:
        (before, before_told, before_name), (last, last_told, last_name) = \
            steps[-2], steps[-1]
        unclear = [n for n, told in ((before_name, before_told),
                                     (last_name, last_told)) if not told]
        if unclear:
            verdict = ("%s lies within the pair's interval, so whether the "
                       "levels converge or oscillate is not told apart"
                       % " and ".join(unclear))
        elif before * last < 0:
            verdict = ("the last two refinements move C_D0 in opposite "
                       "directions: the levels oscillate")
        elif abs(last) < abs(before):
            verdict = ("the last refinement moves C_D0 less than the one "
                       "before (ratio %.2f): the levels converge"
                       % (last / before))
        else:
            verdict = ("the last refinement moves C_D0 more than the one "
                       "before (ratio %.2f): the levels diverge"
                       % (last / before))
        lines.append("- Successive changes: %s." % verdict)
    return lines + [""]


def air_levels_lines(results):
    """The air's resolution varied with the cloth held (study
    resolution7ftFineCloth), from the records, as markdown: per level,
    coarse to fine, cells across D0 and in the mesh, the descent with its
    95 % half-width and drift over the interval, C_D0 with its relative
    half-width (twice the descent's), Dp/D0, C_Dp on the projected area,
    the breathing peak where the spectrum resolves one, the coupling's
    iterations a step over the interval and the wall time; then each
    refinement's change in C_D0 against the pair's combined interval
    (successive_change_lines) and Roache's GCI (gci_lines)."""
    rows, done = [], []
    for run, rec in sorted(results, key=lambda x: cells_per_diameter(x[0])):
        a = rec and rec.get("complete") and rec.get("analysis")
        cpd = cells_per_diameter(run)
        if not a:
            rows.append("| %g | — | %s | not run (`%s`) | | | | | | |"
                        % (cpd, run.ident, run.command()))
            continue
        d0, v, cd, half, breathing = level_values(a)
        dp = a["projectedDiameter"]["mean"] / d0
        wall = rec["wall"]
        rows.append("| %g | %s | %s | %.2f ± %s (%+.2f) | %.3f%s | %.3f | "
                    "%.3f | %s | %.2f | %s |" % (
                        cpd, _f(rec.get("cells"), "%d"), run.ident,
                        v["mean"], _f(v.get("ci95"), "%.2f"), v["drift"], cd,
                        " ± %.1f %%" % (100 * half) if half is not None
                        else "", dp, cd / dp ** 2, breathing,
                        a["coupling"]["meanIterationsSteady"],
                        _f(wall / 60 if wall else None, "%.0f min")))
        done.append((cpd, cd, half))
    lines = ["| cells across D0 | cells | run | descent [m/s] (95 %; drift) "
             "| C_D0 (95 %) | Dp/D0 | C_Dp | breathing | coupling "
             "iterations a step | wall time |",
             "|---|---|---|---|---|---|---|---|---|---|"] + rows + [""]
    return (lines + successive_change_lines(done, "cells across D0",
                                            "The air's resolution")
            + gci_lines(results))


def start_transient_lines(results, bin_width=0.5,
                          title="The descent from the start:"):
    """The descent's course from each run's start, from its record's
    descent series, as markdown under `title`: its means over successive
    bins of
    bin_width [s], the lowest bin and the highest after it with their
    times, and the last bin: whether the run has passed its start's
    transient before its interval is read."""
    lines = []
    for run, rec in results:
        a = rec and rec.get("complete") and rec.get("analysis")
        series = (a or {}).get("descentSeries") or {}
        t = np.asarray(series.get("t") or [], dtype=float)
        v = np.asarray(series.get("v") or [], dtype=float)
        if len(t) < 4:
            continue
        starts = np.arange(0.0, t[-1], bin_width)
        means = [(s0, v[(t >= s0) & (t < s0 + bin_width)].mean())
                 for s0 in starts if np.any((t >= s0) & (t < s0 + bin_width))]
        low = min(range(len(means)), key=lambda k: means[k][1])
        text = "lowest %.2f m/s at %g-%g s" % (
            means[low][1], means[low][0], means[low][0] + bin_width)
        if low + 1 < len(means):
            high = max(range(low + 1, len(means)), key=lambda k: means[k][1])
            text += ", then highest %.2f at %g-%g s; last %.2f" % (
                means[high][1], means[high][0], means[high][0] + bin_width,
                means[-1][1])
        else:
            text += ", the last bin"
        lines.append("- %s (interval from %g s): %s m/s in %g s bins; %s."
                     % (run.ident, a["steady"]["start"],
                        ", ".join("%.2f" % m for _, m in means), bin_width,
                        text))
    if not lines:
        return ["%s no run complete." % title, ""]
    return [title, ""] + lines + [""]


def edge_study_lines(results):
    """An edge study's table and changes (edge_levels_lines) with the
    GCI over the edge's inverse (gci_lines), as markdown."""
    return edge_levels_lines(results) + gci_lines(
        results, lambda run: 1.0 / fabric_edge_cells(run),
        "per finest cell: the edge's inverse")


def window_mean(analysis, start, end):
    """The descent's time mean over [start, end] from a record's descent
    series (report.py's decimated t, v), with its 95 % half-width from the
    series' autocorrelation (report.mean_confidence; None when the window
    holds fewer than two integral times) and its drift; None when the
    series starts after the window or ends more than a twentieth of the
    window before its end (the decimated series' last point may fall
    just short of the run's end)."""
    from . import report
    series = analysis.get("descentSeries") or {}
    t = np.asarray(series.get("t") or [], dtype=float)
    v = np.asarray(series.get("v") or [], dtype=float)
    if len(t) < 4 or t[0] > start or t[-1] < end - (end - start) / 20:
        return None
    inside = report.interval_mask(t, start, end)
    stats = report.time_statistics(t[inside], v[inside])
    half, _, _ = report.mean_confidence(t[inside], v[inside])
    return {"mean": stats["mean"], "ci95": half, "drift": stats["drift"]}


def weight_cd(analysis, speed):
    """C_D0 = W / (rho V^2 S0 / 2) at the descent speed V, W the weight
    the record's drag balances and S0 the nominal area pi D0^2 / 4."""
    par = analysis["parameters"]
    d0 = par["nominalDiameter"]["value"]
    return analysis["dragCoefficient"]["weight"] / (
        0.5 * par["rho"]["value"] * speed ** 2 * math.pi * d0 ** 2 / 4)


def over_window(results, start, end):
    """results [(run, record)] with each complete record's descent and
    C_D0 read over one common window [start, end] from its descent series
    (window_mean), for a study whose runs were read over different
    intervals: a copy of the analysis with descentVelocity's mean, ci95
    and drift and dragCoefficient's weightBalance (weight_cd) replaced.
    The projected diameter and the shape stay over the record's own
    interval; the
    breathing peak is kept only where that interval is the window (a
    peak read over another interval is marked overOtherInterval, not
    resolved). A record whose series does not cover the window becomes
    None (not run over it)."""
    out = []
    for run, rec in results:
        a = rec and rec.get("complete") and rec.get("analysis")
        w = window_mean(a, start, end) if a else None
        if not w:
            out.append((run, None if a else rec))
            continue
        a = dict(a)
        a["dragCoefficient"] = dict(a["dragCoefficient"],
                                    weightBalance=weight_cd(a, w["mean"]))
        a["descentVelocity"] = dict(a["descentVelocity"], mean=w["mean"],
                                    ci95=w["ci95"], drift=w["drift"])
        steady = a.get("steady") or {}
        if (steady.get("start"), steady.get("end")) != (start, end):
            a["breathing"] = {"resolved": False, "overOtherInterval": True}
        out.append((run, dict(rec, analysis=a)))
    return out


def edge_against_cells_lines(results, start=8.0, end=12.0):
    """Whether the 7 ft canopy's drag follows the fabric's edge in metres
    or its ratio to the finest cells (study edgeAgainstCells7ft), from the
    records, as markdown: per run the cells across D0, the edge in finest
    cells and in metres, and the descent over one common window (each
    record's descent series, window_mean) with C_D0 = W / (rho V^2 S0 / 2),
    W the weight the record's drag balances; then each pair of runs at the
    same edge in metres and each at the same edge in cells, with the
    change of C_D0 between them against the pair's combined 95 % interval
    (cd_change; C_D0's relative half-width twice the descent's), and a
    verdict on which of the two sets C_D0."""
    rows, done = [], []
    for run, rec in results:
        a = rec and rec.get("complete") and rec.get("analysis")
        cpd, edge = cells_per_diameter(run), fabric_edge_cells(run)
        w = window_mean(a, start, end) if a else None
        if not w:
            rows.append("| %s | %g | %g | — | %s | |" % (
                run.ident, cpd, edge, "not run (`%s`)" % run.command()
                if not a else "its series does not cover %g-%g s"
                % (start, end)))
            continue
        metres = edge * a["parameters"]["nominalDiameter"]["value"] / cpd
        cd = weight_cd(a, w["mean"])
        rows.append("| %s | %g | %g | %.3f | %.2f%s (drift %+.2f) | %.3f |"
                    % (run.ident, cpd, edge, metres, w["mean"],
                       "" if w["ci95"] is None else " ± %.2f" % w["ci95"],
                       w["drift"], cd))
        half = (2 * w["ci95"] / w["mean"] if w["ci95"] is not None
                else None)
        done.append((run, cpd, edge, metres, cd, half))
    lines = ["The descent over %g-%g s of each run, from its record's "
             "descent series, with its 95 %% interval from the series' "
             "autocorrelation and its drift across the window; C_D0 = W / "
             "(rho V^2 S0 / 2) from that mean, W the weight the drag "
             "balances." % (start, end), "",
             "| run | cells across D0 | edge [finest cells] | edge [m] | "
             "descent [m/s] | C_D0 |", "|---|---|---|---|---|---|"] \
        + rows + [""]
    same_metres, same_cells = [], []
    for i, (r1, n1, e1, m1, c1, h1) in enumerate(done):
        for r2, n2, e2, m2, c2, h2 in done[i + 1:]:
            if n1 == n2:
                continue
            (ra, na, ca), (rb, nb, cb) = sorted(
                [(r1, n1, c1), (r2, n2, c2)], key=lambda x: x[1])
            change, told, text = cd_change(ca, h1, cb, h2)
            pair = "%s (%g cells) to %s (%g cells): %s" % (
                ra.ident, na, rb.ident, nb, text)
            # the same length within 2 %: the edges in cells are given to
            # two digits (0.56 and 0.83 for 1.25 / 1.5^2 and 1.25 / 1.5)
            if abs(m1 - m2) <= 0.02 * max(m1, m2):
                same_metres.append(("- edge %.3f m: %s" % (m1, pair),
                                    change, told))
            elif e1 == e2:
                same_cells.append(("- edge %g finest cells: %s" % (e1, pair),
                                   change, told))
    if not same_metres and not same_cells:
        return lines + ["No pair of runs at two air resolutions with the "
                        "same edge is complete.", ""]
    lines += (["The same edge in metres, the air refined:"]
              + ([p[0] for p in same_metres] or ["- no pair complete"])
              + ["", "The same edge in finest cells, both refined:"]
              + ([p[0] for p in same_cells] or ["- no pair complete"]) + [""])
    if same_metres and same_cells:
        largest = dict((what, max(abs(p[1]) for p in pairs))
                       for what, pairs in (("metres", same_metres),
                                           ("cells", same_cells)))
        moved = dict((what, any(p[2] for p in pairs))
                     for what, pairs in (("metres", same_metres),
                                         ("cells", same_cells)))
        if moved["metres"] and not moved["cells"]:
            verdict = ("C_D0 follows the edge's ratio to the cells: at the "
                       "same ratio the air's refinement moves it within "
                       "the intervals, at the same length beyond them")
        elif moved["cells"] and not moved["metres"]:
            verdict = ("C_D0 follows the edge's length: at the same length "
                       "the air's refinement moves it within the "
                       "intervals, at the same ratio beyond them")
        else:
            verdict = ("neither the edge's length nor its ratio to the "
                       "cells alone sets C_D0: refining the air moves it "
                       "by up to %.1f %% at the same length and %.1f %% at "
                       "the same ratio" % (100 * largest["metres"],
                                           100 * largest["cells"]))
        lines += ["Across the air's resolutions %s." % verdict, ""]
    return lines


def longer_run_lines(results, ident, shorter):
    """A run made longer to reach its steady descent (ident) against the
    shorter run of the same set-up, from their records, as markdown: each
    one's mean descent with its 95 % interval, its drift across its
    interval (the linear fit's change; report.py), C_D0 and Dp/D0."""
    recs = dict((run.ident, r) for run, r in results)
    runs = dict((run.ident, run) for run, _ in results)

    def describe(i):
        a = (recs.get(i) or {}).get("analysis")
        if not a:
            return None
        v, st = a["descentVelocity"], a["steady"]
        d0 = a["parameters"]["nominalDiameter"]["value"]
        return ("%.2f ± %.2f m/s over %.3g-%.3g s (drift %+.2f m/s across "
                "it%s), C_D0 %.3f, Dp/D0 %.2f" % (
                    v["mean"], v.get("ci95") or float("nan"), st["start"],
                    st["end"], v.get("drift") or 0.0,
                    ": drifting" if st.get("warning") else "",
                    a["dragCoefficient"]["weightBalance"],
                    a["projectedDiameter"]["mean"] / d0))
    long_text, short_text = describe(ident), describe(shorter)
    if long_text is None:
        return ["%s (%s) is not run yet (`%s`)." % (
            ident, runs[ident].label, runs[ident].command()), ""]
    return ["%s (%s): %s; %s gave %s." % (
        ident, runs[ident].label.split(";")[0], long_text, shorter,
        short_text or "nothing"), ""]


def cross_free_lines(results, ident="cross-fullLoad-20s"):
    """What the cross in free flight shows against its published
    stability (issue 34 item 5), from its record, as markdown."""
    rec = dict((run.ident, r) for run, r in results).get(ident)
    run = dict((run.ident, run) for run, r in results).get(ident)
    a = rec and rec.get("analysis")
    if not a or not a.get("swing"):
        return ["The cross in free flight (%s) is not run yet." % ident, ""]
    cells = cells_per_diameter(run)
    sw, par = a["swing"], a["parameters"]
    d0 = par["nominalDiameter"]["value"]
    ratio = 0.5 / (par["rho"]["value"] * d0 ** 3)    # its 0.5 kg payload
    growth = sw.get("growth") or {}
    rate = growth.get("rate")
    end = a.get("timeEnd")
    return ["The cross (span 1.27 m, nominal diameter %.3f m, 0.5 kg; "
            "m / ρ D0³ = %.2f, as the 7 ft canopy's 0.46) on the "
            "full-load scheme every other tutorial uses leaves the "
            "vertical at %.1f s%s; over %.1f-%.1f s its suspension "
            "reaches %.0f° (rms %.0f°, mean %.0f°) and the payload whirls "
            "at up to %.1f m/s across gravity, %s. Published cross "
            "canopies oscillate by 0° to ±3° (Knacke, Table 5-1): at %g "
            "cells across the span the model's cross is not stable (study "
            "crossResolution: the same free flight at 11, 16 and 22 "
            "cells). Its payload is as heavy for its canopy as the 7 ft "
            "canopy's, which departs too (σ D0 / V 0.70) but settles, "
            "so the payload's relative mass alone is not what decides "
            "whether a model canopy settles." % (
                d0, ratio, sw["onset"],
                "" if rate is None else " (σ = %.2f /s, σ D0 / V = %.2f)"
                % (rate, rate * d0 / growth["descent"]),
                a["steady"]["start"], a["steady"]["end"], sw["angleMax"],
                sw["angleRms"], sw["angleMean"],
                a["horizontalVelocity"]["max"],
                "to the run's end" if rec.get("complete") else
                "until the run stops at %.1f s (the canopy past the finest "
                "refinement, the coupling unconverged)" % end, cells), ""]


def cross_starts_lines(results):
    """Whether the cross's flat and folded starts reach the same descent
    (study crossStarts; the seed's observation for its starts, §5.7), from
    the records, as markdown: per run the descent over its interval with
    its 95 % interval and drift, C_D on the cloth's area, Dp/D0 and the
    suspension's largest and rms angle; then the two descents' difference
    against their combined interval, and whether either still drifts by
    more than its interval (then the runs are too short to tell)."""
    rows, done = [], []
    for run, rec in results:
        a = rec and rec.get("analysis")
        if not a or not a.get("descentVelocity"):
            rows.append("| %s | not run (`%s`) | | | | |"
                        % (run.ident, run.command()))
            continue
        v, st, sw = a["descentVelocity"], a["steady"], a.get("swing") or {}
        d0 = a["parameters"]["nominalDiameter"]["value"]
        dp = a["projectedDiameter"]["mean"] / d0
        cd = a["dragCoefficient"]["weightBalance"]
        done.append((run, v))
        rows.append("| %s | %.2f ± %.2f (%.3g-%.3g s) | %+.2f | %.2f | "
                    "%.2f | %s |" % (
                        run.ident, v["mean"], v["ci95"], st["start"],
                        st["end"], v["drift"], cd, dp,
                        "%.1f° / %.1f°" % (sw["angleMax"], sw["angleRms"])
                        if sw.get("angleMax") is not None else "—"))
    lines = ["The seed finds that its starts reach the same state (§5.7). "
             "The descent over each run's interval with its 95 % interval "
             "(from the series' autocorrelation) and its drift across the "
             "interval; C_D on the cloth's area; the suspension's angle to "
             "the vertical.", "",
             "| run | descent [m/s] (interval) | drift [m/s] | C_D | Dp/D0 "
             "| suspension largest / rms |", "|---|---|---|---|---|---|"] \
        + rows + [""]
    if len(done) < 2:
        return lines + ["The comparison needs both starts run.", ""]
    v1, v2 = done[0][1], done[1][1]
    diff = v2["mean"] - v1["mean"]
    both = math.hypot(v1["ci95"], v2["ci95"])
    moving = [r.ident for r, v in done if abs(v["drift"]) > v["ci95"]]
    verdict = ("The folded start descends %+.2f m/s from the flat one's, "
               "%s their combined interval (± %.2f m/s)." % (
                   diff, "within" if abs(diff) <= both else "beyond", both))
    if moving:
        one = len(moving) == 1
        verdict += (" %s still drift%s by more than %s over the "
                    "reading: the runs are too short to say whether the "
                    "two starts reach the same state." % (
                        " and ".join(moving), "s" if one else "",
                        "its interval" if one else "their intervals"))
    return lines + [verdict, ""]


def cross_resolution_lines(results, span=1.27, arm_width=0.335):
    """The cross's departure from the vertical descent at each resolution
    (study crossResolution, issue 34 item 5), from the records, as
    markdown: per run the cells across the arm, the ranks, the onset (the
    suspension past 5°), the growth rate σ of the payload's speed across
    gravity and σ D0 / V, the suspension's largest and rms angle over the
    interval and the descent; then whether the departure survives the
    finest level, and σ's scatter between the first run of the coarsest
    level and a later one of the same level on other ranks. span,
    arm_width: the tutorial's cross (canopy.span, canopy.armWidth)."""
    rows, done = [], []
    for run, rec in results:
        a = rec and rec.get("analysis")
        if not a or not a.get("swing"):
            rows.append("| %s | not run (`%s`) | | | | | | |"
                        % (run.ident, run.command()))
            continue
        sw, par, st = a["swing"], a["parameters"], a["steady"]
        d0 = par["nominalDiameter"]["value"]
        n = cells_per_diameter(run)
        growth = sw.get("growth") or {}
        rate = growth.get("rate")
        done.append((run, n, rec.get("ranks"), rate, sw))
        v = a["descentVelocity"]
        rows.append("| %s | %.1f | %s | %s | %s | %s | %.0f° / %.0f° | "
                    "%.2f ± %.2f (%.3g-%.3g s) |" % (
                        run.ident, arm_width / (span / n),
                        rec.get("ranks") or "—",
                        "—" if sw.get("onset") is None else
                        "%.2f s" % sw["onset"],
                        "none" if rate is None else "%.2f /s" % rate,
                        "—" if rate is None else
                        "%.2f" % (rate * d0 / growth["descent"]),
                        sw["angleMax"], sw["angleRms"], v["mean"],
                        v.get("ci95") or float("nan"), st["start"],
                        st["end"]))
    lines = ["The cross's %g m arms, and the gaps between them through "
             "which a cross canopy vents, span few cells on a coarse mesh: "
             "the same free flight at %s cells across the span. σ: the "
             "payload's speed across gravity grows as exp(σ t) "
             "(report.py, swing_growth: from 1 %% to 20 %% of the descent); "
             "the onset: the suspension past 5° from the vertical."
             % (arm_width, ", ".join("%g" % n for n in sorted(set(
                 cells_per_diameter(r) for r, _ in results)))), "",
             "| run | cells across an arm | ranks | onset | σ | σ D0 / V | "
             "suspension largest / rms over the interval | descent [m/s] "
             "(interval) |", "|---|---|---|---|---|---|---|---|"] + rows + [""]
    levels = [d for d in done if "-cellsPerDiameter" in d[0].options]
    wanted = [r for r, _ in results if "-cellsPerDiameter" in r.options]
    if len(levels) < len(wanted):
        return lines + ["The verdict needs every level run.", ""]
    finest = max(levels, key=lambda x: x[1])
    coarsest = min(levels, key=lambda x: x[1])
    twins = [d for d in done if d[1] == coarsest[1] and d[2] != coarsest[2]
             and d[3] is not None and coarsest[3] is not None]
    scatter = ""
    if twins:
        twin = twins[0]
        scatter = (" The coarsest set-up on %s rank%s (%s) departs at σ "
                   "%.2f /s against %.2f on %s: round-off alone moves σ by "
                   "%.0f %%." % (
                       twin[2], "" if twin[2] == 1 else "s", twin[0].ident,
                       twin[3], coarsest[3], coarsest[2],
                       100.0 * abs(twin[3] / coarsest[3] - 1.0)))
    if finest[3] is None:
        verdict = ("At %g cells across the span the payload's speed across "
                   "gravity stays below 20 %% of the descent to the run's "
                   "end (the suspension within %.1f°, rms %.1f°): the "
                   "coarser levels' departure comes with the arms' "
                   "resolution." % (finest[1], finest[4]["angleMax"],
                                    finest[4]["angleRms"]))
    elif all(d[3] is not None for d in levels):
        verdict = ("The vertical descent departs at every level (σ %.2f "
                   "/s at %g cells across the span, %.2f /s at %g: %+.0f "
                   "%%): resolving the arms to %g cells across the span "
                   "does not make the model's cross stable." % (
                       coarsest[3], coarsest[1], finest[3], finest[1],
                       100.0 * (finest[3] / coarsest[3] - 1.0), finest[1]))
    else:
        verdict = ("The finest level departs where a coarser one does not: "
                   "no conclusion.")
    return lines + [verdict + scatter + " Published cross canopies: 0° to "
                    "±3° (Knacke, NWC TP 6575, Table 5-1).", ""]


def turbulence_lines(results, gci_cd0=None, study="resolution7ftHeld"):
    """Laminar against LES in pairs (results: laminar, LES, laminar, LES,
    ...): each pair's change against its combined 95 % interval
    (window_change_lines) and against the GCI of the resolution `study`
    (against_gci_lines), then the verdict of issue 34 item 3 (LES made the
    default only where it changes the answer beyond the GCI), as
    markdown. gci_cd0: C_D0's GCI as a fraction (default: the study's)."""
    g = gci_cd0
    if g is None:
        try:
            g = (converged(study).get("C_D0 (weight)")
                 or {}).get("gci")
        except SystemExit:
            g = None
    lines, verdicts = [], []
    for k in range(0, len(results) - 1, 2):
        pair = results[k:k + 2]
        what = "LES against laminar (%s)" % pair[0][0].label.split(";")[0]
        done = complete_against_first(pair)
        if done is None:
            lines += ["%s: needs %s and %s complete." % (
                what, pair[0][0].ident, pair[1][0].ident), ""]
            continue
        lines += window_change_lines(pair, what)
        lines += against_gci_lines(pair, what, study)
        (lam_run, lam), (les_run, les) = done
        vl, ve = lam["descentVelocity"], les["descentVelocity"]
        cl = lam["dragCoefficient"]["weightBalance"]
        ce = les["dragCoefficient"]["weightBalance"]
        d0 = lam["parameters"]["nominalDiameter"]["value"]
        dc = (ce - cl) / cl
        hc = (math.hypot(2 * vl["ci95"] / vl["mean"],
                         2 * ve["ci95"] / ve["mean"])
              if vl.get("ci95") is not None and ve.get("ci95") is not None
              else None)
        bl = (lam.get("breathingBand") or {}).get("frequency")
        be = (les.get("breathingBand") or {}).get("frequency")
        beyond = g is not None and abs(dc) > g
        verdicts.append(beyond)
        lines += ["%s against %s: %.2f against %.2f m/s, C_D0 %.3f against "
                  "%.3f (%+.1f %%%s; the resolution study's GCI %s), Dp/D0 "
                  "%.3f against %.3f, the breathing's largest peak above "
                  "St 0.1 at %s against %s. The change is %s the GCI." % (
                      les_run.ident, lam_run.ident, ve["mean"], vl["mean"],
                      ce, cl, 100 * dc,
                      "" if hc is None else ", the pair's combined interval "
                      "± %.1f %%: %s" % (100 * hc, "told apart"
                                          if abs(dc) > hc else
                                          "not told apart"),
                      "—" if g is None else "%.1f %%" % (100 * g),
                      les["projectedDiameter"]["mean"] / d0,
                      lam["projectedDiameter"]["mean"] / d0,
                      "—" if be is None else "%.3g Hz" % be,
                      "—" if bl is None else "%.3g Hz" % bl,
                      "beyond" if beyond else "inside"), ""]
    if verdicts:
        lines += ["By issue 34's rule (LES the default where it changes the "
                  "answer beyond the GCI): %s." % (
                      "a pair moves C_D0 beyond the resolution study's GCI, "
                      "so LES is to be the tutorials' default"
                      if any(verdicts) else
                      "no pair moves C_D0 beyond the resolution study's "
                      "GCI, so the tutorials stay laminar"), ""]
    return lines


# What a study's numbers cannot yet be trusted for, found by a later study;
# printed with the study's section, its converged values and the main job's
# summary line
STUDY_CAVEATS = {
    "resolution7ftDamped": "it is read over 10-40 s, over which the "
    "12- and 18-cell levels still slow (over 40-80 s, study "
    "levels7ftDamped, which the 7 ft summaries compare with, the three "
    "levels give C_D0 0.851, 0.898 and 0.859 against 0.768, 0.839 and "
    "0.894 here); its finest level is 27 cells across D0, and its "
    "observed order in C_D0 (0.66) is below the IB forcing's formal first "
    "order, so the extrapolation (1.07) lies far beyond the finest level",
    "levels7ftDamped": "its finest level is 27 cells across D0 (the "
    "40-cell level, 7ft-cpd40-narrow-damped-40s, is not complete); its "
    "levels converge oscillatorily, so the GCI is Roache's bound (safety "
    "factor 3 with the IB forcing's formal first order), and their "
    "spread is of the size of a 40 s window's statistical uncertainty "
    "(the 18- and 27-cell levels differ by 4.5 % in C_D0 against a "
    "combined 95 % interval of ±4.6 %); the main job is read over 30-70 "
    "s, this study over 40-80 s",
    "resolution7ftMarkerHalf": "its levels are the tutorial's before "
    "nylon's damping (the damped tutorial's levels are study "
    "resolution7ftDamped, which the 7 ft summaries compare with), its "
    "finest level is 27 cells across D0 "
    "(the 40-cell level on the narrow refinement, about 9 hours on 2 "
    "cores, is not complete), and its levels converge oscillatorily in C_D0 "
    "and the descent, so the GCI is Roache's bound (safety factor 3 with "
    "the IB forcing's formal first order), not an observed order",
    "resolution7ftUndampedContinued": "its levels (12, 18 and 27 cells "
    "across D0) continue the damped runs' inflated canopies at 15 s "
    "without the hinge dashpots, as the tutorial descends after 2 s, and "
    "are read over 3-8 s of the continuation; their markers are a cell "
    "apart, where the tutorial's are half a cell apart (study "
    "resolution7ftMarkerHalf restates the value for the tutorial as it "
    "is)",
    "resolution7ft": "its runs are read over 5-12 s: on 18 cells that "
    "stands for the steady descent (C_D0 0.674 over 5-12 s, 0.684 over "
    "30-43.9 s in 7ft-cpd18-45s), on 12 cells it is a transient (the "
    "descent falls from 6.0 to 4.8 m/s inside it and levels at 5.1-5.4 "
    "m/s, C_D0 0.93, from 12 s), so the 12-cell level and the observed "
    "order are not to be trusted, and the 40-cell level is not run",
    "resolution7ftStiff": "its runs are read over 5-8 s, a transient: on 18 "
    "cells the descent rises from 5.32 m/s over 5-8 s to 5.73 at 12 s "
    "(7ft-cpd18-tol1e-3-relax1), and on 12 cells the wake's symmetry "
    "breaks at about 9 s (over 10-38 s the 12-cell C_D0 was 0.95 +- 0.08: "
    "study tolerance7ftLong), so the levels' transients, not their "
    "steady states, are compared; the coupling's tolerance no longer "
    "matters (on 18 cells C_D0 0.924 at 5e-3 and 0.920 at 1e-3 over 5-8 "
    "s with the stabiliser's filter, where the earlier scheme gave 0.71 "
    "and 0.80): run the levels long enough for a steady state "
    "(study resolution7ftLong)",
    "resolution7ftCells": "its levels run from rest to 15 s and are read "
    "over 10-15 s, a window of about 7 breathing periods after the "
    "descent's dip at 8-10 s (on the main job's set-up the 2 s means "
    "stay within 5.36-5.54 m/s over 10-40 s, 7ft-default-40s); the "
    "40-cell level (about 1.7 million cells, several hours on 2 cores) "
    "is not yet run, so the finest level is 27 cells across D0",
    "resolution7ftMapped": "its levels continue one 18-cell run's state at "
    "10 s and are read over 2-4 s (the 27-cell level's start transient "
    "lasts 2 s), with the cloth's edge at 0.044 m where the tutorial's is "
    "0.148 m; from rest the descent drifts for tens of seconds (on 18 "
    "cells the 0.066 m cloth gives C_D0 0.835 over 8-12 s, 0.738 over "
    "10-40 s), so the levels share a window that has not settled",
    "resolutionT10Mapped": "its levels (163 kg on the guide wire) "
    "continue one 13-cell run's state at 80 s and are read over 2-12 s, "
    "with the cloth's edge at 0.446 m where the tutorial's is 1.03 m at 13 "
    "cells; the levels converge slowly (observed order 0.7 in C_D0), so "
    "the extrapolation is far from the finest level; they were made "
    "before the coupling's acceleration iterated on the stabiliser's "
    "balance (which changes the iterations, not the converged step); the "
    "breathing is not converged (0.18 and 0.21 Hz at 13 and 20 cells, no "
    "peak resolved at 30)",
    "resolutionT10KernelMarkerHalf": "its levels (163 kg on the guide "
    "wire) continue one 13-cell run's state at 80 s (made on the T-10's "
    "earlier coupling, its markers a cell apart) and are read over 2-12 s, "
    "with the cloth's edge at 0.446 m where the tutorial's is 1.03 m at 13 "
    "cells; each level still slows across its window (by 0.2-0.4 m/s), so "
    "the bound is the mesh's over this window, not the steady descent's; "
    "the observed order (about 7) lies outside [0.5, 3], so the GCI takes "
    "the safety factor 3 with the formal first order",
    "resolutionT10": "its runs converged the coupling to 5e-3 only, which "
    "on the 7 ft canopy's finer levels is not converged (study "
    "relaxation7ft), and whether their wake's symmetry had broken in the "
    "interval read is not checked (study tolerance7ftLong): re-run the "
    "levels with the coupling converged",
}


# Studies whose converged values are read over a common window other
# than their runs' intervals (over_window): the mapped 7 ft levels after
# the 27-cell level's start transient
CONVERGED_WINDOWS = {"resolution7ftMapped": (2.0, 4.0)}


def study_caveat(study):
    """The study's caveat (STUDY_CAVEATS), or None."""
    return STUDY_CAVEATS.get(study)


def study_levels(results):
    """The levels of a resolution study: its runs less those another of its
    runs continues (rest_state_of: a study of levels continuing one source
    also lists the source, for its table; levels that each continue their
    own source, not listed, are all kept)."""
    sources = set(r.rest_state_of for r, _ in results)
    return [(r, rec) for r, rec in results if r.ident not in sources]


def study_fineness(study, runs):
    """What a study refines, as resolution_estimates' fineness: None (cells
    across D0) when its runs differ in cells, the fabric edge's inverse in
    finest cells when they share the cells and differ in edge (the edge
    studies); a study whose runs share both refines neither, and is
    refused (SystemExit naming it)."""
    cells = {cells_per_diameter(r) for r in runs}
    if len(cells) > 1:
        return None
    if len({fabric_edge_cells(r) for r in runs}) > 1:
        return lambda run: 1.0 / fabric_edge_cells(run)
    raise SystemExit("canopy-validate: %s is not a resolution study: its "
                     "runs share the cells across D0 and the fabric's edge"
                     % study)


def converged(study):
    """The converged values of a resolution study, for the benchmarks: a
    dict {quantity: {finest, extrapolated, gci, kind, runs}} from the
    committed records in docs/validation/runs (resolution_estimates); the finest run's value is the
    estimate, the GCI its uncertainty."""
    ids = dict((s[0], s[2]) for s in STUDIES).get(study)
    if ids is None:
        raise SystemExit("canopy-validate: unknown study '%s'" % study)
    results = study_levels([(RUN_BY_ID[i],
                             archive.load(paths.ARCHIVE_DIR, RUN_BY_ID[i])[0])
                            for i in ids])
    if study in CONVERGED_WINDOWS:
        results = over_window(results, *CONVERGED_WINDOWS[study])
    done, table = resolution_estimates(results, study_fineness(
        study, [RUN_BY_ID[i] for i in ids]))
    if not table:
        raise SystemExit("canopy-validate: %s needs three complete runs, "
                         "has %d" % (study, len(done)))
    return {key: {"finest": f[0], "extrapolated": out["extrapolated"],
                  "gci": out["gci"], "kind": out["kind"],
                  "runs": [r.ident for _, r in done],
                  "caveat": study_caveat(study)}
            for key, (f, out) in table.items() if out is not None}


def plot_study(name, title, runs_results, reference_lines=()):
    """Each run's descent speed over time, with reference lines."""
    return plot_series(name, title, runs_results, "descentSeries",
                       "descent speed [m/s]", reference_lines)


def plot_series(name, title, runs_results, key, ylabel, reference_lines=(),
                label=lambda run: run.label, title_size=None):
    """One series of the records' analyses (key: descentSeries or
    swingSeries) against time for each run that holds it, in
    FIG_DIR/name.png; its path relative to the report, or None when no run
    has it."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(paths.FIG_DIR, exist_ok=True)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    drawn = 0
    for run, rec in runs_results:
        series = rec and rec["analysis"] and rec["analysis"].get(key)
        if not series:
            continue
        ax.plot(series["t"], series["v"], lw=1.1, label=label(run))
        drawn += 1
    for value, text, style in reference_lines:
        ax.axhline(value, color="k", ls=style, lw=1, label=text)
    if not drawn:
        plt.close(fig)
        return None
    ax.set_xlabel("time [s]")
    ax.set_ylabel(ylabel)
    if title_size is None:
        ax.set_title(title)
    else:
        ax.set_title(title, fontsize=title_size)
    return save_figure(fig, ax, name)


def skirt_t10_lines(results):
    """Study skirtT10: the seed's paraboloid against the extended skirt,
    each run's descent, C_D0 and Dp/D0 with the change, as lines."""
    got = {run.ident: rec["analysis"] for run, rec in results
           if rec is not None and rec["complete"]
           and rec["analysis"] is not None}
    lines = ["The seed modelled the T-10 as a paraboloid whose skirt is the "
             "nominal diameter, 10.7 m across (seed 000 eq. 5.4, Table "
             "5.2). The T-10 is an extended-skirt canopy (Mills "
             "Manufacturing, \"T-10 series characteristics\"): a band "
             "3 ft (0.914 m) long turns its skirt inwards to a hem 24.5 ft "
             "(7.47 m) across, where the lines attach (globalsecurity.org, "
             "\"T-10 Parachute\": \"nominal diameter is 35 feet (measured 3 "
             "feet up from the skirt) and 24.5 feet at the skirt\"). "
             "T10-m163-skirt builds that band (libcanopy's circular "
             "builder, `canopy.extendedSkirt`) below the tutorial's 1.6 m "
             "paraboloid, whose rim (8.688 m) keeps the nominal area of "
             "89.92 m^2 (the cloth's with the vent's); everything else is "
             "the tutorial's.", ""]
    a, b = got.get("T10-m163-w8"), got.get("T10-m163-skirt")
    if a is None or b is None:
        return lines + ["Needs both runs complete.", ""]
    def row(x):
        v = x["descentVelocity"]
        return (v["mean"], v.get("ci95", float("nan")),
                x["dragCoefficient"]["weightBalance"],
                x["projectedDiameter"]["mean"]
                / x["parameters"]["nominalDiameter"]["value"])
    va, ca, cda, dpa = row(a)
    vb, cb, cdb, dpb = row(b)
    lines += ["| canopy | descent [m/s] (95 %) | C_D0 | Dp/D0 |",
              "|---|---|---|---|",
              "| seed's paraboloid (T10-m163-w8) | %.2f ± %.2f | %.3f | "
              "%.3f |" % (va, ca, cda, dpa),
              "| extended skirt (T10-m163-skirt) | %.2f ± %.2f | %.3f | "
              "%.3f |" % (vb, cb, cdb, dpb), "",
              "The narrower hem closes the canopy's mouth: C_D0 changes by "
              "%+.0f %% and Dp/D0 from %.3f to %.3f, towards the published "
              "0.73 (Mills) and the C_D0 of 0.56-0.66 that the published "
              "descent rates imply at 163 kg (below); the descent changes "
              "by %+.2f m/s against the runs' combined 95 %% interval of "
              "±%.2f. Both are at the tutorial's 11 cells across D0; the "
              "extended skirt's domain and resolution studies are "
              "domainT10Skirt and resolutionT10Skirt."
              % (100 * (cdb - cda) / cda, dpa, dpb, vb - va,
                 math.hypot(ca, cb)), ""]
    return lines


def payload_scaling(runs_results):
    """Terminal velocity against total mass with V ∝ sqrt(M) (seed eq. 5.6)
    through the lightest complete run, each run's C_D0, and the exponent n
    of a least-squares fit V ∝ M^n (1/2 at a constant C_D0): lines for the
    markdown."""
    pts = [(rec["analysis"]["parameters"]["totalMass"]["value"],
            rec["analysis"]["descentVelocity"]["mean"], run, rec)
           for run, rec in runs_results
           if rec is not None and rec["analysis"] is not None]
    if len(pts) < 2:
        return ["Fewer than two complete runs: no scaling comparison yet."]
    pts.sort(key=lambda p: p[0])
    M0, V0, _, _ = pts[0]
    lines = ["| run | total mass [kg] | V [m/s] (95 % interval; interval) "
             "| V0 sqrt(M/M0) [m/s] | difference | C_D0 (weight) |",
             "|---|---|---|---|---|---|"]
    for M, V, run, rec in pts:
        pred = V0 * math.sqrt(M / M0)
        a = rec["analysis"]
        s = a["steady"]
        ci = a["descentVelocity"].get("ci95")
        stopped = ("" if rec["complete"] else
                   "; the run stopped at %.2f s" % a["timeEnd"])
        lines.append("| %s | %.1f | %.2f%s (%.3g–%.3g s%s) | %.2f | %+.0f %% "
                     "| %s |"
                     % (run.ident, M, V, " ± %.2f" % ci if ci else "",
                        s["start"], s["end"], stopped, pred,
                        100 * (V - pred) / pred,
                        _f(a["dragCoefficient"].get("weightBalance"),
                           "%.3f")))
    logm = [math.log(p[0]) for p in pts]
    logv = [math.log(p[1]) for p in pts]
    mm, mv = sum(logm) / len(pts), sum(logv) / len(pts)
    n = (sum((x - mm) * (y - mv) for x, y in zip(logm, logv))
         / sum((x - mm) ** 2 for x in logm))
    lines += ["", "Least-squares fit V ∝ M^n over the %d runs: n = %.3f "
              "(1/2 at a constant C_D0; n < 1/2: C_D0 grows with the "
              "payload)." % (len(pts), n)]
    return lines


# The seed's G-11 descent speed, for the studies' plots
G11_SEED_REF = [(3.0, "seed Fig. 6.2: about 3 m/s", "--")]


NOT_BUILT = ["(build/canopy/bin/canopy-tests is not built: run "
             "./Allwmake first)"]


def canopy_tests_output(*names):
    """The standard output of libcanopy's tests (all, or those named), or
    None when they are not built."""
    exe = os.path.join(paths.TOP, "build", "canopy", "bin", "canopy-tests")
    if not os.access(exe, os.X_OK):
        return None
    return subprocess.run([exe, *names], capture_output=True,
                          text=True).stdout


def structure_studies():
    """The libcanopy test output of the structure-alone studies."""
    out = canopy_tests_output()
    if out is None:
        return NOT_BUILT
    keep, lines = False, []
    for line in out.splitlines():
        if line.startswith("Delta E / E0") or line.startswith("Model-I") \
                or line.startswith("m = "):
            keep = True
        if keep:
            lines.append(line)
        if line.startswith("PASS energy_table") or \
                line.startswith("PASS drum_spectrum"):
            keep = False
    return lines


def hinge_damping_scale(
        test="bending_damping_falls_as_the_fourth_power_of_the_scale"):
    """The libcanopy test output on how the hinge dashpots damp a smooth
    bending against the flapping of single triangles."""
    out = canopy_tests_output(test)
    if out is None:
        return NOT_BUILT
    return [line.strip() for line in out.splitlines()
            if line.startswith("  ") or line.startswith("PASS") or
            line.startswith("FAIL")]


def plot_structure(lines):
    """Plots of the structure-alone studies from the canopy-tests lines:
    seed Table 5.1's energy change, the drum spectrum's cut-off (seed Fig.
    5.4) and the eigen-frequency bounds (seed ch. 3). Returns the figure's
    path relative to the report, or None when the lines hold no data."""
    import re
    energy = {}     # scheme -> [(N, measured, predicted, seed or nan)]
    drum = []       # (m, cut-off, seed cut-off, strongest peak, above ratio)
    bounds = []     # (model, largest omega, bound)
    for line in lines:
        m = re.match(r"\s+\w+ order \((\w[\w-]*)\)\s+N=(\d+)\s+(\S+) \|\s+(\S+) \|"
                     r"\s+(\S+)", line)
        if m:
            try:
                seed = float(m.group(5))    # "inf": the seed's overflow
            except ValueError:
                seed = float("nan")
            if math.isinf(seed):
                seed = float("nan")
            energy.setdefault(m.group(1), []).append(
                (int(m.group(2)), float(m.group(3)), float(m.group(4)), seed))
            continue
        m = re.match(r"m = ([\d.]+): cut-off ([\d.]+) Hz \(seed ([\d.]+)\);"
                     r".*strongest peak ([\d.]+) Hz; largest magnitude above"
                     r" cut-off ([\d.]+)", line)
        if m:
            drum.append(tuple(float(g) for g in m.groups()))
            continue
        m = re.match(r"(Model-I+)\s*: .*largest omega ([\d.]+) rad/s.*"
                     r"bound [^=]+= ([\d.]+)", line)
        if m:
            bounds.append((m.group(1), float(m.group(2)), float(m.group(3))))
    if not energy and not drum:
        return None
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(paths.FIG_DIR, exist_ok=True)
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    ax = axes[0]
    for scheme, rows in sorted(energy.items()):
        rows.sort()
        N = [r[0] for r in rows]
        line, = ax.loglog(N, [abs(r[2]) for r in rows], "-", lw=1,
                          label="%s: χ^(2N) − 1" % scheme)
        ax.loglog(N, [abs(r[1]) for r in rows], "o", color=line.get_color(),
                  mfc="none", label="%s: measured" % scheme)
        seeds = [(r[0], abs(r[3])) for r in rows if r[3] == r[3]]
        if seeds:
            ax.loglog(*zip(*seeds), "x", color=line.get_color(),
                      label="%s: seed Table 5.1" % scheme)
    ax.set_ylim(1e-7, 1e20)
    ax.set_xlabel("steps N at ω·Δt = 0.1")
    ax.set_ylabel("|ΔE / E0|")
    ax.set_title("Energy change (seed Table 5.1)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, ncol=1)
    ax = axes[1]
    if drum:
        x = np.arange(len(drum))
        ax.bar(x - 0.2, [d[1] for d in drum], 0.4, label="cut-off √(7k/m)/2π")
        ax.bar(x + 0.2, [d[3] for d in drum], 0.4,
               label="strongest peak of the spectrum")
        for i, d in enumerate(drum):
            ax.text(i, max(d[1], d[3]) * 1.03, "above cut-off:\n%.1g of peak"
                    % d[4], ha="center", fontsize=7)
        ax.set_xticks(x)
        ax.set_xticklabels(["m = %g" % d[0] for d in drum])
        ax.set_ylabel("frequency [Hz]")
        ax.set_ylim(0, max(d[1] for d in drum) * 1.35)
        ax.legend(fontsize=7, loc="upper left")
    ax.set_title("Drum spectrum, k = 1000 (seed Fig. 5.4)")
    ax = axes[2]
    if bounds:
        x = np.arange(len(bounds))
        ax.bar(x - 0.2, [b[1] for b in bounds], 0.4,
               label="largest eigen-frequency")
        ax.bar(x + 0.2, [b[2] for b in bounds], 0.4, label="seed bound")
        ax.set_xticks(x)
        ax.set_xticklabels([b[0] for b in bounds])
        ax.set_ylabel("ω [rad/s]")
        ax.legend(fontsize=7, loc="lower right")
    ax.set_title("Eigen-frequency bounds (seed ch. 3)")
    fig.tight_layout()
    path = os.path.join(paths.FIG_DIR, "structure.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return os.path.relpath(path, os.path.dirname(paths.DOC))


def resolution_cells_lines():
    """The section on the 7 ft tutorial's resolution as it is (the study
    the 7 ft reference names, report.py's convergedStudy): each level's
    numbers, the converged C_D0 with its GCI, the main job's error against
    it and the handbook's range, from the committed records."""
    study = rep.REFERENCES["7ft"]["convergedStudy"]
    titles = dict((st[0], st[1]) for st in STUDIES)
    ids = dict((st[0], st[2]) for st in STUDIES).get(study)
    if ids is None or any(i not in RUN_BY_ID for i in ids):
        return []
    md = ["## The 7 ft canopy's resolution on the tutorial", "",
          "Study %s (the levels the 7 ft summaries compare with, report.py's "
          "convergedStudy): %s. `bin/canopy-validate run <id>` for each "
          "run; `bin/canopy-validate converged %s` prints the GCI.%s"
          % (study, titles[study], study,
             " Its caveat: %s." % study_caveat(study)
             if study_caveat(study) else ""), "",
          "| run | cells across D0 | cells | descent [m/s] | C_D0 | Dp/D0 "
          "| it./step | wall time [min] |",
          "|---|---|---|---|---|---|---|---|"]
    for ident in ids:
        rec = archive.load(paths.ARCHIVE_DIR, RUN_BY_ID[ident])[0]
        if rec is None or not rec.get("complete") or not rec["analysis"]:
            run = RUN_BY_ID[ident]
            state = run_state(run)
            where = ("stopped at t = %s s" % last_time(run.case_dir)
                     if state == "stopped" else state if state in
                     ("running",) else "not run")
            md.append("| %s | %g | - | %s | - | - | - | - |"
                      % (ident, cells_per_diameter(run), where))
            continue
        a = rec["analysis"]
        v = a["descentVelocity"]
        md.append("| %s | %g | %d | %.3f ± %.3f | %.3f | %.3f | %.2f | %.1f |"
                  % (ident, cells_per_diameter(RUN_BY_ID[ident]),
                     rec["cells"], v["mean"], v["ci95"],
                     a["dragCoefficient"]["weightBalance"],
                     a["projectedDiameter"]["mean"]
                     / a["parameters"]["nominalDiameter"]["value"],
                     a["coupling"]["meanIterations"], rec["wall"] / 60))
    md.append("")
    try:
        c = converged(study)
    except SystemExit as e:
        return md + [str(e) + ".", ""]
    cd = c["C_D0 (weight)"]
    job = archive.load(paths.ARCHIVE_DIR, RUN_BY_ID[MAIN_JOB_RUN])[0]
    if job is None or not job.get("complete") or not job["analysis"]:
        main_job = "The main job (run %s) has no complete record yet." % (
            MAIN_JOB_RUN)
    else:
        job_cd = job["analysis"]["dragCoefficient"]["weightBalance"]
        main_job = ("The main job's C_D0 (run %s, over %g-%g s) is %.3f, "
                    "%+.1f %% from it (within 5 %%: %s)." % (
                        MAIN_JOB_RUN, RUN_BY_ID[MAIN_JOB_RUN].steady_start,
                        RUN_BY_ID[MAIN_JOB_RUN].steady_end, job_cd,
                        100 * (job_cd / cd["finest"] - 1),
                        "yes" if abs(job_cd / cd["finest"] - 1) <= 0.05
                        else "no"))
    md += ["The converged C_D0 is the finest level's, %.3f ± %.1f %% "
           "(Roache's GCI, %s; extrapolated %.3f); the descent %.3f m/s ± "
           "%.1f %% (%s), Dp/D0 %.3f ± %.1f %% (%s). %s Knacke's flat circular canopies "
           "(Parachute Recovery Systems Design Manual, NWC TP 6575, Table 5-1) "
           "have "
           "C_D0 0.75-0.80 and Dp/D0 0.67-0.70: the converged C_D0 is "
           "%+.0f %% from the range's middle, while the canopy is more "
           "open (%.2f D0). Small flat circular models held in an open "
           "wind tunnel give C_D ≈ 0.85 above 6 m/s, with longer lines "
           "raising it (Vu, Le and Tran, JST: Smart Systems and Devices "
           "31(2), 2021, 67-74; the value as its abstract states it, the "
           "reference area not given there). The seed's drop test, 4.27 "
           "m/s, implies C_D0 ≈ 1.35 (tutorials/parachutes/flatCircular7ft/"
           "README.md)."
           % (cd["finest"], 100 * cd["gci"], cd["kind"],
              cd["extrapolated"], c["descent speed [m/s]"]["finest"],
              100 * c["descent speed [m/s]"]["gci"],
              c["descent speed [m/s]"]["kind"],
              c["Dp/D0"]["finest"], 100 * c["Dp/D0"]["gci"],
              c["Dp/D0"]["kind"], main_job,
              100 * (cd["finest"] / 0.775 - 1), c["Dp/D0"]["finest"]), ""]
    return md


# The 7 ft runs on the tutorial's coupling (the load from the cells, the
# stabiliser's balance seen through the kernel) whose breathing the
# section below sets against the cloth's edge and the hinge dashpots
BREATHING_CLOTH_RUNS = ("7ft-cpd12-15s", "7ft-default", "7ft-cpd27-15s",
                        "7ft-cpd12-bend0-15s", "7ft-default-bend0-15s",
                        "7ft-cpd27-bend0-15s", "7ft-cpd12-bend0-cont",
                        "7ft-cpd18-bend0-cont", "7ft-cpd27-bend0-cont",
                        "7ft-cpd12-until2-15s", "7ft-cpd18-until2-15s",
                        "7ft-cpd27-until2-15s",
                        "7ft-mapped-cells-cpd18",
                        "7ft-mapped-cells-cpd27", "7ft-mapped-cells-cpd40")


def breathing_cloth_lines():
    """The 7 ft canopy's breathing against the cloth's edge and the hinge
    dashpots (BREATHING_CLOTH_RUNS), from the committed records, as a
    markdown section."""
    rows = []
    for ident in BREATHING_CLOTH_RUNS:
        run = RUN_BY_ID.get(ident)
        rec = run and archive.load(paths.ARCHIVE_DIR, run)[0]
        if not rec or not rec.get("complete") or not rec.get("analysis"):
            continue
        a = rec["analysis"]
        d0 = a["parameters"]["nominalDiameter"]["value"]
        cpd = cells_per_diameter(run)
        b = a.get("breathingBand") or {}
        breathing = ("%.2f | %.1f | %.2f | %.1f" % (
            b["frequency"], 100 * b["amplitude"], b["strouhal"],
            b["periods"]) if b.get("resolved") else "none resolved | | |")
        until = run_setting(run, PROPS, "fabric/bendingDampingUntil")
        dashpots = "%g%s" % (run_setting(run, PROPS, "fabric/bendingDamping"),
                             " until %g s" % until if until is not None
                             else "")
        rows.append("| %s | %g | %.3f (%.2f) | %s | %g-%g s | %s | %.3f | "
                    "%.3f |" % (ident, cpd, fabric_edge_cells(run) * d0 / cpd,
                                fabric_edge_cells(run),
                                dashpots, run.steady_start,
                                run.steady_end, breathing,
                                a["dragCoefficient"]["weightBalance"],
                                a["projectedDiameter"]["mean"] / d0))
    if not rows:
        return []
    return [
        "## The 7 ft canopy's breathing against the cloth's edge and the "
        "hinge dashpots", "",
        "The runs on the tutorial's coupling (the load from the cells, the "
        "stabiliser's balance seen through the kernel): the largest peak of "
        "the projected diameter's spectrum at or above St = f Dp / V = 0.1 "
        "over each run's interval (the amplitude is the peak's, in the "
        "diameter), against the air's resolution, the cloth's edge and the "
        "hinge dashpots' rate (fabric.bendingDamping). The mapped runs "
        "continue 7ft-cpd18-cloth0.044-10s (study resolution7ftMappedCells) "
        "and are read over 2-5 s after the mapping.", "",
        "| run | cells across D0 | fabric edge [m] (finest cells) | hinge "
        "dashpots [1/s] | interval | breathing [Hz] | amplitude [cm] | St | "
        "periods | C_D0 | Dp/D0 |",
        "|---|---|---|---|---|---|---|---|---|---|---|"] + rows + [""] + \
        BREATHING_CLOTH_PROSE


def previous_sections():
    """{study title: its lines} of the report as it is now (the sections
    between '## ' headings, the structure section excluded)."""
    try:
        with open(paths.DOC) as f:
            lines = f.read().split("\n")
    except OSError:
        return {}
    sections, title = {}, None
    for line in lines:
        if line.startswith("## "):
            title = line[3:].strip()
            sections[title] = []
        if title is not None:
            sections[title].append(line)
    for title, body in sections.items():
        while body and (not body[-1].strip() or
                        body[-1].startswith("(This section is kept")):
            body.pop()
        body.append("")
    return sections
