"""test_extension.py — tests of a validation run that goes on from another (Run.extends, prepare_extension and select in python/canopyfoam/validation_execute.py).

Run as:  /usr/bin/python3 tests/python/test_extension.py   (./Alltest extension)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic runs under a temporary run directory: a source case made on 1
rank (time directories 0, 12.5 and 40, a processor directory, a solver
log ending in End, a report, its wall time and code version) and a run
that extends it. select must list the source before the extension;
prepare_extension must refuse while the source is missing or made on
other ranks, leaving no case behind; then copy the source with its
latest write (not its processor directories), drop the stale report,
carry the wall time and the console log over and mark the case stopped,
so that `run` continues it. A failing edit must leave no case behind.
"""

import os
import shutil
import tempfile

from checks import check, finish
from canopyfoam import validation_execute, validation_paths
from canopyfoam.validation_case import report_json, run_state, wall_time
from canopyfoam.validation_execute import prepare_extension, select
from canopyfoam.validation_runs import RUN_BY_ID, SEVEN, Run


def write(path, text="x"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


tmp = tempfile.mkdtemp()
saved_root = validation_paths.RUN_ROOT
try:
    validation_paths.RUN_ROOT = tmp
    source = Run("test-source", SEVEN, "the source, to 40 s")
    extension = Run("test-extension", SEVEN, "the source on to 80 s",
                    extends="test-source")
    RUN_BY_ID.update({r.ident: r for r in (source, extension)})

    check("select", select(["test-extension"]) ==
          ["test-source", "test-extension"],
          "%s (the source first)" % select(["test-extension"]))

    try:
        prepare_extension(extension, 1)
        refused = False
    except RuntimeError as e:
        refused = "test-source" in str(e) and "missing" in str(e)
    check("source missing", refused
          and not os.path.exists(extension.case_dir),
          "refused naming the source, no case left")

    case = source.case_dir
    for d in ("0", "12.5", "40", "processor0/40", "constant/polyMesh",
              "system", "postProcessing/canopy/0"):
        write(os.path.join(case, d, "U"))
    write(os.path.join(case, "log.canopyPimpleFoam"), "Time = 40\n\nEnd\n")
    write(report_json(case), "{}")
    write(os.path.join(case, "validation-wall-time"), "123.4 1\n")
    write(os.path.join(case, "validation-code-version"), "abc123\n")
    write(os.path.join(tmp, "test-source.out"), "progress: t = 40\n")
    check("source complete", run_state(source) == "complete",
          run_state(source))

    try:
        prepare_extension(extension, 2)
        refused = False
    except RuntimeError as e:
        refused = "-np 1" in str(e)
    check("other ranks", refused and not os.path.exists(extension.case_dir),
          "refused asking for -np 1, no case left")

    latest = prepare_extension(extension, 1)
    out = extension.case_dir
    check("latest write", latest == "40", "goes on from %s" % latest)
    check("copied", all(os.path.exists(os.path.join(out, d, "U"))
                        for d in ("0", "40", "constant/polyMesh",
                                  "postProcessing/canopy/0"))
          and not os.path.exists(os.path.join(out, "processor0")),
          "times, mesh and series copied, processor directories not")
    check("stale report dropped", not os.path.exists(report_json(out)),
          "no report.json until the extension ends")
    check("stopped", run_state(extension) == "stopped",
          "state %s (run --continue goes on)" % run_state(extension))
    check("wall time", wall_time(out) == (123.4, 1), "%s" %
          (wall_time(out),))
    check("console log", open(os.path.join(tmp, "test-extension.out"))
          .read() == "progress: t = 40\n", "the source's output carried")

    def failing(run):
        raise RuntimeError("run %s: cannot set endTime" % run.ident)
    saved_edits = validation_execute.apply_edits
    validation_execute.apply_edits = failing
    try:
        try:
            prepare_extension(extension, 1)
            refused = False
        except RuntimeError:
            refused = True
    finally:
        validation_execute.apply_edits = saved_edits
    check("failed edit", refused and not os.path.exists(extension.case_dir),
          "the error passed on, no case left")
finally:
    validation_paths.RUN_ROOT = saved_root
    shutil.rmtree(tmp)

finish()
