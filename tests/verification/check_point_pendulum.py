#!/usr/bin/env python3
"""A point-mass pendulum (tests/verification/decks/point_pendulum.inp): a FREE point of
mass M on a stiff cable of length L and mass m per metre from a FIXED point, let go at
rest at a small angle theta0, EMC in vacuum.

Checks (exit 1 on a failure):
1. period: the mean period of the bob's x(t) (its zero crossings, linearly interpolated)
   within 0.5 % of the closed form of a point mass on a uniform rigid rod,
       T = 2 pi sqrt(I / (g (M L + m L^2 / 2))) (1 + theta0^2 / 16),
       I = M L^2 + m L^3 / 3
   (the cable's stretch M g / EA = 1e-5 changes T by 5e-6);
2. length: the distance from the pivot to the bob stays within 2.5 M g / EA of L (the
   cable starts unstretched, so its axial mode swings between no stretch and twice the
   static stretch M g / EA = 9.8e-6);
3. energy: EMC keeps the total energy of the system (line and point) to 1e-9 of its
   scale M g L over the run (the Newton tolerance's level; the swing's own energy
   M g L (1 - cos theta0) is 6.1e-4 of that scale).

Usage: check_point_pendulum.py RODYN DECK OUT_DIR"""
import csv
import math
import os
import subprocess
import sys

M, L, MLINE, THETA0, G, EA = 1000.0, 10.0, 0.1, math.radians(2.0), 9.80665, 1.0e9


def main():
    rodyn, deck, out = sys.argv[1:4]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    t, x, r = [], [], []
    with open(os.path.join(out, "dynamic_nodes.csv")) as f:
        rows = [row for row in csv.DictReader(f) if row["line"] == "ARM"]
    last = max(int(row["node"]) for row in rows)
    for row in rows:
        if int(row["node"]) != last:
            continue
        t.append(float(row["time_s"]))
        xb, zb = float(row["x_m"]), float(row["z_m"])
        x.append(xb)
        r.append(math.hypot(xb, float(row["y_m"]), zb))
    cross = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
             for i in range(len(x) - 1) if x[i] > 0 >= x[i + 1] or x[i] < 0 <= x[i + 1]]
    periods = [2.0 * (b - a) for a, b in zip(cross, cross[1:])]
    period = sum(periods) / len(periods)
    inertia = M * L**2 + MLINE * L**3 / 3.0
    closed = 2 * math.pi * math.sqrt(inertia / (G * (M * L + MLINE * L**2 / 2))) \
        * (1 + THETA0**2 / 16)
    err_t = period / closed - 1
    err_l = max(abs(ri - L) for ri in r) / L
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        total = [float(row["total_J"]) for row in csv.DictReader(f)]
    scale = M * G * L
    err_e = (max(total) - min(total)) / scale
    print(f"period {period:.6f} s over {len(periods)} half-swings, closed form "
          f"{closed:.6f} s: {err_t:+.2e}; length within {err_l:.2e} L; energy drift "
          f"{err_e:.2e} of M g L = {scale:.4g} J")
    fails = []
    if abs(err_t) > 5e-3:
        fails.append(f"period off by {err_t:+.2e} (> 0.5 %)")
    if err_l > 2.5 * M * G / EA:
        fails.append(f"length off by {err_l:.2e} L (> 2.5 M g / EA)")
    if err_e > 1e-9:
        fails.append(f"energy drift {err_e:.2e} (> 1e-9)")
    if len(periods) < 4:
        fails.append(f"only {len(periods)} half-swings")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
