"""Reader for the dynamic results of a rodyn run.

The file layout is described in docs/output.md ("Dynamic runs"). `load_dynamic(path)`
takes a results folder (or the path of a dynamic.h5) and returns a `DynamicResults`:
run information, the frame times, one `LineDynamic` per line (deck order) and the step
log (`StepLog`, one row per time step). dynamic.h5 is read with h5py when it is there
(opened with locking=False, so a run still going can be read); otherwise the CSV tables
(dynamic_nodes.csv, dynamic_elements.csv, dynamic_ends.csv, dynamic_log.csv,
dynamic_ends_step.csv) and status.txt. Both give the same arrays: the CSV fields carry 17
significant digits. The support forces of every step (`DynamicResults.step_time`,
`LineDynamic.step_reactions`, `step_end_tension`) are empty in results of a rodyn that
did not write them; `LineDynamic.end_tension_series()` picks them when there.

A run that was killed or failed is read up to what it committed: status.txt gives the
frames and the bytes of each CSV table at the last sync (`frames`,
`committed_bytes.NAME`); anything beyond (a kill inside a sync) is an uncommitted tail,
ignored with a warning, in the CSV tables as in a dynamic.h5 still marked running.
Without those keys (an older rodyn) a last frame with missing rows, or a last row cut
short, is dropped (docs/output.md, "After a killed or failed run").

Every problem with the files raises `RodynResultsError` (from rodyn_post.errors),
whose message names the file and, for CSV, the line number.
"""
from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass, field, fields, replace
from pathlib import Path

import numpy as np

from .errors import RodynResultsError
from .results import _h5_attr, _h5_dataset, _read_key_values
from .results import _read_status as _read_static_status
from .results import check_header, water_defaults
from .schema import header
from .sea import read_sea

H5_FILE = "dynamic.h5"
STATUS_FILE = "status.txt"
NODES_CSV = "dynamic_nodes.csv"
ELEMENTS_CSV = "dynamic_elements.csv"
ENDS_CSV = "dynamic_ends.csv"
ENDS_STEP_CSV = "dynamic_ends_step.csv"
LOG_CSV = "dynamic_log.csv"
LINES_CSV = "dynamic_lines.csv"
# status.txt key of a table's committed size: committed_bytes.dynamic_nodes.csv = 12345
COMMITTED_PREFIX = "committed_bytes."

# the columns of the tables, from the one description of the output (rodyn_post.schema)
NODES_HEADER = header(NODES_CSV)
ELEMENTS_HEADER = header(ELEMENTS_CSV)
LINES_HEADER = header(LINES_CSV)
ENDS_HEADER = header(ENDS_CSV)
ENDS_STEP_HEADER = header(ENDS_STEP_CSV)
LOG_HEADER = header(LOG_CSV)

# Datasets of a line group in dynamic.h5: shapes ('nf' frames, 'nn' nodes, 'ng' points).
H5_LINE_DATASETS = {
    "node_s": ("nn",), "gp_s": ("ng",), "gp_element": ("ng",), "gp_point": ("ng",),
    "x": ("nf", "nn"), "y": ("nf", "nn"), "z": ("nf", "nn"),
    "effective_tension": ("nf", "ng"), "moment_1": ("nf", "ng"), "moment_2": ("nf", "ng"),
    "torque": ("nf", "ng"), "bending_curvature": ("nf", "ng"), "reactions": ("nf", 12),
    "end_tension": ("nf", 2),
}
# Datasets of the water physics (optional: absent in results of an older rodyn).
H5_WATER_DATASETS = {"wall_tension": ("nf", "ng"), "seabed_normal": ("nf", "nn"),
                     "seabed_friction": ("nf", "nn"), "touchdown_s": ("nf",)}
# Datasets of /dynamic/log: (name in the file, shape) per StepLog field.
H5_LOG_DATASETS = {
    "step": ("ns",), "time": ("ns",), "dt": ("ns",), "iterations": ("ns",),
    "cutbacks": ("ns",), "kinetic": ("ns",), "strain": ("ns",), "gravity": ("ns",),
    "external_work": ("ns",), "damping_work": ("ns",), "total": ("ns",),
    "momentum": ("ns", 3), "angular_momentum": ("ns", 3),
    "hydro_work": ("ns",), "seabed_work": ("ns",),
    "numerical_work": ("ns",), "numerical_energy": ("ns",),
}
_OPTIONAL_LOG = ("hydro_work", "seabed_work", "numerical_work", "numerical_energy")
_LOG_INTEGERS = ("step", "iterations", "cutbacks")
# Attributes read of the root, of /dynamic (at the end of a run): all in
# rodyn_post.schema.ATTRIBUTES.
H5_ROOT_ATTRIBUTES = ("complete", "status", "title", "version", "deck_file", "scheme", "dt")
H5_DYNAMIC_ATTRIBUTES = ("steps", "step_iterations", "step_cutbacks", "time_reached_s",
                         "wall_time_s")
# Keys of a dynamic run's status.txt and how to read them (docs/output.md).
STATUS_KEYS = {
    "complete": "bool", "status": "str", "load_factor": "float", "increments": "int",
    "iterations": "int", "cutbacks": "int", "wall_time_s": "float", "dynamic": "bool",
    "time_reached_s": "float", "steps": "int", "step_iterations": "int",
    "step_cutbacks": "int", "rodyn_version": "str", "deck": "str",
}


@dataclass(frozen=True, eq=False)
class LineDynamic:
    """Time histories of one line, SI units, conventions of docs/output.md.

    Frame arrays have nf rows (one per output frame); node columns run from end A.
    """
    name: str
    node_s: np.ndarray             # (nn,)      m    unstretched arc length S of the nodes
    gp_s: np.ndarray               # (ng,)      m    S of the integration points
    gp_element: np.ndarray         # (ng,)      -    element of each point, from 1
    gp_point: np.ndarray           # (ng,)      -    point within its element, from 1
    x: np.ndarray                  # (nf, nn)   m    node positions, global axes
    y: np.ndarray                  # (nf, nn)   m
    z: np.ndarray                  # (nf, nn)   m
    effective_tension: np.ndarray  # (nf, ng)   N    N3, positive in tension
    moment_1: np.ndarray           # (nf, ng)   N m  M1 about d1
    moment_2: np.ndarray           # (nf, ng)   N m  M2 about d2
    torque: np.ndarray             # (nf, ng)   N m  M3 about d3
    bending_curvature: np.ndarray  # (nf, ng)   1/m  sqrt(K1^2 + K2^2)
    reactions: np.ndarray          # (nf, 12)   N, N m  Fx Fy Fz Mx My Mz at A, then at B
    end_tension: np.ndarray        # (nf, 2)    N    |support force| at A, B (0 if free)
    end_held: np.ndarray           # (2,)       bool end A, B has a support
    wall_tension: np.ndarray = None     # (nf, ng)  N    wall (true) tension
    seabed_normal: np.ndarray = None    # (nf, nn)  N/m  seabed normal force per length
    seabed_friction: np.ndarray = None  # (nf, nn)  N/m  seabed friction force per length
    touchdown_s: np.ndarray = None      # (nf,)     m    largest S on the seabed; -1: none
    step_reactions: np.ndarray = None   # (ns1, 12) N, N m  as reactions, every step
    step_end_tension: np.ndarray = None  # (ns1, 2)  N    as end_tension, every step

    def xyz(self, frame: int) -> np.ndarray:
        """Node positions (nn, 3) of one frame [m]."""
        return np.column_stack([self.x[frame], self.y[frame], self.z[frame]])

    def __post_init__(self):
        for key, cols in (("step_reactions", 12), ("step_end_tension", 2)):
            if getattr(self, key) is None:   # not written (an older rodyn): no rows
                object.__setattr__(self, key, np.zeros((0, cols)))

    @property
    def top_end(self) -> int:
        """0 if end A is the higher end at the first frame, else 1 (end B)."""
        return 0 if self.z[0, 0] >= self.z[0, -1] else 1


@dataclass(frozen=True, eq=False)
class StepLog:
    """The step log: one entry per converged time step (docs/output.md, dynamic_log.csv)."""
    step: np.ndarray              # (ns,)    -        step number, from 1
    time: np.ndarray              # (ns,)    s        time at the end of the step
    dt: np.ndarray                # (ns,)    s        step length used
    iterations: np.ndarray        # (ns,)    -        Newton iterations of the step
    cutbacks: np.ndarray          # (ns,)    -        halvings the step needed
    kinetic: np.ndarray           # (ns,)    J
    strain: np.ndarray            # (ns,)    J
    gravity: np.ndarray           # (ns,)    J        potential of the weight
    external_work: np.ndarray     # (ns,)    J        since t = 0
    damping_work: np.ndarray      # (ns,)    J        since t = 0
    total: np.ndarray             # (ns,)    J        kinetic + strain + gravity
    momentum: np.ndarray          # (ns, 3)  kg m/s
    angular_momentum: np.ndarray  # (ns, 3)  kg m2/s
    hydro_work: np.ndarray = None   # (ns,)  J   by the water since t = 0 (0 if not logged)
    seabed_work: np.ndarray = None  # (ns,)  J   by the seabed since t = 0 (0 if not logged)
    # the dissipative EMC (theory.md eq. (128)): its numerical stress's work since t = 0
    # and its numerical energy N (0 if not logged)
    numerical_work: np.ndarray = None     # (ns,)  J
    numerical_energy: np.ndarray = None   # (ns,)  J

    def __post_init__(self):
        for key in _OPTIONAL_LOG:   # not given: 0 (a run without water)
            if getattr(self, key) is None:
                object.__setattr__(self, key, np.zeros(np.shape(self.time)))

    def __len__(self) -> int:
        return len(self.step)

    @property
    def net_work(self) -> np.ndarray:
        """Work done on the lines since t = 0: external + hydro + seabed - damping -
        numerical [J]."""
        return (self.external_work + self.hydro_work + self.seabed_work - self.damping_work
                - self.numerical_work)

    @property
    def initial_total(self) -> float:
        """Total energy at t = 0 [J], from the first step: total(step 1) minus the net
        work of that step (the log has no row for t = 0). nan for an empty log."""
        if len(self) == 0:
            return float("nan")
        return float(self.total[0] - self.net_work[0])

    @property
    def energy_change(self) -> np.ndarray:
        """total(t) - total(0) [J]."""
        return self.total - self.initial_total

    @property
    def energy_error(self) -> np.ndarray:
        """Energy balance error (total(t) - total(0)) - (external - damping work) [J]."""
        return self.energy_change - self.net_work

    def relative_energy_error(self) -> float:
        """max |energy_error| / the largest |work| done on the lines (external, hydro
        or seabed; nan without work or steps)."""
        if len(self) == 0:
            return float("nan")
        scale = float(max(np.max(np.abs(w)) for w in
                          (self.external_work, self.hydro_work, self.seabed_work)))
        if scale == 0.0:
            return float("nan")
        return float(np.max(np.abs(self.energy_error))) / scale


@dataclass(frozen=True, eq=False)
class DynamicResults:
    """Dynamic results of a run: run information, frames, lines (deck order), step log."""
    time: np.ndarray         # (nf,) s, time of each frame
    lines: tuple             # of LineDynamic
    log: StepLog
    complete: bool           # the analysis reached its end
    status: str              # 'complete', what failed, or 'running'
    steps: int               # time steps completed
    step_iterations: int     # Newton iterations over all steps
    step_cutbacks: int       # step halvings in total
    time_reached_s: float    # last time reached [s]
    wall_time_s: float       # as recorded by rodyn (nan if not recorded)
    scheme: str              # 'EMC', ...; '' when read from CSV (not stored there)
    dt: float                # *DYNAMIC DT [s]; from the log when read from CSV
    title: str               # *HEADING text; '' when read from CSV
    deck: str                # deck text; '' when read from CSV
    version: str
    deck_file: str
    folder: Path
    source: Path             # dynamic.h5 or dynamic_nodes.csv
    warnings: tuple = field(default=())  # what was dropped or looked odd
    environment: object = field(default=None)  # environment.Environment; None: dry
    step_time: np.ndarray = field(default_factory=lambda: np.zeros(0))
    # (ns1,) s, times of the support forces of every step: 0, then each step's end
    sea: object = field(default=None)  # sea.Sea: probes, vessels, connections; None: none
    ramp_s: float = 0.0      # longest ramp-in of motions, waves, current [s]; 0 from CSV

    def line(self, name: str) -> LineDynamic:
        """The line called `name` (KeyError if there is none)."""
        for line in self.lines:
            if line.name == name:
                return line
        raise KeyError(name)

    def end_tension_series(self, line: LineDynamic) -> tuple:
        """(time (n,), end tension (n, 2)) of a line: the series of every step when the
        run wrote it (extremes at the ends then do not depend on the frame interval),
        else the frames'."""
        if len(self.step_time) and len(line.step_end_tension) == len(self.step_time):
            return self.step_time, line.step_end_tension
        return self.time, line.end_tension

    def frame_at(self, t: float) -> int:
        """Index of the frame nearest to time t."""
        return int(np.argmin(np.abs(self.time - t)))

    def motion_frequencies(self) -> list:
        """Frequencies [Hz] of the harmonic *MOTION cards of the deck (needs the deck
        text, i.e. dynamic.h5); [] when unknown."""
        return harmonic_frequencies(self.deck)


def harmonic_frequencies(deck: str) -> list:
    """Non-zero frequencies [Hz] on the data lines of *MOTION, TYPE=HARMONIC cards."""
    freqs, in_harmonic = [], False
    for raw in deck.splitlines():
        text = raw.strip()
        if not text or text.startswith("**"):
            continue
        if text.startswith("*"):
            upper = re.sub(r"\s+", "", text.upper())
            in_harmonic = upper.startswith("*MOTION,") and "TYPE=HARMONIC" in upper
            continue
        if in_harmonic:
            parts = [p.strip() for p in text.split(",")]
            try:
                f = float(parts[2])
            except (IndexError, ValueError):
                continue
            if f > 0.0:
                freqs.append(f)
    return freqs


def load_dynamic(path) -> DynamicResults:
    """Read the dynamic results in folder `path` (or in the dynamic.h5 file `path`).

    dynamic.h5 is used when present, unless status.txt shows that it was left by an
    earlier run (other step counters); otherwise the CSV tables. The sea and vessel
    tables (dynamic_waves.csv, dynamic_vessels.csv, dynamic_connections.csv and their
    _step tables; rodyn_post.sea) are read from the folder when there, into `sea`.
    """
    results = _load_dynamic(Path(path))
    folder = Path(path) if Path(path).is_dir() else Path(path).parent
    status_path = folder / STATUS_FILE
    warnings = list(results.warnings)
    status = _read_status(status_path) if status_path.is_file() else None
    sea = read_sea(folder, status, warnings)
    if sea is None:
        return results
    return replace(results, sea=sea, warnings=tuple(warnings))


def _load_dynamic(path: Path) -> DynamicResults:
    """load_dynamic without the sea tables."""
    if path.is_file():
        if path.suffix != ".h5":
            raise RodynResultsError(f"{path}: expected a results folder or a dynamic.h5 file")
        return _read_h5(path, None)
    if not path.is_dir():
        raise RodynResultsError(f"{path}: no such results folder")
    status_path = path / STATUS_FILE
    status = _read_status(status_path) if status_path.is_file() else None
    have_csv = (path / NODES_CSV).is_file()
    if (path / H5_FILE).is_file():
        results = _read_h5(path / H5_FILE, status)
        if status is None or not have_csv or _same_run(results, status):
            return results
    elif not have_csv:
        raise RodynResultsError(f"{path}: no dynamic results here (neither {H5_FILE} "
                                f"nor {NODES_CSV})")
    if status is None:
        raise RodynResultsError(f"{status_path}: missing (it says whether the run completed)")
    return _read_csv_folder(path, status)


def _same_run(results: DynamicResults, status: dict) -> bool:
    """Whether dynamic.h5 and status.txt come from the same run. A finished dynamic.h5
    carries the step counters of its run; one still being written does not (then it
    belongs to the run status.txt describes as running)."""
    if not results.complete and results.status == "running":
        return not status["complete"]
    return (results.steps, results.step_iterations, results.step_cutbacks) == (
        status["steps"], status["step_iterations"], status["step_cutbacks"])


def _check_shapes(arrays: dict, spec: dict, sizes: dict, where: str):
    """Check arrays against shapes of `spec` ('nf', 'nn', ... fixed via `sizes`)."""
    for key, shape in spec.items():
        data = arrays[key]
        expected = tuple(sizes.setdefault(d, n) if isinstance(d, str) else d
                         for d, n in zip(shape, data.shape))
        if data.ndim != len(shape) or data.shape != expected:
            want = "(" + ", ".join(str(sizes.get(d, d)) for d in shape) + ")"
            raise RodynResultsError(f"{where}: {key} has shape {data.shape}, expected {want}")


def _make_line(name, arrays, n_frames, where) -> LineDynamic:
    """LineDynamic from arrays named as in H5_LINE_DATASETS plus end_held."""
    sizes = {"nf": n_frames}
    _check_shapes(arrays, H5_LINE_DATASETS, sizes, where)
    if sizes["nn"] < 2 or sizes["ng"] < 1:
        raise RodynResultsError(f"{where}: {sizes['nn']} nodes and {sizes['ng']} "
                                "integration points; need at least 2 and 1")
    values = {k: np.asarray(arrays[k], dtype=int if k in ("gp_element", "gp_point")
                            else float) for k in H5_LINE_DATASETS}
    values.update(water_defaults(arrays, sizes["nn"]))
    touchdown = arrays.get("touchdown_s")
    values["touchdown_s"] = np.asarray(np.full(n_frames, -1.0) if touchdown is None
                                       else touchdown, dtype=float)
    _check_shapes(values, H5_WATER_DATASETS, sizes, where)
    for key, cols in (("step_reactions", 12), ("step_end_tension", 2)):
        step = arrays.get(key)
        if step is not None:
            values[key] = np.asarray(step, dtype=float)
            if values[key].ndim != 2 or values[key].shape[1] != cols:
                raise RodynResultsError(f"{where}: {key} has shape {values[key].shape}, "
                                        f"expected (n_steps + 1, {cols})")
    return LineDynamic(name=name, end_held=np.asarray(arrays["end_held"], dtype=bool),
                       **values)


def _same_step_rows(step_time, lines) -> tuple:
    """(step_time, lines) with the support forces of every step cut to the rows all of
    them hold (a run killed while writing them)."""
    n = min([len(step_time)] + [len(line.step_end_tension) for line in lines] +
            [len(line.step_reactions) for line in lines])
    return step_time[:n], [replace(line, step_reactions=line.step_reactions[:n],
                                   step_end_tension=line.step_end_tension[:n])
                           for line in lines]


def _make_log(arrays, where) -> StepLog:
    arrays = dict(arrays)
    for key in _OPTIONAL_LOG:   # not logged by an older rodyn: 0
        if arrays.get(key) is None:
            arrays[key] = np.zeros(np.shape(arrays["time"]))
    _check_shapes(arrays, H5_LOG_DATASETS, {}, where)
    return StepLog(**{k: np.asarray(arrays[k], dtype=int if k in _LOG_INTEGERS else float)
                      for k in H5_LOG_DATASETS})


# --- HDF5 ---------------------------------------------------------------------------

def _read_h5(path: Path, status) -> DynamicResults:
    """Dynamic results from a dynamic.h5 file (status: status.txt values or None)."""
    import h5py  # only needed here: the CSV fallback works without h5py

    try:
        f = h5py.File(path, "r", locking=False)
    except OSError as exc:
        raise RodynResultsError(f"{path}: cannot read as HDF5 ({exc})") from None
    with f:
        info = {k: _h5_attr(f, k, path) for k in H5_ROOT_ATTRIBUTES}
        dyn = f.get("dynamic")
        if not isinstance(dyn, h5py.Group):
            raise RodynResultsError(f"{path}: group /dynamic missing")
        time = np.asarray(_h5_dataset(dyn, "time", path)[...], dtype=float)
        if time.ndim != 1:
            raise RodynResultsError(f"{path}: /dynamic/time has shape {time.shape}, "
                                    "expected (n_frames,)")
        log_group = dyn.get("log")
        if not isinstance(log_group, h5py.Group):
            raise RodynResultsError(f"{path}: group /dynamic/log missing")
        log = _make_log({k: _h5_dataset(log_group, k, path)[...] for k in H5_LOG_DATASETS
                         if k not in _OPTIONAL_LOG or k in log_group},
                        f"{path}: /dynamic/log")
        lines = []
        step_time = np.zeros(0)   # the same in every line group (rodyn writes them alike)
        for key, group in dyn.items():
            if key in ("time", "log", "sea"):
                continue
            if not isinstance(group, h5py.Group):
                raise RodynResultsError(f"{path}: {group.name} is not a line group")
            arrays = {k: _h5_dataset(group, k, path)[...] for k in H5_LINE_DATASETS}
            for k in H5_WATER_DATASETS:
                if isinstance(group.get(k), h5py.Dataset):
                    arrays[k] = _h5_dataset(group, k, path)[...]
            arrays["end_held"] = _h5_attr(_h5_dataset(group, "reactions", path),
                                          "end_held", path)
            for k in ("step_reactions", "step_end_tension"):
                if isinstance(group.get(k), h5py.Dataset) and "step_time" in group:
                    arrays[k] = np.asarray(_h5_dataset(group, k, path)[...], dtype=float)
            if isinstance(group.get("step_time"), h5py.Dataset):
                step_time = np.asarray(_h5_dataset(group, "step_time", path)[...],
                                       dtype=float)
            lines.append(_make_line(str(_h5_attr(group, "name", path)), arrays, len(time),
                                    f"{path}: {group.name}"))
        from .environment import environment_of
        environment = environment_of(f, path)
        deck = f["deck"].asstr()[()] if isinstance(f.get("deck"), h5py.Dataset) else ""
        finished = "steps" in dyn.attrs
        ramp = float(dyn.attrs.get("ramp_s", 0.0))
        counters = {}
        if finished:
            counters = {k: _h5_attr(dyn, k, path) for k in H5_DYNAMIC_ATTRIBUTES}
    if not lines:
        raise RodynResultsError(f"{path}: no lines in /dynamic")
    step_time, lines = _same_step_rows(step_time, lines)
    warnings = []
    if not finished and status is not None and status.get("frames") is not None:
        time, log, step_time, lines = _committed_h5(time, log, step_time, lines, status,
                                                    path, warnings)
    if not finished:  # running or killed: counters from what was flushed
        counters = {"steps": len(log), "step_iterations": int(log.iterations.sum()),
                    "step_cutbacks": int(log.cutbacks.sum()),
                    "time_reached_s": float(time[-1]) if len(time) else 0.0,
                    "wall_time_s": float("nan")}
    return DynamicResults(
        time=time, lines=tuple(lines), log=log, complete=bool(info["complete"]),
        status=str(info["status"]), steps=int(counters["steps"]),
        step_iterations=int(counters["step_iterations"]),
        step_cutbacks=int(counters["step_cutbacks"]),
        time_reached_s=float(counters["time_reached_s"]),
        wall_time_s=float(counters["wall_time_s"]), scheme=str(info["scheme"]),
        dt=float(info["dt"]), title=str(info["title"]), deck=str(deck),
        version=str(info["version"]), deck_file=str(info["deck_file"]),
        folder=path.parent, source=path, environment=environment,
        step_time=step_time, warnings=tuple(warnings), ramp_s=ramp)


def _committed_h5(time, log, step_time, lines, status, path, warnings) -> tuple:
    """(time, log, step_time, lines) of a dynamic.h5 still marked running cut to what
    status.txt says was committed: `frames` frames, `steps` log rows, and the support
    forces of the steps up to the last committed one (by time). Rows beyond are an
    uncommitted tail (a kill inside a sync), ignored with a warning."""
    n_frames, n_steps = status["frames"], status["steps"]
    if len(time) < n_frames or len(log) < n_steps:   # not status.txt's run: as it is
        warnings.append(f"{path.name}: {len(time)} frames and {len(log)} steps, fewer than "
                        f"the {n_frames} and {n_steps} status.txt says were committed")
        return time, log, step_time, lines
    if len(time) == n_frames and len(log) == n_steps:
        return time, log, step_time, lines
    warnings.append(f"{path.name}: {len(time) - n_frames} frames and {len(log) - n_steps} "
                    "steps beyond those committed in status.txt (an uncommitted tail), "
                    "ignored")
    t_last = log.time[n_steps - 1] if n_steps else status["time_reached_s"]
    n_rows = int(np.count_nonzero(step_time <= t_last))
    log = replace(log, **{f.name: getattr(log, f.name)[:n_steps] for f in fields(log)})
    per_frame = [k for k, shape in {**H5_LINE_DATASETS, **H5_WATER_DATASETS}.items()
                 if shape[0] == "nf"]
    lines = [replace(line, **{k: getattr(line, k)[:n_frames] for k in per_frame},
                     step_reactions=line.step_reactions[:n_rows],
                     step_end_tension=line.step_end_tension[:n_rows]) for line in lines]
    return time[:n_frames], log, step_time[:n_rows], lines






# --- CSV + status.txt ---------------------------------------------------------------

def _read_status(path: Path) -> dict:
    """status.txt of a dynamic run as a dict of typed values (keys of STATUS_KEYS), plus
    `frames` (int; None when absent: an older rodyn) and `committed` ({table: bytes},
    from the keys committed_bytes.NAME; empty when absent)."""
    raw = _read_key_values(path)
    if raw.get("dynamic") != "true":
        raise RodynResultsError(f"{path}: not the status of a dynamic run (no "
                                "'dynamic = true')")
    status = _read_static_status(path, STATUS_KEYS)
    status["frames"], status["committed"] = None, {}
    for key, value in raw.items():
        if key != "frames" and not key.startswith(COMMITTED_PREFIX):
            continue
        try:
            number = int(value)
        except ValueError:
            raise RodynResultsError(f"{path}: {key} = {value!r} is not a valid int") from None
        if key == "frames":
            status["frames"] = number
        else:
            status["committed"][key[len(COMMITTED_PREFIX):]] = number
    return status



def _committed_text(path: Path, status: dict, warnings: list) -> str:
    """The text of a CSV table up to its committed size in status.txt (the whole file
    when status.txt gives none); a longer file's tail is ignored with a warning. A file
    shorter than that (cut after the run) is read as it is, with a warning: its last
    frame or step, if cut short, is then dropped as for an older rodyn."""
    data = path.read_bytes()
    limit = (status or {}).get("committed", {}).get(path.name)
    if limit is not None:
        if len(data) < limit:
            warnings.append(f"{path.name}: {len(data)} bytes, shorter than the {limit} "
                            f"status.txt says were committed")
        elif len(data) > limit:
            warnings.append(f"{path.name}: {len(data) - limit} bytes beyond the committed "
                            f"size in status.txt (an uncommitted tail), ignored")
            data = data[:limit]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise RodynResultsError(f"{path}: not UTF-8 text ({exc})") from None


def _read_rows(path: Path, header: tuple, warnings: list, status: dict = None) -> tuple:
    """(columns of the file, rows as lists of strings) of a rodyn CSV table up to its
    committed size (`status`: status.txt values or None): the file must hold the columns
    of `header` (by name; results.check_header). A last row with the wrong number of
    fields (cut short by a kill) is dropped with a warning."""
    if not path.is_file():
        raise RodynResultsError(f"{path}: file missing")
    text = _committed_text(path, status, warnings)
    with io.StringIO(text, newline="") as f:
        reader = csv.reader(f)
        header = check_header(path, next(reader, []), header)
        rows, bad = [], None
        for fields in reader:
            if not fields:
                continue
            if bad is not None:  # a short row followed by more rows: malformed
                raise RodynResultsError(f"{path}: line {bad[0]}: {bad[1]} fields, "
                                        f"expected {len(header)}")
            if len(fields) != len(header):
                bad = (reader.line_num, len(fields))
                continue
            rows.append((reader.line_num, fields))
    if bad is not None:
        warnings.append(f"{path.name}: last row (line {bad[0]}) cut short, dropped")
    return header, rows


def _column(rows, index, column, kind, path):
    """One column of rows as a numpy array of `kind` (float or int)."""
    out = np.empty(len(rows), dtype=kind)
    for i, (number, fields) in enumerate(rows):
        try:
            out[i] = kind(fields[index])
        except ValueError:
            raise RodynResultsError(f"{path}: line {number}: column {column}: "
                                    f"{fields[index]!r} is not "
                                    f"{'an integer' if kind is int else 'a number'}") from None
    return out


def _frames(rows, header, path, integer_columns=()):
    """Rows grouped into frames: (times (nf,), {line: {column: (nf, n) array}}).

    Each frame holds the same rows per line; a last frame with fewer rows (a kill
    while writing it) is reported as `short` so that the caller can drop it."""
    columns = {c: _column(rows, i, c, int if c in integer_columns else float, path)
               for i, c in enumerate(header) if c not in ("line", "end")}
    names = [fields[1] for _, fields in rows]
    times = columns["time_s"]
    # frame boundaries: where the time changes
    starts = np.flatnonzero(np.r_[True, times[1:] != times[:-1]])
    counts = np.diff(np.r_[starts, len(rows)])
    return columns, names, times[starts], starts, counts


def _read_csv_folder(folder: Path, status: dict) -> DynamicResults:
    """Dynamic results from the CSV tables of `folder` and its status.txt."""
    from .environment import load_environment
    warnings = []
    node_head, node_rows = _read_rows(folder / NODES_CSV, NODES_HEADER, warnings, status)
    point_head, point_rows = _read_rows(folder / ELEMENTS_CSV, ELEMENTS_HEADER, warnings,
                                        status)
    end_head, end_rows = _read_rows(folder / ENDS_CSV, ENDS_HEADER, warnings, status)
    log_head, log_rows = _read_rows(folder / LOG_CSV, LOG_HEADER, warnings, status)
    for name, rows in ((NODES_CSV, node_rows), (ELEMENTS_CSV, point_rows)):
        if not rows:
            raise RodynResultsError(f"{folder / name}: no frames (header only)")

    nodes = _frames(node_rows, node_head, folder / NODES_CSV, ("node",))
    points = _frames(point_rows, point_head, folder / ELEMENTS_CSV, ("element", "point"))
    # frames: those of the nodes table; the last one may be short in any table
    times = nodes[2]
    n_frames = len(times)
    full = {}
    for name, table in ((NODES_CSV, nodes), (ELEMENTS_CSV, points)):
        counts = table[4]
        if len(counts) and np.any(counts[:-1] != counts[0]):
            k = int(np.flatnonzero(counts[:-1] != counts[0])[0])
            raise RodynResultsError(f"{folder / name}: frame at t = {table[2][k]!r} has "
                                    f"{counts[k]} rows, the first frame {counts[0]}")
        full[name] = len(counts) > 0 and counts[-1] == counts[0]
        n_frames = min(n_frames, len(counts) if full[name] else len(counts) - 1)
    if n_frames < len(times):
        warnings.append(f"last frame (t = {times[-1]:g} s) incomplete, dropped")
    times = times[:n_frames]
    for name, table in ((ELEMENTS_CSV, points),):
        if not np.array_equal(table[2][:n_frames], times):
            raise RodynResultsError(f"{folder / name}: frame times differ from {NODES_CSV}")

    lines = []
    per_frame_nodes = int(nodes[4][0])
    per_frame_points = int(points[4][0]) if len(points[4]) else 0
    node_names = nodes[1][:per_frame_nodes]
    point_names = points[1][:per_frame_points]
    line_names = list(dict.fromkeys(node_names))
    for name in dict.fromkeys(point_names):
        if name not in line_names:
            raise RodynResultsError(f"{folder / ELEMENTS_CSV}: line {name!r} is not in "
                                    f"{NODES_CSV}")
    ends, complete_frames = _ends(end_rows, end_head, folder / ENDS_CSV, times, line_names)
    touchdown = _touchdown(folder / LINES_CSV, times, line_names, warnings, status)
    step_time, step_ends = _ends_step(folder / ENDS_STEP_CSV, ends, warnings, status)
    if complete_frames < n_frames:
        warnings.append(f"last frame (t = {times[-1]:g} s) incomplete in {ENDS_CSV}, "
                        "dropped")
        n_frames = complete_frames
        times = times[:n_frames]
        for line in ends.values():
            line["reactions"] = line["reactions"][:n_frames]
            line["end_tension"] = line["end_tension"][:n_frames]
    for name in line_names:
        nsel = np.array([n == name for n in node_names])
        psel = np.array([n == name for n in point_names], dtype=bool)
        if not psel.any():
            raise RodynResultsError(f"{folder / ELEMENTS_CSV}: no rows for line {name!r}")

        def block(table, sel, column, per_frame):
            data = table[0][column][:n_frames * per_frame].reshape(n_frames, per_frame)
            return data[:, sel]

        arrays = {
            "node_s": block(nodes, nsel, "s_m", per_frame_nodes)[0],
            "x": block(nodes, nsel, "x_m", per_frame_nodes),
            "y": block(nodes, nsel, "y_m", per_frame_nodes),
            "z": block(nodes, nsel, "z_m", per_frame_nodes),
            "gp_s": block(points, psel, "s_m", per_frame_points)[0],
            "gp_element": block(points, psel, "element", per_frame_points)[0],
            "gp_point": block(points, psel, "point", per_frame_points)[0],
            "effective_tension": block(points, psel, "effective_tension_N", per_frame_points),
            "moment_1": block(points, psel, "moment_1_Nm", per_frame_points),
            "moment_2": block(points, psel, "moment_2_Nm", per_frame_points),
            "torque": block(points, psel, "torque_Nm", per_frame_points),
            "bending_curvature": block(points, psel, "curvature_per_m", per_frame_points),
        }
        for key, table, sel, column, per_frame in (
                ("wall_tension", points, psel, "wall_tension_N", per_frame_points),
                ("seabed_normal", nodes, nsel, "seabed_normal_N_per_m", per_frame_nodes),
                ("seabed_friction", nodes, nsel, "seabed_friction_N_per_m", per_frame_nodes)):
            if column in table[0]:
                arrays[key] = block(table, sel, column, per_frame)
        if name in touchdown:
            arrays["touchdown_s"] = touchdown[name][:n_frames]
        arrays.update(ends[name])
        arrays.update(step_ends.get(name, {}))
        lines.append(_make_line(name, arrays, n_frames, f"{folder}: line {name!r}"))

    log = _make_log(_log_arrays(log_rows, log_head, folder / LOG_CSV), f"{folder / LOG_CSV}")
    dt = float(log.dt.max()) if len(log) else float("nan")
    return DynamicResults(
        time=times, lines=tuple(lines), log=log, complete=status["complete"],
        status=status["status"], steps=status["steps"],
        step_iterations=status["step_iterations"], step_cutbacks=status["step_cutbacks"],
        time_reached_s=status["time_reached_s"], wall_time_s=status["wall_time_s"],
        scheme="", dt=dt, title="", deck="", version=status["rodyn_version"],
        deck_file=status["deck"], folder=folder, source=folder / NODES_CSV,
        warnings=tuple(warnings), environment=load_environment(folder),
        step_time=step_time)


def _touchdown(path, times, line_names, warnings, status=None) -> dict:
    """{line: touchdown S per frame (nf,)} from dynamic_lines.csv ({} when the file is
    missing, as in the results of an older rodyn); frames without a row read -1."""
    if not path.is_file():
        return {}
    header, rows = _read_rows(path, LINES_HEADER, warnings, status)
    index = {t: i for i, t in enumerate(times)}
    out = {name: np.full(len(times), -1.0) for name in line_names}
    col_t, col_line, col_s = (header.index(c) for c in LINES_HEADER)
    for number, fields in rows:
        try:
            t, s = float(fields[col_t]), float(fields[col_s])
        except ValueError:
            raise RodynResultsError(f"{path}: line {number}: not a number") from None
        if t in index and fields[col_line] in out:
            out[fields[col_line]][index[t]] = s
    return out


def _ends(rows, header, path, times, line_names):
    """reactions (nf, 12), end_tension (nf, 2), end_held (2,) of every line from the
    rows of dynamic_ends.csv (held ends only; free ends stay zero), and the number of
    frames that have all their rows (the last one may be cut short by a kill)."""
    n_frames = len(times)
    out = {name: {"reactions": np.zeros((n_frames, 12)), "end_tension": np.zeros((n_frames, 2)),
                  "end_held": np.zeros(2, dtype=bool)} for name in line_names}
    index = {t: i for i, t in enumerate(times)}
    seen = {}
    for number, fields in rows:
        where = f"{path}: line {number}"
        try:
            t = float(fields[header.index("time_s")])
        except ValueError:
            raise RodynResultsError(f"{where}: column time_s: {fields[0]!r} is not "
                                    "a number") from None
        name, end = fields[header.index("line")], fields[header.index("end")]
        if name not in out:
            raise RodynResultsError(f"{where}: line {name!r} is not in {NODES_CSV}")
        if end not in ("A", "B"):
            raise RodynResultsError(f"{where}: column end: {end!r} is not A or B")
        k = "AB".index(end)
        if t not in index:
            if t > times[-1]:
                continue  # rows of a dropped last frame
            raise RodynResultsError(f"{where}: time {t!r} is not a frame of {NODES_CSV}")
        values = []
        for column in ENDS_HEADER[3:]:
            text = fields[header.index(column)]
            try:
                values.append(float(text))
            except ValueError:
                raise RodynResultsError(f"{where}: column {column}: {text!r} is not "
                                        "a number") from None
        i = index[t]
        line = out[name]
        line["reactions"][i, 6 * k:6 * k + 6] = values[:6]
        line["end_tension"][i, k] = values[6]
        line["end_held"][k] = True
        seen[(name, k, i)] = True
    complete_frames = n_frames
    for name, line in out.items():
        for k in (0, 1):
            if line["end_held"][k]:
                missing = [i for i in range(n_frames) if (name, k, i) not in seen]
                if missing and missing[0] < n_frames - 1:
                    raise RodynResultsError(f"{path}: no row for line {name!r} end "
                                            f"{'AB'[k]} at t = {times[missing[0]]!r}")
                if missing:
                    complete_frames = n_frames - 1
    return out, complete_frames


def _ends_step(path, ends, warnings, status=None) -> tuple:
    """(step_time (ns1,), {line: {step_reactions (ns1, 12), step_end_tension (ns1, 2)}})
    from dynamic_ends_step.csv (empty when the file is missing: an older rodyn). Each
    step has one row per held end (`ends`: the frames' end_held); a last step with
    fewer rows (a kill while writing) is dropped."""
    if not path.is_file():
        return np.zeros(0), {}
    header, rows = _read_rows(path, ENDS_STEP_HEADER, warnings, status)
    held = [(name, k) for name, line in ends.items() for k in (0, 1) if line["end_held"][k]]
    col = {c: header.index(c) for c in ENDS_STEP_HEADER}
    steps, times, values = [], [], {}
    for number, fields in rows:
        try:
            step, t = int(fields[col["step"]]), float(fields[col["time_s"]])
            vals = [float(fields[col[c]]) for c in ENDS_STEP_HEADER[4:]]
        except ValueError:
            raise RodynResultsError(f"{path}: line {number}: not a number") from None
        key = (fields[col["line"]], "AB".find(fields[col["end"]]))
        if key not in held:
            raise RodynResultsError(f"{path}: line {number}: line {key[0]!r} end "
                                    f"{fields[col['end']]!r} is not a held end of the frames")
        if not steps or steps[-1] != step:
            steps.append(step)
            times.append(t)
        values[(len(steps) - 1,) + key] = vals
    n = len(steps)
    if n and any((n - 1,) + key not in values for key in held):
        warnings.append(f"{path.name}: last step ({steps[-1]}) incomplete, dropped")
        n -= 1
    out = {name: {"step_reactions": np.zeros((n, 12)), "step_end_tension": np.zeros((n, 2))}
           for name in ends}
    for i in range(n):
        for name, k in held:
            vals = values.get((i, name, k))
            if vals is None:
                raise RodynResultsError(f"{path}: no row for line {name!r} end {'AB'[k]} "
                                        f"at step {steps[i]}")
            out[name]["step_reactions"][i, 6 * k:6 * k + 6] = vals[:6]
            out[name]["step_end_tension"][i, k] = vals[6]
    return np.asarray(times[:n], dtype=float), out


def _log_arrays(rows, header, path) -> dict:
    """The step log columns under the StepLog names (hydro and seabed work None when the
    log has no such columns)."""
    cols = {c: _column(rows, i, c, int if c in ("step", "iterations", "cutbacks") else float,
                       path) for i, c in enumerate(header) if c in LOG_HEADER}
    return {
        "step": cols["step"], "time": cols["time_s"], "dt": cols["dt_s"],
        "iterations": cols["iterations"], "cutbacks": cols["cutbacks"],
        "kinetic": cols["kinetic_J"], "strain": cols["strain_J"],
        "gravity": cols["gravity_J"], "external_work": cols["external_work_J"],
        "damping_work": cols["damping_work_J"], "total": cols["total_J"],
        "hydro_work": cols.get("hydro_work_J"), "seabed_work": cols.get("seabed_work_J"),
        "numerical_work": cols.get("numerical_work_J"),
        "numerical_energy": cols.get("numerical_energy_J"),
        "momentum": np.column_stack([cols["px"], cols["py"], cols["pz"]]).reshape(-1, 3),
        "angular_momentum": np.column_stack([cols["Lx"], cols["Ly"], cols["Lz"]]).reshape(-1, 3),
    }
