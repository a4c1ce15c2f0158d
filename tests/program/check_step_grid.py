#!/usr/bin/env python3
"""The time steps stay on their grid over a long run (tests/program/step_grid.inp: 24 000
steps of 0.025 s): times summed step by step drift by round-off, and a drifted end of
the run took a sliver of a step (half a step, splitting the last one) where the grid has
none. Checks: 24 000 step rows in dynamic_log.csv, every step 0.025 s long (within
1e-12 s), no step halved, the last ending at 600 s.

Usage: check_step_grid.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import os
import subprocess
import sys


def main():
    rodyn, deck, out = sys.argv[1:4]
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        log = list(csv.DictReader(f))
    dts = [float(r["dt_s"]) for r in log]
    off = max(abs(d - 0.025) for d in dts)
    cut = sum(int(r["cutbacks"]) for r in log)
    end = float(log[-1]["time_s"])
    print(f"{len(log)} steps, largest step length off 0.025 s by {off:.1e} s, "
          f"{cut} halvings, last step ends at {end!r} s")
    ok = len(log) == 24000 and off <= 1e-12 and cut == 0 and end == 600.0
    sys.exit(0 if ok else "FAIL")


if __name__ == "__main__":
    main()
