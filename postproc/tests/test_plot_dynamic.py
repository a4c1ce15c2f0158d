"""Tests of rodyn_post.dynamic (reader) and rodyn-plot-dynamic
(rodyn_post.commands.plot_dynamic).

Synthetic dynamic results are written by the tests themselves (dynamic.h5 with h5py and
the CSV tables, following docs/output.md). If the environment variable RODYN_EXE names
the rodyn executable, a short run of the paper's case 2 (0.3 s) is also made and plotted.

    python3 -m pytest postproc/tests -q
    RODYN_EXE=build/rodyn python3 -m pytest postproc/tests -q
"""
import csv
import re
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from rodyn_post import RodynResultsError, load_dynamic
from rodyn_post.commands import plot_dynamic
from rodyn_post.dynamic import ELEMENTS_HEADER, ENDS_HEADER, LINES_HEADER, LOG_HEADER, NODES_HEADER
from test_plot_static import rodyn_exe

REPO = Path(__file__).resolve().parents[2]
COMMAND = [sys.executable, "-m", "rodyn_post.commands.plot_dynamic"]  # = rodyn-plot-dynamic

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
PNGS = ("dynamic_snapshots.png", "dynamic_tension.png", "dynamic_energy.png",
        "dynamic_momentum.png")
TITLE = "Synthetic dynamic run"
FREQ = 2.5  # Hz, of the *MOTION in the synthetic deck: period 0.4 s
DECK = f"""*HEADING
{TITLE}
*MOTION, LINE=CABLE, END=A, TYPE=HARMONIC, RAMP=0
Z, 0.1, {FREQ}, 0.0
*DYNAMIC, DT=0.05, TIME=1.1, OUTPUT INTERVAL=0.1
"""
TIMES = np.round(np.arange(12) * 0.1, 12)   # 12 frames, 0 to 1.1 s
N_STEPS = 22                                 # dt = 0.05 s
COUNTERS = dict(steps=N_STEPS, step_iterations=57, step_cutbacks=1)


# --- synthetic results --------------------------------------------------------------

def synthetic():
    """(lines, log): {name: arrays as in dynamic.h5 + end_held}, {log dataset: array}.
    The second line's name has a comma (quoted in CSV) and a '/' ('_' in the group
    name); it is held at end A only."""
    rng = np.random.default_rng(11)
    nf = len(TIMES)
    lines = {}
    for name, nn, ng, held in (("CABLE", 5, 4, (1, 1)), ("TAIL, 1/2", 3, 2, (1, 0))):
        x = np.linspace(0.0, 2.0, nn) + 0.01 * rng.normal(size=(nf, nn))
        z = -np.sin(np.linspace(0.0, np.pi, nn)) + 0.01 * rng.normal(size=(nf, nn))
        z[:, 0] += 0.5  # end A is the top end
        reactions = rng.normal(size=(nf, 12)) * 1e3
        end_tension = np.zeros((nf, 2))
        for k in (0, 1):
            if held[k]:
                end_tension[:, k] = np.linalg.norm(reactions[:, 6 * k:6 * k + 3], axis=1)
            else:
                reactions[:, 6 * k:6 * k + 6] = 0.0
        lines[name] = {
            "node_s": np.linspace(0.0, 2.0, nn),
            "gp_s": np.sort(rng.uniform(0.0, 2.0, ng)),
            "gp_element": np.arange(1, ng + 1, dtype=np.int32),
            "gp_point": np.ones(ng, dtype=np.int32),
            "x": x, "y": 0.01 * rng.normal(size=(nf, nn)), "z": z,
            "effective_tension": rng.normal(size=(nf, ng)) * 1e4,
            "moment_1": rng.normal(size=(nf, ng)), "moment_2": rng.normal(size=(nf, ng)),
            "torque": rng.normal(size=(nf, ng)),
            "bending_curvature": np.abs(rng.normal(size=(nf, ng))),
            "reactions": reactions, "end_tension": end_tension,
            "end_held": np.array(held, dtype=np.int32),
        }
    t = 0.05 * np.arange(1, N_STEPS + 1)
    work = 100.0 * np.sin(t)
    damping = 0.5 * t
    total = -3.0e4 + work - damping + 1e-6 * np.cos(7.0 * t)  # a small balance error
    iterations = np.full(N_STEPS, 2, dtype=np.int32)
    iterations[: COUNTERS["step_iterations"] - 2 * N_STEPS] += 1
    log = {
        "step": np.arange(1, N_STEPS + 1, dtype=np.int32), "time": t,
        "dt": np.full(N_STEPS, 0.05), "iterations": iterations,
        "cutbacks": np.r_[np.int32(1), np.zeros(N_STEPS - 1, dtype=np.int32)],
        "kinetic": rng.uniform(size=N_STEPS), "strain": rng.uniform(size=N_STEPS),
        "gravity": total, "external_work": work, "damping_work": damping, "total": total,
        "momentum": rng.normal(size=(N_STEPS, 3)),
        "angular_momentum": rng.normal(size=(N_STEPS, 3)),
    }
    return lines, log


def write_status(folder, complete=True, counters=COUNTERS, times=TIMES):
    """status.txt of a dynamic run as rodyn writes it."""
    c = counters
    (folder / "status.txt").write_text(
        f"complete = {'true' if complete else 'false'}\n"
        f"status = {'complete' if complete else 'running'}\n"
        "load_factor = 1.0000000000000000E+00\nincrements = 1\niterations = 6\n"
        "cutbacks = 0\nwall_time_s = 1.2345678901234567E+00\ndynamic = true\n"
        f"time_reached_s = {times[-1]:.16E}\nsteps = {c['steps']}\n"
        f"step_iterations = {c['step_iterations']}\nstep_cutbacks = {c['step_cutbacks']}\n"
        "rodyn_version = 0.1.0\ndeck = decks/synthetic.inp\n")


def write_h5(path, lines, log, complete=True, counters=COUNTERS, times=TIMES):
    """dynamic.h5 with the layout of docs/output.md (a finished run when complete,
    else one still running: no counters on /dynamic)."""
    with h5py.File(path, "w", track_order=True) as f:
        f.attrs.update(program="rodyn", version="0.1.0", deck_file="decks/synthetic.inp",
                       title=TITLE, units="SI: m, s, kg, N, N m, rad",
                       complete=np.int32(complete), status="complete" if complete
                       else "running", scheme="EMC", dt=0.05)
        f["deck"] = DECK
        dyn = f.create_group("dynamic", track_order=True)
        dyn.attrs.update(duration_s=times[-1], output_interval_s=times[1] - times[0])
        if complete:
            dyn.attrs.update(frames=np.int32(len(times)), time_reached_s=times[-1],
                             wall_time_s=1.2345678901234567,
                             **{k: np.int32(v) for k, v in counters.items()})
        dyn["time"] = times
        for name, a in lines.items():
            g = dyn.create_group(name.replace("/", "_"), track_order=True)
            g.attrs["name"] = name
            for key, value in a.items():
                if key != "end_held":
                    g[key] = value
            g["reactions"].attrs["end_held"] = a["end_held"]
        lg = dyn.create_group("log", track_order=True)
        for key, value in log.items():
            lg[key] = value


def write_csv(folder, lines, log, times=TIMES):
    """dynamic_nodes.csv, dynamic_elements.csv, dynamic_ends.csv, dynamic_log.csv."""
    def real(v):
        return f"{v:.16E}"

    tables = {"dynamic_nodes.csv": [NODES_HEADER], "dynamic_elements.csv": [ELEMENTS_HEADER],
              "dynamic_ends.csv": [ENDS_HEADER], "dynamic_log.csv": [LOG_HEADER]}
    if any("touchdown_s" in a for a in lines.values()):
        tables["dynamic_lines.csv"] = [LINES_HEADER]
    for i, t in enumerate(times):
        for name, a in lines.items():
            normal = a.get("seabed_normal", np.zeros_like(a["x"]))
            friction = a.get("seabed_friction", np.zeros_like(a["x"]))
            for k in range(len(a["node_s"])):
                tables["dynamic_nodes.csv"].append(
                    [real(t), name, k + 1] + [real(v) for v in (
                        a["node_s"][k], a["x"][i, k], a["y"][i, k], a["z"][i, k],
                        normal[i, k], friction[i, k])])
        for name, a in lines.items():
            wall = a.get("wall_tension", a["effective_tension"])
            for k in range(len(a["gp_s"])):
                tables["dynamic_elements.csv"].append(
                    [real(t), name, a["gp_element"][k], a["gp_point"][k]] + [real(v) for v in (
                        a["gp_s"][k], a["effective_tension"][i, k], wall[i, k],
                        a["moment_1"][i, k],
                        a["moment_2"][i, k], a["torque"][i, k], a["bending_curvature"][i, k])])
        for name, a in lines.items():
            for k, end in enumerate("AB"):
                if a["end_held"][k]:
                    r = a["reactions"][i, 6 * k:6 * k + 6]
                    tables["dynamic_ends.csv"].append(
                        [real(t), name, end] + [real(v) for v in r]
                        + [real(a["end_tension"][i, k])])
        if "dynamic_lines.csv" in tables:
            for name, a in lines.items():
                tables["dynamic_lines.csv"].append(
                    [real(t), name, real(a.get("touchdown_s", np.full(len(times), -1.0))[i])])
    for s in range(len(log["step"])):
        tables["dynamic_log.csv"].append(
            [log["step"][s], real(log["time"][s]), real(log["dt"][s]), log["iterations"][s],
             log["cutbacks"][s]] + [real(log[k][s]) for k in (
                 "kinetic", "strain", "gravity", "external_work", "damping_work")]
            + [real(log.get(k, np.zeros(len(log["step"])))[s])
               for k in ("hydro_work", "seabed_work", "numerical_work",
                         "numerical_energy")] + [real(log["total"][s])]
            + [real(v) for v in log["momentum"][s]]
            + [real(v) for v in log["angular_momentum"][s]])
    for file, rows in tables.items():
        with open(folder / file, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)


def write_results(folder, h5=True, csv_tables=True, complete=True):
    """A synthetic results folder; returns (lines, log) as written."""
    folder.mkdir(parents=True, exist_ok=True)
    lines, log = synthetic()
    if h5:
        write_h5(folder / "dynamic.h5", lines, log, complete)
    if csv_tables:
        write_csv(folder, lines, log)
    write_status(folder, complete)
    return lines, log


def run_script(*args, cwd):
    """Run rodyn-plot-dynamic (python3 -m) in a fresh interpreter; returns the CompletedProcess."""
    return subprocess.run([*COMMAND, *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


def assert_png(path):
    data = Path(path).read_bytes()
    assert len(data) > 1000 and data.startswith(PNG_SIGNATURE), path


def assert_error(capsys, argv, status, *fragments):
    """main(argv) returns `status` with a one-line message naming all fragments."""
    assert plot_dynamic.main([str(a) for a in argv]) == status
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("plot_dynamic: error:"), err
    for fragment in fragments:
        assert fragment in err, (fragment, err)


# --- (a) reader ---------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["h5", "h5 file", "csv"])
def test_load_dynamic_returns_the_arrays(tmp_path, kind):
    folder = tmp_path / "run"
    lines, log = write_results(folder, h5=kind != "csv")
    res = load_dynamic(folder / "dynamic.h5" if kind == "h5 file" else folder)
    assert [line.name for line in res.lines] == list(lines)
    np.testing.assert_array_equal(res.time, TIMES)
    for line in res.lines:
        for key, value in lines[line.name].items():
            got = getattr(line, key)
            assert got.shape == value.shape, key
            assert np.array_equal(got, value), key  # exact: 17 digits in the CSV
    for key, value in log.items():
        assert np.array_equal(getattr(res.log, key), value), key
    assert res.complete and res.status == "complete"
    assert (res.steps, res.step_iterations, res.step_cutbacks) == tuple(COUNTERS.values())
    assert res.line("TAIL, 1/2").end_held.tolist() == [True, False]
    assert res.line("CABLE").top_end == 0
    assert res.source.name == ("dynamic_nodes.csv" if kind == "csv" else "dynamic.h5")
    if kind == "csv":
        assert (res.title, res.scheme, res.deck, res.dt) == ("", "", "", 0.05)
    else:
        assert (res.title, res.scheme, res.dt) == (TITLE, "EMC", 0.05)
        assert res.motion_frequencies() == [FREQ]


def test_energy_balance_quantities():
    _, log_arrays = synthetic()
    from rodyn_post.dynamic import StepLog
    log = StepLog(**log_arrays)
    net = log_arrays["external_work"] - log_arrays["damping_work"]
    total0 = log_arrays["total"][0] - net[0]
    np.testing.assert_array_equal(log.net_work, net)
    assert log.initial_total == total0
    error = (log_arrays["total"] - total0) - net
    np.testing.assert_array_equal(log.energy_error, error)
    assert log.relative_energy_error() == np.max(np.abs(error)) / np.max(np.abs(
        log_arrays["external_work"]))
    assert 0 < log.relative_energy_error() < 1e-7


def test_stale_dynamic_h5_is_ignored(tmp_path):
    """dynamic.h5 left by an earlier run (other counters than status.txt): use CSV."""
    folder = tmp_path / "run"
    lines, log = write_results(folder)
    write_h5(folder / "dynamic.h5", lines, log, counters=dict(COUNTERS, steps=99))
    assert load_dynamic(folder).source.name == "dynamic_nodes.csv"
    assert load_dynamic(folder / "dynamic.h5").steps == 99


def test_killed_run_csv_drops_partial_rows(tmp_path):
    """A kill while writing: the last frame's rows and the last log row cut short."""
    folder = tmp_path / "run"
    write_results(folder, h5=False, complete=False)
    nodes = folder / "dynamic_nodes.csv"
    rows = nodes.read_text().splitlines()
    nodes.write_text("\n".join(rows[:-2]) + "\n")  # last frame misses two node rows
    logf = folder / "dynamic_log.csv"
    text = logf.read_text()
    logf.write_text(text[: text.rstrip("\n").rfind(",")])  # last row cut mid-field
    res = load_dynamic(folder)
    assert len(res.time) == len(TIMES) - 1 and len(res.log) == N_STEPS - 1
    assert res.line("CABLE").x.shape == (len(TIMES) - 1, 5)
    assert res.line("CABLE").end_tension.shape == (len(TIMES) - 1, 2)
    assert any("last frame" in w for w in res.warnings)
    assert any("dynamic_log.csv" in w for w in res.warnings)
    assert not res.complete


def test_running_h5_without_counters(tmp_path):
    folder = tmp_path / "run"
    write_results(folder, csv_tables=False, complete=False)
    res = load_dynamic(folder)
    assert res.status == "running" and not res.complete
    assert res.steps == N_STEPS and res.step_iterations == COUNTERS["step_iterations"]
    assert np.isnan(res.wall_time_s)


# --- (b) the script and the data behind the plots -----------------------------------

def test_script_writes_four_pngs(tmp_path):
    folder = tmp_path / "run"
    write_results(folder, csv_tables=False)
    out = tmp_path / "plots" / "new"
    proc = run_script(folder, "-o", out, "--dpi", 50, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    assert proc.stdout.split() == [str(out / name) for name in PNGS]
    for name in PNGS:
        assert_png(out / name)


def test_csv_only_and_default_folder(tmp_path, monkeypatch, capsys):
    write_results(tmp_path / "paper_case1", h5=False)
    monkeypatch.chdir(tmp_path)
    assert plot_dynamic.main(["--dpi", "40"]) == 0
    assert capsys.readouterr().err == ""
    for name in PNGS:
        assert_png(tmp_path / "paper_case1" / name)


def test_plotted_quantities_match_raw_data(tmp_path):
    folder = tmp_path / "run"
    lines, log = write_results(folder)
    res = load_dynamic(folder)
    # tension: top = end A (higher), bottom = end B; the curves are the raw values
    tension_fig = plot_dynamic.tension_figure(res)
    ax_top, ax_bot = tension_fig.axes
    for name, a in lines.items():
        curves = plot_dynamic.tension_curves(res, res.line(name))
        end, t, top = curves["top"]
        assert end == 0
        np.testing.assert_array_equal(t, TIMES)
        np.testing.assert_array_equal(top, a["end_tension"][:, 0] / 1e3)
        (line,) = [c for c in ax_top.lines if c.get_label() == f"{name} end A"]
        np.testing.assert_array_equal(line.get_xydata(), np.column_stack([TIMES, top]))
        assert ("bottom" in curves) == bool(a["end_held"][1])
    (line,) = ax_bot.lines
    np.testing.assert_array_equal(line.get_ydata(), lines["CABLE"]["end_tension"][:, 1] / 1e3)
    # energy: total - total(0), net work and their difference
    energy_fig = plot_dynamic.energy_figure(res)
    ax_e, ax_d = energy_fig.axes
    net = log["external_work"] - log["damping_work"]
    change = log["total"] - (log["total"][0] - net[0])
    np.testing.assert_array_equal(ax_e.lines[0].get_ydata(), change)
    np.testing.assert_array_equal(ax_e.lines[1].get_ydata(), net)
    np.testing.assert_array_equal(ax_d.lines[0].get_ydata(), change - net)
    np.testing.assert_array_equal(ax_d.lines[0].get_xdata(), log["time"])
    assert "damping" in ax_e.lines[1].get_label()
    # momentum: minus the values at step 1, components x, y, z
    ax_p, ax_l = plot_dynamic.momentum_figure(res).axes
    for k in range(3):
        np.testing.assert_array_equal(ax_p.lines[k].get_ydata(),
                                      log["momentum"][:, k] - log["momentum"][0, k])
        np.testing.assert_array_equal(ax_l.lines[k].get_ydata(), log["angular_momentum"][:, k]
                                      - log["angular_momentum"][0, k])
    t, dp, dl = plot_dynamic.momentum_curves(res.log, (0.3, 0.6))
    assert len(t) == 7 and np.all(dp[0] == log["momentum"][5] - log["momentum"][0])
    # snapshots: the last period (0.4 s) of the motion, over the start shape (no
    # static results in this folder), equal axes
    frames = plot_dynamic.snapshot_frames(res, None, 4)
    assert [round(res.time[f], 9) for f in frames] == [0.8, 0.9, 1.0, 1.1]
    ax = plot_dynamic.snapshots_figure(res, frames).axes[0]
    assert ax.get_aspect() == 1.0
    for name, a in lines.items():
        (start,) = [c for c in ax.lines if c.get_label() == f"{name}: start (t = 0 s)"]
        np.testing.assert_array_equal(start.get_xydata(), np.column_stack(
            [a["x"][0], a["z"][0]]))
        for f in frames:
            (c,) = [c for c in ax.lines if c.get_label() == f"{name}: t = {TIMES[f]:.4g} s"]
            np.testing.assert_array_equal(c.get_xydata(), np.column_stack(
                [a["x"][f], a["z"][f]]))
    # envelope: every frame of the window, one grey collection per line
    envelope = plot_dynamic.envelope_frames(res, (0.25, 0.75))
    assert envelope == [3, 4, 5, 6, 7]
    ax = plot_dynamic.snapshots_figure(res, frames, envelope).axes[0]
    assert len(ax.collections) == len(lines)
    for coll, a in zip(ax.collections, lines.values()):
        segments = coll.get_segments()
        assert len(segments) == len(envelope)
        for seg, f in zip(segments, envelope):
            np.testing.assert_array_equal(seg, np.column_stack([a["x"][f], a["z"][f]]))
    assert ax.collections[0].get_label().startswith("envelope: 5 frames, 0.3 to 0.7 s")


def test_times_and_window(tmp_path):
    folder = tmp_path / "run"
    write_results(folder)
    res = load_dynamic(folder)
    assert plot_dynamic.snapshot_frames(res, [0.04, 0.51, 0.49]) == [0, 5]
    # window: histories limited to it, default snapshots end at its end
    curves = plot_dynamic.tension_curves(res, res.line("CABLE"), (0.3, 0.6))
    np.testing.assert_allclose(curves["top"][1], [0.3, 0.4, 0.5, 0.6])
    t = plot_dynamic.energy_curves(res.log, (0.3, 0.6))[0]
    assert t[0] == pytest.approx(0.3) and t[-1] == pytest.approx(0.6) and len(t) == 7
    frames = plot_dynamic.snapshot_frames(res, None, 2, 0.6)
    assert [round(res.time[f], 9) for f in frames] == [0.4, 0.6]


def test_period_estimated_without_deck(tmp_path):
    """CSV only (no deck text): the period comes from the node that moves most."""
    folder = tmp_path / "run"
    write_results(folder, h5=False)
    nodes = folder / "dynamic_nodes.csv"
    rows = list(csv.reader(nodes.open()))
    times = np.round(np.arange(41) * 0.05, 12)
    out = [rows[0]]
    for t in times:
        for r in rows[1:1 + 8]:  # the first frame's rows, moved in time
            r = list(r)
            r[0] = f"{t:.16E}"
            if r[1] == "CABLE" and r[2] == "1":
                r[6] = f"{0.3 * np.sin(2 * np.pi * FREQ * t + 0.3):.16E}"
            out.append(r)
    with open(nodes, "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(out)
    for name in ("dynamic_elements.csv", "dynamic_ends.csv"):
        rows = list(csv.reader((folder / name).open()))
        first = [r for r in rows[1:] if float(r[0]) == 0.0]
        new = [rows[0]] + [[f"{t:.16E}"] + r[1:] for t in times for r in first]
        with open(folder / name, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(new)
    res = load_dynamic(folder)
    assert len(res.time) == 41
    assert plot_dynamic.motion_period(res) == pytest.approx(1.0 / FREQ, rel=0.05)


# --- (c) bad input ------------------------------------------------------------------

def test_bad_inputs(tmp_path, capsys):
    assert_error(capsys, [tmp_path / "nowhere"], 1, "nowhere", "no such results folder")
    (tmp_path / "empty").mkdir()
    assert_error(capsys, [tmp_path / "empty"], 1, "no dynamic results")
    folder = tmp_path / "run"
    write_results(folder)
    assert_error(capsys, [folder, "--times", "5"], 1, "--times", "outside the run")
    assert_error(capsys, [folder, "--window", "7", "9"], 1, "--window", "overlap")
    with pytest.raises(SystemExit) as exc:
        plot_dynamic.main([str(folder), "--window", "0.5", "0.2"])
    assert exc.value.code == 2
    assert "T1 must be greater" in capsys.readouterr().err


def test_bad_csv_header_and_cell(tmp_path, capsys):
    folder = tmp_path / "run"
    write_results(folder, h5=False)
    path = folder / "dynamic_ends.csv"
    original = path.read_text()
    path.write_text(original.replace("tension_N", "T_N", 1))
    assert_error(capsys, [folder], 1, "dynamic_ends.csv: line 1: header")
    rows = original.splitlines()
    fields = rows[2].split(",")
    fields[5] = "abc"  # Fz_N of the second row (file line 3)
    rows[2] = ",".join(fields)
    path.write_text("\n".join(rows) + "\n")
    assert_error(capsys, [folder], 1, "dynamic_ends.csv: line 3", "Fz_N", "'abc'")


def test_missing_dataset_and_bad_status(tmp_path, capsys):
    folder = tmp_path / "run"
    write_results(folder, csv_tables=False)
    with h5py.File(folder / "dynamic.h5", "r+") as f:
        del f["dynamic/CABLE/end_tension"]
    assert_error(capsys, [folder], 1, "dynamic.h5", "/dynamic/CABLE/end_tension")
    other = tmp_path / "static_only"
    write_results(other, h5=False)
    (other / "status.txt").write_text("complete = true\nstatus = complete\n")
    with pytest.raises(RodynResultsError, match="not the status of a dynamic run"):
        load_dynamic(other)


# --- (d) a real rodyn run -----------------------------------------------------------

def test_real_paper_case2_short(tmp_path):
    exe = rodyn_exe()
    deck_text = (REPO / "input" / "paper_case2.inp").read_text()
    deck_text, n = re.subn(r"TIME=15\.0", "TIME=0.3", deck_text)
    assert n == 1
    shutil.copy(REPO / "input" / "paper_cable_section.inc", tmp_path)
    deck = tmp_path / "case2_short.inp"
    deck.write_text(deck_text)
    out = tmp_path / "case2_short"
    run = subprocess.run([str(exe), str(deck), "-o", str(out), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    proc = run_script(out, "--dpi", 50, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    for name in PNGS:
        assert_png(out / name)

    res = load_dynamic(out)
    assert res.complete and res.source.name == "dynamic.h5" and res.scheme == "EMC"
    assert res.steps == 20 and len(res.time) == 6  # frames at 0, 0.06, ..., 0.3 s
    assert res.motion_frequencies() == [1.0]
    # the top tension plotted is the end A column of dynamic_ends.csv
    with open(out / "dynamic_ends.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["line"] == "CABLE"]
    top_csv = np.array([float(r["tension_N"]) for r in rows if r["end"] == "A"])
    bottom_csv = np.array([float(r["tension_N"]) for r in rows if r["end"] == "B"])
    curves = plot_dynamic.tension_curves(res, res.line("CABLE"))
    np.testing.assert_array_equal(curves["top"][2], top_csv / 1e3)
    np.testing.assert_array_equal(curves["bottom"][2], bottom_csv / 1e3)
    # the snapshots are drawn over the static shape of static_nodes.csv
    with open(out / "static_nodes.csv", newline="") as f:
        xz = np.array([[float(r["x_m"]), float(r["z_m"])] for r in csv.DictReader(f)])
    ax = plot_dynamic.snapshots_figure(res, plot_dynamic.snapshot_frames(res)).axes[0]
    (static,) = [c for c in ax.lines if c.get_label() == "CABLE: static"]
    np.testing.assert_array_equal(static.get_xydata(), xz)
    # EMC: the energy balance holds to the Newton tolerance
    assert res.log.relative_energy_error() < 1e-6

    # the CSV fallback reads the same numbers as dynamic.h5
    csv_only = tmp_path / "csv_only"
    shutil.copytree(out, csv_only)
    (csv_only / "dynamic.h5").unlink()
    from_csv = load_dynamic(csv_only)
    np.testing.assert_array_equal(from_csv.time, res.time)
    a, b = from_csv.line("CABLE"), res.line("CABLE")
    for key in ("node_s", "x", "y", "z", "gp_s", "effective_tension", "moment_1",
                "reactions", "end_tension"):
        np.testing.assert_array_equal(getattr(a, key), getattr(b, key), err_msg=key)
    # bending curvature: CSV and HDF5 may differ in the last bit (computed twice)
    np.testing.assert_allclose(a.bending_curvature, b.bending_curvature, rtol=1e-15,
                               atol=0.0)
    for key in ("time", "iterations", "total", "external_work", "momentum"):
        np.testing.assert_array_equal(getattr(from_csv.log, key), getattr(res.log, key),
                                      err_msg=key)
