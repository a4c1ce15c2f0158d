"""What a batch keeps of each case: the extremes and the envelopes along the lines.

`extract_case(folder, keys)` reads a case's results once, with rodyn_post's readers
(`load_dynamic`, which takes dynamic.h5 or, for a killed run or CSV tables only, the
CSV files; `load_static` for a deck without *DYNAMIC: the file formats are read in
one place), and returns plain numbers:

- `scalars`: {column: float}, columns named `<LINE>.<quantity>_<stat>[_t_s|_S_m]`
  in SI (docs/batch.md lists them), e.g. `CABLE.tension_max_N`, its time
  `CABLE.tension_max_t_s` and arc length `CABLE.tension_max_S_m`;
- `envelope`: {line: {"s": [...], "<quantity>_min": [...], "<quantity>_max": [...]}}
  over all frames at the points the quantity lives on (the range graph of the case).

The end tensions' extremes come from the support forces written every step when the
run wrote them (they then do not depend on the frame interval),
else from the frames. The quantities (`--extract`, EXTRACT_KEYS): end_tension,
tension, wall_tension, moment, curvature (with the minimum bend radius), torque, seabed
(seabed normal force and touchdown range; only for a run with a seabed). Newton statistics come from
status.txt (`newton_stats`) and are always kept.

Values are the binary64 numbers of the files (no rounding): a summary row equals, bit
for bit, the extraction of the same case run alone.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Dict, Iterable, Optional

import numpy as np

from .results import RodynResultsError, _read_key_values

EXTRACT_KEYS = ("end_tension", "tension", "wall_tension", "moment", "curvature", "torque",
                "seabed")
DEFAULT_EXTRACT = ("end_tension", "tension", "moment", "curvature", "seabed")
# status.txt keys kept as Newton statistics (static and dynamic); missing ones are nan.
STATUS_NUMBERS = ("load_factor", "increments", "iterations", "cutbacks", "time_reached_s",
                  "steps", "step_iterations", "step_tangents", "step_cutbacks",
                  "wall_time_s")
NAN = float("nan")


def parse_extract(text: str) -> tuple:
    """The --extract list ('all' or comma-separated EXTRACT_KEYS), ValueError if bad."""
    keys = [k.strip().lower() for k in text.split(",") if k.strip()]
    if keys == ["all"]:
        return EXTRACT_KEYS
    for key in keys:
        if key not in EXTRACT_KEYS:
            raise ValueError(f"--extract {key!r}: unknown (known: all, "
                             f"{', '.join(EXTRACT_KEYS)})")
    if not keys:
        raise ValueError("--extract: empty list")
    return tuple(dict.fromkeys(keys))


def newton_stats(folder: Path) -> Dict[str, float]:
    """Numbers of status.txt (STATUS_NUMBERS; nan when absent) plus `complete` (1/0)
    and `status` text; `status_txt` = '' when the file is missing."""
    path = Path(folder) / "status.txt"
    out: Dict[str, object] = {k: NAN for k in STATUS_NUMBERS}
    out["complete"] = 0
    out["status_txt"] = ""
    if not path.is_file():
        return out
    try:
        raw = _read_key_values(path)
    except (RodynResultsError, OSError, UnicodeDecodeError):
        return out
    for key in STATUS_NUMBERS:
        try:
            out[key] = float(raw[key])
        except (KeyError, ValueError):
            pass
    out["complete"] = 1 if raw.get("complete") == "true" else 0
    out["status_txt"] = raw.get("status", "")
    return out


def status_complete(folder: Path) -> bool:
    """Whether status.txt says `complete = true` (docs/output.md)."""
    try:
        return _read_key_values(Path(folder) / "status.txt").get("complete") == "true"
    except (RodynResultsError, OSError, UnicodeDecodeError):
        return False


def _load(folder: Path):
    """(results, dynamic?) of a case folder; None when it holds no results."""
    from .dynamic import load_dynamic
    from .results import load_static
    folder = Path(folder)
    if (folder / "dynamic.h5").is_file() or (folder / "dynamic_nodes.csv").is_file():
        return load_dynamic(folder), True
    if (folder / "results.h5").is_file() or (folder / "static_nodes.csv").is_file():
        return load_static(folder), False
    return None, False


def _peak(values: np.ndarray, time: np.ndarray, s: Optional[np.ndarray], kind: str):
    """(value, t, S) of the max or min of a (nf, np) array (first occurrence)."""
    if values.size == 0:
        return NAN, NAN, NAN
    flat = int(np.argmax(values) if kind == "max" else np.argmin(values))
    f, p = np.unravel_index(flat, values.shape)
    return (float(values[f, p]), float(time[f]),
            float(s[p]) if s is not None else NAN)


def _put_peak(out: dict, prefix: str, unit: str, values, time, s, kinds=("max", "min")):
    for kind in kinds:
        v, t, at = _peak(values, time, s, kind)
        out[f"{prefix}_{kind}_{unit}"] = v
        out[f"{prefix}_{kind}_t_s"] = t
        if s is not None:
            out[f"{prefix}_{kind}_S_m"] = at


def _line_arrays(line, dynamic: bool) -> dict:
    """The arrays of a line as (nf, n) frames (a static line is one frame)."""
    if dynamic:
        return {"tension": line.effective_tension, "wall_tension": line.wall_tension,
                "moment": np.hypot(line.moment_1, line.moment_2),
                "curvature": line.bending_curvature, "torque": line.torque,
                "end_tension": line.end_tension, "seabed_normal": line.seabed_normal,
                "touchdown_s": line.touchdown_s}
    force = np.linalg.norm(line.reactions[:, :3], axis=1) * line.end_held
    return {"tension": line.effective_tension[None, :],
            "wall_tension": line.wall_tension[None, :],
            "moment": line.moment_magnitude[None, :],
            "curvature": np.hypot(line.curvature[:, 0], line.curvature[:, 1])[None, :],
            "torque": line.torque[None, :], "end_tension": force[None, :],
            "seabed_normal": line.seabed_normal[None, :],
            "touchdown_s": np.array([line.touchdown_s], dtype=float)}


def extract_case(folder: Path, keys: Iterable[str] = DEFAULT_EXTRACT) -> dict:
    """Extremes and envelopes of the results in `folder` (see the module doc), read
    with rodyn_post's readers (load_dynamic, or load_static for a deck without
    *DYNAMIC). Raises RodynResultsError when there are no readable results."""
    keys = tuple(keys)
    results, dynamic = _load(Path(folder))
    if results is None:
        raise RodynResultsError(f"{folder}: no results (neither dynamic.h5, results.h5 "
                                "nor CSV tables)")
    time = results.time if dynamic else np.array([NAN])
    env = getattr(results, "environment", None)
    has_seabed = bool(env is not None and getattr(env, "seabed", False))
    lines = [(line.name, line.gp_s, line.node_s, line.end_held, _line_arrays(line, dynamic))
             for line in results.lines]
    if dynamic:   # the ends' extremes from the support forces of every step, if written
        for line, (_, _, _, _, arrays) in zip(results.lines, lines):
            arrays["end_time"], arrays["end_tension"] = results.end_tension_series(line)
    scalars, envelope = _extract_lines(lines, time, has_seabed, keys)
    info = {"frames": int(len(time)) if dynamic else 0, "dynamic": dynamic}
    if dynamic and len(results.log):
        info["max_step_iterations"] = int(results.log.iterations.max())
    return {"scalars": scalars, "envelope": envelope, "info": info}


def _extract_lines(lines, time, has_seabed: bool, keys: tuple) -> tuple:
    """(scalars, envelope) of lines given as (name, gp_s, node_s, end_held, arrays)."""
    scalars: Dict[str, float] = {}
    envelope: Dict[str, dict] = {}
    for name, gp_s, node_s, end_held, a in lines:
        env_line: Dict[str, list] = {"s": [float(v) for v in gp_s]}
        if "end_tension" in keys:
            for e, end in enumerate("AB"):
                if end_held[e]:
                    _put_peak(scalars, f"{name}.end_{end}_tension", "N",
                              a["end_tension"][:, e:e + 1], a.get("end_time", time), None)
        for key, unit in (("tension", "N"), ("wall_tension", "N"), ("torque", "Nm")):
            if key in keys:
                _put_peak(scalars, f"{name}.{key}", unit, a[key], time, gp_s)
                env_line[f"{key}_min"] = a[key].min(axis=0).tolist()
                env_line[f"{key}_max"] = a[key].max(axis=0).tolist()
        if "moment" in keys:
            _put_peak(scalars, f"{name}.moment", "Nm", a["moment"], time, gp_s, ("max",))
            env_line["moment_max"] = a["moment"].max(axis=0).tolist()
        if "curvature" in keys:
            _put_peak(scalars, f"{name}.curvature", "per_m", a["curvature"], time, gp_s,
                      ("max",))
            kmax = scalars[f"{name}.curvature_max_per_m"]
            scalars[f"{name}.bend_radius_min_m"] = 1.0 / kmax if kmax > 0 else math.inf
            env_line["curvature_max"] = a["curvature"].max(axis=0).tolist()
        if "seabed" in keys and has_seabed:
            _put_peak(scalars, f"{name}.seabed_normal", "N_per_m", a["seabed_normal"],
                      time, node_s, ("max",))
            td = a["touchdown_s"]
            on = td >= 0
            for kind, pick in (("min", np.argmin), ("max", np.argmax)):
                if np.any(on):
                    idx = np.flatnonzero(on)[int(pick(td[on]))]
                    scalars[f"{name}.touchdown_{kind}_S_m"] = float(td[idx])
                    scalars[f"{name}.touchdown_{kind}_t_s"] = float(time[idx])
                else:
                    scalars[f"{name}.touchdown_{kind}_S_m"] = NAN
                    scalars[f"{name}.touchdown_{kind}_t_s"] = NAN
            env_line["node_s"] = [float(v) for v in node_s]
            env_line["seabed_normal_max"] = a["seabed_normal"].max(axis=0).tolist()
        envelope[name] = env_line
    return scalars, envelope
