"""The quantities the post-processing commands plot, at points along a line.

rodyn gives section results (effective tension, bending moments, curvature, torque) at
the integration points (S = gp_s) and positions at the nodes (S = node_s). This module
picks a quantity out of a static or dynamic line, takes it at an arc length S
(`history`), or over a time window at every point (`range_stats`).

Interpolation along the line (stated in docs/postproc.md): a value at an arc length S
is linear in S between the two neighbouring points that carry it (integration points
for section results, nodes for positions); beyond the outermost integration point (the
ends of the line lie outside them) it is the outermost point's value. Magnitudes (the
bending moment sqrt(M1^2 + M2^2), the bending curvature) are interpolated as
magnitudes. A value exactly at a point is that point's value.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from . import units
from .errors import InputError, RodynResultsError  # noqa: F401  (InputError: also here)
from .results import LineStatic


@dataclass(frozen=True)
class Quantity:
    key: str         # name on the command line
    label: str       # axis label, without unit
    dimension: str   # units.FORCE, ...
    where: str       # 'gp' (integration points), 'node' or 'end' (held line ends)
    scale: float     # plotted value = SI value * scale
    unit: str        # plotted unit
    suffix: str      # SI unit as a CSV column suffix (rodyn's style: _N, _Nm, _per_m, _m)

    @property
    def si_unit(self) -> str:
        return units.SI_UNIT[self.dimension]


QUANTITIES = {q.key: q for q in (
    Quantity("tension", "effective tension", units.FORCE, "gp", 1e-3, "kN", "N"),
    Quantity("wall_tension", "wall tension", units.FORCE, "gp", 1e-3, "kN", "N"),
    Quantity("moment", "bending moment |M|", units.MOMENT, "gp", 1e-3, "kN m", "Nm"),
    Quantity("curvature", "bending curvature", units.CURVATURE, "gp", 1.0, "1/m", "per_m"),
    Quantity("torque", "torque M3", units.MOMENT, "gp", 1e-3, "kN m", "Nm"),
    Quantity("x", "x", units.LENGTH, "node", 1.0, "m", "m"),
    Quantity("y", "y", units.LENGTH, "node", 1.0, "m", "m"),
    Quantity("z", "z", units.LENGTH, "node", 1.0, "m", "m"),
    Quantity("seabed_normal", "seabed normal force", units.FORCE_PER_LENGTH, "node", 1e-3,
             "kN/m", "N_per_m"),
    Quantity("end_tension", "support tension |F|", units.FORCE, "end", 1e-3, "kN", "N"),
)}
RANGE_QUANTITIES = ("tension", "moment", "curvature")   # the riser range graph
STATS = ("min", "mean", "max")


BENDING = ("moment", "curvature")  # quantities a line of cable elements does not have


def has_bending(line):
    """Whether a line has bending moments or curvatures: a line of cable elements has
    none (rodyn writes them as zeros at every point and frame)."""
    return bool(np.any(line.moment_1) or np.any(line.moment_2)
                or np.any(line.bending_curvature))


def quantity(key: str) -> Quantity:
    if key not in QUANTITIES:
        raise InputError(f"unknown quantity {key!r} (known: {', '.join(QUANTITIES)})")
    return QUANTITIES[key]


def point_values(line, key: str):
    """(S of the points, values in SI) of a 'gp' or 'node' quantity of a line: values
    are (n_frames, n_points) for a dynamic line, (n_points,) for a static one."""
    q = quantity(key)
    static = isinstance(line, LineStatic)
    if q.where == "node":
        if key == "seabed_normal":
            return line.node_s, line.seabed_normal
        axis = "xyz".index(key)
        return line.node_s, line.node_xyz[:, axis] if static else getattr(line, key)
    if q.where != "gp":
        raise InputError(f"{key} is only defined at a held end (--at A, B, top or bottom)")
    if key == "tension":
        values = line.effective_tension
    elif key == "wall_tension":
        values = line.wall_tension
    elif key == "torque":
        values = line.torque
    elif key == "moment":
        values = line.moment_magnitude if static else np.hypot(line.moment_1, line.moment_2)
    else:  # curvature
        values = (np.hypot(line.curvature[:, 0], line.curvature[:, 1]) if static
                  else line.bending_curvature)
    return line.gp_s, values


def interpolation_weights(points: np.ndarray, s: float) -> tuple:
    """(i0, i1, w) with value(s) = (1 - w) v[i0] + w v[i1]: linear between the two
    neighbouring points, the outermost point's value beyond them."""
    n = len(points)
    if s <= points[0]:
        return 0, 0, 0.0
    if s >= points[-1]:
        return n - 1, n - 1, 0.0
    i1 = int(np.searchsorted(points, s, side="right"))
    i0 = i1 - 1
    return i0, i1, float((s - points[i0]) / (points[i1] - points[i0]))


def at_s(points: np.ndarray, values: np.ndarray, s: float) -> np.ndarray:
    """Values at arc length s along the last axis of `values` (see the module doc)."""
    i0, i1, w = interpolation_weights(points, s)
    if w == 0.0:
        return values[..., i0].copy()
    return (1.0 - w) * values[..., i0] + w * values[..., i1]


def resample_matrix(points: np.ndarray, targets) -> np.ndarray:
    """(n_targets, n_points) matrix W with values_at_targets = values @ W.T, by the rule
    of at_s (e.g. the integration-point values at the nodes)."""
    w = np.zeros((len(targets), len(points)))
    for k, s in enumerate(targets):
        i0, i1, t = interpolation_weights(points, float(s))
        w[k, i0] += 1.0 - t
        w[k, i1] += t
    return w


@dataclass(frozen=True)
class Location:
    """A place on a line: arc length S [m]; end 0 (A) or 1 (B) when it is an end."""
    text: str     # as given: 'A', 'top', '5', ...
    s: float
    end: int      # 0, 1, or -1 (not an end)
    label: str    # for plots: 'end A (top)', 'S = 5 m'
    token: str    # for CSV column names: 'A', 'B', 'mid', 'S5'


def parse_location(text: str, line) -> Location:
    """'A' / 'B' (the ends), 'top' / 'bottom' (the higher / lower end at the first
    frame), 'mid' (S = L/2) or an arc length S in metres from end A."""
    length = float(line.node_s[-1])
    word = text.strip().lower()
    if word in ("a", "b", "top", "bottom"):
        if word in ("a", "b"):
            end = "ab".index(word)
            role = ""
            if hasattr(line, "top_end"):
                role = " (top)" if end == line.top_end else " (bottom)"
        else:
            if not hasattr(line, "top_end"):
                raise InputError(f"--at {text}: top and bottom need dynamic results")
            end = line.top_end if word == "top" else 1 - line.top_end
            role = f" ({word})"
        return Location(text, (0.0, length)[end], end, f"end {'AB'[end]}{role}",
                        word if role == f" ({word})" else "AB"[end])
    if word == "mid":
        return Location(text, 0.5 * length, -1, f"S = {0.5 * length:g} m (mid)", "mid")
    try:
        s = float(text)
    except ValueError:
        raise InputError(f"--at {text!r}: expected A, B, top, bottom, mid or an arc "
                         "length S in m") from None
    if not np.isfinite(s) or s < -1e-9 * length or s > length * (1 + 1e-9):
        raise InputError(f"--at {text}: S is off the line {line.name!r} (0 to {length:g} m)")
    s = min(max(s, 0.0), length)
    return Location(text, s, -1, f"S = {s:g} m", "S" + re.sub(r"[^0-9.eE+-]", "", f"{s:g}"))


def history(line, key: str, where: Location) -> np.ndarray:
    """Values in SI of quantity `key` at `where` of a dynamic line, one per frame."""
    q = quantity(key)
    if q.where == "end":
        if where.end < 0:
            raise InputError(f"{key} is the support force at a held end: use --at A, B, "
                             f"top or bottom, not {where.text!r}")
        if not line.end_held[where.end]:
            raise InputError(f"{key}: end {'AB'[where.end]} of line {line.name!r} has "
                             "no support")
        return line.end_tension[:, where.end].copy()
    points, values = point_values(line, key)
    return at_s(points, values, where.s)


def range_stats(line, key: str, mask: np.ndarray, at=None) -> tuple:
    """(S of the points, {'min', 'mean', 'max': array}) of quantity `key` over the
    frames selected by `mask`, at the integration points (or nodes) themselves: no
    interpolation; or, with `at` (arc lengths S), at those S, each frame's values
    interpolated first (at_s's rule). The mean is the plain mean over those frames."""
    if not np.any(mask):
        raise InputError("no output frame in the time window")
    points, values = point_values(line, key)
    if at is not None:
        values = values @ resample_matrix(points, at).T
        points = np.asarray(at, float)
    part = values[mask]
    return points, {"min": part.min(axis=0), "mean": part.mean(axis=0),
                    "max": part.max(axis=0)}


def pick_line(results, name):
    """The line called `name`, or the first line (deck order) when name is None."""
    if name is None:
        return results.lines[0]
    try:
        return results.line(name)
    except KeyError:
        names = ", ".join(repr(line.name) for line in results.lines)
        raise InputError(f"--line {name!r}: no such line in {results.source} "
                         f"(lines: {names})") from None


def window_mask(t: np.ndarray, window) -> np.ndarray:
    """Boolean mask of the times inside window (T0, T1), or all."""
    if window is None:
        return np.ones(len(t), dtype=bool)
    return (t >= window[0] - 1e-9) & (t <= window[1] + 1e-9)


def check_window(results, window):
    """InputError when the run has no frames, or the window misses them all."""
    t = results.time
    if len(t) == 0:
        raise InputError(f"{results.source}: no output frames")
    if window is not None and not np.any(window_mask(t, window)):
        raise InputError(f"--window {window[0]:g} {window[1]:g} s holds no output frame "
                         f"of the run ({t[0]:g} to {t[-1]:g} s)")


def matching_static(results):
    """The static results in the folder of dynamic `results` when they hold the same
    lines with the same nodes and points (the START=STATIC equilibrium), else None."""
    from .results import load_static
    try:
        static = load_static(results.folder)
        for line in results.lines:
            s = static.line(line.name)
            if len(s.node_s) != len(line.node_s) or len(s.gp_s) != len(line.gp_s):
                return None
        return static
    except (RodynResultsError, KeyError):
        return None
