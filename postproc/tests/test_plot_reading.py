"""Plots an engineer reads at a glance, on a mooring leg of cable elements in 100 m of
water (input/mooring_surge.inp, 6 s): what each figure holds, not its pixels.

- the x-z elevations fill their axes: a 400 m leg in 100 m of water is drawn with z
  exaggerated (and the title says so), not as a thin band between equal axes;
- the seabed's legend gives its depth, not the plane of its trace;
- a line of cable elements gets no bending moment or curvature panel (it has none);
- the animation shows the sea surface and the seabed;
- a history of many periods (the paper's case 1 for 70 s: 46 periods: support tension,
  energy, momentum, the line's histories) is drawn as its range per bin of two periods
  beside a zoom on its last five periods, not as a block.
"""
import re
import shutil
import subprocess

import numpy as np
import pytest

from designed import REPO
from test_plot_static import rodyn_exe
from rodyn_post import load_dynamic, load_static
from rodyn_post.commands import animate, plot_dynamic, plot_history, plot_static, range_graph
from rodyn_post.quantities import QUANTITIES


def shortened_run(work, deck, include, pattern, replacement):
    """Run input/<deck> with `pattern` replaced (once) into work/out (skipped without
    RODYN_EXE); returns the results folder."""
    exe = rodyn_exe()
    text, n = re.subn(pattern, replacement, (REPO / "input" / deck).read_text())
    assert n == 1
    shutil.copy(REPO / "input" / include, work)
    (work / deck).write_text(text)
    run = subprocess.run([str(exe), str(work / deck), "-o", str(work / "out"), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return work / "out"


@pytest.fixture(scope="module")
def leg(tmp_path_factory):
    return shortened_run(tmp_path_factory.mktemp("leg"), "mooring_surge.inp",
                         "mooring_leg_section.inc", r"TIME=120\.0, OUTPUT INTERVAL=0\.1",
                         "TIME=6.0, OUTPUT INTERVAL=0.5")


def drawn_z(ax):
    """z range of everything drawn (lines and collections) on an elevation."""
    return ax.dataLim.intervaly


def test_elevations_fill_their_axes(leg):
    static = load_static(leg)
    dynamic = load_dynamic(leg)
    figures = [plot_static.shape_figure(static),
               plot_dynamic.snapshots_figure(dynamic, [0, len(dynamic.time) - 1],
                                             list(range(len(dynamic.time))))]
    for fig in figures:
        ax = fig.axes[0]
        fig.canvas.draw()
        z0, z1 = drawn_z(ax)
        lo, hi = ax.get_ylim()
        assert lo >= z0 - 0.1 * (z1 - z0) and hi <= z1 + 0.1 * (z1 - z0), (lo, hi, z0, z1)
        assert "z exaggerated" in fig._suptitle.get_text()
        labels = ax.get_legend_handles_labels()[1]
        assert "seabed, z = -100 m" in labels
        assert not any("y =" in label for label in labels)


def test_paper_cable_keeps_equal_axes(short_run):
    fig = plot_static.shape_figure(load_static(short_run))
    assert fig.axes[0].get_aspect() == 1.0
    assert "exaggerated" not in fig._suptitle.get_text()


def test_cable_lines_have_no_bending_panels(leg, tmp_path):
    assert plot_history.main([str(leg), "-o", str(tmp_path)]) == 0
    header = (tmp_path / "history_LEG.csv").read_text().splitlines()[0]
    assert "tension_top_N" in header and "z_top_m" in header
    assert "moment" not in header and "curvature" not in header
    assert range_graph.main([str(leg), "-o", str(tmp_path)]) == 0
    header = (tmp_path / "range_graph.csv").read_text().splitlines()[0]
    assert "tension" in header and "moment" not in header and "curvature" not in header
    fig = plot_static.tension_figure(load_static(leg))
    assert len(fig.axes) == 1 and "bending" not in fig.axes[0].get_ylabel()
    # asked for, a quantity is drawn all the same
    assert plot_history.main([str(leg), "-o", str(tmp_path), "--quantity", "moment"]) == 0
    assert "moment_top_Nm" in (tmp_path / "history_LEG.csv").read_text().splitlines()[0]


def test_rod_lines_keep_bending_panels(short_run, tmp_path):
    assert plot_history.main([str(short_run), "-o", str(tmp_path)]) == 0
    header = (tmp_path / "history_CABLE.csv").read_text().splitlines()[0]
    assert "moment_top_Nm" in header and "curvature_top_per_m" in header
    fig = plot_static.tension_figure(load_static(short_run))
    assert len(fig.axes) == 2


def test_animation_shows_sea_and_seabed(leg):
    results = load_dynamic(leg)
    fig, _, _ = animate.animation_figure(results, animate.animation_frames(results))
    labels = fig.axes[0].get_legend_handles_labels()[1]
    assert any(label.startswith("sea surface") for label in labels)
    assert any(label.startswith("seabed") for label in labels)
    z = np.concatenate([ln.get_ydata() for ln in fig.axes[0].lines
                        if ln.get_label().startswith(("sea surface", "seabed"))])
    assert z.max() == 0.0 and z.min() == -100.0


def test_compare_title_fits_the_figure(leg):
    """rodyn-compare's title (heading, what, the reference and its errors) is wrapped
    to the figure's width: every line of it inside the figure."""
    from rodyn_post.commands.compare import comparison_figure
    from rodyn_post.quantities import QUANTITIES
    x = np.linspace(0.0, 10.0, 11)
    title = ("Mooring leg surged 5 m at the fairlead, period 12 s\nLEG: support tension "
             "|F| at end B (top)\nvs a_reference_export_with_a_long_name.csv: max |error| "
             "1.234 kN, rms 0.5678 kN, 2.35 % of the reference range")
    result = type("R", (), {"overlap": (0.0, 10.0), "x": x, "error": 0.0 * x})()
    fig = comparison_figure(title, QUANTITIES["end_tension"], "time [s]", (x, x), (x, x),
                            result, ("rodyn", "reference"))
    fig.canvas.draw()
    box = fig._suptitle.get_window_extent()
    width = fig.get_size_inches()[0] * fig.dpi
    assert box.x0 >= 0.0 and box.x1 <= width, (box, width)
    assert fig._suptitle.get_text().count("\n") >= 3


def test_long_history_band_and_zoom(tmp_path):
    out = shortened_run(tmp_path, "paper_case1.inp", "paper_cable_section.inc",
                        r"TIME=900\.0", "TIME=70.0")
    results = load_dynamic(out)
    period = 1.0 / 0.658
    for fig in (plot_dynamic.tension_figure(results), plot_dynamic.energy_figure(results)):
        assert len(fig.axes) == 4                           # two rows, whole run and zoom
        whole, zoom = fig.axes[0], fig.axes[1]
        assert whole.collections and not whole.lines         # the band, no 700-point curve
        t0, t1 = zoom.lines[0].get_xdata()[[0, -1]]
        assert t1 == results.time[-1] and 4.9 * period <= t1 - t0 <= 5.1 * period
        lo, hi = whole.collections[0].get_paths()[0].get_extents().intervaly
        tension = results.line("CABLE").end_tension[:, 0] / 1e3
        if "tension" in whole.get_ylabel():
            assert lo == tension.min() and hi == tension.max()
    short = load_dynamic(out)
    short_fig = plot_dynamic.tension_figure(short, window=(50.0, 70.0))   # 13 periods
    assert len(short_fig.axes) == 2 and short_fig.axes[0].lines
    # the momentum and the line's histories alike
    line = results.line("CABLE")
    time, columns = plot_history.history_table(results, line, ["tension", "moment", "z"],
                                               ["top", "mid"])
    for fig, rows in ((plot_dynamic.momentum_figure(results), 2),
                      (plot_history.history_figure(results, line, time, columns), 3)):
        assert len(fig.axes) == 2 * rows
        for whole, zoom in zip(fig.axes[0::2], fig.axes[1::2]):
            assert whole.collections and not whole.lines
            t0, t1 = zoom.lines[0].get_xdata()[[0, -1]]
            assert t1 == results.time[-1] and 4.9 * period <= t1 - t0 <= 5.1 * period
    whole, zoom = fig.axes[0], fig.axes[1]            # tension at the top, in kN
    top = columns[0][2] * QUANTITIES["tension"].scale
    lo, hi = whole.collections[0].get_paths()[0].get_extents().intervaly
    assert lo == top.min() and hi == top.max()
    last = time >= zoom.lines[0].get_xdata()[0]
    np.testing.assert_array_equal(zoom.lines[0].get_ydata(), top[last])
    short_fig = plot_history.history_figure(short, line, *plot_history.history_table(
        short, line, ["tension"], ["top"], (50.0, 70.0)))
    assert len(short_fig.axes) == 1 and short_fig.axes[0].lines


def test_range_graph_starts_after_the_ramp(leg, tmp_path):
    """The leg's surge ramps in over 12 s; run for 6 s it never ends its ramp (whole
    run); the paper's case 2 ramps over 3 s: its default window starts there."""
    results = load_dynamic(leg)
    assert results.ramp_s == 12.0
    out = shortened_run(tmp_path, "paper_case2.inp", "paper_cable_section.inc",
                        r"TIME=15\.0", "TIME=6.0")
    c2 = load_dynamic(out)
    assert c2.ramp_s == 3.0
    assert range_graph.main([str(out), "-o", str(tmp_path / "g")]) == 0
    rows = np.genfromtxt(tmp_path / "g" / "range_graph.csv", delimiter=",", names=True,
                         dtype=None, encoding="utf-8")
    after = c2.time >= 3.0 - 1e-9
    line = c2.line("CABLE")
    assert np.array_equal(rows["tension_max_N"], line.effective_tension[after].max(axis=0))
    assert np.allclose(rows["tension_mean_N"], line.effective_tension[after].mean(axis=0),
                       rtol=1e-12)
    assert not np.allclose(rows["tension_mean_N"], line.effective_tension.mean(axis=0),
                           rtol=1e-6)
    assert range_graph.main([str(out), "-o", str(tmp_path / "w"),
                             "--window", "0", "6"]) == 0
    whole = np.genfromtxt(tmp_path / "w" / "range_graph.csv", delimiter=",", names=True,
                          dtype=None, encoding="utf-8")
    assert np.array_equal(whole["tension_max_N"], line.effective_tension.max(axis=0))
