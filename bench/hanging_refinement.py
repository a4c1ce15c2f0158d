#!/usr/bin/env python3
"""Mesh and step refinement of a hanging line with a free lower end (a slack end in water).

bench/decks/hanging_free_end.inp: cubic cable elements, top at (0, 0, -5), 50 m, D 0.3 m,
100 kg/m, EA 1e9 N, Cd 1, Ca 1, water 1025 kg/m3, 500 m deep; the top surged 2 m in x at
a period of 10 s, ramped in over 12 s; 40 s. The ladder: 20, 40, 80, 160, 320 elements
with dt 0.05, 0.025, 0.0125, 0.00625, 0.003125 s (dt halved with the element length).

For each rung: the top force's magnitude at every step (dynamic_ends_step.csv, end A),
sampled at the common instants every 0.05 s over 20-40 s (cubic interpolation between
the steps, bench/benchlib.py's interp_cubic); its minimum and maximum; what the fit of
harmonics 0-8 of the surge frequency leaves (rms and peak: the noise); the difference
from the next coarser rung: of the force, its largest and its rms, and the largest of
its fitted periodic part; steps, Newton iterations, step halvings, CPU.
Converged under refinement means: the rms difference and the periodic part's difference
each smaller than the one before, and no step halvings. Exit status 1 if that fails.
(The largest difference is written too; it is set by the sharpest snap of the slack
end, the force's content above the 8th harmonic, which a finer mesh resolves sharper.)

    python3 bench/hanging_refinement.py          # the default in water: EMC, RHO INF 0.8
    python3 bench/hanging_refinement.py --scheme "EMC, RHO INF=1" --rungs 4 --tag emc
    python3 bench/hanging_refinement.py --scheme "ALPHA, RHO INF=0" --tag alpha0
    python3 bench/hanging_refinement.py --scheme "EMC, RHO INF=1" \
        --section "AXIAL DAMPING RATIO=1" --tag zeta1
    python3 bench/hanging_refinement.py --rungs 3              # 20, 40, 80 only

Writes bench/results/hanging_refinement[_TAG].csv with the machine facts.
"""
import argparse
import math
import os
import resource
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

DECK = os.path.join(HERE, "decks", "hanging_free_end.inp")
LADDER = [(20, 0.05), (40, 0.025), (80, 0.0125), (160, 0.00625), (320, 0.003125)]
WINDOW = (20.0, 40.0)
PERIOD = 10.0


def top_force(out):
    """Times and magnitudes of the support force at end A, every step."""
    t, f = benchlib.read_end_forces(out, "A")
    return t, np.linalg.norm(f, axis=1)


def harmonic_fit(t, y, n=8):
    """The least-squares fit of harmonics 0-n of the surge frequency to y at t."""
    w = 2 * math.pi / PERIOD
    cols = [np.ones_like(t)]
    for k in range(1, n + 1):
        cols += [np.cos(k * w * t), np.sin(k * w * t)]
    a = np.column_stack(cols)
    coef, *_ = np.linalg.lstsq(a, y, rcond=None)
    return a @ coef


def run(rodyn, work, ne, dt, scheme, extra, section=""):
    out = os.path.join(work, f"ne{ne}")
    with open(DECK) as fh:
        text = fh.read().replace("SCHEME=EMC", "SCHEME=" + scheme)
    if section:
        text = text.replace("CAN=1.0, CAA=0.0\n", f"CAN=1.0, CAA=0.0, {section}\n")
    deck = os.path.join(work, "hanging_free_end.inp")
    with open(deck, "w") as fh:
        fh.write(text)
    args = [rodyn, deck, "-o", out, "--quiet", "--set", f"NE={ne}", "--set", f"DT={dt}"]
    for s in extra:
        args += ["--set", s]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(args, capture_output=True, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    st = benchlib.read_status(os.path.join(out, "status.txt"))
    row = {"elements": ne, "dt_s": dt, "returncode": proc.returncode, "cpu_s": cpu,
           "steps": int(st.get("steps", 0) or 0),
           "iterations": int(st.get("step_iterations", 0) or 0),
           "halvings": int(st.get("step_cutbacks", 0) or 0)}
    if proc.returncode != 0:
        row["error"] = proc.stderr.strip().splitlines()[-1] if proc.stderr else "failed"
        return row, None
    t, f = top_force(out)
    tq = np.arange(WINDOW[0], WINDOW[1] + 1e-9, 0.05)
    fq = benchlib.interp_cubic(t, f, tq)
    per = harmonic_fit(tq, fq)
    res = fq - per
    row.update({"min_N": fq.min(), "max_N": fq.max(), "noise_rms_N": np.sqrt(np.mean(res**2)),
                "noise_peak_N": np.abs(res).max()})
    return row, (fq, per)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--scheme", default="EMC",  # in water: RHO INF 0.8 unless given
                    help="the *DYNAMIC card's SCHEME= value and what follows it, e.g. "
                         "'ALPHA, RHO INF=0'")
    ap.add_argument("--set", action="append", default=[], dest="extra",
                    help="further NAME=VALUE for the deck's *PARAMETER (repeatable)")
    ap.add_argument("--section", default="",
                    help="options added to the *SECTION card, e.g. 'AXIAL DAMPING RATIO=1'")
    ap.add_argument("--rungs", type=int, default=len(LADDER))
    ap.add_argument("--tag", default="")
    args = ap.parse_args()
    rodyn = benchlib.check_rodyn(args.rodyn)
    facts = benchlib.rodyn_binary_facts(rodyn)
    rows, prev = [], None
    with tempfile.TemporaryDirectory() as work:
        for ne, dt in LADDER[:args.rungs]:
            row, fq = run(rodyn, work, ne, dt, args.scheme, args.extra, args.section)
            if fq is not None and prev is not None:
                row["diff_from_coarser_N"] = np.abs(fq[0] - prev[0]).max()
                row["rms_diff_N"] = np.sqrt(np.mean((fq[0] - prev[0]) ** 2))
                row["periodic_diff_N"] = np.abs(fq[1] - prev[1]).max()
            prev = fq
            rows.append(row)
            print("  ".join(f"{k} {v:.6g}" if isinstance(v, float) else f"{k} {v}"
                            for k, v in row.items()), flush=True)
    ok = all(r["returncode"] == 0 and r["halvings"] == 0 for r in rows)
    for key in ("rms_diff_N", "periodic_diff_N"):
        diffs = [r[key] for r in rows if key in r]
        ok = ok and len(diffs) == len(rows) - 1 and all(b < a for a, b in
                                                         zip(diffs, diffs[1:]))
    name = "hanging_refinement" + (f"_{args.tag}" if args.tag else "") + ".csv"
    cols = ["elements", "dt_s", "returncode", "min_N", "max_N", "noise_rms_N",
            "noise_peak_N", "diff_from_coarser_N", "rms_diff_N", "periodic_diff_N", "steps",
            "iterations", "halvings",
            "cpu_s"]
    benchlib.write_csv(os.path.join(ROOT, "bench", "results", name), facts, cols, rows,
                       comments=[f"scheme {args.scheme}; section options {args.section}; "
                                 f"--set {' '.join(args.extra)}",
                                 f"top force magnitude over {WINDOW[0]}-{WINDOW[1]} s, "
                                 "sampled every 0.05 s"])
    print("converged under refinement" if ok else
          "NOT converged: differences do not shrink at every refinement, or steps halved")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
