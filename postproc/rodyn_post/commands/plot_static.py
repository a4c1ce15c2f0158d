"""Plot the static results of a rodyn run.

    rodyn-plot-static [RESULTS] [-o OUT_DIR] [--dpi 200]

RESULTS is a results folder (default: paper_cable, the output folder of
input/paper_cable.inp run from the current directory) or a results.h5 file. Writes
into OUT_DIR (default: the results folder) and prints the paths written:

  static_shape.png    x-z elevation of every line (equal axes), nodes and supports; with
                      water, the sea surface, the seabed's trace in the plane of the
                      lines (y = mean y of the nodes) and an inset of the current
                      profile (speed against z) when a current is given
  static_plan.png     when the lines leave the x-z plane (their y spans more than 1e-6
                      of their x-z extent: a cross current, a load across the plane):
                      x-y plan view of every line (equal axes), nodes and supports
  static_tension.png  effective tension and bending moment magnitude against arc length
  static_wall_tension.png   with water (or a wall tension other than the effective one):
                      wall and effective tension against arc length
  static_seabed.png   when a line touches the seabed: seabed normal and friction force
                      per length against arc length, touchdown points marked
  static_offset_curve.png   with *OFFSET CURVE (static_offset_curve.csv): the body's
                      restoring force and its most loaded fairlead's force against its
                      offset
  static_modes.png    with *MODAL (results.h5's /modes or static_modes.csv): the first
                      modes (up to 6), each as the static shape (grey) and the shape
                      displaced by the mode scaled to 10 % of the system's size, in the
                      plane of the two axes the mode moves along most (with one axis of
                      motion: it and the other axis the lines extend along most; x-z or
                      x-y for lines in an x-z plane); titled with the mode number,
                      period and dominant object

A run that did not complete is still plotted (its last converged state), with a
warning on stderr and in the plot titles.

Exit status: 0 success, 1 bad input (missing or malformed results), 2 bad command
line, 3 cannot write the plots.
"""
import sys

import numpy as np
from matplotlib.figure import Figure

from rodyn_post import cli, load_static  # cli: the Agg backend (never needs a display)
from rodyn_post.modes import load_modes
from rodyn_post.results import load_offset_curve
from rodyn_post.cli import static_title as run_title
from rodyn_post.environment import (current_inset, draw_sea, elevation_range,
                                    fit_elevation, scale_note)

PROG = "plot_static"  # prefix of its messages
COMMAND = "rodyn-plot-static"  # its console command (postproc/pyproject.toml)

SHAPE_PNG = "static_shape.png"
PLAN_PNG = "static_plan.png"
TENSION_PNG = "static_tension.png"
WALL_PNG = "static_wall_tension.png"
SEABED_PNG = "static_seabed.png"
OFFSET_PNG = "static_offset_curve.png"
MODES_PNG = "static_modes.png"
MODES_PLOTTED = 6      # modes drawn in static_modes.png (the longest periods)
MODE_FRACTION = 0.1    # largest displacement drawn, as a fraction of the system's size
AXES = "xyz"
MOVING = 0.01          # share of a mode's motion along an axis that counts (mode_axes)


def tension_curves(line):
    """Plotted data of static_tension.png for one line: S [m] of the integration
    points, effective tension [kN], bending moment magnitude sqrt(M1^2+M2^2) [kN m]."""
    return line.gp_s, line.effective_tension / 1e3, line.moment_magnitude / 1e3


def wall_curves(line):
    """Plotted data of static_wall_tension.png for one line: S [m] of the integration
    points, wall tension [kN], effective tension [kN]."""
    return line.gp_s, line.wall_tension / 1e3, line.effective_tension / 1e3


def seabed_curves(line):
    """Plotted data of static_seabed.png for one line: S [m] of the nodes, seabed normal
    and friction force per length [kN/m], touchdown S [m] (None when none)."""
    touchdown = line.touchdown_s if line.touchdown_s >= 0.0 else None
    return line.node_s, line.seabed_normal / 1e3, line.seabed_friction / 1e3, touchdown


def plane_y(lines_xyz):
    """y of the plotted x-z plane: the mean y of all nodes [m]."""
    return float(np.mean(np.concatenate([xyz[:, 1] for xyz in lines_xyz])))


def wants_plan(results):
    """Whether static_plan.png is drawn: the nodes' y spans more than 1e-6 of the
    lines' extent in x and z."""
    xyz = np.concatenate([line.node_xyz for line in results.lines])
    span = np.ptp(xyz, axis=0)
    return span[1] > 1e-6 * max(span[0], span[2], 1e-30)


def draw_lines(ax, results, k):
    """Every line's nodes in the x-(axis k) plane, its held ends marked."""
    support_label = "support"
    for line in results.lines:
        x, y = line.node_xyz[:, 0], line.node_xyz[:, k]
        ax.plot(x, y, "-o", markersize=3, linewidth=1.5, label=line.name)
        for end, held in zip((0, -1), line.end_held):
            if held:
                ax.plot(x[end], y[end], "k^", markersize=10, markerfacecolor="none",
                        markeredgewidth=1.5, label=support_label)
                support_label = None  # one legend entry for all supports


def plan_figure(results):
    """Figure of the x-y plan view of every line: nodes marked, held ends marked."""
    fig = Figure(figsize=(7.5, 5), layout="constrained")
    ax = fig.add_subplot()
    draw_lines(ax, results, 1)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(True, linewidth=0.5, alpha=0.5)
    ax.legend(loc="best")
    fig.suptitle(run_title(results, "static shape, x-y plan"))
    return fig


def wants_wall(results):
    """Whether static_wall_tension.png is drawn: the run has water, or some wall tension
    differs from the effective tension."""
    return results.environment is not None or any(
        np.any(line.wall_tension != line.effective_tension) for line in results.lines)


def wants_seabed(results):
    """Whether static_seabed.png is drawn: some seabed force is not zero."""
    return any(np.any(line.seabed_normal != 0.0) or np.any(line.seabed_friction != 0.0)
               for line in results.lines)


def shape_figure(results):
    """Figure of the x-z elevation of every line: nodes marked, held ends marked; the
    sea surface, seabed and current profile when the run has water."""
    fig = Figure(figsize=(7.5, 5), layout="constrained")
    ax = fig.add_subplot()
    draw_lines(ax, results, 2)
    env = results.environment
    if env is not None:
        xyz = [line.node_xyz for line in results.lines]
        draw_sea(ax, env, elevation_range([p[:, 0] for p in xyz]), plane_y(xyz))
        current_inset(ax, env)
    exaggeration = fit_elevation(ax)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.grid(True, linewidth=0.5, alpha=0.5)
    ax.legend(loc="best")
    fig.suptitle(run_title(results, "static shape, x-z elevation" + scale_note(exaggeration)))
    return fig


def tension_figure(results):
    """Figure with effective tension (top) and bending moment magnitude (bottom)
    against unstretched arc length, one curve per line; tension alone when no line has
    a bending moment (lines of cable elements)."""
    bending = any(np.any(line.moment_magnitude) for line in results.lines)
    fig = Figure(figsize=(7.5, 6.5 if bending else 4.0), layout="constrained")
    axes = np.atleast_1d(fig.subplots(2 if bending else 1, 1, sharex=True))
    for line in results.lines:
        s, tension, moment = tension_curves(line)
        axes[0].plot(s, tension, ".-", label=line.name)
        if bending:
            axes[1].plot(s, moment, ".-", label=line.name)
    axes[0].set_ylabel("effective tension [kN]")
    if bending:
        axes[1].set_ylabel("bending moment |M| [kN m]")
    axes[-1].set_xlabel("arc length S (unstretched, from end A) [m]")
    for ax in axes:
        ax.grid(True, linewidth=0.5, alpha=0.5)
        ax.legend(loc="best")
    fig.suptitle(run_title(results, "static effective tension and bending moment" if bending
                           else "static effective tension (cable elements: no bending)"))
    return fig


def wall_figure(results):
    """Wall (solid) and effective (dashed) tension against arc length, per line."""
    fig = Figure(figsize=(7.5, 4.5), layout="constrained")
    ax = fig.add_subplot()
    for k, line in enumerate(results.lines):
        s, wall, effective = wall_curves(line)
        ax.plot(s, wall, "-", color=f"C{k}", label=f"{line.name}: wall tension")
        ax.plot(s, effective, "--", color=f"C{k}", label=f"{line.name}: effective tension")
    ax.set_ylabel("tension [kN]")
    ax.set_xlabel("arc length S (unstretched, from end A) [m]")
    ax.grid(True, linewidth=0.5, alpha=0.5)
    ax.legend(loc="best", fontsize=8)
    fig.suptitle(run_title(results, "wall and effective tension "
                                    "(T_eff = T_wall - p_i A_i + p_o A_o)"))
    return fig


def seabed_figure(results):
    """Seabed normal (top) and friction (bottom) force per length against arc length,
    the touchdown points as vertical dotted lines."""
    fig = Figure(figsize=(7.5, 6), layout="constrained")
    ax_n, ax_f = fig.subplots(2, 1, sharex=True)
    for k, line in enumerate(results.lines):
        s, normal, friction, touchdown = seabed_curves(line)
        ax_n.plot(s, normal, ".-", color=f"C{k}", label=line.name)
        ax_f.plot(s, friction, ".-", color=f"C{k}", label=line.name)
        if touchdown is not None:
            for ax in (ax_n, ax_f):
                ax.axvline(touchdown, color=f"C{k}", linestyle=":", linewidth=1.0,
                           label=f"{line.name}: touchdown S = {touchdown:.4g} m"
                           if ax is ax_n else None)
    ax_n.set_ylabel("seabed normal force [kN/m]")
    ax_f.set_ylabel("seabed friction force [kN/m]")
    ax_f.set_xlabel("arc length S (unstretched, from end A) [m]")
    for ax in (ax_n, ax_f):
        ax.grid(True, linewidth=0.5, alpha=0.5)
        ax.legend(loc="best", fontsize=8)
    fig.suptitle(run_title(results, "seabed contact force per unit length"))
    return fig


def offset_figure(results):
    """The body's restoring force and its most loaded fairlead's force against its
    offset (*OFFSET CURVE)."""
    curve = load_offset_curve(results.folder)
    off, force, fair = curve["offset_m"], curve["force_N"], curve["max_end_force_N"]
    fig = Figure(figsize=(7.0, 4.5))
    ax = fig.add_subplot(1, 1, 1)
    ax.plot(off, force / 1e3, "o-", label="restoring force (the force applied)")
    ax.plot(off, fair / 1e3, "s--", label="most loaded line end")
    ax.set_xlabel(f"offset of {curve['body']} along the force [m]")
    ax.set_ylabel("force [kN]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.suptitle(run_title(results, "offset curve"))
    return fig


def mode_scale(modes):
    """Factor on the mode shapes (largest translation 1 m) in static_modes.png: a
    MODE_FRACTION of the system's size (1 for a system of no size)."""
    size = modes.extent()
    return MODE_FRACTION * size if size > 0.0 else 1.0


def mode_axes(modes, k):
    """(i, j), i < j: the plane of global axes (0 x, 1 y, 2 z) static_modes.png draws
    mode k (from 1) in. An axis moves when it holds at least MOVING of the mode's sum of
    squares of the node translations: the plane of the two that move most, or of the
    one that moves and, of the other two, the one the static lines extend along most
    (so that the static shape is not drawn edge on)."""
    moved = np.concatenate([line.translation[k - 1] for line in modes.lines])
    motion = np.sum(moved ** 2, axis=0)
    extent = np.ptp(np.concatenate([line.node_xyz for line in modes.lines]), axis=0)
    moving = motion >= MOVING * np.sum(motion)
    rank = sorted(range(3), key=lambda c: (moving[c], motion[c] if moving[c] else extent[c]),
                  reverse=True)
    return min(rank[:2]), max(rank[:2])


def mode_title(modes, k) -> str:
    """'mode k: T = ... s, dominant (share)' of mode k (from 1)."""
    text = f"mode {k}: T = {modes.period_s[k - 1]:.4g} s"
    if modes.dominant[k - 1]:
        text += f", {modes.dominant[k - 1]}"
        if np.isfinite(modes.share[k - 1]):
            text += f" ({modes.share[k - 1]:.0%})"
    return text


def modes_figure(results, modes):
    """The first MODES_PLOTTED modes, one panel each: every line's static shape (grey)
    and its shape displaced by the scaled mode (the line's colour)."""
    count = min(MODES_PLOTTED, modes.n_modes)
    columns = 1 if count == 1 else 2
    rows = -(-count // columns)
    fig = Figure(figsize=(5.0 * columns, 3.6 * rows + 0.6), layout="constrained")
    axes = np.atleast_1d(fig.subplots(rows, columns, squeeze=False).ravel())
    scale = mode_scale(modes)
    for k, ax in enumerate(axes[:count], 1):
        i, j = mode_axes(modes, k)
        for n, line in enumerate(modes.lines):
            moved = line.displaced(k, scale)
            ax.plot(line.node_xyz[:, i], line.node_xyz[:, j], "-", color="0.65",
                    linewidth=1.0, label="static" if n == 0 else None, gid="static")
            ax.plot(moved[:, i], moved[:, j], "-", color=f"C{n}", linewidth=1.5,
                    label=line.name, gid=f"mode {k}")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{AXES[i]} [m]")
        ax.set_ylabel(f"{AXES[j]} [m]")
        ax.set_title(mode_title(modes, k), fontsize=9)
        ax.grid(True, linewidth=0.5, alpha=0.5)
        ax.legend(loc="best", fontsize=7)
    for ax in axes[count:]:
        ax.set_visible(False)
    fig.suptitle(run_title(results, f"mode shapes (largest translation drawn "
                                    f"{scale:.3g} m)"))
    return fig


def results_modes(results):
    """The modes of these static results (rodyn_post.modes.load_modes), None without."""
    return load_modes(results.source if results.source.suffix == ".h5" else results.folder)


def figures(results):
    """[(PNG name, figure maker)] of the plots that apply to these results."""
    makers = [(SHAPE_PNG, shape_figure), (TENSION_PNG, tension_figure)]
    if load_offset_curve(results.folder):
        makers.append((OFFSET_PNG, offset_figure))
    modes = results_modes(results)
    if modes is not None:
        makers.append((MODES_PNG, lambda r: modes_figure(r, modes)))
    if wants_plan(results):
        makers.insert(1, (PLAN_PNG, plan_figure))
    if wants_wall(results):
        makers.append((WALL_PNG, wall_figure))
    if wants_seabed(results):
        makers.append((SEABED_PNG, seabed_figure))
    return makers


def parse_args(argv):
    """Command line arguments."""
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__),
                             results_default=cli.STATIC_DEFAULT,
                             results_help="results folder or results.h5 file", dpi=200.0)
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        results = load_static(args.results)
        if not results.complete:
            print(f"{PROG}: warning: the run did not complete ({results.status}; load "
                  f"factor {results.load_factor:.4g}): plotting its last converged state",
                  file=sys.stderr)
        out_dir = cli.output_dir(args, results.folder)
        for name, make in figures(results):
            print(cli.save_figure(make(results), out_dir / name, args.dpi))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
