"""The outputs of a run in water: the environment (environment.csv, /environment), wall
tension, seabed forces, touchdown, hydro and seabed work; the sea, seabed and current
drawn by rodyn-plot-static and rodyn-plot-dynamic; the new quantities of
rodyn-range-graph, rodyn-plot-history and rodyn-paraview; results of a dry run and of an
older rodyn."""
import csv
import math
import shutil

import h5py
import numpy as np
import pytest

from rodyn_post.commands import plot_dynamic, plot_history, plot_static, range_graph, to_paraview
from designed import write_designed
from rodyn_post import load_dynamic, load_environment, load_static
from rodyn_post.environment import (CURRENT_GID, SEABED_GID, SURFACE_GID, current_profile,
                                    seabed_trace)
from rodyn_post.results import RodynResultsError
from test_plot_static import write_csv, write_h5, write_status, synthetic_lines

SURFACE, DEPTH, SLOPE, SLOPE_DIR = 2.0, 40.0, 5.0, 0.0   # m, m, deg, deg
CURRENT = ((-38.0, 0.2, 0.0), (-10.0, 0.6, 30.0), (0.0, 1.0, 45.0))  # z, speed, heading


def environment_rows(seabed=True, current=CURRENT):
    """The rows of environment.csv as rodyn writes them (key, value, unit)."""
    rows = [("surface_z", SURFACE, "m"), ("depth", DEPTH, "m"), ("density", 1025.0, "kg/m3"),
            ("current_levels", float(len(current)), "-"), ("current_ramp", 5.0, "s")]
    for k, (z, speed, heading) in enumerate(current, 1):
        rows += [(f"current_z_{k}", z, "m"), (f"current_speed_{k}", speed, "m/s"),
                 (f"current_heading_{k}", heading, "deg")]
    rows.append(("seabed", 1.0 if seabed else 0.0, "-"))
    if seabed:
        rows += [("seabed_slope", SLOPE, "deg"), ("seabed_slope_dir", SLOPE_DIR, "deg"),
                 ("seabed_stiffness", 3e6, "N/m3"), ("seabed_damping", 3e5, "Pa s/m"),
                 ("seabed_mu_axial", 0.5, "-"), ("seabed_mu_lateral", 0.8, "-"),
                 ("seabed_v_mob", 0.01, "m/s")]
    return rows


def write_environment_csv(folder, **kw):
    with open(folder / "environment.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(("key", "value", "unit"))
        for key, value, unit in environment_rows(**kw):
            w.writerow((key, f"{value:.16E}", unit))


def write_environment_h5(path, **kw):
    """The /environment group as rodyn writes it into results.h5 / dynamic.h5."""
    rows = dict((k, (v, u)) for k, v, u in environment_rows(**kw))
    with h5py.File(path, "a") as f:
        g = f.create_group("environment")
        g.attrs["seabed"] = np.int32(rows["seabed"][0])
        for key, (value, unit) in rows.items():
            if key in ("seabed", "current_levels") or key[-1].isdigit():
                continue
            g[key] = value
            g[key].attrs["units"] = unit
        n = int(rows["current_levels"][0])
        for name in ("z", "speed", "heading"):
            g[f"current_{name}"] = [rows[f"current_{name}_{k}"][0] for k in range(1, n + 1)]


def wet_lines():
    """synthetic_lines() of test_plot_static with water results: line 1 lies on the
    seabed from S = 1 m (touchdown), line 2 is off the bottom."""
    lines = synthetic_lines()
    cable = lines["CABLE"]
    cable["wall_tension"] = cable["effective_tension"] + 5e3
    cable["seabed_normal"] = np.array([0.0, 0.0, 120.0, 250.0])
    cable["seabed_friction"] = np.array([0.0, 0.0, 60.0, 125.0])
    cable["touchdown_s"] = 4.0 / 3.0
    cable["node_xyz"][:, 1] = 0.0     # the lines lie in the plane y = 0
    lines["TAIL, 1/2"]["node_xyz"][:, 1] = 0.0
    return lines


def write_wet_static(folder, h5):
    """A static results folder of a run in water (results.h5 or the CSV tables)."""
    folder.mkdir(parents=True, exist_ok=True)
    lines = wet_lines()
    if h5:
        plain = {n: {k: v for k, v in a.items() if k != "touchdown_s"}
                 for n, a in lines.items()}
        write_h5(folder / "results.h5", plain)
        with h5py.File(folder / "results.h5", "a") as f:
            for name, a in lines.items():
                f["static"][name.replace("/", "_")].attrs["touchdown_s"] = \
                    a.get("touchdown_s", -1.0)
        write_environment_h5(folder / "results.h5")
    else:
        write_csv(folder, lines)
        write_environment_csv(folder)
    write_status(folder)
    return lines


def gid_lines(ax, gid):
    return [line for line in ax.lines if line.get_gid() == gid]


# --- the environment and its geometry -------------------------------------------------

def test_seabed_trace_and_current_profile(tmp_path):
    write_environment_csv(tmp_path)
    env = load_environment(tmp_path)
    assert env.surface_z == SURFACE and env.depth == DEPTH and env.seabed
    assert env.mudline_z == SURFACE - DEPTH
    np.testing.assert_array_equal(env.current_heading, [0.0, 30.0, 45.0])
    x, z = seabed_trace(env, (-10.0, 90.0), y=3.0)
    rise = math.tan(math.radians(SLOPE))
    np.testing.assert_allclose(z, SURFACE - DEPTH + rise * x, rtol=0, atol=1e-12)
    # a slope towards +y: level along x, at the depth of the plane y
    across = type(env)(**{**env.__dict__, "seabed_slope_dir": 90.0})
    x, z = seabed_trace(across, (0.0, 50.0), y=20.0)
    np.testing.assert_allclose(z, SURFACE - DEPTH + rise * 20.0, atol=1e-12)
    z, speed = current_profile(env)
    assert z[0] == env.mudline_z and z[-1] == SURFACE     # extended to bed and surface
    assert speed[0] == 0.2 and speed[-1] == 1.0
    assert env.current_at(-24.0) == pytest.approx(0.4)


def test_environment_from_h5_equals_csv(tmp_path):
    (tmp_path / "a").mkdir()
    write_environment_csv(tmp_path / "a")
    with h5py.File(tmp_path / "r.h5", "w"):
        pass
    write_environment_h5(tmp_path / "r.h5")
    a, b = load_environment(tmp_path / "a"), load_environment(tmp_path / "r.h5")
    for key in ("surface_z", "depth", "density", "seabed", "seabed_slope",
                "seabed_mu_lateral", "current_ramp"):
        assert getattr(a, key) == getattr(b, key), key
    for key in ("current_z", "current_speed", "current_heading"):
        np.testing.assert_array_equal(getattr(a, key), getattr(b, key))


@pytest.mark.parametrize("kind, key", [("h5", "seabed_slope"), ("h5", "current_heading"),
                                       ("csv", "seabed_slope"), ("csv", "current_heading_2")])
def test_environment_units_are_the_files(tmp_path, kind, key):
    """The environment is read in the units the file gives (each /environment dataset's
    `units` attribute, environment.csv's unit column), checked against the schema's
    (the schema): an angle the file says is in radians is refused, naming it,
    not read as degrees."""
    if kind == "h5":
        path = tmp_path / "r.h5"
        with h5py.File(path, "w"):
            pass
        write_environment_h5(path)
        with h5py.File(path, "a") as f:
            f["environment"][key].attrs["units"] = "deg"
        assert load_environment(path).seabed_slope == SLOPE      # as written: read
        with h5py.File(path, "a") as f:
            f["environment"][key].attrs["units"] = "rad"
    else:
        write_environment_csv(tmp_path)
        path = tmp_path
        assert load_environment(path).seabed_slope == SLOPE
        text = (tmp_path / "environment.csv").read_text()
        line = next(row for row in text.splitlines() if row.startswith(key + ","))
        assert line.endswith(",deg")
        (tmp_path / "environment.csv").write_text(text.replace(line, line[:-3] + "rad"))
    with pytest.raises(RodynResultsError, match=f"{key}.*'rad'"):
        load_environment(path)


def test_dry_folder_has_no_environment_and_bad_one_is_named(tmp_path):
    assert load_environment(tmp_path) is None
    (tmp_path / "environment.csv").write_text("key,value,unit\ndepth,deep,m\n")
    with pytest.raises(RodynResultsError, match="environment.csv: line 2"):
        load_environment(tmp_path)


# --- static ---------------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["h5", "csv"])
def test_static_water_results_read(tmp_path, kind):
    lines = write_wet_static(tmp_path / "run", h5=kind == "h5")
    res = load_static(tmp_path / "run")
    cable = res.line("CABLE")
    np.testing.assert_array_equal(cable.wall_tension, lines["CABLE"]["wall_tension"])
    np.testing.assert_array_equal(cable.seabed_normal, lines["CABLE"]["seabed_normal"])
    np.testing.assert_array_equal(cable.seabed_friction, lines["CABLE"]["seabed_friction"])
    assert cable.touchdown_s == lines["CABLE"]["touchdown_s"]
    tail = res.line("TAIL, 1/2")
    assert tail.touchdown_s == -1.0
    assert res.environment is not None and res.environment.depth == DEPTH


@pytest.mark.parametrize("kind", ["h5", "csv"])
def test_static_plots_draw_the_sea(tmp_path, kind):
    write_wet_static(tmp_path / "run", h5=kind == "h5")
    res = load_static(tmp_path / "run")
    fig = plot_static.shape_figure(res)
    ax = fig.axes[0]
    surface, = gid_lines(ax, SURFACE_GID)
    assert set(surface.get_ydata()) == {SURFACE}
    bed, = gid_lines(ax, SEABED_GID)
    x = np.asarray(bed.get_xdata())
    np.testing.assert_allclose(bed.get_ydata(),
                               SURFACE - DEPTH + math.tan(math.radians(SLOPE)) * x)
    xs = np.concatenate([line.node_xyz[:, 0] for line in res.lines])
    assert x.min() < xs.min() and x.max() > xs.max()   # spans the lines
    insets = [a for a in ax.child_axes if gid_lines(a, CURRENT_GID)]
    assert len(insets) == 1
    names = [name for name, _ in plot_static.figures(res)]
    assert names == [plot_static.SHAPE_PNG, plot_static.TENSION_PNG, plot_static.WALL_PNG,
                     plot_static.SEABED_PNG]
    s, wall, effective = plot_static.wall_curves(res.line("CABLE"))
    np.testing.assert_allclose(wall - effective, 5.0)      # kN
    s, normal, friction, touchdown = plot_static.seabed_curves(res.line("CABLE"))
    assert touchdown == pytest.approx(4.0 / 3.0) and normal[-1] == 0.25
    assert plot_static.main([str(tmp_path / "run"), "--dpi", "40"]) == 0
    for name in names:
        assert (tmp_path / "run" / name).stat().st_size > 1000


def test_static_dry_run_draws_no_sea(tmp_path):
    folder = tmp_path / "dry"
    folder.mkdir()
    lines = synthetic_lines()
    write_csv(folder, lines)
    write_status(folder)
    res = load_static(folder)
    assert res.environment is None
    np.testing.assert_array_equal(res.lines[0].wall_tension, res.lines[0].effective_tension)
    assert not np.any(res.lines[0].seabed_normal)
    ax = plot_static.shape_figure(res).axes[0]
    assert not gid_lines(ax, SURFACE_GID) and not gid_lines(ax, SEABED_GID)
    assert [n for n, _ in plot_static.figures(res)
            if n != plot_static.PLAN_PNG] == [plot_static.SHAPE_PNG, plot_static.TENSION_PNG]


def test_static_plan_only_when_the_lines_leave_their_plane(tmp_path):
    folder = tmp_path / "dry"
    folder.mkdir()
    write_csv(folder, synthetic_lines())
    write_status(folder)
    res = load_static(folder)
    flat = np.ptp(np.concatenate([line.node_xyz for line in res.lines])[:, 1])
    assert plot_static.wants_plan(res) == (flat > 0.0)
    for line in res.lines:
        line.node_xyz[:, 1] = 0.0
    assert not plot_static.wants_plan(res)
    line = res.lines[0]
    line.node_xyz[:, 1] = np.linspace(0.0, 2.0, len(line.node_xyz))
    assert plot_static.wants_plan(res)
    assert [n for n, _ in plot_static.figures(res)][:2] == [plot_static.SHAPE_PNG,
                                                            plot_static.PLAN_PNG]
    ax = plot_static.plan_figure(res).axes[0]
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), line.node_xyz[:, 1])


def test_static_csv_of_an_older_rodyn_still_reads(tmp_path):
    """Tables without wall_tension_N and the seabed columns: dry defaults."""
    folder = tmp_path / "old"
    folder.mkdir()
    write_csv(folder, synthetic_lines())
    write_status(folder)
    for name, drop in (("static_nodes.csv", (6, 7)), ("static_elements.csv", (5,))):
        rows = list(csv.reader(open(folder / name)))
        rows = [[v for i, v in enumerate(r) if i not in drop] for r in rows]
        with open(folder / name, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)
    res = load_static(folder)
    line = res.lines[0]
    np.testing.assert_array_equal(line.wall_tension, line.effective_tension)
    assert line.seabed_normal.shape == line.node_s.shape and line.touchdown_s == -1.0


# --- dynamic --------------------------------------------------------------------------

def add_dynamic_water(folder):
    """Water results in the designed run's dynamic.h5 and CSV tables: wall tension =
    effective + 2 kN, seabed force on the last riser node, touchdown, hydro work."""
    with h5py.File(folder / "dynamic.h5", "a") as f:
        g = f["dynamic/RISER"]
        nf, nn = g["x"].shape
        g["wall_tension"] = g["effective_tension"][...] + 2e3
        normal = np.zeros((nf, nn))
        normal[:, -1] = 300.0
        g["seabed_normal"] = normal
        g["seabed_friction"] = 0.5 * normal
        g["touchdown_s"] = np.full(nf, 5.0)
        log = f["dynamic/log"]
        ns = len(log["time"])
        log["hydro_work"] = -0.1 * log["time"][...]
        log["seabed_work"] = np.zeros(ns)
        # keep the balance: the total changes by the hydro work
        log["total"][...] = log["total"][...] - 0.1 * log["time"][...]
    write_environment_h5(folder / "dynamic.h5")
    write_environment_csv(folder)


def test_dynamic_water_results_and_plots(designed_run, tmp_path):
    folder, lines, log = designed_run
    (folder / "dynamic_nodes.csv").unlink()           # read dynamic.h5
    add_dynamic_water(folder)
    res = load_dynamic(folder)
    riser = res.line("RISER")
    np.testing.assert_allclose(riser.wall_tension - riser.effective_tension, 2e3)
    assert riser.seabed_normal[0, -1] == 300.0 and np.all(riser.touchdown_s == 5.0)
    tail = res.line("TAIL, 1/2")
    np.testing.assert_array_equal(tail.wall_tension, tail.effective_tension)
    assert np.all(tail.touchdown_s == -1.0)
    np.testing.assert_allclose(res.log.net_work,
                               log["external_work"] - 0.1 * log["time"] - log["damping_work"])
    assert plot_dynamic.work_label(res.log) == "external work + hydro work"
    fig = plot_dynamic.snapshots_figure(res, [0, 10, 20], plot_dynamic.envelope_frames(res))
    ax = fig.axes[0]
    assert len(gid_lines(ax, SURFACE_GID)) == 1 and len(gid_lines(ax, SEABED_GID)) == 1
    assert any(gid_lines(a, CURRENT_GID) for a in ax.child_axes)
    assert plot_dynamic.main([str(folder), "--dpi", "40"]) == 0
    # range graph and histories of the new quantities
    assert range_graph.main([str(folder), "--quantity", "wall_tension", "seabed_normal",
                             "-o", str(tmp_path / "rg")]) == 0
    with open(tmp_path / "rg" / "range_graph.csv") as f:
        header = next(csv.reader(f))
    assert "wall_tension_max_N" in header and "seabed_normal_max_N_per_m" in header
    assert plot_history.main([str(folder), "--at", "B", "--quantity", "wall_tension",
                              "seabed_normal", "-o", str(tmp_path / "hist")]) == 0
    with open(tmp_path / "hist" / "history_RISER.csv") as f:
        rows = list(csv.DictReader(f))
    assert float(rows[0]["seabed_normal_B_N_per_m"]) == 300.0
    # ParaView point data
    assert to_paraview.main([str(folder), "-o", str(tmp_path / "pv")]) == 0
    text = (tmp_path / "pv" / "dynamic_000000.vtp").read_text()
    assert 'Name="wall_tension_N"' in text and 'Name="seabed_normal_N_per_m"' in text


def test_dynamic_csv_reads_touchdown_and_environment(tmp_path):
    folder = tmp_path / "wet"
    lines, log = write_designed(folder, h5=False)
    write_environment_csv(folder, seabed=False)
    with open(folder / "dynamic_lines.csv", "w") as f:
        f.write("time_s,line,touchdown_s_m\n")
        for t in np.unique(np.round(np.arange(81) * 0.025, 12)):
            f.write(f"{t:.16E},RISER,{3.5:.16E}\n")
            f.write(f'{t:.16E},"TAIL, 1/2",{-1.0:.16E}\n')
    res = load_dynamic(folder)
    assert np.all(res.line("RISER").touchdown_s == 3.5)
    assert res.environment is not None and not res.environment.seabed
    ax = plot_dynamic.snapshots_figure(res, [0]).axes[0]
    assert len(gid_lines(ax, SURFACE_GID)) == 1 and not gid_lines(ax, SEABED_GID)


def test_real_dry_run_has_no_environment(short_run, tmp_path):
    """rodyn on a dry deck: no environment.csv, wall = effective, seabed zeros, and the
    plots work as before."""
    folder = tmp_path / "run"
    shutil.copytree(short_run, folder)
    assert not (folder / "environment.csv").exists()
    for res in (load_static(folder), load_dynamic(folder)):
        assert res.environment is None
        line = res.lines[0]
        np.testing.assert_array_equal(line.wall_tension, line.effective_tension)
        assert not np.any(line.seabed_normal)
    lines_csv = list(csv.DictReader(open(folder / "static_lines.csv")))
    assert float(lines_csv[0]["touchdown_s_m"]) == -1.0
    assert "hydro_work_J" in open(folder / "dynamic_log.csv").readline()
    assert plot_static.main([str(folder), "--dpi", "40"]) == 0
