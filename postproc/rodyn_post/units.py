"""Units written in CSV column headers, and their conversion to SI.

A header names its unit in square brackets or parentheses at its end, `time [s]`,
`Top Tension (kN)`, or, as in rodyn's own tables, after the last underscore:
`time_s`, `effective_tension_N`, `curvature_per_m`. `split_header(text)` returns the
name and the unit (None when the header gives none); `unit_factor(unit)` the dimension
and the factor that converts a value in that unit to SI.
"""
from __future__ import annotations

import math
import re

from .errors import UnitError  # noqa: F401  (also importable from here)

# dimension of each quantity kind, as used by rodyn_post.quantities
TIME, LENGTH, FORCE, MOMENT, CURVATURE, NONE = (
    "time", "length", "force", "moment", "curvature", "dimensionless")
FORCE_PER_LENGTH = "force per length"
SI_UNIT = {TIME: "s", LENGTH: "m", FORCE: "N", MOMENT: "N m", CURVATURE: "1/m", NONE: "-",
           FORCE_PER_LENGTH: "N/m"}

_FT, _IN, _LBF = 0.3048, 0.0254, 4.4482216152605
# unit (separators removed, see _normalise) -> (dimension, factor to SI)
UNITS = {
    "s": (TIME, 1.0), "sec": (TIME, 1.0), "ms": (TIME, 1e-3), "min": (TIME, 60.0),
    "h": (TIME, 3600.0),
    "m": (LENGTH, 1.0), "mm": (LENGTH, 1e-3), "cm": (LENGTH, 1e-2), "km": (LENGTH, 1e3),
    "ft": (LENGTH, _FT), "in": (LENGTH, _IN),
    "N": (FORCE, 1.0), "kN": (FORCE, 1e3), "KN": (FORCE, 1e3), "kn": (FORCE, 1e3),
    "MN": (FORCE, 1e6), "kgf": (FORCE, 9.80665), "tf": (FORCE, 9806.65),
    "lbf": (FORCE, _LBF), "kip": (FORCE, 1e3 * _LBF), "kips": (FORCE, 1e3 * _LBF),
    "Nm": (MOMENT, 1.0), "kNm": (MOMENT, 1e3), "KNm": (MOMENT, 1e3), "MNm": (MOMENT, 1e6),
    "lbfft": (MOMENT, _LBF * _FT), "ftlbf": (MOMENT, _LBF * _FT),
    "kipft": (MOMENT, 1e3 * _LBF * _FT), "ftkip": (MOMENT, 1e3 * _LBF * _FT),
    "1/m": (CURVATURE, 1.0), "/m": (CURVATURE, 1.0), "rad/m": (CURVATURE, 1.0),
    "per_m": (CURVATURE, 1.0), "1/km": (CURVATURE, 1e-3), "1/mm": (CURVATURE, 1e3),
    "1/ft": (CURVATURE, 1.0 / _FT), "rad/ft": (CURVATURE, 1.0 / _FT),
    "deg/m": (CURVATURE, math.pi / 180.0),
    "N/m": (FORCE_PER_LENGTH, 1.0), "kN/m": (FORCE_PER_LENGTH, 1e3),
    "N_per_m": (FORCE_PER_LENGTH, 1.0), "kN_per_m": (FORCE_PER_LENGTH, 1e3),
    "-": (NONE, 1.0),
}
_BRACKETED = re.compile(r"^(?P<name>.*?)\s*(\[(?P<b>[^\[\]]*)\]|\((?P<p>[^()]*)\))\s*$")


def _normalise(unit: str) -> str:
    """'kN m', 'kN.m', 'kN·m', 'kN*m', 'kN-m' -> 'kNm'; '-' stays."""
    unit = unit.strip()
    if unit == "-":
        return unit
    return re.sub(r"[\s.*·⋅-]", "", unit)


def unit_factor(unit: str) -> tuple:
    """(dimension, factor to SI) of a unit, e.g. 'kN' -> ('force', 1000.0)."""
    key = _normalise(unit)
    if key not in UNITS:
        raise UnitError(f"unit {unit!r} is not known (known: {known_units()})")
    return UNITS[key]


def known_units() -> str:
    """The units of UNITS grouped by dimension, for messages and --help."""
    groups = {}
    for key, (dimension, _) in UNITS.items():
        if key not in ("KN", "kn", "KNm", "sec", "kips", "ftlbf", "ftkip", "/m", "per_m",
                       "N_per_m", "kN_per_m"):
            groups.setdefault(dimension, []).append(key)
    return "; ".join(f"{d}: {' '.join(keys)}" for d, keys in groups.items())


def split_header(text: str) -> tuple:
    """(name, unit) of a column header; unit None when the header names none.

    'time [s]' -> ('time', 's'); 'Tension (kN)' -> ('Tension', 'kN');
    'effective_tension_N' -> ('effective_tension', 'N');
    'curvature_per_m' -> ('curvature', 'per_m'); 'value' -> ('value', None).
    """
    text = text.strip()
    match = _BRACKETED.match(text)
    if match:
        unit = match.group("b") if match.group("b") is not None else match.group("p")
        return (match.group("name").strip() or text), unit.strip()
    for unit in ("kN_per_m", "N_per_m", "per_m"):   # rodyn's seabed_normal_N_per_m
        if text.endswith("_" + unit) and len(text) > len(unit) + 1:
            return text[: -len(unit) - 1], unit
    name, sep, suffix = text.rpartition("_")
    if sep and name and _normalise(suffix) in UNITS:
        return name, suffix
    return text, None
