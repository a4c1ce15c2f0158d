"""Post-processing of rodyn results.

`load_static(path)` reads the static results of a run (results.h5, or the CSV tables
when there is no results.h5) into plain dataclasses; see `rodyn_post.results`.
"""
from .results import LineStatic, RodynResultsError, StaticResults, load_static

__all__ = ["LineStatic", "RodynResultsError", "StaticResults", "load_static"]
