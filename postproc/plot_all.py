#!/usr/bin/env python3
"""Every plot of a rodyn run, by the scripts of postproc/, in one command.

    python3 postproc/plot_all.py [RESULTS] [-o OUT_DIR] [--dpi DPI] [--window T0 T1]
                                 [--animate] [--paraview]

RESULTS is a results folder (default: paper_cable, the output folder of the main deck
input/paper_cable.inp) or a results.h5 / dynamic.h5 file. What is made depends on the
results found there:

  static results   plot_static.py: static_shape.png (the paper's Figure 2),
                   static_tension.png; in water also static_wall_tension.png and,
                   when a line touches the seabed, static_seabed.png
  dynamic results  plot_dynamic.py: dynamic_snapshots.png (Figures 3-6),
                   dynamic_tension.png, dynamic_energy.png, dynamic_momentum.png;
                   range_graph.py: range_graph.png and .csv;
                   plot_history.py for every line: history_<LINE>.png and .csv
                   (top, mid, bottom: tension, moment, curvature, z);
                   with --animate animate.py (GIF, MP4 when ffmpeg is there), with
                   --paraview to_paraview.py (OUT_DIR/paraview/ or RESULTS/paraview/)

Each script prints the paths it writes and its own messages; --dpi and --window go to
the scripts that take them (default: each script's own). The exit status is the
highest of the scripts' (0 success, 1 bad input, 3 cannot write), 1 when RESULTS holds
no results; 2 bad command line.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from rodyn_post import cli, load_dynamic  # noqa: E402
import animate  # noqa: E402
import plot_dynamic  # noqa: E402
import plot_history  # noqa: E402
import plot_static  # noqa: E402
import range_graph  # noqa: E402
import to_paraview  # noqa: E402

PROG = "plot_all"


def commands(args, kinds, line_names):
    """[(script module, argv)] to run, in order."""
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
    parser = cli.make_parser(f"{PROG}.py", cli.help_text(__doc__),
                             results_default=cli.STATIC_DEFAULT,
                             results_help="results folder, results.h5 or dynamic.h5",
                             dpi=None)
    parser.add_argument("--dpi", type=cli.positive_float,
                        help="resolution of the PNGs (default: each script's own)")
    cli.add_window(parser)
    parser.add_argument("--animate", action="store_true",
                        help="also the animation (animate.py)")
    parser.add_argument("--paraview", action="store_true",
                        help="also the ParaView files (to_paraview.py)")
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)
    path = Path(args.results)
    if not path.exists():
        print(f"{PROG}: error: {path}: no such results folder", file=sys.stderr)
        return cli.EXIT_BAD_INPUT
    kinds = cli.result_kinds(path)
    if path.is_file() and path.name == "dynamic.h5" and "static" in cli.result_kinds(
            path.parent):
        kinds.add("static")
    if not kinds:
        print(f"{PROG}: error: {path}: no rodyn results here (neither results.h5, "
              "static_nodes.csv, dynamic.h5 nor dynamic_nodes.csv)", file=sys.stderr)
        return cli.EXIT_BAD_INPUT
    names = []
    if "dynamic" in kinds:
        status = cli.run(PROG, lambda: names.extend(
            line.name for line in load_dynamic(path).lines))
        if status:
            return status
    worst = cli.EXIT_OK
    for module, argv_part in commands(args, kinds, names):
        worst = max(worst, module.main(argv_part))
    return worst


if __name__ == "__main__":
    sys.exit(main())
