"""A run killed inside a sync (docs/output.md "What is on disk, and when"):
status.txt records what was committed (`frames`, `steps`, `committed_bytes.NAME` of each
CSV table); the data files may hold an uncommitted tail beyond it. rodyn_post reads
exactly the committed frames and steps, from dynamic.h5 and from the CSV tables alike,
and says that it ignored a tail. The state is made from a finished run of RODYN_EXE
(short_run) by rolling its status.txt and dynamic.h5 back to an earlier sync, which is
what a kill between the data files' writes and status.txt's rename leaves."""
import shutil

import numpy as np

from rodyn_post import load_dynamic
from rodyn_post.dynamic import COMMITTED_PREFIX, H5_FILE, LOG_CSV

TABLES = ("dynamic_nodes.csv", "dynamic_elements.csv", "dynamic_ends.csv",
          "dynamic_lines.csv", "dynamic_log.csv", "dynamic_ends_step.csv")


def _bytes_up_to(path, time, column):
    """Bytes of a CSV table up to its last row with column `column` <= time."""
    data = path.read_bytes()
    end = data.index(b"\n") + 1            # the header
    for line in data[end:].splitlines(keepends=True):
        if float(line.split(b",")[column]) > time:
            break
        end += len(line)
    return end


def _roll_back(folder, k):
    """Make `folder` (a finished run) look killed inside the sync after frame k: its
    status.txt committed at frame k (k + 1 frames), the data files whole (the tail)."""
    import h5py
    full = load_dynamic(folder)
    t = float(full.time[k])
    steps = int(np.count_nonzero(full.log.time <= t))
    status = {}
    for line in (folder / "status.txt").read_text().splitlines():
        key, _, value = line.partition(" = ")
        status[key] = value
    nodes = (folder / "dynamic_nodes.csv").read_text().splitlines()[1:]
    reached = next(r.split(",")[0] for r in nodes if float(r.split(",")[0]) == t)
    status.update(complete="false", status="running", steps=str(steps), frames=str(k + 1),
                  time_reached_s=reached)
    for name in TABLES:
        column = 1 if name in (LOG_CSV, "dynamic_ends_step.csv") else 0
        status[COMMITTED_PREFIX + name] = str(_bytes_up_to(folder / name, t, column))
    (folder / "status.txt").write_text("".join(f"{a} = {b}\n" for a, b in status.items()))
    with h5py.File(folder / H5_FILE, "r+") as f:
        f.attrs["complete"] = 0
        f.attrs["status"] = "running"
        for key in list(f["dynamic"].attrs):
            if key in ("steps", "step_iterations", "step_cutbacks", "time_reached_s",
                       "wall_time_s", "step_tangents", "frames"):
                del f["dynamic"].attrs[key]
    return full, steps


def test_uncommitted_tail_ignored(short_run, tmp_path):
    folder = tmp_path / "killed"
    shutil.copytree(short_run, folder)
    k = 7
    full, steps = _roll_back(folder, k)
    assert len(full.time) > k + 2 and steps < len(full.log)
    csv_only = tmp_path / "killed_csv"
    shutil.copytree(folder, csv_only, ignore=shutil.ignore_patterns(H5_FILE))
    for res in (load_dynamic(folder), load_dynamic(csv_only)):
        assert res.source.name == (H5_FILE if res.folder == folder else "dynamic_nodes.csv")
        assert not res.complete and res.status == "running"
        np.testing.assert_array_equal(res.time, full.time[:k + 1])
        assert len(res.log) == steps
        np.testing.assert_array_equal(res.log.total, full.log.total[:steps])
        for a, b in zip(res.lines, full.lines):
            np.testing.assert_array_equal(a.x, b.x[:k + 1])
            np.testing.assert_array_equal(a.effective_tension, b.effective_tension[:k + 1])
            np.testing.assert_array_equal(a.reactions, b.reactions[:k + 1])
            np.testing.assert_array_equal(a.touchdown_s, b.touchdown_s[:k + 1])
            n = len(a.step_end_tension)
            assert 0 < n < len(b.step_end_tension)
            np.testing.assert_array_equal(a.step_end_tension, b.step_end_tension[:n])
        assert len(res.step_time) == len(res.lines[0].step_end_tension)
        assert res.step_time[-1] <= full.log.time[steps - 1]
        assert any("uncommitted tail" in w for w in res.warnings), res.warnings


def test_file_shorter_than_committed_read_with_a_warning(short_run, tmp_path):
    folder = tmp_path / "short"
    shutil.copytree(short_run, folder)
    (folder / H5_FILE).unlink()
    whole = load_dynamic(folder)
    size = (folder / "dynamic_nodes.csv").stat().st_size
    text = (folder / "status.txt").read_text()
    key = COMMITTED_PREFIX + "dynamic_nodes.csv"
    assert f"{key} = {size}\n" in text  # a finished run committed every table whole
    (folder / "status.txt").write_text(text.replace(f"{key} = {size}", f"{key} = {size + 1}"))
    res = load_dynamic(folder)
    np.testing.assert_array_equal(res.time, whole.time)
    assert any("shorter than" in w for w in res.warnings), res.warnings


def test_finished_run_commits_everything(short_run):
    status = dict(line.split(" = ", 1) for line in
                  (short_run / "status.txt").read_text().splitlines())
    res = load_dynamic(short_run)
    assert int(status["frames"]) == len(res.time)
    for name in TABLES:
        assert int(status[COMMITTED_PREFIX + name]) == (short_run / name).stat().st_size
    assert not any("uncommitted" in w for w in res.warnings)
