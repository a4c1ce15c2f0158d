#!/usr/bin/env python3
"""MoorDyn's own point and body test cases as rodyn cross-checks.

Four of MoorDyn's unit tests (FloatingArrayDesign/MoorDyn, tag v2.7.1, tests/) whose physics
rodyn has. Two (pendulum, pinned) are run by MoorDyn 2.7.2 (the python package) on
MoorDyn's own input file and by rodyn on an equivalent deck, both judged by MoorDyn's own
test criteria and against each other by the same signal processing; two (rotating,
orbital) drive MoorDyn through its C and C++ APIs in ways its python package cannot, and
are run by rodyn alone, judged by the tests' criteria:

pendulum  tests/pendulum.cpp on tests/Mooring/pendulum.txt (bench/systems/moordyn/
          pendulum.txt; rodyn: bench/systems/decks/moordyn_pendulum.inp). A FREE point of
          1e5 kg on a neutrally buoyant cable (100.5 m, EA 1e9 N, 20 segments) from a fixed
          point, released at rest from x0 = 10 m, z = -100 m. The test: l0 = |x0| =
          100.49876 m, T = 2 pi sqrt(l0/g) (the simple pendulum's closed form), MoorDyn
          stepped dt = T/100 for 5 T; every sample the length |x| within 1 % of l0; the
          peaks of x (its own peak finder: the distance from the last peak stops growing)
          at i T/2 within 0.025 T and |x_peak| within 1 % of x0.
          Added here, on both sides the same way: the period from the zero crossings of x
          (linear interpolation; the mean spacing of all crossings after the first, times
          2) and the amplitude (the mean |x| at the peaks, over the start x of each side:
          rodyn's 10 m, MoorDyn's 9.938 m after its Init, see the deck).
          rodyn against MoorDyn: period within 1e-3 (justified in the deck-independent
          budget below), amplitude ratio within 1 % (MoorDyn's own amplitude tolerance).
          Closed forms: MoorDyn's T = 2 pi sqrt(l0/g) with the test's 0.025 T; and, for
          information, the compound pendulum's T = 2 pi sqrt(I/(M g L)) (1 + th0^2/16) with
          L the line stretched by M g (EA), I = M L^2 + m_line L^2/3 (the line neutrally
          buoyant: no moment from it, only inertia), th0 = asin(x0/l0).
pinned    tests/bodies.cpp TEST_CASE("Pinned body") on tests/Mooring/body_tests/
          pinnedBody.txt (bench/systems/moordyn/pinnedBody.txt; rodyn: bench/systems/decks/
          moordyn_pinned_body.inp). A massless body pinned at (0, 0, -5) carrying a rigid
          10 m rod (5e3 kg/m, diameter 2 m) fixed to it from 5 m to 15 m below the pin
          (the rod's ends are given in the body's axes), in a vacuum, its pin accelerated
          along y at a = 0.5 m/s2 from rest. rodyn has no body whose translation alone
          is prescribed (MoorDyn's CoupledPinned): its deck is the same case in the pin's
          frame (gravity (0, -a, -g), a
          line from a FIXED point: a massless rigid 5 m arm, then the rod; see the
          deck). The test: dt = 0.01 s; after 30 steps it counts the
          extrema of the roll (sign changes of its slope) and stops after the 4th; the mean
          of the roll samples until then within 0.001 rad of atan(-a/g).
          The roll on both sides the same way: atan2(y_tip - y_pin, -(z_tip - z_pin)) of
          the rod's end nodes (rodyn: the CAN segment's; MoorDyn: GetRodNodePos; it
          equals MoorDyn's body roll
          GetBodyState()[3], which is stored too and used for MoorDyn's own check).
          rodyn against MoorDyn: mean roll within 1e-4 rad, period (zero crossings of the
          roll less atan(-a/g)) within 1e-3.
          Closed forms: atan(-a/g) (the test's); the compound pendulum's period
          T = 2 pi sqrt(I/(m g' c)) (1 + th^2/16), c = 5 + L/2 = 10 m from the pin to the
          rod's centre, I = m (L^2/12 + r^2/4 + c^2) (MoorDyn's rod inertia, Rod.cpp's
          I_r_correction on its lumped nodes; rodyn's with the solid section's rotary
          inertia), g' = sqrt(g^2 + a^2), th = atan(a/g) the swing's amplitude, within
          1e-3.

rotating  tests/bodies.cpp TEST_CASE("Rotating body") on tests/Mooring/body_tests/
          rotatingBody.txt (bench/systems/moordyn/rotatingBody.txt; rodyn: bench/systems/
          decks/moordyn_rotating_body.inp with moordyn_rotating_body_path.csv). A free
          body held at its centre by six taut lines, turned by a seventh from its point
          (1, 0, 0) to a coupled point dragged on three quarter circles (xz, yz, xy
          planes), each followed by a 0.5 s hold. The test: after each hold the body's
          point within numpy's allclose (rtol 0.1, atol 0.15) of (0, 0, 1), (0, 1, 0),
          (1, 0, 0) from the centre; at the end a turn of 90 degrees (within 10) about x
          (the axis within 0.2 of it). rodyn only: the test moves the coupled point
          through MoorDyn's C API step by step with a velocity a tenth of the path's (see
          the deck), a path a rodyn table gives only as the test means it.
orbital   tests/bodies.cpp TEST_CASE("Excentric body") on tests/Mooring/body_tests/
          orbitalBody.txt (bench/systems/moordyn/orbitalBody.txt; rodyn: bench/systems/
          decks/moordyn_orbital_body.inp). Two free bodies with their reference points
          10 m from their centres of mass, one carrying two point masses, the other a
          rigid rod, given a spin of 0.2 rad/s about the x axis through the centres, no
          gravity, no water. The test: every 0.25 s for 10 s each reference point stays
          10 m from the centre within 1e-6 of the radius and turns at 0.2 rad/s within
          1e-6 (its angle over the time). rodyn only: the test sets the bodies' velocities
          through MoorDyn's C++ API, which its Python package lacks; MoorDyn's criteria
          are closed forms.

Tolerance of 1e-3 on the periods of rodyn against MoorDyn: both integrate the same
equations; the differences of model (consistent against lumped line mass: the line is
0.8 % of the pendulum's mass, its lumping changes the inertia by L^2/(6 N^2) of its share,
3e-6; the start (MoorDyn's Init moves the pendulum's point to x = 9.938 m, which changes
the finite-amplitude term th0^2/16 by 8e-6); the time integration (MoorDyn RK4 at cfl
0.1 / its dtM 1 ms, rodyn EMC with dt = T/400 and 0.01 s: periods elongated by
(w dt)^2/12 = 2e-5 and 8e-6) are each below 1e-4; 1e-3 is ten times the largest and still
25 times tighter than MoorDyn's own peak-time tolerance. The mean roll of the pinned body
within 1e-4 rad of MoorDyn's: the two means are taken over the test's own window, which
ends at the 4th extremum of each side's samples (a step more or less moves the mean by
up to the swing's 0.05 rad over 1300 samples, 4e-5 rad); 1e-4 is 10 times tighter than
the test's own 0.001 rad against atan(-a/g).

Measured (Release build, MoorDyn 2.7.2; bench/results/moordyn_cases.csv):
  pendulum: period from the zero crossings, rodyn 20.16285 s, MoorDyn 20.16303 s
    (9.0e-6 apart); MoorDyn's test formula 2 pi sqrt(l0/g) = 20.11407 s (both 2.43e-3
    above it, within the test's 0.025 T); the compound pendulum (stretched line, line
    inertia, amplitude) 20.16284 s for rodyn's start, 20.16302 s for MoorDyn's (within
    9.3e-6 of each side); amplitude over the start x 0.99907 (rodyn) and 0.99810
    (MoorDyn). MoorDyn's own checks on rodyn: length within 1.96e-3 l0, peaks within
    0.0200 T of i T/2 (10 peaks), |x_peak| within 3.8e-3 x0; on MoorDyn: 1.00e-3, 0.0200 T,
    9.975e-3 x0 (just inside its own 1 %: its Init moved the point to x = 9.938 m).
  pinned body: mean roll over the test's window, rodyn -0.050890 rad (1323 steps),
    MoorDyn -0.050852 rad (1324 steps), atan(-a/g) = -0.050942 rad (5.1e-5 and 9.0e-5
    from it, the test's 0.001); period rodyn 6.60835 s, MoorDyn 6.60830 s, compound
    pendulum 6.60830 s (7.8e-6 and 1.3e-7); swing amplitude 0.050942 rad on both.
  rotating body (rodyn, EMC at dt 0.01 s): the body's point at (-0.061, 0.000, 1.013),
    (-0.073, 1.011, -0.101) and (1.012, 0.054, -0.054) m from the centre after the holds;
    final turn 83.91 degrees about an axis 0.057 off -x (the test: 10 degrees, 0.2).
  excentric bodies (rodyn, EMC at dt 0.01 s): radius within 1.3e-14 (the body with the
    point masses) and 2.5e-12 (the body with the clamped rod) of 10 m; turning rate
    3.33e-7 and 3.39e-7 below 0.2 rad/s, the Cayley rotation's (omega dt)^2/12 = 3.3e-7
    (the test: 1e-6 each).

Not done (the other point/body cases of MoorDyn's tests/, and why):
  "Body drag" (bodyDrag.txt): the test checks only that MoorDyn runs (rodyn's body drag,
      *BODY DRAG, is verified by ctest -R verify_body_current_drag).
  bodies_and_rods.cpp, rods.cpp, tripod.cpp and the others: MoorDyn rods (rigid, fixed to
      bodies, with end added mass and drag), body added mass, wave kinematics from files.

Usage:
  python3 bench/systems/moordyn_cases.py --write            # MoorDyn 2.7.2 on its own
                                                             # inputs -> bench/results/
                                                             # moordyn_cases.csv
  python3 bench/systems/moordyn_cases.py --quick [--rodyn build/rodyn]
                                                             # rodyn on the decks against
                                                             # the stored MoorDyn series
  --write runs MoorDyn (about 10 s); --quick runs rodyn only (under a second) and exits
  1 on a miss.
"""
import argparse
import contextlib
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS_CSV = os.path.join(ROOT, "bench", "results", "moordyn_cases.csv")
MD_DIR = os.path.join(HERE, "moordyn")
DECKS = os.path.join(HERE, "decks")

G = 9.80665                      # MoorDyn's default g (source/MoorDyn2.cpp), rodyn's too
# pendulum (tests/Mooring/pendulum.txt)
P_X0, P_Z0 = 10.0, -100.0
P_L0 = math.hypot(P_X0, P_Z0)    # the test's l0 (before Init)
P_T = 2.0 * math.pi / math.sqrt(G / P_L0)
P_MASS, P_LUNSTR, P_EA, P_MLINE = 1.0e5, 100.5, 1.0e9, 7.85398
# pinned body (tests/Mooring/body_tests/pinnedBody.txt, tests/bodies.cpp)
B_ACCEL, B_DT, B_LEN, B_DIAM, B_ARM = 0.5, 0.01, 10.0, 2.0, 5.0
# rotating body (tests/Mooring/body_tests/rotatingBody.txt, tests/bodies.cpp): after each
# hold, the body's point (1, 0, 0) from its centre (0, 0, 5)
R_CENTRE = (0.0, 0.0, 5.0)
R_HOLDS = ((2.6, (0.0, 0.0, 1.0)), (5.1, (0.0, 1.0, 0.0)), (7.6, (1.0, 0.0, 0.0)))
# excentric body (tests/Mooring/body_tests/orbitalBody.txt, tests/bodies.cpp)
O_RADIUS, O_OMEGA, O_CENTRE = 10.0, 0.2, (0.0, 0.0, 20.0)

TOL = {
    "pendulum_length": 0.01,       # MoorDyn's: |x| within 1 % of l0
    "pendulum_peak_time": 0.025,   # MoorDyn's: peaks at i T/2 within 0.025 T
    "pendulum_peak_x": 0.01,       # MoorDyn's: |x_peak| within 1 % of x0
    "pendulum_period_vs_md": 1e-3,  # this script's (docstring)
    "pendulum_amp_vs_md": 0.01,    # MoorDyn's amplitude tolerance
    "pendulum_period_closed": 0.025,  # MoorDyn's peak-time tolerance, on the period
    "pinned_mean_roll": 0.001,     # MoorDyn's [rad]
    "rotating_rtol": 0.1,          # MoorDyn's allclose(rel_pos, expected, 0.1, 0.15)
    "rotating_atol": 0.15,
    "rotating_axis": 0.2,          # MoorDyn's: |axis.y|, |axis.z| < 0.2 (|axis.x| > 0.85)
    "rotating_angle": 10.0,        # MoorDyn's: |angle - 90| < 10 degrees
    "orbital_radius": 1e-6,        # MoorDyn's: |R - r0| within 1e-6 of the radius
    "orbital_rate": 1e-6,          # MoorDyn's: angle / t within 1e-6 of omega
    "pinned_mean_vs_md": 1e-4,     # this script's [rad]
    "pinned_period_vs_md": 1e-3,   # this script's
    "pinned_period_closed": 1e-3,  # this script's
}


# ----------------------------------------------------------------------------- signals
def md_peaks(t, x, x0):
    """MoorDyn's pendulum.cpp peak finder: the first peak (0, x0); a new peak where the
    distance from the last one stops growing."""
    xp, tp, dpk = [x0], [0.0], 0.0
    for ti, xi in zip(t, x):
        d = abs(xi - xp[-1])
        if d > dpk:
            dpk = d
        else:
            xp.append(xi)
            tp.append(ti)
            dpk = 0.0
    return tp, xp


def zero_crossings(t, y):
    """Times where y changes sign, linearly interpolated."""
    out = []
    for i in range(1, len(y)):
        if y[i - 1] == 0.0:
            continue
        if y[i - 1] * y[i] < 0.0 or y[i] == 0.0:
            out.append(t[i - 1] + (t[i] - t[i - 1]) * y[i - 1] / (y[i - 1] - y[i]))
    return out


def period_from_crossings(t, y):
    """2 x the mean spacing of the zero crossings after the first (the release is not a
    crossing)."""
    zc = zero_crossings(t, y)
    if len(zc) < 3:
        return float("nan"), len(zc)
    return 2.0 * (zc[-1] - zc[0]) / (len(zc) - 1), len(zc)


def md_pinned_mean(roll, dt=B_DT):
    """MoorDyn's bodies.cpp averaging: roll[i] the samples after each step; from i = 30 on
    count the sign changes of the slope, stop after the 4th; the mean of roll[0..i]."""
    j = 0
    for i in range(len(roll)):
        if i >= 30:
            if ((roll[i] - roll[i - 1]) / dt) * ((roll[i - 1] - roll[i - 2]) / dt) < 0:
                j += 1
        if j > 3:
            return sum(roll[: i + 1]) / (i + 1), i + 1
    return float("nan"), len(roll)


def pendulum_closed_refined(x0, l0):
    """Compound pendulum: the point on a neutrally buoyant, uniformly massive cable."""
    lstr = P_LUNSTR * (1.0 + P_MASS * G / P_EA)
    mline = P_MLINE * P_LUNSTR
    inertia = P_MASS * lstr ** 2 + mline * lstr ** 2 / 3.0
    th0 = math.asin(x0 / l0)
    return 2.0 * math.pi * math.sqrt(inertia / (P_MASS * G * lstr)) * (1.0 + th0 ** 2 / 16.0)


def pinned_closed():
    gp = math.hypot(G, B_ACCEL)
    r = B_DIAM / 2.0
    c = B_ARM + B_LEN / 2.0
    ratio = (B_LEN ** 2 / 12.0 + r ** 2 / 4.0 + c ** 2) / (gp * c)
    th = math.atan(B_ACCEL / G)
    return 2.0 * math.pi * math.sqrt(ratio) * (1.0 + th ** 2 / 16.0)


# ----------------------------------------------------------------------------- MoorDyn
@contextlib.contextmanager
def quiet_fd():
    """MoorDyn writes to the process's stdout and stderr: send them to /dev/null."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    try:
        yield
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, null):
            os.close(fd)


def moordyn_pendulum(work):
    import moordyn
    shutil.copy(os.path.join(MD_DIR, "pendulum.txt"), work)
    rows = []
    with quiet_fd():
        s = moordyn.Create(os.path.join(work, "pendulum.txt"))
        p = moordyn.GetPoint(s, 2)
        x0 = moordyn.GetPointPos(p)
        moordyn.Init(s, [], [])
        xi = moordyn.GetPointPos(p)
        dt, t = P_T / 100.0, 0.0
        rows.append((0.0, xi[0], xi[2]))
        while t < 5.0 * P_T:       # pendulum.cpp's loop (MoorDyn_Step advances t by dt)
            moordyn.Step(s, [], [], t, dt)
            t += dt
            x = moordyn.GetPointPos(p)
            rows.append((t, x[0], x[2]))
        moordyn.Close(s)
    return x0, rows


def moordyn_pinned(work):
    import moordyn
    shutil.copy(os.path.join(MD_DIR, "pinnedBody.txt"), work)
    rows = []
    with quiet_fd():
        s = moordyn.Create(os.path.join(work, "pinnedBody.txt"))
        x = [0.0, 0.0, -5.0, 0.0, 0.0, 0.0]
        xd = [0.0] * 6
        moordyn.Init(s, x, xd)
        body = moordyn.GetBody(s, 1)
        rod = moordyn.GetRod(s, 1)
        nlast = moordyn.GetRodNumberNodes(rod) - 1
        t, i, j, roll = 0.0, 0, 0, []
        while t < 50.0:            # bodies.cpp's loop, its stop rule, a little longer
            x[1] = 0.5 * B_ACCEL * t ** 2
            xd[1] = B_ACCEL * t
            moordyn.Step(s, x, xd, t, B_DT)
            r, _ = moordyn.GetBodyState(body)
            pa, pb = moordyn.GetRodNodePos(rod, 0), moordyn.GetRodNodePos(rod, nlast)
            tip = math.atan2(pb[1] - pa[1], -(pb[2] - pa[2]))
            roll.append(r[3])
            rows.append((t + B_DT, r[3], tip))
            if i >= 30 and (roll[i] - roll[i - 1]) * (roll[i - 1] - roll[i - 2]) < 0:
                j += 1
            t += B_DT
            i += 1
            if t > 16.0 - 1e-9:    # past the test's stop (4th extremum, about 13.2 s)
                break
        moordyn.Close(s)
    return rows


def write(args):
    import importlib.metadata
    version = importlib.metadata.version("moordyn")
    work = tempfile.mkdtemp(prefix="moordyn_cases_")
    try:
        x0, prow = moordyn_pendulum(work)
        brow = moordyn_pinned(work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    with open(RESULTS_CSV, "w", newline="") as fh:
        fh.write(f"# bench/systems/moordyn_cases.py --write: MoorDyn {version} (python "
                 "package) on its own test inputs (bench/systems/moordyn/, from "
                 "FloatingArrayDesign/MoorDyn tag v2.7.1 tests/Mooring/)\n")
        fh.write(f"# pendulum: the test's sampling dt = T/100 = {P_T / 100:.9g} s for 5 T; "
                 f"x0 before Init {x0[0]:.12g} {x0[2]:.12g}; signals x, z of point 2 "
                 "after each step (t = 0: after Init)\n")
        fh.write("# pinned: the test's dt = 0.01 s to t = 16 s; signals roll "
                 "(GetBodyState()[3]) and tip (atan2 of the rod's end nodes) after "
                 "each step\n")
        w = csv.writer(fh)
        w.writerow(["case", "signal", "time_s", "value"])
        for t, x, z in prow:
            w.writerow(["pendulum", "x_m", f"{t:.9g}", f"{x:.12g}"])
            w.writerow(["pendulum", "z_m", f"{t:.9g}", f"{z:.12g}"])
        for t, r, tip in brow:
            w.writerow(["pinned", "roll_rad", f"{t:.9g}", f"{r:.12g}"])
            w.writerow(["pinned", "tip_rad", f"{t:.9g}", f"{tip:.12g}"])
    print(f"wrote {os.path.relpath(RESULTS_CSV, ROOT)} (MoorDyn {version})")
    return 0


def read_stored():
    sig, version = {}, "?"
    with open(RESULTS_CSV) as fh:
        lines = [ln for ln in fh]
    for ln in lines:
        if ln.startswith("#") and "MoorDyn " in ln and version == "?":
            version = ln.split("MoorDyn ")[1].split()[0]
    for r in csv.DictReader(ln for ln in lines if not ln.startswith("#")):
        key = (r["case"], r["signal"])
        sig.setdefault(key, ([], []))
        sig[key][0].append(float(r["time_s"]))
        sig[key][1].append(float(r["value"]))
    return version, sig


# ----------------------------------------------------------------------------- rodyn
def run_rodyn(rodyn, deck, out):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"rodyn failed on {deck}:\n{proc.stderr}")


def rodyn_nodes(out, line, nodes):
    """{node: (t, x, y, z)} of the given nodes (the last node: -1)."""
    data = {}
    with open(os.path.join(out, "dynamic_nodes.csv")) as fh:
        for r in csv.DictReader(fh):
            if r["line"] != line:
                continue
            data.setdefault(int(r["node"]), []).append(
                (float(r["time_s"]), float(r["x_m"]), float(r["y_m"]), float(r["z_m"])))
    nmax = max(data)
    return {k: data[nmax if k == -1 else k] for k in nodes}


def pendulum_checks(t, x, z, x0_md_test, xstart):
    """MoorDyn's checks and the shared measures for one side."""
    lmax = max(abs(math.hypot(a, b) - P_L0) for a, b in zip(x, z)) / P_L0
    tp, xp = md_peaks(t[1:], x[1:], P_X0)
    dt_peak = max(abs(ti - i * 0.5 * P_T) for i, ti in enumerate(tp)) / P_T
    dx_peak = max(abs(abs(xi) - x0_md_test) for xi in xp) / x0_md_test
    period, ncross = period_from_crossings(t, x)
    amp = sum(abs(v) for v in xp[1:]) / (len(xp) - 1) / xstart
    return dict(lmax=lmax, npeaks=len(tp), dt_peak=dt_peak, dx_peak=dx_peak,
                period=period, ncross=ncross, amp=amp)


def rotation_matrix(rv):
    """The rotation of rotation vector rv (Rodrigues)."""
    th = math.sqrt(sum(v * v for v in rv))
    if th == 0.0:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    k = [v / th for v in rv]
    kk = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]]
    k2 = [[sum(kk[i][m] * kk[m][j] for m in range(3)) for j in range(3)] for i in range(3)]
    return [[(1.0 if i == j else 0.0) + math.sin(th) * kk[i][j] + (1.0 - math.cos(th))
             * k2[i][j] for j in range(3)] for i in range(3)]


def rotating_checks(out):
    """The rotating body's frames (dynamic_bodies.csv): the body's point (1, 0, 0) from
    the centre at the ends of the holds, and the final turn's axis and angle [deg]."""
    with open(os.path.join(out, "dynamic_bodies.csv")) as f:
        rows = list(csv.DictReader(f))
    holds = []
    for t, _ in R_HOLDS:
        r = [r for r in rows if abs(float(r["time_s"]) - t) < 1e-9][0]
        q = rotation_matrix([float(r[k]) for k in ("rx_rad", "ry_rad", "rz_rad")])
        holds.append([float(r[k]) + q[i][0] - R_CENTRE[i]
                      for i, k in enumerate(("x_m", "y_m", "z_m"))])
    rv = [float(rows[-1][k]) for k in ("rx_rad", "ry_rad", "rz_rad")]
    th = math.sqrt(sum(v * v for v in rv))
    return holds, [v / th for v in rv], math.degrees(th)


def orbital_errors(out):
    """MoorDyn's excentric-body checks on rodyn's body frames (dynamic_bodies.csv): per
    body the largest | |R - r0| - r | / r and | atan2(z, y) / t - w | / w over the frames
    after t = 0 (the test's samples every 0.25 s)."""
    res = {}
    with open(os.path.join(out, "dynamic_bodies.csv")) as f:
        for r in csv.DictReader(f):
            t = float(r["time_s"])
            if t <= 0.0:
                continue
            q = [float(r["x_m"]) - O_CENTRE[0], float(r["y_m"]) - O_CENTRE[1],
                 float(r["z_m"]) - O_CENTRE[2]]
            e_r = abs(math.sqrt(sum(v * v for v in q)) - O_RADIUS) / O_RADIUS
            e_w = abs(math.atan2(q[2], q[1]) / t - O_OMEGA) / O_OMEGA
            a, b, n = res.get(r["body"], (0.0, 0.0, 0))
            res[r["body"]] = (max(a, e_r), max(b, e_w), n + 1)
    if not res or any(n != 40 for _, _, n in res.values()):
        sys.exit(f"orbital: expected 40 frames after t = 0 per body in {out}")
    return [(b, *v) for b, v in sorted(res.items())]


def quick(args):
    rodyn = os.path.abspath(args.rodyn)
    if not os.access(rodyn, os.X_OK):
        sys.exit(f"no executable rodyn at {rodyn} (build it, or give --rodyn)")
    version, md = read_stored()
    work = tempfile.mkdtemp(prefix="moordyn_cases_")
    rows, fails = [], 0

    def row(case, quantity, r, m, c, diff, tol, source):
        nonlocal fails
        ok = diff <= tol
        fails += 0 if ok else 1
        rows.append((case, quantity, r, m, c, f"{diff:.2e}", f"{tol:g}", source,
                     "ok" if ok else "MISS"))

    try:
        # ---- pendulum
        out = os.path.join(work, "pendulum")
        run_rodyn(rodyn, os.path.join(DECKS, "moordyn_pendulum.inp"), out)
        nd = rodyn_nodes(out, "L1", [-1])[-1]
        rt = [v[0] for v in nd]
        rx = [v[1] for v in nd]
        rz = [v[3] for v in nd]
        mt, mx = md[("pendulum", "x_m")]
        mz = md[("pendulum", "z_m")][1]
        rr = pendulum_checks(rt, rx, rz, P_X0, rx[0])
        mm = pendulum_checks(mt, mx, mz, P_X0, mx[0])
        t_closed = P_T
        t_ref_r = pendulum_closed_refined(rx[0], math.hypot(rx[0], rz[0]))
        t_ref_m = pendulum_closed_refined(mx[0], math.hypot(mx[0], mz[0]))
        for side, s in (("rodyn", rr), (f"MoorDyn {version}", mm)):
            row("pendulum", f"{side}: max ||x|-l0|/l0", f"{s['lmax']:.3e}", "", "",
                s["lmax"], TOL["pendulum_length"], "MoorDyn test")
            row("pendulum", f"{side}: peaks ({s['npeaks']}) |t-iT/2|/T", f"{s['dt_peak']:.3e}",
                "", "", s["dt_peak"], TOL["pendulum_peak_time"], "MoorDyn test")
            row("pendulum", f"{side}: peaks ||x|-x0|/x0", f"{s['dx_peak']:.3e}", "", "",
                s["dx_peak"], TOL["pendulum_peak_x"], "MoorDyn test")
        row("pendulum", "period (zero crossings) [s]", f"{rr['period']:.5f}",
            f"{mm['period']:.5f}", f"{t_closed:.5f}",
            abs(rr["period"] / mm["period"] - 1.0), TOL["pendulum_period_vs_md"],
            "this script")
        for side, s in (("rodyn", rr), ("MoorDyn", mm)):
            row("pendulum", f"{side} period vs 2 pi sqrt(l0/g)", f"{s['period']:.5f}", "",
                f"{t_closed:.5f}", abs(s["period"] / t_closed - 1.0),
                TOL["pendulum_period_closed"], "MoorDyn test")
        row("pendulum", "period vs compound pendulum (info)", f"{rr['period']:.5f}",
            f"{mm['period']:.5f}", f"{t_ref_r:.5f} / {t_ref_m:.5f}",
            max(abs(rr["period"] / t_ref_r - 1.0), abs(mm["period"] / t_ref_m - 1.0)),
            float("inf"), "information")
        row("pendulum", "amplitude / own start x", f"{rr['amp']:.5f}", f"{mm['amp']:.5f}",
            "1", abs(rr["amp"] - mm["amp"]), TOL["pendulum_amp_vs_md"], "MoorDyn test")

        # ---- pinned body
        out = os.path.join(work, "pinned")
        run_rodyn(rodyn, os.path.join(DECKS, "moordyn_pinned_body.inp"), out)
        # node 4: the end of the one cubic element of the 5 m arm, the rod's top
        nd = rodyn_nodes(out, "ROD", [4, -1])
        rt = [v[0] for v in nd[4]]
        rtip = [math.atan2(b[2] - a[2], -(b[3] - a[3])) for a, b in zip(nd[4], nd[-1])]
        # the samples after each step: t = 0.01, 0.02, ... (as MoorDyn's roll[i])
        rroll = rtip[1:]
        mt, mtip = md[("pinned", "tip_rad")]
        mroll = md[("pinned", "roll_rad")][1]
        theta = math.atan(-B_ACCEL / G)
        r_mean, r_n = md_pinned_mean(rroll)
        m_mean, m_n = md_pinned_mean(mroll)
        m_mean_tip, _ = md_pinned_mean(mtip)
        row("pinned", f"rodyn mean roll ({r_n} steps) [rad]", f"{r_mean:.6f}", "",
            f"{theta:.6f}", abs(r_mean - theta), TOL["pinned_mean_roll"], "MoorDyn test")
        row("pinned", f"MoorDyn mean body roll ({m_n} steps) [rad]", "", f"{m_mean:.6f}",
            f"{theta:.6f}", abs(m_mean - theta), TOL["pinned_mean_roll"], "MoorDyn test")
        row("pinned", "mean roll, rod's end nodes [rad]", f"{r_mean:.6f}",
            f"{m_mean_tip:.6f}", f"{theta:.6f}", abs(r_mean - m_mean_tip),
            TOL["pinned_mean_vs_md"], "this script")
        rp, _ = period_from_crossings(rt[1:], [v - theta for v in rroll])
        mp, _ = period_from_crossings(mt, [v - theta for v in mtip])
        tc = pinned_closed()
        row("pinned", "period (zero crossings of roll - atan(-a/g)) [s]", f"{rp:.5f}",
            f"{mp:.5f}", f"{tc:.5f}", abs(rp / mp - 1.0), TOL["pinned_period_vs_md"],
            "this script")
        for side, p in (("rodyn", rp), ("MoorDyn", mp)):
            row("pinned", f"{side} period vs compound pendulum", f"{p:.5f}", "",
                f"{tc:.5f}", abs(p / tc - 1.0), TOL["pinned_period_closed"], "this script")
        ramp = (max(rroll) - min(rroll)) / 2.0
        mamp = (max(mtip) - min(mtip)) / 2.0
        row("pinned", "swing amplitude (max-min)/2 [rad]", f"{ramp:.6f}", f"{mamp:.6f}",
            f"{-theta:.6f}", abs(ramp / mamp - 1.0), 0.01, "this script")

        # ---- rotating body: MoorDyn's own criteria after each hold and at the end
        out = os.path.join(work, "rotating")
        run_rodyn(rodyn, os.path.join(DECKS, "moordyn_rotating_body.inp"), out)
        holds, axis, angle = rotating_checks(out)
        for (t, want), rel in zip(R_HOLDS, holds):
            # numpy's allclose: |a - b| <= atol + rtol |b|, as a margin (<= 0 passes)
            miss = max(abs(a - b) - TOL["rotating_atol"] - TOL["rotating_rtol"] * abs(b)
                       for a, b in zip(rel, want))
            row("rotating", f"rodyn point (1,0,0) at t = {t} s",
                "(" + ", ".join(f"{v:.3f}" for v in rel) + ")", "",
                "(" + ", ".join(f"{v:g}" for v in want) + ")", max(miss, 0.0), 0.0,
                "MoorDyn test (allclose 0.1, 0.15)")
        row("rotating", "rodyn final turn: axis off x", f"{max(abs(axis[1]), abs(axis[2])):.3f}",
            "", "0", max(abs(axis[1]), abs(axis[2])), TOL["rotating_axis"], "MoorDyn test")
        row("rotating", "rodyn final turn [deg]", f"{angle:.2f}", "", "90", abs(angle - 90.0),
            TOL["rotating_angle"], "MoorDyn test")

        # ---- excentric body: MoorDyn's own criteria, at its 0.25 s samples
        out = os.path.join(work, "orbital")
        run_rodyn(rodyn, os.path.join(DECKS, "moordyn_orbital_body.inp"), out)
        for body, err_r, err_w, n in orbital_errors(out):
            row("orbital", f"rodyn {body}: max ||R-r0|-r|/r ({n} samples)", f"{err_r:.3e}",
                "", "0", err_r, TOL["orbital_radius"], "MoorDyn test")
            row("orbital", f"rodyn {body}: max |angle/t-w|/w ({n} samples)", f"{err_w:.3e}",
                "", "0", err_w, TOL["orbital_rate"], "MoorDyn test")
    finally:
        shutil.rmtree(work, ignore_errors=True)

    head = ("case", "quantity", "rodyn", f"MoorDyn {version}", "closed form", "diff",
            "tol", "tol source", "")
    widths = [max(len(str(r[i])) for r in rows + [head]) for i in range(len(head))]
    for r in [head] + rows:
        print("  ".join(str(v).ljust(w) for v, w in zip(r, widths)).rstrip())
    print(f"{len(rows) - fails} of {len(rows)} within tolerance"
          + ("" if fails == 0 else f"; {fails} MISS"))
    return 1 if fails else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--write", action="store_true",
                    help="run MoorDyn on its own inputs, store bench/results/"
                         "moordyn_cases.csv")
    ap.add_argument("--quick", action="store_true",
                    help="run rodyn on the decks, compare with the stored MoorDyn series")
    args = ap.parse_args()
    if not (args.write or args.quick):
        ap.error("give --write and/or --quick")
    status = 0
    if args.write:
        status |= write(args)
    if args.quick:
        status |= quick(args)
    sys.exit(status)


if __name__ == "__main__":
    main()
