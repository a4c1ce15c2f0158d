#!/usr/bin/env python3
"""rodyn's arrowhead solver (src/solver/rodyn_arrowhead.f90) against SuiteSparse's
sparse direct solvers UMFPACK and KLU, on the matrix of a mooring system: m lines in one
band (not coupled to one another), each line's ends coupled to a point's 3 unknowns (a
point per three lines) and a shared body's 6, the entries from a formula (the driver
bench/src/sparse_direct.f90 with bench/src/suitesparse_shim.c, built as
build/bench_sparse when Debian's libsuitesparse-dev is installed). Lines of 60 cubic
cable elements (543 unknowns, half-bandwidth 11) and of 100 cubic rod elements (1806
unknowns, half-bandwidth 23), 3, 12 and 48 of them. For each solver: the shortest wall
time of 5 repetitions of the symbolic analysis (once per sparsity pattern; the
arrowhead's structure is given), the numeric factorisation (once per Newton tangent)
and the solve (once per Newton iteration), and the relative residual.

Exit 1 if a sparse solver's factorisation plus solve is faster than the arrowhead's on
any case (the choice of solver would then be revisited).

    python3 bench/sparse_direct.py [--exe build/bench_sparse]

Writes bench/results/sparse_direct.csv with the machine facts.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

CASES = [("cable", 543, 11), ("rod", 1806, 23)]
LINES = [3, 12, 48]
REPS = 5


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "bench_sparse"))
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"),
                    help="the program of the same build (for the machine facts)")
    args = ap.parse_args()
    if not os.path.exists(args.exe):
        sys.exit(f"{args.exe} not built: apt-get install libsuitesparse-dev, then cmake")
    rows, slower = [], []
    for kind, n, hb in CASES:
        for m in LINES:
            out = subprocess.run([args.exe, str(m), str(n), str(hb), str(REPS)],
                                 capture_output=True, text=True, check=True).stdout
            res = {}
            for line in out.splitlines():
                name, order, nnz, ta, tf, ts, resid = line.split()
                res[name] = (float(ta), float(tf), float(ts))
                rows.append({"lines": m, "line": kind, "unknowns": int(order),
                             "nonzeros": int(nnz), "solver": name, "analysis_s": float(ta),
                             "factor_s": float(tf), "solve_s": float(ts),
                             "residual": float(resid)})
            base = res["arrowhead"][1] + res["arrowhead"][2]
            ratios = {s: (res[s][1] + res[s][2]) / base for s in ("umfpack", "klu")}
            print(f"{m:3d} {kind:5s} lines, {rows[-1]['unknowns']} unknowns: arrowhead "
                  f"factor {res['arrowhead'][1]:.3e} s, solve {res['arrowhead'][2]:.3e} s; "
                  f"factor + solve {ratios['umfpack']:.1f}x as long with UMFPACK, "
                  f"{ratios['klu']:.1f}x with KLU", flush=True)
            slower += [r for r in ratios.values() if r < 1.0]
    benchlib.write_csv(os.path.join(ROOT, "bench", "results", "sparse_direct.csv"),
                       benchlib.rodyn_binary_facts(benchlib.check_rodyn(args.rodyn)),
                       list(rows[0].keys()), rows)
    bad = [r for r in rows if r["residual"] > 1e-10]
    sys.exit(1 if slower or bad else 0)


if __name__ == "__main__":
    main()
