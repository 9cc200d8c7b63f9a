"""validation_results.py — a validation run's results read from its case (report.json, solver log, dictionaries) into the record docs/validation/runs/<run id>.json keeps."""

import os

import numpy as np

from . import cloth_stress
from . import forced_turn
from . import load_moment
from . import report as rep
from . import shape
from . import turn_fit
from . import validation_archive as archive
from . import validation_paths as paths
from .validation_runs import (DISC_RETRACTED_RUNS, DISC_TUTORIAL_RUNS,
                              FORCED_HELD, FORCED_TURN,
                              FORCED_TURN_AXIS, FORCED_TURN_START,
                              PIVOT_WIND, PROPS, TILT_T10_SPEED)
from .validation_case import (cell_count, foam_get, last_time,
                              run_code_version, run_state, running_pid,
                              wall_time)


def result(run):
    """The run's analysis (report.analyse) or None, and its state."""
    state = run_state(run)
    if state == "missing" and not os.path.isdir(
            os.path.join(paths.TOP, "tutorials", run.tutorial)):
        return None, ("not run: tutorials/%s is not in this version (see "
                      "tutorials/README.md)" % run.tutorial)
    if state == "missing":
        return None, "not run (`%s`)" % run.command()
    try:
        r = rep.analyse(run.case_dir, reference=run.reference,
                        steady_start=run.steady_start,
                        steady_end=run.steady_end)
    except (rep.ReportError, OSError) as e:
        if run.steady_start is None or state == "complete":
            return None, "%s (%s)" % (state, e)
        # a run that stopped before its steady interval: its last third
        try:
            r = rep.analyse(run.case_dir, reference=run.reference)
        except (rep.ReportError, OSError) as e2:
            return None, "%s (%s)" % (state, e2)
        state += " before its interval (last third shown)"
    if run.ident in PIVOT_WIND:
        try:
            r["turnFit"] = turn_fit.analyse(run.case_dir,
                                            r["steady"]["start"],
                                            r["steady"]["end"],
                                            stabiliser_settings(run))
        except (load_moment.LoadMomentError, rep.ReportError, OSError,
                RuntimeError, np.linalg.LinAlgError) as e:
            r["turnFit"] = {"note": str(e)}
    if run.ident in DISC_RING_RUNS:
        try:
            r["pressureJumpRings"] = pressure_jump_rings(
                run.case_dir, r["steady"]["start"], r["steady"]["end"])
        except (cloth_stress.ClothStressError, shape.ShapeError, OSError,
                ValueError) as e:
            r["pressureJumpRings"] = {"note": str(e)}
    if run.ident == FORCED_HELD:
        try:
            peaks, resolution = forced_turn.wake_peaks(
                run.case_dir, r["steady"]["start"], r["steady"]["end"])
            r["wakePeaks"] = {"peaks": peaks, "resolution": resolution}
        except (rep.ReportError, OSError, ValueError, IndexError) as e:
            r["wakePeaks"] = {"note": str(e)}
    if run.ident in FORCED_TURN:
        amplitude, period = FORCED_TURN[run.ident]
        p = r["parameters"]
        try:
            r["forcedTurn"] = forced_turn.analyse(
                run.case_dir, amplitude, period, FORCED_TURN_START,
                FORCED_TURN_AXIS, r["steady"]["start"], r["steady"]["end"],
                TILT_T10_SPEED, p["nominalDiameter"]["value"],
                p["rho"]["value"])
        except (load_moment.LoadMomentError, OSError,
                np.linalg.LinAlgError) as e:
            r["forcedTurn"] = {"note": str(e)}
    return r, state


# Runs whose record keeps the pressure jump on the cloth by ring (the rigid
# disc's: where on the plate its load lies)
DISC_RING_RUNS = frozenset(r.ident for r in DISC_TUTORIAL_RUNS
                           + DISC_RETRACTED_RUNS)
DISC_RINGS = 20


def pressure_jump_rings(case_dir, t0, t1, rings=DISC_RINGS):
    """The pressure jump canopy.h5 holds (dp, one value a triangle) over
    [t0, t1] as cloth_stress.analyse averages it: per ring of equal width
    in s (the radial position, 0 at the centre, 1 at the rim) the ring's
    mid s and its area-weighted mean jump [Pa], with the cloth's mean and
    the number of states."""
    a = cloth_stress.analyse(case_dir, t0, t1, rings)
    return {"s": [(k + 0.5) / rings for k in range(rings)],
            "dp": [row[5] for row in a["rows"]],
            "mean": a["pressureJump"], "states": a["states"]}


def stabiliser_settings(run):
    """The run's added-mass stabiliser as load_moment.analyse takes it
    ({"mass", "direction"}), None without one; RuntimeError for a kind
    load_moment cannot rebuild (distribution consistent, filter
    triangleMean, balance stepMean)."""
    path = os.path.join(run.case_dir, PROPS)
    try:
        mass = float(foam_get(path, "coupling/addedMass/mass"))
    except RuntimeError:
        return None
    settings = {"mass": mass, "direction": "normal"}
    for entry, default in (("direction", "normal"), ("distribution",
                                                      "lumped"),
                           ("filter", "none"), ("balance", "stepMean")):
        try:
            settings[entry] = foam_get(path, "coupling/addedMass/" + entry)
        except RuntimeError:
            settings[entry] = default
    if settings["distribution"] != "lumped" or settings["filter"] != "none" \
            or settings["balance"] != "endOfStep":
        raise RuntimeError("the added-mass stabiliser's distribution %s / "
                           "filter %s / balance %s: its balance is rebuilt "
                           "from the written (end-of-step) accelerations "
                           "only for lumped, no filter, endOfStep" % (
                               settings["distribution"], settings["filter"],
                               settings["balance"]))
    return {"mass": mass, "direction": settings["direction"]}


def record(run):
    """(record, None) with what the report shows of a run, or (None, why
    not). A run with a case in build/validation is read from it and its
    record written to the archive (docs/validation/runs); a run without
    one is read from the archive."""
    state = run_state(run)
    if state == "running":
        # its record is written when it ends; the archive's, if any, is
        # of an earlier run of the same definition
        return None, "running (`bin/canopy-progress %s %d`)" % (
            run.case_dir, running_pid(run.case_dir))
    if state == "stopped":
        # a part of a run, not a result: no record until it is complete
        return None, "stopped at t = %s s, to be continued (`bin/canopy-" \
            "validate run --continue %s`)" % (last_time(run.case_dir),
                                              run.ident)
    if state == "missing":
        rec, why = archive.load(paths.ARCHIVE_DIR, run)
        if rec is not None:
            return rec, None
        _, text = result(run)
        return None, text if why == "no record" else "%s; %s" % (text, why)
    r, text = result(run)
    analysis = None
    if r is not None:
        analysis = rep.json_ready(r)
        for private in ("caseDir", "files"):    # this machine's paths
            analysis.pop(private, None)
        analysis["descentSeries"] = archive.thin_series(r["_series"].t,
                                                        r["_descent"])
        # the suspension's angle over time where it swings (a run on the
        # guide wire stays within a degree of the vertical)
        if r["_angle"] is not None and \
                np.max(r["_angle"]) > rep.SWING_ONSET_DEG:
            analysis["swingSeries"] = archive.thin_series(r["_series"].t,
                                                          r["_angle"])
    wall, ranks = wall_time(run.case_dir)
    rec = {"state": text, "complete": state == "complete",
           "codeVersion": run_code_version(run.case_dir), "wall": wall,
           "ranks": ranks, "cells": cell_count(run.case_dir),
           "analysis": analysis, "source": "run"}
    archive.save(paths.ARCHIVE_DIR, run, rec)
    return rec, None
