"""Every plot of a rodyn run, by the other rodyn_post commands, in one command.

    rodyn-plot-all [RESULTS] [-o OUT_DIR] [--dpi DPI] [--window T0 T1]
                   [--animate] [--paraview]

RESULTS is a results folder (default: paper_cable, the output folder of the main deck
input/paper_cable.inp) or a results.h5 / dynamic.h5 file. What is made depends on the
results found there:

  static results   rodyn-plot-static: static_shape.png (the paper's Figure 2),
                   static_tension.png; in water also static_wall_tension.png and,
                   when a line touches the seabed, static_seabed.png
  dynamic results  rodyn-plot-dynamic: dynamic_snapshots.png (Figures 3-6),
                   dynamic_tension.png, dynamic_energy.png, dynamic_momentum.png;
                   rodyn-range-graph: range_graph.png and .csv;
                   rodyn-plot-history for every line: history_<LINE>.png and .csv
                   (top, mid, bottom: tension, moment, curvature, z);
                   with --animate rodyn-animate (GIF, MP4 when ffmpeg is there), with
                   --paraview rodyn-paraview (OUT_DIR/paraview/ or RESULTS/paraview/)

Each command prints the paths it writes and its own messages; --dpi and --window go to
the commands that take them (default: each command's own). The exit status is the
highest of the commands' (0 success, 1 bad input, 3 cannot write), 1 when RESULTS holds
no results; 2 bad command line.
"""
import sys
from pathlib import Path

from rodyn_post import cli, errors, load_dynamic
from rodyn_post.commands import (animate, plot_dynamic, plot_history, plot_static,
                                 range_graph, to_paraview)

PROG = "plot_all"  # prefix of its messages
COMMAND = "rodyn-plot-all"  # its console command (postproc/pyproject.toml)


def commands(args, kinds, line_names):
    """[(command module, argv)] to run, in order."""
    common = [str(args.results)] + (["-o", args.out_dir] if args.out_dir else [])
    dpi = ["--dpi", f"{args.dpi:g}"] if args.dpi else []
    window = ["--window", *(f"{t!r}" for t in args.window)] if args.window else []
    todo = []
    if "static" in kinds:
        static_target = common
        if Path(args.results).is_file() and "dynamic" in kinds:
            static_target = [str(Path(args.results).parent)] + common[1:]
        todo.append((plot_static, static_target + dpi))
    if "dynamic" in kinds:
        todo.append((plot_dynamic, common + dpi + window))
        todo.append((range_graph, common + dpi + window))
        for name in line_names:
            todo.append((plot_history, common + dpi + window + ["--line", name]))
        if args.animate:
            todo.append((animate, common + window))
        if args.paraview:
            out = ["-o", str(Path(args.out_dir) / "paraview")] if args.out_dir else []
            todo.append((to_paraview, [str(args.results)] + out + window))
    return todo


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__),
                             results_default=cli.STATIC_DEFAULT,
                             results_help="results folder, results.h5 or dynamic.h5",
                             dpi=None)
    parser.add_argument("--dpi", type=cli.positive_float,
                        help="resolution of the PNGs (default: each command's own)")
    cli.add_window(parser)
    parser.add_argument("--animate", action="store_true",
                        help="also the animation (rodyn-animate)")
    parser.add_argument("--paraview", action="store_true",
                        help="also the ParaView files (rodyn-paraview)")
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)
    path = Path(args.results)
    if not path.exists():
        print(f"{PROG}: error: {path}: no such results folder", file=sys.stderr)
        return errors.EXIT_BAD_INPUT
    kinds = cli.result_kinds(path)
    if path.is_file() and path.name == "dynamic.h5" and "static" in cli.result_kinds(
            path.parent):
        kinds.add("static")
    if not kinds:
        print(f"{PROG}: error: {path}: no rodyn results here (neither results.h5, "
              "static_nodes.csv, dynamic.h5 nor dynamic_nodes.csv)", file=sys.stderr)
        return errors.EXIT_BAD_INPUT
    names = []
    if "dynamic" in kinds:
        status = cli.run(PROG, lambda: names.extend(
            line.name for line in load_dynamic(path).lines))
        if status:
            return status
    worst = errors.EXIT_OK
    for module, argv_part in commands(args, kinds, names):
        worst = max(worst, module.main(argv_part))
    return worst


if __name__ == "__main__":
    sys.exit(main())
