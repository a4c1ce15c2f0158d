"""Time histories of a rodyn dynamic run at chosen arc lengths or ends of a line.

    rodyn-plot-history [RESULTS] [--at WHERE ...] [--quantity Q ...]
                       [--line NAME] [--window T0 T1] [-o OUT_DIR]
                       [--dpi 150]

RESULTS is a results folder (default: paper_case1) or a dynamic.h5 file. Writes into
OUT_DIR (default: the results folder) and prints the paths written:

  history_<LINE>.png  one panel per quantity against time, one curve per place; a run
                      of more than 40 periods of the motion as its range in bins of
                      time beside a zoom on the last 5 periods (as rodyn-plot-dynamic)
  history_<LINE>.csv  the numbers, SI: time_s, then one column per quantity and place,
                      named <quantity>_<place>_<unit>, e.g. tension_A_N,
                      moment_S5_Nm, curvature_mid_per_m, z_top_m, end_tension_top_N

WHERE (default: top mid bottom): A or B (an end), top or bottom (the higher or lower end
at the first frame), mid (S = L/2), or an arc length S [m] from end A.
Q (default: tension moment curvature z; tension and z for a line of cable elements,
which has no bending):
  tension      effective tension N3 [kN]
  moment       bending moment magnitude sqrt(M1^2 + M2^2) [kN m]
  curvature    bending curvature sqrt(K1^2 + K2^2) [1/m]
  torque       torsional moment M3 [kN m]
  x, y, z      position of the point of the line at S [m]
  end_tension  support force |F| at a held end (only at A, B, top, bottom) [kN]

What is interpolated: rodyn gives section results at the integration points and
positions at the nodes. At an S between two integration points (nodes for x, y, z) the
value is linear in S between them; beyond the outermost integration point (an end lies
outside them, by about 0.11 element lengths for cubic elements) it is that point's value
(so 'tension' at an end is N3 at the nearest integration point: use end_tension for the
support force). Magnitudes (moment, curvature) are interpolated as magnitudes. The
values are those of the output frames; nothing is interpolated in time.
"""
import sys

import numpy as np

from rodyn_post import cli, load_dynamic
from rodyn_post.commands.plot_dynamic import band_bins, draw_history, history_axes, zoom_start
from rodyn_post.quantities import (BENDING, QUANTITIES, check_window, has_bending, history,
                                   parse_location, pick_line, quantity, window_mask)

PROG = "plot_history"  # prefix of its messages
COMMAND = "rodyn-plot-history"  # its console command (postproc/pyproject.toml)
DEFAULT_AT = ("top", "mid", "bottom")
DEFAULT_QUANTITIES = ("tension", "moment", "curvature", "z")


def history_table(results, line, keys, places, window=None):
    """(time (n,), [(quantity key, Location, values in SI (n,)), ...]) for the frames in
    the window. Raises InputError for a bad quantity or place."""
    mask = window_mask(results.time, window)
    locations = {}
    for text in places:  # a place given twice (same CSV column name) is used once
        where = parse_location(text, line)
        locations.setdefault(where.token, where)
    locations = list(locations.values())
    columns = []
    for key in keys:
        quantity(key)
        for where in locations:
            columns.append((key, where, history(line, key, where)[mask]))
    return results.time[mask], columns


def column_name(key, where):
    """CSV column of a quantity at a place: <quantity>_<place>_<SI unit suffix>."""
    return f"{key}_{where.token}_{QUANTITIES[key].suffix}"


def history_figure(results, line, time, columns):
    """One panel per quantity (plotted units), one curve per place; a long run (more than
    40 periods of the motion) as its range per bin of time beside a zoom on its last 5
    periods (plot_dynamic.zoom_start), not as a solid block."""
    keys = list(dict.fromkeys(key for key, _, _ in columns))
    t0 = zoom_start(results, time)
    bins = band_bins(results, time)
    fig = cli.new_figure(8 if t0 is None else 11, 1.0 + 2.3 * len(keys))
    rows = history_axes(fig, len(keys), t0, bins)
    for (ax, zoom), key in zip(rows, keys):
        q = QUANTITIES[key]
        for k, (col_key, where, values) in enumerate(c for c in columns if c[0] == key):
            draw_history((ax, zoom), time, values * q.scale, t0, bins, "-", linewidth=1.0,
                         color=f"C{k}", label=where.label)
        ax.set_ylabel(f"{q.label} [{q.unit}]")
        for axes in (ax, zoom):
            if axes is not None:
                cli.finish_axes(axes)
    for axes in rows[-1]:
        if axes is not None:
            axes.set_xlabel("time [s]")
    fig.suptitle(cli.dynamic_title(
        results, f"time histories of line {line.name} (between integration points / "
                 "nodes: linear in S)"))
    return fig


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__))
    parser.add_argument("--at", nargs="+", metavar="WHERE", default=list(DEFAULT_AT),
                        help="places on the line (default: top mid bottom)")
    parser.add_argument("--quantity", nargs="+", metavar="Q",
                        default=list(DEFAULT_QUANTITIES), choices=list(QUANTITIES),
                        help="quantities (default: tension moment curvature z)")
    cli.add_line(parser)
    cli.add_window(parser)
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        results = load_dynamic(args.results)
        check_window(results, args.window)
        line = pick_line(results, args.line)
        keys = list(args.quantity)
        if keys == list(DEFAULT_QUANTITIES) and not has_bending(line):
            keys = [k for k in keys if k not in BENDING]   # cable elements: none to show
        time, columns = history_table(results, line, keys, args.at, args.window)
        cli.warn_dynamic(PROG, results)
        out = cli.output_dir(args, results.folder)
        stem = f"history_{cli.safe_name(line.name)}"
        print(cli.save_figure(history_figure(results, line, time, columns),
                              out / f"{stem}.png", args.dpi))
        header = ["time_s"] + [column_name(key, where) for key, where, _ in columns]
        rows = [[cli.real(t)] + [cli.real(values[i]) for _, _, values in columns]
                for i, t in enumerate(time)]
        print(cli.write_csv(out / f"{stem}.csv", header, rows))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
