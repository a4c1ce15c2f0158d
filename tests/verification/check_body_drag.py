#!/usr/bin/env python3
"""A body's quadratic drag (*BODY DRAG; docs/theory.md eq. (149)) on
decks/body_drag.inp: a body of 1000 kg on a heave spring of 1e5 N/m with a heave drag
c = 1/2 rho_w CdA3 = 500 kg/m, released 0.1 m above its equilibrium. Its heave (R's z
less the equilibrium -m g / k) against an independent integration of m z'' + c |z'| z'
+ k z = 0 (scipy's solve_ivp, tolerances 1e-12) over 5 s (8 periods): within 2e-3 of
the release offset at dt = 2.5 ms; the error falls with dt halved by at least 3 (second
order); the motion decays (the last period's amplitude below 0.6 of the release's: the
drag acts). EMC's energy identity with the drag's work is checked by the run at every
step (a step breaking it would be cut back: none is).

Usage: check_body_drag.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

M, K, C, G = 1000.0, 1.0e5, 500.0, 9.80665


def heave_error(rodyn, deck, out, dt):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", "--set", f"DT={dt}"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_bodies.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        cuts = sum(int(r["cutbacks"]) for r in csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    z = np.array([float(r["z_m"]) for r in rows]) + M * G / K
    ref = solve_ivp(lambda _, y: [y[1], (-K * y[0] - C * abs(y[1]) * y[1]) / M],
                    [0.0, t[-1]], [z[0], 0.0], t_eval=t, rtol=1e-12, atol=1e-14).y[0]
    return np.max(np.abs(z - ref)) / z[0], np.max(np.abs(z[t > t[-1] - 0.63])) / z[0], cuts


def main():
    rodyn, deck, out = sys.argv[1:4]
    fails = []
    e1, last, cuts = heave_error(rodyn, deck, os.path.join(out, "dt1"), 0.0025)
    e2, _, cuts2 = heave_error(rodyn, deck, os.path.join(out, "dt2"), 0.00125)
    print(f"heave against the integrated ODE: {e1:.2e} of the offset at dt 2.5 ms, "
          f"{e2:.2e} at 1.25 ms (ratio {e1 / e2:.2f}); last period's amplitude "
          f"{last:.3f} of the offset; cut-backs {cuts + cuts2}")
    if not e1 <= 2e-3:
        fails.append(f"heave off by {e1:.2e} of the offset")
    if not e1 / e2 >= 3.0:
        fails.append(f"error ratio {e1 / e2:.2f} with dt halved (second order: 4)")
    if not last < 0.6:
        fails.append(f"the motion does not decay ({last:.3f})")
    if cuts + cuts2:
        fails.append(f"{cuts + cuts2} steps cut back (the energy identity broken?)")
    for msg in fails:
        print("FAIL:", msg)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
