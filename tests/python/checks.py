"""checks.py — what the python tests share: the repository's python/ on the import path, one PASS/FAIL line per check, a synthetic canopy.h5, and the exit status."""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.dirname(os.path.realpath(__file__)))), "python"))

failures = []


def check(name, ok, detail):
    """Print PASS or FAIL, the check's name and its numbers; remember a
    failure."""
    print("%s %s: %s" % ("PASS" if ok else "FAIL", name, detail))
    if not ok:
        failures.append(name)


def refused(name, call, error, text):
    """Check that call() raises error with text in its message."""
    try:
        call()
    except error as e:
        check(name, text in str(e), str(e))
        return
    check(name, False, "no error")


def finish():
    """Print the count of failed checks and exit 1 if there are any."""
    print("%d failed" % len(failures))
    sys.exit(1 if failures else 0)


def write_canopy_h5(path, groups, triangles, springs, rest, spring_groups,
                    states):
    """Write a canopy.h5 at path with the mesh and, per state, a group
    steps/NNNNNN holding the time attribute and the state's datasets;
    states is a list of (time, {name: array}). Needs h5py."""
    import h5py
    import numpy as np
    with h5py.File(path, "w") as f:
        m = f.create_group("mesh")
        m["node_group"] = np.asarray(groups).astype(np.int32)
        m["triangles"] = np.asarray(triangles).astype(np.int32)
        m["springs"] = np.asarray(springs).astype(np.int32)
        m["spring_rest_length"] = rest
        m["spring_group"] = np.asarray(spring_groups).astype(np.int32)
        for k, (t, data) in enumerate(states):
            g = f.create_group("steps/%06d" % k)
            g.attrs["time"] = t
            for name, value in data.items():
                g[name] = value
