#!/usr/bin/env python3
"""A FREE body thrown (*INITIAL VELOCITY, BODY=; decks/body_thrown.inp): its system (a
body of 100 kg, a rod of 200 kg and two cables of 50 kg each) in vacuum.
- W = 0, everything at (1, 2, 3) m/s: the momentum of dynamic_log.csv at the start is
  400 (1, 2, 3) kg m/s within 1e-12, and the six momenta stay (1e-9).
- The body spinning at W = (0.4, -0.6, 0.9) rad/s about R (its ends move with it): the
  energy and the six momenta stay within 1e-9 of their scale over 400 steps, and the
  lines deform (check_system_free_flight.py).

With CONN=CLAMPED (the deck's parameter): the rod's end clamped to the body, turning with
it (*POINT, CONNECTION=CLAMPED), the same checks.

Usage: check_body_thrown.py RODYN DECK OUT_DIR [NAME=VALUE ...] (the deck's parameters).
Exit 0 on success."""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    rodyn, deck, out = sys.argv[1:4]
    extra = sys.argv[4:]
    sets = [a for v in extra for a in ("--set", v)]
    fails = []
    still = os.path.join(out, "translation")
    proc = subprocess.run([rodyn, deck, "-o", still, "--quiet", *sets, "--set", "WX=0.0",
                           "--set", "WY=0.0", "--set", "WZ=0.0"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(still, "dynamic_log.csv")) as f:
        rows = list(csv.DictReader(f))
    p0 = [float(rows[0][c]) for c in ("px", "py", "pz")]
    want = [400.0 * v for v in (1.0, 2.0, 3.0)]
    err = max(abs(a - b) for a, b in zip(p0, want)) / max(want)
    drift = max(abs(float(r[c]) - float(rows[0][c])) for r in rows
                for c in ("px", "py", "pz", "Lx", "Ly", "Lz")) / max(want)
    print(f"translation: momentum at the start {p0} kg m/s (400 (1, 2, 3): {err:.1e}); "
          f"momenta kept within {drift:.1e}")
    if not err <= 1e-12:
        fails.append(f"momentum at the start off by {err:.2e}")
    if not drift <= 1e-9:
        fails.append(f"momenta drift by {drift:.2e}")
    spin = subprocess.run([sys.executable, os.path.join(HERE, "check_system_free_flight.py"),
                           rodyn, deck, os.path.join(out, "spin"), *extra],
                          capture_output=True,
                          text=True)
    print(spin.stdout.strip())
    if spin.returncode != 0:
        fails.append("the spinning body's system does not keep its energy and momenta")
    for msg in fails:
        print("FAIL:", msg)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
