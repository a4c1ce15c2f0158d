#!/usr/bin/env python3
"""Plot the static results of a rodyn run.

    python3 postproc/plot_static.py [RESULTS] [-o OUT_DIR] [--dpi 200]

RESULTS is a results folder (default: paper_cable, the output folder of
input/paper_cable.inp run from the current directory) or a results.h5 file. Writes
into OUT_DIR (default: the results folder) and prints the paths written:

  static_shape.png    x-z elevation of every line (equal axes), nodes and supports
  static_tension.png  effective tension and bending moment magnitude against arc length

A run that did not complete is still plotted (its last converged state), with a
warning on stderr and in the plot titles.

Exit status: 0 success, 1 bad input (missing or malformed results), 2 bad command
line, 3 cannot write the plots.
"""
import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # never needs a display
from matplotlib.figure import Figure  # noqa: E402  (after the backend choice)

sys.path.insert(0, str(Path(__file__).resolve().parent))
from rodyn_post import RodynResultsError, load_static  # noqa: E402
from rodyn_post.cli import static_title as run_title  # noqa: E402

SHAPE_PNG = "static_shape.png"
TENSION_PNG = "static_tension.png"


def shape_curve(line):
    """Plotted data of static_shape.png for one line: node x [m], node z [m]."""
    return line.node_xyz[:, 0], line.node_xyz[:, 2]


def tension_curves(line):
    """Plotted data of static_tension.png for one line: S [m] of the integration
    points, effective tension [kN], bending moment magnitude sqrt(M1^2+M2^2) [kN m]."""
    return line.gp_s, line.effective_tension / 1e3, line.moment_magnitude / 1e3


def shape_figure(results):
    """Figure of the x-z elevation of every line: nodes marked, held ends marked."""
    fig = Figure(figsize=(7.5, 5), layout="constrained")
    ax = fig.add_subplot()
    support_label = "support"
    for line in results.lines:
        x, z = shape_curve(line)
        ax.plot(x, z, "-o", markersize=3, linewidth=1.5, label=line.name)
        for end, held in zip((0, -1), line.end_held):
            if held:
                ax.plot(x[end], z[end], "k^", markersize=10, markerfacecolor="none",
                        markeredgewidth=1.5, label=support_label)
                support_label = None  # one legend entry for all supports
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.grid(True, linewidth=0.5, alpha=0.5)
    ax.legend(loc="best")
    fig.suptitle(run_title(results, "static shape, x-z elevation"))
    return fig


def tension_figure(results):
    """Figure with effective tension (top) and bending moment magnitude (bottom)
    against unstretched arc length, one curve per line."""
    fig = Figure(figsize=(7.5, 6.5), layout="constrained")
    ax_t, ax_m = fig.subplots(2, 1, sharex=True)
    for line in results.lines:
        s, tension, moment = tension_curves(line)
        ax_t.plot(s, tension, ".-", label=line.name)
        ax_m.plot(s, moment, ".-", label=line.name)
    ax_t.set_ylabel("effective tension [kN]")
    ax_m.set_ylabel("bending moment |M| [kN m]")
    ax_m.set_xlabel("arc length S (unstretched, from end A) [m]")
    for ax in (ax_t, ax_m):
        ax.grid(True, linewidth=0.5, alpha=0.5)
        ax.legend(loc="best")
    fig.suptitle(run_title(results, "static effective tension and bending moment"))
    return fig


def parse_args(argv):
    """Command line arguments."""
    parser = argparse.ArgumentParser(
        description="Plot the static shape, tension and bending moment of a rodyn run.",
        epilog="exit status: 0 success, 1 bad input, 2 bad command line, "
               "3 cannot write the plots")
    parser.add_argument("results", nargs="?", default="paper_cable",
                        help="results folder or results.h5 file (default: paper_cable)")
    parser.add_argument("-o", "--out-dir", help="folder for the PNGs "
                        "(default: the results folder)")
    parser.add_argument("--dpi", type=float, default=200, help="resolution (default: 200)")
    args = parser.parse_args(argv)
    if args.dpi <= 0:
        parser.error("--dpi must be positive")
    return args


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)
    try:
        results = load_static(args.results)
    except RodynResultsError as exc:
        print(f"plot_static: error: {exc}", file=sys.stderr)
        return 1
    if not results.complete:
        print(f"plot_static: warning: the run did not complete ({results.status}; load "
              f"factor {results.load_factor:.4g}): plotting its last converged state",
              file=sys.stderr)
    out_dir = Path(args.out_dir) if args.out_dir else results.folder
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
        for name, make in ((SHAPE_PNG, shape_figure), (TENSION_PNG, tension_figure)):
            path = out_dir / name
            make(results).savefig(path, dpi=args.dpi)
            print(path)
    except OSError as exc:
        print(f"plot_static: error: cannot write {exc.filename or out_dir}: "
              f"{exc.strerror or exc}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
