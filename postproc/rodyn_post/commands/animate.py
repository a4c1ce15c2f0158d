"""Animation of the lines of a rodyn dynamic run (x-z elevation, equal axes).

    rodyn-animate [RESULTS] [-o OUT_DIR] [--window T0 T1] [--every N]
                  [--max-frames 150] [--fps 10] [--no-mp4] [--dpi 100]

RESULTS is a results folder (default: paper_case1) or a dynamic.h5 file. Writes into
OUT_DIR (default: the results folder) and prints the paths written:

  dynamic_animation.gif  every line at the output frames of the window, over the static
                         equilibrium (dashed), the time in the corner; written with
                         Pillow (matplotlib's PillowWriter), loops for ever
  dynamic_animation.mp4  the same as H.264 video, when ffmpeg is on the PATH (otherwise
                         a note on stderr, and no MP4); not with --no-mp4

Frames: the output frames with T0 <= t <= T1 (default: all), every N-th (--every);
when more than --max-frames remain, every k-th with k the smallest that keeps at most
that many (the last frame of the window is always shown). The axes are fixed: they
hold every line at every frame shown.
"""
import subprocess
import sys

import numpy as np
from matplotlib.animation import FFMpegWriter
from matplotlib.backends.backend_agg import FigureCanvasAgg
from PIL import Image

from rodyn_post import cli, errors, load_dynamic
from rodyn_post.quantities import check_window, matching_static, window_mask
from rodyn_post.environment import draw_sea, fit_elevation, scale_note

PROG = "animate"  # prefix of its messages
COMMAND = "rodyn-animate"  # its console command (postproc/pyproject.toml)
GIF = "dynamic_animation.gif"
MP4 = "dynamic_animation.mp4"


def animation_frames(results, window=None, every=1, max_frames=150):
    """Indices of the frames shown (see the module doc)."""
    selected = np.flatnonzero(window_mask(results.time, window))
    frames, last = selected[::every], selected[-1]
    stride = max(1, len(frames) // max_frames)
    while True:
        shown = frames[::stride]
        if shown[-1] != last:
            shown = np.r_[shown, last]
        if len(shown) <= max_frames:
            return [int(f) for f in shown]
        stride += 1


def axis_limits(results, frames, margin=0.05):
    """((x0, x1), (z0, z1)) holding every line at every frame shown, plus a margin."""
    x = np.concatenate([line.x[frames].ravel() for line in results.lines])
    z = np.concatenate([line.z[frames].ravel() for line in results.lines])
    pad = margin * max(np.ptp(x), np.ptp(z), 1e-6)
    return (x.min() - pad, x.max() + pad), (z.min() - pad, z.max() + pad)


def animation_figure(results, frames, dpi=100):
    """(figure, moving artists, update(frame index) -> None) of the animation."""
    fig = cli.new_figure(7.2, 4.8)
    fig.set_dpi(dpi)
    ax = fig.add_subplot()
    static = matching_static(results)
    curves = []
    for k, line in enumerate(results.lines):
        if static is not None:
            xyz = static.line(line.name).node_xyz
            ax.plot(xyz[:, 0], xyz[:, 2], "--", color="0.5", linewidth=1.0,
                    label=f"{line.name}: static")
        (curve,) = ax.plot(line.x[frames[0]], line.z[frames[0]], "-o", color=f"C{k}",
                           markersize=2, linewidth=1.6, label=line.name)
        curves.append(curve)
    (xlim, zlim) = axis_limits(results, frames)
    ax.update_datalim([(xlim[0], zlim[0]), (xlim[1], zlim[1])])   # every frame shown
    env = results.environment
    if env is not None:
        y = float(np.mean([line.y[frames].mean() for line in results.lines]))
        draw_sea(ax, env, xlim, y)
    exaggeration = fit_elevation(ax)
    if exaggeration == 1.0:
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlim(*ax.dataLim.intervalx)
        ax.set_ylim(*ax.dataLim.intervaly)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    cli.finish_axes(ax)
    clock = ax.text(0.02, 0.95, "", transform=ax.transAxes, va="top", fontsize=10)
    fig.suptitle(cli.dynamic_title(results, "x-z elevation" + scale_note(exaggeration)),
                 fontsize=9)

    def update(frame):
        for curve, line in zip(curves, results.lines):
            curve.set_data(line.x[frame], line.z[frame])
        clock.set_text(f"t = {results.time[frame]:.3f} s")

    return fig, curves + [clock], update


def gif_frames(fig, moving, update, frames):
    """RGB images of the frames: the still parts are drawn once, the moving artists
    on top of them for each frame (blitting; a full redraw per frame is 30 times
    slower)."""
    canvas = FigureCanvasAgg(fig)
    for artist in moving:
        artist.set_animated(True)      # left out of canvas.draw(): the background
    canvas.draw()
    fig.set_layout_engine("none")      # keep the layout of this draw
    background = canvas.copy_from_bbox(fig.bbox)
    size = canvas.get_width_height()
    for frame in frames:
        canvas.restore_region(background)
        update(frame)
        for artist in moving:
            fig.draw_artist(artist)
        yield Image.frombuffer("RGBA", size, bytes(canvas.buffer_rgba()), "raw", "RGBA",
                               0, 1).convert("RGB")


def to_palette(images):
    """The frames as palette images sharing the palette of the first frame (the same
    artists, so the same colours): one quantization instead of one per frame."""
    first = None
    for image in images:
        if first is None:
            first = image.quantize(colors=128)
            yield first
        else:
            yield image.quantize(palette=first, dither=Image.Dither.NONE)


def write_gif(fig, moving, update, frames, path, fps):
    """The GIF, written with Pillow as matplotlib's PillowWriter does (loops for ever)."""
    images = list(to_palette(gif_frames(fig, moving, update, frames)))
    try:
        images[0].save(path, save_all=True, append_images=images[1:],
                       duration=max(10, int(round(1000.0 / fps))), loop=0)
    except OSError as exc:
        raise errors.WriteError(f"cannot write {path}: {exc.strerror or exc}") from None
    return path


def write_mp4(fig, update, frames, path, fps, dpi):
    """The MP4, with matplotlib's FFMpegWriter (H.264, yuv420p for every player)."""
    writer = FFMpegWriter(fps=fps, codec="h264", extra_args=["-pix_fmt", "yuv420p"])
    try:
        with writer.saving(fig, str(path), dpi):
            for frame in frames:
                update(frame)
                writer.grab_frame()
    except (OSError, subprocess.CalledProcessError) as exc:
        raise errors.WriteError(f"cannot write {path}: {getattr(exc, 'strerror', None) or exc}") \
            from None
    return path


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__), dpi=100)
    cli.add_window(parser)
    parser.add_argument("--every", type=cli.positive_int, default=1, metavar="N",
                        help="use every N-th output frame (default: 1)")
    parser.add_argument("--max-frames", type=cli.positive_int, default=150, metavar="M",
                        help="at most M frames (default: 150)")
    parser.add_argument("--fps", type=cli.positive_float, default=10.0,
                        help="frames per second of the animation (default: 10)")
    parser.add_argument("--no-mp4", action="store_true", help="write the GIF only")
    args = cli.parse(parser, argv)
    if args.max_frames < 2:
        parser.error("--max-frames must be at least 2")
    return args


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        results = load_dynamic(args.results)
        check_window(results, args.window)
        cli.warn_dynamic(PROG, results)
        frames = animation_frames(results, args.window, args.every, args.max_frames)
        out = cli.output_dir(args, results.folder)
        fig, moving, update = animation_figure(results, frames, args.dpi)
        print(write_gif(fig, moving, update, frames, out / GIF, args.fps))
        if args.no_mp4:
            return
        if not FFMpegWriter.isAvailable():
            print(f"{PROG}: note: ffmpeg is not on the PATH: no MP4 written",
                  file=sys.stderr)
            return
        print(write_mp4(fig, update, frames, out / MP4, args.fps, args.dpi))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
