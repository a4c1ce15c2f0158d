#!/usr/bin/env python3
"""The deck fuzzer's full mode: 10 000 mutated decks through rodyn.

Runs tools/fuzz_decks.py (the same cases as its quick mode in CTest, 300 of them, and
9 700 more) and writes its summary with the machine it ran on:
bench/results/fuzz_bench.md (the table docs/fuzz.md quotes) and, with --json, every
case's record. Exits 1 when any case broke rodyn's contract (the failing decks are kept,
see the fuzzer's output). 5 to 12 minutes on one core of the 2-core machine (quiet or shared).

    nice -n 10 python3 bench/fuzz_bench.py [--rodyn build/rodyn] [--count 10000]
"""
import argparse
import os
import subprocess
import sys

from benchlib import machine_facts

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    p.add_argument("--count", type=int, default=10000, help="number of decks (10000)")
    p.add_argument("--seed", default="1", help="seed of the fuzzer (1)")
    p.add_argument("--jobs", type=int, default=1, help="rodyn processes at a time (1)")
    p.add_argument("--out", default=os.path.join(HERE, "results", "fuzz_bench.md"))
    p.add_argument("--json", default=None, help="every case's record (JSON)")
    p.add_argument("--work", default=None, help="folder for the cases and failures")
    args = p.parse_args()
    rodyn = os.path.abspath(args.rodyn)
    facts = machine_facts(rodyn, load_average=True)
    cmd = [sys.executable, os.path.join(ROOT, "tools", "fuzz_decks.py"), "--rodyn", rodyn,
           "--count", str(args.count), "--seed", args.seed, "--jobs", str(args.jobs)]
    if args.json:
        cmd += ["--json", args.json]
    if args.work:
        cmd += ["--work", args.work]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    sys.stdout.write(proc.stdout)
    sys.stderr.write(proc.stderr)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(f"# Deck fuzzer, {args.count} decks (bench/fuzz_bench.py)\n\n")
        for k, v in facts.items():
            f.write(f"- {k}: {v}\n")
        shown = [os.path.relpath(c, ROOT) if c.startswith(ROOT) else c for c in cmd[1:]]
        f.write(f"- command: python3 {' '.join(shown)}\n\n")
        f.write(proc.stdout)
    print(f"written {os.path.relpath(args.out, ROOT)}")
    return proc.returncode


if __name__ == "__main__":
    sys.exit(main())
