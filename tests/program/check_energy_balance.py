#!/usr/bin/env python3
"""Run an EMC deck that must complete, and check that no step breaks the energy
balance: the change of (total energy - external work + damping work) over any one step
stays below TOL times the largest |external work| of the run (dynamic_log.csv).

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
    bal = [float(r["total_J"]) - float(r["external_work_J"]) + float(r["damping_work_J"])
           for r in rows]
    work = max(abs(float(r["external_work_J"])) for r in rows)
    jump = max(abs(b - a) for a, b in zip(bal, bal[1:]))
    halvings = sum(int(r["cutbacks"]) for r in rows)
    print(f"{len(rows)} steps, {halvings} halvings; largest one-step change of the energy "
          f"balance {jump:.3g} J, largest work {work:.3g} J, ratio {jump / work:.2e}")
    ok = jump <= tol * work
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
