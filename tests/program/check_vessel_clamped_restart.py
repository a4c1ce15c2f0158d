#!/usr/bin/env python3
"""A clamped end turning with its vessel, continued from a checkpoint (docs/vessels.md):
vessel_clamped_riser.inp (the drop riser clamped to the offset FPSO in a regular head
sea) cut to 8 s with CHECKPOINT=2, killed after step 97 (RODYN_TEST_KILL_AFTER_STEP)
and continued with --restart, leaves every CSV table byte for byte as the run never
interrupted: the clamp's directors at t = 0 (its turn Q d(0)) and the vessel at rest at
its offset are set up again from the checkpoint's start state.

Usage: check_vessel_clamped_restart.py RODYN DECK WORK_DIR. Exit 0 on success."""
import filecmp
import os
import shutil
import subprocess
import sys


def main():
    rodyn, deck, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    with open(deck) as f:
        text = f.read()
    old = "*DYNAMIC, DT=0.05, TIME=20.0, OUTPUT INTERVAL=0.5"
    if old not in text:
        sys.exit(f"FAIL: {deck} has no line '{old}'")
    text = text.replace(old, old.replace("TIME=20.0", "TIME=8.0") + ", CHECKPOINT=2.0")
    text = text.replace("../../input/", os.path.join(os.path.dirname(os.path.abspath(deck)),
                                                     "..", "..", "input", ""))
    cut = os.path.join(work, "vessel_clamped_riser_cut.inp")
    with open(cut, "w") as f:
        f.write(text)
    full, killed = os.path.join(work, "full"), os.path.join(work, "killed")
    for d in (full, killed):
        shutil.rmtree(d, ignore_errors=True)
    run = subprocess.run([rodyn, cut, "-o", full, "--quiet"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"FAIL: the full run exit {run.returncode}: {run.stderr.strip()}")
    env = dict(os.environ, RODYN_TEST_KILL_AFTER_STEP="97")
    run = subprocess.run([rodyn, cut, "-o", killed, "--quiet"], env=env,
                         capture_output=True, text=True)
    if run.returncode == 0:
        sys.exit("FAIL: the run was not killed")
    run = subprocess.run([rodyn, cut, "--restart", killed, "--quiet"], capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"FAIL: --restart exit {run.returncode}: {run.stderr.strip()}")
    tables = sorted(f for f in os.listdir(full) if f.endswith(".csv"))
    differ = [t for t in tables
              if not filecmp.cmp(os.path.join(full, t), os.path.join(killed, t),
                                 shallow=False)]
    print(f"{len(tables)} CSV tables compared after a kill at step 97 and --restart; "
          f"differing: {differ or 'none'}")
    if differ or not tables:
        sys.exit("FAILED")
    print("PASS")


if __name__ == "__main__":
    main()
