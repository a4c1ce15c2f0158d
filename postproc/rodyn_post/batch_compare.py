"""`rodyn-batch compare`: another tool's exports against a batch, one table of errors.

    rodyn-batch compare OUT REFDIR (--at WHERE | --range STAT) [--quantity Q]
                        [--x COL] [--y COL] [--s-from A|B] [--line NAME]
                        [--window T0 T1] [--on reference|rodyn] [-o TABLE.csv]

REFDIR holds one CSV per case, named by the case id (`REFDIR/<id>.csv`). Each is
compared with OUT/<id> as the compare command does (`postproc/compare.py`, same
options and meaning: a time history at WHERE, or a range graph statistic against
arc length), by the same code: `rodyn_post.reference.ReferenceTable` reads the
export (units in the headers converted to SI) and `rodyn_post.reference.compare`
resamples the two series and computes the errors. Written: OUT/compare_<REFDIR>.csv
(or -o), a row per reference file: id, status (ok, or why not), message, points,
max_abs_error, rms_error, mean_error, reference_range, rel_max_error, rel_rms_error
(SI; error = rodyn - reference), and the maximum of each series. A reference without
a case, or a case whose results cannot be read, gives a row with the reason; the
others are compared.
"""
from __future__ import annotations

import argparse
import math
from pathlib import Path

from .batch_cases import BatchInputError

METRICS = ("max_abs_error", "rms_error", "mean_error", "reference_range", "rel_max_error",
           "rel_rms_error")


def _parser() -> argparse.ArgumentParser:
    from .quantities import QUANTITIES, STATS

    p = argparse.ArgumentParser(prog="rodyn-batch compare", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output", metavar="OUT", help="batch folder")
    p.add_argument("refdir", metavar="REFDIR", help="folder of <case id>.csv exports")
    what = p.add_mutually_exclusive_group(required=True)
    what.add_argument("--at", metavar="WHERE", help="time history at A, B, top, bottom, "
                      "mid or an arc length S [m]")
    what.add_argument("--range", choices=STATS, help="range graph statistic")
    p.add_argument("--quantity", default="tension", choices=list(QUANTITIES))
    p.add_argument("--x", default="1", metavar="COL")
    p.add_argument("--y", default="2", metavar="COL")
    p.add_argument("--s-from", choices=("A", "B"), default="A")
    p.add_argument("--line", metavar="NAME")
    p.add_argument("--window", nargs=2, type=float, metavar=("T0", "T1"))
    p.add_argument("--on", choices=("reference", "rodyn"), default="reference")
    p.add_argument("-o", "--table", metavar="CSV", help="table file (default: in OUT)")
    return p


def rodyn_series(folder: Path, args):
    """(x, y) in SI of the rodyn side of one case (as compare.py's --at / --range)."""
    from . import units
    from .dynamic import load_dynamic
    from .quantities import (check_window, history, parse_location, pick_line,
                             range_stats, window_mask)

    results = load_dynamic(folder)
    window = tuple(args.window) if args.window else None
    check_window(results, window)
    line = pick_line(results, args.line)
    mask = window_mask(results.time, window)
    if args.at is not None:
        where = parse_location(args.at, line)
        return results.time[mask], history(line, args.quantity, where)[mask], units.TIME, line
    x, stats = range_stats(line, args.quantity, mask)
    return x, stats[args.range], units.LENGTH, line


def compare_one(folder: Path, ref: Path, args) -> dict:
    """Metrics of one case against its reference (errors raised as they come)."""
    from .quantities import QUANTITIES
    from .reference import ReferenceTable, compare

    x_r, y_r, x_dim, line = rodyn_series(folder, args)
    table = ReferenceTable(ref)
    xcol = table.column(args.x, x_dim, increasing=True)
    ycol = table.column(args.y, QUANTITIES[args.quantity].dimension)
    x_f, y_f = xcol.values, ycol.values
    if args.s_from == "B":
        x_f, y_f = float(line.node_s[-1]) - x_f[::-1], y_f[::-1]
    result = compare(x_r, y_r, x_f, y_f, on=args.on)
    row = dict(result.metrics())
    row["points"] = len(result.x)
    row["rodyn_max"] = result.peaks["rodyn"]["max"][0]
    row["reference_max"] = result.peaks["reference"]["max"][0]
    return row


def main(argv=None) -> int:
    from .cli import real, write_csv
    from .quantities import InputError
    from .results import RodynResultsError

    args = _parser().parse_args(argv)
    out, refdir = Path(args.output), Path(args.refdir)
    if not refdir.is_dir():
        raise BatchInputError(f"{refdir}: no such folder of reference exports")
    refs = sorted(refdir.glob("*.csv"))
    if not refs:
        raise BatchInputError(f"{refdir}: no .csv file (one per case, named by its id)")
    header = ["id", "status", "message", "points"] + list(METRICS) + ["rodyn_max",
                                                                       "reference_max"]
    rows, bad = [], 0
    for ref in refs:
        case = ref.stem
        row = {"id": case, "status": "ok", "message": ""}
        folder = out / case
        if not folder.is_dir():
            row.update(status="no case", message=f"{folder}: no such case folder")
        else:
            try:
                row.update(compare_one(folder, ref, args))
            except (RodynResultsError, InputError) as exc:
                row.update(status="error", message=" ".join(str(exc).split()))
        bad += row["status"] != "ok"
        rows.append(row)

    def fmt(key, value):
        if key in ("id", "status", "message"):
            return str(value)
        if value is None:
            return ""
        if key == "points":
            return str(value)
        return "" if math.isnan(value) else real(value)

    path = Path(args.table) if args.table else out / f"compare_{refdir.name}.csv"
    write_csv(path, header, [[fmt(k, r.get(k)) for k in header] for r in rows])
    width = max(len(r["id"]) for r in rows)
    print(f"{'id':{width}}  {'status':8} {'max_abs_error':>14} {'rel_max_error':>14}")
    for r in rows:
        if r["status"] == "ok":
            print(f"{r['id']:{width}}  {'ok':8} {r['max_abs_error']:14.6g} "
                  f"{r['rel_max_error']:14.6g}")
        else:
            print(f"{r['id']:{width}}  {r['status']:8} {r['message']}")
    print(path)
    return 4 if bad else 0
