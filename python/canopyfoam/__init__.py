"""canopyfoam: Python post-processing of canopyFoam runs (report: time-series analysis; render: ParaView pictures)."""

# The modules are imported on demand: `report` needs numpy (matplotlib only
# for its plots), `render` needs ParaView's `paraview.simple` (pvbatch or
# pvpython). Importing this package pulls in neither.
