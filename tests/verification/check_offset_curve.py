#!/usr/bin/env python3
"""The offset-restoring-force curve of a body (*OFFSET CURVE, static_offset_curve.csv) on
the OC3-Hywind spar (tests/verification/decks/spar_offset_curve.inp): a horizontal force at
R along +x raised to 1 MN in 4 steps from the mean equilibrium. Checks:
1. the last point against MoorPy 1.3.0's equilibrium of the same body under 1 MN
   (bench/results/moorpy_spar.csv, case offset_system): x and z of R within 1e-5 of the
   line length (902.2 m), the pitch within 1e-5 rad (bench/systems/moorpy_spar.py's
   tolerances);
2. the curve rises: offset and force grow together, step by step, and the offset is
   along the force (y of R within 1e-9 m).

Usage: check_offset_curve.py RODYN DECK RESULTS_CSV OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys

LENGTH = 902.2


def main():
    rodyn, deck, results, out = sys.argv[1:5]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "static_offset_curve.csv")) as f:
        rows = list(csv.DictReader(f))
    ref = {}
    with open(results) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            if r["case"] == "offset_system" and r["source"].startswith("moorpy"):
                ref[r["quantity"]] = float(r["value"])
    last = rows[-1]
    fails = []
    for q, col, scale in (("SPAR.x", "x_m", LENGTH), ("SPAR.z", "z_m", LENGTH),
                          ("SPAR.ry", "ry_rad", 1.0)):
        e = abs(float(last[col]) - ref[q]) / scale
        print(f"{q} at {float(last['force_N']):.4g} N: rodyn {float(last[col]):.9g}, MoorPy "
              f"{ref[q]:.9g}: {e:.2e}")
        if not e <= 1e-5:
            fails.append(f"{q} off by {e:.2e} (> 1e-5)")
    off = [float(r["offset_m"]) for r in rows]
    force = [float(r["force_N"]) for r in rows]
    print("curve (force N, offset m): " + ", ".join(f"({f:.3g}, {o:.4g})"
                                                     for f, o in zip(force, off)))
    if not all(b > a for a, b in zip(off, off[1:])) or \
            not all(b > a for a, b in zip(force, force[1:])):
        fails.append("the curve does not rise step by step")
    if max(abs(float(r["y_m"])) for r in rows) > 1e-9:
        fails.append("the offset leaves the force's direction")
    if len(rows) != 5:
        fails.append(f"{len(rows)} points, not 5")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
