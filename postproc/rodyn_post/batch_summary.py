"""The summary of a batch: `summary.csv` and `summary.h5`, one row per case.

Columns, in this order (docs/batch.md):

- `id`, then one column per parameter (as given, empty for a case without it, as a
  case of another batch into the folder; in summary.h5 a float dataset, nan where
  empty, when every other value is a number, else strings);
- `status` (complete, failed, timeout, signal, error, cancelled, abandoned, locked,
  not run), `exit_code` (rodyn's exit status, -N for a signal N; empty / nan when it
  did not run), `message` (the last error line of rodyn's stderr, or why it did not
  run), `wall_time_s` (of the case, measured by the batch), `skipped` (1 when this
  batch found the case complete and did not run it again);
- Newton statistics of status.txt: `load_factor`, `increments`, `iterations`,
  `cutbacks`, `time_reached_s`, `steps`, `step_iterations`, `step_tangents`,
  `step_cutbacks`, `rodyn_wall_time_s`, and `max_step_iterations`, `frames`;
- the extremes of `batch_extract.extract_case` (`<LINE>.<quantity>_<stat>_<unit>`),
  the union over the cases (empty / nan where a case has none).

summary.h5 holds the same columns as datasets of `/cases` (n_cases,), and the
per-case envelopes along the lines as one ragged table `/envelope` (a row per
integration point of each line of each case: `case` (row of /cases), `line`, `s`
and `<quantity>_min` / `_max`) and `/envelope_nodes` for node quantities (the seabed
normal force). Reals are the binary64 values of the cases' files; the CSV writes them
with 17 significant digits, which read back exactly.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Dict, List, Sequence

import numpy as np

from .cli import real, write_csv

SUMMARY_CSV = "summary.csv"
SUMMARY_H5 = "summary.h5"
NEWTON_COLUMNS = ("load_factor", "increments", "iterations", "cutbacks", "time_reached_s",
                  "steps", "step_iterations", "step_tangents", "step_cutbacks",
                  "rodyn_wall_time_s", "max_step_iterations", "frames")
RUN_COLUMNS = ("status", "exit_code", "message", "wall_time_s", "skipped")
TIMING_COLUMNS = ("wall_time_s", "rodyn_wall_time_s")   # differ from run to run
INTEGER_COLUMNS = ("exit_code", "skipped", "increments", "iterations", "cutbacks", "steps",
                   "step_iterations", "step_tangents", "step_cutbacks",
                   "max_step_iterations", "frames")


def _num(value) -> float:
    if value is None:
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def summary_rows(entries: Sequence[dict], param_names: Sequence[str]) -> tuple:
    """(columns, rows as dicts) of the summary of `entries`, each a dict with `id`,
    `params` and `record` (the case's batch_case.json record, or None) and, optional,
    `status`, `message` and `skipped` overriding the record's."""
    rows: List[dict] = []
    extreme_cols: Dict[str, None] = {}
    for entry in entries:
        rec = entry.get("record") or {}
        row: Dict[str, object] = {"id": entry["id"]}
        params = entry.get("params") or {}
        for name in param_names:
            row[name] = params.get(name, "")
        row["status"] = entry.get("status") or rec.get("status") or "not run"
        row["exit_code"] = _num(rec.get("exit_code"))
        row["message"] = entry.get("message", rec.get("message", ""))
        row["wall_time_s"] = _num(rec.get("wall_time_s"))
        row["skipped"] = 1 if entry.get("skipped") else 0
        newton = rec.get("newton") or {}
        for key in NEWTON_COLUMNS[:9]:
            row[key] = _num(newton.get(key))
        row["rodyn_wall_time_s"] = _num(newton.get("wall_time_s"))
        ext = rec.get("extract") or {}
        info = ext.get("info") or {}
        row["max_step_iterations"] = _num(info.get("max_step_iterations"))
        row["frames"] = _num(info.get("frames"))
        for key, value in (ext.get("scalars") or {}).items():
            extreme_cols.setdefault(key)
            row[key] = _num(value)
        rows.append(row)
    columns = (["id"] + list(param_names) + list(RUN_COLUMNS) + list(NEWTON_COLUMNS)
               + list(extreme_cols))
    for row in rows:
        for key in extreme_cols:
            row.setdefault(key, math.nan)
    return columns, rows


def _field(value, integer: bool = False) -> str:
    if isinstance(value, float):
        if math.isnan(value):
            return ""
        if integer and value.is_integer():
            return str(int(value))
        return real(value)
    return str(value)


def _numeric(values) -> bool:
    """Whether every value is a number or empty (a case without the parameter: nan)."""
    try:
        [float(v) for v in values if v != ""]
    except (TypeError, ValueError):
        return False
    return True


def write_summary(out: Path, entries: Sequence[dict], param_names: Sequence[str],
                  meta: dict = None) -> tuple:
    """Write OUT/summary.csv and OUT/summary.h5; returns their paths."""
    import h5py

    out = Path(out)
    columns, rows = summary_rows(entries, param_names)
    csv_path = write_csv(out / SUMMARY_CSV, columns,
                         [[_field(row[c], c in INTEGER_COLUMNS) for c in columns]
                          for row in rows])
    h5_path = out / SUMMARY_H5
    tmp = out / f".{SUMMARY_H5}.tmp"
    text = {"id", "status", "message"}
    with h5py.File(tmp, "w") as f:
        f.attrs["program"] = "rodyn-batch"
        f.attrs["n_cases"] = len(rows)
        f.attrs["parameters"] = ",".join(param_names)
        for key, value in (meta or {}).items():
            f.attrs[key] = value
        g = f.create_group("cases")
        for col in columns:
            values = [row[col] for row in rows]
            if col in text or (col in param_names and not _numeric(values)):
                ds = g.create_dataset(col, data=np.array([str(v) for v in values],
                                                         dtype=object),
                                      dtype=h5py.string_dtype())
            else:
                ds = g.create_dataset(col, data=np.array([_num(v) for v in values],
                                                         dtype=float))
            ds.attrs["column"] = columns.index(col)
        g.attrs["columns"] = np.array(columns, dtype=object)
        _write_envelopes(f, entries)
    tmp.replace(h5_path)
    return csv_path, h5_path


def _write_envelopes(f, entries):
    """The ragged tables /envelope (integration points) and /envelope_nodes."""
    import h5py

    gp: Dict[str, list] = {"case": [], "line": [], "s": []}
    nodes: Dict[str, list] = {"case": [], "line": [], "s": []}
    gp_keys: Dict[str, None] = {}
    node_keys: Dict[str, None] = {}
    per_case = []
    for k, entry in enumerate(entries):
        rec = entry.get("record") or {}
        env = (rec.get("extract") or {}).get("envelope") or {}
        per_case.append(env)
        for data in env.values():
            for key in data:
                if key in ("s", "node_s"):
                    continue
                (node_keys if key == "seabed_normal_max" else gp_keys).setdefault(key)
    for key in gp_keys:
        gp[key] = []
    for key in node_keys:
        nodes[key] = []
    for k, env in enumerate(per_case):
        for line, data in env.items():
            n = len(data["s"])
            gp["case"].append(np.full(n, k))
            gp["line"].extend([line] * n)
            gp["s"].append(np.asarray(data["s"], float))
            for key in gp_keys:
                gp[key].append(np.asarray(data.get(key, [math.nan] * n), float))
            if "node_s" in data:
                m = len(data["node_s"])
                nodes["case"].append(np.full(m, k))
                nodes["line"].extend([line] * m)
                nodes["s"].append(np.asarray(data["node_s"], float))
                for key in node_keys:
                    nodes[key].append(np.asarray(data.get(key, [math.nan] * m), float))
    for name, table in (("envelope", gp), ("envelope_nodes", nodes)):
        if not table["s"]:
            continue
        g = f.create_group(name)
        for key, parts in table.items():
            if key == "line":
                g.create_dataset(key, data=np.array(parts, dtype=object),
                                 dtype=h5py.string_dtype())
            elif key == "case":
                g.create_dataset(key, data=np.concatenate(parts).astype(np.int32))
            else:
                g.create_dataset(key, data=np.concatenate(parts))


def read_summary(path) -> dict:
    """summary.h5 as {'columns': [...], 'cases': {col: array}, 'envelope': {key:
    array} or None, 'envelope_nodes': ..., 'attrs': {...}} (strings as str)."""
    import h5py

    path = Path(path)
    if path.is_dir():
        path = path / SUMMARY_H5
    with h5py.File(path, "r") as f:
        columns = [str(c) for c in f["cases"].attrs["columns"]]
        cases = {}
        for col in columns:
            ds = f["cases"][col]
            cases[col] = (ds.asstr()[...] if h5py.check_string_dtype(ds.dtype)
                          else ds[...])
        out = {"columns": columns, "cases": cases, "attrs": dict(f.attrs)}
        for name in ("envelope", "envelope_nodes"):
            if name in f:
                g = f[name]
                out[name] = {k: (g[k].asstr()[...] if h5py.check_string_dtype(g[k].dtype)
                                 else g[k][...]) for k in g}
            else:
                out[name] = None
    return out
