"""The sea of a rodyn run: still water level, depth, current profile and seabed.

rodyn writes the environment of a deck with *WATER once per run (docs/output.md,
"Environment"): the /environment group of results.h5 and dynamic.h5, and
environment.csv (key, value, unit rows) for runs with CSV tables only. A dry deck
writes none: `load_environment` then returns None, and the plots draw no sea.

Geometry (as rodyn's seabed_t): the seabed is the plane through (0, 0, surface - depth)
rising at angle `slope` towards the horizontal heading `slope_dir` (from +x towards
+y), z_bed(x, y) = surface - depth + tan(slope) (x cos(slope_dir) + y sin(slope_dir)).
The current flows towards `heading` (same convention); its speed is linear in z between
the profile levels and constant beyond them.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import RodynResultsError
from .schema import ENVIRONMENT, header

ENVIRONMENT_CSV = "environment.csv"
ENVIRONMENT_HEADER = header(ENVIRONMENT_CSV)  # rodyn_post.schema
_PROFILE = ("current_z", "current_speed", "current_heading")
# units of the keys of environment.csv / datasets of /environment, as rodyn_post reads
# them: the schema's (rodyn_post.schema.ENVIRONMENT); the counts current_levels and
# seabed are dimensionless. A file that gives another unit is refused.
KEY_UNITS = {**{p.rsplit("/", 1)[1]: u for p, (u, _) in ENVIRONMENT.items()},
         "current_levels": "-", "seabed": "-"}
# scalar keys of environment.csv / datasets of /environment
_SCALARS = tuple(k for k in KEY_UNITS if k not in _PROFILE + ("current_levels", "seabed"))
_REQUIRED = ("surface_z", "depth", "density")


@dataclass(frozen=True, eq=False)
class Environment:
    """The water of a run, SI units except angles (degrees, as written)."""
    surface_z: float                  # m     z of the still water level
    depth: float                      # m     water depth at x = y = 0
    density: float                    # kg/m3
    current_z: np.ndarray             # (nc,) m    profile levels, increasing
    current_speed: np.ndarray         # (nc,) m/s
    current_heading: np.ndarray       # (nc,) deg  towards, from +x towards +y
    current_ramp: float = 0.0         # s
    seabed: bool = False              # a seabed is modelled
    seabed_slope: float = 0.0         # deg
    seabed_slope_dir: float = 0.0     # deg  heading of steepest ascent
    seabed_stiffness: float = float("nan")   # N/m3
    seabed_damping: float = float("nan")     # Pa s/m
    seabed_mu_axial: float = float("nan")    # -
    seabed_mu_lateral: float = float("nan")  # -
    seabed_v_mob: float = float("nan")       # m/s
    source: Path = None               # file it was read from

    @property
    def has_current(self) -> bool:
        """A current profile with some non-zero speed is given."""
        return len(self.current_z) > 0 and bool(np.any(self.current_speed != 0.0))

    @property
    def mudline_z(self) -> float:
        """z of the seabed plane at x = y = 0 [m]."""
        return self.surface_z - self.depth

    def seabed_z(self, x, y=0.0):
        """z of the seabed plane at (x, y) [m] (arrays broadcast)."""
        slope = math.radians(self.seabed_slope)
        heading = math.radians(self.seabed_slope_dir)
        return self.mudline_z + math.tan(slope) * (np.asarray(x, float) * math.cos(heading)
                                                   + np.asarray(y, float) * math.sin(heading))

    def current_at(self, z):
        """Current speed [m/s] at levels z: linear between the profile levels, constant
        beyond; 0 without a profile."""
        if len(self.current_z) == 0:
            return np.zeros_like(np.asarray(z, float))
        return np.interp(z, self.current_z, self.current_speed)


def seabed_trace(env: Environment, x_range, y=0.0, n=2):
    """(x, z) of the seabed's trace in the vertical plane y = const (the x-z elevation
    the plots draw) over x_range = (x0, x1): a straight line, n points. None without a
    seabed. With a slope towards +-y the trace is level at that plane's depth."""
    if env is None or not env.seabed:
        return None
    x = np.linspace(float(x_range[0]), float(x_range[1]), n)
    return x, env.seabed_z(x, y)


def current_profile(env: Environment, z_low=None, z_high=None):
    """(z, speed) of the current profile to plot: the given levels, extended at constant
    speed down to z_low (default: the seabed at x = y = 0) and up to z_high (default: the
    surface) when they lie beyond; None without a current."""
    if env is None or not env.has_current:
        return None
    z = list(env.current_z)
    speed = list(env.current_speed)
    low = env.mudline_z if z_low is None else z_low
    high = env.surface_z if z_high is None else z_high
    if low < z[0]:
        z.insert(0, low)
        speed.insert(0, speed[0])
    if high > z[-1]:
        z.append(high)
        speed.append(speed[-1])
    return np.array(z), np.array(speed)


def load_environment(path):
    """The environment of a results folder (or of the .h5 file `path`): from the
    /environment group of the HDF5 file when reading one, else from environment.csv;
    None when there is none (a dry deck). Raises RodynResultsError for a malformed one."""
    path = Path(path)
    if path.is_file():
        return _read_h5(path) if path.suffix == ".h5" else None
    csv_path = path / ENVIRONMENT_CSV
    return _read_csv(csv_path) if csv_path.is_file() else None


def environment_of(h5file, path):
    """Environment from an open h5py File (None without /environment)."""
    import h5py

    from .results import h5_units_checked   # each dataset's own units, as the schema's
    group = h5file.get("environment")
    if not isinstance(group, h5py.Group):
        return None
    values = {}
    for key in _SCALARS:
        if isinstance(group.get(key), h5py.Dataset):
            values[key] = float(h5_units_checked(group[key], path)[()])
    arrays = {}
    for key in _PROFILE:
        data = group.get(key)
        arrays[key] = (np.asarray(h5_units_checked(data, path)[...], float).ravel()
                       if isinstance(data, h5py.Dataset) else np.zeros(0))
    seabed = bool(group.attrs.get("seabed", "seabed_slope" in values))
    return _make(values, arrays, seabed, path)


def _read_h5(path: Path):
    import h5py

    try:
        f = h5py.File(path, "r", locking=False)
    except OSError as exc:
        raise RodynResultsError(f"{path}: cannot read as HDF5 ({exc})") from None
    with f:
        return environment_of(f, path)


def _read_csv(path: Path) -> Environment:
    values, profile = {}, {}
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        first = next(reader, [])
        if tuple(first) != ENVIRONMENT_HEADER:
            raise RodynResultsError(f"{path}: line 1: header is {','.join(first)!r}, "
                                    f"expected {','.join(ENVIRONMENT_HEADER)!r}")
        for fields in reader:
            if not fields:
                continue
            where = f"{path}: line {reader.line_num}"
            if len(fields) != 3:
                raise RodynResultsError(f"{where}: {len(fields)} fields, expected 3")
            key, text, unit = fields
            try:
                value = float(text)
            except ValueError:
                raise RodynResultsError(f"{where}: {key}: {text!r} is not a number") from None
            head, _, index = key.rpartition("_")
            known = KEY_UNITS.get(head if head in _PROFILE and index.isdigit() else key)
            if known is not None and unit != known:
                raise RodynResultsError(f"{where}: {key} is in {unit!r}, rodyn_post reads it "
                                        f"in {known!r} (docs/output.md)")
            if head in _PROFILE and index.isdigit():
                profile.setdefault(head, {})[int(index)] = value
            else:
                values[key] = value
    n = int(values.get("current_levels", 0))
    arrays = {}
    for key in _PROFILE:
        given = profile.get(key, {})
        if sorted(given) != list(range(1, n + 1)):
            raise RodynResultsError(f"{path}: {key}_1 .. {key}_{n} expected "
                                    f"(current_levels = {n})")
        arrays[key] = np.array([given[k] for k in range(1, n + 1)], float)
    return _make(values, arrays, bool(values.get("seabed", 0.0)), path)


def _make(values, arrays, seabed, path) -> Environment:
    for key in _REQUIRED:
        if key not in values:
            raise RodynResultsError(f"{path}: environment: {key} missing")
    if not (len(arrays["current_z"]) == len(arrays["current_speed"])
            == len(arrays["current_heading"])):
        raise RodynResultsError(f"{path}: environment: current_z, current_speed and "
                                "current_heading differ in length")
    known = {k: v for k, v in values.items() if k in _SCALARS}
    return Environment(current_z=arrays["current_z"], current_speed=arrays["current_speed"],
                       current_heading=arrays["current_heading"], seabed=seabed,
                       source=Path(path), **known)


# --- drawing (matplotlib is imported by the callers' figures only) --------------------

SURFACE_GID, SEABED_GID, CURRENT_GID = "sea_surface", "seabed", "current_profile"


def elevation_range(xs, margin=0.1):
    """(x0, x1) spanning the arrays of x in `xs` with a margin of `margin` of the span on
    each side (at least 1 m)."""
    lo = min(float(np.nanmin(x)) for x in xs)
    hi = max(float(np.nanmax(x)) for x in xs)
    pad = max(margin * (hi - lo), 1.0)
    return lo - pad, hi + pad


def fit_elevation(ax, box_ratio=1.5, max_ratio=3.0):
    """Scale an x-z elevation to what is drawn on it: equal axes when the drawing is at
    most max_ratio times as wide as it is high; else z exaggerated so that the drawing
    fills an axes box box_ratio times as wide as high (a mooring leg hundreds of metres
    long in a shallower sea would otherwise be a thin band). Returns the exaggeration
    of z (1 for equal axes)."""
    (x0, x1), (z0, z1) = ax.dataLim.intervalx, ax.dataLim.intervaly
    width, height = x1 - x0, max(z1 - z0, 1e-9)
    if width <= max_ratio * height:
        ax.set_aspect("equal", adjustable="datalim")
        return 1.0
    exaggeration = width / (box_ratio * height)
    pad = 0.04 * height
    ax.set_xlim(x0, x1)
    ax.set_ylim(z0 - pad, z1 + pad)
    ax.set_aspect(exaggeration, adjustable="box")
    return exaggeration


def scale_note(exaggeration):
    """Text for a title: '' for equal axes, else the vertical exaggeration."""
    return "" if exaggeration == 1.0 else f", z exaggerated {exaggeration:.2g}x"


def draw_sea(ax, env, x_range, y=0.0):
    """Draw the still water level (z = surface, blue) and the seabed's trace in the
    plane y = const (brown, shaded below) on an x-z elevation, over x_range widened to
    at least 1.5 water depths about its centre; returns {'surface':
    Line2D, 'seabed': Line2D or None} (gids SURFACE_GID, SEABED_GID). Nothing (and {})
    for env None."""
    if env is None:
        return {}
    x0, x1 = x_range
    half = 0.75 * env.depth            # at least 1.5 depths wide: the view is water deep
    if x1 - x0 < 2.0 * half:
        centre = 0.5 * (x0 + x1)
        x0, x1 = centre - half, centre + half
        x_range = (x0, x1)
    surface, = ax.plot([x0, x1], [env.surface_z, env.surface_z], "-", color="tab:blue",
                       linewidth=1.2, zorder=0.5, label=f"sea surface, z = {env.surface_z:g} m")
    surface.set_gid(SURFACE_GID)
    artists = {"surface": surface, "seabed": None}
    trace = seabed_trace(env, x_range, y)
    if trace is not None:
        xb, zb = trace
        if env.seabed_slope == 0.0:
            label = f"seabed, z = {env.mudline_z:g} m"
        else:
            label = f"seabed ({env.seabed_slope:g}° slope), its trace at y = {y:.4g} m"
        bed, = ax.plot(xb, zb, "-", color="saddlebrown", linewidth=1.5, zorder=0.5,
                       label=label)
        bed.set_gid(SEABED_GID)
        ax.fill_between(xb, zb, zb - 0.03 * max(env.depth, 1.0), color="tan", alpha=0.5,
                        zorder=0.4, linewidth=0)
        artists["seabed"] = bed
    return artists


def draw_current(ax, env):
    """Draw the current profile (speed [m/s] against z [m], from the seabed to the
    surface) on `ax`; returns the Line2D (gid CURRENT_GID), or None without a current."""
    profile = current_profile(env)
    if profile is None:
        return None
    z, speed = profile
    line, = ax.plot(speed, z, "-o", color="tab:blue", markersize=2.5, linewidth=1.2)
    line.set_gid(CURRENT_GID)
    ax.axhline(env.surface_z, color="tab:blue", linewidth=0.6, alpha=0.6)
    if env.seabed:
        ax.axhline(env.mudline_z, color="saddlebrown", linewidth=0.6, alpha=0.6)
    ax.set_xlim(left=0.0, right=1.1 * max(float(np.max(speed)), 1e-9))
    ax.set_xlabel("current [m/s]", fontsize=7)
    ax.set_ylabel("z [m]", fontsize=7)
    ax.tick_params(labelsize=6)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.set_title("current", fontsize=7)
    return line


def current_inset(ax, env):
    """An inset in the lower left corner of `ax` with the current profile (draw_current);
    returns the inset Axes, or None without a current."""
    if env is None or not env.has_current:
        return None
    inset = ax.inset_axes([0.07, 0.08, 0.2, 0.38])
    inset.patch.set_alpha(0.85)
    draw_current(inset, env)
    return inset
