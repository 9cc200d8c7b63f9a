"""test_model_differences.py — known-answer tests of the line that names the model entries in which a study's runs differ (python/canopyfoam/validation_runs.py, model_difference_lines), and of the 10-40 s studies that compare runs of one load.

Run as:  /usr/bin/python3 tests/python/test_model_differences.py   (./Alltest model_differences)
Prints one PASS/FAIL line per check; exits 1 if any fails.

Synthetic runs of the 7 ft tutorial: one on the tutorial's load, one with
coupling.load.reaction markers, one with the markers' spacing removed;
runs that agree give no line, runs of two tutorials are compared within
each tutorial only; an entry set to the tutorial's own value (read from
the tutorial's dictionary, in its sub-dictionary) agrees with it. Then
the studies domain7ftLong, damping7ftLong, edgeLength7ftLong and
turbulence7ftConverged as defined: their first two
runs must agree in every model entry (each pairs runs of one load).
"""

from checks import check, finish
from canopyfoam.validation_runs import (PROPS, REMOVE, RUN_BY_ID, Run, SEVEN,
                                        model_difference_lines, tutorial_entry)
from canopyfoam.validation_studies import STUDIES

tutorial = Run("test-tutorial", SEVEN, "synthetic; interval 10-40 s")
markers = Run("test-markers", SEVEN, "synthetic; interval 10-40 s",
                edits=[(PROPS, "coupling/load/reaction", "markers")])
removed = Run("test-removed", SEVEN, "synthetic; interval 10-40 s",
                edits=[(PROPS, "coupling/forcing/markerSpacingCells",
                        REMOVE)])
same = Run("test-same", SEVEN, "synthetic; interval 10-40 s",
             edits=[("system/controlDict", "endTime", "12")])
other = Run("test-other", "parachutes/T10", "synthetic; interval 10-40 s",
              edits=[(PROPS, "coupling/load/reaction", "markers")])

text = "\n".join(model_difference_lines([tutorial, markers]))
check("a load that differs is named with its runs",
      "coupling.load.reaction: the tutorial's cells (test-tutorial); markers "
      "(test-markers)" in text, text)
text = "\n".join(model_difference_lines([tutorial, removed]))
check("a removed entry says so",
      "removed (the code's default) (test-removed)" in text, text)
check("runs that agree in the model give no line",
      model_difference_lines([tutorial, same]) == [],
      model_difference_lines([tutorial, same]))
check("runs of two tutorials are compared within each",
      model_difference_lines([tutorial, other]) == [],
      model_difference_lines([tutorial, other]))

own = Run("test-own", SEVEN, "synthetic; interval 10-40 s",
            edits=[(PROPS, "fabric/damping",
                    tutorial_entry(SEVEN, PROPS, "fabric/damping"))])
check("an entry set to the tutorial's own value agrees with the tutorial",
      model_difference_lines([tutorial, own]) == [],
      model_difference_lines([tutorial, own]))
# lines.damping is read in its own sub-dictionary, not fabric's damping
fabric_value = tutorial_entry(SEVEN, PROPS, "fabric/damping")
lines_value = tutorial_entry(SEVEN, PROPS, "lines/damping")
check("a nested entry is read in its sub-dictionary",
      fabric_value is not None and lines_value is not None
      and float(fabric_value) != float(lines_value),
      "fabric %s, lines %s" % (fabric_value, lines_value))
sibling = Run("test-sibling", SEVEN, "synthetic; interval 10-40 s",
                edits=[(PROPS, "lines/damping", fabric_value)])
text = "\n".join(model_difference_lines([tutorial, sibling]))
check("a value equal to a sibling sub-dictionary's still differs",
      "lines.damping: the tutorial's %s (test-tutorial); %s (test-sibling)"
      % (lines_value, fabric_value) in text, text)
check("an absent entry reads as None",
      tutorial_entry(SEVEN, PROPS, "coupling/forcing/markerSpacing")
      is None and tutorial_entry(SEVEN, PROPS, "no/such/entry") is None,
      "markerSpacing %r" % tutorial_entry(SEVEN, PROPS,
                                            "coupling/forcing/markerSpacing"))

studies = dict((s[0], s[2]) for s in STUDIES)
for name in ("domain7ftLong", "damping7ftLong", "edgeLength7ftLong",
             "turbulence7ftConverged"):
    first_two = [RUN_BY_ID[i] for i in studies[name][:2]]
    lines = model_difference_lines(first_two)
    check("%s: %s and %s on one model" % (name, first_two[0].ident,
                                          first_two[1].ident),
          lines == [], lines)

finish()
