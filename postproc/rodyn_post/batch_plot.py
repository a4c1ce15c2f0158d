"""`rodyn-batch plot`: figures of a batch drawn from its summary.h5 alone (no frame of
any case is read again).

    rodyn-batch plot OUT --y COLUMN --x PARAM [--by PARAM] [-o FILE.png] [--dpi 150]
    rodyn-batch plot OUT --envelope Q [--line NAME] [-o FILE.png] [--dpi 150]

--y/--x: a summary column (e.g. CABLE.tension_max_N, or tension_max_N when one line
has it) against a parameter, one line per value of --by; cases that are not complete,
and cases without the parameter (another batch's into the folder), are left out. --envelope Q (tension, wall_tension, moment, curvature, torque,
seabed_normal): the range graph over all complete cases: each case's min and max
along the line (thin) and the envelope of them all (thick), with OUT/envelope_<Q>.csv
giving, at each arc length, the envelope and the case that sets it.
"""
from __future__ import annotations

import argparse
import re
from pathlib import Path

import numpy as np

from .batch_cases import BatchInputError

SCALES = {"N": (1e-3, "kN"), "Nm": (1e-3, "kN m"), "per_m": (1.0, "1/m"), "m": (1.0, "m"),
          "s": (1.0, "s"), "N_per_m": (1e-3, "kN/m")}
ENVELOPE_Q = {"tension": ("effective tension", "N"), "wall_tension": ("wall tension", "N"),
              "moment": ("bending moment |M|", "Nm"), "curvature": ("bending curvature",
                                                                   "per_m"),
              "torque": ("torque", "Nm"), "seabed_normal": ("seabed normal force",
                                                            "N_per_m")}


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="rodyn-batch plot", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output", metavar="OUT", help="batch folder (with summary.h5)")
    what = p.add_mutually_exclusive_group(required=True)
    what.add_argument("--y", metavar="COLUMN", help="summary column to plot")
    what.add_argument("--envelope", choices=list(ENVELOPE_Q), metavar="Q",
                      help="range graph over all cases: " + ", ".join(ENVELOPE_Q))
    p.add_argument("--x", metavar="PARAM", help="parameter on the x axis (with --y)")
    p.add_argument("--by", metavar="PARAM", help="one line per value of PARAM (with --y)")
    p.add_argument("--line", metavar="NAME", help="line (--envelope; default: the first)")
    p.add_argument("-o", "--png", metavar="FILE", help="figure file (default: in OUT)")
    p.add_argument("--dpi", type=float, default=150.0)
    return p


def find_column(columns, name: str) -> str:
    """A summary column by its full name or, when unique, by the part after 'LINE.'."""
    if name in columns:
        return name
    hits = [c for c in columns if c.split(".", 1)[-1] == name]
    if len(hits) == 1:
        return hits[0]
    if hits:
        raise BatchInputError(f"--y {name}: several lines have it: {', '.join(hits)}")
    raise BatchInputError(f"--y {name}: no such column in the summary")


def _unit(column: str):
    for suffix in sorted(SCALES, key=len, reverse=True):
        if column.endswith("_" + suffix):
            return SCALES[suffix]
    return 1.0, "-"


QUANTITY_WORDS = {"seabed_normal": "seabed normal force"}   # others: the name in words


def column_label(column: str) -> str:
    """A summary column as an axis reads it, without the unit suffix of its name (the
    unit follows in brackets where it is used): the line (and end), then the extreme and
    the quantity in words, and for the time or arc length of an extreme what it is:
    'LEG.end_B_tension_max_N' -> 'LEG end B: max tension', 'CABLE.tension_max_t_s' ->
    'CABLE: time of max tension', 'CABLE.moment_max_S_m' -> 'CABLE: S of max moment',
    'LEG.touchdown_min_S_m' -> 'LEG: min touchdown S'; other columns in words."""
    line, _, name = column.rpartition(".")
    for suffix in sorted(SCALES, key=len, reverse=True):
        if name.endswith("_" + suffix):
            name = name[:-len(suffix) - 1]
            break
    match = re.fullmatch(r"(?:end_([AB])_)?([a-z_]+?)_(max|min)(?:_([tS]))?", name)
    if not line or match is None:
        words = name.replace("_", " ")
        return f"{line}: {words}" if line else words
    end, quantity, stat, at = match.groups()
    words = f"{stat} {QUANTITY_WORDS.get(quantity, quantity.replace('_', ' '))}"
    if quantity == "touchdown":      # touchdown_<stat>_S: the touchdown point itself
        words, at = f"{words} S", {"t": "t", "S": None}.get(at)
    if at is not None:
        words = f"{'time' if at == 't' else 'S'} of {words}"
    return f"{line}{f' end {end}' if end else ''}: {words}"


def axis_label(column: str) -> str:
    """column_label with the plotted unit in brackets (none for a count)."""
    unit = _unit(column)[1]
    return column_label(column) + ("" if unit == "-" else f" [{unit}]")


def _as_float(values):
    try:
        return np.array([float(v) for v in values]), True
    except (TypeError, ValueError):
        return np.asarray(values), False


def plot_column(summary: dict, ycol: str, xparam: str, by: str = None):
    """Figure of summary column `ycol` against parameter `xparam` (lines by `by`)."""
    from .cli import finish_axes, new_figure

    cases, columns = summary["cases"], summary["columns"]
    ycol = find_column(columns, ycol)
    for name, opt in ((xparam, "--x"), (by, "--by")):
        if name is not None and name not in columns:
            raise BatchInputError(f"{opt} {name}: not a parameter of the batch "
                                  f"(parameters: {summary['attrs'].get('parameters', '')})")
    ok = cases["status"] == "complete"
    x, numeric = _as_float(cases[xparam])
    given = ~np.isnan(x) if numeric else np.asarray(x) != ""
    if by is not None:   # a case without a parameter (another batch's) is left out
        given &= np.array([str(v) not in ("", "nan") for v in cases[by]])
    without = int((ok & ~given).sum())
    ok &= given
    y = np.asarray(cases[ycol], float)
    groups = [None] if by is None else list(dict.fromkeys(cases[by][ok]))
    scale = _unit(ycol)[0]
    fig = new_figure(7, 4.5)
    ax = fig.subplots()
    for g in groups:
        sel = ok if g is None else ok & (cases[by] == g)
        xs, ys = x[sel], y[sel]
        order = np.argsort(xs, kind="stable") if numeric else np.arange(len(xs))
        ax.plot(xs[order], ys[order] * scale, "o-", markersize=4,
                label=None if g is None else f"{by} = {g}")
    ax.set_xlabel(xparam)
    ax.set_ylabel(axis_label(ycol))
    finish_axes(ax, legend=by is not None)
    left = int((~ok).sum()) - without
    notes = ([f"{left} cases not complete"] if left else []) + (
        [f"{without} cases without {' or '.join(p for p in (xparam, by) if p)}"]
        if without else [])
    fig.suptitle(f"{column_label(ycol)} against {xparam}"
                 + (f" ({', '.join(notes)} left out)" if notes else ""))
    return fig


def envelope_table(summary: dict, q: str, line: str = None) -> dict:
    """Envelope of quantity q over the complete cases of a line: {'line', 's', 'min',
    'max', 'min_case', 'max_case', 'cases': [(id, s, lo, hi)]}. Cases with other
    points are interpolated (linear in S) onto the union of the points."""
    table = summary["envelope_nodes" if q == "seabed_normal" else "envelope"]
    if table is None or f"{q}_max" not in table:
        raise BatchInputError(f"--envelope {q}: not in the summary (extract it with "
                              "--extract)")
    names = list(dict.fromkeys(table["line"]))
    line = line or names[0]
    if line not in names:
        raise BatchInputError(f"--line {line}: no such line (lines: {', '.join(names)})")
    ids, status = summary["cases"]["id"], summary["cases"]["status"]
    per_case = []
    for k in np.unique(table["case"]):
        if status[k] != "complete":
            continue
        sel = (table["case"] == k) & (table["line"] == line)
        if not np.any(sel):
            continue
        hi = table[f"{q}_max"][sel]
        lo = table[f"{q}_min"][sel] if f"{q}_min" in table else None
        per_case.append((str(ids[k]), table["s"][sel], lo, hi))
    if not per_case:
        raise BatchInputError(f"--envelope {q}: no complete case has line {line}")
    s = np.unique(np.concatenate([c[1] for c in per_case]))
    his = np.array([np.interp(s, c[1], c[3]) for c in per_case])
    out = {"line": line, "s": s, "max": his.max(axis=0),
           "max_case": [per_case[i][0] for i in his.argmax(axis=0)], "cases": per_case}
    if per_case[0][2] is not None:
        los = np.array([np.interp(s, c[1], c[2]) for c in per_case])
        out["min"] = los.min(axis=0)
        out["min_case"] = [per_case[i][0] for i in los.argmin(axis=0)]
    return out


def plot_envelope(env: dict, q: str):
    from .cli import finish_axes, new_figure

    label, suffix = ENVELOPE_Q[q]
    scale, unit = SCALES[suffix]
    fig = new_figure(8, 4.5)
    ax = fig.subplots()
    for k, (_, s, lo, hi) in enumerate(env["cases"]):
        ax.plot(s, hi * scale, "-", color="0.6", linewidth=0.6,
                label="each case" if k == 0 else None)
        if lo is not None:
            ax.plot(s, lo * scale, "-", color="0.6", linewidth=0.6)
    ax.plot(env["s"], env["max"] * scale, "-", color="C3", linewidth=1.8,
            label="envelope: max")
    if "min" in env:
        ax.plot(env["s"], env["min"] * scale, "-", color="C0", linewidth=1.8,
                label="envelope: min")
    ax.set_xlabel("arc length S (unstretched, from end A) [m]")
    ax.set_ylabel(f"{label} [{unit}]")
    finish_axes(ax)
    fig.suptitle(f"line {env['line']}: range graph of {label} over "
                 f"{len(env['cases'])} cases")
    return fig


def main(argv=None) -> int:
    from .batch_summary import read_summary
    from .cli import real, save_figure, write_csv, safe_name

    args = _parser().parse_args(argv)
    out = Path(args.output)
    if not (out / "summary.h5").is_file():
        raise BatchInputError(f"{out / 'summary.h5'}: no summary (run the batch first)")
    summary = read_summary(out)
    if args.y:
        if not args.x:
            raise BatchInputError("--y needs --x PARAM")
        fig = plot_column(summary, args.y, args.x, args.by)
        png = Path(args.png) if args.png else out / (
            f"plot_{safe_name(args.y)}_vs_{safe_name(args.x)}.png")
    else:
        env = envelope_table(summary, args.envelope, args.line)
        fig = plot_envelope(env, args.envelope)
        png = Path(args.png) if args.png else out / (
            f"envelope_{args.envelope}_{safe_name(env['line'])}.png")
        suffix = ENVELOPE_Q[args.envelope][1]
        header = ["s_m", f"{args.envelope}_max_{suffix}", "max_case"]
        rows = [[real(env["s"][i]), real(env["max"][i]), env["max_case"][i]]
                for i in range(len(env["s"]))]
        if "min" in env:
            header += [f"{args.envelope}_min_{suffix}", "min_case"]
            for i, row in enumerate(rows):
                row += [real(env["min"][i]), env["min_case"][i]]
        print(write_csv(png.with_suffix(".csv"), header, rows))
    print(save_figure(fig, png, args.dpi))
    return 0
