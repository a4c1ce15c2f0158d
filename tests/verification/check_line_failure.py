#!/usr/bin/env python3
"""Line failure (tests/verification/decks/line_failure.inp): a cable hanging from a FIXED
point with a FREE point of mass at its lower end, swinging, its top end released at
t_r = 1 s (*FAILURE), dry, EMC. Checks from dynamic_log.csv and dynamic_ends_step.csv:
1. the energy (total_J) is kept through the whole run, the release included (the pin
   does no work and the release takes none), to 1e-9 of M g L;
2. after the release the system falls freely: pz(t) = pz(t_r) - M g (t - t_r) at every
   step (its centre of mass accelerates at g: the closed form of the fall), and px, py
   stay constant, each to 1e-9 of M g (t_end - t_r) (M the line's and the point's mass);
3. the force at the released end: the line's weight and swing before (at least M g / 2),
   below 1e-6 of that after.

Usage: check_line_failure.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys

M, G, L, TR = 100.0 + 2.0 * 10.0, 9.80665, 10.0, 1.0


def main():
    rodyn, deck, out = sys.argv[1:4]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        log = list(csv.DictReader(f))
    t = [float(r["time_s"]) for r in log]
    tot = [float(r["total_J"]) for r in log]
    e_energy = (max(tot) - min(tot)) / (M * G * L)
    after = [r for r in log if float(r["time_s"]) >= TR + 1e-9]
    k0 = next(i for i, r in enumerate(log) if float(r["time_s"]) >= TR - 1e-9)
    p0 = [float(log[k0][c]) for c in ("px", "py", "pz")]
    span = M * G * (t[-1] - TR)
    e_mom = 0.0
    for r in after:
        dt = float(r["time_s"]) - TR
        e_mom = max(e_mom, abs(float(r["px"]) - p0[0]), abs(float(r["py"]) - p0[1]),
                    abs(float(r["pz"]) - (p0[2] - M * G * dt)))
    e_mom /= span
    with open(os.path.join(out, "dynamic_ends_step.csv")) as f:
        ends = [r for r in csv.DictReader(f) if r["line"] == "WIRE" and r["end"] == "A"]
    before = max(float(r["tension_N"]) for r in ends if float(r["time_s"]) < TR - 1e-9)
    later = max(float(r["tension_N"]) for r in ends if float(r["time_s"]) > TR + 0.02)
    print(f"{len(log)} steps to {t[-1]:g} s; energy kept within {e_energy:.2e} of M g L; after "
          f"the release at {TR} s the momentum follows the free fall within {e_mom:.2e} of "
          f"M g t; the end's force {before:.4g} N before, {later:.3g} N after")
    fails = []
    if not e_energy <= 1e-9:
        fails.append(f"energy drifts by {e_energy:.2e} (> 1e-9)")
    if not e_mom <= 1e-9:
        fails.append(f"momentum off the free fall by {e_mom:.2e} (> 1e-9)")
    if not before >= 0.5 * M * G:
        fails.append(f"the end held too little before the release: {before:.4g} N")
    if not later <= 1e-6 * before:
        fails.append(f"the released end still carries {later:.3g} N")
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
