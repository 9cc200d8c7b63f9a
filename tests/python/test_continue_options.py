"""test_continue_options.py — tests of validation.continue_options (the Allrun options a stopped run goes on with: `bin/canopy-validate run --continue`).

Run as:  /usr/bin/python3 tests/python/test_continue_options.py   (./Alltest continue_options)
Prints one PASS/FAIL line per check; exits 1 if any fails.

A mapped run's options (-cellsPerDiameter 30 -mapFieldsFrom ../source)
go on as -cellsPerDiameter 30: canopy-run-case refuses -mapFieldsFrom
with -continue, which would stop every continued mapped run. Options
without it come back unchanged, and so does their order; the list given
is not modified.
"""

from checks import check, finish
from canopyfoam.validation_execute import continue_options
from canopyfoam.validation_runs import RUNS

mapped = ["-cellsPerDiameter", "30", "-mapFieldsFrom", "../source",
          "-steadyStart", "2"]
got = continue_options(mapped)
check("-mapFieldsFrom and its folder left out, the rest in order",
      got == ["-cellsPerDiameter", "30", "-steadyStart", "2"], got)
check("the run's own list is not modified", len(mapped) == 6, mapped)
plain = ["-cellsPerDiameter", "27"]
check("options without it unchanged", continue_options(plain) == plain,
      continue_options(plain))
check("no options", continue_options([]) == [], continue_options([]))
check("every mapped run of the studies goes on without it",
      all("-mapFieldsFrom" not in continue_options(r.options)
          for r in RUNS), sum("-mapFieldsFrom" in r.options
                                 for r in RUNS))

finish()
