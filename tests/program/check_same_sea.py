#!/usr/bin/env python3
"""An irregular sea is reproducible: run a deck with *WAVE, TYPE=JONSWAP (and parameters
SEED and T_END, run for 4 s here) twice, and once with --set SEED=<another>; the two
runs with the same seed must write the same dynamic results byte for byte
(dynamic_nodes.csv, dynamic_ends.csv, dynamic_log.csv), the run with another seed
other ones.

Usage: check_same_sea.py RODYN DECK OUT_DIR. Exit 0 on success."""
import filecmp
import os
import shutil
import subprocess
import sys

FILES = ("dynamic_nodes.csv", "dynamic_ends.csv", "dynamic_log.csv")


def run(rodyn, deck, out, *extra):
    """Run rodyn into a fresh folder out; stop the check if it fails."""
    shutil.rmtree(out, ignore_errors=True)
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", "--set", "T_END=4",
                           *extra], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")


def main():
    rodyn, deck, out = sys.argv[1:4]
    dirs = [os.path.join(out, name) for name in ("seed_a", "seed_a_again", "seed_b")]
    run(rodyn, deck, dirs[0])
    run(rodyn, deck, dirs[1])
    run(rodyn, deck, dirs[2], "--set", "SEED=8")
    same = all(filecmp.cmp(os.path.join(dirs[0], f), os.path.join(dirs[1], f),
                           shallow=False) for f in FILES)
    other = not filecmp.cmp(os.path.join(dirs[0], FILES[0]), os.path.join(dirs[2], FILES[0]),
                            shallow=False)
    print(f"same seed, same files byte for byte: {same}; another seed, other nodes: {other}")
    ok = same and other
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
