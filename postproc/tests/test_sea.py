"""The sea and vessel tables (docs/output.md, "Waves and vessels"): rodyn_post.sea reads
the wave elevation at the probes, the vessel motion and the connection forces, at the
frames and every step, into load_dynamic(...).sea; a killed run's uncommitted tail
(beyond status.txt's committed_bytes) and a last time with missing rows are dropped with a
warning; a run without probes or vessels has sea None. The run is a short one of
RODYN_EXE (skipped without it): the paper's cable hung from a vessel moved by RAOs in a
regular wave, two probes."""
import shutil
import subprocess

import numpy as np
import pytest

from designed import REPO, rodyn_exe
from rodyn_post import load_dynamic
from rodyn_post.dynamic import COMMITTED_PREFIX
from rodyn_post.errors import RodynResultsError
from rodyn_post.sea import CONNECTIONS_STEP_CSV, VESSELS_CSV, WAVES_CSV, WAVES_STEP_CSV

DT, T_END = 0.05, 1.0

DECK = f"""*HEADING
Cable on a vessel in a regular wave, two probes
*GRAVITY
0.0, 0.0, -9.80665
*INCLUDE, INPUT=paper_cable_section.inc
*LINE, NAME=CABLE, SECTION=CABLE, LENGTH=10.0, ELEMENTS=10, ORDER=3
0.0, 0.0, 0.0, 8.0, 0.0, -1.0
*BOUNDARY, LINE=CABLE, END=A, TYPE=PINNED
*BOUNDARY, LINE=CABLE, END=B, TYPE=PINNED
*WATER, DEPTH=80.0, SURFACE=-20.0
*WAVE, HEIGHT=3.0, PERIOD=9.0, HEADING=120.0
*WAVE PROBE, NAME=P1
0.0, 0.0
*WAVE PROBE, NAME=P2
10.0, -5.0
*VESSEL, NAME=SHIP, TYPE=RAO, INPUT=rao.csv
-5.0, 2.0, 3.0, 30.0
*MOTION, LINE=CABLE, END=A, TYPE=VESSEL, VESSEL=SHIP, RAMP=0.5
*DYNAMIC, DT={DT}, TIME={T_END}, OUTPUT INTERVAL=0.25
*OUTPUT, CSV=YES, HDF5=YES
"""


@pytest.fixture(scope="module")
def sea_run(tmp_path_factory):
    exe = rodyn_exe()
    work = tmp_path_factory.mktemp("sea")
    shutil.copy(REPO / "input" / "paper_cable_section.inc", work)
    rows = []
    for period in (7.0, 9.0, 11.0):
        for head in (0.0, 90.0, 180.0, 270.0):
            rows.append([period, head] + [0.2 + 0.01 * period] * 6 + [head / 4 + period] * 6)
    (work / "rao.csv").write_text("".join(", ".join(map(repr, r)) + "\n" for r in rows))
    (work / "sea.inp").write_text(DECK)
    out = work / "out"
    run = subprocess.run([str(exe), str(work / "sea.inp"), "-o", str(out), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return out


def _csv(path):
    lines = path.read_text().splitlines()
    head = lines[0].split(",")
    return [dict(zip(head, line.split(","))) for line in lines[1:]]


def test_reads_every_table(sea_run):
    res = load_dynamic(sea_run)
    sea = res.sea
    assert set(sea.probes) == {"P1", "P2"}
    assert set(sea.vessels) == {"SHIP"}
    assert set(sea.connections) == {("SHIP", "CABLE", "A")}
    n_steps = round(T_END / DT)
    p2 = sea.probes["P2"]
    assert p2.columns == ("x_m", "y_m", "elevation_m")
    np.testing.assert_array_equal(p2.time, res.time)           # a row per frame
    np.testing.assert_array_equal(p2.step, np.arange(n_steps + 1))  # and per step
    rows = [r for r in _csv(sea_run / WAVES_STEP_CSV) if r["probe"] == "P2"]
    np.testing.assert_array_equal(p2.step_column("elevation_m"),
                                  [float(r["elevation_m"]) for r in rows])
    assert np.all(p2.step_column("x_m") == 10.0) and np.all(p2.frame_column("y_m") == -5.0)
    assert np.max(np.abs(p2.step_column("elevation_m"))) > 0.1
    ship = sea.vessels["SHIP"]
    rows = _csv(sea_run / VESSELS_CSV)
    np.testing.assert_array_equal(ship.frame_column("heading_rad"),
                                  [float(r["heading_rad"]) for r in rows])
    # the connection force is minus the support force of end A, every step
    conn = sea.connections[("SHIP", "CABLE", "A")]
    line = res.line("CABLE")
    np.testing.assert_array_equal(conn.step_time, res.step_time)
    np.testing.assert_array_equal(conn.steps[:, 0:6], -line.step_reactions[:, 0:6])
    np.testing.assert_array_equal(conn.step_column("tension_N"), line.step_end_tension[:, 0])
    assert not res.warnings


def test_without_sea_tables(sea_run, tmp_path):
    folder = tmp_path / "plain"
    shutil.copytree(sea_run, folder)
    for path in folder.glob("dynamic_*.csv"):
        if any(k in path.name for k in ("waves", "vessels", "connections")):
            path.unlink()
    (folder / "dynamic.h5").unlink()
    assert load_dynamic(folder).sea is None


def _commit_up_to(folder, name, n_rows):
    """status.txt commits the header and the first n_rows rows of table `name`."""
    data = (folder / name).read_bytes()
    size = len(b"".join(data.splitlines(keepends=True)[:1 + n_rows]))
    text = (folder / "status.txt").read_text().replace(
        f"{COMMITTED_PREFIX}{name} = {len(data)}", f"{COMMITTED_PREFIX}{name} = {size}")
    assert text != (folder / "status.txt").read_text()
    (folder / "status.txt").write_text(text)


def test_uncommitted_tail_and_cut_time(sea_run, tmp_path):
    folder = tmp_path / "killed"
    shutil.copytree(sea_run, folder)
    full = load_dynamic(sea_run).sea
    # the step table committed up to 5 steps and one probe of the 6th: the 6th dropped
    _commit_up_to(folder, WAVES_STEP_CSV, 2 * 5 + 1)
    res = load_dynamic(folder)
    p1 = res.sea.probes["P1"]
    assert len(p1.step) == 5
    np.testing.assert_array_equal(p1.steps, full.probes["P1"].steps[:5])
    assert any("beyond the committed size" in w for w in res.warnings)
    assert any("incomplete, dropped" in w for w in res.warnings)
    # the frames of the probes: committed whole
    assert len(p1.time) == len(full.probes["P1"].time)


def test_status_lists_the_tables(sea_run):
    text = (sea_run / "status.txt").read_text()
    for name in (WAVES_CSV, WAVES_STEP_CSV, VESSELS_CSV, CONNECTIONS_STEP_CSV):
        size = (sea_run / name).stat().st_size
        assert f"{COMMITTED_PREFIX}{name} = {size}" in text


def test_malformed_table(sea_run, tmp_path):
    folder = tmp_path / "bad"
    shutil.copytree(sea_run, folder)
    path = folder / CONNECTIONS_STEP_CSV
    lines = path.read_text().splitlines(keepends=True)
    fields = lines[3].split(",")
    fields[6] = "x"
    lines[3] = ",".join(fields)
    path.write_text("".join(lines))
    with pytest.raises(RodynResultsError, match="line 4: not a number"):
        load_dynamic(folder)


def test_hdf5_same_as_csv(sea_run, tmp_path):
    """A run's /dynamic/sea holds the values of the CSV tables, bit for bit; read from it
    when the CSV tables are absent (CSV=NO)."""
    folder = _h5_only(sea_run, tmp_path / "h5only")
    csv_sea = load_dynamic(sea_run).sea
    h5_sea = load_dynamic(folder).sea
    for kind in ("probes", "vessels", "connections"):
        a, b = getattr(csv_sea, kind), getattr(h5_sea, kind)
        assert set(a) == set(b)
        for key in a:
            assert a[key].columns == b[key].columns
            np.testing.assert_array_equal(a[key].frames, b[key].frames)
            np.testing.assert_array_equal(a[key].steps, b[key].steps)
            np.testing.assert_array_equal(a[key].time, b[key].time)
            np.testing.assert_array_equal(a[key].step_time, b[key].step_time)
            np.testing.assert_array_equal(a[key].step, b[key].step)


def _h5_only(sea_run, folder):
    """A copy of the run without its sea tables (read from dynamic.h5's /dynamic/sea)."""
    shutil.copytree(sea_run, folder)
    for path in folder.glob("dynamic_*.csv"):
        if any(k in path.name for k in ("waves", "vessels", "connections")):
            path.unlink()
    text = (folder / "status.txt").read_text()
    (folder / "status.txt").write_text("".join(
        line + "\n" for line in text.splitlines()
        if not any(k in line for k in ("_waves", "_vessels", "_connections"))))
    return folder


@pytest.mark.parametrize("change", ["two vessel names", "a connection column more"])
def test_hdf5_layout_is_the_files(sea_run, tmp_path, change):
    """/dynamic/sea is read by its own layout: the items its
    attributes name, each dataset's width split among them, and the columns that gives
    checked against the schema's tables. A file whose attributes name more vessels than
    its datasets hold, or whose connection rows have a column the schema has not, is
    refused naming the dataset (it was read with fixed widths, silently wrong)."""
    import h5py
    folder = _h5_only(sea_run, tmp_path / "h5only")
    with h5py.File(folder / "dynamic.h5", "r+") as f:
        g = f["dynamic/sea"]
        if change == "two vessel names":
            g.attrs["vessels"] = "SHIP, SHIP2"
            dataset = "vessel_motion"
        else:
            for name in ("connection_load", "step_connection_load"):
                old = g[name]
                values, attrs = old[...], dict(old.attrs)
                del g[name]
                new = g.create_dataset(name, data=np.column_stack(
                    [values, np.zeros(len(values))]))
                new.attrs.update(attrs)
            dataset = "connection_load"
    with pytest.raises(RodynResultsError, match=dataset):
        load_dynamic(folder)
