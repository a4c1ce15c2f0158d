#!/usr/bin/env python3
"""The stiffness of a system at its FREE points (static_stiffness.csv: the consistent
tangent condensed onto the points, docs/theory.md (133)) on the crowfoot of
tests/verification/decks/crowfoot_stiffness.inp: three legs of 420 m, partly grounded,
from anchors at 400 m to a buoyant hub pulled by 50 kN along +x.

1. Finite differences (240 cubic elements a leg, Newton to 1e-13): the hub's load
   changed by +-dF = 1 N along x, y and z, the central difference of its equilibrium
   position gives the compliance C; K C equals the identity to 1e-6 (largest entry of
   K C - I; measured 1.0e-8, and 5.2e-7 with dF = 10 N, 5.2e-5 with 100 N: the
   difference's own error, second order in dF, as it should be for a consistent
   tangent).
2. MoorPy 1.3.0 (bench/results/moorpy_points.csv, the analytic Point.getStiffnessA of the
   same hub; MoorPy need not be installed): with 960 elements a leg every entry within
   1e-4 of the largest entry. The legs' touchdown moves along the seabed with the hub: on
   the discrete line it moves from node to node, so the stiffness converges unevenly
   under refinement (measured: largest difference 8.0e-3 at 120 elements, 2.6e-3 at
   240, 1.5e-4 at 480, 4.0e-5 at 960; docs/systems.md).

Usage: check_point_stiffness.py RODYN DECK RESULTS_CSV OUT_DIR [--no-moorpy]"""
import csv
import os
import sys

import numpy as np

from stiffness_lib import read_stiffness, run_rodyn

DF = 1.0
FX = 50000.0


def run(rodyn, deck, out, **params):
    run_rodyn(rodyn, deck, out, params)
    with open(os.path.join(out, "static_points.csv")) as f:
        hub = [r for r in csv.DictReader(f) if r["point"] == "HUB"][0]
    x = np.array([float(hub[c]) for c in ("x_m", "y_m", "z_m")])
    return x, read_stiffness(out, "HUB", 3)


def main():
    rodyn, deck, results, out = sys.argv[1:5]
    fails = []
    _, k = run(rodyn, deck, os.path.join(out, "base"), NE=240)
    comp = np.zeros((3, 3))
    for j, name in enumerate(("FX", "FY", "FZ")):
        base = {"FX": FX, "FY": 0.0, "FZ": 0.0}
        xs = []
        for sign in (1, -1):
            p = dict(base)
            p[name] = base[name] + sign * DF
            xs.append(run(rodyn, deck, os.path.join(out, f"{name}{sign:+d}"), NE=240, **p)[0])
        # the load is on the hub: F_lines = -load, so dx/dload = K^-1
        comp[:, j] = (xs[0] - xs[1]) / (2 * DF)
    dev = np.abs(k @ comp - np.eye(3)).max()
    print(f"finite differences (dF = {DF:g} N): largest entry of K C - I {dev:.2e}")
    if not dev <= 1e-6:
        fails.append(f"K C - I = {dev:.2e} (> 1e-6)")
    if "--no-moorpy" not in sys.argv:
        ref = np.zeros((3, 3))
        with open(results) as f:
            for r in csv.DictReader(line for line in f if not line.startswith("#")):
                if r["case"] == "crowfoot" and r["quantity"].startswith("HUB.K_"):
                    a, b = r["quantity"][-2:]
                    ref["xyz".index(a), "xyz".index(b)] = float(r["value"])
        _, k960 = run(rodyn, deck, os.path.join(out, "fine"), NE=960)
        diff = np.abs(k960 - ref).max() / np.abs(ref).max()
        print("rodyn (960 elements a leg):\n", np.array2string(k960, precision=2))
        print("MoorPy 1.3.0:\n", np.array2string(ref, precision=2))
        print(f"largest difference {diff:.2e} of the largest entry")
        if not diff <= 1e-4:
            fails.append(f"stiffness differs from MoorPy's by {diff:.2e} (> 1e-4)")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
