#!/usr/bin/env python3
"""A FREE body's natural periods as a rigid body on its moorings (static_body_modes.csv,
docs/theory.md eq. (144)) on tests/verification/decks/body_damped.inp with an added mass
(A11 ... A66 set): a body of 1000 kg and inertia 100 kg m2 about G = R on uncoupled
springs (1e5 N/m in translation, 1e4 N m/rad in rotation): the six periods
2 pi sqrt((m + A_ii) / k_i) and 2 pi sqrt((J + A_ii) / k_i), each within 1e-9, and each
mode along its one direction (largest other entry below 1e-9).

Usage: check_body_modes.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

ADDED = {"A11": 200.0, "A22": 300.0, "A33": 500.0, "A44": 10.0, "A55": 25.0, "A66": 35.0}
DOFS = ("x", "y", "z", "rx", "ry", "rz")


def main():
    rodyn, deck, out = sys.argv[1:4]
    sets = []
    for k, v in ADDED.items():
        sets += ["--set", f"{k}={v}"]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", *sets], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    mass = [1000.0 + ADDED[f"A{i}{i}"] for i in (1, 2, 3)] + \
        [100.0 + ADDED[f"A{i}{i}"] for i in (4, 5, 6)]
    stiff = [1.0e5] * 3 + [1.0e4] * 3
    closed = {d: 2 * math.pi * math.sqrt(m / k) for d, m, k in zip(DOFS, mass, stiff)}
    fails = []
    with open(os.path.join(out, "static_body_modes.csv")) as f:
        rows = list(csv.DictReader(f))
    seen = set()
    for r in rows:
        shape = {d: float(r[d]) for d in DOFS}
        main_dof = max(shape, key=lambda d: abs(shape[d]))
        other = max(abs(v) for d, v in shape.items() if d != main_dof)
        period = float(r["period_s"])
        err = abs(period / closed[main_dof] - 1)
        print(f"mode {r['mode']}: {period:.9f} s along {main_dof} (closed form "
              f"{closed[main_dof]:.9f} s): {err:.1e}; largest other entry {other:.1e}")
        seen.add(main_dof)
        if not err <= 1e-9:
            fails.append(f"mode {r['mode']} ({main_dof}) off by {err:.2e}")
        if not other <= 1e-9:
            fails.append(f"mode {r['mode']} not along {main_dof} alone ({other:.1e})")
    if seen != set(DOFS):
        fails.append(f"the modes are along {sorted(seen)}, not all six directions")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
