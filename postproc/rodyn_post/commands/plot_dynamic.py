"""Plot the dynamic results of a rodyn run.

    rodyn-plot-dynamic [RESULTS] [-o OUT_DIR] [--times T ...]
                       [--window T0 T1] [--snapshots N] [--no-envelope]
                       [--dpi 150]

RESULTS is a results folder (default: paper_case1, the output folder of
input/paper_case1.inp run from the current directory) or a dynamic.h5 file. Writes
into OUT_DIR (default: the results folder) and prints the paths written:

  dynamic_snapshots.png  x-z elevation of the lines at a few times of the last period of
                         the motion, over the static shape (equal axes) and the envelope
                         (every frame of the window, light grey), as the paper's
                         Figures 3-6; with water, the sea surface, the seabed's trace in
                         the plane of the lines and an inset of the current profile
  dynamic_tension.png    tension at the top and at the bottom support against time
  dynamic_energy.png     total energy minus its initial value and the net work done on
                         the lines (external + hydro + seabed - damping) against time,
                         and their difference
  dynamic_momentum.png   linear and angular momentum (x, y, z) minus their values at the
                         first step of the log, against time

--times picks the snapshot times (the nearest output frames); by default N (--snapshots,
8) frames spread over the last period of the harmonic *MOTION of the deck (from
dynamic.h5; with the CSV tables only, the period is estimated from the motion of the
node that moves most). --window T0 T1 limits the time histories and the envelope to
T0 <= t <= T1 and takes the default snapshots from the last period before T1.
--no-envelope leaves the envelope out.

Long runs: a history of more than 40 periods of the motion (or, without a harmonic
motion, more than 2000 points) would be drawn as a solid block; the tension, energy and
momentum histories of such a run show the whole run as the range (min to max) in bins of
two periods, beside a zoom on the last 5 periods drawn in full (zoom_start, band_bins).

Momentum: the step log has no row for t = 0, so the drift is measured from step 1. It is
zero (to the solver tolerance, for EMC) only for a line without supports, gravity or
loads; otherwise it shows the impulse of the supports and loads.

A run that did not complete is still plotted (what is on disk), with a warning on
stderr and in the plot titles.

Exit status: 0 success, 1 bad input (missing or malformed results, times outside the
run), 2 bad command line, 3 cannot write the plots.
"""
import sys

import numpy as np
from matplotlib import colormaps
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from rodyn_post import cli, load_dynamic  # cli: the Agg backend (never needs a display)
from rodyn_post.cli import dynamic_title as run_title
from rodyn_post.environment import (current_inset, draw_sea, elevation_range,
                                    fit_elevation, scale_note)
from rodyn_post.errors import InputError as PlotInputError
from rodyn_post.quantities import matching_static, window_mask

PROG = "plot_dynamic"  # prefix of its messages
COMMAND = "rodyn-plot-dynamic"  # its console command (postproc/pyproject.toml)

SNAPSHOTS_PNG = "dynamic_snapshots.png"
TENSION_PNG = "dynamic_tension.png"
ENERGY_PNG = "dynamic_energy.png"
MOMENTUM_PNG = "dynamic_momentum.png"

# --- the data behind the plots ------------------------------------------------------

def motion_period(results):
    """Period [s] of the excitation: 1/f of the lowest harmonic *MOTION frequency of the
    deck; without the deck text, estimated from the node coordinate that moves most over
    the second half of the run (mean time between its upward crossings of its mean);
    None if neither works."""
    freqs = results.motion_frequencies()
    if freqs:
        return 1.0 / min(freqs)
    t = results.time
    half = t >= t[len(t) // 2]
    if half.sum() < 5:
        return None
    best, series = 0.0, None
    for line in results.lines:
        for coord in (line.x, line.y, line.z):
            part = coord[half]
            spread = np.ptp(part, axis=0)
            node = int(np.argmax(spread))
            if spread[node] > best:
                best, series = spread[node], part[:, node] - part[:, node].mean()
    if series is None:
        return None
    th = t[half]
    up = np.flatnonzero((series[:-1] < 0.0) & (series[1:] >= 0.0))
    if len(up) < 2:
        return None
    # crossing times by linear interpolation
    tc = th[up] + (th[up + 1] - th[up]) * (-series[up]) / (series[up + 1] - series[up])
    return float((tc[-1] - tc[0]) / (len(tc) - 1))


def snapshot_frames(results, times=None, count=8, t_end=None):
    """Frame indices of the snapshots: the frames nearest to `times`, or `count` frames
    spread over the last period before t_end (default: the last frame). Raises
    PlotInputError for a time outside the run."""
    t = results.time
    if times:
        for value in times:
            if value < t[0] - 1e-9 or value > t[-1] + 1e-9:
                raise PlotInputError(f"--times: t = {value:g} s is outside the run "
                                     f"({t[0]:g} to {t[-1]:g} s)")
        return sorted({results.frame_at(v) for v in times})
    t_end = t[-1] if t_end is None else t_end
    last = int(np.searchsorted(t, t_end + 1e-9)) - 1
    if last < 0:
        raise PlotInputError(f"no frame at or before t = {t_end:g} s")
    period = motion_period(results)
    if period is None:
        period = 0.25 * (t[last] - t[0]) if last > 0 else 0.0
    # `count` times evenly over one period ending at the last frame (the period's
    # start is the same phase as its end, so it is left out)
    wanted = t[last] - period * np.arange(count)[::-1] / count
    frames = sorted({results.frame_at(v) for v in wanted if v >= t[0] - 1e-9})
    return [f for f in frames if f <= last]


def static_shapes(results):
    """{line name: (x, z)} of the static equilibrium when the run's folder has static
    results of the same lines, else of the first frame (the start); and a label."""
    static = matching_static(results)
    if static is not None:
        return {line.name: (static.line(line.name).node_xyz[:, 0],
                            static.line(line.name).node_xyz[:, 2])
                for line in results.lines}, "static"
    return {line.name: (line.x[0], line.z[0]) for line in results.lines}, \
        f"start (t = {results.time[0]:g} s)"


def snapshot_curves(line, frames):
    """Plotted data of dynamic_snapshots.png for one line: [(frame, x, z), ...]."""
    return [(f, line.x[f], line.z[f]) for f in frames]


def envelope_frames(results, window=None):
    """Frames drawn as the envelope: every frame in the window (default: all)."""
    return [int(f) for f in np.flatnonzero(window_mask(results.time, window))]


def tension_curves(results, line, window=None):
    """Plotted data of dynamic_tension.png for one line: {'top'|'bottom': (end index,
    time [s], tension [kN])} for the held ends; top is the higher end at t = 0."""
    mask = window_mask(results.time, window)
    curves = {}
    top = line.top_end
    for role, end in (("top", top), ("bottom", 1 - top)):
        if line.end_held[end]:
            curves[role] = (end, results.time[mask], line.end_tension[mask, end] / 1e3)
    return curves


def energy_curves(log, window=None):
    """Plotted data of dynamic_energy.png: time [s], total - total(0) [J], the net work
    external + hydro + seabed - damping [J], their difference [J] (the balance error)."""
    mask = window_mask(log.time, window)
    return (log.time[mask], log.energy_change[mask], log.net_work[mask],
            log.energy_error[mask])


def momentum_curves(log, window=None):
    """Plotted data of dynamic_momentum.png: time [s], linear momentum minus its value at
    step 1 (n, 3) [kg m/s], angular momentum minus its value at step 1 (n, 3) [kg m2/s]."""
    mask = window_mask(log.time, window)
    if len(log) == 0:
        return log.time, log.momentum, log.angular_momentum
    return (log.time[mask], (log.momentum - log.momentum[0])[mask],
            (log.angular_momentum - log.angular_momentum[0])[mask])


# --- figures ------------------------------------------------------------------------

def snapshots_figure(results, frames, envelope=None):
    """x-z elevation of every line at the given frames over the static shape, and over
    the envelope (every frame of `envelope`, light grey) when given."""
    fig = Figure(figsize=(8, 5.2), layout="constrained")
    ax = fig.add_subplot()
    shapes, static_label = static_shapes(results)
    cmap = colormaps["viridis"]
    if envelope:
        t0, t1 = results.time[envelope[0]], results.time[envelope[-1]]
        for k, line in enumerate(results.lines):
            segments = [np.column_stack([line.x[f], line.z[f]]) for f in envelope]
            ax.add_collection(LineCollection(
                segments, colors="0.8", linewidths=0.6, zorder=0,
                label=(f"envelope: {len(envelope)} frames, {t0:.4g} to {t1:.4g} s"
                       if k == 0 else None)))
    for line in results.lines:
        x0, z0 = shapes[line.name]
        ax.plot(x0, z0, "k--", linewidth=1.8, label=f"{line.name}: {static_label}")
        for k, (f, x, z) in enumerate(snapshot_curves(line, frames)):
            color = cmap(k / max(1, len(frames) - 1))
            ax.plot(x, z, "-", color=color, linewidth=1.1,
                    label=f"{line.name}: t = {results.time[f]:.4g} s")
    env = results.environment
    if env is not None:
        shown = envelope or frames or [0]
        xs = [line.x[f] for line in results.lines for f in shown]
        y = float(np.mean([line.y[f].mean() for line in results.lines for f in shown]))
        draw_sea(ax, env, elevation_range(xs), y)
        current_inset(ax, env)
    exaggeration = fit_elevation(ax)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.grid(True, linewidth=0.5, alpha=0.5)
    ax.legend(loc="best", fontsize=7, ncol=2 if len(frames) > 5 else 1)
    span = results.time[frames[-1]] - results.time[frames[0]] if frames else 0.0
    fig.suptitle(run_title(results, f"dynamic configurations, x-z elevation "
                                    f"({len(frames)} frames over {span:.4g} s"
                                    f"{scale_note(exaggeration)})"))
    return fig


def zoom_start(results, t):
    """Start [s] of the zoom panel of a long history, None for a short one. A history is
    long when it holds more than 40 periods of the motion (or, without a harmonic motion,
    more than 2000 points): drawn whole it would be a solid block. The zoom shows the last
    5 periods (the last twentieth of the run without a period)."""
    if len(t) < 2:
        return None
    span = t[-1] - t[0]
    period = motion_period(results)
    if period is not None and period > 0.0:
        return t[-1] - 5.0 * period if span > 40.0 * period else None
    return t[-1] - span / 20.0 if len(t) > 2000 else None


def band_bins(results, t):
    """Bins of the whole-run band: 300, or fewer so that each holds two periods of the
    motion (a bin shorter than a period would show the phase of the oscillation in it,
    not its range)."""
    period = motion_period(results)
    if period is None or not period > 0.0 or len(t) < 2:
        return 300
    return int(max(10, min(300, (t[-1] - t[0]) / (2.0 * period))))


def draw_history(axes, t, y, t0, bins=300, style="-", **kw):
    """A history on axes (whole run, zoom or None): whole when t0 is None; else the whole
    run as the band between the minimum and maximum of each of `bins` bins in time (what
    a plot of every point shows at this size, without the solid block) and the last part,
    from t0, as a curve on the zoom axes."""
    ax_all, ax_zoom = axes
    if t0 is None:
        ax_all.plot(t, y, style, **kw)
        return
    edges = np.linspace(t[0], t[-1], bins + 1)
    k = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, bins - 1)
    lo = np.full(bins, np.nan)
    hi = np.full(bins, np.nan)
    np.fmin.at(lo, k, y)
    np.fmax.at(hi, k, y)
    mid = 0.5 * (edges[:-1] + edges[1:])
    keep = ~np.isnan(lo)
    band = ax_all.fill_between(mid[keep], lo[keep], hi[keep], alpha=0.6, linewidth=0.5,
                               label=kw.get("label"), color=kw.get("color"))
    color = kw.pop("color", None) or band.get_facecolor()[0]
    ax_all.axvspan(t0, t[-1], color="0.85", zorder=0)
    last = t >= t0
    ax_zoom.plot(t[last], y[last], style, color=color, **kw)


def history_axes(fig, rows, t0, bins=300):
    """[(whole-run axes, zoom axes or None), ...] for `rows` rows of histories: one
    column, or two (the whole run, the last part) when t0 is not None."""
    if t0 is None:
        return [(ax, None) for ax in np.atleast_1d(fig.subplots(rows, 1, sharex=True))]
    grid = fig.subplots(rows, 2, sharex="col", width_ratios=(3, 2), squeeze=False)
    grid[0, 1].set_title("last part (grey on the left)", fontsize=9)
    grid[0, 0].set_title(f"whole run: range in each of {bins} bins of time", fontsize=9)
    return [tuple(row) for row in grid]


def finish_history_axes(rows, xlabel="time [s]"):
    for ax_all, ax_zoom in rows:
        for ax in (ax_all, ax_zoom):
            if ax is not None:
                ax.grid(True, linewidth=0.5, alpha=0.5)
                if ax.get_legend_handles_labels()[0]:
                    ax.legend(loc="best", fontsize=8)
    for ax in rows[-1]:
        if ax is not None:
            ax.set_xlabel(xlabel)


def tension_figure(results, window=None):
    """Top and bottom support tension [kN] against time, one curve per line; a long run
    as its range per bin beside a zoom on its last periods (zoom_start)."""
    mask = window_mask(results.time, window)
    t0 = zoom_start(results, results.time[mask])
    bins = band_bins(results, results.time[mask])
    fig = Figure(figsize=(8 if t0 is None else 11, 6), layout="constrained")
    rows = history_axes(fig, 2, t0, bins)
    for line in results.lines:
        for role, (end, t, tension) in tension_curves(results, line, window).items():
            axes = rows[0] if role == "top" else rows[1]
            draw_history(axes, t, tension, t0, bins, "-", linewidth=0.9,
                         label=f"{line.name} end {'AB'[end]}")
    rows[0][0].set_ylabel("top tension [kN]")
    rows[1][0].set_ylabel("bottom tension [kN]")
    finish_history_axes(rows)
    fig.suptitle(run_title(results, "support tension |F| at the held ends"))
    return fig


def energy_figure(results, window=None):
    """Energy change and net work against time (top), their difference (bottom); a long
    run as its range per bin beside a zoom on its last periods (zoom_start)."""
    t, change, work, error = energy_curves(results.log, window)
    t0 = zoom_start(results, t)
    bins = band_bins(results, t)
    fig = Figure(figsize=(8 if t0 is None else 11, 6), layout="constrained")
    rows = history_axes(fig, 2, t0, bins)
    draw_history(rows[0], t, change, t0, bins, "-", linewidth=1.2,
                 label="total energy - total(0)")
    draw_history(rows[0], t, work, t0, bins, "--", linewidth=1.2,
                 label=work_label(results.log))
    draw_history(rows[1], t, error, t0, bins, "-", linewidth=0.9, color="C3",
                 label="difference")
    rows[0][0].set_ylabel("energy [J]")
    rows[1][0].set_ylabel("difference [J]")
    finish_history_axes(rows)
    scheme = f"{results.scheme}, " if results.scheme else ""
    fig.suptitle(run_title(results, f"energy balance ({scheme}total = kinetic + strain + "
                                    "gravity; total(0) from step 1)"))
    return fig


def work_label(log):
    """Legend of the net work: the terms the log holds (external work always)."""
    text = "external work"
    for name, values in (("hydro", log.hydro_work), ("seabed", log.seabed_work)):
        if np.any(values != 0.0):
            text += f" + {name} work"
    if np.any(log.damping_work != 0.0):
        text += " - damping work"
    return text


def momentum_figure(results, window=None):
    """Linear (top) and angular (bottom) momentum components minus their step-1 values;
    a long run as its range per bin beside a zoom on its last periods (zoom_start)."""
    t, dp, dl = momentum_curves(results.log, window)
    t0 = zoom_start(results, t)
    bins = band_bins(results, t)
    fig = Figure(figsize=(8 if t0 is None else 11, 6), layout="constrained")
    rows = history_axes(fig, 2, t0, bins)
    for k, axis in enumerate("xyz"):
        draw_history(rows[0], t, dp[:, k], t0, bins, "-", linewidth=1.0, color=f"C{k}",
                     label=f"p{axis} - p{axis}(step 1)")
        draw_history(rows[1], t, dl[:, k], t0, bins, "-", linewidth=1.0, color=f"C{k}",
                     label=f"L{axis} - L{axis}(step 1)")
    rows[0][0].set_ylabel("linear momentum drift [kg m/s]")
    rows[1][0].set_ylabel("angular momentum drift [kg m2/s]")
    if len(t):
        finish_history_axes(rows)
    else:
        for ax_all, _ in rows:
            ax_all.grid(True, linewidth=0.5, alpha=0.5)
        rows[-1][0].set_xlabel("time [s]")
    start = f"t = {results.log.time[0]:.4g} s" if len(results.log) else "none"
    fig.suptitle(run_title(results, f"momentum minus its value at step 1 ({start}); "
                                    "angular momentum about the origin"))
    return fig


# --- command line -------------------------------------------------------------------

def parse_args(argv):
    """Command line arguments."""
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__), dpi=150.0)
    parser.add_argument("--times", type=float, nargs="+", metavar="T",
                        help="snapshot times [s] (nearest frames; default: the last "
                             "period of the motion)")
    cli.add_window(parser)
    parser.add_argument("--snapshots", type=cli.positive_int, default=8,
                        help="number of default snapshots (default: 8)")
    parser.add_argument("--no-envelope", action="store_true",
                        help="leave the envelope (every frame, grey) out of the snapshots")
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        results = load_dynamic(args.results)
        if len(results.time) == 0:
            raise PlotInputError(f"{results.source}: no output frames")
        if args.window and (args.window[1] < results.time[0]
                            or args.window[0] > results.time[-1]):
            raise PlotInputError(f"--window {args.window[0]:g} {args.window[1]:g} s does not "
                                 f"overlap the run ({results.time[0]:g} to "
                                 f"{results.time[-1]:g} s)")
        t_end = min(args.window[1], results.time[-1]) if args.window else None
        frames = snapshot_frames(results, args.times, args.snapshots, t_end)
        cli.warn_dynamic(PROG, results)
        out_dir = cli.output_dir(args, results.folder)
        window = args.window
        envelope = None if args.no_envelope else envelope_frames(results, window)
        makers = ((SNAPSHOTS_PNG, lambda: snapshots_figure(results, frames, envelope)),
                  (TENSION_PNG, lambda: tension_figure(results, window)),
                  (ENERGY_PNG, lambda: energy_figure(results, window)),
                  (MOMENTUM_PNG, lambda: momentum_figure(results, window)))
        for name, make in makers:
            print(cli.save_figure(make(), out_dir / name, args.dpi))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
