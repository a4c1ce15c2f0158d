#!/usr/bin/env python3
"""The support forces are written every step (dynamic_ends_step.csv, and step_time,
step_reactions, step_end_tension of each line in dynamic.h5), so that the extremes at the ends do not
depend on the frame interval. The paper's case 1 for 20 s (dt = 0.1 s, end A
heaved at 0.658 Hz) is run twice: frames every 0.5 s (3 frames a period of the motion)
and a frame every step. Checked:

- both runs write one row per held end per step, from step 0 (t = 0) to the last;
- in each run the rows at the frame times equal the frames' rows of dynamic_ends.csv
  character for character (one interpolation serves both);
- the top-force maximum of the per-step series of the coarse run equals the every-step
  run's (relative 1e-9: the two runs take the same steps, but the step end times are
  summed differently, t + dt against the frame time, so the last bits of dt and then
  the Newton iterates differ, within the solver tolerance 1e-8);
- the frames-only maximum of the coarse run misses it by more than 1 %;
- dynamic.h5 holds the same series as the CSV table, bit for bit (with h5py).

Usage: check_ends_every_step.py RODYN DECK WORK_DIR. Exit 0 on success."""
import csv
import os
import re
import subprocess
import sys


def run(rodyn, deck, work, interval):
    """Run the deck for 20 s with frames every `interval` s; the output folder."""
    with open(deck) as f:
        text = f.read()
    text, n = re.subn(r"TIME=[0-9.]+, OUTPUT INTERVAL=[0-9.]+",
                      f"TIME=20.0, OUTPUT INTERVAL={interval}", text)
    if n != 1:
        sys.exit(f"{deck}: no '*DYNAMIC, ..., TIME=..., OUTPUT INTERVAL=...' to change")
    text = text.replace("INPUT=paper", "INPUT=" + os.path.dirname(os.path.abspath(deck))
                        + "/paper")
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, f"case1_{interval}.inp")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(work, f"case1_{interval}")
    proc = subprocess.run([rodyn, path, "-o", out, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"{path}: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    return out


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    rodyn, deck, work = sys.argv[1:4]
    failures = []
    maxima = {}
    for interval in ("0.5", "0.1"):
        out = run(rodyn, deck, work, interval)
        steps = rows(os.path.join(out, "dynamic_ends_step.csv"))
        frames = rows(os.path.join(out, "dynamic_ends.csv"))
        log = rows(os.path.join(out, "dynamic_log.csv"))
        for end in "AB":
            got = [int(r["step"]) for r in steps if r["end"] == end]
            if got != list(range(len(log) + 1)):
                failures.append(f"OI={interval}: end {end}: steps {got[:3]}...{got[-3:]}, "
                                f"expected 0..{len(log)}")
        by_time = {(r["time_s"], r["end"]): r for r in steps}
        for r in frames:
            s = by_time.get((r["time_s"], r["end"]))
            if s is None or any(s[k] != r[k] for k in r):
                failures.append(f"OI={interval}: frame at t = {r['time_s']} end {r['end']}: "
                                f"not the step row {s}")
                break
        step_max = max(float(r["tension_N"]) for r in steps if r["end"] == "A")
        frame_max = max(float(r["tension_N"]) for r in frames if r["end"] == "A")
        maxima[interval] = (step_max, frame_max)
        print(f"OUTPUT INTERVAL={interval}: top force max {step_max:.10g} N per step, "
              f"{frame_max:.10g} N from the {len(frames) // 2} frames")
        try:
            import h5py
            import numpy as np
        except ImportError:
            print("h5py not available: dynamic.h5 not checked")
            continue
        with h5py.File(os.path.join(out, "dynamic.h5"), "r") as f:
            t = f["dynamic/CABLE/step_time"][...]
            ten = f["dynamic/CABLE/step_end_tension"][...]
            reac = f["dynamic/CABLE/step_reactions"][...]
        for k, end in enumerate("AB"):
            sel = [r for r in steps if r["end"] == end]
            ok = (np.array_equal(t, [float(r["time_s"]) for r in sel])
                  and np.array_equal(ten[:, k], [float(r["tension_N"]) for r in sel])
                  and np.array_equal(reac[:, 6 * k + 2], [float(r["Fz_N"]) for r in sel]))
            if not ok:
                failures.append(f"OI={interval}: dynamic.h5 step series of end {end} "
                                "differ from dynamic_ends_step.csv")
    coarse, fine = maxima["0.5"], maxima["0.1"]
    rel = abs(coarse[0] - fine[0]) / fine[0]
    print(f"per-step maximum, frames every 0.5 s against every step: relative "
          f"difference {rel:.3g}; frames-only maximum off by "
          f"{100 * (fine[0] - coarse[1]) / fine[0]:.2f} %")
    if rel > 1e-9:
        failures.append(f"per-step maxima differ by {rel:.3g} (relative)")
    if fine[0] - coarse[1] <= 0.01 * fine[0]:
        failures.append("the frames-only maximum does not miss the per-step maximum: "
                        "the test no longer shows what it should")
    if fine[1] != fine[0]:
        failures.append("frames every step: frame maximum differs from the step maximum")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
