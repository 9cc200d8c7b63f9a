"""checks.py — what the python tests share: the repository's python/ on the import path, one PASS/FAIL line per check, and the exit status."""

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
