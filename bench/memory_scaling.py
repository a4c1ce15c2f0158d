#!/usr/bin/env python3
"""Peak memory of a dynamic run of rodyn against element count, for the paper's cable.

usage: python3 bench/memory_scaling.py [--rodyn PATH] [--sizes N [N ...]]
       (about 1 minute; writes bench/results/memory_scaling.csv and prints a markdown
        table)

The decks of bench/dynamic_scaling.py (the paper's cable with the motion of case 2,
EMC, dt = 0.015 s, 20 steps, orders 3 and 2, 10 to 10 000 elements) with the outputs
written (*OUTPUT, CSV=YES, HDF5=YES, a frame every 5 steps), since the writers hold
buffers too. Peak memory is the maximum resident set size of the rodyn process
(GNU time's %M, in KiB). Reported: peak memory, the part above the 10-element run
(the program's fixed size: code, HDF5 and LAPACK libraries), that part per element, and
the exponent b of (peak - peak at 10 elements) ~ n^b fitted on log-log over n >= 100.
A banded solver stores (3 kl + 1) n doubles for the tangent and its factors, and the
state a fixed amount per node, so b = 1 is expected.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from dynamic_scaling import make_deck  # noqa: E402

SIZES = [10, 30, 100, 300, 1000, 3000, 10000]


def peak_kib(rodyn, deck, out):
    """Peak resident set size of one run [KiB], via GNU time."""
    proc = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M", rodyn, deck, "-o", out,
                           "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"{deck}: rodyn exit {proc.returncode}: {proc.stderr.strip()[-300:]}")
    m = re.search(r"MAXRSS (\d+)", proc.stderr)
    if not m:
        sys.exit("GNU time did not report the peak memory (apt-get install time)")
    return int(m.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default="build/rodyn")
    ap.add_argument("--sizes", type=int, nargs="+", default=SIZES)
    args = ap.parse_args()
    rodyn = os.path.abspath(args.rodyn)
    benchlib.check_rodyn(rodyn)
    if not os.path.exists("/usr/bin/time"):
        sys.exit("needs GNU time: apt-get install time")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for order in (3, 2):
            base = None
            for n in sorted(args.sizes):
                text = make_deck(n, order, True)
                text = re.sub(r"\*OUTPUT[^\n]*", "*OUTPUT, CSV=YES, HDF5=YES", text)
                text = benchlib.set_params(text, "*DYNAMIC", {"OUTPUT INTERVAL": 0.075})
                deck = benchlib.write_deck(tmp, f"p{order}_n{n}", text)
                kib = peak_kib(rodyn, deck, os.path.join(tmp, f"out_p{order}_n{n}"))
                base = kib if base is None else base
                rows.append({"order": order, "elements": n, "peak_kib": kib,
                             "above_base_kib": kib - base, "failed": False})
                print(f"  p={order} n={n}: {kib} KiB", file=sys.stderr)
    table = []
    for r in rows:
        per = r["above_base_kib"] / r["elements"] if r["above_base_kib"] > 0 else float("nan")
        table.append([str(r["order"]), str(r["elements"]), f"{r['peak_kib'] / 1024:.1f}",
                      f"{r['above_base_kib'] / 1024:.1f}", f"{per:.2f}"])
    print("\n".join(benchlib.md_table(["order", "elements", "peak [MiB]",
                                       "above 10 elements [MiB]",
                                       "above, per element [KiB]"], table)))
    for order in (3, 2):
        sub = [dict(r, y=max(r["above_base_kib"], 1e-9)) for r in rows if r["order"] == order]
        b = benchlib.fit_exponent(sub, "y")
        print(f"order {order}: (peak - peak at 10 elements) ~ n^{b:.2f} over n >= 100")
    benchlib.write_csv(os.path.join(benchlib.ROOT, "bench", "results", "memory_scaling.csv"),
                       benchlib.machine_facts(rodyn),
                       ["order", "elements", "peak_kib", "above_base_kib"], rows)


if __name__ == "__main__":
    main()
