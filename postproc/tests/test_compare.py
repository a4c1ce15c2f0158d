"""Tests of rodyn-compare (rodyn_post.commands.compare) and its pieces (rodyn_post.units,
rodyn_post.reference):
zero error against rodyn's own numbers, the known error against a shifted copy, the
exit statuses (0, 1, 2, 4), units converted from the header, and a clear one-line
message for every malformed reference CSV. The example reference of tests/compare/ is
compared with 0.6 s of the paper's case 2 when RODYN_EXE is set.
"""
import csv
import math
import shutil

import numpy as np
import pytest

from rodyn_post.commands import compare, plot_history, range_graph
from designed import OMEGA, REPO, TIMES, write_designed
from rodyn_post import units
from rodyn_post.reference import ReferenceTable
from rodyn_post.reference import compare as compare_series

EXAMPLE = REPO / "tests" / "compare" / "top_tension_case2.csv"


def run(capsys, *argv):
    """compare.main(argv) -> (status, {metric: value in SI}, stdout, stderr)."""
    status = compare.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    metrics = {}
    for line in out.splitlines():
        key, sep, value = line.partition(" = ")
        if sep and key.replace("_", "").isalpha():
            try:
                metrics[key] = float(value.split()[0])
            except ValueError:
                pass
    return status, metrics, out, err


def assert_bad(capsys, argv, *fragments):
    """Exit 1 with a one-line message naming the fragments."""
    status, _, _, err = run(capsys, *argv)
    assert status == 1, err
    assert err.count("\n") == 1 and err.startswith("compare: error: "), err
    for fragment in fragments:
        assert fragment in err, (fragment, err)


def write_reference(path, header, rows, delimiter=","):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, delimiter=delimiter, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)
    return path


# --- units and the reader -------------------------------------------------------------

def test_header_units():
    assert units.split_header("time [s]") == ("time", "s")
    assert units.split_header(" Top Tension (kN) ") == ("Top Tension", "kN")
    assert units.split_header("effective_tension_N") == ("effective_tension", "N")
    assert units.split_header("curvature_mid_per_m") == ("curvature_mid", "per_m")
    assert units.split_header("moment [kN.m]") == ("moment", "kN.m")
    assert units.split_header("value") == ("value", None)
    assert units.split_header("line_name") == ("line_name", None)
    assert units.unit_factor("kN m") == (units.MOMENT, 1e3)
    assert units.unit_factor("kN·m") == (units.MOMENT, 1e3)
    assert units.unit_factor("min") == (units.TIME, 60.0)
    assert units.unit_factor("1/km") == (units.CURVATURE, 1e-3)
    assert units.unit_factor("kip")[1] == pytest.approx(4448.2216152605)
    with pytest.raises(units.UnitError, match="'furlong' is not known"):
        units.unit_factor("furlong")


def test_reader_layouts(tmp_path):
    """Comments, a byte-order mark, ';' and tab, trailing delimiters, columns by name,
    by name without unit and by number (from 1); values converted to SI."""
    text = ("\ufeff# exported by another tool\n\n"
            "Time (ms);Arc [m];Tension (kN);\n"
            "0;1;1.5;\n# a comment between rows\n"
            "500;2;2.5\n1000;3;-0.25;\n")
    path = tmp_path / "ref.csv"
    path.write_text(text, encoding="utf-8")
    table = ReferenceTable(path)
    assert table.delimiter == ";" and table.header == ["Time (ms)", "Arc [m]", "Tension (kN)"]
    col = table.column("1", units.TIME, increasing=True)
    np.testing.assert_array_equal(col.values, [0.0, 0.5, 1.0])
    assert col.line_numbers.tolist() == [4, 6, 7]
    np.testing.assert_array_equal(table.column("tension", units.FORCE).values,
                                  [1500.0, 2500.0, -250.0])
    assert table.column("Arc [m]", units.LENGTH).number == 2
    tab = write_reference(tmp_path / "tab.csv", ["t", "T_kN"], [[0, 1], [1, 2]], "\t")
    assert ReferenceTable(tab).column("T", units.FORCE).values.tolist() == [1e3, 2e3]


def test_orcaflex_style_export(tmp_path):
    """Values exported from an OrcaFlex time-history graph: a title line, then a
    tab-separated header with units in parentheses (kN), then the rows."""
    path = tmp_path / "orcaflex.txt"
    path.write_text("Time History: Line1 Effective Tension at End B\n"
                    "Time (s)\tLine1 Effective Tension at End B (kN)\n"
                    "0.0\t123.5\n0.1\t124.0\n0.2\t-1.5\n")
    table = ReferenceTable(path)
    assert table.title == "Time History: Line1 Effective Tension at End B"
    assert table.column("Time", units.TIME, increasing=True).values.tolist() == [0.0, 0.1, 0.2]
    column = table.column("Line1 Effective Tension at End B", units.FORCE)
    assert column.values.tolist() == [123.5e3, 124.0e3, -1.5e3]
    assert column.line_numbers.tolist() == [3, 4, 5]


@pytest.mark.parametrize("text, fragments", [
    ("", ["empty"]),
    ("# only a comment\n", ["empty"]),
    ("time tension\n0 1\n", ["line 1", "one column"]),
    ("t [s],T [kN]\n", ["no data rows"]),
    ("t [s],T [kN]\n0,1\n0.5,1,7\n", ["line 3", "3 fields", "header has 2"]),
    ("t [s],T [kN]\n0,1\n0.5,abc\n", ["line 3", "'T [kN]'", "'abc' is not a finite number"]),
    ("t [s],T [kN]\n0,1\n0.5,nan\n", ["line 3", "'nan'"]),
    ("t [s],T [kN]\n0,1\n0,2\n", ["line 3", "'t [s]'", "does not increase"]),
    ("t [s],T [furlong]\n0,1\n1,2\n", ["'T [furlong]'", "'furlong' is not known"]),
    ("t [s],T [m]\n0,1\n1,2\n", ["'T [m]'", "length", "expected a force"]),
    ("t [m],T [N]\n0,1\n1,2\n", ["'t [m]'", "expected a time"]),
])
def test_malformed_reference(tmp_path, designed_run, capsys, text, fragments):
    folder, _, _ = designed_run
    path = tmp_path / "bad.csv"
    path.write_text(text)
    assert_bad(capsys, [folder, path, "--at", "A"], "bad.csv", *fragments)


def test_bad_columns_and_files(tmp_path, designed_run, capsys):
    folder, _, _ = designed_run
    ref = write_reference(tmp_path / "ref.csv", ["time [s]", "a [N]", "a [kN]"],
                          [[0, 1, 2], [1, 2, 3]])
    assert_bad(capsys, [folder, ref, "--at", "A", "--y", "4"], "ref.csv", "column 4",
               "3 columns (counted from 1)")
    assert_bad(capsys, [folder, ref, "--at", "A", "--y", "force"], "no column named 'force'",
               "'a [N]'")
    assert_bad(capsys, [folder, ref, "--at", "A", "--y", "a"], "several columns named 'a'")
    assert_bad(capsys, [folder, tmp_path / "missing.csv", "--at", "A"], "missing.csv",
               "no such file")
    assert_bad(capsys, [tmp_path / "nowhere", ref, "--at", "A"], "nowhere",
               "no such results folder")
    assert_bad(capsys, [folder, ref, "--at", "A", "--window", "5", "6"], "--window")
    late = write_reference(tmp_path / "late.csv", ["time [s]", "T [N]"], [[5, 1], [6, 2]])
    assert_bad(capsys, [folder, late, "--at", "A"], "do not overlap")
    assert_bad(capsys, [folder, ref, "--at", "A", "--tol", "1 m", "--metric", "max_abs"],
               "--tol", "not a unit of force")


def test_command_line_errors(designed_run, capsys):
    folder, _, _ = designed_run
    for argv in ([str(folder), str(EXAMPLE)],                             # what to compare?
                 [str(folder), str(EXAMPLE), "--at", "A", "--range", "max"],
                 [str(folder), str(EXAMPLE), "--static", "--window", "0", "1"],
                 [str(folder), str(EXAMPLE), "--at", "A", "--s-from", "B"],
                 [str(folder), str(EXAMPLE), "--at", "A", "--metric", "worst"]):
        with pytest.raises(SystemExit) as exc:
            compare.main(argv)
        assert exc.value.code == 2
        assert "usage: rodyn-compare" in capsys.readouterr().err


def test_help_of_every_script(capsys):
    from rodyn_post.commands import animate, plot_all, plot_dynamic, plot_static, to_paraview
    for module in (compare, plot_history, range_graph, animate, to_paraview, plot_all,
                   plot_static, plot_dynamic):
        with pytest.raises(SystemExit) as exc:
            module.main(["--help"])
        assert exc.value.code == 0
        out = capsys.readouterr().out
        assert out.startswith("usage: ") and "exit status" in out, module.__name__
        assert "-o OUT_DIR" in out, module.__name__
        assert ("--dpi" in out) == (module is not to_paraview), module.__name__


# --- the comparison ---------------------------------------------------------------------

def test_metrics_of_a_shifted_series():
    x = np.linspace(0.0, 10.0, 101)
    y = np.sin(x)
    exact = compare_series(x, y, x, y)
    assert exact.metrics()["max_abs_error"] == 0.0 and exact.metrics()["rms_error"] == 0.0
    shifted = compare_series(x, y, x[::2], y[::2] + 0.25).metrics()
    assert shifted["max_abs_error"] == pytest.approx(0.25, rel=1e-12)
    assert shifted["rms_error"] == pytest.approx(0.25, rel=1e-12)
    assert shifted["mean_error"] == pytest.approx(-0.25, rel=1e-12)
    assert shifted["reference_range"] == pytest.approx(np.ptp(y[::2]), rel=1e-15)
    assert shifted["rel_max_error"] == pytest.approx(0.25 / np.ptp(y[::2]), rel=1e-12)
    # peaks: each series' own samples in the overlap, with their x
    part = compare_series(x, y, x[10:40], 2 * y[10:40])
    assert part.overlap == (1.0, pytest.approx(3.9))
    assert part.peaks["rodyn"]["max"] == (np.max(y[10:40]), x[10 + np.argmax(y[10:40])])
    assert part.peaks["reference"]["min"][0] == 2 * np.min(y[10:40])
    # on rodyn's points: the reference is interpolated
    on_rodyn = compare_series(x[::5], y[::5], x, y + 1.0, on="rodyn")
    np.testing.assert_array_equal(on_rodyn.x, x[::5])
    np.testing.assert_allclose(on_rodyn.error, -1.0, rtol=1e-12)


def test_zero_error_against_its_own_history(designed_run, tmp_path, capsys):
    """The history CSV that plot_history writes, used as the reference: zero error."""
    folder, _, _ = designed_run
    assert plot_history.main([str(folder), "-o", str(tmp_path), "--at", "top", "2.25",
                              "--quantity", "end_tension", "tension", "--dpi", "30"]) == 1
    capsys.readouterr()  # end_tension at S = 2.25: refused (bad input)
    assert plot_history.main([str(folder), "-o", str(tmp_path), "--at", "top",
                              "--quantity", "end_tension", "tension", "--dpi", "30"]) == 0
    capsys.readouterr()
    ref = tmp_path / "history_RISER.csv"
    status, m, out, err = run(capsys, folder, ref, "--at", "top", "--quantity",
                              "end_tension", "--y", "end_tension_top_N", "-o", tmp_path,
                              "--dpi", "30", "--tol", "0", "--metric", "max_abs")
    assert status == 0, err
    assert m["max_abs_error"] == 0.0 and m["rms_error"] == 0.0 and m["rel_max_error"] == 0.0
    assert "points = 81 (reference points, t 0 to 2 s)" in out
    assert m["rodyn_max"] == m["reference_max"] == pytest.approx(1.3e4, rel=1e-12)
    assert "rodyn_max = 13000 N at t = 0.2 s" in out
    assert "within tolerance: max_abs_error = 0 N <= 0 N" in out
    assert (tmp_path / "compare_history_RISER.png").is_file()
    # the comparison table: x, rodyn, reference, error
    with open(tmp_path / "compare_history_RISER.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["time_s", "rodyn_N", "reference_N", "error_N"]
    assert len(rows) == 82 and all(float(r[3]) == 0.0 for r in rows[1:])


def test_known_error_against_a_shifted_copy(designed_run, tmp_path, capsys):
    """The end tension written in kN plus 0.5 kN: max and rms error 500 N, bias -500 N;
    --tol decides the exit status (0 or 4)."""
    folder, lines, _ = designed_run
    top = lines["RISER"]["end_tension"][:, 0]
    ref = write_reference(tmp_path / "shifted.csv", ["Time (s)", "Top tension (kN)"],
                          [[repr(float(t)), repr(float(v + 500.0) / 1e3)]
                           for t, v in zip(TIMES, top)])
    common = [folder, ref, "--at", "A", "--quantity", "end_tension", "-o", tmp_path,
              "--no-plot"]
    status, m, out, err = run(capsys, *common)
    assert status == 0 and err == "", err
    assert m["max_abs_error"] == pytest.approx(500.0, rel=1e-9)
    assert m["rms_error"] == pytest.approx(500.0, rel=1e-9)
    assert m["mean_error"] == pytest.approx(-500.0, rel=1e-9)
    assert m["reference_range"] == pytest.approx(6e3, rel=1e-6)
    assert m["rel_max_error"] == pytest.approx(500.0 / 6e3, rel=1e-6)
    assert "[kN -> N: x 1000]" in out and not (tmp_path / "compare_shifted.png").exists()
    assert (tmp_path / "compare_shifted.csv").is_file()
    status, m, out, err = run(capsys, *common, "--tol", "0.6 kN", "--metric", "max_abs")
    assert status == 0 and "within tolerance" in out
    status, m, out, err = run(capsys, *common, "--tol", "400", "--metric", "max_abs")
    assert status == 4
    assert err.strip() == "compare: above tolerance: max_abs_error = 500 N > 400 N"
    status, _, _, err = run(capsys, *common, "--tol", "0.05")   # rel_max 0.083
    assert status == 4 and "rel_max_error = 0.0833333 > 0.05" in err
    assert run(capsys, *common, "--tol", "0.1")[0] == 0


def test_time_shifted_copy(tmp_path, capsys):
    """A reference lagging by tau: for a sine of amplitude A the rms error over whole
    periods is sqrt(2) A sin(w tau / 2)."""
    folder = tmp_path / "fine"
    write_designed(folder)
    tau = 0.05
    t = np.arange(0.0, 2.0 + 1e-9, 0.025)
    ref = write_reference(tmp_path / "lag.csv", ["t [s]", "T [N]"],
                          [[repr(a), repr(1e4 + 3e3 * math.sin(OMEGA * (a - tau)))]
                           for a in t.tolist()])
    status, m, _, err = run(capsys, folder, ref, "--at", "A", "--quantity", "end_tension",
                          "--window", "0", "1.6", "-o", tmp_path, "--no-plot")
    assert status == 0, err
    expected = math.sqrt(2.0) * 3e3 * math.sin(OMEGA * tau / 2)
    # 65 points over two periods (the end point counted once more): within 1 %
    assert m["rms_error"] == pytest.approx(expected, rel=1e-2)
    assert m["max_abs_error"] == pytest.approx(2 * 3e3 * math.sin(OMEGA * tau / 2), rel=1e-2)


def test_range_graph_and_static_against_their_own_csv(designed_run, tmp_path, capsys):
    folder, _, _ = designed_run
    assert range_graph.main([str(folder), "-o", str(tmp_path), "--dpi", "30", "--line",
                             "RISER"]) == 0
    capsys.readouterr()
    with open(tmp_path / "range_graph.csv", newline="") as f:
        rows = [r for r in csv.reader(f)]
    riser = [r for r in rows[1:] if r[0] == "RISER"]
    # arc length from end B, reversed rows, tension in kN: still zero error
    ref = write_reference(tmp_path / "from_b.csv", ["S from B [m]", "max T [kN]"],
                          [[repr(6.0 - float(r[1])), repr(float(r[4]) / 1e3)]
                           for r in reversed(riser)])
    status, m, out, _ = run(capsys, folder, ref, "--range", "max", "--s-from", "B",
                            "-o", tmp_path, "--no-plot", "--line", "RISER")
    assert status == 0
    assert m["max_abs_error"] < 1e-8 and "S from end B" in out
    assert "points = 6 (reference points, S 0.5 to 5.5 m)" in out
    # against the range graph's curvature min, by column name as written
    status, m, _, err = run(capsys, folder, tmp_path / "range_graph.csv", "--range", "min",
                            "--quantity", "curvature", "--x", "s_m", "--y",
                            "curvature_min_per_m", "-o", tmp_path, "--no-plot")
    assert status == 0 and m["max_abs_error"] == 0.0, err


def test_static_comparison(tmp_path, capsys, monkeypatch):
    from test_plot_static import write_results
    folder = tmp_path / "paper_cable"
    lines = write_results(folder)
    s, tension = lines["CABLE"]["gp_s"], lines["CABLE"]["effective_tension"]
    ref = write_reference(tmp_path / "static.csv", ["S [m]", "N3 [kN]"],
                          [[repr(float(a)), repr(float(b) / 1e3 + 0.1)]
                           for a, b in zip(s, tension)])
    monkeypatch.chdir(tmp_path)  # the default RESULTS of --static is ./paper_cable
    status, m, out, err = run(capsys, ref, "--static", "--dpi", "30")
    assert status == 0, err
    assert m["mean_error"] == pytest.approx(-100.0, rel=1e-9)
    assert (folder / "compare_static.png").is_file()


# --- the example reference and a real run ------------------------------------------------

def test_example_reference_file():
    table = ReferenceTable(EXAMPLE)
    t = table.column("Time", units.TIME, increasing=True)
    top = table.column("Top Tension", units.FORCE)
    assert len(t.values) == 251 and t.values[-1] == 15.0
    assert top.unit == "kN" and 3e3 < top.values.min() < top.values.max() < 3e4


def test_example_reference_against_a_real_run(short_run, tmp_path, capsys):
    """0.6 s of case 2 (a frame every 0.03 s) against the example (every 0.06 s, in kN
    to 1 N, from a run with the same deck): the 11 common points agree to the rounding."""
    folder = tmp_path / "run"
    shutil.copytree(short_run, folder)
    status, m, out, err = run(capsys, folder, EXAMPLE, "--at", "top", "--quantity",
                              "end_tension", "--tol", "0.05", "--dpi", "40")
    assert status == 0, err
    assert "points = 11 (reference points, t 0 to 0.6 s)" in out
    # the short run's last frame (t = 0.6 s) has its support force extrapolated from the
    # steps before it (docs/output.md, dynamic_ends.csv); the example, from a longer run,
    # has it interpolated: 29 N apart (0.24 %). The other points agree to the rounding.
    assert m["max_abs_error"] < 60.0
    lines = EXAMPLE.read_text().splitlines()
    inner = tmp_path / "example_inner.csv"
    inner.write_text("\n".join(ln for ln in lines
                               if ln.startswith("#") or not ln[:1].isdigit()
                               or float(ln.split(",")[0]) < 0.59) + "\n")
    status, m_in, _, err = run(capsys, folder, inner, "--at", "top", "--quantity",
                               "end_tension", "--no-plot")
    assert status == 0, err
    assert m_in["max_abs_error"] < 1.0  # N; 0.5 N of rounding if rodyn is unchanged
    assert (folder / "compare_top_tension_case2.png").is_file()
    # the effective tension at the nearest integration point is not the support force:
    # a tolerance of 1e-6 of the range fails (exit 4)
    status, m, _, err = run(capsys, folder, EXAMPLE, "--at", "top", "--tol", "1e-6",
                            "--no-plot")
    assert status == 4 and "above tolerance" in err
