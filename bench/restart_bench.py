#!/usr/bin/env python3
"""Checkpoint and restart under real kills: the paper's case 1 (60 s, a frame
every step, CHECKPOINT=5 s) is run once uninterrupted, then --trials times killed with
SIGKILL at a random wall time (seeded) and continued with `rodyn DECK --restart DIR`
(each continued run killed again at random with probability 1/2) until it completes;
its files are compared with the uninterrupted run's (every CSV byte for byte, every
dataset of dynamic.h5 and results.h5 to the bit, as tests/program/check_restart.py).
A kill before the first checkpoint leaves nothing to continue (--restart refuses it,
exit 1): the run is started again, as a user would. Also measured: what checkpoints
cost (wall time and tangents of the same deck without CHECKPOINT; best of 3 runs).

Usage: python3 bench/restart_bench.py [--rodyn build/rodyn] [--trials 20] [--seed 1]
Prints 'bit-identical at every kill time tried' when every trial matched."""
import argparse
import importlib.util
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
spec = importlib.util.spec_from_file_location(
    "check_restart", os.path.join(ROOT, "tests", "program", "check_restart.py"))
check_restart = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check_restart)


def status(folder):
    out = {}
    with open(os.path.join(folder, "status.txt")) as f:
        for line in f:
            k, _, v = line.partition("=")
            out[k.strip()] = v.strip()
    return out


def timed(rodyn, args):
    t0 = time.perf_counter()
    proc = subprocess.run([rodyn] + args + ["--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"{args}: exit {proc.returncode}: {proc.stderr}")
    return time.perf_counter() - t0


def killed_at(rodyn, args, after):
    """Start rodyn, SIGKILL it after `after` s of wall time; its exit status."""
    proc = subprocess.Popen([rodyn] + args + ["--quiet"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    try:
        proc.wait(timeout=after)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    return proc.returncode, proc.stderr.read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--trials", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rodyn = os.path.abspath(a.rodyn)
    rng = random.Random(a.seed)
    work = tempfile.mkdtemp(prefix="rodyn_restart_")
    sub = (r"TIME=900\.0, OUTPUT INTERVAL=0\.1", "TIME=60.0, OUTPUT INTERVAL=0.1")
    plain = check_restart.deck(os.path.join(ROOT, "input"), work, "case1_plain",
                               "paper_case1.inp", [sub])
    deck = check_restart.deck(os.path.join(ROOT, "input"), work, "case1",
                              "paper_case1.inp", [(sub[0], sub[1] + ", CHECKPOINT=5.0")])
    ref = os.path.join(work, "ref")
    walls = {"with": [], "without": []}
    for _ in range(3):
        walls["with"].append(timed(rodyn, [deck, "-o", ref]))
        walls["without"].append(timed(rodyn, [plain, "-o", os.path.join(work, "plain")]))
    s_with, s_without = status(ref), status(os.path.join(work, "plain"))
    size = os.path.getsize(os.path.join(ref, "checkpoint.h5"))
    print(f"case 1, 60 s, 600 steps: without checkpoints {min(walls['without']):.3f} s, "
          f"{s_without['step_iterations']} iterations, {s_without['step_tangents']} "
          f"tangents; CHECKPOINT=5 (11 checkpoints) {min(walls['with']):.3f} s, "
          f"{s_with['step_iterations']} iterations, {s_with['step_tangents']} tangents; "
          f"checkpoint.h5 {size} bytes")
    t_run = min(walls["with"])
    kills = restarts = refused = 0
    bad = []
    for trial in range(a.trials):
        out = os.path.join(work, f"t{trial}")
        shutil.rmtree(out, ignore_errors=True)
        args = [deck, "-o", out]
        times = []
        while True:
            after = rng.uniform(0.02, 0.98 * t_run)
            code, err = killed_at(rodyn, args, after)
            if code == 0:
                break
            if code == -signal.SIGKILL:
                kills += 1
                times.append(round(after, 3))
            elif code == 1 and "no checkpoint" in err:
                refused += 1
                args = [deck, "-o", out]
                continue
            else:
                sys.exit(f"trial {trial}: exit {code}: {err}")
            args = [deck, "--restart", out]
            restarts += 1
            if rng.random() < 0.5:   # the continued run is left to finish
                proc = subprocess.run([rodyn] + args + ["--quiet"], capture_output=True,
                                      text=True)
                if proc.returncode == 0:
                    break
                if proc.returncode == 1 and "no checkpoint" in proc.stderr:
                    refused += 1
                    args = [deck, "-o", out]
                    continue
                sys.exit(f"trial {trial}: restart exit {proc.returncode}: {proc.stderr}")
        check_restart.FAILURES.clear()
        n = check_restart.same_files(ref, out, f"trial {trial}")
        ok = not check_restart.FAILURES
        if not ok:
            bad.append((trial, times, list(check_restart.FAILURES)[:3]))
        print(f"trial {trial:2d}: killed at {times} s of wall time: {n} files and datasets, "
              f"{'bit-identical' if ok else 'DIFFERENT'}")
    print(f"{kills} kills, {restarts} restarts, {refused} restarts refused (killed before "
          f"the first checkpoint: run again) in {a.trials} trials")
    if bad:
        for b in bad:
            print("FAIL:", b)
        return 1
    print("bit-identical at every kill time tried")
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
