"""Tests of rodyn-animate, rodyn-paraview and rodyn-plot-all (rodyn_post.commands): the
files are written, the GIF has the frames chosen, the ParaView files hold the node
positions and the section results interpolated to the nodes, plot_all runs every
script that applies; on the synthetic run of designed.py and, with RODYN_EXE, on 0.6 s
of the paper's case 2.
"""
import shutil
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from matplotlib.animation import FFMpegWriter
from PIL import Image

from rodyn_post.commands import animate, plot_all, to_paraview
from designed import TIMES
from rodyn_post import load_dynamic, load_static


# --- animation ----------------------------------------------------------------------

def test_animation_frames(designed_run):
    folder, _, _ = designed_run
    res = load_dynamic(folder)
    assert animate.animation_frames(res) == list(range(81))
    assert animate.animation_frames(res, every=10) == [0, 10, 20, 30, 40, 50, 60, 70, 80]
    assert animate.animation_frames(res, every=7)[-2:] == [77, 80]  # the last one added
    frames = animate.animation_frames(res, max_frames=10)
    assert len(frames) <= 10 and frames[0] == 0 and frames[-1] == 80
    assert np.all(np.diff(frames)[:-1] == frames[1] - frames[0])  # evenly spaced
    assert animate.animation_frames(res, (0.5, 0.6)) == [20, 21, 22, 23, 24]
    # fixed axes holding every line at every frame shown
    (x0, x1), (z0, z1) = animate.axis_limits(res, frames)
    for line in res.lines:
        assert x0 < line.x[frames].min() and line.x[frames].max() < x1
        assert z0 < line.z[frames].min() and line.z[frames].max() < z1


def test_gif_written_mp4_skipped_without_ffmpeg(designed_run, tmp_path, capsys,
                                                monkeypatch):
    folder, _, _ = designed_run
    monkeypatch.setenv("PATH", str(tmp_path))  # no ffmpeg on the PATH
    assert not FFMpegWriter.isAvailable()
    out = tmp_path / "anim"
    assert animate.main([str(folder), "-o", str(out), "--every", "8", "--dpi", "40",
                         "--fps", "5"]) == 0
    captured = capsys.readouterr()
    assert captured.out.split() == [str(out / "dynamic_animation.gif")]
    assert captured.err.strip() == ("animate: note: ffmpeg is not on the PATH: no MP4 "
                                    "written")
    assert not (out / "dynamic_animation.mp4").exists()
    with Image.open(out / "dynamic_animation.gif") as gif:
        assert gif.n_frames == 11  # frames 0, 8, ..., 80
        assert gif.info["duration"] == 200 and gif.info["loop"] == 0
        assert gif.size == (round(7.2 * 40), round(4.8 * 40))
        first = np.asarray(gif.convert("RGB"))
        gif.seek(5)
        middle = np.asarray(gif.convert("RGB"))
    assert np.any(first != middle)  # the line moves
    assert animate.main([str(folder), "-o", str(out), "--no-mp4", "--max-frames", "3",
                         "--dpi", "30"]) == 0
    assert capsys.readouterr().err == ""
    with Image.open(out / "dynamic_animation.gif") as gif:
        assert gif.n_frames == 3


def test_mp4_frames_go_to_ffmpeg(designed_run, tmp_path, capsys, monkeypatch):
    """With an 'ffmpeg' on the PATH the frames are piped to it: a stand-in that stores
    its input receives every frame as raw RGBA (the MP4 path without a real ffmpeg)."""
    folder, _, _ = designed_run
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake = bin_dir / "ffmpeg"
    fake.write_text('#!/bin/sh\nfor last; do :; done\ncat > "$last"\n')
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", f"{bin_dir}:/usr/bin:/bin")
    out = tmp_path / "anim"
    assert animate.main([str(folder), "-o", str(out), "--every", "20", "--dpi", "30"]) == 0
    assert capsys.readouterr().out.split() == [str(out / "dynamic_animation.gif"),
                                               str(out / "dynamic_animation.mp4")]
    width, height = round(7.2 * 30), round(4.8 * 30)
    raw = np.fromfile(out / "dynamic_animation.mp4", dtype=np.uint8)
    assert raw.size == 5 * width * height * 4  # frames 0, 20, 40, 60, 80
    frames = raw.reshape(5, height, width, 4)
    assert np.any(frames[0] != frames[1])  # the moving line is drawn in every frame


@pytest.mark.skipif(not FFMpegWriter.isAvailable(), reason="ffmpeg not on the PATH")
def test_mp4_with_ffmpeg(designed_run, tmp_path, capsys):
    folder, _, _ = designed_run
    assert animate.main([str(folder), "-o", str(tmp_path), "--every", "20",
                         "--dpi", "40"]) == 0
    assert (tmp_path / "dynamic_animation.mp4").stat().st_size > 1000


# --- ParaView -----------------------------------------------------------------------

def read_vtp(path):
    """{'time': float or None, 'points': (n, 3), 'offsets': [...], name: array}."""
    root = ET.parse(path).getroot()
    assert root.get("type") == "PolyData"
    piece = root.find("PolyData/Piece")
    out = {"time": None}
    field = root.find("PolyData/FieldData/DataArray")
    if field is not None:
        out["time"] = float(field.text)
    out["points"] = np.array(piece.find("Points/DataArray").text.split(),
                             float).reshape(-1, 3)
    assert int(piece.get("NumberOfPoints")) == len(out["points"])
    for array in piece.findall("Lines/DataArray") + piece.findall("CellData/DataArray"):
        out[array.get("Name")] = [int(v) for v in array.text.split()]
    assert piece.find("PointData").get("Scalars") == "effective_tension_N"
    for array in piece.findall("PointData/DataArray"):
        out[array.get("Name")] = np.array(array.text.split(), float)
    return out


def test_paraview_files(designed_run, tmp_path, capsys):
    folder, lines, _ = designed_run
    assert to_paraview.main([str(folder), "--every", "20"]) == 0
    out = folder / "paraview"
    assert capsys.readouterr().out.split() == [str(out / "dynamic.pvd")]  # no static
    root = ET.parse(out / "dynamic.pvd").getroot()
    entries = [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]
    assert entries == [(TIMES[f], f"dynamic_{f:06d}.vtp") for f in (0, 20, 40, 60, 80)]
    for f in (0, 40, 80):
        vtp = read_vtp(out / f"dynamic_{f:06d}.vtp")
        assert vtp["time"] == TIMES[f]
        sizes = [len(a["node_s"]) for a in lines.values()]
        assert vtp["offsets"] == list(np.cumsum(sizes))
        assert vtp["connectivity"] == list(range(sum(sizes)))
        assert vtp["line_index"] == [0, 1]
        xyz = np.vstack([np.column_stack([a["x"][f], a["y"][f], a["z"][f]])
                         for a in lines.values()])
        np.testing.assert_array_equal(vtp["points"], xyz)
        # section results at the nodes: linear in S between the integration points,
        # the outermost point's value beyond them (numpy.interp does the same)
        for key, name in (("effective_tension", "effective_tension_N"),
                          ("bending_curvature", "bending_curvature_per_m")):
            expected = np.concatenate([np.interp(a["node_s"], a["gp_s"], a[key][f])
                                       for a in lines.values()])
            np.testing.assert_allclose(vtp[name], expected, rtol=1e-14, atol=1e-300)
        a = lines["RISER"]
        np.testing.assert_allclose(vtp["effective_tension_N"][1:6], 1e4 + 2e3 * a["node_s"][
            1:6] + 3e3 * np.sin(2 * np.pi * 1.25 * TIMES[f]) * (1 - a["node_s"][1:6] / 6),
            rtol=1e-13)
        np.testing.assert_array_equal(vtp["s_m"], np.concatenate(
            [a["node_s"] for a in lines.values()]))


def test_paraview_window_static_and_errors(designed_run, tmp_path, capsys):
    from test_plot_static import write_results
    folder = tmp_path / "static_only"
    static_lines = write_results(folder)
    assert to_paraview.main([str(folder), "-o", str(tmp_path / "pv")]) == 0
    assert capsys.readouterr().out.split() == [str(tmp_path / "pv" / "static.vtp")]
    vtp = read_vtp(tmp_path / "pv" / "static.vtp")
    assert vtp["time"] is None
    a = static_lines["CABLE"]
    moment = np.hypot(a["moment"][:, 0], a["moment"][:, 1])
    np.testing.assert_allclose(vtp["bending_moment_Nm"][:4],
                               np.interp(a["node_s"], a["gp_s"], moment), rtol=1e-14)
    designed, _, _ = designed_run
    assert to_paraview.main([str(designed), "-o", str(tmp_path / "w"), "--window", "1",
                             "1.1"]) == 0
    capsys.readouterr()
    root = ET.parse(tmp_path / "w" / "dynamic.pvd").getroot()
    assert [d.get("file") for d in root.iter("DataSet")] == [
        f"dynamic_{f:06d}.vtp" for f in (40, 41, 42, 43, 44)]
    assert to_paraview.main([str(tmp_path / "nowhere")]) == 1
    assert "nowhere: no such results folder" in capsys.readouterr().err
    (tmp_path / "empty").mkdir()
    assert to_paraview.main([str(tmp_path / "empty")]) == 1
    assert "no rodyn results here" in capsys.readouterr().err


# --- plot_all -----------------------------------------------------------------------

def test_plot_all_commands(designed_run, tmp_path, capsys):
    """Static results only: the static plots; dynamic results: which scripts run with
    which arguments (they are run for real in test_real_run_all)."""
    from test_plot_static import write_results
    folder = tmp_path / "paper_cable"
    write_results(folder)
    assert plot_all.main([str(folder), "--dpi", "30"]) == 0
    assert capsys.readouterr().out.split() == [str(folder / "static_shape.png"),
                                               str(folder / "static_plan.png"),
                                               str(folder / "static_tension.png")]
    designed, _, _ = designed_run
    args = plot_all.parse_args([str(designed), "-o", "out", "--window", "0.5", "1",
                                "--paraview"])
    todo = plot_all.commands(args, {"dynamic"}, ["RISER", "TAIL, 1/2"])
    window = ["--window", "0.5", "1.0"]
    assert [(m.__name__.split(".")[-1], argv) for m, argv in todo] == [
        ("plot_dynamic", [str(designed), "-o", "out"] + window),
        ("range_graph", [str(designed), "-o", "out"] + window),
        ("plot_history", [str(designed), "-o", "out"] + window + ["--line", "RISER"]),
        ("plot_history", [str(designed), "-o", "out"] + window + ["--line", "TAIL, 1/2"]),
        ("to_paraview", [str(designed), "-o", "out/paraview"] + window)]
    assert plot_all.main([str(tmp_path / "nowhere")]) == 1
    assert "no such results folder" in capsys.readouterr().err
    (tmp_path / "empty").mkdir()
    assert plot_all.main([str(tmp_path / "empty")]) == 1
    assert "no rodyn results here" in capsys.readouterr().err


def test_real_run_all(short_run, tmp_path, capsys):
    """plot_all on 0.6 s of case 2: static and dynamic plots, the animation and the
    ParaView files; the last .vtp holds the last frame of dynamic.h5."""
    folder = tmp_path / "run"
    shutil.copytree(short_run, folder)
    assert plot_all.main([str(folder), "--dpi", "40", "--animate", "--paraview"]) == 0
    written = capsys.readouterr().out.split()
    for name in ("static_shape.png", "static_tension.png", "dynamic_snapshots.png",
                 "dynamic_momentum.png", "range_graph.csv", "history_CABLE.csv",
                 "dynamic_animation.gif", "paraview/static.vtp", "paraview/dynamic.pvd"):
        assert str(folder / name) in written, name
        assert (folder / name).stat().st_size > 100
    res = load_dynamic(folder)
    with Image.open(folder / "dynamic_animation.gif") as gif:
        assert gif.n_frames == len(res.time) == 21
    last = read_vtp(folder / "paraview" / "dynamic_000020.vtp")
    cable = res.line("CABLE")
    np.testing.assert_array_equal(last["points"], cable.xyz(20))
    assert last["time"] == res.time[20]
    static = read_vtp(folder / "paraview" / "static.vtp")
    np.testing.assert_array_equal(static["points"], load_static(folder).line("CABLE").node_xyz)


def test_hdf5_only_run_plots_as_csv_run(short_run, tmp_path, capsys):
    """A run with *OUTPUT, CSV=NO (results.h5, dynamic.h5 and status.txt only) is
    plotted by plot_all and converted by to_paraview as the same run with CSV tables:
    the same files, the same CSV tables of the plots and the same ParaView files."""
    h5_only = tmp_path / "h5_only"
    shutil.copytree(short_run, h5_only, ignore=shutil.ignore_patterns("*.csv"))
    assert not list(h5_only.glob("*.csv"))
    both = tmp_path / "both"
    shutil.copytree(short_run, both)
    for folder in (both, h5_only):
        assert plot_all.main([str(folder), "--dpi", "30", "--paraview"]) == 0, \
            capsys.readouterr().err
    made = {p.relative_to(both) for p in both.rglob("*")
            if not (short_run / p.relative_to(both)).exists()}
    made_h5 = {p.relative_to(h5_only) for p in h5_only.rglob("*")
               if not (short_run / p.relative_to(h5_only)).exists()}
    assert made == made_h5 and any(p.suffix == ".png" for p in made)
    for rel in made:
        if rel.suffix in (".csv", ".vtp", ".pvd"):
            assert (both / rel).read_bytes() == (h5_only / rel).read_bytes(), rel
    assert read_vtp(h5_only / "paraview" / "static.vtp")["points"].shape[0] > 2
