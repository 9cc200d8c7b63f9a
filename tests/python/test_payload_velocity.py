"""test_payload_velocity.py — tests of validation.last_payload_velocity (a mapped run's initialVelocity: the payload's velocity at its source's last time) on synthetic canopy.dat files.

Run as:  /usr/bin/python3 tests/python/test_payload_velocity.py   (./Alltest payload_velocity)
Prints one PASS/FAIL line per check; exits 1 if any fails.

A case with one canopy.dat of three rows, its columns named in an order
other than report.COLUMNS' (payload velocity last): the last row's
payload velocity comes back exactly, as OpenFOAM's "(x y z)". The same
case restarted from t = 0.15 (a second canopy.dat in
postProcessing/canopy/0.15): the restart's last row wins. A case with no
canopy.dat is refused with report.ReportError.
"""

import os
import shutil
import tempfile

from checks import check, finish
from canopyfoam import report
from canopyfoam.validation_execute import last_payload_velocity

OTHERS = [c for c in report.COLUMNS
          if c not in ("time", "payload_Ux", "payload_Uy", "payload_Uz")]


def write_dat(case, start, rows):
    """canopy.dat under postProcessing/canopy/<start>: rows of (t, Ux, Uy,
    Uz), every other column 0, the velocity's columns last."""
    folder = os.path.join(case, "postProcessing", "canopy", start)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "canopy.dat"), "w") as f:
        f.write("# nominalDiameter 2.134\n")
        f.write("# time %s payload_Ux payload_Uy payload_Uz\n"
                % " ".join(OTHERS))
        for t, ux, uy, uz in rows:
            f.write("%r %s %r %r %r\n" % (t, " ".join("0" for _ in OTHERS),
                                          ux, uy, uz))


top = tempfile.mkdtemp()
try:
    case = os.path.join(top, "source")
    write_dat(case, "0", [(0.05, 0.0, 0.0, -1.0), (0.1, 0.25, -0.5, -5.5),
                          (0.2, 0.125, -0.0625, -5.6625)])
    got = last_payload_velocity(case)
    check("the last row's payload velocity, found by column name",
          got == "(0.125 -0.0625 -5.6625)", got)
    write_dat(case, "0.15", [(0.15, 0.0, 0.0, -5.0),
                             (0.3, -0.25, 0.375, -5.75)])
    got = last_payload_velocity(case)
    check("a restart's last row wins", got == "(-0.25 0.375 -5.75)", got)
    empty = os.path.join(top, "empty")
    os.makedirs(empty)
    try:
        last_payload_velocity(empty)
        refused = False
    except report.ReportError:
        refused = True
    check("a case without canopy.dat is refused", refused, "ReportError" if refused else "no error")
finally:
    shutil.rmtree(top)
finish()
