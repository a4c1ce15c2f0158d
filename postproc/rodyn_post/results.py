"""Reader for the static results of a rodyn run.

The file layout is described in docs/output.md. `load_static(path)` takes a results
folder (or the path of a results.h5) and returns a `StaticResults`: run information
plus one `LineStatic` per line, in deck order, and the environment (None for a dry
deck). results.h5 is read with h5py when it is there; otherwise the CSV tables
(static_nodes.csv, static_elements.csv, static_reactions.csv, static_lines.csv,
environment.csv) and status.txt are read. Both give the same arrays: the CSV fields
carry 17 significant digits, so every binary64 value comes back exactly.

CSV columns are found by name, so extra columns are ignored. Results written before
rodyn had water (no wall_tension, seabed_*, touchdown) still read: wall tension =
effective tension, seabed forces 0, touchdown -1 (none).

Every problem with the files (missing folder, file, dataset or attribute, wrong
shape, bad CSV header, a field that is not a number) raises `RodynResultsError`,
whose message names the file and, for CSV, the line number.
"""
from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import RodynResultsError  # noqa: F401  (also importable from here)
from .schema import DATASETS, ENVIRONMENT, header

H5_FILE = "results.h5"
STATUS_FILE = "status.txt"
NODES_CSV = "static_nodes.csv"
ELEMENTS_CSV = "static_elements.csv"
REACTIONS_CSV = "static_reactions.csv"
LINES_CSV = "static_lines.csv"

# the columns of the tables, from the one description of the output (rodyn_post.schema)
NODES_HEADER = header(NODES_CSV)
ELEMENTS_HEADER = header(ELEMENTS_CSV)
LINES_HEADER = header(LINES_CSV)
OFFSET_CURVE_CSV = "static_offset_curve.csv"
OFFSET_CURVE_HEADER = header(OFFSET_CURVE_CSV)
# columns an older rodyn did not write (read as: wall = effective, seabed forces and
# hydro and seabed work 0); static and dynamic tables
OPTIONAL_COLUMNS = ("wall_tension_N", "seabed_normal_N_per_m", "seabed_friction_N_per_m",
                    "hydro_work_J", "seabed_work_J", "numerical_work_J",
                    "numerical_energy_J")
REACTIONS_HEADER = header(REACTIONS_CSV)

# Datasets of a line group in results.h5 and their shapes ('nn' nodes, 'ng' points).
H5_LINE_DATASETS = {
    "node_s": ("nn",), "node_xyz": ("nn", 3), "gp_s": ("ng",),
    "effective_tension": ("ng",), "shear": ("ng", 2), "moment": ("ng", 2),
    "torque": ("ng",), "curvature": ("ng", 3), "reactions": (2, 6),
}
# Datasets of the water physics (optional: absent in results of an older rodyn).
H5_WATER_DATASETS = {"wall_tension": ("ng",), "seabed_normal": ("nn",),
                     "seabed_friction": ("nn",)}
# Attributes read of the root, of /static (rodyn_post.schema.ATTRIBUTES has them all).
H5_ROOT_ATTRIBUTES = ("complete", "status", "title", "version", "deck_file")
H5_STATIC_ATTRIBUTES = ("load_factor", "increments", "iterations", "cutbacks", "wall_time_s")
# Keys of status.txt and how to read them.
STATUS_KEYS = {
    "complete": "bool", "status": "str", "load_factor": "float", "increments": "int",
    "iterations": "int", "cutbacks": "int", "wall_time_s": "float",
    "rodyn_version": "str", "deck": "str",
}
_INTEGER_COLUMNS = {"node", "element", "point"}
_TEXT_COLUMNS = {"line", "end", "key", "unit"}


@dataclass(frozen=True, eq=False)
class LineStatic:
    """Static results of one line, SI units, conventions of docs/output.md.

    Node arrays have nn rows (from end A), integration-point arrays ng rows.
    """
    name: str
    node_s: np.ndarray             # (nn,)    m    unstretched arc length S of the nodes
    node_xyz: np.ndarray           # (nn, 3)  m    node positions x, y, z (global)
    gp_s: np.ndarray               # (ng,)    m    S of the integration points
    effective_tension: np.ndarray  # (ng,)    N    N3, positive in tension
    shear: np.ndarray              # (ng, 2)  N    N1, N2
    moment: np.ndarray             # (ng, 2)  N m  M1, M2 (bending about d1, d2)
    torque: np.ndarray             # (ng,)    N m  M3
    curvature: np.ndarray          # (ng, 3)  1/m  K1, K2 (bending), K3 (twist)
    reactions: np.ndarray          # (2, 6)   N, N m  rows end A, B; Fx Fy Fz Mx My Mz
    end_held: np.ndarray           # (2,)     bool  end A, B has a support
    wall_tension: np.ndarray = None     # (ng,)  N    wall (true) tension
    seabed_normal: np.ndarray = None    # (nn,)  N/m  seabed normal force per length
    seabed_friction: np.ndarray = None  # (nn,)  N/m  seabed friction force per length
    touchdown_s: float = -1.0           # m  largest S in contact with the seabed; -1: none

    @property
    def moment_magnitude(self) -> np.ndarray:
        """Bending moment magnitude sqrt(M1^2 + M2^2) at the integration points [N m]."""
        return np.hypot(self.moment[:, 0], self.moment[:, 1])


@dataclass(frozen=True, eq=False)
class StaticResults:
    """Static results of a run: run information and the lines in deck order."""
    lines: tuple            # of LineStatic
    complete: bool          # the analysis reached its end
    status: str             # 'complete' or what failed
    load_factor: float      # static load factor reached
    increments: int
    iterations: int
    cutbacks: int
    wall_time_s: float
    title: str              # *HEADING text; '' when read from CSV (not stored there)
    version: str            # rodyn version
    deck_file: str          # main deck, as given to rodyn
    folder: Path            # results folder
    source: Path            # file the line data came from (results.h5 or static_nodes.csv)
    environment: object = field(default=None)  # environment.Environment; None: dry

    def line(self, name: str) -> LineStatic:
        """The line called `name` (KeyError if there is none)."""
        for line in self.lines:
            if line.name == name:
                return line
        raise KeyError(name)


def load_static(path) -> StaticResults:
    """Read the static results in folder `path` (or in the results.h5 file `path`).

    results.h5 is used when present, unless status.txt shows that it was left by an
    earlier run (docs/output.md: old files are not deleted); otherwise the CSV tables.
    """
    path = Path(path)
    if path.is_file():
        if path.suffix != ".h5":
            raise RodynResultsError(f"{path}: expected a results folder or a results.h5 file")
        return _read_h5(path)
    if not path.is_dir():
        raise RodynResultsError(f"{path}: no such results folder")
    status_path = path / STATUS_FILE
    status = _read_status(status_path) if status_path.is_file() else None
    if status is not None:
        status["dynamic"] = _read_key_values(status_path).get("dynamic") == "true"
    if (path / H5_FILE).is_file():
        results = _read_h5(path / H5_FILE)
        if status is None or _same_run(results, status):
            return results
    elif not (path / NODES_CSV).is_file():
        raise RodynResultsError(f"{path}: no rodyn results here (neither {H5_FILE} "
                                f"nor {NODES_CSV})")
    if status is None:
        raise RodynResultsError(f"{status_path}: missing (it says whether the run completed)")
    return _read_csv_folder(path, status)


def _same_run(results: StaticResults, status: dict) -> bool:
    """Whether results.h5 and status.txt come from the same run (the statics' counters
    and wall time; a dynamic run's status.txt gives the wall time of the statics and the
    time loop together, so for it the counters alone)."""
    keys = ["load_factor", "increments", "iterations", "cutbacks"]
    if not status.get("dynamic"):
        keys.append("wall_time_s")
    return all(vars(results)[k] == status[k] for k in keys)


def _make_line(name, arrays, where) -> LineStatic:
    """LineStatic from a dict of arrays named as in H5_LINE_DATASETS plus end_held,
    after checking the shapes; `where` names the data in error messages."""
    sizes = {}
    for key, shape in H5_LINE_DATASETS.items():
        data = arrays[key]
        expected = tuple(sizes.setdefault(d, n) if isinstance(d, str) else d
                         for d, n in zip(shape, data.shape))
        if data.ndim != len(shape) or data.shape != expected:
            want = "(" + ", ".join(str(sizes.get(d, d)) for d in shape) + ")"
            raise RodynResultsError(f"{where}: {key} has shape {data.shape}, expected {want}")
    if sizes["nn"] < 2 or sizes["ng"] < 1:
        raise RodynResultsError(f"{where}: {sizes['nn']} nodes and {sizes['ng']} "
                                "integration points; need at least 2 and 1")
    water = water_defaults(arrays, sizes["nn"])
    for key, shape in H5_WATER_DATASETS.items():
        want = tuple(sizes[d] for d in shape)
        if water[key].shape != want:
            raise RodynResultsError(f"{where}: {key} has shape {water[key].shape}, "
                                    f"expected {want}")
    return LineStatic(name=name, end_held=np.asarray(arrays["end_held"], dtype=bool),
                      touchdown_s=float(arrays.get("touchdown_s", -1.0)), **water,
                      **{k: np.asarray(arrays[k], dtype=float) for k in H5_LINE_DATASETS})


def water_defaults(arrays, nn) -> dict:
    """wall_tension, seabed_normal, seabed_friction of `arrays` as float arrays, with the
    dry values where missing (None): the effective tension, zeros at the nn nodes."""
    def given(key, default):
        value = arrays.get(key)
        return np.asarray(default if value is None else value, dtype=float)
    zeros = np.zeros(np.shape(arrays["effective_tension"])[:-1] + (nn,))
    return {"wall_tension": given("wall_tension", arrays["effective_tension"]),
            "seabed_normal": given("seabed_normal", zeros),
            "seabed_friction": given("seabed_friction", zeros)}


# --- HDF5 ---------------------------------------------------------------------------

def _read_h5(path: Path) -> StaticResults:
    """Static results from a results.h5 file."""
    import h5py  # only needed here: the CSV fallback works without h5py

    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise RodynResultsError(f"{path}: cannot read as HDF5 ({exc})") from None
    with f:
        info = {k: _h5_attr(f, k, path) for k in H5_ROOT_ATTRIBUTES}
        static = f.get("static")
        if not isinstance(static, h5py.Group):
            raise RodynResultsError(f"{path}: group /static missing")
        counters = {k: _h5_attr(static, k, path) for k in H5_STATIC_ATTRIBUTES}
        lines = []
        for group in static.values():
            if not isinstance(group, h5py.Group):
                raise RodynResultsError(f"{path}: {group.name} is not a line group")
            arrays = {k: _h5_dataset(group, k, path)[...] for k in H5_LINE_DATASETS}
            for k in H5_WATER_DATASETS:
                if isinstance(group.get(k), h5py.Dataset):
                    arrays[k] = _h5_dataset(group, k, path)[...]
            if "touchdown_s" in group.attrs:
                arrays["touchdown_s"] = _h5_attr(group, "touchdown_s", path)
            arrays["end_held"] = _h5_attr(_h5_dataset(group, "reactions", path),
                                          "end_held", path)
            lines.append(_make_line(str(_h5_attr(group, "name", path)), arrays,
                                    f"{path}: {group.name}"))
        from .environment import environment_of
        environment = environment_of(f, path)
    if not lines:
        raise RodynResultsError(f"{path}: no lines in /static")
    return StaticResults(
        lines=tuple(lines), complete=bool(info["complete"]), status=str(info["status"]),
        load_factor=float(counters["load_factor"]), increments=int(counters["increments"]),
        iterations=int(counters["iterations"]), cutbacks=int(counters["cutbacks"]),
        wall_time_s=float(counters["wall_time_s"]), title=str(info["title"]),
        version=str(info["version"]), deck_file=str(info["deck_file"]),
        folder=path.parent, source=path, environment=environment)


def _h5_attr(obj, key, path):
    """Attribute `key` of an HDF5 object; str for strings, Python/numpy values else."""
    if key not in obj.attrs:
        raise RodynResultsError(f"{path}: attribute '{key}' missing on {obj.name}")
    value = obj.attrs[key]
    if isinstance(value, bytes):
        value = value.decode("utf-8")
    return value.item() if isinstance(value, np.generic) else value


def _h5_dataset(group, key, path):
    """Dataset `key` of an HDF5 group, after checking its own `units` attribute against
    the schema (h5_units_checked)."""
    import h5py

    data = group.get(key)
    if not isinstance(data, h5py.Dataset):
        raise RodynResultsError(f"{path}: dataset {group.name.rstrip('/')}/{key} missing")
    h5_units_checked(data, path)
    return data


def h5_units_checked(data, path):
    """A dataset of results.h5 or dynamic.h5 whose `units` attribute is those rodyn_post
    reads it in (rodyn_post.schema.DATASETS, ENVIRONMENT for /environment; SI, degrees
    for the angles of /environment, docs/output.md); RodynResultsError
    otherwise. A dataset without the attribute (an older rodyn) or not in the schema
    passes."""
    parts = data.name.split("/")
    file = {"static": "results.h5", "modes": "results.h5",
            "dynamic": "dynamic.h5"}.get(parts[1])
    if (file is None and parts[1] != "environment") or "units" not in data.attrs:
        return data
    key = data.name
    if len(parts) == 4 and parts[2] not in ("log", "sea"):
        key = f"/{parts[1]}/LINE/{parts[3]}"
    known = (ENVIRONMENT if file is None else DATASETS[file]).get(key)
    units = data.attrs["units"]
    if isinstance(units, bytes):
        units = units.decode("utf-8")
    if known is not None and str(units) != known[0]:
        raise RodynResultsError(f"{path}: {data.name} is in {units!r}, rodyn_post reads it "
                                f"in {known[0]!r} (docs/output.md)")
    return data


# --- CSV + status.txt ---------------------------------------------------------------

def _read_status(path: Path, keys: dict = None) -> dict:
    """status.txt as a dict of typed values for `keys` (name -> 'str', 'int', 'float' or
    'bool'; default STATUS_KEYS). Shared by the static and the dynamic reader."""
    keys = STATUS_KEYS if keys is None else keys
    raw = _read_key_values(path)
    status = {}
    for key, kind in keys.items():
        if key not in raw:
            raise RodynResultsError(f"{path}: key '{key}' missing")
        value = raw[key]
        try:
            if kind == "bool":
                status[key] = {"true": True, "false": False}[value]
            else:
                status[key] = {"str": str, "int": int, "float": float}[kind](value)
        except (KeyError, ValueError):
            raise RodynResultsError(f"{path}: {key} = {value!r} is not a valid {kind}") from None
    return status


def _read_key_values(path: Path) -> dict:
    """The 'key = value' lines of a status file, values as text."""
    raw = {}
    with open(path, encoding="utf-8") as f:
        for number, text in enumerate(f, 1):
            if text.strip():
                key, sep, value = text.partition("=")
                if not sep:
                    raise RodynResultsError(f"{path}: line {number}: expected 'key = value', "
                                            f"got {text.strip()!r}")
                raw[key.strip()] = value.strip()
    return raw


def _read_csv_folder(folder: Path, status: dict) -> StaticResults:
    """Static results from the CSV tables of `folder` and its status.txt."""
    from .environment import load_environment
    nodes = _read_table(folder / NODES_CSV, NODES_HEADER)
    points = _read_table(folder / ELEMENTS_CSV, ELEMENTS_HEADER)
    supports = _read_table(folder / REACTIONS_CSV, REACTIONS_HEADER)
    touchdown = {}
    if (folder / LINES_CSV).is_file():
        touchdown = {name: rows[0]["touchdown_s_m"]
                     for name, rows in _read_table(folder / LINES_CSV, LINES_HEADER).items()}
    for file, table in ((ELEMENTS_CSV, points), (REACTIONS_CSV, supports)):
        for name in table:
            if name not in nodes:
                raise RodynResultsError(f"{folder / file}: line {name!r} is not in {NODES_CSV}")
    if not nodes:
        raise RodynResultsError(f"{folder / NODES_CSV}: no lines (header only)")
    lines = []
    for name, node_rows in nodes.items():
        if name not in points:
            raise RodynResultsError(f"{folder / ELEMENTS_CSV}: no rows for line {name!r}")
        lines.append(_csv_line(name, node_rows, points[name], supports.get(name, []),
                               f"{folder}: line {name!r}", touchdown.get(name, -1.0)))
    return StaticResults(
        lines=tuple(lines), complete=status["complete"], status=status["status"],
        load_factor=status["load_factor"], increments=status["increments"],
        iterations=status["iterations"], cutbacks=status["cutbacks"],
        wall_time_s=status["wall_time_s"], title="", version=status["rodyn_version"],
        deck_file=status["deck"], folder=folder, source=folder / NODES_CSV,
        environment=load_environment(folder))


def _csv_line(name, node_rows, point_rows, support_rows, where, touchdown=-1.0) -> LineStatic:
    """LineStatic from the CSV rows of one line (rows are dicts column -> value)."""
    def columns(rows, *names):
        return np.array([[row[c] for c in names] for row in rows], dtype=float)

    reactions = np.zeros((2, 6))
    end_held = np.zeros(2, dtype=bool)
    for row in support_rows:
        end = "AB".index(row["end"])
        reactions[end] = [row[c] for c in REACTIONS_HEADER[2:8]]
        end_held[end] = True
    arrays = {
        "node_s": columns(node_rows, "s_m")[:, 0],
        "node_xyz": columns(node_rows, "x_m", "y_m", "z_m"),
        "gp_s": columns(point_rows, "s_m")[:, 0],
        "effective_tension": columns(point_rows, "effective_tension_N")[:, 0],
        "shear": columns(point_rows, "shear_1_N", "shear_2_N"),
        "moment": columns(point_rows, "moment_1_Nm", "moment_2_Nm"),
        "torque": columns(point_rows, "torque_Nm")[:, 0],
        "curvature": columns(point_rows, "curvature_1_per_m", "curvature_2_per_m",
                             "twist_per_m"),
        "reactions": reactions, "end_held": end_held, "touchdown_s": touchdown,
    }
    for key, rows, column in (("wall_tension", point_rows, "wall_tension_N"),
                              ("seabed_normal", node_rows, "seabed_normal_N_per_m"),
                              ("seabed_friction", node_rows, "seabed_friction_N_per_m")):
        if column in rows[0]:
            arrays[key] = columns(rows, column)[:, 0]
    return _make_line(name, arrays, where)


def load_offset_curve(folder) -> dict:
    """The offset curve of a body (*OFFSET CURVE) in results folder `folder`
    (static_offset_curve.csv, docs/output.md): {"body": name, column: float array for
    every other column}; {} when the run wrote none."""
    path = Path(folder) / OFFSET_CURVE_CSV
    if not path.is_file():
        return {}
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        cols = check_header(path, next(reader, []), OFFSET_CURVE_HEADER)
        rows = [fields for fields in reader if fields]
    if not rows:
        raise RodynResultsError(f"{path}: no rows")
    out = {"body": rows[0][cols.index("body")]}
    for j, c in enumerate(cols):
        if c == "body":
            continue
        try:
            out[c] = np.array([float(r[j]) for r in rows])
        except (ValueError, IndexError) as e:
            raise RodynResultsError(f"{path}: column {c}: {e}") from None
    return out


def check_header(path: Path, first: list, header: tuple) -> tuple:
    """The columns of a CSV file whose first row is `first`, after checking that it
    holds every column of `header` but OPTIONAL_COLUMNS (found by name: their order
    and extra columns do not matter)."""
    missing = [c for c in header if c not in first and c not in OPTIONAL_COLUMNS]
    if missing or len(set(first)) != len(first):
        raise RodynResultsError(f"{path}: line 1: header is {','.join(first)!r}, "
                                f"expected {','.join(header)!r}")
    return tuple(first)


def _read_table(path: Path, header: tuple) -> dict:
    """Rows of a rodyn CSV table grouped by line name, lines in order of first
    appearance: {name: [row, ...]}, each row a dict column -> converted value.
    Columns are found by name (check_header)."""
    if not path.is_file():
        raise RodynResultsError(f"{path}: file missing")
    table = {}
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        header = check_header(path, next(reader, []), header)
        for fields in reader:
            if not fields:
                continue  # blank line
            where = f"{path}: line {reader.line_num}"
            if len(fields) != len(header):
                raise RodynResultsError(f"{where}: {len(fields)} fields, expected {len(header)}")
            row = {c: _field(text, c, where) for c, text in zip(header, fields)}
            table.setdefault(row["line"], []).append(row)
    return table


def _field(text: str, column: str, where: str):
    """Value of one CSV field: str for `line`, 'A'/'B' for `end`, int or float else."""
    if column in _TEXT_COLUMNS and column != "end":
        return text
    if column == "end":
        if text in ("A", "B"):
            return text
        expected = "A or B"
    else:
        kind, expected = (int, "an integer") if column in _INTEGER_COLUMNS else (float, "a number")
        try:
            return kind(text)
        except ValueError:
            pass
    raise RodynResultsError(f"{where}: column {column}: {text!r} is not {expected}")
