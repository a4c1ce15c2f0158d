"""Tests of the modes reader (rodyn_post.modes.load_modes), static_modes.png of
rodyn-plot-static and the mode files of rodyn-paraview, on a small deck with *MODAL run
by RODYN_EXE (skipped without it): a subsea buoy (a FREE point) between a cable tether
and a rod riser, so that the shapes have line translations, rod rotations and a point's
motion.

    RODYN_EXE=build/rodyn python3 -m pytest postproc/tests/test_modes.py -q
"""
import csv
import shutil
import subprocess
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

from rodyn_post import RodynResultsError, load_modes
from rodyn_post.commands import plot_static, to_paraview
from test_plot_static import assert_png, rodyn_exe, write_results

N_MODES = 8
DECK = f"""*HEADING
Tethered buoy: natural periods
*WATER, DEPTH=100.0, DENSITY=1025.0
*SEABED, STIFFNESS=3.0e6, DAMPING=3.0e5
*SECTION, NAME=CHAIN, OD=0.1, CDN=1.2, CDA=0.05, CAN=1.0, CAA=0.0
6.0e8, 0.0, 0.0, 0.0, 60.0
*SECTION, NAME=PIPE, OD=0.1, CDN=1.2, CDA=0.05, CAN=1.0, CAA=0.0
6.0e8, 2.0e4, 2.0e4, 1.5e4, 60.0
*POINT, NAME=ANCHOR, TYPE=FIXED
0.0, 0.0, -100.0
*POINT, NAME=BUOY, TYPE=FREE, MASS=2000.0, VOLUME=20.0, CDA=4.0, CA=0.5
35.0, 0.0, -52.0
*POINT, NAME=FAIRLEAD, TYPE=FIXED
300.0, 0.0, -10.0
*LINE, NAME=TETHER, SECTION=CHAIN, LENGTH=60.0, ELEMENTS=6, ORDER=2, ELEMENT=CABLE, POINT A=ANCHOR, POINT B=BUOY
*LINE, NAME=RISER, SECTION=PIPE, LENGTH=300.0, ELEMENTS=16, ORDER=2, ELEMENT=ROD, POINT A=BUOY, POINT B=FAIRLEAD
*STATIC, INCREMENTS=20
*MODAL, MODES={N_MODES}
*OUTPUT, CSV=YES, HDF5=YES
"""
COMPONENTS = ("x", "y", "z", "rx", "ry", "rz")


@pytest.fixture(scope="module")
def modal_run(tmp_path_factory):
    """Folder of the deck above run by RODYN_EXE, once per module; tests copy it before
    writing into it."""
    exe = rodyn_exe()
    work = tmp_path_factory.mktemp("modal")
    (work / "buoy.inp").write_text(DECK)
    out = work / "buoy"
    run = subprocess.run([str(exe), str(work / "buoy.inp"), "-o", str(out), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return out


@pytest.fixture
def run_copy(modal_run, tmp_path):
    folder = tmp_path / "buoy"
    shutil.copytree(modal_run, folder)
    return folder


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def shapes_by_object(folder):
    """{object: (nm, n, 6) array of x..rz} of static_mode_shapes.csv, read on its own."""
    out = {}
    for row in csv_rows(folder / "static_mode_shapes.csv"):
        out.setdefault(row["object"], []).append([float(row[c]) for c in COMPONENTS])
    return {name: np.array(rows).reshape(N_MODES, -1, 6) for name, rows in out.items()}


def assert_same_modes(a, b):
    """Every number of two ModalResults equal (bit for bit)."""
    for key in ("period_s", "frequency_hz"):
        np.testing.assert_array_equal(getattr(a, key), getattr(b, key), err_msg=key)
    assert [line.name for line in a.lines] == [line.name for line in b.lines]
    for la, lb in zip(a.lines, b.lines):
        for key in ("node_s", "node_xyz", "translation", "rotation"):
            np.testing.assert_array_equal(getattr(la, key), getattr(lb, key),
                                          err_msg=f"{la.name} {key}")


# --- the reader ---------------------------------------------------------------------

def test_reader_against_the_csv_tables(modal_run):
    modes = load_modes(modal_run)
    assert modes.source.name == "results.h5"
    assert modes.n_modes == N_MODES and modes.solver in ("DENSE", "LANCZOS")
    assert np.isfinite(modes.tangent_asymmetry)
    table = csv_rows(modal_run / "static_modes.csv")
    assert [int(r["mode"]) for r in table] == list(range(1, N_MODES + 1))
    np.testing.assert_array_equal(modes.period_s, [float(r["period_s"]) for r in table])
    np.testing.assert_array_equal(modes.frequency_hz,
                                  [float(r["frequency_hz"]) for r in table])
    assert modes.dominant == tuple(r["dominant"] for r in table)
    assert set(modes.dominant) <= {"TETHER", "RISER", "BUOY"}
    np.testing.assert_array_equal(modes.share, [float(r["share"]) for r in table])
    assert np.all(np.diff(modes.period_s) <= 0.0)  # longest first

    shapes = shapes_by_object(modal_run)
    assert list(shapes) == ["TETHER", "RISER", "BUOY"]
    nodes = csv_rows(modal_run / "static_nodes.csv")
    for line in modes.lines:
        expected = shapes[line.name]
        assert line.translation.shape == expected[..., :3].shape
        np.testing.assert_array_equal(line.translation, expected[..., :3], err_msg=line.name)
        np.testing.assert_array_equal(line.rotation, expected[..., 3:], err_msg=line.name)
        xyz = [[float(r[c]) for c in ("x_m", "y_m", "z_m")] for r in nodes
               if r["line"] == line.name]
        np.testing.assert_array_equal(line.node_xyz, xyz)
        np.testing.assert_array_equal(line.displaced(2, 3.0),
                                      line.node_xyz + 3.0 * expected[1, :, :3])
    assert not np.any(modes.line("TETHER").rotation)   # a cable: no rotations
    assert np.any(modes.line("RISER").rotation)        # a rod's
    buoy = modes.object("BUOY")
    np.testing.assert_array_equal(buoy.translation, shapes["BUOY"][:, 0, :3])
    # the line ends on the buoy move with it
    np.testing.assert_array_equal(modes.line("TETHER").translation[:, -1], buoy.translation)
    np.testing.assert_array_equal(modes.line("RISER").translation[:, 0], buoy.translation)
    # scaled so that the largest translation of the system (its largest entry) is 1 m
    largest = np.max([np.max(np.abs(line.translation), axis=(1, 2))
                      for line in modes.lines], axis=0)
    np.testing.assert_allclose(largest, 1.0, rtol=1e-12)


def test_reader_reads_the_h5_datasets(modal_run):
    modes = load_modes(modal_run / "results.h5")
    with h5py.File(modal_run / "results.h5", "r") as f:
        np.testing.assert_array_equal(modes.period_s, f["modes/period_s"][...])
        for line in modes.lines:
            for c, key in enumerate(("ux", "uy", "uz")):
                np.testing.assert_array_equal(line.translation[..., c],
                                              f[f"modes/{line.name}/{key}"][...])
            for c, key in enumerate(("rx", "ry", "rz")):
                np.testing.assert_array_equal(line.rotation[..., c],
                                              f[f"modes/{line.name}/{key}"][...])


def test_csv_only_reads_the_same(run_copy):
    from_h5 = load_modes(run_copy)
    (run_copy / "results.h5").unlink()
    from_csv = load_modes(run_copy)
    assert from_csv.source.name == "static_mode_shapes.csv"
    assert_same_modes(from_h5, from_csv)
    assert from_csv.dominant == from_h5.dominant and from_csv.solver == ""
    np.testing.assert_array_equal(from_csv.object("BUOY").translation,
                                  from_h5.object("BUOY").translation)


def test_h5_without_the_csv_tables(run_copy):
    full = load_modes(run_copy)
    for name in ("static_modes.csv", "static_mode_shapes.csv"):
        (run_copy / name).unlink()
    modes = load_modes(run_copy)
    assert_same_modes(full, modes)
    assert modes.dominant == ("",) * N_MODES and np.all(np.isnan(modes.share))
    assert modes.objects == ()


def test_no_modes(tmp_path, run_copy):
    write_results(tmp_path / "synthetic")
    assert load_modes(tmp_path / "synthetic") is None
    with h5py.File(run_copy / "results.h5", "a") as f:
        del f["modes"]
    assert load_modes(run_copy) is None   # results.h5 without /modes


def test_bad_files(run_copy):
    path = run_copy / "static_modes.csv"
    text = path.read_text()
    path.write_text(text.replace("period_s", "periods", 1))
    with pytest.raises(RodynResultsError, match="static_modes.csv: line 1: header"):
        load_modes(run_copy)
    path.write_text(text)
    shapes = run_copy / "static_mode_shapes.csv"
    shapes.write_text("".join(shapes.read_text().splitlines(keepends=True)[:-1]))
    with pytest.raises(RodynResultsError, match="'BUOY': 7 rows, expected 8 modes x 1"):
        load_modes(run_copy)
    with h5py.File(run_copy / "results.h5", "a") as f:
        f["modes/RISER/uy"].attrs["units"] = "mm"
    with pytest.raises(RodynResultsError, match="/modes/RISER/uy is in 'mm'"):
        load_modes(run_copy)


# --- static_modes.png ---------------------------------------------------------------

def test_static_modes_png(run_copy, capsys):
    assert plot_static.main([str(run_copy), "--dpi", "60"]) == 0
    assert str(run_copy / "static_modes.png") in capsys.readouterr().out.split()
    assert_png(run_copy / "static_modes.png")

    modes = load_modes(run_copy)
    scale = plot_static.mode_scale(modes)
    assert scale == pytest.approx(0.1 * 300.0, rel=0.01)   # the riser spans 300 m in x
    fig = plot_static.modes_figure(plot_static.load_static(run_copy), modes)
    panels = [ax for ax in fig.axes if ax.get_visible()]
    assert len(panels) == 6
    # the buoy's modes across the x-z plane are drawn in x-y, those in it in x-z
    assert {ax.get_ylabel() for ax in panels} == {"y [m]", "z [m]"}
    for k, ax in enumerate(panels, 1):
        assert ax.get_title().startswith(f"mode {k}: T = {modes.period_s[k - 1]:.4g} s, "
                                         f"{modes.dominant[k - 1]} (")
        i, j = plot_static.mode_axes(modes, k)
        moved = np.concatenate([line.translation[k - 1] for line in modes.lines])
        assert np.argmax(np.sum(moved ** 2, axis=0)) in (i, j) and 0 in (i, j)  # x: 300 m
        assert ax.get_xlabel() == f"{'xyz'[i]} [m]" and ax.get_ylabel() == f"{'xyz'[j]} [m]"
        moved = [c for c in ax.lines if c.get_gid() == f"mode {k}"]
        still = [c for c in ax.lines if c.get_gid() == "static"]
        assert len(moved) == len(still) == 2
        for line, curve, grey in zip(modes.lines, moved, still):
            np.testing.assert_array_equal(
                curve.get_xydata(), line.displaced(k, scale)[:, [i, j]])
            np.testing.assert_array_equal(grey.get_xydata(), line.node_xyz[:, [i, j]])


def test_mode_axes():
    """The plane of a mode: the two axes it moves along most; with one, it and the axis
    the static line extends along most (the line is not drawn edge on)."""
    from rodyn_post.modes import LineModes, ModalResults
    s = np.linspace(0.0, 10.0, 5)
    xyz = np.column_stack([s, 0.0 * s, -0.2 * s])   # along x, sloping down in z
    u = np.zeros((4, 5, 3))
    u[0, :, 1] = np.sin(s)                          # across: y only
    u[1, :, 2] = np.sin(s)                          # z only
    u[2, :, 0], u[2, :, 1] = 1.0, 0.3               # x and y
    u[3, :, 0], u[3, :, 1], u[3, :, 2] = 1e-3, 0.5, 1.0   # z and y; x below 1 %
    line = LineModes("L", s, xyz, u, np.zeros_like(u))
    modes = ModalResults(np.ones(4), np.ones(4), ("",) * 4, np.full(4, np.nan), (line,),
                         (), "", float("nan"), None, None)
    assert [plot_static.mode_axes(modes, k) for k in (1, 2, 3, 4)] == [
        (0, 1), (0, 2), (0, 1), (1, 2)]
    assert plot_static.mode_scale(modes) == pytest.approx(1.0)   # 10 % of 10 m
    assert plot_static.mode_title(modes, 1) == "mode 1: T = 1 s"


def test_no_modes_png_without_modes(tmp_path, capsys):
    write_results(tmp_path / "synthetic")
    assert plot_static.main([str(tmp_path / "synthetic"), "--dpi", "60"]) == 0
    assert "static_modes.png" not in capsys.readouterr().out
    assert not (tmp_path / "synthetic" / "static_modes.png").exists()


# --- ParaView -----------------------------------------------------------------------

def read_mode_vtp(path):
    """(points (n, 3), {point data name: array (n,) or (n, c)}, TimeValue, active
    scalars and vectors)."""
    root = ET.parse(path).getroot()
    piece = root.find("PolyData/Piece")
    points = np.array(piece.find("Points/DataArray").text.split(), float).reshape(-1, 3)
    assert int(piece.get("NumberOfPoints")) == len(points)
    data = {}
    for array in piece.findall("PointData/DataArray"):
        values = np.array(array.text.split(), float)
        components = int(array.get("NumberOfComponents", "1"))
        data[array.get("Name")] = values.reshape(-1, components) if components > 1 else values
    time = float(root.find("PolyData/FieldData/DataArray").text)
    point_data = piece.find("PointData")
    return points, data, time, (point_data.get("Scalars"), point_data.get("Vectors"))


def test_paraview_mode_files(run_copy, capsys):
    assert to_paraview.main([str(run_copy)]) == 0
    out = run_copy / "paraview"
    assert capsys.readouterr().out.split() == [str(out / "static.vtp"),
                                               str(out / "modes.pvd")]
    root = ET.parse(out / "modes.pvd").getroot()
    entries = [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]
    assert entries == [(k, f"mode_{k:03d}.vtp") for k in range(1, N_MODES + 1)]

    with h5py.File(run_copy / "results.h5", "r") as f:
        names = list(f["static"])
        static_xyz = np.vstack([f[f"static/{n}/node_xyz"][...] for n in names])
        node_s = np.concatenate([f[f"static/{n}/node_s"][...] for n in names])
        shape = {key: np.hstack([f[f"modes/{n}/{key}"][...] for n in names])
                 for key in ("ux", "uy", "uz", "rx", "ry", "rz")}
    assert len(static_xyz) == 2 * 6 + 1 + 2 * 16 + 1
    for k in (1, 4, N_MODES):
        points, data, time, active = read_mode_vtp(out / f"mode_{k:03d}.vtp")
        assert time == k and active == ("displacement_magnitude", "displacement")
        assert points.shape == (len(static_xyz), 3)
        np.testing.assert_array_equal(points, static_xyz)
        displacement = np.column_stack([shape[c][k - 1] for c in ("ux", "uy", "uz")])
        rotation = np.column_stack([shape[c][k - 1] for c in ("rx", "ry", "rz")])
        np.testing.assert_array_equal(data["displacement"], displacement)
        np.testing.assert_array_equal(data["rotation"], rotation)
        np.testing.assert_array_equal(data["displacement_magnitude"],
                                      np.linalg.norm(displacement, axis=1))
        np.testing.assert_array_equal(data["s_m"], node_s)
