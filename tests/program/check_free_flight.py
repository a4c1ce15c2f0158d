#!/usr/bin/env python3
"""Free flight of two rods without supports, without rotary inertia (no OD, no RHOI):
tests/decks/good/dynamic_free_flight.inp run to its end, with MIDPOINT, which conserves
linear and angular momentum exactly (the Newton tolerance aside; docs/dynamics.md).

The roll of such a rod about its centreline has neither inertia nor stiffness: a null
vector of the step's tangent. Before the dynamics took the statics' roll gauge (the
iteration matrix only, rodyn_statics' header), the deck stopped at t = 2.3e-3 s with
corrections of 1e11 and "no convergence after 6 halvings".

Usage: check_free_flight.py RODYN DECK OUT_DIR. Exit 0 when the run completes every step
and px, py, pz, Lx, Ly, Lz of dynamic_log.csv stay within TOL of their scale."""
import csv
import os
import subprocess
import sys

TOL = 1.0e-8


def main():
    rodyn, deck, out = sys.argv[1:4]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        rows = list(csv.DictReader(f))
    ok = abs(float(rows[-1]["time_s"]) - 1.0) < 1e-9
    print(f"{rows[-1]['step']} steps to t = {rows[-1]['time_s']} s")
    for group in (("px", "py", "pz"), ("Lx", "Ly", "Lz")):
        scale = max(abs(float(rows[0][c])) for c in group)
        for c in group:
            v = [float(r[c]) for r in rows]
            drift = (max(v) - min(v)) / scale
            print(f"{c}: {v[0]:+.6e}, largest change {drift:.2e} of {scale:.4g}")
            ok = ok and drift <= TOL
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
