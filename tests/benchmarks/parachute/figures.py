"""figures.py — the parachute benchmark's figures from finished runs: the main job's C_D0 error against the resolution study's converged value, and each resolution level's cost and coupling iterations in steady descent.

Usage: python3 figures.py mainjob <case dir> <wall seconds>
       python3 figures.py mainjob   (the main job's validation run)
       python3 figures.py levels [study]
       python3 figures.py study      (prints the default study's name)
Prints BENCH lines (name value unit) and '# ' comment lines.

mainjob: C_D0 of the case over the main job's own interval (the steady
interval of MAIN_JOB_RUN in python/canopyfoam/validation_runs.py,
the one its Allrun's report reads), against the converged value of
the study the 7 ft reference names (report.py's convergedStudy: its
finest run and GCI, bin/canopy-validate converged <study>, from the
committed records); then both over that interval, when the finest run
is in build/validation and its series covers it. Without a case: the
main job's run of bin/canopy-validate (validation_runs.MAIN_JOB_RUN in
build/validation, its wall time from mesh to report as the validation
run measured it), for a report made without the benchmark's own run.

levels: for each run of a resolution study (default the study the 7 ft
reference's summaries compare with, report.py's convergedStudy; e.g.
resolution7ftMappedCells: the levels that continue a coarser run) found in
build/validation (the study's own runs, 2 ranks), over the interval of
the study's first run: cells, wall seconds per time step (ClockTime
increments of the solver log) and coupling iterations per step
(canopy.dat). A run not in build/validation is read from its committed
record (docs/validation/runs), which holds the whole run's wall time and
steps (so its cost per step includes the meshing and the start) and the
coupling iterations over its own steady interval; a comment line says
so. A source run the study also lists (one whose start differs from the
first run's: validation_tables.study_levels) is left out.
"""

import os
import re
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__)))))
sys.path.insert(0, os.path.join(TOP, "python"))

from canopyfoam import report as rep          # noqa: E402
from canopyfoam import validation_archive as archive  # noqa: E402
from canopyfoam.validation_case import (cell_count, run_state,  # noqa: E402
                                        solver_log, wall_time)
from canopyfoam.validation_paths import ARCHIVE_DIR  # noqa: E402
from canopyfoam.validation_runs import MAIN_JOB_RUN, RUN_BY_ID  # noqa: E402
from canopyfoam.validation_studies import STUDIES  # noqa: E402
from canopyfoam.validation_tables import (cells_per_diameter,  # noqa: E402
                                          converged, study_levels)

STUDY = rep.REFERENCES["7ft"]["convergedStudy"]


def interval(study=STUDY):
    """The interval every level of a study is read over (its first
    run's)."""
    run = RUN_BY_ID[dict((s[0], s[2]) for s in STUDIES)[study][0]]
    return run.steady_start, run.steady_end


def main_job(case_dir, wall):
    job = RUN_BY_ID[MAIN_JOB_RUN]
    t0, t1 = job.steady_start, job.steady_end
    a = rep.analyse(case_dir, steady_start=t0, steady_end=t1)
    cd0 = a["dragCoefficient"]["weightBalance"]
    print("# the main job: C_D0 %.4f over %g-%g s, descent %.3f m/s"
          % (cd0, t0, t1, a["descentVelocity"]["mean"]))
    print("BENCH parachute_main_job_wall_time %.0f s" % wall)
    print("BENCH parachute_main_job_C_D0 %.4f" % cd0)
    study = rep.REFERENCES["7ft"]["convergedStudy"]
    try:
        conv = converged(study)["C_D0 (weight)"]
    except SystemExit as e:
        print("# no converged value: %s" % e)
        return
    ref = conv["finest"]
    print("# converged C_D0 (finest of %s): %.4f, GCI %.1f %% (%s), "
          "extrapolated %.4f" % (", ".join(conv["runs"]), ref,
                                 100 * conv["gci"], conv["kind"],
                                 conv["extrapolated"]))
    print("BENCH parachute_main_job_C_D0_error %.4f fraction"
          % ((cd0 - ref) / ref))
    # The same comparison with the finest level read over the main job's
    # interval too
    finest = RUN_BY_ID[conv["runs"][0]]
    if run_state(finest) != "complete":
        print("# %s not in build/validation: no comparison over %g-%g s"
              % (finest.ident, t0, t1))
        return
    if rep.load_case(finest.case_dir).t[-1] < t1:
        print("# %s ends before %g s: no comparison over %g-%g s"
              % (finest.ident, t1, t0, t1))
        return
    fine = rep.analyse(finest.case_dir, steady_start=t0,
                       steady_end=t1)["dragCoefficient"]["weightBalance"]
    print("# over the main job's %g-%g s: C_D0 %.4f against %.4f (%s)"
          % (t0, t1, cd0, fine, finest.ident))
    print("BENCH parachute_main_job_C_D0_error_own_window %.4f fraction"
          % ((cd0 - fine) / fine))


def main_job_validation():
    """main_job on the main job's validation run, when it is complete in
    build/validation."""
    job = RUN_BY_ID[MAIN_JOB_RUN]
    wall, ranks = wall_time(job.case_dir)
    if run_state(job) != "complete" or wall is None:
        print("# the main job's validation run is not in build/validation "
              "(bin/canopy-validate run %s)" % job.ident)
        return
    print("# from the validation run %s (bin/canopy-validate, %d ranks, "
          "mesh to report)" % (job.ident, ranks))
    main_job(job.case_dir, wall)


def step_costs(log, t0, t1):
    """Wall seconds per time step over the steps of the solver log (the
    last part of a continued run) that end in [t0, t1]; their count and the
    first and last step's time."""
    times, clocks = [], []
    t = None
    with open(log, errors="replace") as f:
        for line in f:
            if line.startswith("Time = "):
                t = float(line.split()[2])
            elif line.startswith("ExecutionTime") and t is not None:
                m = re.search(r"ClockTime = ([0-9.eE+-]+)", line)
                times.append(t)
                clocks.append(float(m.group(1)))
    sel = [i for i in range(1, len(times)) if t0 <= times[i] <= t1]
    if not sel:
        return None, 0, None, None
    return ((clocks[sel[-1]] - clocks[sel[0] - 1]) / len(sel), len(sel),
            times[sel[0]], times[sel[-1]])


def levels(study=STUDY):
    t0, t1 = interval(study)
    ids = dict((s[0], s[2]) for s in STUDIES)[study]
    for run, _ in study_levels([(RUN_BY_ID[i], None) for i in ids]):
        ident = run.ident
        n = cells_per_diameter(run)
        log = solver_log(run.case_dir)
        if run_state(run) == "complete":
            cost, steps, first, last = step_costs(log, t0, t1)
            series = rep.load_case(run.case_dir)
            m = (series.t >= t0) & (series.t <= t1)
            its = series.column("coupling_iterations")[m].mean()
            cells = cell_count(run.case_dir)
            print("# %s: %d cells, cost per step over the solver log's %d "
                  "steps in %.4g-%.4g s; iterations over %g-%g s"
                  % (ident, cells, steps, first, last, t0, t1))
        else:
            record, why = archive.load(ARCHIVE_DIR, run)
            if record is None or not record["complete"]:
                print("# %s: not in build/validation and %s (bin/canopy-"
                      "validate run %s)" % (ident, why or "incomplete",
                                            ident))
                continue
            a = record["analysis"]
            cells, steps = record["cells"], a["steps"]
            cost = record["wall"] / steps
            its = a["coupling"]["meanIterationsSteady"]
            print("# %s: %d cells, from its committed record: the whole "
                  "run's %d steps on %d ranks (cost per step with the "
                  "meshing and the start), iterations over %g-%g s"
                  % (ident, cells, steps, record["ranks"],
                     run.steady_start, run.steady_end))
        name = "parachute_%scpd%g" % ("" if study == STUDY else
                                       study + "_", n)
        print("BENCH %s_cells %d cells" % (name, cells))
        print("BENCH %s_time_per_step_2_ranks %.3f s" % (name, cost))
        print("BENCH %s_coupling_iterations %.2f iterations/step"
              % (name, its))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "mainjob":
        main_job(sys.argv[2], float(sys.argv[3]))
    elif len(sys.argv) == 2 and sys.argv[1] == "mainjob":
        main_job_validation()
    elif len(sys.argv) == 2 and sys.argv[1] == "study":
        print(STUDY)
    elif len(sys.argv) in (2, 3) and sys.argv[1] == "levels":
        levels(*sys.argv[2:])
    else:
        sys.exit(__doc__.split("\n\n")[1])
