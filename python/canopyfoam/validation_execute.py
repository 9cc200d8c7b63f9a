"""validation_execute.py — a validation run's case prepared (a copy of its tutorial with its edits, or a run it extends at its latest write), run, continued and slimmed once complete."""

import math
import os
import shutil
import signal
import subprocess
import time

from . import report as rep
from . import rest_state
from . import validation_paths as paths
from .validation_runs import (NARROW_BLOCK_MESH, NARROW_BOX_ENTRY, REMOVE,
                              REST_STATE, RUNS, RUN_BY_ID,
                              SOURCE_PAYLOAD_VELOCITY)
from .validation_studies import STUDIES
from .validation_case import (foam_get, record_code_version,
                              report_json, run_state, running_file,
                              stopped_file, wall_time)


def _time_name(name):
    """The time a directory's name spells, or None."""
    try:
        value = float(name)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def terminate_tree(pid):
    """SIGTERM to a process and all its descendants (Allrun, mpirun, the
    solver's ranks), the deepest first."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(ppid, []).append(int(entry))
    order, todo = [], [pid]
    while todo:
        p = todo.pop()
        order.append(p)
        todo.extend(children.get(p, []))
    for p in reversed(order):
        try:
            os.kill(p, signal.SIGTERM)
        except OSError:
            pass


def slim_case(case_dir):
    """Remove a complete run's field writes that its report does not read:
    the processor directories and every time directory but 0 and the
    latest (the report reads postProcessing/, the logs and the latest
    time's fields, which canopy-render draws). Returns (directories
    removed, bytes freed)."""
    def size(path):
        total = 0
        for root, _, files in os.walk(path):
            for f in files:
                try:
                    total += os.lstat(os.path.join(root, f)).st_size
                except OSError:
                    pass
        return total

    names = os.listdir(case_dir)
    times = [(_time_name(n), n) for n in names
             if os.path.isdir(os.path.join(case_dir, n))
             and _time_name(n) is not None]
    latest = max(times)[1] if times else None
    doomed = [n for n in names if n.startswith("processor")
              and os.path.isdir(os.path.join(case_dir, n))]
    doomed += [n for t, n in times if t != 0.0 and n != latest]
    freed = 0
    for n in doomed:
        path = os.path.join(case_dir, n)
        freed += size(path)
        shutil.rmtree(path)
    return len(doomed), freed


def last_payload_velocity(case_dir):
    """The payload's velocity at the last time of a run's series (every
    canopy.dat of the case, restarts joined; report.load_case) as an
    OpenFOAM vector "(x y z)" [m/s]."""
    return "(%.10g %.10g %.10g)" % tuple(rep.load_case(case_dir).columns(
        "payload_Ux", "payload_Uy", "payload_Uz")[-1])


def apply_edits(run):
    """Set the run's (file, entry, value) edits in its case directory."""
    for rel, entry, value in run.edits:
        path = os.path.join(run.case_dir, rel)
        if entry == NARROW_BOX_ENTRY:
            with open(path, "w") as f:
                f.write(NARROW_BLOCK_MESH % tuple(value.split()))
            mesh_dict = os.path.join(run.case_dir, "system", "canopyMeshDict")
            if os.path.exists(mesh_dict):
                os.remove(mesh_dict)
            continue
        if value == "DOUBLE":
            value = "%.10g" % (2 * float(foam_get(path, entry)))
        if value == SOURCE_PAYLOAD_VELOCITY:
            value = last_payload_velocity(
                RUN_BY_ID[run.rest_state_of].case_dir)
        action = ["-remove"] if value == REMOVE else ["-set", value]
        out = subprocess.run(["foamDictionary", "-entry", entry] + action
                             + [path], capture_output=True, text=True)
        if out.returncode != 0:
            raise RuntimeError("run %s: cannot set %s in %s: %s"
                               % (run.ident, entry, rel, out.stderr.strip()))


def prepare(run):
    """Fresh copy of the tutorial with the run's edits."""
    src = os.path.join(paths.TOP, "tutorials", run.tutorial)
    if not os.path.isdir(src):
        raise RuntimeError("run %s: no tutorial %s" % (run.ident, src))
    if os.path.exists(run.case_dir):
        shutil.rmtree(run.case_dir)
    shutil.copytree(src, run.case_dir, symlinks=True)
    apply_edits(run)
    if run.rest_state_of:
        source = os.path.join(RUN_BY_ID[run.rest_state_of].case_dir,
                              "postProcessing", "canopy", "canopy.h5")
        try:
            rest_state.write_rest_state(
                source, os.path.join(run.case_dir, REST_STATE))
        except rest_state.RestStateError as e:
            raise RuntimeError("run %s starts from run %s's last state "
                               "(`bin/canopy-validate run %s` first): %s"
                               % (run.ident, run.rest_state_of,
                                  run.rest_state_of, e))


def prepare_extension(run, ranks):
    """Make run `run` the continuation of its complete source run
    (run.extends): the source's case directory copied with its latest
    write, the run's edits set on top (e.g. a later endTime), that write
    decomposed for `ranks` and the case marked stopped, so execute(resume)
    goes on from it with the source's wall time and code version carried
    over. Nothing is left behind if a step fails."""
    source = RUN_BY_ID[run.extends]
    state = run_state(source)
    if state != "complete":
        raise RuntimeError("run %s goes on from run %s, which is %s "
                           "(`bin/canopy-validate run %s` first)"
                           % (run.ident, source.ident, state, source.ident))
    _, source_ranks = wall_time(source.case_dir)
    if source_ranks != ranks:
        raise RuntimeError("run %s goes on from run %s, made on %s ranks: "
                           "give -np %s" % (run.ident, source.ident,
                                            source_ranks, source_ranks))
    times = [(_time_name(n), n) for n in os.listdir(source.case_dir)
             if _time_name(n) is not None
             and os.path.isdir(os.path.join(source.case_dir, n))]
    latest = max(times)[1] if times else None
    if latest is None or float(latest) == 0.0:
        raise RuntimeError("run %s: run %s has no written time after 0 to "
                           "go on from" % (run.ident, source.ident))
    if os.path.exists(run.case_dir):
        shutil.rmtree(run.case_dir)
    try:
        shutil.copytree(source.case_dir, run.case_dir, symlinks=True,
                        ignore=shutil.ignore_patterns("processor*"))
        apply_edits(run)
        stale = report_json(run.case_dir)
        if os.path.exists(stale):
            os.remove(stale)
        command = ["decomposePar", "-force", "-time", latest]
        if os.path.exists(os.path.join(run.case_dir, "system",
                                       "decomposeParDict.run")):
            command += ["-decomposeParDict", "system/decomposeParDict.run"]
        if ranks > 1:
            with open(os.path.join(run.case_dir, "log.decomposePar.extend"),
                      "w") as out:
                status = subprocess.run(command, cwd=run.case_dir,
                                        stdout=out, stderr=subprocess.STDOUT)
            if status.returncode != 0:
                raise RuntimeError("run %s: decomposePar of run %s's time %s "
                                   "failed (log.decomposePar.extend)"
                                   % (run.ident, source.ident, latest))
        with open(stopped_file(run.case_dir), "w") as f:
            f.write("extends %s from %s s\n" % (source.ident, latest))
        earlier = os.path.join(paths.RUN_ROOT, source.ident + ".out")
        if os.path.exists(earlier):
            shutil.copy(earlier,
                        os.path.join(paths.RUN_ROOT, run.ident + ".out"))
    except BaseException:
        shutil.rmtree(run.case_dir, ignore_errors=True)
        raise
    return latest


def continue_options(options):
    """A run's Allrun options for going on with it (-continue): those
    that start a run afresh (-mapFieldsFrom DIR: canopy-run-case refuses
    it with -continue) left out."""
    out, skip = [], False
    for option in options:
        if skip:
            skip = False
        elif option == "-mapFieldsFrom":
            skip = True
        else:
            out.append(option)
    return out


def execute(run, ranks, resume=False):
    """Run a case afresh, or (resume) continue its stopped run from its
    latest written time (bin/canopy-run-case -continue); the wall time
    recorded is then the sum of its parts."""
    earlier = 0.0
    if resume:
        earlier, earlier_ranks = wall_time(run.case_dir)
        if earlier is None or earlier_ranks != ranks:
            raise RuntimeError("run %s: no stopped run on %d ranks to "
                               "continue in %s" % (run.ident, ranks,
                                                   run.case_dir))
    else:
        prepare(run)
    record_code_version(run.case_dir, resume)
    cmd = [os.path.join(run.case_dir, "Allrun"), "-np", str(ranks)]
    cmd += ((continue_options(run.options) + ["-continue"]) if resume
            else run.options)
    start = time.time()
    log = os.path.join(paths.RUN_ROOT, run.ident + ".out")
    print("canopy-validate: %s %s(%s) in %s, output in %s"
          % (run.ident, "continued " if resume else "", run.label,
             run.case_dir, log), flush=True)
    def record_wall():
        # kept current while the run goes, so a run killed with its
        # session still has its time so far for a later --continue
        with open(os.path.join(run.case_dir, "validation-wall-time"),
                  "w") as f:
            f.write("%.1f %d\n" % (earlier + time.time() - start, ranks))

    if os.path.exists(stopped_file(run.case_dir)):
        os.remove(stopped_file(run.case_dir))
    with open(running_file(run.case_dir), "w") as f:
        f.write("%d\n" % os.getpid())

    def stop(signum, frame):
        raise KeyboardInterrupt
    previous = signal.signal(signal.SIGTERM, stop)
    proc = None
    try:
        with open(log, "a" if resume else "w") as out:
            proc = subprocess.Popen(cmd, stdout=out,
                                    stderr=subprocess.STDOUT,
                                    cwd=run.case_dir)
            while True:
                record_wall()
                try:
                    status = proc.wait(timeout=30)
                    break
                except subprocess.TimeoutExpired:
                    pass
        record_wall()
    except KeyboardInterrupt:
        # stopped by hand or with the session: the solver's run goes with
        # it, and the case is kept for --continue
        if proc is not None and proc.poll() is None:
            terminate_tree(proc.pid)
            proc.wait()
        record_wall()
        with open(stopped_file(run.case_dir), "w") as f:
            f.write("%s\n" % time.strftime("%Y-%m-%d %H:%M:%S"))
        print("canopy-validate: %s stopped after %.0f s; `bin/canopy-"
              "validate run --continue %s` goes on from its latest write"
              % (run.ident, earlier + time.time() - start, run.ident),
              flush=True)
        raise
    finally:
        signal.signal(signal.SIGTERM, previous)
        os.remove(running_file(run.case_dir))
    wall = earlier + time.time() - start
    print("canopy-validate: %s %s after %.0f s" % (
        run.ident, "done" if status == 0 else "FAILED (status %d)" % status,
        wall), flush=True)
    return status == 0


def select(names):
    """Run ids from run ids and study names ('all': every run)."""
    studies = {s[0]: s[2] for s in STUDIES}
    chosen = []
    for name in names:
        if name == "all":
            ids = [r.ident for r in RUNS]
        elif name in studies:
            ids = studies[name]
        elif name in RUN_BY_ID:
            ids = [name]
        else:
            raise SystemExit("canopy-validate: unknown run or study '%s' "
                             "(see --list)" % name)
        for i in ids:
            # a run that goes on from another comes after it
            needs = []
            while i is not None and i not in chosen and i not in needs:
                needs.insert(0, i)
                i = RUN_BY_ID[i].extends
            chosen += needs
    return chosen
