"""What the stiffness checks share (check_point_stiffness.py, check_body_stiffness.py):
a static run of rodyn with parameters set, and the stiffness of one object read from its
static_stiffness.csv (docs/output.md)."""
import csv
import os
import subprocess
import sys

import numpy as np

DOFS = ("x", "y", "z", "rx", "ry", "rz")


def run_rodyn(rodyn, deck, out, params):
    """Run rodyn on deck into out with --set NAME=VALUE for each of params; exit on failure."""
    sets = []
    for k, v in params.items():
        sets += ["--set", f"{k}={v}"]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", *sets], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")


def read_stiffness(out, name, n):
    """The n x n block of static_stiffness.csv (column `stiffness`) of object `name`."""
    k = np.zeros((n, n))
    with open(os.path.join(out, "static_stiffness.csv")) as f:
        for r in csv.DictReader(f):
            if r["row_object"] == name and r["column_object"] == name:
                k[DOFS.index(r["row_dof"]), DOFS.index(r["column_dof"])] = float(r["stiffness"])
    return k
