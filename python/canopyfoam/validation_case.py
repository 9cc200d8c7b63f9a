"""validation_case.py — a validation run's case directory: its state (missing, running, stopped, failed, complete), solver log, latest time, wall time and the code version it ran with."""

import os
import re
import subprocess

from . import validation_paths as paths


def solver_log(case_dir):
    return os.path.join(case_dir, "log.canopyPimpleFoam")


def last_time(case_dir):
    """The solver log's last 'Time = ' ('?' without one)."""
    t = "?"
    try:
        with open(solver_log(case_dir), errors="replace") as f:
            for line in f:
                if line.startswith("Time = "):
                    t = line.split()[2]
    except OSError:
        pass
    return t


def report_json(case_dir):
    return os.path.join(case_dir, "postProcessing", "report", "report.json")


def running_file(case_dir):
    """Holds the process id of the canopy-validate that runs the case."""
    return os.path.join(case_dir, "validation-running")


def running_pid(case_dir):
    """The id of the live canopy-validate process running the case, or
    None (no file, or its process has gone: killed with its session)."""
    try:
        with open(running_file(case_dir)) as f:
            pid = int(f.read().split()[0])
        os.kill(pid, 0)
    except (OSError, ValueError, IndexError):
        return None
    return pid


def stopped_file(case_dir):
    """Marks a run whose canopy-validate was stopped (Ctrl-C, SIGTERM) to
    be continued later with --continue."""
    return os.path.join(case_dir, "validation-stopped")


def run_state(run):
    """'complete', 'running' (its canopy-validate process is alive),
    'stopped' (its canopy-validate was stopped, or killed with its session,
    before the solver ended: --continue goes on with it), 'failed' (a
    solver log without End) or 'missing'."""
    log = solver_log(run.case_dir)
    if not os.path.exists(log):
        return "missing"
    if running_pid(run.case_dir) is not None:
        return "running"
    if os.path.exists(stopped_file(run.case_dir)) or \
            os.path.exists(running_file(run.case_dir)):
        return "stopped"
    with open(log, errors="replace") as f:
        ended = any(line.startswith("End") for line in f)
    if ended and os.path.exists(report_json(run.case_dir)):
        return "complete"
    return "failed"


def foam_get(path, entry):
    out = subprocess.run(["foamDictionary", "-entry", entry, "-value", path],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError("%s has no entry %s: %s"
                           % (path, entry, out.stderr.strip()))
    return out.stdout.strip()


def wall_time(case_dir):
    path = os.path.join(case_dir, "validation-wall-time")
    try:
        with open(path) as f:
            wall, ranks = f.read().split()
        return float(wall), int(ranks)
    except (OSError, ValueError):
        return None, None


def code_version():
    """git describe of the working tree (with -dirty), or 'unknown'."""
    out = subprocess.run(["git", "-C", paths.TOP, "describe", "--always",
                          "--dirty"], capture_output=True, text=True)
    return out.stdout.strip() if out.returncode == 0 else "unknown"


def record_code_version(case_dir, resume):
    """Write the code version a run starts with; a continued run keeps
    the versions it ran with before and adds this one when it differs
    ('a, continued with b')."""
    path = os.path.join(case_dir, "validation-code-version")
    version = code_version()
    if resume:
        before = run_code_version(case_dir)
        if before != "unrecorded":
            if before.split(", continued with ")[-1] == version:
                return
            version = "%s, continued with %s" % (before, version)
    with open(path, "w") as f:
        f.write(version + "\n")


def run_code_version(case_dir):
    """The code version a run was made with ('unrecorded' for runs made
    before versions were recorded)."""
    try:
        with open(os.path.join(case_dir, "validation-code-version")) as f:
            return f.read().strip() or "unrecorded"
    except OSError:
        return "unrecorded"


def cell_count(case_dir):
    try:
        with open(os.path.join(case_dir, "constant", "polyMesh", "owner"),
                  "rb") as f:
            m = re.search(rb"nCells:\s*(\d+)", f.read(2048))
        return int(m.group(1)) if m else None
    except OSError:
        return None
