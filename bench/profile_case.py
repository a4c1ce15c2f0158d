#!/usr/bin/env python3
"""Where the time of a dynamic run goes: assembly (element forces and tangents),
factorisation, back-substitution, output, the rest; and what each "skip" saves.

The counts are instructions executed inside the time loop (valgrind's callgrind, with
collection switched on in run_dynamic only, inclusive per routine: the time loop with
the dynamic set-up and the opening and closing of the output files; the static start is
left out. The link-time optimiser inlines timeloop_run into run_dynamic, so the time
loop alone has no symbol to switch on), which, unlike timings on a shared machine, repeat exactly. Cases: the paper's case 1 (30 cubic
elements, dt = 0.1 s) and the 1000 m line of bench/decks/scr1000.inp, each shortened to
`--time` seconds, with TANGENT=REUSE (the default) and TANGENT=NEW, and case 1 once more
without output files (*OUTPUT, CSV=NO, HDF5=NO).

Usage: python3 bench/profile_case.py [--rodyn build/rodyn] [--time 10] [--scr-time 2]
Writes a markdown table on stdout and bench/results/profile_case.csv. Needs valgrind
(apt-get install valgrind). Takes about 2 minutes.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

# Routines whose inclusive count makes a part; the first match of a symbol wins.
PARTS = [
    ("assembly", r"__rodyn_dynamics_MOD_dyn_evaluate$"),
    ("factorisation", r"__rodyn_banded_MOD_banded_factor$"),
    # LAPACK's dgbtrs (pivoted factors), or the unpivoted solve inlined into rod_solve
    # (its count less the factorisation inside it: see split)
    ("back-substitution", r"^dgbtrs_$"),
    ("output", r"__rodyn_output_dynamic_MOD_dynamic_output_(frame|step)"),
]


def callgrind(rodyn, deck, workdir):
    """Inclusive instruction counts of a run: (total, {symbol: count})."""
    out = os.path.join(workdir, "cg.out")
    res = os.path.join(workdir, "res")
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                    "--toggle-collect=*run_dynamic*", rodyn, deck, "-o", res, "--quiet"],
                   check=True, capture_output=True)
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                         check=True, capture_output=True, text=True).stdout
    total, incl = 0, {}
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(\S+)", line)
        if not m:
            continue
        count = int(m.group(1).replace(",", ""))
        sym = m.group(2)
        if "PROGRAM TOTALS" in line:
            total = count
            continue
        name = sym.split(":", 1)[1] if ":" in sym else sym
        name = re.sub(r"\.(constprop|isra|part)\.\d+", "", name)
        incl[name] = max(incl.get(name, 0), count)
    if not total:
        total = max(incl.values())
    status = benchlib.read_status(os.path.join(res, "status.txt"))
    return total, incl, status


def split(total, incl):
    """Counts per part (first matching symbol of each part), and the rest."""
    parts = {}
    for part, pat in PARTS:
        parts[part] = sum(c for name, c in incl.items() if re.search(pat, name))
    if not parts["back-substitution"]:
        solve = incl.get("__rodyn_rod_problem_MOD_rod_solve", 0)
        parts["back-substitution"] = max(solve - parts["factorisation"], 0)
    parts["rest"] = total - sum(parts.values())
    return parts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default="build/rodyn")
    ap.add_argument("--time", type=float, default=10.0, help="simulated time of case 1 [s]")
    ap.add_argument("--scr-time", type=float, default=2.0,
                    help="simulated time of the 1000 m line [s]")
    args = ap.parse_args()
    rodyn = os.path.abspath(args.rodyn)
    benchlib.check_rodyn(rodyn)
    case1 = benchlib.read_deck("input/paper_case1.inp")
    scr = benchlib.read_deck("bench/decks/scr1000.inp")
    cases = []
    for tangent in ("REUSE", "NEW"):
        cases.append((f"case 1, {tangent}", benchlib.set_params(
            case1, "*DYNAMIC", {"TIME": args.time, "TANGENT": tangent}),
            ["input/paper_cable_section.inc"]))
    text = benchlib.set_params(case1, "*DYNAMIC", {"TIME": args.time})
    text = benchlib.set_params(text, "*OUTPUT", {"CSV": "NO", "HDF5": "NO"})
    cases.append(("case 1, REUSE, no output", text, ["input/paper_cable_section.inc"]))
    for tangent in ("REUSE", "NEW"):
        cases.append((f"1000 m line, {tangent}", benchlib.set_params(
            scr, "*DYNAMIC", {"TIME": args.scr_time, "TANGENT": tangent}), []))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, (label, text, inc) in enumerate(cases):
            work = os.path.join(tmp, f"c{k}")
            os.makedirs(work)
            deck = benchlib.write_deck(work, "deck", text, inc)
            total, incl, status = callgrind(rodyn, deck, work)
            parts = split(total, incl)
            row = {"case": label, "instructions": total,
                   "steps": int(status.get("steps", 0)),
                   "iterations": int(status.get("step_iterations", 0)),
                   "tangents": int(status.get("step_tangents", 0))}
            row.update({p: parts[p] / total for p in parts})
            rows.append(row)
            print(f"  {label}: {total:.3e} instructions", file=sys.stderr)
    names = [p for p, _ in PARTS] + ["rest"]
    header = ["case", "instructions", "per step", "it./step", "tangents/step"] + names
    table = []
    for r in rows:
        steps = max(r["steps"], 1)
        table.append([r["case"], f"{r['instructions']:.3e}",
                      f"{r['instructions'] / steps:.3e}", f"{r['iterations'] / steps:.2f}",
                      f"{r['tangents'] / steps:.2f}"] + [f"{100 * r[p]:.1f} %" for p in names])
    print("\n".join(benchlib.md_table(header, table)))
    facts = benchlib.machine_facts(rodyn)
    os.makedirs(os.path.join(benchlib.ROOT, "bench", "results"), exist_ok=True)
    benchlib.write_csv(os.path.join(benchlib.ROOT, "bench", "results", "profile_case.csv"),
                       facts, ["case", "instructions", "steps", "iterations", "tangents"]
                       + names, rows,
                       comments=["parts: fraction of the instructions of the whole run"])


if __name__ == "__main__":
    main()
