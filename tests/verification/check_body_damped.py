#!/usr/bin/env python3
"""A body on linear springs with linear damping (tests/verification/decks/body_damped.inp):
mass m = 1000 kg, heave stiffness k = 1e5 N/m (*BODY HYDROSTATICS), heave damping
c = 1000 N s/m (*BODY DAMPING; zeta = c / (2 sqrt(k m)) = 0.05), released from z0 = 0.1 m
at rest, EMC with dt = 0.0025 s. Closed form:
    z(t) = z0 exp(-zeta w t) (cos(w_d t) + zeta / sqrt(1 - zeta^2) sin(w_d t)),
    w = sqrt(k / m), w_d = w sqrt(1 - zeta^2).
Checks (dynamic_bodies_step.csv, dynamic_log.csv):
1. the heave history within 1e-3 z0 of the closed form at every step (5 s, 8 periods);
2. the energy balance: the springs (*BODY HYDROSTATICS) are a load whose work is booked
   as hydro_work_J, and total_J (kinetic and strain) is 0 at the start (at rest), so
   total_J - hydro_work_J + damping_work_J = 0 at every step, to 1e-9 of k z0^2/2; and the
   damping's work at the end within 1e-3 of the energy the closed form has lost.

With NAME=VALUE arguments (the deck's parameters A11 ... A66: *BODY ADDED MASS), the
same with the added mass: m is 1000 kg + A33 in the closed form.

Usage: check_body_damped.py RODYN DECK OUT_DIR [NAME=VALUE ...]. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

import numpy as np

M, K, C, Z0 = 1000.0, 1.0e5, 1000.0, 0.1


def main():
    rodyn, deck, out = sys.argv[1:4]
    sets = []
    added = {}
    for arg in sys.argv[4:]:
        sets += ["--set", arg]
        k, v = arg.split("=")
        added[k] = float(v)
    m = M + added.get("A33", 0.0)
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", *sets], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_bodies_step.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    z = np.array([float(r["z_m"]) for r in rows])
    w = math.sqrt(K / m)
    zeta = C / (2 * math.sqrt(K * m))
    wd = w * math.sqrt(1 - zeta**2)
    ref = Z0 * np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta / math.sqrt(1 - zeta**2)
                                         * np.sin(wd * t))
    err = np.abs(z - ref).max() / Z0
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        log = list(csv.DictReader(f))
    e0 = 0.5 * K * Z0**2
    bal = [float(r["total_J"]) - float(r["hydro_work_J"]) + float(r["damping_work_J"])
           for r in log]
    e_bal = max(abs(b) for b in bal) / e0
    vz = np.gradient(ref, t)
    lost = e0 - (0.5 * K * ref[-1]**2 + 0.5 * m * vz[-1]**2)
    e_work = abs(float(log[-1]["damping_work_J"]) - lost) / e0
    print(f"heave within {err:.2e} z0 of the closed form over {len(t) - 1} steps; energy "
          f"balance within {e_bal:.2e} of k z0^2/2; damping work {float(log[-1]['damping_work_J']):.4f} J "
          f"against {lost:.4f} J lost in the closed form ({e_work:.2e} of k z0^2/2)")
    fails = []
    if not err <= 1e-3:
        fails.append(f"heave off by {err:.2e} z0 (> 1e-3)")
    if not e_bal <= 1e-9:
        fails.append(f"energy balance off by {e_bal:.2e} (> 1e-9)")
    if not e_work <= 1e-3:
        fails.append(f"damping work off by {e_work:.2e} (> 1e-3)")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
