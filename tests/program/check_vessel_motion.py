#!/usr/bin/env python3
"""A line end on a vessel follows the vessel's rigid-body motion exactly.

The paper's cable (input/paper_cable_section.inc) hangs from a point of a vessel whose
reference point is away from the end (a lever arm of about 6 m in all three axes) and
whose heading is 30 deg. The vessel surges, sways, heaves, rolls, pitches and yaws
(*VESSEL, TYPE=TABLE) with rotations of up to 12 deg, and the end's position in
dynamic_nodes.csv is held at every frame against the rigid-body transform computed here
independently: scipy's Rotation.from_euler('ZYX', [yaw, pitch, roll]) (intrinsic z-y'-x'',
the same as Rz Ry Rx about fixed axes, docs/vessels.md), the heading's turn about z, the
lever arm, and the ramp (1 - cos(pi t / T))/2 on the six motions. Tolerance 1e-9 m: the
held node reaches its prescribed position through the linear solve, to round-off.

Then the same vessel moved by displacement RAOs (TYPE=RAO, phases as lags, rotations in
deg/m) in a regular Airy wave (*WAVE) of 9 s travelling towards 120 deg, a relative
heading of 90 deg: each of the 6 motions must be a R_k cos(omega t + phi_O - eps_k), with
phi_O = -(k.O) - phi the wave's phase at the vessel's reference point O, k from the
dispersion relation solved here (scipy's brentq), R_k and eps_k the table's row for
9 s and 90 deg; end A's positions follow through the same rigid-body transform (1e-9 m).
The line hangs in air above the surface, so the water does not load it.

A small-angle transform (X = O + R0 (xi + p + theta x p)) is also computed, and must be
off by more than 1 cm somewhere: the test would not tell the exact composition from
added angles otherwise. And the same deck with ROTATION UNITS=RAD and the table in
radians gives the same positions.

Usage: check_vessel_motion.py RODYN INPUT_DIR WORK_DIR. Exit 0 on success."""
import csv
import math
import os
import shutil
import subprocess
import sys

import numpy as np
from scipy.spatial.transform import Rotation

ORIGIN = np.array([-5.0, 2.0, 3.0])
HEADING = 30.0  # deg
RAMP = 2.0      # s
DT = 0.05
T_END = 4.0


def motion(t):
    """xi(t): surge, sway, heave [m], roll, pitch, yaw [deg]."""
    return np.array([0.5 * math.sin(2 * math.pi * 0.2 * t),
                     0.3 * math.cos(2 * math.pi * 0.15 * t) - 0.3,
                     0.4 * math.sin(2 * math.pi * 0.25 * t),
                     6.0 * math.sin(2 * math.pi * 0.2 * t),
                     4.0 * math.sin(2 * math.pi * 0.3 * t + 0.5) - 4.0 * math.sin(0.5),
                     12.0 * math.sin(2 * math.pi * 0.1 * t)])


def ramp(t):
    return 1.0 if t >= RAMP else 0.5 * (1.0 - math.cos(math.pi * t / RAMP))


def expected(t, x0, small=False, motion=motion):
    """Position of the vessel point at x0 (vessel at rest) at time t."""
    c, s = math.cos(math.radians(HEADING)), math.sin(math.radians(HEADING))
    r0 = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    p = r0.T @ (x0 - ORIGIN)
    xi = ramp(t) * motion(t)
    ang = np.radians(xi[3:6])
    if small:
        moved = p + np.cross(ang, p)
    else:
        rv = Rotation.from_euler("ZYX", [ang[2], ang[1], ang[0]]).as_matrix()
        moved = rv @ p
    return ORIGIN + r0 @ (xi[0:3] + moved)


# the cable of both decks, and the end of both decks after the *VESSEL card
CABLE = """*GRAVITY
0.0, 0.0, -9.80665
*INCLUDE, INPUT=paper_cable_section.inc
*LINE, NAME=CABLE, SECTION=CABLE, LENGTH=10.0, ELEMENTS=10, ORDER=3
0.0, 0.0, 0.0, 8.0, 0.0, -1.0
*BOUNDARY, LINE=CABLE, END=A, TYPE=PINNED
*BOUNDARY, LINE=CABLE, END=B, TYPE=PINNED
"""


def vessel_end():
    """The *VESSEL data line, end A on the vessel, *DYNAMIC and *OUTPUT."""
    return f"""{ORIGIN[0]}, {ORIGIN[1]}, {ORIGIN[2]}, {HEADING}
*MOTION, LINE=CABLE, END=A, TYPE=VESSEL, VESSEL=SHIP, RAMP={RAMP}
*DYNAMIC, DT={DT}, TIME={T_END}
*OUTPUT, CSV=YES, HDF5=NO
"""


def run(rodyn, workdir, section, units):
    os.makedirs(workdir, exist_ok=True)
    shutil.copy(section, workdir)
    scale = 1.0 if units == "DEG" else math.pi / 180.0
    with open(os.path.join(workdir, "vessel_motion.csv"), "w") as f:
        f.write("t, surge, sway, heave, roll, pitch, yaw\n")
        n = int(round(T_END / DT)) + 2
        for k in range(n):
            t = k * DT
            xi = motion(t)
            xi[3:6] *= scale
            f.write(", ".join(repr(float(v)) for v in [t, *xi]) + "\n")
    deck = f"""*HEADING
Paper cable hung from a point of a moving vessel (rotations in {units})
{CABLE}*VESSEL, NAME=SHIP, TYPE=TABLE, INPUT=vessel_motion.csv, ROTATION UNITS={units}
{vessel_end()}"""
    return run_deck(rodyn, workdir, "vessel", deck)


def run_deck(rodyn, workdir, name, deck):
    """Write deck text as workdir/name.inp, run it; end A's position at each frame."""
    path = os.path.join(workdir, name + ".inp")
    with open(path, "w") as f:
        f.write(deck)
    out = os.path.join(workdir, "out")
    proc = subprocess.run([rodyn, path, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"{name}: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    frames = {}
    with open(os.path.join(out, "dynamic_nodes.csv")) as f:
        for row in csv.DictReader(f):
            if int(row["node"]) == 1:
                frames[float(row["time_s"])] = np.array(
                    [float(row["x_m"]), float(row["y_m"]), float(row["z_m"])])
    return frames


# the RAO test: wave and table (periods 7, 9, 11 s; relative headings 0, 90, 180, 270)
WAVE_H, WAVE_T, WAVE_DIR, WAVE_PHASE, DEPTH = 3.0, 9.0, 120.0, 25.0, 80.0
RAO_AMP = [0.3, 0.8, 0.9, 4.0, 1.5, 0.7]      # at 9 s, 90 deg: m/m and deg/m
RAO_LAG = [40.0, -70.0, 15.0, 100.0, -20.0, 160.0]  # deg


def rao_rows():
    """Rows of the RAO table; the row at 9 s and 90 deg is RAO_AMP, RAO_LAG."""
    rows = []
    for period in (7.0, 9.0, 11.0):
        for head in (0.0, 90.0, 180.0, 270.0):
            if period == 9.0 and head == 90.0:
                amp, lag = RAO_AMP, RAO_LAG
            else:
                amp = [0.1 + 0.01 * period + 0.001 * head] * 6
                lag = [head / 3.0 + period] * 6
            rows.append([period, head, *amp, *lag])
    return rows


def wave_number(omega, depth, g=9.80665):
    from scipy.optimize import brentq
    return brentq(lambda k: omega**2 - g * k * math.tanh(k * depth), 1e-8, 10.0,
                  xtol=1e-15, rtol=1e-15)


def rao_motion(t):
    """xi(t) of the RAO vessel: m and deg."""
    omega = 2 * math.pi / WAVE_T
    k = wave_number(omega, DEPTH)
    beta = math.radians(WAVE_DIR)
    phi_o = -(k * (math.cos(beta) * ORIGIN[0] + math.sin(beta) * ORIGIN[1])) \
        - math.radians(WAVE_PHASE)
    a = WAVE_H / 2
    return np.array([a * RAO_AMP[i] * math.cos(omega * t + phi_o - math.radians(RAO_LAG[i]))
                     for i in range(6)])


def run_rao(rodyn, workdir, section):
    os.makedirs(workdir, exist_ok=True)
    shutil.copy(section, workdir)
    with open(os.path.join(workdir, "rao.csv"), "w") as f:
        f.write("# period, heading, 6 amplitudes (surge ... yaw), 6 phase lags\n")
        for row in rao_rows():
            f.write(", ".join(repr(float(v)) for v in row) + "\n")
    deck = f"""*HEADING
Paper cable hung from a vessel moved by displacement RAOs in a regular wave
{CABLE}*WATER, DEPTH={DEPTH}, SURFACE=-20.0
*WAVE, HEIGHT={WAVE_H}, PERIOD={WAVE_T}, HEADING={WAVE_DIR}, PHASE={WAVE_PHASE}
*VESSEL, NAME=SHIP, TYPE=RAO, INPUT=rao.csv, PHASE=LAG
{vessel_end()}"""
    return run_deck(rodyn, workdir, "vessel_rao", deck)


def main():
    rodyn, input_dir, work = sys.argv[1:4]
    section = os.path.join(input_dir, "paper_cable_section.inc")
    x0 = np.array([0.0, 0.0, 0.0])
    frames = run(rodyn, os.path.join(work, "deg"), section, "DEG")
    if len(frames) < int(T_END / DT):
        sys.exit(f"only {len(frames)} frames written")
    worst = worst_small = 0.0
    for t, x in frames.items():
        worst = max(worst, float(np.max(np.abs(x - expected(t, x0)))))
        worst_small = max(worst_small, float(np.max(np.abs(x - expected(t, x0, True)))))
    print(f"end A against the exact rigid-body transform: max error {worst:.3e} m over "
          f"{len(frames)} frames; against small angles: {worst_small:.3e} m")
    ok = worst <= 1e-9 and worst_small > 1e-2
    frames_rad = run(rodyn, os.path.join(work, "rad"), section, "RAD")
    diff = max(float(np.max(np.abs(frames_rad[t] - frames[t]))) for t in frames)
    print(f"ROTATION UNITS=RAD against DEG: max difference {diff:.3e} m")
    ok = ok and diff <= 1e-9
    frames_rao = run_rao(rodyn, os.path.join(work, "rao"), section)
    worst_rao = max(float(np.max(np.abs(x - expected(t, x0, motion=rao_motion))))
                    for t, x in frames_rao.items())
    travel = max(float(np.max(np.abs(x - x0))) for x in frames_rao.values())
    print(f"TYPE=RAO in a regular wave: end A against a R cos(omega t + phi_O - eps) "
          f"through the rigid-body transform: max error {worst_rao:.3e} m over "
          f"{len(frames_rao)} frames (end A travels up to {travel:.3f} m)")
    ok = ok and worst_rao <= 1e-9 and travel > 0.5
    if not ok:
        sys.exit("FAILED")
    print("PASS")


if __name__ == "__main__":
    main()
