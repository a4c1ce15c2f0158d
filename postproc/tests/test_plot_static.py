"""Tests of rodyn_post (reader) and rodyn-plot-static (rodyn_post.commands.plot_static).

Synthetic results are written by the tests themselves (results.h5 with h5py and the
CSV tables, following docs/output.md). If the environment variable RODYN_EXE names
the rodyn executable, the paper cable deck is also run and its result plotted.

    python3 -m pytest postproc/tests -q
    RODYN_EXE=build/rodyn python3 -m pytest postproc/tests -q
"""
import csv
import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from rodyn_post import RodynResultsError, load_static
from rodyn_post.commands import plot_static
from rodyn_post.results import ELEMENTS_HEADER, LINES_HEADER, NODES_HEADER, REACTIONS_HEADER
from rodyn_post.schema import DATASETS

REPO = Path(__file__).resolve().parents[2]
COMMAND = [sys.executable, "-m", "rodyn_post.commands.plot_static"]  # = rodyn-plot-static

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
TITLE = "Synthetic: two lines"
COUNTERS = dict(load_factor=1.0, increments=3, iterations=11, cutbacks=0,
                wall_time_s=0.0123456789)


# --- synthetic results --------------------------------------------------------------

def synthetic_lines():
    """{line name: arrays as in results.h5 + end_held}: two small lines, random data.
    The second name has a comma (quoted in CSV) and a '/' ('_' in the group name)."""
    rng = np.random.default_rng(7)
    lines = {}
    for name, nn, ng, held in (("CABLE", 4, 3, (1, 1)), ("TAIL, 1/2", 3, 2, (1, 0))):
        reactions = rng.normal(size=(2, 6)) * 1e3
        reactions[np.array(held) == 0] = 0.0
        lines[name] = {
            "node_s": np.linspace(0.0, 2.0, nn), "node_xyz": rng.normal(size=(nn, 3)),
            "gp_s": np.sort(rng.uniform(0.0, 2.0, ng)),
            "effective_tension": rng.normal(size=ng) * 1e4, "shear": rng.normal(size=(ng, 2)),
            "moment": rng.normal(size=(ng, 2)) * 1e3, "torque": rng.normal(size=ng),
            "curvature": rng.normal(size=(ng, 3)), "reactions": reactions,
            "end_held": np.array(held, dtype=np.int32),
        }
    return lines


def write_status(folder, complete=True, counters=COUNTERS):
    """status.txt as rodyn writes it."""
    c = counters
    (folder / "status.txt").write_text(
        f"complete = {'true' if complete else 'false'}\n"
        f"status = {'complete' if complete else 'diverged at load factor 0.5'}\n"
        f"load_factor = {c['load_factor']:.16E}\nincrements = {c['increments']}\n"
        f"iterations = {c['iterations']}\ncutbacks = {c['cutbacks']}\n"
        f"wall_time_s = {c['wall_time_s']:.16E}\nrodyn_version = 0.1.0\n"
        "deck = decks/synthetic.inp\n")


def write_h5(path, lines, complete=True, counters=COUNTERS):
    """results.h5 with the layout of docs/output.md."""
    with h5py.File(path, "w", track_order=True) as f:
        f.attrs.update(program="rodyn", version="0.1.0", deck_file="decks/synthetic.inp",
                       title=TITLE, units="SI: m, s, kg, N, N m, rad",
                       complete=np.int32(complete),
                       status="complete" if complete else "diverged at load factor 0.5")
        f["deck"] = "*HEADING\n" + TITLE + "\n"
        static = f.create_group("static", track_order=True)
        static.attrs.update(load_factor=float(counters["load_factor"]),
                            increments=np.int32(counters["increments"]),
                            iterations=np.int32(counters["iterations"]),
                            cutbacks=np.int32(counters["cutbacks"]),
                            wall_time_s=float(counters["wall_time_s"]))
        for name, a in lines.items():
            g = static.create_group(name.replace("/", "_"), track_order=True)
            g.attrs["name"] = name
            for key, value in a.items():
                if key != "end_held":
                    g[key] = value
                    units = DATASETS["results.h5"].get(f"/static/LINE/{key}", ("-",))[0]
                    g[key].attrs.update(units=units, description=key)
            g["reactions"].attrs["end_held"] = a["end_held"]


def write_csv(folder, lines):
    """static_nodes.csv, static_elements.csv, static_reactions.csv."""
    def real(v):
        return f"{v:.16E}"

    tables = {"static_nodes.csv": [NODES_HEADER], "static_elements.csv": [ELEMENTS_HEADER],
              "static_reactions.csv": [REACTIONS_HEADER]}
    if any("touchdown_s" in a for a in lines.values()):
        tables["static_lines.csv"] = [LINES_HEADER]
    for name, a in lines.items():
        normal = a.get("seabed_normal", np.zeros(len(a["node_s"])))
        friction = a.get("seabed_friction", np.zeros(len(a["node_s"])))
        wall = a.get("wall_tension", a["effective_tension"])
        for i, (s, xyz) in enumerate(zip(a["node_s"], a["node_xyz"])):
            tables["static_nodes.csv"].append([name, i + 1, real(s)] + [real(v) for v in xyz]
                                              + [real(normal[i]), real(friction[i])])
        for i in range(len(a["gp_s"])):
            k = a["curvature"][i]
            values = [a["gp_s"][i], a["effective_tension"][i], wall[i], *a["shear"][i],
                      *a["moment"][i], a["torque"][i], *k, np.hypot(k[0], k[1])]
            tables["static_elements.csv"].append([name, i + 1, 1] + [real(v) for v in values])
        for end, held in zip("AB", a["end_held"]):
            if held:
                r = a["reactions"]["AB".index(end)]
                tables["static_reactions.csv"].append(
                    [name, end] + [real(v) for v in r] + [real(np.linalg.norm(r[:3]))])
        if "static_lines.csv" in tables:
            tables["static_lines.csv"].append(
                [name, real(a["node_s"][-1]), real(a.get("touchdown_s", -1.0))])
    for file, rows in tables.items():
        with open(folder / file, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)


def write_results(folder, h5=True, csv_tables=True, complete=True):
    """A synthetic results folder; returns the line arrays written."""
    folder.mkdir(parents=True, exist_ok=True)
    lines = synthetic_lines()
    if h5:
        write_h5(folder / "results.h5", lines, complete)
    if csv_tables:
        write_csv(folder, lines)
    write_status(folder, complete)
    return lines


def run_script(*args, cwd):
    """Run rodyn-plot-static (python3 -m) in a fresh interpreter; returns the CompletedProcess."""
    return subprocess.run([*COMMAND, *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


def assert_png(path):
    data = Path(path).read_bytes()
    assert len(data) > 1000 and data.startswith(PNG_SIGNATURE), path


def assert_one_line_error(proc, *fragments):
    """Exit 1, a one-line message on stderr naming all fragments, no traceback."""
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    for fragment in fragments:
        assert fragment in proc.stderr, (fragment, proc.stderr)


# --- (a) reader and script on synthetic results -------------------------------------

@pytest.mark.parametrize("kind", ["h5", "h5 file", "csv"])
def test_load_static_returns_the_arrays(tmp_path, kind):
    folder = tmp_path / "run"
    expected = write_results(folder, h5=kind != "csv")
    results = load_static(folder / "results.h5" if kind == "h5 file" else folder)
    assert [line.name for line in results.lines] == list(expected)
    for line in results.lines:
        for key, value in expected[line.name].items():
            got = getattr(line, key)
            assert got.shape == value.shape, key
            assert np.array_equal(got, value), key  # exact: 17 digits in the CSV
    assert results.complete and results.status == "complete"
    assert results.version == "0.1.0" and results.deck_file == "decks/synthetic.inp"
    assert results.iterations == COUNTERS["iterations"]
    assert results.wall_time_s == COUNTERS["wall_time_s"]
    assert results.title == ("" if kind == "csv" else TITLE)
    assert results.source.name == ("static_nodes.csv" if kind == "csv" else "results.h5")
    assert results.line("TAIL, 1/2").end_held.tolist() == [True, False]


@pytest.mark.parametrize("kind", ["h5", "csv"])
def test_script_writes_both_pngs(tmp_path, kind):
    folder = tmp_path / "run"
    write_results(folder, h5=kind == "h5", csv_tables=kind == "csv")
    out = tmp_path / "plots" / "new"
    proc = run_script(folder, "-o", out, "--dpi", 60, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    written = [out / "static_shape.png", out / "static_plan.png", out / "static_tension.png"]
    assert proc.stdout.split() == [str(p) for p in written]
    for path in written:
        assert_png(path)


def test_script_default_is_paper_cable_in_cwd(tmp_path):
    write_results(tmp_path / "paper_cable")
    proc = run_script("--dpi", 50, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert_png(tmp_path / "paper_cable" / "static_shape.png")
    assert_png(tmp_path / "paper_cable" / "static_tension.png")


def test_incomplete_run_is_plotted_with_a_warning(tmp_path):
    write_results(tmp_path / "run", complete=False)
    proc = run_script(tmp_path / "run", "--dpi", 50, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "did not complete" in proc.stderr and "diverged" in proc.stderr
    assert_png(tmp_path / "run" / "static_shape.png")
    fig = plot_static.shape_figure(load_static(tmp_path / "run"))
    assert "INCOMPLETE" in fig.get_suptitle()


def test_stale_results_h5_is_ignored(tmp_path):
    """results.h5 left by an earlier run (other counters than status.txt): use CSV."""
    folder = tmp_path / "run"
    lines = write_results(folder)
    write_h5(folder / "results.h5", lines, counters=dict(COUNTERS, iterations=99))
    assert load_static(folder).source.name == "static_nodes.csv"
    assert load_static(folder / "results.h5").iterations == 99


# --- (b) the data behind the plots --------------------------------------------------

def test_plotted_quantities_match_raw_data(tmp_path):
    write_results(tmp_path / "run")
    results = load_static(tmp_path / "run")
    with h5py.File(tmp_path / "run" / "results.h5", "r") as f:
        raw = {g.attrs["name"]: {k: g[k][...] for k in ("gp_s", "effective_tension",
                                                        "moment", "node_xyz")}
               for g in f["static"].values()}
    tension_ax, moment_ax = plot_static.tension_figure(results).axes
    shape_ax = plot_static.shape_figure(results).axes[0]
    for line in results.lines:
        r = raw[line.name]
        s, tension, moment = plot_static.tension_curves(line)
        np.testing.assert_array_equal(s, r["gp_s"])
        np.testing.assert_allclose(tension, r["effective_tension"] / 1e3, rtol=1e-15)
        magnitude = np.sqrt(r["moment"][:, 0] ** 2 + r["moment"][:, 1] ** 2)
        np.testing.assert_allclose(moment, magnitude / 1e3, rtol=1e-14)
        # ...and these are what the figures show
        for ax, y in ((tension_ax, tension), (moment_ax, moment)):
            (curve,) = [c for c in ax.lines if c.get_label() == line.name]
            np.testing.assert_array_equal(curve.get_xydata(), np.column_stack([s, y]))
        (curve,) = [c for c in shape_ax.lines if c.get_label() == line.name]
        np.testing.assert_array_equal(curve.get_xydata(), r["node_xyz"][:, [0, 2]])
    supports = [c for c in shape_ax.lines if c.get_marker() == "^"]
    assert len(supports) == 3  # CABLE: A and B; TAIL: A
    assert shape_ax.get_aspect() == 1.0


# --- (c) bad input ------------------------------------------------------------------

def test_bad_csv_header(tmp_path):
    folder = tmp_path / "run"
    write_results(folder, h5=False)
    path = folder / "static_elements.csv"
    path.write_text(path.read_text().replace("effective_tension_N", "tension_N", 1))
    proc = run_script(folder, cwd=tmp_path)
    assert_one_line_error(proc, "static_elements.csv", "header")
    with pytest.raises(RodynResultsError, match="static_elements.csv: line 1: header"):
        load_static(folder)


def test_non_numeric_csv_cell(tmp_path):
    folder = tmp_path / "run"
    write_results(folder, h5=False)
    path = folder / "static_nodes.csv"
    rows = path.read_text().splitlines()
    fields = rows[2].split(",")
    fields[4] = "abc"  # y_m of the second node (file line 3)
    rows[2] = ",".join(fields)
    path.write_text("\n".join(rows) + "\n")
    proc = run_script(folder, cwd=tmp_path)
    assert_one_line_error(proc, "static_nodes.csv: line 3", "y_m", "'abc'")


def test_missing_dataset(tmp_path):
    folder = tmp_path / "run"
    write_results(folder, csv_tables=False)
    with h5py.File(folder / "results.h5", "r+") as f:
        del f["static/CABLE/effective_tension"]
    proc = run_script(folder, cwd=tmp_path)
    assert_one_line_error(proc, "results.h5", "/static/CABLE/effective_tension")


def test_missing_folder_and_missing_tables(tmp_path):
    proc = run_script(tmp_path / "nowhere", cwd=tmp_path)
    assert_one_line_error(proc, "nowhere", "no such results folder")
    (tmp_path / "empty").mkdir()
    with pytest.raises(RodynResultsError, match="no rodyn results"):
        load_static(tmp_path / "empty")
    write_results(tmp_path / "run", h5=False)
    (tmp_path / "run" / "static_reactions.csv").unlink()
    with pytest.raises(RodynResultsError, match="static_reactions.csv: file missing"):
        load_static(tmp_path / "run")


# --- (d) a real rodyn run -----------------------------------------------------------

def rodyn_exe():
    """The executable named by RODYN_EXE (relative to the cwd or the repo); the test is
    skipped when RODYN_EXE is not set."""
    value = os.environ.get("RODYN_EXE")
    if not value:
        pytest.skip("RODYN_EXE not set")
    for candidate in (Path(value), REPO / value):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate.resolve()
    pytest.fail(f"RODYN_EXE={value} is not an executable file")


def test_real_paper_cable(tmp_path):
    exe = rodyn_exe()
    out = tmp_path / "paper_cable"
    run = subprocess.run([str(exe), str(REPO / "input" / "paper_cable.inp"), "-o", str(out),
                          "--quiet"], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    proc = run_script(out, "--dpi", 80, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert_png(out / "static_shape.png")
    assert_png(out / "static_tension.png")

    with open(out / "static_nodes.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["line"] == "CABLE"]
    csv_xz = np.array([[float(r["x_m"]), float(r["z_m"])] for r in rows])
    results = load_static(out)
    assert results.complete and results.source.name == "results.h5"
    shape_ax = plot_static.shape_figure(results).axes[0]
    (curve,) = [c for c in shape_ax.lines if c.get_label() == "CABLE"]
    np.testing.assert_array_equal(curve.get_xydata(), csv_xz)

    # the CSV fallback reads the same numbers as results.h5
    csv_only = tmp_path / "csv_only"
    shutil.copytree(out, csv_only)
    (csv_only / "results.h5").unlink()
    from_csv = load_static(csv_only).line("CABLE")
    for key in ("node_s", "node_xyz", "gp_s", "effective_tension", "moment", "reactions"):
        np.testing.assert_array_equal(getattr(from_csv, key),
                                      getattr(results.line("CABLE"), key), err_msg=key)


def test_real_offset_curve(tmp_path):
    """A body's offset curve (*OFFSET CURVE) is plotted from static_offset_curve.csv: the
    applied force and the most loaded line end's force against the offset."""
    exe = rodyn_exe()
    out = tmp_path / "spar"
    deck = REPO / "tests" / "verification" / "decks" / "spar_offset_curve.inp"
    run = subprocess.run([str(exe), str(deck), "-o", str(out), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    proc = run_script(out, "--dpi", 80, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert_png(out / "static_offset_curve.png")
    with open(out / "static_offset_curve.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    ax = plot_static.offset_figure(load_static(out)).axes[0]
    applied = [c for c in ax.lines if c.get_label().startswith("restoring force")][0]
    np.testing.assert_array_equal(applied.get_xdata(), [float(r["offset_m"]) for r in rows])
    np.testing.assert_array_equal(applied.get_ydata(),
                                  [float(r["force_N"]) / 1e3 for r in rows])
