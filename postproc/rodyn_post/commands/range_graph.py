"""Range graphs of a rodyn dynamic run: minimum, mean and maximum over a time window
against arc length, for effective tension, bending moment and bending curvature (or
the quantities of --quantity).

    rodyn-range-graph [RESULTS] [-o OUT_DIR] [--window T0 T1]
                      [--line NAME] [--quantity Q ...] [--dpi 150]

RESULTS is a results folder (default: paper_case1) or a dynamic.h5 file. The window is
--window, else from the end of the run's longest ramp-in (of its motions, waves and
current: dynamic.h5's /dynamic ramp_s; the start-up is not the response) to its end.
Writes into OUT_DIR (default: the results folder) and prints the paths written:

  range_graph.png  three panels against the unstretched arc length S from end A:
                   effective tension [kN], bending moment |M| [kN m], bending
                   curvature [1/m]; min and max (band) and mean (dashed) over the
                   window, the static equilibrium (dotted) when the folder has it
  range_graph.csv  the numbers, SI: line, s_m, then tension_min_N, tension_mean_N,
                   tension_max_N, moment_*_Nm, curvature_*_per_m; one row per
                   integration point of each line

--quantity picks the panels (default: tension moment curvature; tension alone when every
line is of cable elements, which have no bending) among tension,
wall_tension, moment, curvature, torque (at the integration points) and seabed_normal,
x, y, z (at the nodes); one panel and three CSV columns each, in the order given.

The statistics are over the output frames with T0 <= t <= T1 (default: all), at the
integration points themselves (no interpolation), or at the nodes when every quantity
asked is a node quantity; a node quantity asked together with section quantities is
taken at the integration points, linear in S between the nodes in each frame. The mean
is the plain mean of those frames. Extremes between two frames are not seen: a finer
OUTPUT INTERVAL sees more.
"""
import sys

from rodyn_post import cli, load_dynamic
from rodyn_post.quantities import (BENDING, QUANTITIES, RANGE_QUANTITIES, STATS, has_bending,
                                   check_window, matching_static, pick_line, point_values,
                                   range_stats, window_mask)

PROG = "range_graph"  # prefix of its messages
COMMAND = "rodyn-range-graph"  # its console command (postproc/pyproject.toml)
PNG = "range_graph.png"
CSV = "range_graph.csv"


CHOICES = [key for key, q in QUANTITIES.items() if q.where != "end"]


def csv_header(keys=RANGE_QUANTITIES):
    """Columns of range_graph.csv."""
    return ["line", "s_m"] + [f"{key}_{stat}_{QUANTITIES[key].suffix}"
                              for key in keys for stat in STATS]


def range_table(results, lines, window=None, keys=RANGE_QUANTITIES):
    """{line name: (S of the points, {quantity: {stat: array}})} in SI: at the
    integration points, or at the nodes when every quantity is a node quantity."""
    mask = window_mask(results.time, window)
    at_nodes = all(QUANTITIES[key].where == "node" for key in keys)
    table = {}
    for line in lines:
        stats = {}
        at = None if at_nodes else line.gp_s
        for key in keys:
            s, stats[key] = range_stats(line, key, mask,
                                        at if QUANTITIES[key].where == "node" else None)
        table[line.name] = (s, stats)
    return table


def csv_rows(table, keys=RANGE_QUANTITIES):
    """Rows of range_graph.csv (formatted fields)."""
    rows = []
    for name, (s, stats) in table.items():
        for i in range(len(s)):
            rows.append([name, cli.real(s[i])] + [cli.real(stats[key][stat][i])
                                                  for key in keys
                                                  for stat in STATS])
    return rows


def range_figure(results, table, window=None, keys=RANGE_QUANTITIES):
    """One panel per quantity; curves in plotted units (kN, kN m, 1/m, ...)."""
    fig = cli.new_figure(8, 2.2 + 2.1 * len(keys))
    axes = fig.subplots(len(keys), 1, sharex=True, squeeze=False)[:, 0]
    static = matching_static(results)
    for k, (name, (s, stats)) in enumerate(table.items()):
        color = f"C{k}"
        for ax, key in zip(axes, keys):
            q = QUANTITIES[key]
            lo, mean, hi = (stats[key][stat] * q.scale for stat in STATS)
            ax.fill_between(s, lo, hi, color=color, alpha=0.25, linewidth=0)
            ax.plot(s, hi, "-", color=color, linewidth=1.2, label=f"{name}: max")
            ax.plot(s, mean, "--", color=color, linewidth=1.0, label=f"{name}: mean")
            ax.plot(s, lo, "-", color=color, linewidth=0.8, label=f"{name}: min")
            if static is not None:
                s0, v0 = point_values(static.line(name), key)
                ax.plot(s0, v0 * q.scale, ":", color="k", linewidth=1.2,
                        label=f"{name}: static")
    for ax, key in zip(axes, keys):
        q = QUANTITIES[key]
        ax.set_ylabel(f"{q.label} [{q.unit}]")
        cli.finish_axes(ax, fontsize=7)
    axes[-1].set_xlabel("arc length S (unstretched, from end A) [m]")
    mask = window_mask(results.time, window)
    fig.suptitle(cli.dynamic_title(results, "range graph: min, mean, max over "
                                   + cli.window_text(results.time, mask)))
    return fig


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__))
    cli.add_window(parser)
    cli.add_line(parser, every=True)
    parser.add_argument("--quantity", nargs="+", metavar="Q", default=list(RANGE_QUANTITIES),
                        choices=CHOICES, help="quantities, one panel each (default: "
                        f"{' '.join(RANGE_QUANTITIES)}; choices: {', '.join(CHOICES)})")
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        results = load_dynamic(args.results)
        check_window(results, args.window)
        lines = [pick_line(results, args.line)] if args.line else list(results.lines)
        cli.warn_dynamic(PROG, results)
        if args.window is None and 0.0 < results.ramp_s < results.time[-1]:
            args.window = (results.ramp_s, float(results.time[-1]))   # after the ramp-in
        keys = list(dict.fromkeys(args.quantity))
        if keys == list(RANGE_QUANTITIES) and not any(has_bending(ln) for ln in lines):
            keys = [k for k in keys if k not in BENDING]   # cable elements: none to show
        table = range_table(results, lines, args.window, keys)
        out = cli.output_dir(args, results.folder)
        print(cli.save_figure(range_figure(results, table, args.window, keys), out / PNG,
                              args.dpi))
        print(cli.write_csv(out / CSV, csv_header(keys), csv_rows(table, keys)))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
