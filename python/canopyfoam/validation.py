"""validation.py — the validation studies of canopyFoam: runs tutorial variants (bin/canopy-validate) and writes docs/validation.md from their reports.

A run is a copy of a tutorial in build/validation/<run id>/ with some
dictionary entries changed (foamDictionary -set) and some options given to
its Allrun; its Allrun writes postProcessing/report/report.json
(bin/canopy-report). A study groups runs and says what they are compared
with. `run` does the runs that have no complete result yet (a run is
complete when its solver log ends with "End" and its report.json exists),
then removes the field writes its report does not read (slim_case; `run
--keep-fields` keeps them); `report` reads the runs and writes the
markdown and the plots; a run that failed is listed as such.

Every run read is recorded in docs/validation/runs/<run id>.json
(validation_archive.py), which is committed: a run that is not in
build/validation (another machine made it) is read from its record. A
study none of whose runs is in either place keeps its section of the
previous report, marked as kept; otherwise a missing run is listed with
the command that makes it.

Only the standard library and numpy are needed to run; matplotlib for the
plots.

The parts: validation_runs.py (the runs), validation_studies.py (the
studies), validation_case.py (a run's case directory and its state),
validation_execute.py (preparing, running and continuing a run),
validation_results.py (a run's record), validation_tables.py (the
report's tables, estimates and figures), validation_notes.py (its prose),
validation_report.py (docs/validation.md); this module is the command
line (bin/canopy-validate).
"""

import argparse
import os
import sys

from . import validation_archive as archive
from . import validation_paths as paths
from .validation_runs import RUN_BY_ID
from .validation_studies import STUDIES
from .validation_case import (run_state, running_pid)
from .validation_execute import (execute, prepare_extension, select, slim_case)
from .validation_results import record
from .validation_tables import converged
from .validation_report import write_report


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="canopy-validate",
        description="Run the validation studies and write docs/validation.md.")
    sub = p.add_subparsers(dest="action", required=True)
    r = sub.add_parser("run", help="run studies or runs that are not "
                       "complete (see --list)")
    r.add_argument("names", nargs="+", help="study, run id, or all")
    r.add_argument("-np", type=int, default=2, help="ranks (default 2)")
    r.add_argument("--force", action="store_true",
                   help="re-run complete runs too")
    r.add_argument("--continue", dest="resume", action="store_true",
                   help="continue stopped runs from their latest written "
                   "time instead of starting them afresh (a long run in "
                   "parts: stop it with Ctrl-C or kill, continue later)")
    r.add_argument("--keep-fields", action="store_true",
                   help="keep every field write of a complete run (by "
                   "default its processor directories and all time "
                   "directories but 0 and the latest are removed once "
                   "its report is written: a study of dozens of runs "
                   "would otherwise fill the disk)")
    sub.add_parser("report", help="write docs/validation.md from the "
                   "complete runs")
    sub.add_parser("list", help="list the studies and runs with their state")
    c = sub.add_parser("converged", help="print the converged values of a "
                       "resolution study (finest run, extrapolation, GCI) "
                       "as JSON")
    c.add_argument("study")
    args = p.parse_args(argv)

    if args.action == "list":
        for name, title, ids in STUDIES:
            print("%s: %s" % (name, title))
            for i in ids:
                run = RUN_BY_ID[i]
                state = run_state(run)
                if state == "missing" and \
                        archive.load(paths.ARCHIVE_DIR, run)[0] is not None:
                    state = "archived"
                print("  %-16s %-9s %s" % (i, state, run.label))
        return 0
    if args.action == "converged":
        import json
        print(json.dumps(converged(args.study), indent=1))
        return 0
    if args.action == "report":
        write_report()
        return 0
    if args.np < 1:
        raise SystemExit("canopy-validate: -np must be >= 1")
    if not os.environ.get("CANOPYFOAM_DIR"):
        raise SystemExit("canopy-validate: run needs OpenFOAM's environment: "
                         "source bin/openfoam-env first "
                         "(. bin/openfoam-env)")
    os.makedirs(paths.RUN_ROOT, exist_ok=True)
    ok = True
    for ident in select(args.names):
        run = RUN_BY_ID[ident]
        if run_state(run) == "complete" and not args.force:
            print("canopy-validate: %s is complete (--force re-runs it)"
                  % ident)
            continue
        if run_state(run) == "running":
            print("canopy-validate: %s is running (process %d); not "
                  "started again" % (ident, running_pid(run.case_dir)),
                  file=sys.stderr)
            ok = False
            continue
        resume = args.resume and run_state(run) in ("failed", "stopped")
        try:
            if run.extends and not resume:
                latest = prepare_extension(run, args.np)
                print("canopy-validate: %s goes on from %s's write at %s s"
                      % (ident, run.extends, latest), flush=True)
                resume = True
            ok = execute(run, args.np, resume) and ok
            record(run)     # its record in docs/validation/runs
            if run_state(run) == "complete" and not args.keep_fields:
                n, freed = slim_case(run.case_dir)
                if n:
                    print("canopy-validate: %s: removed %d field writes "
                          "(%.2f GB; postProcessing, the logs and the "
                          "latest time kept; --keep-fields keeps them)"
                          % (ident, n, freed / 1e9), flush=True)
        except RuntimeError as e:
            print("canopy-validate: %s" % e, file=sys.stderr)
            ok = False
        except KeyboardInterrupt:
            return 130      # stopped: execute said where it stands
    return 0 if ok else 1
