#!/usr/bin/env python3
"""The stiffness of a system at a FREE body (static_stiffness.csv: the consistent
tangent condensed onto the body's six unknowns and taken to its reference point R,
docs/theory.md (133), (140)) against finite differences of the static solution: each of
the six components of a load on the body at R (*LOAD, BODY=: parameters FX ... MZ of the
deck) changed by +-dF, the central difference of R's position and rotation vector
(static_bodies.csv) gives the compliance C; K C equals the identity to TOL (largest entry
of K C - I).

Usage: check_body_stiffness.py RODYN DECK OUT_DIR BODY DF DM [TOL]
(DF [N] the force step, DM [N m] the moment step; TOL default 1e-6). Exit 0 on success."""
import csv
import os
import sys

import numpy as np

from stiffness_lib import read_stiffness, run_rodyn

PARAMS = ("FX", "FY", "FZ", "MX", "MY", "MZ")


def run(rodyn, deck, out, body, **params):
    run_rodyn(rodyn, deck, out, params)
    with open(os.path.join(out, "static_bodies.csv")) as f:
        row = [r for r in csv.DictReader(f) if r["body"] == body][0]
    q = np.array([float(row[c]) for c in ("x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad")])
    return q, read_stiffness(out, body, 6)


def main():
    rodyn, deck, out, body, df, dm = sys.argv[1:7]
    tol = float(sys.argv[7]) if len(sys.argv) > 7 else 1e-6
    steps = [float(df)] * 3 + [float(dm)] * 3
    _, k = run(rodyn, deck, os.path.join(out, "base"), body)
    comp = np.zeros((6, 6))
    for j, name in enumerate(PARAMS):
        qs = [run(rodyn, deck, os.path.join(out, f"{name}{s:+d}"), body,
                  **{name: s * steps[j]})[0] for s in (1, -1)]
        comp[:, j] = (qs[0] - qs[1]) / (2 * steps[j])
    dev = np.abs(k @ comp - np.eye(6)).max()
    print("K (about R):\n", np.array2string(k, precision=4))
    print(f"finite differences (dF = {df} N, dM = {dm} N m): largest entry of K C - I "
          f"{dev:.2e}")
    if not dev <= tol:
        print(f"FAIL: K C - I = {dev:.2e} (> {tol})")
        sys.exit(1)


if __name__ == "__main__":
    main()
