"""test_slim_case.py — tests of slim_case in python/canopyfoam/validation_execute.py (a complete validation run's field writes removed, what its report reads kept).

Run as:  /usr/bin/python3 tests/python/test_slim_case.py   (./Alltest slim_case)
Prints one PASS/FAIL line per check; exits 1 if any fails.

A synthetic case holds time directories 0, 0.375, 2, 10 and 9.5 (10 the
latest: a lexical order would take 9.5), two processor directories, and
0.orig, constant, system, postProcessing, a log and a file named 3 (not
a directory). slim_case must remove exactly the processor directories and
the time directories 0.375, 2 and 9.5, report 5 removed and the bytes
their files held (written here: 1000 bytes in each), and keep everything
else byte for byte.
"""

import os
import shutil
import tempfile

from checks import check, finish
from canopyfoam.validation_execute import slim_case


def write(path, nbytes=1000):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(b"x" * nbytes)


tmp = tempfile.mkdtemp()
try:
    case = os.path.join(tmp, "case")
    for d in ("0", "0.375", "2", "10", "9.5", "processor0/2",
              "processor1/2", "0.orig", "constant/polyMesh", "system",
              "postProcessing/canopy/0"):
        write(os.path.join(case, d, "U"))
    write(os.path.join(case, "log.canopyPimpleFoam"))
    write(os.path.join(case, "3"))
    n, freed = slim_case(case)
    left = sorted(os.listdir(case))
    want = sorted(["0", "10", "0.orig", "constant", "system",
                   "postProcessing", "log.canopyPimpleFoam", "3"])
    check("kept", left == want, "left %s" % left)
    check("count and bytes", n == 5 and freed == 5000,
          "%d removed, %d bytes (expected 5, 5000)" % (n, freed))
    check("kept intact", all(os.path.getsize(os.path.join(case, d, "U"))
                             == 1000 for d in ("0", "10", "constant/"
                                               "polyMesh",
                                               "postProcessing/canopy/0")),
          "files of 1000 bytes")
    n, freed = slim_case(case)
    check("idempotent", n == 0 and freed == 0,
          "%d removed the second time" % n)
finally:
    shutil.rmtree(tmp)

finish()
