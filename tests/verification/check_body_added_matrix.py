#!/usr/bin/env python3
"""A body's 6 x 6 added mass about R (*BODY ADDED MASS, FORM=MATRIX; docs/theory.md eqs.
(152)-(154)) on decks/body_added_matrix.inp: 1000 kg, inertias 120, 150, 200 kg m2 about
G = R + (0.3, -0.2, -0.4) m, on coupled springs K_R = C about R (no gravity, no line on
the body), a coupled added mass A_R about R. One run:

modes: *MODAL's six periods against 2 pi / sqrt(lambda) of K_R phi = lambda M_R phi,
M_R = T^T diag(m I, J) T + A_R, T = [I, -skew(G - R); 0, I] (numpy), within 1e-8;
static_body_modes.csv's likewise.

motion: the dynamics (EMC, dt 2 ms, 3 s, about 1.5 periods of the slowest mode) from
the deck's position with the velocity (V, W) of R (*INITIAL VELOCITY): R's six
coordinates against the trapezoidal rule's exact
solution of M_R q'' + K_R q = 0, q = sum_k phi_k (phi_k^T M_R u0 / omega_k)
sin(omega~_k t), omega~ = (2/dt) atan(omega dt / 2) (each mode turned by the Cayley
rotation of the rule), within 1e-4 of the largest translation (m) and rotation (rad)
(the motion is of order 1e-4: its nonlinear terms are of order 1e-4 of it); the energy
balance of dynamic_log.csv within 1e-8 of the largest kinetic energy.

Usage: check_body_added_matrix.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

import numpy as np

MASS = 1000.0
INERTIA = (120.0, 150.0, 200.0)
COG = (0.3, -0.2, -0.4)
SPRINGS = [[1.0e5, 0.0, 0.0, 0.0, 2.0e4, 0.0],
           [0.0, 1.2e5, 0.0, -1.5e4, 0.0, 0.0],
           [0.0, 0.0, 0.8e5, 0.0, 0.0, 0.0],
           [0.0, -1.5e4, 0.0, 1.0e4, 0.0, 0.0],
           [2.0e4, 0.0, 0.0, 0.0, 1.2e4, 0.0],
           [0.0, 0.0, 0.0, 0.0, 0.0, 0.9e4]]
ADDED = [[400.0, 30.0, 0.0, 0.0, -150.0, 10.0],
         [30.0, 350.0, 0.0, 140.0, 0.0, 0.0],
         [0.0, 0.0, 200.0, 0.0, 0.0, 20.0],
         [0.0, 140.0, 0.0, 90.0, 0.0, 0.0],
         [-150.0, 0.0, 0.0, 0.0, 100.0, 0.0],
         [10.0, 0.0, 20.0, 0.0, 0.0, 40.0]]
U0 = (2.0e-4, -1.0e-4, 1.5e-4, 1.0e-4, 2.0e-4, -1.5e-4)   # the deck's V, W
DT = 0.002
COLUMNS = ("x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad")


def skew(a):
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


def matrices():
    """K_R and M_R about R."""
    t = np.eye(6)
    t[0:3, 3:6] = -skew(COG)
    m_g = np.diag([MASS] * 3 + list(INERTIA))
    m_r = t.T @ m_g @ t + np.array(ADDED)
    return np.array(SPRINGS), m_r


def check_modes(out, lam, fails):
    closed = sorted((2 * math.pi / math.sqrt(v) for v in lam), reverse=True)
    for name in ("static_modes.csv", "static_body_modes.csv"):
        with open(os.path.join(out, name)) as f:
            periods = [float(r["period_s"]) for r in csv.DictReader(f)]
        if len(periods) != 6:
            fails.append(f"{name}: {len(periods)} modes, not 6")
            continue
        errs = [abs(p / c - 1) for p, c in zip(periods, closed)]
        print(f"{name}: periods {', '.join(f'{p:.10f}' for p in periods)} s; largest "
              f"difference from the generalized eigenvalues {max(errs):.1e}")
        if not max(errs) <= 1e-8:
            fails.append(f"{name}: periods off the closed form by {max(errs):.2e}")


def check_motion(out, m_r, lam, phi, fails):
    with open(os.path.join(out, "dynamic_bodies.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    q = np.array([[float(r[c]) for c in COLUMNS] for r in rows])
    omega = np.sqrt(lam)
    omega_t = 2.0 / DT * np.arctan(omega * DT / 2.0)
    amp = (phi.T @ m_r @ np.array(U0)) / omega
    exact = (np.sin(np.outer(t, omega_t)) * amp) @ phi.T
    err_x = np.abs(q[:, :3] - exact[:, :3]).max() / np.abs(exact[:, :3]).max()
    err_r = np.abs(q[:, 3:] - exact[:, 3:]).max() / np.abs(exact[:, 3:]).max()
    print(f"motion over {t[-1]:.1f} s: R's translation within {err_x:.1e} of its largest "
          f"({np.abs(exact[:, :3]).max():.2e} m), rotation within {err_r:.1e} of its "
          f"largest ({np.abs(exact[:, 3:]).max():.2e} rad)")
    if not (err_x <= 1e-4 and err_r <= 1e-4):
        fails.append(f"motion off the trapezoidal rule's solution by {err_x:.2e}, "
                     f"{err_r:.2e} > 1e-4")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        log = list(csv.DictReader(f))
    total = np.array([float(r["total_J"]) for r in log])
    work = np.array([float(r["external_work_J"]) - float(r["damping_work_J"]) +
                     float(r["hydro_work_J"]) + float(r["seabed_work_J"]) for r in log])
    kinetic = max(float(r["kinetic_J"]) for r in log)
    bal = np.abs((total - total[0]) - (work - work[0])).max() / kinetic
    print(f"energy balance within {bal:.1e} of the largest kinetic energy {kinetic:.3e} J")
    if not bal <= 1e-8:
        fails.append(f"energy balance off by {bal:.2e} of the kinetic energy")


def main():
    rodyn, deck, out = sys.argv[1:4]
    k_r, m_r = matrices()
    lam, phi = np.linalg.eig(np.linalg.solve(m_r, k_r))
    order = np.argsort(lam.real)
    lam, phi = lam.real[order], phi.real[:, order]
    phi = phi / np.sqrt(np.einsum("ik,ij,jk->k", phi, m_r, phi))
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    fails = []
    check_modes(out, lam, fails)
    check_motion(out, m_r, lam, phi, fails)
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
