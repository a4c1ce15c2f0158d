#!/usr/bin/env python3
"""input/mooring_waves.inp, shortened: the fairlead follows the FPSO's RAO motion.

    check_mooring_waves.py RODYN INPUT_DIR WORK_DIR [T_END]

The deck (the mooring leg's fairlead on the MSS FPSO, input/fpso_rao.csv with
PHASE=LEAD, in a regular wave of 4 m and 11.48 s towards +x, vessel heading 30 deg: a
relative heading of 330 deg, a mirrored heading of the table) is run for T_END s (default
20) with --set. End B's position in every frame is held against the closed form computed
here from the table's row (11.48 s, 330 deg):

  xi_k(t) = r(t) a R_k cos(omega t - k O_x + eps_k)   (the wave's phase at O, a lead eps_k)
  X(t)    = O + R0 (xi_1-3 + Rz(yaw) Ry(pitch) Rx(roll) p),   p = R0^T (x0 - O),

r the wave's ramp (1 - cos(pi t/RAMP))/2, k from the dispersion relation at 100 m
(scipy's brentq), rotations by scipy's Rotation. Tolerance 1e-9 m. The same with the
phases taken as lags instead (the wrong convention) must be off by more than 0.5 m, so
the test tells the two apart. The fairlead tension must stay positive and finite.
"""
import csv
import math
import os
import subprocess
import sys

import numpy as np
from scipy.optimize import brentq
from scipy.spatial.transform import Rotation

ORIGIN = np.array([82.0, 47.0, 0.0])
HEADING = 30.0
WAVE_H, WAVE_T, WAVE_DIR, RAMP, DEPTH, G = 4.0, 11.48, 0.0, 22.96, 100.0, 9.80665
X0 = np.array([0.0, 0.0, -10.0])


def table_row(path, period, heading):
    with open(path) as fh:
        for line in fh:
            s = line.strip()
            if not s or s.startswith("#") or s.startswith("period"):
                continue
            v = [float(x) for x in s.split(",")]
            if abs(v[0] - period) < 1e-9 and abs(v[1] - heading) < 1e-9:
                return np.array(v[2:8]), np.radians(v[8:14])
    sys.exit(f"no row {period} s, {heading} deg in {path}")


def expected(t, amp, eps, sign):
    omega = 2 * math.pi / WAVE_T
    k = brentq(lambda kk: omega**2 - G * kk * math.tanh(kk * DEPTH), 1e-8, 10.0,
               xtol=1e-15, rtol=1e-15)
    beta = math.radians(WAVE_DIR)
    phi_o = -k * (math.cos(beta) * ORIGIN[0] + math.sin(beta) * ORIGIN[1])
    r = 1.0 if t >= RAMP else 0.5 * (1.0 - math.cos(math.pi * t / RAMP))
    xi = r * (WAVE_H / 2) * amp * np.cos(omega * t + phi_o + sign * eps)
    c, s = math.cos(math.radians(HEADING)), math.sin(math.radians(HEADING))
    r0 = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    p = r0.T @ (X0 - ORIGIN)
    ang = np.radians(xi[3:6])
    rv = Rotation.from_euler("ZYX", [ang[2], ang[1], ang[0]]).as_matrix()
    return ORIGIN + r0 @ (xi[0:3] + rv @ p)


def main():
    rodyn, inputs, work = sys.argv[1:4]
    t_end = float(sys.argv[4]) if len(sys.argv) > 4 else 20.0
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "out")
    proc = subprocess.run([rodyn, os.path.join(inputs, "mooring_waves.inp"), "-o", out,
                           "--quiet", "--set", f"T_END={t_end:g}"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    amp, eps = table_row(os.path.join(inputs, "fpso_rao.csv"), WAVE_T, 330.0)
    frames = {}
    with open(os.path.join(out, "dynamic_nodes.csv")) as fh:
        rows = list(csv.DictReader(fh))
    last = max(int(r["node"]) for r in rows)
    for r in rows:
        if int(r["node"]) == last:
            frames[float(r["time_s"])] = np.array(
                [float(r["x_m"]), float(r["y_m"]), float(r["z_m"])])
    err = max(np.linalg.norm(x - expected(t, amp, eps, +1)) for t, x in frames.items())
    wrong = max(np.linalg.norm(x - expected(t, amp, eps, -1)) for t, x in frames.items())
    travel = max(np.linalg.norm(x - X0) for x in frames.values())
    fails = []
    print(f"fairlead against the RAO motion (leads): {err:.2e} m over {len(frames)} "
          f"frames, the fairlead travelling up to {travel:.3f} m")
    if not err < 1e-9:
        fails.append("fairlead not on the RAO motion")
    print(f"the same with the phases taken as lags: {wrong:.3f} m off")
    if not wrong > 0.5:
        fails.append("lead and lag not told apart")
    with open(os.path.join(out, "dynamic_ends.csv")) as fh:
        ten = [float(r["tension_N"]) for r in csv.DictReader(fh) if r["end"] == "B"]
    print(f"fairlead tension {min(ten):.0f} .. {max(ten):.0f} N")
    if not all(math.isfinite(x) and x > 0 for x in ten):
        fails.append("fairlead tension not positive and finite")
    if travel < 0.1:
        fails.append("the fairlead hardly moved")
    for f in fails:
        print("FAIL " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
