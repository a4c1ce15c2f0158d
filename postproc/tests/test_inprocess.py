"""rodyn in process (package rodyn over librodyn; docs/python.md), on MoorDyn's
OC3-Hywind lines (tests/decks/good/moordyn/lines.txt): counts, the coupled points where
the file has them, the statics' forces kept by 10 steps at rest, the node arrays, and
errors raised, never a crash."""
import math
import os

import numpy as np
import pytest

import rodyn
import rodyn.moordyn as md

LINES = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "decks", "good",
                     "moordyn", "lines.txt")


def test_system_at_rest():
    with rodyn.System(LINES) as s:
        assert (s.n_coupled, s.n_lines, s.n_points) == (9, 3, 6)
        x = s.coupled_positions()
        assert np.allclose(x[:3], [5.2, 0.0, -70.0], atol=0, rtol=0)
        s.init()
        f0 = s.step(x, np.zeros(9), 0.0)
        assert s.t == 0.0
        for _ in range(10):
            f = s.step(x, np.zeros(9), 0.5)
        assert s.t == pytest.approx(5.0, abs=1e-12)
        # the statics are the dynamics' rest
        assert np.max(np.abs(f - f0)) <= 1e-8 * np.max(np.abs(f0))
        # the lines pull the fairleads down and towards their anchors
        assert f0[0] > 0.0 and f0[2] < 0.0
        xyz = s.line_nodes(1)
        assert xyz.shape == (21, 3)
        assert np.allclose(xyz[-1], x[:3], atol=1e-9)
        ten = s.line_tensions(1)
        assert ten.shape == (21, 3) and np.linalg.norm(ten[-1]) > np.linalg.norm(ten[0])


def test_errors_raised():
    with pytest.raises(rodyn.RodynError):
        rodyn.System("no_such_file.txt")
    with rodyn.System(LINES) as s:
        with pytest.raises(rodyn.RodynError):   # a step before init
            s.step(np.zeros(9), np.zeros(9), 0.5)
        with pytest.raises(rodyn.RodynError):
            s.line_nodes(4)


def test_moordyn_names():
    h = md.Create(LINES)
    assert md.NCoupledDOF(h) == 9 and md.GetNumberLines(h) == 3
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    assert md.Init(h, x, [0.0] * 9) == 0
    f = md.Step(h, x, [0.0] * 9, 0.0, 0.5)
    assert len(f) == 9
    fh, fv, ah, av = md.GetFASTtens(h, 3)
    # a catenary at rest with no current: the same horizontal tension at both ends; the
    # anchor's vertical tension far below the fairlead's (the chain lies on the seabed)
    assert abs(fh[0] - ah[0]) <= 1e-6 * fh[0] and fv[0] > 100.0 * av[0]
    assert md.GetLineNumberNodes(md.GetLine(h, 1)) == 21
    # at rest the nodes do not move; a catenary's tension is largest at its fairlead
    assert max(abs(c) for c in md.GetLineNodeVel(md.GetLine(h, 1), 10)) < 1e-9
    assert md.GetLineMaxTen(md.GetLine(h, 1)) == md.GetLineFairTen(md.GetLine(h, 1))
    assert md.GetPointType(md.GetPoint(h, 1)) == 1 and md.GetPointType(md.GetPoint(h, 4)) == -1
    assert md.Close(h) == 0
    assert md.Create("no_such_file.txt") is None


def test_out_file(tmp_path):
    """FILE.out as MoorDyn writes it: names, units, a row at t = 0 and after each step,
    each value the one librodyn's getters give (to the 8 digits written)."""
    with open(LINES) as f:
        text = f.read()
    i = text.index("------------------------- need this line")
    path = tmp_path / "lines_out.txt"
    path.write_text(text[:i] + "---------------------- OUTPUTS ----\nFairTen1 AnchTen1\n"
                    "L2N10T L1N10PX\nP4FX P4PZ\n" + text[i:])
    h = md.Create(str(path))
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    assert md.Init(h, x, [0.0] * 9) == 0
    for k in range(3):
        x[0] += 0.05
        f = md.Step(h, x, [0.1] + [0.0] * 8, 0.5 * k, 0.5)
    fair = md.GetLineFairTen(md.GetLine(h, 1))
    t2 = np.linalg.norm(md.GetLineNodeTen(md.GetLine(h, 2), 10))
    px = md.GetLineNodePos(md.GetLine(h, 1), 10)[0]
    assert md.Close(h) == 0
    lines = (tmp_path / "lines_out.out").read_text().splitlines()
    assert lines[0].split() == ["Time", "FairTen1", "AnchTen1", "L2N10T", "L1N10PX", "P4FX",
                                "P4PZ"]
    assert lines[1].split() == ["(s)", "N", "N", "N", "m", "N", "m"]
    assert len(lines[0]) == 10 + 6 * 20
    rows = np.array([[float(v) for v in ln.split()] for ln in lines[2:]])
    assert rows.shape == (4, 7)
    assert np.allclose(rows[:, 0], [0.0, 0.5, 1.0, 1.5], atol=0)
    for got, want in zip(rows[-1, 1:], [fair, None, t2, px, f[0], -70.0 + 0.0]):
        if want is not None:
            assert abs(got - want) <= 1e-7 * abs(want)
    bad = tmp_path / "bad_out.txt"
    bad.write_text(path.read_text().replace("P4FX P4PZ", "P4FX B1PX"))
    assert md.Create(str(bad)) is None


def test_compare_reads_moordyn_out(tmp_path):
    """rodyn-compare's reference reader takes a MoorDyn .out table as it is: the units of
    its units row, and none without one."""
    from rodyn_post.reference import ReferenceTable
    out = tmp_path / "case.out"
    out.write_text("      Time            FairTen1                L1N3PZ\n"
                   "       (s)                   N                     m\n"
                   "    0.0000       9.0076599e+05      -6.9000000e+01\n"
                   "    0.5000       9.0100000e+05      -6.8500000e+01\n")
    t = ReferenceTable(out)
    assert t.header == ["Time [s]", "FairTen1 [N]", "L1N3PZ [m]"]
    assert list(t.column("FairTen1", "force").values) == [900765.99, 901000.0]
    assert list(t.column("1", "time", increasing=True).values) == [0.0, 0.5]
    bare = tmp_path / "bare.out"
    bare.write_text("Time FairTen1\n0.0 1.0e5\n0.5 1.1e5\n")
    assert ReferenceTable(bare).column("FairTen1", "force").unit is None


def test_bad_input_never_crashes_the_host():
    """Every bad MoorDyn file of tests/decks/bad/moordyn/ gives NULL from MoorDyn_Create
    in this one process, and every function given a NULL handle MOORDYN_INVALID_VALUE
    (-6): the host goes on."""
    import ctypes
    import glob
    from rodyn._lib import lib
    bad = sorted(glob.glob(os.path.join(os.path.dirname(LINES), "..", "..", "bad", "moordyn",
                                        "*.txt")))
    assert len(bad) >= 20
    for path in bad:
        assert md.Create(path) is None, path
    L = lib()
    n, d, v3 = ctypes.c_uint(0), ctypes.c_double(0.0), (ctypes.c_double * 3)()
    assert L.MoorDyn_NCoupledDOF(None, ctypes.byref(n)) == -6
    assert L.MoorDyn_Init(None, None, None) == -6
    assert L.MoorDyn_Step(None, None, None, None, ctypes.byref(d), ctypes.byref(d)) == -6
    assert L.MoorDyn_Close(None) == -6
    assert L.MoorDyn_GetLine(None, 1) is None and L.MoorDyn_GetPoint(None, 1) is None
    assert L.MoorDyn_GetLineNodePos(None, 0, v3) == -6
    assert L.MoorDyn_GetLineNodeTen(None, 0, v3) == -6
    assert L.MoorDyn_GetPointPos(None, v3) == -6
    h = md.Create(LINES)
    line = md.GetLine(h, 1)
    assert L.MoorDyn_GetLineNodePos(line, 0, v3) == -6      # before Init
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    assert md.Init(h, x, [0.0] * 9) == 0
    assert md.Init(h, x, [0.0] * 9) == -6                   # twice
    assert L.MoorDyn_GetLineNodePos(line, 21, v3) == -6     # past the last node
    assert L.MoorDyn_GetLineNodePos(line, 20, v3) == 0
    assert md.Close(h) == 0


def test_api_statics_are_the_programs(tmp_path):
    """MoorDyn_Init's static state is `rodyn FILE`'s, node for node and bit for bit (the
    same file read the same way; the API's deck adds only its *DYNAMIC)."""
    import csv
    import subprocess
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    subprocess.run([exe, LINES, "-o", str(tmp_path / "prog"), "--quiet"], check=True)
    with open(tmp_path / "prog" / "static_nodes.csv") as f:
        rows = list(csv.DictReader(f))
    with rodyn.System(LINES) as s:
        s.init()
        for line in (1, 2, 3):
            mine = s.line_nodes(line)
            prog = np.array([[float(r[k]) for k in ("x_m", "y_m", "z_m")] for r in rows
                             if r["line"] == f"L{line}"])
            assert prog.shape == mine.shape and np.array_equal(prog, mine), line


def lines_on_body(text):
    """The OC3-Hywind lines file with its three fairleads as points of a coupled body
    (reference point at the fairleads' height, -70 m)."""
    return text.replace(
        "4     Vessel    5.2     0.0     -70.0", "4     Body1     5.2     0.0     0.0  ").replace(
        "5     Vessel    -2.6    4.5     -70.0", "5     Body1     -2.6    4.5     0.0  ").replace(
        "6     Vessel    -2.6    -4.5    -70.0", "6     Body1     -2.6    -4.5    0.0  ").replace(
        "---------------------- POINT PROPERTIES",
        "---------------------- BODIES ----\nID Att X0 Y0 Z0 r0 p0 y0 M CG I V CdA Ca\n"
        "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kgm2) (m3) (m2) (-)\n"
        "1 Coupled 0 0 -70 0 0 0 0 0 0 0 0 0\n---------------------- POINT PROPERTIES")


def test_coupled_body_is_its_points(tmp_path):
    """A coupled body (6 DOFs: MoorDyn's pose, orientation Rx(r) Ry(p) Rz(y)) carrying the
    OC3-Hywind fairleads as Body1 points gives, after 12 steps of a surge, sway, heave,
    roll, pitch and yaw motion, the force and moment about its reference point that the
    same fairleads as coupled points, moved to the body's pose at every step end, give
    summed: to 1e-7 (measured 5.2e-9; the Newton tolerance is 1e-8)."""
    text = open(LINES).read()
    body = lines_on_body(text)
    (tmp_path / "body.txt").write_text(body)
    hb, hp = md.Create(str(tmp_path / "body.txt")), md.Create(LINES)
    assert (md.NCoupledDOF(hb), md.NCoupledDOF(hp)) == (6, 9)

    def rot(a):
        c, s = np.cos(a), np.sin(a)
        rx = np.array([[1, 0, 0], [0, c[0], -s[0]], [0, s[0], c[0]]])
        ry = np.array([[c[1], 0, s[1]], [0, 1, 0], [-s[1], 0, c[1]]])
        rz = np.array([[c[2], -s[2], 0], [s[2], c[2], 0], [0, 0, 1]])
        return rx @ ry @ rz

    p = np.array([[5.2, 0, 0], [-2.6, 4.5, 0], [-2.6, -4.5, 0]])
    r0 = np.array([0.0, 0.0, -70.0])
    assert md.Init(hb, list(r0) + [0.0] * 3, [0.0] * 6) == 0
    assert md.Init(hp, list((r0 + p).ravel()), [0.0] * 9) == 0
    dt, amp, ang = 0.5, np.array([2.0, 1.0, 0.5]), np.array([0.05, 0.03, 0.1])

    def pose(t):
        return r0 + amp * np.sin(0.3 * t), ang * np.sin(0.3 * t)

    for k in range(12):
        (r, a), (r1, a1) = pose(k * dt), pose((k + 1) * dt)
        fb = md.Step(hb, list(r) + list(a), list((r1 - r) / dt) + list((a1 - a) / dt),
                     k * dt, dt)
        q0, q1 = r + (rot(a) @ p.T).T, r1 + (rot(a1) @ p.T).T
        fp = np.array(md.Step(hp, list(q0.ravel()), list(((q1 - q0) / dt).ravel()),
                              k * dt, dt)).reshape(3, 3)
    want = np.concatenate([fp.sum(0), sum(np.cross(q1[i] - r1, fp[i]) for i in range(3))])
    assert np.max(np.abs(np.array(fb) - want)) <= 1e-7 * np.max(np.abs(want[:3]))
    # the body's state is the pose the host gave, back in MoorDyn's angles
    assert md.GetNumberBodies(hb) == 1 and md.GetBody(hb, 2) is None
    r, _ = md.GetBodyState(md.GetBody(hb, 1))
    assert np.max(np.abs(np.array(r) - np.concatenate([r1, a1]))) <= 1e-12
    assert md.Close(hb) == 0 and md.Close(hp) == 0


def test_free_body_state(tmp_path):
    """MoorDyn_GetBodyState of a FREE body after MoorDyn_Init: its reference point where
    `rodyn FILE`'s statics put it (static_bodies.csv), bit for bit, and its pitch the
    rotation the statics give it (a turn about y alone: MoorDyn's p is the rotation
    vector's y), at rest."""
    import csv
    import subprocess
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    src = os.path.join(os.path.dirname(LINES), "..", "..", "..", "program", "moordyn_buoy.txt")
    buoy = str(tmp_path / "moordyn_buoy.txt")    # (librodyn writes its .out beside it)
    with open(src) as f, open(buoy, "w") as g:
        g.write(f.read())
    subprocess.run([exe, buoy, "-o", str(tmp_path / "buoy"), "--quiet"], check=True)
    with open(tmp_path / "buoy" / "static_bodies.csv") as f:
        row = next(csv.DictReader(f))
    h = md.Create(buoy)
    assert md.Init(h, [], []) == 0
    r, rd = md.GetBodyState(md.GetBody(h, 1))
    assert list(r[:3]) == [float(row[k]) for k in ("x_m", "y_m", "z_m")]
    rot = [float(row[k]) for k in ("rx_rad", "ry_rad", "rz_rad")]
    assert rot[0] == rot[2] == 0.0 and abs(rot[1]) > 0.01       # the buoy pitches
    assert abs(r[4] - rot[1]) <= 1e-12 and abs(r[3]) + abs(r[5]) == 0.0
    assert max(abs(v) for v in rd) == 0.0
    b = md.GetBody(h, 1)
    assert md.GetBodyType(b) == 0                                 # free
    assert md.GetBodyPos(b) == r[:3] and md.GetBodyAngle(b) == r[3:]
    assert md.GetBodyVel(b) == rd[:3] and md.GetBodyAngVel(b) == rd[3:]
    assert md.Close(h) == 0


def test_break_line():
    """MoorDyn_BreakLine: line 1 leaves its fairlead (point 4) at the next step. The
    fairlead then carries nothing (its only line gone), the other fairleads keep their
    static forces (each line on its own point), the freed end sinks, and a second break of
    the same end, a line not on the point, or a break before Init are refused (MoorDyn
    makes a free point of no mass at the freed end; here the end is simply free)."""
    h = md.Create(LINES)
    p4, l1, l2 = md.GetPoint(h, 4), md.GetLine(h, 1), md.GetLine(h, 2)
    with pytest.raises(RuntimeError):          # before Init
        md.BreakLine(h, p4, l1)
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    assert md.Init(h, x, [0.0] * 9) == 0
    f0 = np.array(md.Step(h, x, [0.0] * 9, 0.0, 0.5))
    with pytest.raises(RuntimeError):          # line 2 is not on point 4
        md.BreakLine(h, p4, l2)
    md.BreakLine(h, p4, l1)
    z = []
    t = 0.5
    for _ in range(6):
        f = np.array(md.Step(h, x, [0.0] * 9, t, 0.5))
        t += 0.5
        assert np.all(f[0:3] == 0.0)
        # (to Newton's tolerance: one Newton solve holds all lines, and the falling line
        # takes it more iterations)
        assert np.max(np.abs(f[3:] - f0[3:])) <= 1e-7 * np.max(np.abs(f0))
        z.append(md.GetLineNodePos(l1, 20)[2])
    # the freed end falls, faster and faster at first
    assert z[0] < x[2] and z[1] - z[0] < z[0] - x[2] < 0.0
    assert np.all(np.diff(z) < 0.0)
    with pytest.raises(RuntimeError):          # already off the point
        md.BreakLine(h, p4, l1)
    assert md.Close(h) == 0


def test_points_lines_and_settings():
    """The line ends on a point in MoorDyn's order, a coupled point's velocity the host's,
    a line's EA the file's, the time scheme and CFL noted but not used, and MoorDyn_SetDt:
    host steps of 0.5 s in rodyn steps of at most 0.1 s give the forces of host steps of
    0.1 s (the same steps)."""
    h = md.Create(LINES)
    p1, p4, l1 = md.GetPoint(h, 1), md.GetPoint(h, 4), md.GetLine(h, 1)
    assert md.GetPointNAttached(p4) == 1 and md.GetPointNAttached(p1) == 1
    assert md.GetPointAttached(p4, 0) == (l1, 1) and md.GetPointAttached(p1, 0) == (l1, 0)
    with pytest.raises(RuntimeError):
        md.GetPointAttached(p4, 1)
    assert md.IsLineConstantEA(l1) and md.GetLineConstantEA(l1) == 384.243e6
    assert md.GetTimeScheme(h) == "EMC"
    assert md.SetTimeScheme(h, "RK4") == 0 and md.SetTimeScheme(h, "aca10") == 0
    assert md.SetTimeScheme(h, "RK5") == -6 and md.GetTimeScheme(h) == "EMC"
    assert md.SetCFL(h, 0.5) == 0 and md.GetCFL(h) == 0.5
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    v = [0.2, 0.0, 0.1] + [0.0] * 6
    assert md.Init(h, x, v) == 0
    assert md.SetDt(h, 0.0) == -6 and md.SetDt(h, 0.1) == 0 and md.GetDt(h) == 0.1
    fine = md.Create(LINES)
    assert md.Init(fine, x, v) == 0
    t, f = 0.0, None
    xs = np.array(x)
    for _ in range(2):
        f = np.array(md.Step(h, xs, v, t, 0.5))
        for k in range(5):
            f_fine = np.array(md.Step(fine, xs + np.array(v) * 0.1 * k, v, t + 0.1 * k, 0.1))
        xs = xs + np.array(v) * 0.5
        t += 0.5
        assert np.max(np.abs(f - f_fine)) <= 1e-9 * np.max(np.abs(f))
    # the coupled point moves with the host's velocity; its node's rate at the step's end
    # is the midpoint rule's, v_n+1 = 2 dx/dt - v_n: from rest 2 v, then 0, 2 v, ...
    assert md.GetPointVel(p4) == tuple(v[:3])
    assert np.allclose(md.GetLineNodeVel(l1, 20), 0.0, rtol=0, atol=1e-9)
    assert np.allclose(md.GetPointPos(p4), xs[:3], rtol=0, atol=1e-9)
    assert md.Close(h) == 0 and md.Close(fine) == 0


def test_external_kinematics(tmp_path):
    """MoorDyn's external water kinematics (WaveKin 1): MoorDyn's places in its order (the
    nodes of each line, then every point, then the ground: 70 for these lines, as MoorDyn
    2.7 gives them); the water at rest given by the host changes nothing, bit for bit; a
    uniform flow of 0.5 m/s held from t = 0 brings the lines, through their drag, to
    the static equilibrium of `rodyn` under a *CURRENT of 0.5 m/s (the deck of
    `rodyn --to-deck`), the nodes within 1e-4 of the 1.56 m the current moves them."""
    import csv
    import subprocess
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    with open(LINES) as f:
        text = f.read()
    wk = tmp_path / "lines_wk.txt"
    wk.write_text(text.replace("1.0           dtIC",
                               "1             WaveKin       external\n1.0           dtIC"))
    deck = subprocess.run([exe, "--to-deck", str(wk)], check=True, capture_output=True,
                          text=True).stdout
    statics = {}
    for name, extra in (("still", ""), ("current", "*CURRENT\n0.0, 0.5, 0.0\n")):
        (tmp_path / f"{name}.inp").write_text(deck.replace("*STATIC", extra + "*STATIC", 1))
        subprocess.run([exe, str(tmp_path / f"{name}.inp"), "-o", str(tmp_path / name),
                        "--quiet"], check=True)
        with open(tmp_path / name / "static_nodes.csv") as f:
            statics[name] = np.array([[float(r[k]) for k in ("x_m", "y_m", "z_m")]
                                      for r in csv.DictReader(f)])
    moved = np.abs(statics["current"] - statics["still"]).max()
    assert 1.0 < moved < 2.0

    def run(path, u, steps, dt):
        h = md.Create(str(path))
        x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
        assert md.Init(h, x, [0.0] * 9) == 0
        if u is not None:
            assert md.ExternalWaveKinInit(h) == 0
            n = md.ExternalWaveKinGetN(h)
            places = md.ExternalWaveKinGetCoordinates(h)
            assert n == 70 and len(places) == 70
            assert places[20] == x[0:3] and places[-1] == [0.0, 0.0, 0.0]
            assert md.ExternalWaveKinSet(h, [u] * n, [[0.0] * 3] * n, 0.0) == 0
        errs, t = [], 0.0
        for i in range(steps):
            f = md.Step(h, x, [0.0] * 9, t, dt)
            t += dt
            if (i + 1) % 100 == 0:
                nodes = [md.GetLineNodePos(md.GetLine(h, l), k) for l in (1, 2, 3)
                         for k in range(21)]
                errs.append(np.abs(np.array(nodes) - statics["current"]).max())
        assert md.Close(h) == 0
        return f, errs

    f_plain, _ = run(LINES, None, 20, 0.5)
    f_rest, _ = run(wk, [0.0, 0.0, 0.0], 20, 0.5)
    assert f_rest == f_plain
    _, errs = run(wk, [0.5, 0.0, 0.0], 200, 2.0)
    assert errs[1] < errs[0] and errs[1] <= 1e-4 * moved


ROD_FILE = """--------------------- MoorDyn Input File ----------------------
two chains hanging from a fixed rod
---------------------- LINE TYPES ----------------------
Name  Diam  Mass/m  EA     BA/-zeta  EI  Cd   Ca   CdAx  CaAx
(-)   (m)   (kg/m)  (N)    (N-s)     (-) (-)  (-)  (-)   (-)
chain 0.1   20.0    1.0e8  -0.5      0   1.2  1.0  0.2   0.0
---------------------- ROD TYPES ----------------------
Name Diam Mass/m Cd Ca CdEnd CaEnd
(-) (m) (kg/m) (-) (-) (-) (-)
pipe 0.5 100 1.0 1.0 0.6 1.0
---------------------- RODS ----------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 pipe Fixed -1 0 -5 1 0 -5 4 -
---------------------- POINTS ----------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -80 0 -50 0 0 0 0
2 Fixed 80 0 -50 0 0 0 0
---------------------- LINES ----------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 R1A 95 12 -
2 chain 2 R1B 95 12 -
---------------------- OPTIONS ----------------------
1025 WtrDnsty
50 WtrDpth
---------------------- need this line ----------------------
"""


def test_fixed_rod(tmp_path):
    """A Fixed rod's getters: its ID, type (MoorDyn's FIXED, 2), segments and nodes evenly
    from end A to end B, at rest; the chains hung from its ends end there."""
    path = tmp_path / "rod.txt"
    path.write_text(ROD_FILE)
    h = md.Create(str(path))
    assert md.GetNumberRods(h) == 1 and md.GetRod(h, 2) is None
    rod = md.GetRod(h, 1)
    assert md.GetRodID(rod) == 1 and md.GetRodType(rod) == 2
    assert md.GetRodN(rod) == 4 and md.GetRodNumberNodes(rod) == 5
    assert [md.GetRodNodePos(rod, i) for i in range(5)] == [
        (-1.0, 0.0, -5.0), (-0.5, 0.0, -5.0), (0.0, 0.0, -5.0), (0.5, 0.0, -5.0),
        (1.0, 0.0, -5.0)]
    assert md.GetRodNodePos(rod, 5) == (0.0, 0.0, 0.0)      # past the end: refused
    assert md.Init(h, [], []) == 0
    assert md.GetRodNodeVel(rod, 4) == (0.0, 0.0, 0.0)
    for line, node in ((1, 0), (2, 4)):
        end = md.GetLineNodePos(md.GetLine(h, line), 12)
        assert np.allclose(end, md.GetRodNodePos(rod, node), rtol=0, atol=1e-9)
    assert md.Close(h) == 0


def test_step_force_smooth_after_jump():
    """The force MoorDyn_Step returns on a coupled point after a jump in the host's
    velocity: MoorDyn's 50 m chain (quasi_static_chain.cpp) whose fairlead starts heaving
    from rest at 1.2 m/s (ZZP1_A1), from 5 s on. From one step to the next the force
    does not alternate: its second difference is under 2 % of it (measured 0.6 %, at the
    touchdown's stick and slip near the lowest fairlead position; 41 % when the forces
    were extrapolated from the last two force points). Coupling steps of 0.1 s and
    0.025 s change it as they change the tension of the segment at the fairlead, to 2 %
    of it (measured 1.04 %, where the coarse run's tension itself is rough, at the
    touchdown); and it exceeds that tension by the end node's share of the loads, under
    3 % of it (measured 0.001 to 1.99 %; the half segment's weight in water alone is
    16.6 kN, 1.5 to 1.8 % of the force)."""
    suite = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "moordyn_suite",
                         "Mooring")
    with open(os.path.join(suite, "QuasiStatic", "ZZP1_A1.txt")) as f:
        motion = np.array([[float(v) for v in ln.split()] for ln in f if ln.strip()])

    def run(h):
        s = md.Create(os.path.join(suite, "WD0050_Chain.txt"))
        assert md.Init(s, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]) == 0
        t_all = np.arange(-10.0, 20.0 + 1e-9, h)
        path = np.stack([np.interp(t_all, motion[:, 0], motion[:, j]) for j in (1, 2, 3)], 1)
        force, tension = {}, {}
        line = md.GetLine(s, 1)
        n = md.GetLineN(line)
        for k in range(len(t_all) - 1):
            v = (path[k + 1] - path[k]) / h
            f = md.Step(s, list(path[k]), list(v), t_all[k] + 10.0, h)
            key = round(t_all[k + 1], 6)
            if key >= 5.0:
                force[key] = np.linalg.norm(f)
                tension[key] = np.linalg.norm(md.GetLineNodeTen(line, n))
        md.Close(s)
        return force, tension

    coarse, tension = run(0.1)
    fine, tension_fine = run(0.025)
    times = sorted(coarse)
    f = np.array([coarse[t] for t in times])
    second = np.abs(f[1:-1] - 0.5 * (f[:-2] + f[2:])) / f[1:-1]
    assert second.max() < 0.02
    # what the step changes in the force is what it changes in the line's state
    assert max(abs((coarse[t] - fine[t]) - (tension[t] - tension_fine[t])) / coarse[t]
               for t in times) < 0.02
    excess = np.array([(coarse[t] - tension[t]) / coarse[t] for t in times])
    assert 0.0 < excess.min() and excess.max() < 0.03


def test_fast_tens_on_a_deck(tmp_path):
    """MoorDyn_GetFASTtens on a deck's line of cubic elements (MoorDyn's 200 m chain as a
    deck of 12 cubic elements, its fairlead HOST=YES): the horizontal and vertical
    forces of the line on the points that hold its ends; at the fairlead those of the
    force MoorDyn_Step returns, to float precision, after each of 10 steps of a heave.
    On a deck's line whose ends no point holds (input/mooring_surge.inp) it is refused
    with MOORDYN_UNHANDLED_ERROR (-255), not answered."""
    import ctypes
    import re
    import subprocess
    from rodyn._lib import lib
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    suite = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "moordyn_suite",
                         "Mooring")
    deck = subprocess.run([exe, "--to-deck", os.path.join(suite, "WD0200_Chain.txt")],
                          check=True, capture_output=True, text=True).stdout
    deck = re.sub(r"ELEMENTS=\d+, ORDER=1", "ELEMENTS=12, ORDER=3", deck).replace(
        "*OUTPUT, CSV=YES, HDF5=YES", "*DYNAMIC, DT=1.0, TIME=1.0e7\n*OUTPUT, CSV=NO, HDF5=NO")
    (tmp_path / "chain.inp").write_text(deck)
    s = md.Create(str(tmp_path / "chain.inp"))
    assert md.NCoupledDOF(s) == 3 and md.Init(s, [0.0] * 3, [0.0] * 3) == 0
    for k in range(10):
        z, z1 = 0.5 * np.sin(0.6 * k * 0.1), 0.5 * np.sin(0.6 * (k + 1) * 0.1)
        f = md.Step(s, [0.0, 0.0, z], [0.0, 0.0, (z1 - z) / 0.1], k * 0.1, 0.1)
        fh, fv, ah, av = md.GetFASTtens(s, 1)
        assert fh[0] == pytest.approx(np.hypot(f[0], f[1]), rel=1e-6)
        assert fv[0] == pytest.approx(abs(f[2]), rel=1e-6)
        assert ah[0] > 1e6 and av[0] > 0.0
    md.Close(s)
    src = os.path.join(os.path.dirname(__file__), "..", "..", "input")
    text = open(os.path.join(src, "mooring_surge.inp")).read().replace("TIME=120.0", "TIME=2.0")
    (tmp_path / "surge.inp").write_text(text)
    import shutil
    shutil.copy(os.path.join(src, "mooring_leg_section.inc"), tmp_path)
    s = md.Create(str(tmp_path / "surge.inp"))
    assert md.Init(s, [], []) == 0
    arrays = [(ctypes.c_float * 1)() for _ in range(4)]
    assert lib().MoorDyn_GetFASTtens(s, ctypes.byref(ctypes.c_int(1)), *arrays) == -255
    md.Close(s)


def test_save_load(tmp_path):
    """MoorDyn_Save and MoorDyn_Load on the OC3-Hywind lines, a fairlead surging: a
    system saved after 4 steps of 0.5 s and a new system of the same file, initialised
    the same way (MoorDyn_Init; MoorDyn_Init_NoIC) and loaded, give the same forces over
    4 more steps, bit for bit. Refused with MOORDYN_UNHANDLED_ERROR (-255): a state
    loaded into a system initialised otherwise, a file that is not a saved state, a
    save after a line broke."""
    x0 = [5.2, 0, -70, -2.6, 4.5, -70, -2.6, -4.5, -70]

    def motion(k):
        x, v = np.array(x0, dtype=float), np.zeros(9)
        x[0] += 2.0 * np.sin(0.15 * k)
        v[0] = 0.3 * np.cos(0.15 * k)
        return list(x), list(v)

    for init in (md.Init, md.Init_NoIC):
        state = str(tmp_path / f"{init.__name__}.h5")
        a = md.Create(LINES)
        assert init(a, x0, [0.0] * 9) == 0
        fa = []
        for k in range(8):
            if k == 4:
                assert md.Save(a, state) == 0
            fa.append(md.Step(a, *motion(k), k * 0.5, 0.5))
        b = md.Create(LINES)
        assert init(b, x0, [0.0] * 9) == 0
        assert md.Load(b, state) == 0
        fb = [md.Step(b, *motion(k), k * 0.5, 0.5) for k in range(4, 8)]
        assert np.array_equal(np.array(fa[4:]), np.array(fb))
        other = md.Create(LINES)
        assert (md.Init_NoIC if init is md.Init else md.Init)(other, x0, [0.0] * 9) == 0
        assert md.Load(other, state) == -255
        for h in (a, b, other):
            md.Close(h)
    (tmp_path / "bad.h5").write_bytes(b"not a state")
    c = md.Create(LINES)
    assert md.Init(c, x0, [0.0] * 9) == 0
    assert md.Load(c, str(tmp_path / "bad.h5")) == -255
    md.Step(c, *motion(0), 0.0, 0.5)
    md.BreakLine(c, md.GetPoint(c, 4), md.GetLine(c, 1))
    md.Step(c, *motion(1), 0.5, 0.5)
    assert md.Save(c, str(tmp_path / "broken.h5")) == -255
    md.Close(c)


def test_host_deck_is_its_file(tmp_path):
    """A rodyn deck whose points and bodies have HOST=YES is driven through librodyn as
    the MoorDyn file it was written from (`rodyn --to-deck`, a *DYNAMIC added): the same
    coupled DOFs, and after 10 steps of a surge and heave the same forces, bit for bit,
    for the OC3-Hywind lines' three coupled points and for their fairleads on a coupled
    body."""
    import subprocess
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    text = open(LINES).read()
    body = lines_on_body(text)
    (tmp_path / "points.txt").write_text(text)
    (tmp_path / "body.txt").write_text(body)
    for name, x0 in [("points", [5.2, 0, -70, -2.6, 4.5, -70, -2.6, -4.5, -70]),
                     ("body", [0, 0, -70, 0, 0, 0])]:
        md_file = str(tmp_path / f"{name}.txt")
        deck = subprocess.run([exe, "--to-deck", md_file], check=True, capture_output=True,
                              text=True).stdout
        assert deck.count("HOST=YES") == (3 if name == "points" else 1)
        deck = deck.replace("*OUTPUT,", "*DYNAMIC, DT=1.0, TIME=1.0e7\n*OUTPUT,")
        (tmp_path / f"{name}.inp").write_text(deck)
        hf, hd = md.Create(md_file), md.Create(str(tmp_path / f"{name}.inp"))
        n = len(x0)
        assert md.NCoupledDOF(hf) == md.NCoupledDOF(hd) == n
        assert md.Init(hf, x0, [0.0] * n) == 0 and md.Init(hd, x0, [0.0] * n) == 0
        dt = 0.5
        for k in range(10):
            x = np.array(x0, dtype=float)
            v = np.zeros(n)
            for i in range(0, n if name == "points" else 3, 3):
                x[i] += 2.0 * np.sin(0.3 * k * dt)
                x[i + 2] += 0.5 * np.sin(0.3 * k * dt)
                v[i] = 2.0 * 0.3 * np.cos(0.3 * k * dt)
                v[i + 2] = 0.5 * 0.3 * np.cos(0.3 * k * dt)
            ff = md.Step(hf, list(x), list(v), k * dt, dt)
            fd = md.Step(hd, list(x), list(v), k * dt, dt)
            assert np.array_equal(np.asarray(ff), np.asarray(fd))
        assert np.abs(np.asarray(ff)).max() > 1e5
        md.Close(hf)
        md.Close(hd)


def test_rodyn_deck_in_process(tmp_path):
    """A rodyn deck through librodyn (input/mooring_surge.inp, its run cut to 2 s): no
    coupled DOF, the statics `rodyn DECK`'s bit for bit, and 40 steps of the deck's DT
    driven by its own *MOTION the positions `rodyn DECK` writes at the same times, to
    1e-9 m; MoorDyn's node tension refused on its cubic line (a code, not a crash)."""
    import csv
    import shutil
    import subprocess
    import h5py
    exe = os.environ.get("RODYN_EXE")
    if not exe:
        pytest.skip("RODYN_EXE not set")
    src = os.path.join(os.path.dirname(__file__), "..", "..", "input")
    shutil.copy(os.path.join(src, "mooring_leg_section.inc"), tmp_path)
    with open(os.path.join(src, "mooring_surge.inp")) as f:
        text = f.read().replace("TIME=120.0", "TIME=2.0")
    deck = tmp_path / "surge.inp"
    deck.write_text(text)
    subprocess.run([exe, str(deck), "-o", str(tmp_path / "prog"), "--quiet"], check=True)
    with h5py.File(tmp_path / "prog" / "results.h5") as f:
        static = np.asarray(f["static/LEG/node_xyz"])
    with h5py.File(tmp_path / "prog" / "dynamic.h5") as f:
        times = np.asarray(f["dynamic/time"])
        xyz = np.stack([np.asarray(f[f"dynamic/LEG/{c}"]) for c in "xyz"], axis=-1)
    with rodyn.System(deck) as s:
        assert (s.n_coupled, s.n_lines) == (0, 1)
        s.init()
        nodes = s.line_nodes(1)
        assert nodes.shape == (361, 3)
        assert np.array_equal(nodes, static.reshape(nodes.shape))
        with pytest.raises(rodyn.RodynError):
            s.line_tensions(1)
        s.record(tmp_path / "deck_nodes.csv")
        with open(tmp_path / "deck_nodes.csv") as f:
            rows = list(csv.DictReader(f))
        assert len(rows) == 361 and all(r["tension_N"] == "" for r in rows)
        worst = 0.0
        for k in range(1, 41):
            s.step(np.zeros(0), np.zeros(0), 0.05)
            frame = np.flatnonzero(np.abs(times - s.t) < 1e-9)
            if frame.size:
                worst = max(worst, np.abs(s.line_nodes(1) - xyz[frame[0]]).max())
        assert s.t == pytest.approx(2.0, abs=1e-12)
        assert 0.0 <= worst <= 1e-9
    with pytest.raises(rodyn.RodynError):      # a deck of statics alone: no steps to take
        rodyn.System(os.path.join(src, "mooring_catenary.inp"))


def test_body_channels(tmp_path):
    """A body's OUTPUTS channels (B<n>PX ... B<n>RVZ) in FILE.out: the free buoy's
    reference point, MoorDyn's angles in degrees and the rates, as MoorDyn_GetBodyState
    gives them, at t = 0 and after two steps; a body's acceleration refused at Create."""
    buoy = os.path.join(os.path.dirname(LINES), "..", "..", "..", "program", "moordyn_buoy.txt")
    with open(buoy) as f:
        text = f.read()
    path = tmp_path / "buoy.txt"
    path.write_text(text.replace("FairTen2\n", "FairTen2\nB1PX B1PZ B1RY B1VZ B1RVY\n"))
    h = md.Create(str(path))
    assert md.Init(h, [], []) == 0
    r0, _ = md.GetBodyState(md.GetBody(h, 1))
    for k in range(2):
        md.Step(h, [], [], 0.5 * k, 0.5)
    r, rd = md.GetBodyState(md.GetBody(h, 1))
    assert md.Close(h) == 0
    lines = (tmp_path / "buoy.out").read_text().splitlines()
    assert lines[0].split()[3:] == ["B1PX", "B1PZ", "B1RY", "B1VZ", "B1RVY"]
    assert lines[1].split()[3:] == ["m", "m", "deg", "m/s", "deg/s"]
    rows = [[float(v) for v in ln.split()] for ln in lines[2:]]
    assert len(rows) == 3
    for row, (rr, rrd) in ((rows[0], (r0, None)), (rows[-1], (r, rd))):
        want = [rr[0], rr[2], math.degrees(rr[4])]
        if rrd is not None:
            want += [rrd[2], math.degrees(rrd[4])]
        for got, w in zip(row[3:], want):
            assert abs(got - w) <= 1e-7 * max(abs(w), 1e-3)
    assert abs(rows[0][5] - math.degrees(0.0338)) < 0.01      # the statics' pitch
    bad = tmp_path / "bad.txt"
    bad.write_text(path.read_text().replace("B1RVY", "B1AX"))
    assert md.Create(str(bad)) is None


def test_init_noic_pendulum():
    """MoorDyn_Init_NoIC on MoorDyn's pendulum (tests/decks/good/moordyn/pendulum.txt: a
    point of 1e5 kg held 10 m aside, 100 m down, on a 100.5 m line of water's density):
    the mass starts where the file puts it, not at its equilibrium, and swings with the
    period of the pendulum, 2 pi (l/g)^(1/2) with l the line stretched by M g/EA, times
    (1 + theta0^2/16) for its amplitude and (1 + m/(3 M))^(1/2) for the line's mass m
    (no weight in water): 20.163 s, within 1e-3 over four swings; its length within 1 %
    of the start's (MoorDyn's pendulum.cpp bound)."""
    path = os.path.join(os.path.dirname(LINES), "pendulum.txt")
    h = md.Create(path)
    p = md.GetPoint(h, 2)
    assert md.Init_NoIC(h, [], []) == 0
    x0 = md.GetPointPos(p)
    assert x0 == (10.0, 0.0, -100.0)
    big_m, g, ea, unstr, m_line = 1.0e5, 9.80665, 1.0e9, 100.5, 7.85398 * 100.5
    length = unstr * (1.0 + big_m * g / ea)
    theta0 = math.atan(10.0 / 100.0)
    period = (2.0 * math.pi * math.sqrt(length / g) * (1.0 + theta0 ** 2 / 16.0)
              * math.sqrt(1.0 + m_line / (3.0 * big_m)))
    l0 = math.hypot(x0[0], x0[2])
    dt, t, prev, crossings = period / 100.0, 0.0, x0, []
    for _ in range(460):
        md.Step(h, [], [], t, dt)
        t += dt
        q = md.GetPointPos(p)
        assert abs(math.hypot(q[0], q[2]) - l0) <= 0.01 * l0
        if prev[0] > 0.0 >= q[0]:
            crossings.append(t - dt * q[0] / (q[0] - prev[0]))
        prev = q
    assert md.Close(h) == 0
    assert len(crossings) == 5
    for a, b in zip(crossings, crossings[1:]):
        assert abs((b - a) - period) <= 1e-3 * period


def test_record(tmp_path):
    """System.record: the nodes of every line appended to a CSV at each call, read back
    equal to the arrays, to the bit (the tension left empty on a deck's cubic line:
    test_rodyn_deck_in_process)."""
    import csv
    out = tmp_path / "nodes.csv"
    with rodyn.System(LINES) as s:
        x = s.coupled_positions()
        s.init(x)
        s.record(out)
        s.step(x, np.zeros(9), 0.5)
        s.record(out)
        want = s.line_nodes(2)
        ten = np.linalg.norm(s.line_tensions(2), axis=1)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 2 * 3 * 21
    last = [r for r in rows if r["t_s"] == "0.5" and r["line"] == "2"]
    assert np.array_equal([[float(r[k]) for k in ("x_m", "y_m", "z_m")] for r in last], want)
    assert np.array_equal([float(r["tension_N"]) for r in last], ten)
