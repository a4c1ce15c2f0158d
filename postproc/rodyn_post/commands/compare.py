"""Compare a rodyn result with a reference exported by another tool (CSV).

    rodyn-compare [RESULTS] REFERENCE.csv
                  (--at WHERE | --range STAT | --static) [--quantity Q]
                  [--x COL] [--y COL] [--s-from A|B] [--line NAME]
                  [--window T0 T1] [--on reference|rodyn]
                  [--tol TOL [--metric M]] [--no-plot] [-o OUT_DIR]
                  [--dpi 150]

What is compared (one of):
  --at WHERE    a time history of Q at a place of the line (A, B, top, bottom, mid or an
                arc length S [m]; as rodyn-plot-history), against a reference of time and
                value
  --range STAT  the range graph of Q over the --window (STAT: min, mean or max against
                arc length, as rodyn-range-graph), against a reference of arc length and
                value
  --static      Q of the static equilibrium against arc length (RESULTS default
                paper_cable), against a reference of arc length and value
Q (default tension): tension, moment, curvature, torque, x, y, z, end_tension (see
rodyn-plot-history --help).

The reference CSV: a header line (lines starting with '#' are skipped), delimiter ',',
';' or tab; --x and --y choose the columns (default 1 and 2) by header, by name without
unit, or by number counting from 1. Units in the header, 'time [s]', 'Tension (kN)' or
rodyn's 'tension_A_N', are converted to SI; a header without a unit is taken as SI.
The x column must increase. --s-from B: the reference's arc length is measured from
end B.

Both series are resampled onto common points: the reference's points (--on reference,
the default) or rodyn's (--on rodyn) inside the overlap of the two x ranges, the other
series interpolated linearly. Printed (SI units; error = rodyn - reference):
max_abs_error, rms_error, mean_error, reference_range (max - min of the reference),
rel_max_error and rel_rms_error (divided by that range), and each series' max and min
with their time (or S). Written into OUT_DIR (default: the results folder):

  compare_<REFERENCE>.png  the two series overlaid (kN, kN m, 1/m, m) and the error
                           (not with --no-plot)
  compare_<REFERENCE>.csv  the common points: x, rodyn, reference, error (SI)

--tol TOL: exit 4 when the --metric (default rel_max) is above TOL. TOL of max_abs or
rms is in SI units unless a unit is given ('--tol "0.5 kN"'); rel_* are fractions.
"""
import sys
import textwrap
from pathlib import Path

import numpy as np

from rodyn_post import cli, errors, load_dynamic, load_static, units
from rodyn_post.errors import InputError
from rodyn_post.quantities import (QUANTITIES, STATS, check_window, history,
                                   parse_location, pick_line, point_values, quantity,
                                   range_stats, window_mask)
from rodyn_post.reference import ReferenceTable, compare

PROG = "compare"  # prefix of its messages
COMMAND = "rodyn-compare"  # its console command (postproc/pyproject.toml)
METRICS = ("max_abs", "rms", "rel_max", "rel_rms")
EPILOG = ("exit status: 0 success (and within --tol), 1 bad input (missing or malformed "
          "results or reference), 2 bad command line, 3 cannot write the outputs, "
          "4 the metric is above --tol")


def rodyn_series(args):
    """(x, y in SI, description, x dimension, the results, the line) of the rodyn side."""
    q = quantity(args.quantity)
    if args.static:
        results = load_static(args.results)
        line = pick_line(results, args.line)
        if q.where == "end":
            raise InputError("--static: end_tension is a dynamic quantity (use tension)")
        x, y = point_values(line, q.key)
        what = f"static {q.label}"
        return x, y, what, units.LENGTH, results, line
    results = load_dynamic(args.results)
    check_window(results, args.window)
    line = pick_line(results, args.line)
    mask = window_mask(results.time, args.window)
    if args.at is not None:
        where = parse_location(args.at, line)
        what = f"{q.label} at {where.label}"
        return results.time[mask], history(line, q.key, where)[mask], what, units.TIME, \
            results, line
    x, stats = range_stats(line, q.key, mask)
    what = f"{args.range} of {q.label} over {cli.window_text(results.time, mask)}"
    return x, stats[args.range], what, units.LENGTH, results, line


def reference_series(args, x_dimension, line):
    """(x, y in SI, the two Column objects) of the reference CSV."""
    table = ReferenceTable(args.reference)
    xcol = table.column(args.x, x_dimension, increasing=True)
    ycol = table.column(args.y, QUANTITIES[args.quantity].dimension)
    x, y = xcol.values, ycol.values
    if args.s_from == "B":
        x, y = float(line.node_s[-1]) - x[::-1], y[::-1]
    return x, y, xcol, ycol


def parse_tolerance(text, metric, dimension):
    """--tol as a number in SI (or a fraction for rel_*)."""
    parts = text.strip().split(None, 1)
    try:
        value = float(parts[0])
    except (ValueError, IndexError):
        raise InputError(f"--tol {text!r}: expected a number, optionally with a unit") \
            from None
    if len(parts) == 2:
        if metric.startswith("rel"):
            raise InputError(f"--tol {text!r}: {metric} is a fraction, without unit")
        try:
            found, factor = units.unit_factor(parts[1])
        except units.UnitError as exc:
            raise InputError(f"--tol {text!r}: {exc}") from None
        if found != dimension:
            raise InputError(f"--tol {text!r}: {parts[1]} is not a unit of {dimension}")
        value *= factor
    if not value >= 0.0:
        raise InputError(f"--tol {text!r}: must be 0 or more")
    return value


def describe_column(col):
    if col.unit is None:
        return f"column {col.number} {col.header!r} (no unit: taken as SI)"
    si = units.SI_UNIT[col.dimension]
    conversion = "" if col.factor == 1.0 else f" -> {si}: x {col.factor:g}"
    return f"column {col.number} {col.header!r} [{col.unit}{conversion}]"


def report(result, q, x_unit, x_name):
    """The printed lines of the comparison (SI units)."""
    m = result.metrics()
    si = q.si_unit
    lines = [f"points = {len(result.x)} ({result.on} points, {x_name} {result.overlap[0]:g} "
             f"to {result.overlap[1]:g} {x_unit})"]
    for key in ("max_abs_error", "rms_error", "mean_error", "reference_range"):
        lines.append(f"{key} = {m[key]:.6g} {si}")
    for key in ("rel_max_error", "rel_rms_error"):
        lines.append(f"{key} = {m[key]:.6g}")
    for who in ("rodyn", "reference"):
        for kind in ("max", "min"):
            value, at = result.peaks[who][kind]
            lines.append(f"{who}_{kind} = {value:.6g} {si} at {x_name} = {at:.6g} {x_unit}")
    return lines


def comparison_figure(title, q, x_label, rodyn_xy, ref_xy, result, labels):
    """Top: both series (plotted units) over the overlap; bottom: the error."""
    fig = cli.new_figure(8, 6.5)
    ax, ax_e = fig.subplots(2, 1, sharex=True, height_ratios=(2, 1))
    lo, hi = result.overlap
    for (x, y), style, label in ((rodyn_xy, "-", labels[0]), (ref_xy, ".--", labels[1])):
        keep = (x >= lo - 1e-9 * max(1.0, abs(hi))) & (x <= hi + 1e-9 * max(1.0, abs(hi)))
        ax.plot(x[keep], y[keep] * q.scale, style, linewidth=1.1, markersize=3, label=label)
    ax_e.plot(result.x, result.error * q.scale, "-", color="C3", linewidth=1.0,
              label="rodyn - reference")
    ax.set_ylabel(f"{q.label} [{q.unit}]")
    ax_e.set_ylabel(f"error [{q.unit}]")
    ax_e.set_xlabel(x_label)
    for a in (ax, ax_e):
        cli.finish_axes(a)
    fig.suptitle("\n".join(textwrap.fill(part, 88, break_on_hyphens=False)
                           for part in title.split("\n")), fontsize=10)
    return fig


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__), epilog=EPILOG,
                             results=False)
    parser.add_argument("results", nargs="?", default=None,
                        help="results folder, dynamic.h5 or results.h5 (default: "
                             "paper_case1; with --static paper_cable)")
    parser.add_argument("reference", help="reference CSV file")
    what = parser.add_mutually_exclusive_group(required=True)
    what.add_argument("--at", metavar="WHERE", help="compare a time history at WHERE")
    what.add_argument("--range", choices=STATS, help="compare a range graph statistic")
    what.add_argument("--static", action="store_true",
                      help="compare the static equilibrium along the line")
    parser.add_argument("--quantity", default="tension", choices=list(QUANTITIES),
                        help="quantity (default: tension)")
    parser.add_argument("--x", default="1", metavar="COL",
                        help="reference x column (time or arc length; default: 1)")
    parser.add_argument("--y", default="2", metavar="COL",
                        help="reference value column (default: 2)")
    parser.add_argument("--s-from", choices=("A", "B"), default="A",
                        help="end the reference's arc length starts from (default: A)")
    cli.add_line(parser)
    cli.add_window(parser)
    parser.add_argument("--on", choices=("reference", "rodyn"), default="reference",
                        help="whose points to compare on (default: reference)")
    parser.add_argument("--tol", metavar="TOL",
                        help="exit 4 when the metric is above TOL")
    parser.add_argument("--metric", choices=METRICS, default="rel_max",
                        help="metric checked by --tol (default: rel_max)")
    parser.add_argument("--no-plot", action="store_true",
                        help="write no PNG (the metrics and the CSV only; faster)")
    args = cli.parse(parser, argv)
    if args.results is None:
        args.results = cli.STATIC_DEFAULT if args.static else cli.DYNAMIC_DEFAULT
    if args.static and args.window:
        parser.error("--window does not apply to --static")
    if args.at is not None and args.s_from == "B":
        parser.error("--s-from applies to an arc length (--range, --static), not to --at")
    return args


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        q = quantity(args.quantity)
        tol = (parse_tolerance(args.tol, args.metric, q.dimension)
               if args.tol is not None else None)
        x_r, y_r, what, x_dim, results, line = rodyn_series(args)
        x_f, y_f, xcol, ycol = reference_series(args, x_dim, line)
        result = compare(x_r, y_r, x_f, y_f, on=args.on)
        metrics = result.metrics()
        if hasattr(results, "warnings"):
            cli.warn_dynamic(PROG, results)
        time_axis = x_dim == units.TIME
        x_name, x_unit = ("t", "s") if time_axis else ("S", "m")
        print(f"rodyn: {results.source}: line {line.name}: {what} [{q.si_unit}]")
        print(f"reference: {args.reference}: {describe_column(ycol)} against "
              f"{describe_column(xcol)}" + (", S from end B" if args.s_from == "B" else ""))
        for text in report(result, q, x_unit, x_name):
            print(text)
        out = cli.output_dir(args, results.folder)
        stem = f"compare_{cli.safe_name(Path(args.reference).stem)}"
        x_label = "time [s]" if time_axis else "arc length S (unstretched, from end A) [m]"
        title = cli.one_line(results.title or f"results {results.folder.name}")[:90] + (
            f"\n{line.name}: {what}\nvs {Path(args.reference).name}: max |error| "
            f"{metrics['max_abs_error'] * q.scale:.4g} {q.unit}, rms "
            f"{metrics['rms_error'] * q.scale:.4g} {q.unit}, "
            f"{100 * metrics['rel_max_error']:.3g} % of the reference range")
        if not args.no_plot:
            fig = comparison_figure(title, q, x_label, (x_r, y_r), (x_f, y_f), result,
                                    (f"rodyn ({results.folder.name})",
                                     f"reference ({Path(args.reference).name})"))
            print(cli.save_figure(fig, out / f"{stem}.png", args.dpi))
        x_head = "time_s" if time_axis else "s_m"
        header = [x_head] + [f"{who}_{q.suffix}" for who in ("rodyn", "reference", "error")]
        rows = [[cli.real(v) for v in row] for row in
                zip(result.x, result.rodyn, result.reference, result.error)]
        print(cli.write_csv(out / f"{stem}.csv", header, rows))
        if tol is None:
            return errors.EXIT_OK
        value = metrics[f"{args.metric}_error"]
        if np.isnan(value):
            raise InputError(f"--metric {args.metric}: the reference is constant over the "
                             "common points (range 0); use max_abs or rms")
        unit = "" if args.metric.startswith("rel") else f" {q.si_unit}"
        if value > tol:
            print(f"{PROG}: above tolerance: {args.metric}_error = {value:.6g}{unit} > "
                  f"{tol:.6g}{unit}", file=sys.stderr)
            return errors.EXIT_TOLERANCE
        print(f"within tolerance: {args.metric}_error = {value:.6g}{unit} <= {tol:.6g}{unit}")
        return errors.EXIT_OK
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
