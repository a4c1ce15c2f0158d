"""Reader for the sea and vessel outputs of a dynamic run (docs/output.md, "Waves and
vessels"): the wave elevation at the probes of *WAVE PROBE (dynamic_waves.csv), the pose
of each vessel and the total force of its lines on it (dynamic_vessels.csv), and the
force of each line end fixed to a vessel (dynamic_connections.csv), at the frames and, in
the `_step` tables, at every time step (step 0: the start).

`read_sea(folder, status, warnings)` returns a `Sea`, or None when the run wrote none of
these tables (a deck without probes or vessels). Without the CSV tables (`CSV=NO`) the
same values are read from dynamic.h5's /dynamic/sea (h5py), up to the frames and steps
status.txt says were committed. Tables are read up to the committed size
status.txt gives for them (`committed_bytes.NAME`), like the other tables of a live or
killed run; a last time with missing rows is dropped with a warning. Column names and
units come from rodyn_post.schema (the one description of the output).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import RodynResultsError
from .schema import header

WAVES_CSV = "dynamic_waves.csv"
WAVES_STEP_CSV = "dynamic_waves_step.csv"
VESSELS_CSV = "dynamic_vessels.csv"
VESSELS_STEP_CSV = "dynamic_vessels_step.csv"
CONNECTIONS_CSV = "dynamic_connections.csv"
CONNECTIONS_STEP_CSV = "dynamic_connections_step.csv"

# the key columns of each table (what a row is about) and the values after them
_KEYS = {"waves": ("probe",), "vessels": ("vessel",), "connections": ("vessel", "line", "end")}
_FILES = {"waves": (WAVES_CSV, WAVES_STEP_CSV), "vessels": (VESSELS_CSV, VESSELS_STEP_CSV),
          "connections": (CONNECTIONS_CSV, CONNECTIONS_STEP_CSV)}


@dataclass(frozen=True, eq=False)
class SeaSeries:
    """One probe, vessel or connection: its values at the frames and at every step.

    `columns` names the value columns (as in the table, units in the names); `frames`
    is (nf, nc) at `time`, `steps` (ns1, nc) at `step_time` (0, then each step's end),
    `step` the step numbers. Use `frame_column` / `step_column` to pick one by name."""
    key: tuple
    columns: tuple
    time: np.ndarray
    frames: np.ndarray
    step: np.ndarray
    step_time: np.ndarray
    steps: np.ndarray

    def frame_column(self, name: str) -> np.ndarray:
        """One column at the frames (KeyError: no such column)."""
        return self.frames[:, self.columns.index(name)]

    def step_column(self, name: str) -> np.ndarray:
        """One column at every step (KeyError: no such column)."""
        return self.steps[:, self.columns.index(name)]


@dataclass(frozen=True, eq=False)
class Sea:
    """The sea and vessel outputs: {probe name: SeaSeries}, {vessel name: SeaSeries},
    {(vessel, line, end): SeaSeries}; each empty when the run wrote no such table."""
    probes: dict
    vessels: dict
    connections: dict


def read_sea(folder, status, warnings: list):
    """The sea and vessel tables of results folder `folder` (None when there are none).
    `status`: status.txt as rodyn_post.dynamic reads it (committed sizes), or None."""
    folder = Path(folder)
    if not any((folder / f).is_file() for pair in _FILES.values() for f in pair):
        if (folder / "dynamic.h5").is_file():
            return _read_sea_h5(folder / "dynamic.h5", status)
        return None
    out = {}
    for kind, (frame_file, step_file) in _FILES.items():
        out[kind] = {}
        if not (folder / frame_file).is_file() and not (folder / step_file).is_file():
            continue
        frames = _grouped(folder / frame_file, _KEYS[kind], False, status, warnings)
        steps = _grouped(folder / step_file, _KEYS[kind], True, status, warnings)
        columns = header(frame_file)[1 + len(_KEYS[kind]):]
        for key in frames[1]:
            if key not in steps[1]:
                raise RodynResultsError(f"{folder / step_file}: no rows for {key!r}")
            out[kind][key if len(key) > 1 else key[0]] = SeaSeries(
                key=key, columns=columns, time=frames[0], frames=frames[1][key],
                step=steps[2], step_time=steps[0], steps=steps[1][key])
    return Sea(probes=out["waves"], vessels=out["vessels"], connections=out["connections"])


def _grouped(path: Path, keys: tuple, with_step: bool, status, warnings: list) -> tuple:
    """(times (n,), {key: values (n, nc)}, step numbers (n,) or None) of one table: rows
    grouped by time, each time with one row per key (those of the first time); a last
    time with fewer rows (a kill while writing) is dropped with a warning."""
    from .dynamic import _read_rows   # (the CSV reading of the other tables)
    expected = header(path.name)
    cols, rows = _read_rows(path, expected, warnings, status)
    index = {c: cols.index(c) for c in expected}
    lead = (("step",) if with_step else ()) + ("time_s",) + keys
    values = [c for c in expected if c not in lead]
    times, step_numbers, groups = [], [], []
    for number, fields in rows:
        try:
            t = float(fields[index["time_s"]])
            step = int(fields[index["step"]]) if with_step else None
            vals = [float(fields[index[c]]) for c in values]
        except ValueError:
            raise RodynResultsError(f"{path}: line {number}: not a number") from None
        key = tuple(fields[index[c]] for c in keys)
        new_time = not times or (step != step_numbers[-1] if with_step else t != times[-1])
        if new_time:
            times.append(t)
            step_numbers.append(step)
            groups.append({})
        if key in groups[-1]:
            raise RodynResultsError(f"{path}: line {number}: {key!r} twice at t = {t!r}")
        groups[-1][key] = vals
    order = list(groups[0]) if groups else []
    n = len(groups)
    if n and set(groups[-1]) != set(order):
        if len(groups[-1]) < len(order) and set(groups[-1]) <= set(order):
            warnings.append(f"{path.name}: last time (t = {times[-1]:g} s) incomplete, "
                            "dropped")
            n -= 1
        else:
            raise RodynResultsError(f"{path}: rows at t = {times[-1]!r} are not those of "
                                    "the first time")
    for i in range(n):
        if set(groups[i]) != set(order):
            raise RodynResultsError(f"{path}: rows at t = {times[i]!r} are not those of "
                                    "the first time")
    data = {key: np.array([groups[i][key] for i in range(n)], dtype=float).reshape(
        n, len(values)) for key in order}
    steps = np.array(step_numbers[:n], dtype=int) if with_step else None
    return np.array(times[:n], dtype=float), data, steps


def _read_sea_h5(path: Path, status):
    """The Sea of dynamic.h5's /dynamic/sea (None when it has none): the same columns as
    the CSV tables (x_m, y_m of a probe from probe_xy); frames and steps cut to those
    status.txt commits (`frames`, and the steps up to the last committed frame's time).
    The layout is the file's own: the items are those its attributes probes, vessels and
    connections name, each item's columns a dataset's width over their number; these
    must add up to the columns of the matching table of the schema (RodynResultsError)."""
    import h5py

    from .results import _h5_dataset
    with h5py.File(path, "r", locking=False) as f:
        if "dynamic/sea" not in f:
            return None
        g = f["dynamic/sea"]
        time = _h5_dataset(f["dynamic"], "time", path)[...]
        step_time = _h5_dataset(g, "step_time", path)[...]
        n_f = len(time)
        if status and status.get("frames") is not None:
            n_f = min(n_f, status["frames"])
        n_s = len(step_time)
        if n_f < len(time) and n_f > 0:
            n_s = int(np.count_nonzero(step_time <= time[n_f - 1]))
        time, step_time = time[:n_f], step_time[:n_s]
        step = np.arange(n_s)

        def split(attr):
            text = g.attrs.get(attr, "")
            text = text.decode() if isinstance(text, bytes) else str(text)
            return [t for t in text.split(", ") if t]

        def data(name, n):
            return _h5_dataset(g, name, path)[:n]   # its units checked

        def widths(names, table, lead, *datasets):
            """Columns per item of each dataset (its width over the items' number),
            checked against the schema's columns of `table` after `lead` key columns."""
            out = []
            for name in datasets:
                width, rest = divmod(_h5_dataset(g, name, path).shape[1], len(names))
                if rest or width < 1:
                    raise RodynResultsError(
                        f"{path}: /dynamic/sea/{name} has {width * len(names) + rest} "
                        f"columns, not a multiple of the {len(names)} names {names}")
                out.append(width)
            if sum(out) != len(header(table)) - lead:
                raise RodynResultsError(
                    f"{path}: /dynamic/sea/{', '.join(datasets)} hold {sum(out)} columns "
                    f"per item, the schema's {table} {len(header(table)) - lead}")
            return out

        out = {"waves": {}, "vessels": {}, "connections": {}}
        names = split("probes")
        if names:
            widths(names, WAVES_CSV, 4, "probe_elevation")   # time, probe, x, y lead
            widths(names, WAVES_CSV, 4, "step_probe_elevation")
            xy = _h5_dataset(g, "probe_xy", path)[...]
            fr, st = data("probe_elevation", n_f), data("step_probe_elevation", n_s)
            for k, name in enumerate(names):
                def cols(a, n):
                    return np.column_stack([np.full(n, xy[k, 0]), np.full(n, xy[k, 1]), a[:, k]])
                out["waves"][name] = SeaSeries(
                    key=(name,), columns=header(WAVES_CSV)[2:], time=time,
                    frames=cols(fr, n_f), step=step, step_time=step_time,
                    steps=cols(st, n_s))
        names = split("vessels")
        if names:
            a, b = widths(names, VESSELS_CSV, 2, "vessel_motion", "vessel_load")
            widths(names, VESSELS_CSV, 2, "step_vessel_motion", "step_vessel_load")
            m, sm = data("vessel_motion", n_f), data("step_vessel_motion", n_s)
            ld, sl = data("vessel_load", n_f), data("step_vessel_load", n_s)
            for k, name in enumerate(names):
                out["vessels"][name] = SeaSeries(
                    key=(name,), columns=header(VESSELS_CSV)[2:], time=time,
                    frames=np.column_stack([m[:, a * k:a * k + a], ld[:, b * k:b * k + b]]),
                    step=step, step_time=step_time,
                    steps=np.column_stack([sm[:, a * k:a * k + a], sl[:, b * k:b * k + b]]))
        names = split("connections")
        if names:
            w, = widths(names, CONNECTIONS_CSV, 4, "connection_load")
            widths(names, CONNECTIONS_CSV, 4, "step_connection_load")
            c, sc = data("connection_load", n_f), data("step_connection_load", n_s)
            for k, name in enumerate(names):
                key = tuple(name.split("/"))
                out["connections"][key] = SeaSeries(
                    key=key, columns=header(CONNECTIONS_CSV)[4:], time=time,
                    frames=c[:, w * k:w * k + w], step=step, step_time=step_time,
                    steps=sc[:, w * k:w * k + w])
    return Sea(probes=out["waves"], vessels=out["vessels"], connections=out["connections"])
