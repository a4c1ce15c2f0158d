#!/usr/bin/env python3
"""*MODAL's two eigensolvers against the size of the system: the OC3-Hywind spar of
input/oc3_spar.inp (its three chains on 8 to 240 cubic elements each, the spar a FREE
body) with *MODAL, MODES=10 solved by SOLVER=DENSE (LAPACK dsygv on the reduced
matrices) and SOLVER=LANCZOS (ARPACK's shift-invert Lanczos on the factorised tangent).
The modal analysis's time is the run's wall time less that of the same deck without
*MODAL (best of `--repeat` runs each); the ten periods of the two solvers are compared.
Writes bench/results/modal_solvers.csv and prints a markdown table. Run on an idle
machine: it is a timing.

usage: python3 bench/systems/modal_solvers.py [--rodyn build/rodyn] [--repeat 3]
       [--quick] (8 to 30 elements a line)"""
import argparse
import csv
import pathlib
import re
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def deck_text(n, solver):
    text = (ROOT / "input" / "oc3_spar.inp").read_text()
    text = re.sub(r"ELEMENTS=60", f"ELEMENTS={n}", text)
    text = re.sub(r"^\*(DYNAMIC|MODAL).*$", "", text, flags=re.M)
    text = re.sub(r"^\*OUTPUT.*$", "*OUTPUT, CSV=YES, HDF5=NO", text, flags=re.M)
    if solver:
        text += f"*MODAL, MODES=10, SOLVER={solver}\n"
    return text


def best_time(rodyn, deck, out, repeat):
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run([rodyn, str(deck), "-o", str(out), "--quiet"], check=True)
        best = min(best, time.perf_counter() - t0)
    return best


def periods(out):
    with open(out / "static_modes.csv") as f:
        return [float(r["period_s"]) for r in csv.DictReader(f)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rodyn", default=str(ROOT / "build" / "rodyn"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    sizes = [8, 16, 30] if args.quick else [8, 12, 16, 20, 30, 60, 120, 240]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for n in sizes:
            times, result = {}, {}
            for solver in ("", "DENSE", "LANCZOS"):
                if solver == "DENSE" and n > 60:
                    continue
                deck = tmp / f"spar_{n}_{solver or 'none'}.inp"
                deck.write_text(deck_text(n, solver))
                out = tmp / f"out_{n}_{solver or 'none'}"
                times[solver] = best_time(args.rodyn, deck, out, args.repeat)
                if solver:
                    result[solver] = periods(out)
            unknowns = 3 * 3 * (3 * n + 1) + 6   # the statics': 3 a cable node, 6 the body
            dense = times.get("DENSE", float("nan")) - times[""]
            lanczos = times["LANCZOS"] - times[""]
            diff = (max(abs(a / b - 1) for a, b in zip(result["DENSE"], result["LANCZOS"]))
                    if "DENSE" in result else float("nan"))
            rows.append((n, unknowns, dense, lanczos, diff))
            print(f"{n} elements a line: dense {dense:.4f} s, Lanczos {lanczos:.4f} s, "
                  f"periods differ by {diff:.1e}", flush=True)
    (ROOT / "bench" / "results").mkdir(exist_ok=True)
    with open(ROOT / "bench" / "results" / "modal_solvers.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["elements_per_line", "unknowns", "dense_s", "lanczos_s", "period_diff"])
        w.writerows(rows)
    print("\n| elements a line | unknowns | DENSE [s] | LANCZOS [s] | periods differ by |")
    print("|---|---|---|---|---|")
    for n, u, d, l, diff in rows:
        print(f"| {n} | {u} | {d:.4f} | {l:.4f} | {diff:.1e} |")


if __name__ == "__main__":
    main()
