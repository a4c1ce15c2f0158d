#!/usr/bin/env python3
"""A hanging line with a free lower end, 160 cubic cable elements, with axial damping.

    check_slack_end_damped.py RODYN DECK WORK_DIR

The deck is bench/decks/hanging_free_end.inp (50 m, 100 kg/m, EA 1e9 N in water, the
top surged 2 m at 10 s) run at the fourth rung of bench/hanging_refinement.py (160
elements, dt 0.00625 s) for 30 s, its section given AXIAL DAMPING RATIO=1 (MoorDyn's
BA = -1). Without damping, EMC at this rung slackens the lowest 6 m of the line and
halves its step 59 times (docs/dynamics.md, "Refinement with a slack end"). Held here:
the run completes without a step halving; after 15 s no frame has more than one slack
integration point (the one nearest the free end, whose static tension is w le/8); the
top force stays within 12.9-13.9 kN (the converged range of the ladder is 13.05-13.73
kN); the damping's work in the log is positive.
"""
import os
import subprocess
import sys

import h5py
import numpy as np


def main():
    rodyn, deck, work = (os.path.abspath(a) for a in sys.argv[1:4])
    os.makedirs(work, exist_ok=True)
    with open(deck) as f:
        text = f.read()
    text = text.replace("CAN=1.0, CAA=0.0\n", "CAN=1.0, CAA=0.0, AXIAL DAMPING RATIO=1\n")
    text = text.replace("CSV=YES, HDF5=NO", "CSV=YES, HDF5=YES")
    assert "AXIAL DAMPING RATIO=1" in text and "HDF5=YES" in text
    path = os.path.join(work, "slack_end.inp")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(work, "out")
    subprocess.run([rodyn, path, "-o", out, "--quiet", "--set", "NE=160", "--set",
                    "DT=0.00625", "--set", "T_END=30"], check=True)
    status = {}
    with open(os.path.join(out, "status.txt")) as f:
        for line in f:
            if "=" in line:
                k, v = line.split("=", 1)
                status[k.strip()] = v.strip()
    cuts = int(status["step_cutbacks"])
    with h5py.File(os.path.join(out, "dynamic.h5"), "r") as f:
        t = f["dynamic/time"][...]
        g = f["dynamic/LINE"]
        ten = g["effective_tension"][...]
        react = g["step_reactions"][...]
        step_t = g["step_time"][...]
        damping = f["dynamic/log/damping_work"][...]
    keep = t >= 15.0
    slack = (ten[keep] <= 0.0).sum(axis=1).max()
    top = np.linalg.norm(react[:, 0:3], axis=1)[step_t >= 15.0]
    print(f"step halvings {cuts}; most slack points in a frame after 15 s: {slack}; "
          f"top force {top.min() / 1e3:.3f}-{top.max() / 1e3:.3f} kN; damping work "
          f"{damping[-1]:.4g} J")
    ok = cuts == 0 and slack <= 1 and top.min() > 12.9e3 and top.max() < 13.9e3 \
        and damping[-1] > 0.0
    print("ok" if ok else "FAILED")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
