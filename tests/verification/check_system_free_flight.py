#!/usr/bin/env python3
"""Free flight of a system in vacuum (tests/verification/decks/system_free_flight.inp):
a rod and two cables joined at a FREE point, each thrown with its own velocity and spin,
no gravity, no support, EMC. The step of the whole system (lines and point, the ends
eliminated onto the point: docs/theory.md (131)-(134)) keeps the energy and the six
momenta: each of px, py, pz, Lx, Ly, Lz and the total energy of dynamic_log.csv stays
within TOL = 1e-9 of its scale (the largest of its group at the start; the energy's,
the kinetic energy at the start) at every step, and the run reaches its end.

Usage: check_system_free_flight.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys

TOL = 1.0e-9


def main():
    rodyn, deck, out = sys.argv[1:4]
    sets = [a for v in sys.argv[4:] for a in ("--set", v)]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", *sets], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        rows = list(csv.DictReader(f))
    fails = []
    if abs(float(rows[-1]["time_s"]) - 4.0) > 1e-9:
        fails.append(f"the run stopped at t = {rows[-1]['time_s']} s")
    groups = (("px", "py", "pz"), ("Lx", "Ly", "Lz"), ("total_J",))
    for group in groups:
        scale = max(abs(float(rows[0][c])) for c in group)
        if group == ("total_J",):
            scale = float(rows[0]["kinetic_J"])
        for c in group:
            v = [float(r[c]) for r in rows]
            drift = (max(v) - min(v)) / scale
            print(f"{c}: {v[0]:+.6e}, largest change {drift:.2e} of {scale:.4g}")
            if not drift <= TOL:
                fails.append(f"{c} drifts by {drift:.2e} of its scale (> {TOL})")
    strain = max(float(r["strain_J"]) for r in rows)
    print(f"{len(rows) - 1} steps; largest strain energy {strain:.4g} J "
          f"({strain / float(rows[0]['kinetic_J']):.2e} of the kinetic energy at t = 0)")
    if not strain > 1e-3 * float(rows[0]["kinetic_J"]):
        fails.append("the lines hardly deform: the test would not see a wrong coupling")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
