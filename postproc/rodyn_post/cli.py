"""The command-line scaffold of every rodyn_post command (rodyn_post.commands, the
console commands rodyn-plot-static, rodyn-compare, ...): arguments, messages, exit
statuses, titles and writing files. Importing it selects matplotlib's Agg backend (no
display is ever needed).

Every command's main(argv=None) builds its parser with make_parser, reads its
arguments with parse and runs its body through run, which turns the errors of
rodyn_post.errors into a one-line message on stderr and the exit status:
0 success, 1 bad input (missing or malformed results or reference file, a request the
results cannot answer; one-line message naming the file), 2 bad command line
(argparse), 3 an output cannot be written; `rodyn-compare` adds 4: a metric above its
--tol.
"""
from __future__ import annotations

import argparse
import csv
import sys
import textwrap
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # never needs a display
from matplotlib.figure import Figure  # noqa: E402  (after the backend choice)

from .errors import EXIT_OK, InputError, RodynResultsError, WriteError, exit_status  # noqa: E402
STATIC_DEFAULT = "paper_cable"    # output folder of input/paper_cable.inp (the main deck)
DYNAMIC_DEFAULT = "paper_case1"   # output folder of input/paper_case1.inp
EPILOG = ("exit status: 0 success, 1 bad input (missing or malformed results), 2 bad "
          "command line, 3 cannot write the outputs")


def positive_float(text: str) -> float:
    """argparse type: a number > 0."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not value > 0.0:
        raise argparse.ArgumentTypeError(f"{text} is not positive")
    return value


def positive_int(text: str) -> int:
    """argparse type: a whole number >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text} is less than 1")
    return value


def help_text(doc: str) -> str:
    """A command's docstring for --help, without its usage paragraph (the one that
    starts with the command's name; argparse prints its own)."""
    paragraphs = doc.strip("\n").split("\n\n")
    return "\n\n".join(p for p in paragraphs
                       if not p.lstrip().startswith(("rodyn-", "python3 ")))


def make_parser(prog: str, description: str, results_default=DYNAMIC_DEFAULT,
                results_help="results folder or dynamic.h5 file", dpi=150.0,
                epilog=EPILOG, results=True) -> argparse.ArgumentParser:
    """ArgumentParser of command `prog` with the arguments every command has: RESULTS
    (optional, with its default folder), -o/--out-dir and --dpi (not with dpi=None)."""
    parser = argparse.ArgumentParser(prog=prog, description=description, epilog=epilog,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    if results:
        parser.add_argument("results", nargs="?", default=results_default,
                            help=f"{results_help} (default: {results_default}, the output "
                                 "folder of its deck run from the current folder)")
    parser.add_argument("-o", "--out-dir", metavar="OUT_DIR",
                        help="folder for the outputs (default: the results folder; "
                             "created if needed)")
    if dpi is not None:
        parser.add_argument("--dpi", type=positive_float, default=dpi,
                            help=f"resolution of the PNGs (default: {dpi:g})")
    return parser


def add_window(parser):
    parser.add_argument("--window", type=float, nargs=2, metavar=("T0", "T1"),
                        help="time window [s]: the frames with T0 <= t <= T1 "
                             "(default: the whole run)")


def add_line(parser, every=False):
    parser.add_argument("--line", metavar="NAME",
                        help="line name (default: " + ("every line" if every else
                                                       "the first line of the deck") + ")")


def parse(parser, argv):
    """parse_args plus the checks shared by all commands (--window order)."""
    args = parser.parse_args(argv)
    window = getattr(args, "window", None)
    if window and not window[1] > window[0]:
        parser.error("--window: T1 must be greater than T0")
    if window:
        args.window = tuple(window)
    return args


def run(prog: str, body) -> int:
    """Call body() (returns an exit status or None) and turn the known failures into
    a one-line message on stderr and their exit status."""
    try:
        status = body()
    except (RodynResultsError, InputError, WriteError) as exc:
        print(f"{prog}: error: {one_line(exc)}", file=sys.stderr)
        return exit_status(exc)
    return EXIT_OK if status is None else status


def one_line(exc) -> str:
    return " ".join(str(exc).split("\n"))


def warn_dynamic(prog: str, results):
    """The reader's warnings, and one for a run that did not complete, on stderr."""
    for warning in results.warnings:
        print(f"{prog}: warning: {warning}", file=sys.stderr)
    if not results.complete:
        print(f"{prog}: warning: the run did not complete ({results.status}; t "
              f"reached {results.time_reached_s:.4g} s): using what is on disk",
              file=sys.stderr)


def output_dir(args, folder: Path, sub: str = None) -> Path:
    """-o OUT_DIR, or the results folder (plus `sub`), created if needed."""
    out = Path(args.out_dir) if args.out_dir else Path(folder)
    if sub:
        out = out / sub
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise WriteError(f"cannot write {exc.filename or out}: {exc.strerror or exc}") \
            from None
    return out


def save_figure(fig, path: Path, dpi: float) -> Path:
    """fig.savefig(path); an OSError becomes a WriteError naming the file."""
    try:
        fig.savefig(path, dpi=dpi)
    except OSError as exc:
        raise WriteError(f"cannot write {path}: {exc.strerror or exc}") from None
    return path


def real(value: float) -> str:
    """A real as rodyn writes it: 17 significant digits (exact when read back)."""
    return f"{value:.16E}"


def write_text(path: Path, text: str) -> Path:
    try:
        Path(path).write_text(text, encoding="utf-8")
    except OSError as exc:
        raise WriteError(f"cannot write {path}: {exc.strerror or exc}") from None
    return path


def result_kinds(path) -> set:
    """Which results a folder holds, {'static', 'dynamic'} or a part of it, from the
    files present; for a file: 'dynamic' for dynamic.h5, 'static' for another .h5."""
    path = Path(path)
    if path.is_file():
        return {"dynamic" if path.name == "dynamic.h5" else "static"}
    kinds = set()
    if (path / "results.h5").is_file() or (path / "static_nodes.csv").is_file():
        kinds.add("static")
    if (path / "dynamic.h5").is_file() or (path / "dynamic_nodes.csv").is_file():
        kinds.add("dynamic")
    return kinds


def write_csv(path: Path, header, rows) -> Path:
    """A CSV table (header, then rows of already formatted fields)."""
    try:
        with open(path, "w", newline="", encoding="utf-8") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(header)
            writer.writerows(rows)
    except OSError as exc:
        raise WriteError(f"cannot write {path}: {exc.strerror or exc}") from None
    return path


def new_figure(width=8.0, height=6.0) -> Figure:
    return Figure(figsize=(width, height), layout="constrained")


def finish_axes(ax, legend=True, fontsize=8):
    ax.grid(True, linewidth=0.5, alpha=0.5)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(loc="best", fontsize=fontsize)


def _heading(results) -> str:
    heading = results.title or f"results {results.folder.name or results.folder}"
    return textwrap.fill(heading, 80, break_on_hyphens=False)


def static_title(results, what: str) -> str:
    """Figure title: the run's *HEADING (or its folder name), what is plotted, and a
    warning line if the static run did not complete."""
    title = _heading(results) + f"\n{what}"
    if not results.complete:
        title += (f"\nINCOMPLETE RUN (load factor {results.load_factor:.4g}): "
                  + textwrap.shorten(results.status, 60))
    return title


def dynamic_title(results, what: str) -> str:
    """As static_title for a dynamic run (the warning gives the time reached)."""
    title = _heading(results) + f"\n{what}"
    if not results.complete:
        title += (f"\nINCOMPLETE RUN (t reached {results.time_reached_s:.4g} s): "
                  + textwrap.shorten(results.status, 60))
    return title


def window_text(t, mask) -> str:
    """'frames 0 to 15 s (101 frames)' for the titles."""
    sel = t[mask]
    return f"{sel[0]:.4g} to {sel[-1]:.4g} s ({len(sel)} frames)"


def safe_name(name: str) -> str:
    """A line name as part of a file name: characters other than letters, digits,
    '-' and '.' become '_'."""
    return "".join(c if c.isalnum() or c in "-." else "_" for c in name)
