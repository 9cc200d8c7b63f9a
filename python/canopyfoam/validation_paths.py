"""validation_paths.py — where the validation runs (build/validation), the report (docs/validation.md), its figures and the runs' records (docs/validation/runs) live."""

import os

TOP = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__))))
RUN_ROOT = os.path.join(TOP, "build", "validation")
DOC = os.path.join(TOP, "docs", "validation.md")
FIG_DIR = os.path.join(TOP, "docs", "validation")
ARCHIVE_DIR = os.path.join(FIG_DIR, "runs")
