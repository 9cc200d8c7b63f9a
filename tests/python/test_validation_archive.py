"""test_validation_archive.py — the run records of bin/canopy-validate (python/canopyfoam/validation_archive.py): a run read once is reported from its record after its case is gone; a stale record and a missing run are not.

Run as:  /usr/bin/python3 tests/python/test_validation_archive.py
Prints one PASS/FAIL line per check; exits 1 if any fails.

Uses the synthetic run of test_report.py (descent 4 m/s over its last
third, 1200 steps) as the case of a validation run, in a temporary copy of
the report's folders.
"""

import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, HERE)

from canopyfoam import validation_paths as paths  # noqa: E402
from canopyfoam.validation_case import (report_json,  # noqa: E402
                                        run_state, running_file,
                                        solver_log, stopped_file)
from canopyfoam.validation_execute import terminate_tree  # noqa: E402
from canopyfoam.validation_report import write_report  # noqa: E402
from canopyfoam.validation_results import record  # noqa: E402
from canopyfoam.validation_runs import RUN_BY_ID, RUNS, Run  # noqa: E402
from canopyfoam.validation_studies import STUDIES  # noqa: E402
from canopyfoam import validation_archive as archive  # noqa: E402
import test_report as synthetic  # noqa: E402

check = synthetic.check         # PASS/FAIL lines, failures collected in
                                # test_report's list


def make_case(case_dir):
    """A complete run: the synthetic canopy.dat, a solver log ending in
    End, a report.json, a wall time."""
    synthetic.write_dat(os.path.join(case_dir, "postProcessing", "canopy",
                                      "0", "canopy.dat"),
                        synthetic.HEADER, synthetic.steps(1, 1200),
                        synthetic.DOWN)
    with open(os.path.join(case_dir, "log.canopyPimpleFoam"), "w") as f:
        f.write("Time = 12\n\nEnd\n")
    os.makedirs(os.path.dirname(report_json(case_dir)))
    with open(report_json(case_dir), "w") as f:
        f.write("{}\n")
    with open(os.path.join(case_dir, "validation-wall-time"), "w") as f:
        f.write("90.0 2\n")


def use_tmp(tmp):
    """Point the validation module at a scratch report and run folder."""
    paths.RUN_ROOT = os.path.join(tmp, "build", "validation")
    paths.FIG_DIR = os.path.join(tmp, "docs", "validation")
    paths.ARCHIVE_DIR = os.path.join(paths.FIG_DIR, "runs")
    paths.DOC = os.path.join(tmp, "docs", "validation.md")


def test_record_round_trip(tmp):
    run = Run("synthetic", "parachutes/flatCircular7ft", "synthetic run")
    make_case(run.case_dir)
    rec, why = record(run)
    path = archive.record_path(paths.ARCHIVE_DIR, run.ident)
    check("a read run is recorded", rec is not None and os.path.exists(path),
          "record %s, why %s, file %s" % (rec is not None, why, path))
    mean = rec["analysis"]["descentVelocity"]["mean"]
    check("the record holds the analysis", abs(mean - 4.0) < 1e-5,
          "mean descent %.7f m/s (synthetic: 4 - 5.6e-8)" % mean)
    series = rec["analysis"]["descentSeries"]
    check("the descent series is thinned to at most %d points"
          % archive.SERIES_POINTS,
          len(series["t"]) == archive.SERIES_POINTS
          and series["t"][0] == 0.01 and series["t"][-1] == 12.0,
          "%d points from %s to %s s (1200 steps)" % (
              len(series["t"]), series["t"][0], series["t"][-1]))
    text = open(path).read()
    check("the record holds no path of this machine", tmp not in text,
          "%s in the record: %s" % (tmp, tmp in text))

    shutil.rmtree(run.case_dir)
    again, why = record(run)
    check("without its case the run is read from its record",
          again is not None and again["source"] == "archive"
          and again["analysis"]["descentVelocity"]["mean"] == mean
          and again["complete"] and again["wall"] == 90.0
          and again["ranks"] == 2,
          "source %s, mean %s, why %s" % (
              again and again["source"],
              again and again["analysis"]["descentVelocity"]["mean"], why))

    changed = Run("synthetic", "parachutes/flatCircular7ft",
                      "synthetic run", edits=[("constant/canopyProperties",
                                               "payload/mass", "10")])
    stale, why = record(changed)
    check("a record of another definition is not used",
          stale is None and "earlier definition" in why, "why: %s" % why)
    return run


def test_report_keeps_and_rewrites(run):
    missing = Run("never-run", "parachutes/flatCircular7ft",
                      "a run made nowhere")
    RUNS[:] = [run, missing]
    RUN_BY_ID.clear()
    RUN_BY_ID.update({r.ident: r for r in RUNS})
    STUDIES[:] = [
        ("fromRecord", "Study read from its record", ["synthetic"]),
        ("keptStudy", "Study with a run made nowhere", ["never-run"]),
        ("newStudy", "Study new to the report", ["never-run"])]
    os.makedirs(os.path.dirname(paths.DOC), exist_ok=True)
    with open(paths.DOC, "w") as f:
        f.write("# Validation\n\n## Study with a run made nowhere\n\n"
                "| never-run | measured elsewhere: 3.21 ± 0.04 |\n\n"
                "## Study read from its record\n\nold text\n")
    write_report()
    doc = open(paths.DOC).read()
    kept = doc.split("## Study with a run made nowhere")[1].split("## ")[0]
    check("a study with an unrecorded run keeps its previous section",
          "measured elsewhere: 3.21 ± 0.04" in kept
          and "kept from the previous report" in kept
          and "never-run" in kept, kept.strip().replace("\n", " / "))
    fresh = doc.split("## Study read from its record")[1].split("## ")[0]
    check("a study whose runs are recorded is rewritten",
          "old text" not in fresh and "| synthetic |" in fresh
          and "4.00 ± 0.04" in fresh,
          [line for line in fresh.split("\n") if "synthetic" in line][:1])
    new = doc.split("## Study new to the report")[1].split("## ")[0]
    check("a new study lists its missing run with the command",
          "not run (`bin/canopy-validate run never-run`)" in new,
          [line for line in new.split("\n") if "never-run" in line][:1])
    check("the plot of a recorded study is drawn",
          os.path.exists(os.path.join(paths.FIG_DIR, "fromRecord.png")),
          "docs/validation/fromRecord.png")


def test_running_run(tmp):
    """A run whose canopy-validate is alive is 'running' and gets no record
    yet; once its process has gone (killed with its session), or when it
    was stopped (its marker), it is 'stopped', without a record, until
    --continue completes it; a solver log without End and neither file is
    'failed' and is recorded."""
    run = Run("synthetic-running", "parachutes/flatCircular7ft",
                  "synthetic run still going")
    make_case(run.case_dir)
    with open(solver_log(run.case_dir), "w") as f:
        f.write("Time = 6\n")
    with open(running_file(run.case_dir), "w") as f:
        f.write("%d\n" % os.getpid())
    rec, why = record(run)
    path = archive.record_path(paths.ARCHIVE_DIR, run.ident)
    check("a run whose process is alive is running, without a record",
          run_state(run) == "running" and rec is None
          and why.startswith("running") and not os.path.exists(path),
          "state %s, record %s, why %s" % (run_state(run), rec, why))
    gone = subprocess.Popen(["true"])
    gone.wait()
    with open(running_file(run.case_dir), "w") as f:
        f.write("%d\n" % gone.pid)
    rec, why = record(run)
    check("a run whose process has gone is stopped, without a record",
          run_state(run) == "stopped" and rec is None
          and why.startswith("stopped at t = 6 s")
          and not os.path.exists(path),
          "state %s, record %s, why %s" % (run_state(run), rec, why))
    os.remove(running_file(run.case_dir))
    with open(stopped_file(run.case_dir), "w") as f:
        f.write("stopped\n")
    check("a run marked stopped is stopped",
          run_state(run) == "stopped", "state %s" % run_state(run))
    os.remove(stopped_file(run.case_dir))
    rec, why = record(run)
    check("a solver log without End and no marker: failed, recorded",
          run_state(run) == "failed" and rec is not None
          and not rec["complete"] and os.path.exists(path),
          "state %s, record %s" % (run_state(run), rec is not None))
    os.remove(path)
    shutil.rmtree(run.case_dir)


def test_terminate_tree():
    """terminate_tree stops a process and its descendants: a shell whose
    two children sleep (as Allrun's mpirun and ranks would run)."""
    shell = subprocess.Popen(["bash", "-c", "sleep 60 & sleep 60 & wait"])
    import time
    time.sleep(0.3)
    kids = [int(p) for p in subprocess.run(
        ["pgrep", "-P", str(shell.pid)], capture_output=True,
        text=True).stdout.split()]
    terminate_tree(shell.pid)
    shell.wait(timeout=10)
    time.sleep(0.3)
    alive = [k for k in kids if os.path.exists("/proc/%d" % k)
             and open("/proc/%d/stat" % k).read().rsplit(")", 1)[1].split()[0]
             != "Z"]
    check("terminate_tree: the shell and its children end",
          len(kids) == 2 and not alive,
          "children %s, still alive %s" % (kids, alive))


def main():
    tmp = tempfile.mkdtemp(prefix="canopy-validation-archive-")

    def body():
        use_tmp(tmp)
        run = test_record_round_trip(tmp)
        test_running_run(tmp)
        test_terminate_tree()
        test_report_keeps_and_rewrites(run)
    return synthetic.run_checks(tmp, body, "validation archive")


if __name__ == "__main__":
    sys.exit(main())
