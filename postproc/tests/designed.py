"""Helpers of the post-processing tests: synthetic dynamic results with known values, and
the short rodyn run (RODYN_EXE) shared by the tests of range_graph, plot_history,
compare, animate, to_paraview and plot_all.

The synthetic run has two lines. RISER (7 nodes at S = 0, 1, ..., 6 m; integration
points at S = 0.5, 1.5, ..., 5.5 m; both ends held, end A on top) has quantities linear
in S, so that interpolating along the line is exact:

    tension(t, S)   = 1e4 + 2e3 S + 3e3 sin(w t) (1 - S/6)   [N]
    curvature(t, S) = 0.01 + 1e-3 S t                        [1/m]
    x(t, S) = 0.8 S + 0.1 sin(w t) (1 - S/6),  z(t, S) = -0.5 S + 0.2 sin(w t) (1 - S/6)
    end tension     = 1e4 + 3e3 sin(w t) at A,  2e4 + 1e3 cos(w t) at B

with w = 2 pi 1.25 rad/s (period 0.8 s), frames every 0.025 s from 0 to 2 s. The
second line, 'TAIL, 1/2', is random data (held at end A only).
"""
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from test_plot_dynamic import write_csv, write_h5, write_status
from test_plot_static import rodyn_exe  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
OMEGA = 2 * np.pi * 1.25
TIMES = np.round(np.arange(81) * 0.025, 12)
RISER_LENGTH = 6.0


def designed():
    """(lines, log) as test_plot_dynamic's writers take them."""
    t = TIMES[:, None]
    nf = len(TIMES)
    node_s = np.linspace(0.0, RISER_LENGTH, 7)
    gp_s = node_s[:-1] + 0.5
    wave = np.sin(OMEGA * t)
    rng = np.random.default_rng(5)
    riser = {
        "node_s": node_s, "gp_s": gp_s,
        "gp_element": np.arange(1, 7, dtype=np.int32), "gp_point": np.ones(6, np.int32),
        "x": 0.8 * node_s + 0.1 * wave * (1 - node_s / 6),
        "y": np.zeros((nf, 7)),
        "z": -0.5 * node_s + 0.2 * wave * (1 - node_s / 6),
        "effective_tension": 1e4 + 2e3 * gp_s + 3e3 * wave * (1 - gp_s / 6),
        "moment_1": 100.0 * gp_s * np.cos(OMEGA * t), "moment_2": 50.0 + 0.0 * t * gp_s,
        "torque": 0.0 * t * gp_s, "bending_curvature": 0.01 + 1e-3 * gp_s * t,
        "reactions": np.zeros((nf, 12)),
        "end_tension": np.column_stack([1e4 + 3e3 * wave[:, 0],
                                        2e4 + 1e3 * np.cos(OMEGA * TIMES)]),
        "end_held": np.array([1, 1], dtype=np.int32),
    }
    riser["reactions"][:, 2] = riser["end_tension"][:, 0]
    riser["reactions"][:, 8] = riser["end_tension"][:, 1]
    tail = {
        "node_s": np.linspace(0.0, 2.0, 3), "gp_s": np.array([0.5, 1.5]),
        "gp_element": np.array([1, 2], np.int32), "gp_point": np.ones(2, np.int32),
        "x": 5.0 + rng.normal(size=(nf, 3)), "y": rng.normal(size=(nf, 3)),
        "z": -1.0 + rng.normal(size=(nf, 3)),
        "effective_tension": rng.normal(size=(nf, 2)) * 1e3,
        "moment_1": rng.normal(size=(nf, 2)), "moment_2": rng.normal(size=(nf, 2)),
        "torque": rng.normal(size=(nf, 2)), "bending_curvature": rng.uniform(size=(nf, 2)),
        "reactions": np.zeros((nf, 12)), "end_tension": np.zeros((nf, 2)),
        "end_held": np.array([1, 0], dtype=np.int32),
    }
    tail["reactions"][:, 2] = 500.0
    tail["end_tension"][:, 0] = 500.0
    n_steps = 2 * (len(TIMES) - 1)
    ts = 0.0125 * np.arange(1, n_steps + 1)
    log = {
        "step": np.arange(1, n_steps + 1, dtype=np.int32), "time": ts,
        "dt": np.full(n_steps, 0.0125), "iterations": np.full(n_steps, 3, np.int32),
        "cutbacks": np.zeros(n_steps, np.int32), "kinetic": 1.0 + np.sin(ts),
        "strain": 2.0 + 0 * ts, "gravity": -3.0 + 0 * ts, "external_work": np.sin(ts),
        "damping_work": 0 * ts, "total": np.sin(ts),
        "momentum": np.column_stack([ts, 2 * ts, 0 * ts]),
        "angular_momentum": np.column_stack([0 * ts, ts ** 2, 0 * ts]),
    }
    return {"RISER": riser, "TAIL, 1/2": tail}, log


def write_designed(folder, h5=True, csv_tables=True):
    """The synthetic run in `folder`; returns (lines, log)."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    lines, log = designed()
    counters = dict(steps=len(log["step"]), step_iterations=int(log["iterations"].sum()),
                    step_cutbacks=0)
    if h5:
        write_h5(folder / "dynamic.h5", lines, log, counters=counters, times=TIMES)
    if csv_tables:
        write_csv(folder, lines, log, times=TIMES)
    write_status(folder, counters=counters, times=TIMES)
    return lines, log


def short_case2(folder):
    """Run 0.6 s of the paper's case 2 (40 steps, a frame every 0.03 s) into `folder`
    (static results too: START=STATIC); returns the folder. Skips without RODYN_EXE."""
    exe = rodyn_exe()
    folder = Path(folder)
    work = folder.parent
    text = (REPO / "input" / "paper_case2.inp").read_text()
    text, n = re.subn(r"TIME=15\.0, OUTPUT INTERVAL=0\.06", "TIME=0.6, OUTPUT INTERVAL=0.03",
                      text)
    assert n == 1
    shutil.copy(REPO / "input" / "paper_cable_section.inc", work)
    deck = work / "case2_short.inp"
    deck.write_text(text)
    run = subprocess.run([str(exe), str(deck), "-o", str(folder), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return folder
