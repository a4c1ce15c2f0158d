"""Reader for the natural periods and mode shapes of a rodyn run (*MODAL).

The files are described in docs/output.md (static_modes.csv, static_mode_shapes.csv and
the /modes group of results.h5). `load_modes(path)` takes a results folder (or the path
of a results.h5) and returns a `ModalResults`, or None when the run computed no modes.

The static shape comes from `load_static` (results.h5 when present and of the same run
as status.txt, else the CSV tables), and the modes from the same source: from
results.h5, the periods and each line's node motions of /modes; from the CSV tables,
static_modes.csv and static_mode_shapes.csv. The dominant object and its share of each
mode's kinetic energy, and the motion of the FREE points and bodies, are only in the
CSV tables: read from them when they are there (CSV=YES) and of the same run (same
periods), else `dominant` is '' and `share` NaN for every mode and `objects` is empty.
The CSV fields carry 17 significant digits, so both sources give the same numbers.

Mode shapes are scaled as rodyn writes them: the largest translation of the whole
system is 1 m. Every problem with the files raises `RodynResultsError`.
"""
from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import RodynResultsError
from .results import H5_FILE, check_header, h5_units_checked, load_static
from .schema import header

MODES_CSV = "static_modes.csv"
SHAPES_CSV = "static_mode_shapes.csv"
MODES_HEADER = header(MODES_CSV)
SHAPES_HEADER = header(SHAPES_CSV)
# Datasets of /modes, of each line group of /modes (each (nm, nn)), attributes of /modes
H5_MODES_DATASETS = ("period_s", "frequency_hz", "omega_rad_s")
H5_SHAPE_DATASETS = ("ux", "uy", "uz", "rx", "ry", "rz")
H5_MODES_ATTRIBUTES = ("solver", "tangent_asymmetry")
_TEXT = {"dominant", "object"}
_INTEGER = {"mode", "node"}


@dataclass(frozen=True, eq=False)
class LineModes:
    """One line in every mode: its static shape and its nodes' motions (nm modes)."""
    name: str
    node_s: np.ndarray       # (nn,)        m    unstretched arc length S of the nodes
    node_xyz: np.ndarray     # (nn, 3)      m    static node positions (global axes)
    translation: np.ndarray  # (nm, nn, 3)  m    x, y, z translation of each node
    rotation: np.ndarray     # (nm, nn, 3)  rad  rotation about x, y, z (0: a cable's)

    def displaced(self, mode: int, scale: float) -> np.ndarray:
        """Node positions (nn, 3) of the static shape plus `scale` times mode `mode`
        (numbered from 1, as in static_modes.csv)."""
        return self.node_xyz + scale * self.translation[mode - 1]


@dataclass(frozen=True, eq=False)
class ObjectModes:
    """A FREE point or body in every mode (a body: the motion of its R)."""
    name: str
    translation: np.ndarray  # (nm, 3)  m    x, y, z translation
    rotation: np.ndarray     # (nm, 3)  rad  rotation about x, y, z (0 for a point)


@dataclass(frozen=True, eq=False)
class ModalResults:
    """The natural periods and mode shapes of a run, longest period first."""
    period_s: np.ndarray      # (nm,)  s
    frequency_hz: np.ndarray  # (nm,)  Hz
    dominant: tuple           # (nm,) of str: the line, point or body with the largest
                              # share of the mode's kinetic energy ('' when unknown)
    share: np.ndarray         # (nm,)  that share, 0 to 1 (NaN when unknown)
    lines: tuple              # of LineModes, deck order
    objects: tuple            # of ObjectModes: FREE points and bodies (CSV only)
    solver: str               # DENSE or LANCZOS ('' when read from CSV)
    tangent_asymmetry: float  # |K - K^T| / |K| of the tangent (NaN when read from CSV)
    folder: Path              # results folder
    source: Path              # file the line shapes came from

    @property
    def n_modes(self) -> int:
        return len(self.period_s)

    def line(self, name: str) -> LineModes:
        """The line called `name` (KeyError if there is none)."""
        for line in self.lines:
            if line.name == name:
                return line
        raise KeyError(name)

    def object(self, name: str) -> ObjectModes:
        """The FREE point or body called `name` (KeyError if there is none)."""
        for obj in self.objects:
            if obj.name == name:
                return obj
        raise KeyError(name)

    def extent(self) -> float:
        """The system's size: the largest extent along x, y or z of the static lines'
        nodes [m] (0 for a single point)."""
        xyz = np.concatenate([line.node_xyz for line in self.lines])
        return float(np.max(np.ptp(xyz, axis=0)))


def load_modes(path) -> ModalResults | None:
    """The modes in results folder `path` (or in the results.h5 file `path`); None when
    the run computed none (no /modes in results.h5, or no static_modes.csv)."""
    path = Path(path)
    if not path.exists():
        raise RodynResultsError(f"{path}: no such results folder")
    static = load_static(path)
    folder = static.folder
    csv_rows = _read_csv(folder) if (folder / MODES_CSV).is_file() else None
    if static.source.name == H5_FILE:
        return _from_h5(static, csv_rows)
    if csv_rows is None:
        return None
    return _from_csv(static, csv_rows)


# --- HDF5 ---------------------------------------------------------------------------

def _from_h5(static, csv_rows) -> ModalResults | None:
    import h5py

    path = static.source
    with h5py.File(path, "r") as f:
        modes = f.get("modes")
        if modes is None:
            return None
        if not isinstance(modes, h5py.Group):
            raise RodynResultsError(f"{path}: /modes is not a group")
        attrs = {}
        for key in H5_MODES_ATTRIBUTES:
            if key not in modes.attrs:
                raise RodynResultsError(f"{path}: attribute '{key}' missing on /modes")
            value = modes.attrs[key]
            attrs[key] = value.decode("utf-8") if isinstance(value, bytes) else value
        data = {k: _dataset(modes, k, path) for k in H5_MODES_DATASETS}
        nm = len(data["period_s"])
        for key, values in data.items():
            if values.shape != (nm,):
                raise RodynResultsError(f"{path}: /modes/{key} has shape {values.shape}, "
                                        f"expected ({nm},)")
        if nm < 1:
            raise RodynResultsError(f"{path}: /modes/period_s is empty")
        lines = []
        for group_name, line in zip(f["static"], static.lines):
            group = modes.get(group_name)
            if not isinstance(group, h5py.Group):
                raise RodynResultsError(f"{path}: group /modes/{group_name} missing "
                                        f"(line {line.name!r})")
            parts = [_dataset(group, k, path) for k in H5_SHAPE_DATASETS]
            want = (nm, len(line.node_s))
            for key, values in zip(H5_SHAPE_DATASETS, parts):
                if values.shape != want:
                    raise RodynResultsError(f"{path}: /modes/{group_name}/{key} has shape "
                                            f"{values.shape}, expected {want}")
            lines.append(LineModes(line.name, line.node_s, line.node_xyz,
                                   np.stack(parts[:3], axis=-1), np.stack(parts[3:], axis=-1)))
    dominant, share, objects = ("",) * nm, np.full(nm, np.nan), ()
    if csv_rows is not None and np.array_equal(csv_rows[0]["period_s"], data["period_s"]):
        modes_table, shape_rows = csv_rows
        dominant, share = modes_table["dominant"], modes_table["share"]
        objects = _objects(shape_rows, nm, static.folder / SHAPES_CSV)
    return ModalResults(
        period_s=data["period_s"], frequency_hz=data["frequency_hz"], dominant=dominant,
        share=share, lines=tuple(lines), objects=objects, solver=str(attrs["solver"]),
        tangent_asymmetry=float(attrs["tangent_asymmetry"]), folder=static.folder,
        source=path)


def _dataset(group, key, path) -> np.ndarray:
    import h5py

    data = group.get(key)
    if not isinstance(data, h5py.Dataset):
        raise RodynResultsError(f"{path}: dataset {group.name.rstrip('/')}/{key} missing")
    return np.asarray(h5_units_checked(data, path)[...], dtype=float)


# --- CSV ----------------------------------------------------------------------------

def _read_csv(folder: Path):
    """(modes, shape rows) of static_modes.csv and static_mode_shapes.csv: modes a dict
    column -> array (dominant a tuple of str), mode numbers checked to be 1..nm; shape
    rows a list of dicts column -> value."""
    path = folder / MODES_CSV
    rows = _rows(path, MODES_HEADER)
    if not rows:
        raise RodynResultsError(f"{path}: no rows")
    numbers = [row["mode"] for row in rows]
    if numbers != list(range(1, len(rows) + 1)):
        raise RodynResultsError(f"{path}: modes {numbers}, expected 1 to {len(rows)}")
    table = {c: np.array([row[c] for row in rows], dtype=float)
             for c in ("period_s", "frequency_hz", "share")}
    table["dominant"] = tuple(row["dominant"] for row in rows)
    shapes = folder / SHAPES_CSV
    if not shapes.is_file():
        raise RodynResultsError(f"{shapes}: file missing (written with {MODES_CSV})")
    return table, _rows(shapes, SHAPES_HEADER)


def _rows(path: Path, columns: tuple) -> list:
    """The rows of a CSV table as dicts column -> value (text, int or float)."""
    out = []
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        cols = check_header(path, next(reader, []), columns)
        for fields in reader:
            if not fields:
                continue
            where = f"{path}: line {reader.line_num}"
            if len(fields) != len(cols):
                raise RodynResultsError(f"{where}: {len(fields)} fields, expected {len(cols)}")
            row = {}
            for c, text in zip(cols, fields):
                if c in _TEXT:
                    row[c] = text
                    continue
                try:
                    row[c] = int(text) if c in _INTEGER else float(text)
                except ValueError:
                    raise RodynResultsError(f"{where}: column {c}: {text!r} is not "
                                            f"{'an integer' if c in _INTEGER else 'a number'}"
                                            ) from None
            out.append(row)
    return out


def _motions(rows, nm, n, where):
    """(translation, rotation), each (nm, n, 3), of the rows of one object (n per mode,
    in mode order)."""
    if len(rows) != nm * n:
        raise RodynResultsError(f"{where}: {len(rows)} rows, expected {nm} modes x {n}")
    if [row["mode"] for row in rows] != [k for k in range(1, nm + 1) for _ in range(n)]:
        raise RodynResultsError(f"{where}: rows not in mode order 1 to {nm}")
    values = np.array([[row[c] for c in ("x", "y", "z", "rx", "ry", "rz")] for row in rows],
                      dtype=float).reshape(nm, n, 6)
    return values[..., :3], values[..., 3:]


def _objects(shape_rows, nm, path) -> tuple:
    """ObjectModes of the rows with node 0 (FREE points and bodies), in file order."""
    rows = {}
    for row in shape_rows:
        if row["node"] == 0:
            rows.setdefault(row["object"], []).append(row)
    out = []
    for name, own in rows.items():
        translation, rotation = _motions(own, nm, 1, f"{path}: {name!r}")
        out.append(ObjectModes(name, translation[:, 0], rotation[:, 0]))
    return tuple(out)


def _from_csv(static, csv_rows) -> ModalResults:
    table, shape_rows = csv_rows
    nm = len(table["period_s"])
    path = static.folder / SHAPES_CSV
    per_line = {}
    for row in shape_rows:
        if row["node"] != 0:
            per_line.setdefault(row["object"], []).append(row)
    for name in per_line:
        if name not in [line.name for line in static.lines]:
            raise RodynResultsError(f"{path}: line {name!r} is not in the static results")
    lines = []
    for line in static.lines:
        rows = per_line.get(line.name)
        if rows is None:
            raise RodynResultsError(f"{path}: no rows for line {line.name!r}")
        nn = len(line.node_s)
        translation, rotation = _motions(rows, nm, nn, f"{path}: line {line.name!r}")
        if [row["node"] for row in rows[:nn]] != list(range(1, nn + 1)):
            raise RodynResultsError(f"{path}: line {line.name!r}: nodes not 1 to {nn}")
        lines.append(LineModes(line.name, line.node_s, line.node_xyz, translation, rotation))
    return ModalResults(
        period_s=table["period_s"], frequency_hz=table["frequency_hz"],
        dominant=table["dominant"], share=table["share"], lines=tuple(lines),
        objects=_objects(shape_rows, nm, path), solver="", tangent_asymmetry=float("nan"),
        folder=static.folder, source=path)
