#!/usr/bin/env python3
"""A line end on a vessel with a static offset and a slow drift (docs/vessels.md).

The deck of check_vessel_motion.py (the paper's cable, end A on a vessel point with a
lever arm, vessel heading 30 deg, a 6-DOF table motion with rotations up to 12 deg) with
*VESSEL's OFFSET X=1.5, OFFSET Y=-0.7, OFFSET Z=0.4, OFFSET HEADING=8 and a drift
DRIFT X=0.9, DRIFT Y=0.6, DRIFT YAW=5 of DRIFT PERIOD=6 s, DRIFT PHASE=30 (faster than
a real slow drift, so that a 4 s run sees it). End A's position at every frame is held
against the closed form computed here,

  X = O + r d(t) + Rz(psi0 + r d_psi(t)) (r xi_1:3 + Rv(r xi_4:6) p),
  d(t) = offset + a sin(2 pi t/T_d + phi_d),

Rv from scipy's Rotation.from_euler('ZYX', [yaw, pitch, roll]), r the *MOTION's ramp;
tolerance 1e-9 m (the held node reaches its position through the linear solve). The
offset and drift must move the end by more than 1 m against the same deck without them.
That is the deck with OFFSET START=DYNAMIC (the static analysis at rest at O, the offset
ramped in with the motion).

With OFFSET START=STATIC (the default) the static analysis has the vessel at its offset:
end A's static position (static_nodes.csv) is O + offset + Rz(psi0 + offset_psi) p, and
the dynamics starts there, the vessel at rest at its offset (O' = O + offset, psi0' =
psi0 + offset_psi), the offset not ramped again:

  X = O' + r a sin(...) + Rz(psi0' + r a_psi sin(...)) (r xi_1:3 + Rv(r xi_4:6) p),

held at every frame (1e-9 m), frame 0 the static position.

Usage: check_vessel_drift.py RODYN INPUT_DIR WORK_DIR. Exit 0 on success."""
import csv
import math
import os
import sys

import numpy as np
from scipy.spatial.transform import Rotation

import check_vessel_motion as cvm

OFFSET = [1.5, -0.7, 0.4, 8.0]     # m, m, m, deg
DRIFT = [0.9, 0.6, 0.0, 5.0]       # m, m, -, deg
DRIFT_T, DRIFT_PHASE = 6.0, 30.0   # s, deg


def expected(t, x0, static_offset=False):
    """Position of the vessel point at x0 (vessel at rest at O) at time t; with
    static_offset the offset is in the static solution, not ramped."""
    r = cvm.ramp(t)
    d = r * (np.array(OFFSET) + np.array(DRIFT) * math.sin(
        2 * math.pi * t / DRIFT_T + math.radians(DRIFT_PHASE)))
    if static_offset:
        d = np.array(OFFSET) + r * np.array(DRIFT) * math.sin(
            2 * math.pi * t / DRIFT_T + math.radians(DRIFT_PHASE))
    psi0 = math.radians(cvm.HEADING)
    c, s = math.cos(psi0), math.sin(psi0)
    p = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]]) @ (x0 - cvm.ORIGIN)
    xi = r * cvm.motion(t)
    ang = np.radians(xi[3:6])
    rv = Rotation.from_euler("ZYX", [ang[2], ang[1], ang[0]]).as_matrix()
    psi = psi0 + math.radians(d[3])
    rz = Rotation.from_euler("z", psi).as_matrix()
    return cvm.ORIGIN + d[0:3] + rz @ (xi[0:3] + rv @ p)


def main():
    rodyn, input_dir, work = sys.argv[1:4]
    section = os.path.join(input_dir, "paper_cable_section.inc")
    plain = cvm.run(rodyn, os.path.join(work, "plain"), section, "DEG")
    card = ("*VESSEL, NAME=SHIP, TYPE=TABLE, INPUT=vessel_motion.csv, ROTATION UNITS=DEG, "
            "OFFSET START=DYNAMIC, "
            f"OFFSET X={OFFSET[0]}, OFFSET Y={OFFSET[1]}, OFFSET Z={OFFSET[2]}, "
            f"OFFSET HEADING={OFFSET[3]}, DRIFT X={DRIFT[0]}, DRIFT Y={DRIFT[1]}, "
            f"DRIFT YAW={DRIFT[3]}, DRIFT PERIOD={DRIFT_T}, DRIFT PHASE={DRIFT_PHASE}")
    deck = f"""*HEADING
Paper cable hung from a vessel with a static offset and a drift
{cvm.CABLE}{card}
{cvm.vessel_end()}"""
    workdir = os.path.join(work, "drift")
    cvm.run(rodyn, workdir, section, "DEG")  # writes the motion table into workdir
    frames = cvm.run_deck(rodyn, workdir, "vessel_drift", deck)
    x0 = np.array([0.0, 0.0, 0.0])
    if len(frames) < int(cvm.T_END / cvm.DT):
        sys.exit(f"only {len(frames)} frames written")
    worst = max(float(np.max(np.abs(x - expected(t, x0)))) for t, x in frames.items())
    moved = max(float(np.linalg.norm(frames[t] - plain[t])) for t in frames)
    print(f"end A with OFFSET and DRIFT against the closed form: max error {worst:.3e} m "
          f"over {len(frames)} frames; moved by up to {moved:.3f} m against the deck "
          "without them")
    ok = worst <= 1e-9 and moved > 1.0
    # OFFSET START=STATIC (the default): the offset in the static solution
    deck = deck.replace("OFFSET START=DYNAMIC, ", "")
    frames = cvm.run_deck(rodyn, workdir, "vessel_drift_static", deck)
    with open(os.path.join(workdir, "out", "static_nodes.csv")) as f:
        row = next(r for r in csv.DictReader(f) if int(r["node"]) == 1)
        xs = np.array([float(row["x_m"]), float(row["y_m"]), float(row["z_m"])])
    c, s_ = math.cos(math.radians(cvm.HEADING)), math.sin(math.radians(cvm.HEADING))
    p = np.array([[c, s_, 0.0], [-s_, c, 0.0], [0.0, 0.0, 1.0]]) @ (x0 - cvm.ORIGIN)
    rz = Rotation.from_euler("z", math.radians(cvm.HEADING + OFFSET[3])).as_matrix()
    x_off = cvm.ORIGIN + np.array(OFFSET[0:3]) + rz @ p
    err_static = float(np.max(np.abs(xs - x_off)))
    worst_s = max(float(np.max(np.abs(x - expected(t, x0, True)))) for t, x in frames.items())
    print(f"OFFSET START=STATIC: static end A against O + offset + Rz p: {err_static:.3e} m "
          f"(moved {np.linalg.norm(x_off - x0):.3f} m); frames against the closed form with "
          f"the offset not ramped: max error {worst_s:.3e} m over {len(frames)} frames")
    ok = ok and err_static <= 1e-9 and worst_s <= 1e-9 and len(frames) >= int(cvm.T_END / cvm.DT)
    if not ok:
        sys.exit("FAILED")
    print("PASS")


if __name__ == "__main__":
    main()
