"""canopy_h5.py — a run's structure file, postProcessing/canopy/canopy.h5, opened for reading with the error class the caller names (shape.py, load_moment.py, step_changes.py).

Reading needs h5py (Debian's python3-h5py; bin/setup installs it).
"""

import os

# The node and spring groups of the file's mesh/node_group and
# mesh/spring_group (libcanopy's canopy_group, src/canopy/include/canopy.h)
GROUP_FABRIC, GROUP_TAPE, GROUP_LINE, GROUP_PAYLOAD = 0, 1, 2, 3


def path(case_dir):
    """<case_dir>/postProcessing/canopy/canopy.h5"""
    return os.path.join(case_dir, "postProcessing", "canopy", "canopy.h5")


def open_file(case_dir, error):
    """The case's canopy.h5 as an h5py.File open for reading; error(message)
    is raised without h5py or without the file (h5py's own OSError when the
    file cannot be read)."""
    try:
        import h5py
    except ImportError:
        raise error("python3-h5py is not installed (bin/setup installs it)")
    name = path(case_dir)
    if not os.path.isfile(name):
        raise error("no %s" % os.path.relpath(name, case_dir))
    return h5py.File(name, "r")
