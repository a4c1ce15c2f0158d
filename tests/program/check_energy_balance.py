#!/usr/bin/env python3
"""Run an EMC deck that must complete, and check that no step breaks the energy
balance: the change of (total energy - external work - hydro work - seabed work + damping
work) over any one step stays below TOL times the largest |work done on the lines|
(external, hydro or seabed) of the run (dynamic_log.csv; the hydro and seabed columns
count as 0 in a log written before they existed). In a free motion, where nothing works
on the lines, the scale is the largest kinetic energy instead.

Usage: check_energy_balance.py RODYN DECK OUT_DIR [TOL]. Exit 0 on success."""
import csv
import subprocess
import sys


def main():
    rodyn, deck, out = sys.argv[1:4]
    tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-6
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(f"{out}/dynamic_log.csv") as f:
        rows = list(csv.DictReader(f))
    def work_in(r):
        """Work done on the lines since t = 0 by loads, motions, water and seabed [J]."""
        return (float(r["external_work_J"]) + float(r.get("hydro_work_J", 0.0))
                + float(r.get("seabed_work_J", 0.0)))

    bal = [float(r["total_J"]) - work_in(r) + float(r["damping_work_J"])
           + float(r.get("numerical_work_J", 0.0)) for r in rows]
    work = max(max(abs(float(r[k])) for k in ("external_work_J", "hydro_work_J",
                                              "seabed_work_J") if k in r) for r in rows)
    if work == 0.0:
        work = max(float(r["kinetic_J"]) for r in rows)
    jump = max(abs(b - a) for a, b in zip(bal, bal[1:]))
    halvings = sum(int(r["cutbacks"]) for r in rows)
    print(f"{len(rows)} steps, {halvings} halvings; largest one-step change of the energy "
          f"balance {jump:.3g} J, largest work {work:.3g} J, ratio {jump / work:.2e}")
    ok = jump <= tol * work
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
