#!/usr/bin/env python3
"""A body's first-order wave load (*BODY WAVE LOAD; tests/verification/decks/
body_wave_load.inp): a neutrally buoyant body on linear springs and dampers about its
reference point R, with G off R and an added mass at G, in a regular wave (H 2 m, T 5 s,
heading 30 deg, phase 40 deg, 100 m of water), driven by a table of force and moment
amplitudes and phase lags at 4 and 6 s, 0 and 60 deg (so that the load at 5 s, 30 deg is
the mean of the four corners' complex values).

Closed form (docs/theory.md eq. (150)): with the elevation a cos(w t + phi) at R's
position R_s at the start of the dynamics, phi = -(k . R_s) - phase, the load at R is
Re(a X exp(i phi) exp(i w t)), X = R exp(-i eps) for a lag eps. The body's linear
equations about R, q = (x_R - R_s, theta):
    M_R q'' + B q' + C q = F,   M_R = T^T M_G T,   T = [I, -skew(r_G); 0, I],
M_G = diag(m + A1..3, I_G + A4..6), r_G = G - R; the steady response Re(Q exp(i w t)),
Q = (C - w^2 M_R + i w B)^-1 a X exp(i phi).

Checks:
1. the first harmonic of each of the six motions of R (dynamic_bodies_step.csv: x, y, z
   and the rotation vector), fitted by least squares over 15-25 s (the sea's ramp ends
   at 10 s; the slowest transient has decayed by e^-8 by 15 s), within 2e-4 of the
   closed form's Q_k (|Q_fit - Q_k| / |Q_k|); what is left after the fit within 1e-4 of
   the amplitude for the translations, and for the rotations within 3 theta_max^2, the
   second-order scale of a rotation vector turning about several axes at once (its mean
   and its double frequency);
2. the energy balance of dynamic_log.csv (EMC: the wave's work is booked with the
   water's): the change of total energy less the works within 1e-6 of the largest work;
3. the same table written as phase leads (PHASE=LEAD, phases negated) and read from a
   file (INPUT=) gives the same motions to the last digit;
4. a run with checkpoints killed after step 1300 and restarted (rodyn --restart) ends
   with the same dynamic_bodies_step.csv, byte for byte, as the run not interrupted.

Usage: check_body_wave_load.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import re
import subprocess
import sys

import numpy as np

G = 9.80665
DEPTH = 100.0
A, T, HEADING, PHASE = 1.0, 5.0, 30.0, 40.0
MASS, INERTIA = 1000.0, np.array([100.0, 120.0, 140.0])
ADDED = np.array([300.0, 300.0, 300.0, 10.0, 20.0, 30.0])
R_G = np.array([0.3, -0.2, 0.4])
C = np.diag([1.0e5, 1.2e5, 1.5e5, 1.0e4, 1.2e4, 1.4e4])
B = np.diag([4000.0, 4800.0, 6000.0, 1500.0, 1800.0, 2100.0])
COLS = ["x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad"]


def run(rodyn, deck, out):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode} on {deck}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_bodies_step.csv")) as f:
        return list(csv.DictReader(f))


def table_rows(text):
    """The 14-value rows of the deck's *BODY WAVE LOAD card."""
    block = text.split("*BODY WAVE LOAD")[2].split("\n*")[0]
    return [[float(v) for v in line.split(",")] for line in block.splitlines()[1:]
            if line.strip() and not line.startswith("**")]


def wave_number(omega):
    k = omega**2 / G
    for _ in range(100):
        k = omega**2 / (G * math.tanh(k * DEPTH))
    return k


def closed_form(rows, rs):
    omega = 2 * math.pi / T
    k = wave_number(omega)
    beta = math.radians(HEADING)
    x = np.zeros(6, complex)
    for r in rows:               # the four corners, each weighted 1/4
        x += np.array(r[2:8]) * np.exp(-1j * np.radians(r[8:14])) / 4
    phi = -(k * math.cos(beta) * rs[0] + k * math.sin(beta) * rs[1]) - math.radians(PHASE)
    f = A * x * np.exp(1j * phi)
    mg = np.diag(np.concatenate([MASS + ADDED[:3], INERTIA + ADDED[3:]]))
    sk = np.array([[0, -R_G[2], R_G[1]], [R_G[2], 0, -R_G[0]], [-R_G[1], R_G[0], 0]])
    tr = np.eye(6)
    tr[:3, 3:] = -sk
    mr = tr.T @ mg @ tr
    return np.linalg.solve(C - omega**2 * mr + 1j * omega * B, f), omega


def variants(deck, out, rows):
    """The deck with the table as leads, and with the table in a file."""
    text = open(deck).read()
    head, rest = text.split("*BODY WAVE LOAD, BODY=BOX, PHASE=LAG\n")
    tail = rest[rest.index("*POINT"):]
    lead = "".join(", ".join(repr(v) for v in r[:8] + [-p for p in r[8:]]) + "\n"
                   for r in rows)
    os.makedirs(out, exist_ok=True)
    d_lead = os.path.join(out, "lead.inp")
    open(d_lead, "w").write(head + "*BODY WAVE LOAD, BODY=BOX, PHASE=LEAD\n" + lead + tail)
    table = os.path.join(out, "load_rao.csv")
    open(table, "w").write("period, heading, amplitudes, phases\n" + "".join(
        ", ".join(repr(v) for v in r) + "\n" for r in rows))
    d_file = os.path.join(out, "file.inp")
    open(d_file, "w").write(head + "*BODY WAVE LOAD, BODY=BOX, INPUT=load_rao.csv\n" + tail)
    return d_lead, d_file


def restart_same(rodyn, deck, out):
    """A run with checkpoints, killed and restarted, against one not interrupted."""
    text = open(deck).read().replace("OUTPUT INTERVAL=0.5,", "OUTPUT INTERVAL=0.5, CHECKPOINT=5.0,")
    d = os.path.join(out, "checkpoints.inp")
    open(d, "w").write(text)
    full, cut = os.path.join(out, "full"), os.path.join(out, "killed")
    run(rodyn, d, full)
    env = dict(os.environ, RODYN_TEST_KILL_AFTER_STEP="1300")
    proc = subprocess.run([rodyn, d, "-o", cut, "--quiet"], env=env, capture_output=True)
    if proc.returncode == 0:
        print("restart: the run was not killed")
        return False
    proc = subprocess.run([rodyn, d, "--restart", cut, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        print(f"restart: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
        return False
    same = all(open(os.path.join(full, f), "rb").read() == open(os.path.join(cut, f),
                                                                  "rb").read()
               for f in ("dynamic_bodies_step.csv", "dynamic_log.csv"))
    print(f"restart: {'the same' if same else 'DIFFERENT'} body motions and log")
    return same


def main():
    rodyn, deck, out = sys.argv[1:4]
    rows = table_rows(open(deck).read())
    if len(rows) != 4:
        sys.exit(f"FAIL: expected 4 table rows in the deck, found {len(rows)}")
    steps = run(rodyn, deck, os.path.join(out, "lag"))
    rs = np.array([float(steps[0][c]) for c in COLS[:3]])
    q_ref, omega = closed_form(rows, rs)
    t = np.array([float(r["time_s"]) for r in steps])
    q = np.array([[float(r[c]) for c in COLS] for r in steps])
    q[:, :3] -= rs
    win = t >= 15.0
    basis = np.c_[np.cos(omega * t[win]), -np.sin(omega * t[win])]
    theta_max = np.abs(q_ref[3:]).max()
    ok = True
    for j, c in enumerate(COLS):
        fit, *_ = np.linalg.lstsq(basis, q[win, j], rcond=None)
        err = abs(complex(fit[0], fit[1]) - q_ref[j]) / abs(q_ref[j])
        rest = np.abs(q[win, j] - basis @ fit).max()
        bound = 1e-4 * abs(q_ref[j]) if j < 3 else 3.0 * theta_max**2
        print(f"{c}: amplitude {abs(q_ref[j]):.5e}, first harmonic off by {err:.3e} of it;"
              f" the rest {rest:.3e} (bound {bound:.3e})")
        ok &= err <= 2e-4 and rest <= bound
    with open(os.path.join(out, "lag", "dynamic_log.csv")) as f:
        log = list(csv.DictReader(f))
    tot = np.array([float(r["total_J"]) for r in log])
    work = np.array([float(r["external_work_J"]) + float(r["hydro_work_J"])
                     + float(r["seabed_work_J"]) - float(r["damping_work_J"])
                     - float(r["numerical_work_J"]) for r in log])
    scale = max(np.abs(np.array([float(r["hydro_work_J"]) for r in log])).max(),
                np.abs(np.array([float(r["damping_work_J"]) for r in log])).max())
    bal = np.abs((tot - tot[0]) - (work - work[0])).max() / scale
    print(f"energy balance: {bal:.3e} of the largest work ({scale:.4e} J)")
    ok &= bal <= 1e-6
    d_lead, d_file = variants(deck, out, rows)
    for name, d in (("PHASE=LEAD", d_lead), ("INPUT=file", d_file)):
        same = run(rodyn, d, os.path.join(out, re.sub(r"\W", "_", name))) == steps
        print(f"{name}: {'the same motions' if same else 'DIFFERENT motions'}")
        ok &= same
    ok &= restart_same(rodyn, deck, out)
    if not ok:
        sys.exit("FAIL")
    print("PASS")


if __name__ == "__main__":
    main()
