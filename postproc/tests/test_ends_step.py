"""The support forces of every step: read from dynamic.h5 and from
dynamic_ends_step.csv alike, and used by the batch extraction for the ends' extremes,
so that they do not depend on the frame interval. A run of the paper's case 1 for 8 s
with a frame every 0.5 s (3 frames a period of the 0.658 Hz motion) by RODYN_EXE."""
import csv
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from designed import REPO, rodyn_exe
from rodyn_post.batch_extract import extract_case
from rodyn_post.dynamic import ENDS_STEP_CSV, H5_FILE, load_dynamic


@pytest.fixture(scope="module")
def coarse_run(tmp_path_factory):
    exe = rodyn_exe()
    work = tmp_path_factory.mktemp("ends_step")
    text = (REPO / "input" / "paper_case1.inp").read_text()
    text, n = re.subn(r"TIME=900\.0, OUTPUT INTERVAL=0\.1", "TIME=8.0, OUTPUT INTERVAL=0.5",
                      text)
    assert n == 1
    shutil.copy(REPO / "input" / "paper_cable_section.inc", work)
    deck = work / "case1_coarse.inp"
    deck.write_text(text)
    folder = work / "case1_coarse"
    run = subprocess.run([str(exe), str(deck), "-o", str(folder), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return folder


def _csv_top(folder):
    with open(folder / ENDS_STEP_CSV, newline="") as f:
        return [float(r["tension_N"]) for r in csv.DictReader(f) if r["end"] == "A"]


def test_h5_and_csv_give_the_same_step_series(coarse_run, tmp_path):
    h5 = load_dynamic(coarse_run)
    assert h5.source.name == H5_FILE
    csv_only = tmp_path / "csv"
    shutil.copytree(coarse_run, csv_only)
    (csv_only / H5_FILE).unlink()
    from_csv = load_dynamic(csv_only)
    assert len(h5.step_time) == len(h5.log) + 1 == 81
    assert np.array_equal(h5.step_time, from_csv.step_time)
    for a, b in zip(h5.lines, from_csv.lines):
        assert np.array_equal(a.step_reactions, b.step_reactions)
        assert np.array_equal(a.step_end_tension, b.step_end_tension)
    assert np.array_equal(h5.lines[0].step_end_tension[:, 0], _csv_top(coarse_run))


def test_killed_csv_drops_the_last_incomplete_step(coarse_run, tmp_path):
    folder = tmp_path / "killed"
    shutil.copytree(coarse_run, folder)
    (folder / H5_FILE).unlink()
    path = folder / ENDS_STEP_CSV
    rows = path.read_text().splitlines(keepends=True)
    path.write_text("".join(rows[:-1]))            # end B of the last step is missing
    results = load_dynamic(folder)
    assert len(results.step_time) == 80
    assert any("incomplete" in w for w in results.warnings)


def test_batch_extremes_of_the_ends_come_from_every_step(coarse_run):
    scalars = extract_case(coarse_run)["scalars"]
    top = _csv_top(coarse_run)
    assert scalars["CABLE.end_A_tension_max_N"] == max(top)
    assert scalars["CABLE.end_A_tension_min_N"] == min(top)
    frames = load_dynamic(coarse_run).lines[0].end_tension[:, 0]
    assert frames.max() < 0.99 * max(top)   # the frames alone miss the maximum
