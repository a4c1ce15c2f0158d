"""Reference results exported by another tool (CSV), and their comparison with rodyn's.

Accepted layout (docs/postproc.md, "CSV layouts of compare"):

- text, UTF-8 (a byte-order mark is allowed); lines starting with '#' and blank lines
  are skipped anywhere;
- the first other line is the header: one name per column; the delimiter is the one
  of ',', ';' and tab that the header holds most often (a single-column header is
  refused: at least two columns are needed); lines before it that hold none of the
  three are titles, as in OrcaFlex's exported values (`Time History: Line1 Effective
  Tension at End B`, then `Time (s)<tab>Effective Tension (kN)`), and are skipped;
- a header names its unit in brackets or parentheses at its end, `time [s]`,
  `Tension (kN)`, or after the last underscore as rodyn's tables do (`time_s`,
  `tension_A_N`, `curvature_per_m`); without a unit the column is taken to be SI;
- then one row per point, every row with the header's number of fields (empty fields
  at the end of a row are ignored); the cells of the columns used must be finite
  numbers ('.' as decimal point); other columns may hold anything;
- the x column (time or arc length) must increase strictly.

MoorDyn's `.out` tables are read as they are (a file named `*.out`, or one whose second
line starts with `(s)`): a header whose first name is `Time` and whose columns are
separated by blanks only, then (when MoorDyn wrote it, WriteUnits > 0) a row of units,
`(s)` first, the others bare (`N`, `m`, `m/s`), then the rows; each column gets the unit
of that row (docs/capi.md, "The .out file").

A column is chosen by its header (exactly as written, or its name without the unit,
ignoring case) or by its number, counting from 1 for the first column.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import units
from .errors import InputError, ReferenceError  # noqa: F401  (also importable from here)

DELIMITERS = (",", ";", "\t")


@dataclass(frozen=True)
class Column:
    """One numeric column of a reference CSV, converted to SI."""
    header: str         # as written
    number: int         # from 1
    unit: str           # as written, or None
    dimension: str      # units.TIME, ... ; None without a unit
    factor: float       # SI value = written value * factor
    values: np.ndarray  # SI
    line_numbers: np.ndarray  # line of the file of each value


class ReferenceTable:
    """The header and rows of a reference CSV (cells as text until a column is used)."""

    def __init__(self, path):
        self.path = Path(path)
        try:
            text = self.path.read_text(encoding="utf-8-sig")
        except FileNotFoundError:
            raise ReferenceError(f"{self.path}: no such file") from None
        except UnicodeDecodeError as exc:
            raise ReferenceError(f"{self.path}: not UTF-8 text ({exc.reason} at byte "
                                 f"{exc.start})") from None
        except OSError as exc:
            raise ReferenceError(f"{self.path}: cannot read ({exc.strerror or exc})") \
                from None
        numbered = [(n, line) for n, line in enumerate(text.splitlines(), 1)
                    if line.strip() and not line.lstrip().startswith("#")]
        if not numbered:
            raise ReferenceError(f"{self.path}: empty (no header line)")
        if self._moordyn_out(numbered):
            return
        # title lines (no delimiter) before a header that has one, as OrcaFlex's exported
        # values start: 'Time History: Line1 Effective Tension at End B'
        first = next((i for i, (_, line) in enumerate(numbered)
                      if any(d in line for d in DELIMITERS)), 0)
        self.title = " / ".join(line.strip() for _, line in numbered[:first])
        numbered = numbered[first:]
        header_number, header_line = numbered[0]
        counts = {d: header_line.count(d) for d in DELIMITERS}
        self.delimiter = max(DELIMITERS, key=lambda d: counts[d])
        if counts[self.delimiter] == 0:
            raise ReferenceError(f"{self.path}: line {header_number}: header "
                                 f"{header_line.strip()!r} has one column; expected at "
                                 "least two separated by ',', ';' or tab")
        rows = list(csv.reader([line for _, line in numbered], delimiter=self.delimiter))
        header = rows[0]
        while len(header) > 2 and not header[-1].strip():  # a trailing delimiter
            header = header[:-1]
        self.header = [h.strip() for h in header]
        self.rows = []
        for (number, _), fields in zip(numbered[1:], rows[1:]):
            while len(fields) > len(self.header) and not fields[-1].strip():
                fields = fields[:-1]
            if len(fields) != len(self.header):
                raise ReferenceError(f"{self.path}: line {number}: {len(fields)} fields, "
                                     f"the header has {len(self.header)}")
            self.rows.append((number, fields))
        if not self.rows:
            raise ReferenceError(f"{self.path}: no data rows after the header")

    def _moordyn_out(self, numbered):
        """Read a MoorDyn .out table (header `Time ...`, blanks between the columns, an
        optional row of units); False when the text is not one."""
        header = numbered[0][1].split()
        if not header or header[0] != "Time" or any(d in numbered[0][1] for d in DELIMITERS):
            return False
        body = numbered[1:]
        unit_row = body[0][1].split() if body else []
        if self.path.suffix != ".out" and unit_row[:1] != ["(s)"]:
            return False
        if unit_row and unit_row[0] == "(s)":
            header = [f"{h} [{u.strip('()')}]" if u.strip("()") else h
                      for h, u in zip(header, unit_row)]
            body = body[1:]
        self.delimiter = " "
        self.header = header
        self.rows = []
        for number, line in body:
            fields = line.split()
            if len(fields) != len(header):
                raise ReferenceError(f"{self.path}: line {number}: {len(fields)} fields, "
                                     f"the header has {len(header)}")
            self.rows.append((number, fields))
        if not self.rows:
            raise ReferenceError(f"{self.path}: no data rows after the header")
        return True

    def find(self, spec: str) -> int:
        """Index (from 0) of the column named by `spec`: a number from 1, the header as
        written, or the header's name without its unit (then, if none matches, the
        same ignoring case)."""
        spec = str(spec).strip()
        if spec.isdigit():
            number = int(spec)
            if not 1 <= number <= len(self.header):
                raise ReferenceError(f"{self.path}: column {number}: there are "
                                     f"{len(self.header)} columns (counted from 1)")
            return number - 1
        if spec in self.header:
            return self.header.index(spec)
        names = [units.split_header(h)[0] for h in self.header]
        matches = [i for i, name in enumerate(names) if name == spec]
        if not matches:
            matches = [i for i, (h, name) in enumerate(zip(self.header, names))
                       if spec.lower() in (h.lower(), name.lower())]
        if len(matches) == 1:
            return matches[0]
        what = "several columns" if matches else "no column"
        listed = ", ".join(repr(h) for h in self.header)
        raise ReferenceError(f"{self.path}: {what} named {spec!r} (columns: {listed})")

    def column(self, spec: str, dimension: str, increasing=False) -> Column:
        """The column named by `spec` as numbers in SI. Its unit (if the header gives
        one) must be of `dimension`; with `increasing` the values must increase."""
        index = self.find(spec)
        header = self.header[index]
        unit = units.split_header(header)[1]
        factor, found = 1.0, None
        if unit is not None:
            try:
                found, factor = units.unit_factor(unit)
            except units.UnitError as exc:
                raise ReferenceError(f"{self.path}: column {header!r}: {exc}") from None
            if found != dimension:
                raise ReferenceError(f"{self.path}: column {header!r} is in {unit} "
                                     f"({found}); expected a {dimension} "
                                     f"(e.g. {units.SI_UNIT[dimension]})")
        values = np.empty(len(self.rows))
        numbers = np.empty(len(self.rows), dtype=int)
        for i, (number, fields) in enumerate(self.rows):
            text = fields[index].strip()
            try:
                value = float(text)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise ReferenceError(f"{self.path}: line {number}: column {header!r}: "
                                     f"{text!r} is not a finite number")
            values[i], numbers[i] = value * factor, number
            if increasing and i > 0 and not values[i] > values[i - 1]:
                raise ReferenceError(f"{self.path}: line {number}: column {header!r}: "
                                     f"{text} does not increase (previous row: "
                                     f"{self.rows[i - 1][1][index].strip()}); the x "
                                     "column must increase strictly")
        return Column(header, index + 1, unit, found, factor, values, numbers)


# --- the comparison -----------------------------------------------------------------

@dataclass(frozen=True)
class Comparison:
    """rodyn's series against the reference on common points (SI units)."""
    x: np.ndarray            # common points (time or arc length)
    rodyn: np.ndarray        # rodyn at x
    reference: np.ndarray    # reference at x
    on: str                  # 'reference' or 'rodyn': whose points x are
    overlap: tuple           # (x0, x1): where both series are defined
    peaks: dict              # {'rodyn'|'reference': {'max'|'min': (value, x)}}

    @property
    def error(self) -> np.ndarray:
        """rodyn - reference at the common points."""
        return self.rodyn - self.reference

    def metrics(self) -> dict:
        """max_abs_error, rms_error, mean_error (rodyn - reference), reference_range
        (max - min of the reference on the common points), rel_max_error and
        rel_rms_error (the first two divided by the range; nan when it is 0)."""
        e = self.error
        max_abs = float(np.max(np.abs(e)))
        rms = float(np.sqrt(np.mean(e * e)))
        span = float(np.ptp(self.reference))
        return {"max_abs_error": max_abs, "rms_error": rms, "mean_error": float(np.mean(e)),
                "reference_range": span,
                "rel_max_error": max_abs / span if span > 0 else math.nan,
                "rel_rms_error": rms / span if span > 0 else math.nan}


def compare(x_rodyn, y_rodyn, x_ref, y_ref, on="reference") -> Comparison:
    """Resample onto common points and compare. The common points are those of the
    reference (on='reference') or of rodyn (on='rodyn') inside the overlap of the two
    x ranges; the other series is interpolated linearly onto them. Peaks are each
    series' own largest and smallest sample inside the overlap."""
    x_rodyn, y_rodyn = np.asarray(x_rodyn, float), np.asarray(y_rodyn, float)
    x_ref, y_ref = np.asarray(x_ref, float), np.asarray(y_ref, float)
    lo, hi = max(x_rodyn[0], x_ref[0]), min(x_rodyn[-1], x_ref[-1])
    eps = 1e-9 * max(abs(lo), abs(hi), hi - lo, 1e-300)
    if hi < lo - eps:
        raise InputError(f"the reference ({x_ref[0]:g} to {x_ref[-1]:g}) and rodyn "
                         f"({x_rodyn[0]:g} to {x_rodyn[-1]:g}) do not overlap")

    def inside(x):
        return (x >= lo - eps) & (x <= hi + eps)

    if on == "reference":
        sel = inside(x_ref)
        x = x_ref[sel]
        ref, rod = y_ref[sel], np.interp(x, x_rodyn, y_rodyn)
    else:
        sel = inside(x_rodyn)
        x = x_rodyn[sel]
        rod, ref = y_rodyn[sel], np.interp(x, x_ref, y_ref)
    if len(x) == 0:
        raise InputError(f"no {on} point inside the overlap {lo:g} to {hi:g}")
    peaks = {}
    for name, xs, ys in (("rodyn", x_rodyn, y_rodyn), ("reference", x_ref, y_ref)):
        m = inside(xs)
        xm, ym = xs[m], ys[m]
        if len(xm) == 0:  # overlap between two samples: use the resampled values
            xm, ym = x, (rod if name == "rodyn" else ref)
        peaks[name] = {"max": (float(ym.max()), float(xm[ym.argmax()])),
                       "min": (float(ym.min()), float(xm[ym.argmin()]))}
    return Comparison(x, rod, ref, on, (float(lo), float(hi)), peaks)
