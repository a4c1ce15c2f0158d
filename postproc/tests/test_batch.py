"""Tests of rodyn-batch (rodyn_post.batch): short runs of the paper's cable.

Needs RODYN_EXE (tools/test.sh sets it); the Dask tests need `distributed`. The
parameter-grid test needs a rodyn with --set (*PARAMETER) and is skipped otherwise.
"""
from __future__ import annotations

import csv
import json
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from rodyn_post import batch
from rodyn_post.batch_extract import DEFAULT_EXTRACT, extract_case
from rodyn_post.batch_summary import TIMING_COLUMNS, read_summary

ROOT = Path(__file__).resolve().parents[2]
RODYN = os.environ.get("RODYN_EXE")
INCLUDE = ROOT / "input" / "paper_cable_section.inc"
POSTPROC = ROOT / "postproc"

pytestmark = pytest.mark.skipif(not RODYN or not Path(RODYN).is_file(),
                                reason="RODYN_EXE not set (run through tools/test.sh)")


def cable_deck(amplitude: float, frequency: float, elements: int = 4,
               duration: float = 1.0) -> str:
    """input/paper_case1.inp, short and coarse, with another heave motion."""
    text = (ROOT / "input" / "paper_case1.inp").read_text()
    text = text.replace("INPUT=paper_cable_section.inc", f"INPUT={INCLUDE}")
    text = text.replace("ELEMENTS=30", f"ELEMENTS={elements}")
    text = text.replace("TIME=900.0", f"TIME={duration}")
    return text.replace("Z, 0.4, 0.658, 0.0", f"Z, {amplitude}, {frequency}, 0.0")


def write_decks(folder: Path, n: int = 12, **kw) -> list:
    folder.mkdir(parents=True, exist_ok=True)
    decks = []
    for k in range(n):
        amp, freq = 0.1 + 0.1 * (k % 4), (0.5, 0.658, 0.8)[k // 4 % 3]
        path = folder / f"case{k:02d}.inp"
        path.write_text(cable_deck(amp, freq, **kw))
        decks.append(path)
    return decks


def run_main(argv) -> int:
    return batch.main([str(a) for a in argv])


def csv_rows(path: Path) -> list:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def same_values(a, b) -> bool:
    """Equal bit for bit (nan equal to nan)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind == "f":
        return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))
    return a.shape == b.shape and bool(np.all(a == b))


def assert_same_summary(s1: dict, s2: dict, ignore=TIMING_COLUMNS + ("skipped",)):
    assert s1["columns"] == s2["columns"]
    for col in s1["columns"]:
        if col not in ignore:
            assert same_values(s1["cases"][col], s2["cases"][col]), col
    for name in ("envelope", "envelope_nodes"):
        assert (s1[name] is None) == (s2[name] is None)
        if s1[name] is not None:
            for key in s1[name]:
                assert same_values(s1[name][key], s2[name][key]), (name, key)


@pytest.fixture(scope="module")
def batch12(tmp_path_factory):
    """12 short cases (12 deck files) run by a batch on 2 local workers."""
    base = tmp_path_factory.mktemp("batch12")
    decks = write_decks(base / "decks")
    out = base / "out"
    code = run_main([base / "decks" / "case*.inp", "-o", out, "-j", "2", "--rodyn", RODYN])
    return {"base": base, "decks": decks, "out": out, "code": code}


def test_local_batch_equals_lone_runs(batch12, tmp_path):
    out = batch12["out"]
    assert batch12["code"] == 0
    rows = csv_rows(out / "summary.csv")
    assert len(rows) == 12 and all(r["status"] == "complete" for r in rows)
    summary = read_summary(out)
    ids = list(summary["cases"]["id"])
    assert ids == [f"case{k:02d}" for k in range(12)]
    log = (out / "batch.log").read_text()
    for k, deck in enumerate(batch12["decks"]):
        case = out / ids[k]
        assert (case / "command.txt").read_text().startswith(f"{RODYN} {deck} -o ")
        assert f"case {ids[k]}: {RODYN} {deck}" in log
        lone = tmp_path / ids[k]
        subprocess.run([RODYN, str(deck), "-o", str(lone), "--quiet"], check=True)
        scalars = extract_case(lone, DEFAULT_EXTRACT)["scalars"]
        assert scalars, "nothing extracted"
        for key, value in scalars.items():
            assert same_values(summary["cases"][key][k], value), (ids[k], key)
            text = rows[k][key]
            assert same_values(float(text) if text else math.nan, value), (ids[k], key)
    # one extreme straight from the lone run's CSV tables
    ends = csv_rows(tmp_path / ids[-1] / "dynamic_ends.csv")
    top = max(float(r["tension_N"]) for r in ends if r["end"] == "A")
    assert summary["cases"]["CABLE.end_A_tension_max_N"][-1] == top
    elements = csv_rows(tmp_path / ids[-1] / "dynamic_elements.csv")
    tmax = max(elements, key=lambda r: float(r["effective_tension_N"]))
    assert summary["cases"]["CABLE.tension_max_N"][-1] == float(tmax["effective_tension_N"])
    assert summary["cases"]["CABLE.tension_max_t_s"][-1] == float(tmax["time_s"])
    assert summary["cases"]["CABLE.tension_max_S_m"][-1] == float(tmax["s_m"])
    # Newton statistics and envelopes are there
    assert np.all(summary["cases"]["step_iterations"] > 0)
    env = summary["envelope"]
    assert set(np.unique(env["case"])) == set(range(12))
    assert np.all(env["tension_max"] >= env["tension_min"])
    assert not list(out.glob(".*.lock")) and not list(out.glob(".*.tmp-*"))


def test_rerun_skips_complete_cases(batch12, capsys):
    out = batch12["out"]
    assert run_main([batch12["base"] / "decks" / "case*.inp", "-o", out, "--rodyn", RODYN,
                     "--list"]) == 0
    listed = capsys.readouterr().out.splitlines()
    assert len(listed) == 12 and all("\tskip (complete)\t" in x for x in listed)
    before = {p.name: p.stat().st_mtime_ns for p in out.glob("case*/batch_case.json")}
    assert run_main([batch12["base"] / "decks" / "case*.inp", "-o", out, "-j", "2",
                     "--rodyn", RODYN, "--no-progress"]) == 0
    after = {p.name: p.stat().st_mtime_ns for p in out.glob("case*/batch_case.json")}
    assert before == after
    assert all(r["skipped"] == "1" for r in csv_rows(out / "summary.csv"))


def test_plots_and_bulk_compare(batch12, tmp_path):
    out = batch12["out"]
    assert run_main(["plot", out, "--envelope", "tension", "-o", tmp_path / "env.png"]) == 0
    assert (tmp_path / "env.png").stat().st_size > 1000
    env = csv_rows(tmp_path / "env.csv")
    summary = read_summary(out)
    assert max(float(r["tension_max_N"]) for r in env) == np.max(
        summary["cases"]["CABLE.tension_max_N"])
    refdir = tmp_path / "refs"
    refdir.mkdir()
    ends = csv_rows(out / "case03" / "dynamic_ends.csv")
    with open(refdir / "case03.csv", "w") as f:
        f.write("time [s],tension [kN]\n")
        for r in ends:
            if r["end"] == "A":
                f.write(f"{r['time_s']},{float(r['tension_N']) * 1e-3}\n")
    (refdir / "nocase.csv").write_text("t,T\n0,1\n1,2\n")
    code = run_main(["compare", out, refdir, "--at", "A", "--quantity", "end_tension",
                     "-o", tmp_path / "errors.csv"])
    rows = {r["id"]: r for r in csv_rows(tmp_path / "errors.csv")}
    assert code == 4 and rows["nocase"]["status"] == "no case"
    assert rows["case03"]["status"] == "ok"
    assert float(rows["case03"]["rel_max_error"]) < 1e-12


def test_plot_against_parameter(tmp_path):
    """A batch from a case table... replaced by a fake summary: plot needs parameters."""
    from rodyn_post.batch_summary import write_summary
    entries = []
    for k in range(6):
        rec = {"status": "complete", "extract": {"scalars": {"L.tension_max_N": 1e3 * k},
                                                 "envelope": {}}}
        entries.append({"id": f"c{k}", "params": {"HS": str(k % 3), "DIR": str(k // 3)},
                        "record": rec})
    write_summary(tmp_path, entries, ["HS", "DIR"])
    assert run_main(["plot", tmp_path, "--y", "tension_max_N", "--x", "HS", "--by",
                     "DIR", "-o", tmp_path / "p.png"]) == 0
    assert (tmp_path / "p.png").is_file()
    # the axis names the quantity and its unit once, not the column's name
    from rodyn_post.batch_plot import plot_column
    from rodyn_post.batch_summary import read_summary
    fig = plot_column(read_summary(tmp_path), "L.tension_max_N", "HS", "DIR")
    assert fig.axes[0].get_ylabel() == "L: max tension [kN]"
    from rodyn_post.batch_plot import axis_label
    assert [axis_label(c) for c in (
        "LEG.end_B_tension_max_N", "LEG.end_A_tension_min_t_s", "CABLE.moment_max_S_m",
        "LEG.touchdown_max_S_m", "LEG.touchdown_min_t_s", "CABLE.bend_radius_min_m",
        "LEG.seabed_normal_max_N_per_m", "max_step_iterations")] == [
        "LEG end B: max tension [kN]", "LEG end A: time of min tension [s]",
        "CABLE: S of max moment [m]", "LEG: max touchdown S [m]",
        "LEG: time of min touchdown S [s]", "CABLE: min bend radius [m]",
        "LEG: max seabed normal force [kN/m]", "max step iterations"]


def test_parameter_grid_equals_lone_runs(tmp_path):
    deck = tmp_path / "param.inp"
    text = cable_deck(0.4, 0.658).replace("Z, 0.4, 0.658, 0.0", "Z, <AMP>, <FREQ>, 0.0")
    deck.write_text(text.replace("*HEADING", "*PARAMETER\nAMP = 0.4\nFREQ = 0.658\n*HEADING"))
    out = tmp_path / "out"
    assert run_main([deck, "-o", out, "-j", "2", "--grid", "AMP=0.1,0.2,0.3,0.4",
                     "--grid", "FREQ=0.5,0.658,0.8", "--rodyn", RODYN]) == 0
    summary = read_summary(out)
    assert len(summary["cases"]["id"]) == 12
    assert summary["cases"]["id"][0] == "AMP=0.1_FREQ=0.5"
    for k, case_id in enumerate(summary["cases"]["id"]):
        params = dict(p.split("=") for p in case_id.split("_"))
        lone = tmp_path / "lone" / case_id
        subprocess.run([RODYN, str(deck), "-o", str(lone), "--quiet"]
                       + [a for n, v in params.items() for a in ("--set", f"{n}={v}")],
                       check=True)
        for key, value in extract_case(lone)["scalars"].items():
            assert same_values(summary["cases"][key][k], value), (case_id, key)


def test_parameter_grid_ids_commands_and_rerun(tmp_path):
    """The grid path: ids, parameter columns, --set command lines; a changed deck runs
    every case again; a parameter plot from the summary."""
    deck = tmp_path / "param.inp"
    text = cable_deck(0.4, 0.658).replace("Z, 0.4, 0.658, 0.0", "Z, <AMP>, <FREQ>, 0.0")
    deck.write_text(text.replace("*HEADING", "*PARAMETER\nAMP = 0.4\nFREQ = 0.658\n"
                                             "*HEADING"))
    out = tmp_path / "out"
    grid = ["--grid", "AMP=0.1,0.2,0.3,0.4", "--grid", "FREQ=0.5,0.658,0.8"]
    assert run_main([deck, "-o", out, "-j", "2", *grid, "--rodyn", RODYN,
                     "--no-progress"]) == 0
    summary = read_summary(out)
    ids = list(summary["cases"]["id"])
    assert len(ids) == 12 and ids[:2] == ["AMP=0.1_FREQ=0.5", "AMP=0.1_FREQ=0.658"]
    assert list(summary["cases"]["AMP"][:4]) == [0.1, 0.1, 0.1, 0.2]
    cmd = (out / ids[5] / "command.txt").read_text()
    assert cmd.endswith("--set AMP=0.2 --set FREQ=0.8 --quiet\n")
    status = (out / ids[5] / "status.txt").read_text()   # rodyn echoes the values used
    assert "parameter.AMP = 0.2" in status and "parameter.FREQ = 0.8" in status
    assert run_main(["plot", out, "--y", "CABLE.end_A_tension_max_N", "--x", "AMP",
                     "--by", "FREQ", "-o", tmp_path / "p.png"]) == 0
    deck.write_text(deck.read_text().replace("DT=0.1", "DT=0.05"))
    assert run_main([deck, "-o", out, "-j", "2", *grid, "--rodyn", RODYN,
                     "--no-progress"]) == 0
    assert not any(r["skipped"] == "1" for r in csv_rows(out / "summary.csv"))


def test_example_case_table(tmp_path):
    """input/batch/cable_heave.inp with input/batch/cases.csv (shortened by --set)."""
    out = tmp_path / "out"
    code = run_main([ROOT / "input" / "batch" / "cable_heave.inp", "--cases",
                     ROOT / "input" / "batch" / "cases.csv", "--set", "DURATION=2",
                     "-o", out, "-j", "2", "--rodyn", RODYN, "--no-progress"])
    assert code == 0
    rows = csv_rows(out / "summary.csv")
    assert [r["id"] for r in rows][-1] == "a04_f066_fine"
    assert rows[-1]["ELEMENTS"] == "30" and rows[0]["ELEMENTS"] == ""
    assert all(r["status"] == "complete" for r in rows)


# --- Dask -------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def cluster():
    distributed = pytest.importorskip("distributed")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(POSTPROC)] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
                           if p]))
    saved = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = env["PYTHONPATH"]      # the worker processes import us
    try:
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                      dashboard_address=None, silence_logs=50) as c:
            yield c
    finally:
        if saved is None:
            os.environ.pop("PYTHONPATH", None)
        else:
            os.environ["PYTHONPATH"] = saved


def test_dask_local_cluster(batch12, cluster, tmp_path):
    out = tmp_path / "out"
    code = run_main([batch12["base"] / "decks" / "case*.inp", "-o", out, "--scheduler",
                     cluster.scheduler_address, "--rodyn", RODYN, "--no-progress"])
    assert code == 0
    assert_same_summary(read_summary(out), read_summary(batch12["out"]))


def test_dask_worker_killed_mid_case(cluster, tmp_path):
    # cases of 10 000 steps, so that the kill (a few ms after the case's folder appears)
    # finds the case running on a machine many times faster than this one
    decks = write_decks(tmp_path / "decks", n=4, elements=30, duration=1000.0)
    out = tmp_path / "out"
    result = {}
    thread = threading.Thread(target=lambda: result.setdefault("code", run_main(
        [tmp_path / "decks" / "case*.inp", "-o", out, "--scheduler",
         cluster.scheduler_address, "--rodyn", RODYN, "--no-progress"])))
    thread.start()
    killed = None
    deadline = time.monotonic() + 30
    while killed is None and time.monotonic() < deadline:
        for tmp in out.glob(".case*.tmp-*"):
            if (tmp / "stderr.txt").exists():
                killed = (tmp.name.split(".tmp-")[0][1:], int(tmp.name.split("-")[1]))
                os.kill(killed[1], signal.SIGKILL)
                break
        time.sleep(0.002)
    thread.join(120)
    assert killed is not None and not thread.is_alive()
    assert result["code"] == 0
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert len(rows) == 4 and all(r["status"] == "complete" for r in rows.values())
    record = json.loads((out / killed[0] / "batch_case.json").read_text())
    assert record["pid"] != killed[1]        # run again by another worker process
    assert len(decks) == 4


# --- failures -----------------------------------------------------------------------------

def test_bad_deck_failing_case_and_time_limit(tmp_path, capsys):
    decks = write_decks(tmp_path / "decks", n=3)
    bad = tmp_path / "decks" / "bad.inp"
    bad.write_text(cable_deck(0.1, 0.5).replace("SECTION=CABLE, LENGTH", "SECTION=NONE, "
                                                                           "LENGTH"))
    nan = tmp_path / "decks" / "nan.inp"
    nan.write_text((ROOT / "tests" / "program" / "dynamic_nan.inp").read_text()
                   .replace("../../input/paper_cable_section.inc", str(INCLUDE)))
    slow = tmp_path / "decks" / "slow.inp"     # 10^6 steps: unfinishable in 1.5 s anywhere
    slow.write_text(cable_deck(0.1, 0.5, elements=30, duration=1.0e5))
    out = tmp_path / "out"
    code = run_main(list(decks) + [bad, nan, slow, "-o", out, "-j", "2", "--timeout", "1.5",
                                   "--rodyn", RODYN, "--no-progress"])
    assert code == 4
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert [rows[f"case{k:02d}"]["status"] for k in range(3)] == ["complete"] * 3
    assert rows["bad"]["status"] == "failed" and rows["bad"]["exit_code"] == "1"
    assert "error" in rows["bad"]["message"] and "NONE" in rows["bad"]["message"]
    assert rows["nan"]["status"] == "failed" and rows["nan"]["exit_code"] == "2"
    assert "NaN or Inf" in rows["nan"]["message"]
    assert rows["nan"]["CABLE.end_A_tension_max_N"] != ""     # frames up to the failure
    assert rows["slow"]["status"] == "timeout" and "time limit" in rows["slow"]["message"]
    assert "3 of 6 cases not complete" in capsys.readouterr().err


@pytest.mark.skipif(not Path("/proc/self/cmdline").exists(), reason="needs /proc")
def test_case_killed_by_a_signal(tmp_path):
    """A rodyn process killed from outside (not by the time limit): status signal."""
    decks = write_decks(tmp_path / "decks", n=2, elements=30, duration=1.0e5)
    out = tmp_path / "out"
    result = {}
    thread = threading.Thread(target=lambda: result.setdefault("code", run_main(
        [decks[0], "-o", out, "--rodyn", RODYN, "--no-progress", "--timeout", "60"])))
    thread.start()
    victim, deadline = None, time.monotonic() + 30
    exe = str(Path(RODYN).resolve()).encode()
    while victim is None and time.monotonic() < deadline:
        for proc in Path("/proc").iterdir():
            try:
                cmd = (proc / "cmdline").read_bytes().split(b"\0")
            except OSError:
                continue
            if cmd and cmd[0] == exe and str(out).encode() in b" ".join(cmd):
                victim = int(proc.name)
                break
        time.sleep(0.05)
    assert victim is not None
    os.kill(victim, signal.SIGKILL)
    thread.join(60)
    assert result["code"] == 4
    row = csv_rows(out / "summary.csv")[0]
    assert row["status"] == "signal" and row["exit_code"] == "-9"
    assert row["message"].startswith("killed by SIGKILL")


def _batch_cmd(decks_glob, out):
    return [sys.executable, "-m", "rodyn_post.batch", str(decks_glob), "-o", str(out),
            "-j", "2", "--rodyn", RODYN, "--no-progress"]


def test_interrupt_and_resume(tmp_path):
    # cases of 2000 steps: the interrupt (at most 20 ms after the third case is seen done)
    # comes long before the twelfth is done, on a machine many times faster than this one
    write_decks(tmp_path / "decks", n=12, elements=30, duration=200.0)
    pattern = tmp_path / "decks" / "case*.inp"
    env = dict(os.environ, PYTHONPATH=str(POSTPROC))
    out = tmp_path / "out"
    proc = subprocess.Popen(_batch_cmd(pattern, out), env=env, stderr=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while len(list(out.glob("case*/batch_case.json"))) < 3 and time.monotonic() < deadline:
        time.sleep(0.02)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    finished = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("case*/batch_case.json")}
    assert 3 <= len(finished) < 12
    assert not list(out.glob(".*.tmp-*")) and not list(out.glob(".*.lock"))
    rows = csv_rows(out / "summary.csv")
    assert sum(r["status"] == "not run" for r in rows) == 12 - len(finished)
    done = subprocess.run(_batch_cmd(pattern, out), env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    for name, mtime in finished.items():
        assert (out / name / "batch_case.json").stat().st_mtime_ns == mtime, name
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert {k for k, r in rows.items() if r["skipped"] == "1"} == set(finished)
    whole = tmp_path / "whole"
    assert subprocess.run(_batch_cmd(pattern, whole), env=env).returncode == 0
    assert_same_summary(read_summary(out), read_summary(whole))


def test_sigterm_stops_like_ctrl_c(tmp_path):
    write_decks(tmp_path / "decks", n=6, elements=30, duration=200.0)
    out = tmp_path / "out"
    proc = subprocess.Popen(_batch_cmd(tmp_path / "decks" / "case*.inp", out),
                            env=dict(os.environ, PYTHONPATH=str(POSTPROC)),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while not list(out.glob("case*/batch_case.json")) and time.monotonic() < deadline:
        time.sleep(0.02)
    proc.terminate()
    assert proc.wait(timeout=60) == 130
    assert not list(out.glob(".*.tmp-*")) and not list(out.glob(".*.lock"))
    assert any(r["status"] == "not run" for r in csv_rows(out / "summary.csv"))


# --- bad input ----------------------------------------------------------------------------

PARAM_DECK = "*PARAMETER\nAMP = 0.4\n** a comment\nFREQ = 0.658\n*HEADING\nx\n"


def _bad(argv, capsys) -> str:
    code = run_main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 1, err
    assert len(err.splitlines()) == 1, err
    return err


def test_bad_input(tmp_path, capsys):
    deck = tmp_path / "param.inp"
    deck.write_text(PARAM_DECK)
    out = tmp_path / "out"
    table = tmp_path / "cases.csv"
    table.write_text("id,AMP,DEPTH\nc1,0.1,100\nc2,0.2,200\n")
    err = _bad([deck, "--cases", table, "-o", out, "--rodyn", RODYN], capsys)
    assert f"{table}:2" in err and "DEPTH" in err
    table.write_text("id,AMP\nc1,0.1\nc2,0.2\nc1,0.3\n")
    err = _bad([deck, "--cases", table, "-o", out, "--rodyn", RODYN], capsys)
    assert f"{table}:4" in err and "duplicate case id 'c1'" in err
    err = _bad([deck, "--grid", "AMP=1,2", "--grid", "NOPE=3", "-o", out, "--rodyn",
                RODYN], capsys)
    assert "NOPE" in err and str(deck) in err
    table.write_text("id,AMP\nsummary.csv,0.1\n")
    err = _bad([deck, "--cases", table, "-o", out, "--rodyn", RODYN], capsys)
    assert f"{table}:2" in err and "its own files" in err
    err = _bad([tmp_path / "missing.inp", "-o", out, "--rodyn", RODYN], capsys)
    assert "missing.inp: no such deck" in err
    good = write_decks(tmp_path / "decks", n=1)[0]
    err = _bad([good, "-o", out, "--scheduler", "tcp://127.0.0.1:1", "--connect-timeout",
                "1", "--rodyn", RODYN], capsys)
    assert "tcp://127.0.0.1:1" in err
    assert not out.exists() or not list(out.iterdir())


def test_locked_case_refused_and_stale_lock_taken_over(tmp_path, capsys):
    import socket
    good = write_decks(tmp_path / "decks", n=1)[0]
    out = tmp_path / "out"
    out.mkdir()
    lock = out / ".case00.lock"
    lock.write_text(json.dumps({"pid": os.getpid(), "host": socket.gethostname(),
                                "batch": "other", "time": "now"}))
    err = _bad([good, "-o", out, "--rodyn", RODYN], capsys)
    assert "being written by another batch" in err and f"pid {os.getpid()}" in err
    assert not (out / "case00").exists()
    dead = subprocess.Popen(["true"])
    dead.wait()
    lock.write_text(json.dumps({"pid": dead.pid, "host": socket.gethostname(),
                                "batch": "other", "time": "now"}))
    assert run_main([good, "-o", out, "--rodyn", RODYN, "--no-progress"]) == 0
    assert not lock.exists()


def test_seabed_and_static_extremes(tmp_path):
    """A mooring leg on the seabed: touchdown range and seabed force, dynamic (short
    surge) and static (a deck without *DYNAMIC: no times)."""
    decks = tmp_path / "decks"
    decks.mkdir()
    inc = ROOT / "input" / "mooring_leg_section.inc"
    for name, src in (("surge", "mooring_surge.inp"), ("static", "mooring_catenary.inp")):
        text = (ROOT / "input" / src).read_text().replace("ELEMENTS=120", "ELEMENTS=30")
        text = text.replace("TIME=120.0", "TIME=3.0")
        (decks / f"{name}.inp").write_text(text.replace("INPUT=mooring_leg_section.inc",
                                                        f"INPUT={inc}"))
    out = tmp_path / "out"
    assert run_main([decks / "*.inp", "-o", out, "--rodyn", RODYN, "--no-progress",
                     "--extract", "all"]) == 0
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    lines = csv_rows(out / "surge" / "dynamic_lines.csv")
    td = [float(r["touchdown_s_m"]) for r in lines]
    assert float(rows["surge"]["LEG.touchdown_min_S_m"]) == min(td)
    assert float(rows["surge"]["LEG.touchdown_max_S_m"]) == max(td)
    assert float(rows["surge"]["LEG.seabed_normal_max_N_per_m"]) > 0
    assert rows["static"]["LEG.tension_max_t_s"] == ""           # no time in statics
    assert float(rows["static"]["LEG.touchdown_min_S_m"]) > 0
    assert run_main(["plot", out, "--envelope", "seabed_normal", "-o",
                     tmp_path / "sb.png"]) == 0


def test_deck_parameters_hash_and_ids(tmp_path):
    from rodyn_post.batch_cases import case_hash, deck_parameters, grid_cases
    inc = tmp_path / "sub" / "params.inc"
    inc.parent.mkdir()
    inc.write_text("*PARAMETER\nDEPTH = 100.0\n** HIDDEN = 1\n*SECTION, NAME=X\nNOT = 2\n")
    deck = tmp_path / "deck.inp"
    deck.write_text("** header\n*Parameter\n  amp = 0.4\nFREQ=2*<AMP>\n"
                    "*INCLUDE, INPUT=sub/params.inc\n*HEADING\nx\n")
    assert deck_parameters(deck) == {"AMP": "0.4", "FREQ": "2*<AMP>", "DEPTH": "100.0"}
    h0 = case_hash(deck, {"AMP": "1"})
    assert h0 == case_hash(deck, {"AMP": "1"}) != case_hash(deck, {"AMP": "2"})
    inc.write_text(inc.read_text().replace("100.0", "200.0"))
    assert case_hash(deck, {"AMP": "1"}) != h0          # an include changed
    cases = grid_cases(["DIR=N/E,S W", "amp=1"], deck, {"DEPTH": "5"})
    assert [c.id for c in cases] == ["DIR=N_E_amp=1", "DIR=S_W_amp=1"]
    assert cases[0].params == {"DEPTH": "5", "DIR": "N/E", "amp": "1"}


# --- two batches into one folder ---------------------------------------------------------

def test_two_batches_into_one_folder_merge(tmp_path, capsys):
    """A second batch with another case table into the same folder: the summary, the
    summary's HDF5 file and batch_cases.json list the cases of both batches, and
    `rodyn-batch summary OUT` gives them again; a case id defined again takes its new
    definition (run again), the other earlier cases are kept as they were."""
    first = write_decks(tmp_path / "a", n=3)
    second = []
    for k, amp in enumerate((0.15, 0.25)):
        path = tmp_path / "b" / f"other{k}.inp"
        path.parent.mkdir(exist_ok=True)
        path.write_text(cable_deck(amp, 0.7))
        second.append(path)
    redefined = tmp_path / "b" / "case02.inp"            # same id as a case of the first
    redefined.write_text(cable_deck(0.35, 0.9))
    out = tmp_path / "out"
    assert run_main(first + ["-o", out, "--rodyn", RODYN, "--no-progress"]) == 0
    before = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert run_main(second + [redefined, "-o", out, "--rodyn", RODYN,
                              "--no-progress"]) == 0
    assert "holds 2 case(s) of another batch" in capsys.readouterr().err
    want = ["case00", "case01", "other0", "other1", "case02"]
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert sorted(rows) == sorted(want)
    assert all(r["status"] == "complete" for r in rows.values())
    for cid in ("case00", "case01"):               # the earlier cases, as they were
        assert rows[cid]["CABLE.end_A_tension_max_N"] == before[cid][
            "CABLE.end_A_tension_max_N"]
    assert rows["case02"]["skipped"] == "0"        # its deck changed: run again
    assert (rows["case02"]["CABLE.end_A_tension_max_N"]
            != before["case02"]["CABLE.end_A_tension_max_N"])
    state = json.loads((out / "batch_cases.json").read_text())
    assert [c["id"] for c in state["cases"]] == want
    assert sorted(read_summary(out)["cases"]["id"]) == sorted(want)
    merged = read_summary(out)
    (out / "summary.csv").unlink()
    (out / "summary.h5").unlink()
    assert run_main(["summary", out]) == 0
    assert sorted(r["id"] for r in csv_rows(out / "summary.csv")) == sorted(want)
    assert_same_summary(read_summary(out), merged)


def _param_deck(tmp_path: Path) -> Path:
    deck = tmp_path / "param.inp"
    text = cable_deck(0.4, 0.658).replace("Z, 0.4, 0.658, 0.0", "Z, <AMP>, <FREQ>, 0.0")
    deck.write_text(text.replace("*HEADING", "*PARAMETER\nAMP = 0.4\nFREQ = 0.658\n"
                                             "*HEADING"))
    return deck


def test_two_case_tables_at_once_and_a_list_of_the_last_batch_only(tmp_path):
    """Two case tables of one deck run into one folder at once: both exit 0 and the
    summary lists the cases of both with the values of each table run alone. A folder
    whose batch_cases.json lists only the last batch's cases (as rodyn-batch wrote it
    when it kept only the last batch's list): `rodyn-batch summary OUT` and a further
    batch take the other case folders in again."""
    deck = _param_deck(tmp_path)
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    first.write_text("id,AMP\na1,0.1\na2,0.2\n")
    second.write_text("id,FREQ\nf1,0.5\nf2,0.8\nf3,0.7\n")
    common = ["-j", "2", "--rodyn", RODYN, "--no-progress"]
    out, alone = tmp_path / "out", tmp_path / "alone"
    env = dict(os.environ, PYTHONPATH=str(POSTPROC))
    procs = [subprocess.Popen([sys.executable, "-m", "rodyn_post.batch", str(deck),
                               "--cases", str(t), "-o", str(out), *common], env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for t in (first, second)]
    for proc in procs:
        _, err = proc.communicate(timeout=600)
        assert proc.returncode == 0, err
    ids = ["a1", "a2", "f1", "f2", "f3"]
    summary = read_summary(out)
    assert sorted(summary["cases"]["id"]) == ids
    assert list(summary["cases"]["status"]) == ["complete"] * 5
    assert sorted(summary["columns"][1:3]) == ["AMP", "FREQ"]
    row = {cid: k for k, cid in enumerate(summary["cases"]["id"])}
    for table, where in ((first, alone / "1"), (second, alone / "2")):
        assert run_main([deck, "--cases", table, "-o", where, *common]) == 0
        part = read_summary(where)
        for k, cid in enumerate(part["cases"]["id"]):
            for col in part["columns"]:
                if col not in TIMING_COLUMNS + ("skipped", "AMP", "FREQ"):
                    assert same_values(summary["cases"][col][row[cid]],
                                       part["cases"][col][k]), (cid, col)
    state = json.loads((out / "batch_cases.json").read_text())
    state["cases"] = [c for c in state["cases"] if c["id"].startswith("f")]
    (out / "batch_cases.json").write_text(json.dumps(state))
    (out / "summary.csv").unlink()
    assert run_main(["summary", out]) == 0
    rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
    assert sorted(rows) == ids and rows["a2"]["AMP"] == "0.2"
    assert all(r["status"] == "complete" for r in rows.values())
    assert sorted(c["id"] for c in json.loads((out / "batch_cases.json").read_text())
                  ["cases"]) == ids
    state["cases"] = state["cases"][:1]               # again, then one more batch
    (out / "batch_cases.json").write_text(json.dumps(state))
    more = tmp_path / "more.csv"
    more.write_text("id,AMP\nm1,0.3\n")
    assert run_main([deck, "--cases", more, "-o", out, *common]) == 0
    assert sorted(r["id"] for r in csv_rows(out / "summary.csv")) == sorted(ids + ["m1"])


def test_parameters_of_another_batch_stay_numbers(tmp_path):
    """Two case tables with different parameters into one folder: each parameter column
    of summary.h5 stays a float dataset, nan for the cases of the other table (empty in
    summary.csv), and `rodyn-batch plot --x` draws the cases that have the parameter."""
    deck = _param_deck(tmp_path)
    out = tmp_path / "out"
    common = ["-o", out, "-j", "2", "--rodyn", RODYN, "--no-progress"]
    for name, text in (("first.csv", "id,AMP\na1,0.1\na2,0.2\n"),
                       ("second.csv", "id,FREQ\nf1,0.8\nf2,0.5\n")):
        (tmp_path / name).write_text(text)
        assert run_main([deck, "--cases", tmp_path / name, *common]) == 0
    summary = read_summary(out)
    assert list(summary["cases"]["id"]) == ["a1", "a2", "f1", "f2"]
    assert same_values(summary["cases"]["AMP"], [0.1, 0.2, math.nan, math.nan])
    assert same_values(summary["cases"]["FREQ"], [math.nan, math.nan, 0.8, 0.5])
    assert [r["FREQ"] for r in csv_rows(out / "summary.csv")] == ["", "", "0.8", "0.5"]
    from rodyn_post.batch_plot import plot_column
    fig = plot_column(summary, "CABLE.end_A_tension_max_N", "FREQ")
    (line,) = fig.axes[0].lines
    assert list(line.get_xdata()) == [0.5, 0.8]
    np.testing.assert_array_equal(line.get_ydata(), summary["cases"][
        "CABLE.end_A_tension_max_N"][[3, 2]] / 1e3)
    assert "2 cases without FREQ left out" in fig._suptitle.get_text()
    assert run_main(["plot", out, "--y", "CABLE.end_A_tension_max_N", "--x", "AMP",
                     "-o", tmp_path / "amp.png"]) == 0


def test_second_batch_while_the_first_runs(tmp_path):
    """A batch into a folder where another batch is running: its summary lists the other
    batch's cases as running; the batch that ends last writes every case complete.
    The first batch's rodyn waits for a gate file, so no timing decides the order."""
    decks = write_decks(tmp_path / "decks", n=2)
    gate, started = tmp_path / "gate", tmp_path / "started"
    wrapper = tmp_path / "gated_rodyn"
    wrapper.write_text(f"#!/bin/sh\n[ \"$1\" = --help ] || {{ touch {started}; "
                       f"while [ ! -e {gate} ]; do sleep 0.05; done; }}\n"
                       f"exec {RODYN} \"$@\"\n")
    wrapper.chmod(0o755)
    out = tmp_path / "out"
    first = subprocess.Popen([sys.executable, "-m", "rodyn_post.batch", *map(str, decks),
                              "-o", str(out), "-j", "1", "--rodyn", str(wrapper),
                              "--no-progress"], env=dict(os.environ, PYTHONPATH=str(POSTPROC)),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 120          # a guard against a hang only
        while not started.exists() and first.poll() is None \
                and time.monotonic() < deadline:
            time.sleep(0.02)
        assert started.exists(), first.communicate()
        deck = _param_deck(tmp_path)
        (tmp_path / "b.csv").write_text("id,AMP\nb1,0.2\nb2,0.3\n")
        assert run_main([deck, "--cases", tmp_path / "b.csv", "-o", out, "--rodyn", RODYN,
                         "--no-progress"]) == 0
        rows = {r["id"]: r for r in csv_rows(out / "summary.csv")}
        assert sorted(rows) == ["b1", "b2", "case00", "case01"]
        assert [rows[i]["status"] for i in ("case00", "case01", "b1", "b2")] == \
            ["running"] * 2 + ["complete"] * 2
        assert "another batch" in rows["case00"]["message"]
    finally:
        gate.touch()
        _, err = first.communicate(timeout=300)
    assert first.returncode == 0, err
    rows = csv_rows(out / "summary.csv")
    assert sorted(r["id"] for r in rows) == ["b1", "b2", "case00", "case01"]
    assert all(r["status"] == "complete" for r in rows)
    state = json.loads((out / "batch_cases.json").read_text())
    assert sorted(c["id"] for c in state["cases"]) == ["b1", "b2", "case00", "case01"]
