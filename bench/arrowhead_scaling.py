#!/usr/bin/env python3
"""Cost of the arrowhead solver (src/solver/rodyn_arrowhead.f90) against the number of
lines: 3, 6, 12, 24 and 48 lines of 1806 unknowns each (100 cubic rod elements: 301
nodes of 6 unknowns, half-bandwidth 23), all lines' unknowns concatenated in one band
(the lines not coupled to one another), each line's ends coupled to a point's 3 unknowns
(a point per three lines) and a shared body's 6, the entries from a formula (the
driver bench/src/arrowhead_scaling.f90, built as build/bench_arrowhead). For each size:
the order, the junction unknowns, the shortest wall time of 5 factorisations and of 5
solves, per unknown, and the relative residual of the solution.

Target (exit 1 if missed): the cost linear in the total size, the exponent b of the
least-squares fit time ~ n^b of the factorisation at most 1.1.

    python3 bench/arrowhead_scaling.py [--exe build/bench_arrowhead]

Writes bench/results/arrowhead_scaling.csv with the machine facts.
"""
import argparse
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

LINES = [3, 6, 12, 24, 48]
N, HB, REPS = 1806, 23, 5


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "bench_arrowhead"))
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"),
                    help="the program of the same build (for the machine facts)")
    args = ap.parse_args()
    rows = []
    for m in LINES:
        out = subprocess.run([args.exe, str(m), str(N), str(HB), str(REPS)],
                             capture_output=True, text=True, check=True).stdout.split()
        lines, order, nj = int(out[0]), int(out[1]), int(out[2])
        tf, ts, resid = float(out[3]), float(out[4]), float(out[5])
        rows.append({"lines": lines, "unknowns": order, "junctions": nj,
                     "factor_s": tf, "solve_s": ts, "factor_per_unknown_s": tf / order,
                     "solve_per_unknown_s": ts / order, "residual": resid})
        print("  ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                        for k, v in rows[-1].items()), flush=True)
    xs = [math.log(r["unknowns"]) for r in rows]
    ys = [math.log(r["factor_s"]) for r in rows]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    print(f"factorisation time ~ n^{b:.3f} (target <= 1.1)")
    benchlib.write_csv(os.path.join(ROOT, "bench", "results", "arrowhead_scaling.csv"),
                       benchlib.rodyn_binary_facts(benchlib.check_rodyn(args.rodyn)),
                       list(rows[0].keys()), rows,
                       comments=[f"factorisation exponent {b:.3f}"])
    sys.exit(0 if b <= 1.1 and all(r["residual"] < 1e-10 for r in rows) else 1)


if __name__ == "__main__":
    main()
