#!/usr/bin/env python3
"""The last frame's support forces with a motion table that ends at TIME
(tests/program/motion_end.inp): a frame's forces are interpolated between the step
forces on both sides of its time, and the last one's come from a step past TIME. That
step continues a table that ends before it on the straight line of its last step, so a
table ending at TIME (motion_end_short.csv) gives the same last frame as the same table
continued on its last slope (motion_end_long.csv), to 1e-9 of the force; a table held
constant past its end would have stopped the end there (half the force on this deck).

Usage: check_motion_end.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys


def last_force(rodyn, deck, out, table):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", "--set", f"TABLE={table}"],
                          capture_output=True, text=True, cwd=os.path.dirname(deck))
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_ends.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["end"] == "B"]
    return float(rows[-1]["time_s"]), [float(rows[-1][k]) for k in ("Fx_N", "Fy_N", "Fz_N")]


def main():
    rodyn, deck, out = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    t1, short = last_force(rodyn, deck, os.path.join(out, "short"), "motion_end_short.csv")
    t2, long = last_force(rodyn, deck, os.path.join(out, "long"), "motion_end_long.csv")
    scale = max(abs(v) for v in long)
    diff = max(abs(a - b) for a, b in zip(short, long)) / scale
    print(f"last frame (t = {t1} s): end B's force {short} N with the table ending at TIME,"
          f" {long} N with it continued: difference {diff:.1e} of {scale:.4g} N")
    sys.exit(0 if t1 == t2 == 4.0 and diff <= 1e-9 else "FAIL")


if __name__ == "__main__":
    main()
