"""Post-processing of rodyn results.

`load_static(path)` reads the static results of a run (results.h5, or the CSV tables
when there is no results.h5) into plain dataclasses; see `rodyn_post.results`.
`load_dynamic(path)` reads the dynamic results (dynamic.h5, or the dynamic CSV tables)
the same way; see `rodyn_post.dynamic`. `load_environment(path)` reads the sea (water
level, depth, current, seabed) of a run with water, None for a dry run; see
`rodyn_post.environment` (which also gives the seabed's trace and the current profile
the plots draw). `load_modes(path)` reads the natural periods and mode shapes of a run
with *MODAL (None without); see `rodyn_post.modes`.

The commands (rodyn_post.commands, installed as the console commands rodyn-plot-static,
rodyn-plot-dynamic, rodyn-plot-history, rodyn-range-graph, rodyn-animate,
rodyn-paraview, rodyn-compare, rodyn-plot-all by `pip install -e postproc`; see
postproc/pyproject.toml) share:
  rodyn_post.cli         the command-line scaffold: arguments, messages, exit statuses,
                         writing files (Agg backend)
  rodyn_post.errors      the exception types and the exit statuses they map to
  rodyn_post.quantities  quantities at points of a line, values at an arc length,
                         range statistics (what is interpolated, and how)
  rodyn_post.units       units in CSV headers and their SI factors
  rodyn_post.reference   reading another tool's CSV, resampling, error metrics
  rodyn_post.vtk         ParaView .vtp / .pvd text
"""
from .dynamic import DynamicResults, LineDynamic, StepLog, load_dynamic
from .environment import Environment, load_environment
from .errors import InputError, RodynResultsError, WriteError
from .modes import LineModes, ModalResults, ObjectModes, load_modes
from .results import LineStatic, StaticResults, load_static

__all__ = ["DynamicResults", "Environment", "InputError", "LineDynamic", "LineModes",
           "LineStatic", "ModalResults", "ObjectModes", "RodynResultsError",
           "StaticResults", "StepLog", "WriteError", "load_dynamic", "load_environment",
           "load_modes", "load_static"]
