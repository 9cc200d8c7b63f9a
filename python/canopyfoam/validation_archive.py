"""validation_archive.py — the committed record of each validation run's result (docs/validation/runs/<run id>.json), so that docs/validation.md can be rewritten on a machine that has not made every run.

A record holds what the report needs of one run: its state, the analysis
of bin/canopy-report (JSON-ready, without the private time series) plus
the descent speed against time thinned to at most SERIES_POINTS points for
the study plots, its wall time, ranks, cell count and the code version it
ran with. It also holds the run's definition (tutorial, Allrun options,
dictionary edits, reference, steady interval): a record whose definition
differs from the current one is stale and is not used.
"""

import json
import math
import os

import numpy as np

SERIES_POINTS = 400
FORMAT = 1


def definition(run):
    """What makes a run: a record of another definition is stale."""
    return {"tutorial": run.tutorial,
            "options": list(run.options),
            "edits": [list(e) for e in run.edits],
            "reference": run.reference,
            "steadyStart": run.steady_start,
            "steadyEnd": run.steady_end}


def record_path(archive_dir, ident):
    return os.path.join(archive_dir, ident + ".json")


def _round(x, digits=6):
    """x to `digits` significant digits (None for NaN and infinities)."""
    x = float(x)
    if not math.isfinite(x):
        return None
    return float("%.*g" % (digits, x))


def thin_series(t, v, points=SERIES_POINTS):
    """{"t": [...], "v": [...]}: at most `points` samples, evenly spread
    over the indices, first and last kept."""
    t = np.asarray(t, dtype=float)
    v = np.asarray(v, dtype=float)
    n = len(t)
    if n == 0:
        return {"t": [], "v": []}
    idx = np.unique(np.round(np.linspace(0, n - 1, min(n, points)))
                    .astype(int))
    return {"t": [_round(x) for x in t[idx]],
            "v": [_round(x) for x in v[idx]]}


def save(archive_dir, run, rec):
    """Write the record of `run` (a dict from validation.record)."""
    os.makedirs(archive_dir, exist_ok=True)
    data = {"format": FORMAT,
            "run": run.ident,
            "label": run.label,
            "definition": definition(run),
            "state": rec["state"],
            "complete": rec["complete"],
            "codeVersion": rec["codeVersion"],
            "wallTime": rec["wall"],
            "ranks": rec["ranks"],
            "cells": rec["cells"],
            "analysis": rec["analysis"]}
    path = record_path(archive_dir, run.ident)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1, sort_keys=True, allow_nan=False)
        f.write("\n")
    os.replace(tmp, path)
    return path


def load(archive_dir, run):
    """(record, None) from the archive, or (None, why not)."""
    path = record_path(archive_dir, run.ident)
    if not os.path.exists(path):
        return None, "no record"
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        return None, "unreadable record %s (%s)" % (path, e)
    if data.get("format") != FORMAT:
        return None, "record %s has format %s, not %d" % (
            path, data.get("format"), FORMAT)
    if data.get("definition") != definition(run):
        return None, ("the record in %s is of an earlier definition of the "
                      "run" % os.path.basename(path))
    return {"state": data["state"], "complete": data["complete"],
            "codeVersion": data["codeVersion"], "wall": data["wallTime"],
            "ranks": data["ranks"], "cells": data["cells"],
            "analysis": data["analysis"], "source": "archive"}, None
