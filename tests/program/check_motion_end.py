#!/usr/bin/env python3
"""The last frame's support forces with a motion table that ends at TIME
(tests/program/motion_end.inp): a frame's forces are interpolated between the step
forces on both sides of its time, and the last one's come from a step past TIME. That
step continues a table that ends before it on the straight line of its last step, so a
table ending at TIME (motion_end_short.csv) gives the same last frame as the same table
continued on its last slope (motion_end_long.csv), to 1e-9 of the force; a table held
constant past its end would have stopped the end there (half the force on this deck).
The same for a vessel's motion table (motion_end_vessel.inp: a riser clamped to a vessel
surging, heaving and pitching; vessel_end_short.csv against vessel_end_long.csv), its
force and moment (a table held constant gives 56 % of the force there).

Usage: check_motion_end.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys


def last_force(rodyn, deck, out, table, keys=("Fx_N", "Fy_N", "Fz_N")):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", "--set", f"TABLE={table}"],
                          capture_output=True, text=True, cwd=os.path.dirname(deck))
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_ends.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["end"] == "B"]
    return float(rows[-1]["time_s"]), [float(rows[-1][k]) for k in keys]


def main():
    rodyn, deck, out = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    t1, short = last_force(rodyn, deck, os.path.join(out, "short"), "motion_end_short.csv")
    t2, long = last_force(rodyn, deck, os.path.join(out, "long"), "motion_end_long.csv")
    scale = max(abs(v) for v in long)
    diff = max(abs(a - b) for a, b in zip(short, long)) / scale
    print(f"last frame (t = {t1} s): end B's force {short} N with the table ending at TIME,"
          f" {long} N with it continued: difference {diff:.1e} of {scale:.4g} N")
    ok = t1 == t2 == 4.0 and diff <= 1e-9
    vdeck = os.path.join(os.path.dirname(deck), "motion_end_vessel.inp")
    keys = ("Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm")
    t3, vshort = last_force(rodyn, vdeck, os.path.join(out, "vessel_short"),
                            "vessel_end_short.csv", keys)
    t4, vlong = last_force(rodyn, vdeck, os.path.join(out, "vessel_long"),
                           "vessel_end_long.csv", keys)
    fscale = max(abs(v) for v in vlong[:3])
    mscale = max(abs(v) for v in vlong[3:])
    fdiff = max(abs(a - b) for a, b in zip(vshort[:3], vlong[:3])) / fscale
    mdiff = max(abs(a - b) for a, b in zip(vshort[3:], vlong[3:])) / mscale
    print(f"vessel table, last frame (t = {t3} s): end B's force and moment differ by "
          f"{fdiff:.1e} of {fscale:.4g} N and {mdiff:.1e} of {mscale:.4g} N m between the "
          "table ending at TIME and the table continued")
    ok = ok and t3 == t4 == 4.0 and fdiff <= 1e-9 and mdiff <= 1e-9
    sys.exit(0 if ok else "FAIL")


if __name__ == "__main__":
    main()
