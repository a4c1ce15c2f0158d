#!/usr/bin/env python3
"""A compound pendulum (tests/verification/decks/body_pendulum.inp): a rigid body of
mass m and inertia I about G, hung at a point h above G by a stiff cable of length a from
a FIXED point, let go at rest with the cable at phi0 and the body upright, in vacuum.

The linear double pendulum (cable angle phi, body angle theta; the cable's mass, 20 g
against 1000 kg, and stretch, 2e-4 m, left out):
    M = [[m a^2, m a h], [m a h, m h^2 + I]],  K = diag(m g a, m g h),
    q(t) = sum_k c_k v_k cos(omega_k t),  q(0) = (phi0, 0),
from the generalized eigenproblem K v = omega^2 M v. From dynamic_bodies_step.csv over
20 s (about 6 periods of the slow mode, 18 of the fast): phi = atan(x_R / -z_R) and theta
= -ry (the body's rotation about y) are each fitted by two cosines (least squares on the
amplitudes and frequencies); the two periods within 1e-3 of the closed form's and each
mode's amplitudes in phi and theta within 1 % of the largest (the modes' shapes and the
start).

Usage: check_body_pendulum.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import least_squares

M, I, H, A, G = 1000.0, 500.0, 1.0, 2.0, 9.80665
PHI0 = math.radians(1.0)
TOL_PERIOD = 1e-3
TOL_AMP = 0.01


def fit(t, y, guess):
    """(amplitudes, periods) of y(t) = a1 cos(w1 t) + a2 cos(w2 t), from guess."""
    def res(p):
        return p[0] * np.cos(p[1] * t) + p[2] * np.cos(p[3] * t) - y
    p = least_squares(res, guess, xtol=1e-14, ftol=1e-14).x
    return np.array([p[0], p[2]]), 2 * math.pi / np.array([p[1], p[3]])


def main():
    rodyn, deck, out = sys.argv[1:4]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    t, phi, theta = [], [], []
    with open(os.path.join(out, "dynamic_bodies_step.csv")) as f:
        for r in csv.DictReader(f):
            t.append(float(r["time_s"]))
            phi.append(math.atan2(float(r["x_m"]), -float(r["z_m"])))
            theta.append(-float(r["ry_rad"]))
    t, phi, theta = map(np.array, (t, phi, theta))
    mm = np.array([[M * A * A, M * A * H], [M * A * H, M * H * H + I]])
    kk = np.diag([M * G * A, M * G * H])
    w2, v = eigh(kk, mm)
    c = np.linalg.solve(v, [PHI0, 0.0])
    periods = 2 * math.pi / np.sqrt(w2)
    amp = v * c                  # amp[i, k]: mode k's amplitude in phi (i = 0), theta (1)
    fails = []
    for i, (name, y) in enumerate((("phi", phi), ("theta", theta))):
        guess = [amp[i, 0], math.sqrt(w2[0]), amp[i, 1], math.sqrt(w2[1])]
        a, p = fit(t, y, guess)
        e_p = np.abs(p / periods - 1).max()
        e_a = np.abs(a - amp[i]).max() / np.abs(amp[i]).max()
        print(f"{name}: periods {p[0]:.5f} s, {p[1]:.5f} s (closed form {periods[0]:.5f}, "
              f"{periods[1]:.5f}): within {e_p:.2e}; amplitudes {a[0]:+.5f}, {a[1]:+.5f} "
              f"rad (closed form {amp[i, 0]:+.5f}, {amp[i, 1]:+.5f}): within {e_a:.2e}")
        if not e_p <= TOL_PERIOD:
            fails.append(f"{name}: periods off by {e_p:.2e} (> {TOL_PERIOD})")
        if not e_a <= TOL_AMP:
            fails.append(f"{name}: amplitudes off by {e_a:.2e} (> {TOL_AMP})")
    if abs(t[-1] - 20.0) > 1e-9:
        fails.append(f"the run stopped at {t[-1]} s")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
