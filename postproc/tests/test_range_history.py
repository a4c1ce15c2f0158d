"""Tests of rodyn-range-graph and rodyn-plot-history (rodyn_post.commands): the files are written,
and the numbers behind them are those of the raw data (numpy on dynamic.h5 / the CSV
tables), on the synthetic run of designed.py and, with RODYN_EXE, on 0.6 s of the
paper's case 2.
"""
import csv

import h5py
import numpy as np
import pytest

from rodyn_post.commands import plot_history, range_graph
from designed import RISER_LENGTH, TIMES
from rodyn_post import load_dynamic
from rodyn_post.quantities import at_s, parse_location

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def assert_png(path):
    data = path.read_bytes()
    assert len(data) > 1000 and data.startswith(PNG_SIGNATURE), path


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def assert_error(capsys, main, argv, status, *fragments):
    """main(argv) returns `status` with a one-line message on stderr naming fragments."""
    assert main([str(a) for a in argv]) == status
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ": error: " in err, err
    for fragment in fragments:
        assert fragment in err, (fragment, err)


# --- range graph --------------------------------------------------------------------

def test_range_graph_matches_numpy(designed_run, tmp_path, capsys):
    folder, lines, _ = designed_run
    out = tmp_path / "out"
    assert range_graph.main([str(folder), "-o", str(out), "--dpi", "40",
                             "--window", "0.5", "1.5"]) == 0
    assert capsys.readouterr().out.split() == [str(out / "range_graph.png"),
                                               str(out / "range_graph.csv")]
    assert_png(out / "range_graph.png")
    header, rows = read_csv(out / "range_graph.csv")
    assert header == ["line", "s_m", "tension_min_N", "tension_mean_N", "tension_max_N",
                      "moment_min_Nm", "moment_mean_Nm", "moment_max_Nm",
                      "curvature_min_per_m", "curvature_mean_per_m", "curvature_max_per_m"]
    sel = (TIMES >= 0.5) & (TIMES <= 1.5)
    assert sel.sum() == 41
    for name, a in lines.items():
        got = np.array([[float(v) for v in r[1:]] for r in rows if r[0] == name])
        np.testing.assert_array_equal(got[:, 0], a["gp_s"])
        raw = {"tension": a["effective_tension"][sel],
               "moment": np.hypot(a["moment_1"], a["moment_2"])[sel],
               "curvature": a["bending_curvature"][sel]}
        for k, key in enumerate(("tension", "moment", "curvature")):
            np.testing.assert_array_equal(got[:, 1 + 3 * k], raw[key].min(axis=0))
            np.testing.assert_allclose(got[:, 2 + 3 * k], raw[key].mean(axis=0),
                                       rtol=1e-15)
            np.testing.assert_array_equal(got[:, 3 + 3 * k], raw[key].max(axis=0))
    # the designed riser: tension extremes where sin(w t) is +-1 (t = 0.6 and 1.4 s)
    riser = np.array([[float(v) for v in r[1:]] for r in rows if r[0] == "RISER"])
    s = riser[:, 0]
    np.testing.assert_allclose(riser[:, 3], 1e4 + 2e3 * s + 3e3 * (1 - s / 6), rtol=1e-12)
    np.testing.assert_allclose(riser[:, 1], 1e4 + 2e3 * s - 3e3 * (1 - s / 6), rtol=1e-12)
    # the CSV tables give the same table (17 digits: the same numbers)
    (folder / "dynamic.h5").unlink()
    res = load_dynamic(folder)
    assert res.source.name == "dynamic_nodes.csv"
    assert range_graph.csv_rows(range_graph.range_table(res, res.lines, (0.5, 1.5))) == rows


def test_range_graph_figure_shows_the_table(designed_run):
    folder, lines, _ = designed_run
    res = load_dynamic(folder)
    table = range_graph.range_table(res, res.lines)
    ax_t, ax_m, ax_k = range_graph.range_figure(res, table).axes
    a = lines["RISER"]
    (hi,) = [c for c in ax_t.lines if c.get_label() == "RISER: max"]
    np.testing.assert_array_equal(hi.get_xdata(), a["gp_s"])
    np.testing.assert_allclose(hi.get_ydata(), a["effective_tension"].max(axis=0) / 1e3,
                               rtol=1e-15)
    (lo,) = [c for c in ax_k.lines if c.get_label() == "RISER: min"]
    np.testing.assert_array_equal(lo.get_ydata(), a["bending_curvature"].min(axis=0))
    assert "0 to 2 s (81 frames)" in ax_t.figure.get_suptitle()


def test_range_graph_bad_input(designed_run, tmp_path, capsys):
    folder, _, _ = designed_run
    assert_error(capsys, range_graph.main, [folder, "--window", "5", "6"], 1,
                 "--window", "no output frame")
    assert_error(capsys, range_graph.main, [folder, "--line", "NOPE"], 1,
                 "'NOPE'", "RISER")
    with pytest.raises(SystemExit) as exc:
        range_graph.main([str(folder), "--window", "1", "0.5"])
    assert exc.value.code == 2
    assert "T1 must be greater" in capsys.readouterr().err
    blocked = tmp_path / "file"
    blocked.write_text("")
    assert_error(capsys, range_graph.main, [folder, "-o", blocked / "x"], 3,
                 "cannot write", "file")
    with h5py.File(folder / "dynamic.h5", "r+") as f:
        del f["dynamic/RISER/bending_curvature"]
    (folder / "dynamic_nodes.csv").unlink()  # dynamic.h5 is then the only source
    assert_error(capsys, range_graph.main, [folder], 1, "dynamic.h5",
                 "/dynamic/RISER/bending_curvature")


# --- time histories -----------------------------------------------------------------

def test_history_values_and_csv(designed_run, tmp_path, capsys):
    folder, lines, _ = designed_run
    out = tmp_path / "out"
    argv = [str(folder), "-o", str(out), "--dpi", "40", "--line", "RISER",
            "--at", "top", "2.25", "mid", "B", "--quantity", "tension", "curvature", "x",
            "z", "moment"]
    assert plot_history.main(argv) == 0
    assert capsys.readouterr().out.split() == [str(out / "history_RISER.png"),
                                               str(out / "history_RISER.csv")]
    assert_png(out / "history_RISER.png")
    header, rows = read_csv(out / "history_RISER.csv")
    assert header[:6] == ["time_s", "tension_top_N", "tension_S2.25_N", "tension_mid_N",
                          "tension_B_N", "curvature_top_per_m"]
    assert "z_mid_m" in header and "moment_B_Nm" in header
    data = {h: np.array([float(r[i]) for r in rows]) for i, h in enumerate(header)}
    t = TIMES
    np.testing.assert_array_equal(data["time_s"], TIMES)
    wave = np.sin(2 * np.pi * 1.25 * t)

    def tension(s):
        return 1e4 + 2e3 * s + 3e3 * wave * (1 - s / 6)
    # between integration points: linear in S, exact for the designed tension
    np.testing.assert_allclose(data["tension_S2.25_N"], tension(2.25), rtol=1e-13)
    np.testing.assert_allclose(data["tension_mid_N"], tension(3.0), rtol=1e-13)
    # beyond the outermost point (S = 0.5 and 5.5): that point's value
    a = lines["RISER"]
    np.testing.assert_array_equal(data["tension_top_N"], a["effective_tension"][:, 0])
    np.testing.assert_array_equal(data["tension_B_N"], a["effective_tension"][:, -1])
    np.testing.assert_allclose(data["curvature_mid_per_m"], 0.01 + 3e-3 * t, rtol=1e-13)
    # positions: linear between nodes, exact at the ends
    np.testing.assert_allclose(data["x_S2.25_m"], 0.8 * 2.25 + 0.1 * wave * (1 - 2.25 / 6),
                               rtol=1e-13)
    np.testing.assert_array_equal(data["z_top_m"], a["z"][:, 0])
    np.testing.assert_array_equal(data["z_B_m"], a["z"][:, -1])
    # moment magnitude: interpolated as a magnitude between S = 1.5 and 2.5
    mag = np.hypot(a["moment_1"], a["moment_2"])
    np.testing.assert_allclose(data["moment_S2.25_Nm"], 0.25 * mag[:, 1] + 0.75 * mag[:, 2],
                               rtol=1e-14)


def test_history_end_tension_and_window(designed_run, tmp_path, capsys):
    folder, lines, _ = designed_run
    res = load_dynamic(folder)
    line = res.line("RISER")
    time, columns = plot_history.history_table(res, line, ["end_tension", "z"],
                                               ["top", "bottom"], (1.0, 1.5))
    np.testing.assert_allclose(time, TIMES[40:61])
    (key, where, values) = columns[0]
    assert (key, where.end, where.label) == ("end_tension", 0, "end A (top)")
    np.testing.assert_array_equal(values, lines["RISER"]["end_tension"][40:61, 0])
    assert columns[1][1].end == 1
    # the figure shows the numbers in kN
    fig = plot_history.history_figure(res, line, time, columns)
    (curve,) = [c for c in fig.axes[0].lines if c.get_label() == "end A (top)"]
    np.testing.assert_allclose(curve.get_ydata(), values / 1e3, rtol=1e-15)
    # the defaults: the first line, top mid bottom, tension moment curvature z
    args = plot_history.parse_args([str(folder)])
    assert (args.line, args.at, args.quantity) == (None, ["top", "mid", "bottom"],
                                                    ["tension", "moment", "curvature", "z"])


def test_locations_and_interpolation_rule():
    res_line = type("L", (), {"node_s": np.linspace(0, 10, 11), "name": "C", "top_end": 1})
    assert parse_location("b", res_line).label == "end B (top)"
    assert parse_location("bottom", res_line).s == 0.0
    assert parse_location("10", res_line).token == "S10"
    points = np.array([1.0, 2.0, 4.0])
    values = np.array([[10.0, 20.0, 0.0]])
    assert at_s(points, values, 0.0)[0] == 10.0       # before the first point
    assert at_s(points, values, 3.0)[0] == 10.0       # halfway between 20 and 0
    assert at_s(points, values, 2.0)[0] == 20.0       # at a point: its value
    assert at_s(points, values, 9.0)[0] == 0.0        # beyond the last point


def test_history_bad_input(designed_run, capsys):
    folder, _, _ = designed_run
    assert_error(capsys, plot_history.main, [folder, "--at", "7"], 1, "--at 7",
                 "off the line", f"0 to {RISER_LENGTH:g} m")
    assert_error(capsys, plot_history.main, [folder, "--at", "middle"], 1, "'middle'")
    assert_error(capsys, plot_history.main, [folder, "--at", "3", "--quantity",
                                             "end_tension"], 1, "held end")
    assert_error(capsys, plot_history.main, [folder, "--line", "TAIL, 1/2", "--at", "B",
                                             "--quantity", "end_tension"], 1, "no support")
    with pytest.raises(SystemExit) as exc:
        plot_history.main([str(folder), "--quantity", "stress"])
    assert exc.value.code == 2
    assert "invalid choice: 'stress'" in capsys.readouterr().err


# --- the real run ---------------------------------------------------------------------

def test_real_run_range_and_history(short_run):
    """The numbers behind range_graph.csv and history_<LINE>.csv against rodyn's own
    CSV tables (the files themselves are written in test_real_run_all)."""
    res = load_dynamic(short_run)
    assert res.source.name == "dynamic.h5"
    cable = res.line("CABLE")
    with open(short_run / "dynamic_elements.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    times = sorted({float(r["time_s"]) for r in rows})
    assert len(times) == 21
    ng = len(rows) // len(times)
    col = {c: np.array([float(r[c]) for r in rows]).reshape(len(times), ng) for c in
           ("s_m", "effective_tension_N", "moment_1_Nm", "moment_2_Nm", "curvature_per_m")}
    table = range_graph.range_table(res, res.lines)
    got = np.array([[float(v) for v in r[1:]] for r in range_graph.csv_rows(table)])
    np.testing.assert_array_equal(got[:, 0], col["s_m"][0])
    tension = col["effective_tension_N"]
    np.testing.assert_array_equal(got[:, 1], tension.min(axis=0))
    np.testing.assert_allclose(got[:, 2], tension.mean(axis=0), rtol=1e-14)
    np.testing.assert_array_equal(got[:, 3], tension.max(axis=0))
    moment = np.hypot(col["moment_1_Nm"], col["moment_2_Nm"])
    np.testing.assert_array_equal(got[:, 4], moment.min(axis=0))
    np.testing.assert_array_equal(got[:, 6], moment.max(axis=0))
    # curvature: the CSV and dynamic.h5 may differ in the last bit (computed twice)
    np.testing.assert_allclose(got[:, 9], col["curvature_per_m"].max(axis=0), rtol=1e-14)
    # histories: tension at the ends = the outermost integration points; end_tension =
    # the support force of dynamic_ends.csv
    time, columns = plot_history.history_table(res, cable, ["tension", "end_tension"],
                                               ["A", "B"])
    np.testing.assert_array_equal(time, times)
    data = {plot_history.column_name(k, w): v for k, w, v in columns}
    np.testing.assert_array_equal(data["tension_A_N"], tension[:, 0])
    np.testing.assert_array_equal(data["tension_B_N"], tension[:, -1])
    with open(short_run / "dynamic_ends.csv", newline="") as f:
        ends = [r for r in csv.DictReader(f)]
    for end in "AB":
        np.testing.assert_array_equal(data[f"end_tension_{end}_N"], [
            float(r["tension_N"]) for r in ends if r["end"] == end])
