#!/usr/bin/env python3
"""The paper's dynamic cases with rodyn: cost, energy balance and support tensions.

dos Santos & Rochinha, section 5: the cable of Table 1 hangs between two pins; from its
static equilibrium the top end A is moved vertically, 0.4 sin(2 pi f t) m.

  case1         input/paper_case1.inp: f = 0.658 Hz, dt 0.1 s, 900 s (about a minute)
  case2..case4  input/paper_case2..4.inp: f = 1, 1.25, 1.5 Hz, dt 0.015 s, 15 s
  case1_sudden  case 1 started suddenly as in the paper (RAMP=0 on the *MOTION line),
                100 s, output every step (OUTPUT INTERVAL=0)
  case1_ramp100 the same 100 s with the default 3 s ramp-in, output every step: the
                reference for case1_sudden
  case1_sudden_alpha, case1_ramp100_alpha
                the two 100 s variants with SCHEME=ALPHA (generalized-alpha, default
                RHO INF=0.8), the dissipative scheme offered for the sudden start

Each case runs once with `rodyn --quiet` (the decks are copied, and edited for the two
variants, into a temporary folder, or into --out). Reported per case: process wall
time, steps, Newton iterations (total, mean and largest per step), halvings, steps per
second, the energy balance error (max over the steps of |(total(t) - total(0)) -
(external work - damping work)| / max |external work|, total(0) = total after step 1
minus that step's work, from dynamic_log.csv), the tension at the top support (end A)
and at the bottom support (end B) and the smallest and largest effective tension along
the line, each over the whole run and over a final window (the last 100 s for case 1,
the last 20 s for the 100 s variants, the last 5 s otherwise), how often the top
tension changes direction from one frame to the next in that window (a smooth history
sampled n times a period: about 2/n; a history that flips every step: 1), the range
of the lowest point's z in the window, and how close the nearest frame comes to the
configuration of the paper's Table 2 (largest distance over the nodes S = 1..9 m).

Writes bench/results/dynamic_cases.csv (machine facts as # comments) and prints a
markdown table. Run from anywhere; paths are relative to the repository root.
"""
import argparse
import datetime
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from rodyn_post import load_dynamic  # noqa: E402  (installed: bash tools/setup.sh)
from benchlib import machine_facts  # noqa: E402

SECTION_INC = "paper_cable_section.inc"
# name: (deck in input/, final window [s], edits: RAMP on *MOTION, TIME, OUTPUT INTERVAL)
CASES = {
    "case1": ("paper_case1.inp", 100.0, None),
    "case2": ("paper_case2.inp", 5.0, None),
    "case3": ("paper_case3.inp", 5.0, None),
    "case4": ("paper_case4.inp", 5.0, None),
    "case1_sudden": ("paper_case1.inp", 20.0, {"ramp": 0.0, "time": 100.0, "interval": 0.0}),
    "case1_ramp100": ("paper_case1.inp", 20.0, {"time": 100.0, "interval": 0.0}),
    "case1_sudden_alpha": ("paper_case1.inp", 20.0,
                           {"ramp": 0.0, "time": 100.0, "interval": 0.0, "scheme": "ALPHA"}),
    "case1_ramp100_alpha": ("paper_case1.inp", 20.0,
                            {"time": 100.0, "interval": 0.0, "scheme": "ALPHA"}),
}
CSV_COLUMNS = (
    "case", "deck", "edits", "scheme", "complete", "time_s", "dt_s", "steps", "frames",
    "process_wall_s", "status_wall_s", "newton_iterations", "mean_iterations_per_step",
    "max_iterations_per_step", "halvings", "steps_per_s", "energy_balance_rel",
    "window_s", "top_min_N", "top_max_N", "top_min_window_N", "top_max_window_N",
    "bottom_min_N", "bottom_max_N", "bottom_min_window_N", "bottom_max_window_N",
    "line_min_N", "line_max_N", "line_min_window_N", "line_max_window_N",
    "top_reversals_window", "lowest_z_min_window_m", "lowest_z_max_window_m",
    "table2_best_distance_m", "table2_best_time_s")
# The paper's Table 2 (40-element column): X, Z [m] of its "dynamic configuration" at
# S = 1, 2, ..., 9 m (the time is not given).
PAPER_TABLE2_XZ = np.array([
    [0.55013855, -0.92111874], [1.16627385, -1.70791546], [1.89623243, -2.38908535],
    [2.75579154, -2.89488858], [3.71708198, -3.15792114], [4.71347723, -3.14134350],
    [5.66875000, -2.85537888], [6.53194628, -2.35401905], [7.29713406, -1.71132149]])


def edit_deck(text, edits):
    """The deck text with RAMP= added to the *MOTION line, TIME= / OUTPUT INTERVAL=
    replaced on the *DYNAMIC line, and the edits noted in the *HEADING title."""
    out, heading = [], False
    for line in text.splitlines():
        upper = line.strip().upper()
        if heading and upper and not upper.startswith("**"):
            line = line.rstrip() + f" [variant: {describe(edits)}]"
            heading = False
        if upper.startswith("*HEADING"):
            heading = True
        if upper.startswith("*MOTION") and "ramp" in edits:
            line = line.rstrip() + f", RAMP={edits['ramp']:g}"
        if upper.startswith("*DYNAMIC"):
            if "scheme" in edits:
                line = line.rstrip() + f", SCHEME={edits['scheme']}"
            if "time" in edits:
                line = re.sub(r"TIME\s*=\s*[^,]+", f"TIME={edits['time']:g}", line,
                              flags=re.I)
            if "interval" in edits:
                line = re.sub(r"OUTPUT\s+INTERVAL\s*=\s*[^,]+",
                              f"OUTPUT INTERVAL={edits['interval']:g}", line, flags=re.I)
        out.append(line)
    return "\n".join(out) + "\n"


def describe(edits):
    if not edits:
        return "as in input/"
    parts = []
    if "ramp" in edits:
        parts.append(f"RAMP={edits['ramp']:g}")
    if "time" in edits:
        parts.append(f"TIME={edits['time']:g}")
    if "interval" in edits:
        parts.append(f"OUTPUT INTERVAL={edits['interval']:g}")
    if "scheme" in edits:
        parts.append(f"SCHEME={edits['scheme']}")
    return " ".join(parts)


def write_deck(workdir, name):
    """Copy (and edit) the deck of case `name` into workdir; returns its path."""
    deck, _, edits = CASES[name]
    with open(os.path.join(ROOT, "input", deck)) as f:
        text = f.read()
    if edits:
        text = edit_deck(text, edits)
        before = open(os.path.join(ROOT, "input", deck)).read()
        if text.count("RAMP=") == before.count("RAMP=") and "ramp" in edits:
            sys.exit(f"could not edit the *MOTION line of {deck}")
    shutil.copy(os.path.join(ROOT, "input", SECTION_INC), os.path.join(workdir, SECTION_INC))
    path = os.path.join(workdir, f"{name}.inp")
    with open(path, "w") as f:
        f.write(text)
    return path


def reversals(series):
    """Fraction of interior samples where the series changes direction."""
    d = np.diff(series)
    if len(d) < 2:
        return float("nan")
    return float(np.mean(d[1:] * d[:-1] < 0.0))


def run_case(rodyn, workdir, name):
    deck = write_deck(workdir, name)
    out = os.path.join(workdir, name)
    if os.path.isdir(out):
        shutil.rmtree(out)
    print(f"  {name}: running {os.path.relpath(deck, workdir)} ...", file=sys.stderr,
          flush=True)
    t0 = time.perf_counter()
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if proc.returncode not in (0, 2):
        sys.exit(f"rodyn failed on {deck} (exit {proc.returncode}):\n{proc.stderr}")
    res = load_dynamic(out)
    line = res.lines[0]
    log = res.log
    window = CASES[name][1]
    t = res.time
    in_window = t >= t[-1] - window - 1e-9
    top, bottom = line.top_end, 1 - line.top_end
    tt, tb = line.end_tension[:, top], line.end_tension[:, bottom]
    nt = line.effective_tension
    steps = res.steps
    row = {
        "case": name, "deck": CASES[name][0], "edits": describe(CASES[name][2]),
        "scheme": res.scheme,
        "complete": res.complete, "time_s": float(t[-1]), "dt_s": res.dt, "steps": steps,
        "frames": len(t), "process_wall_s": wall, "status_wall_s": res.wall_time_s,
        "newton_iterations": res.step_iterations,
        "mean_iterations_per_step": res.step_iterations / max(steps, 1),
        "max_iterations_per_step": int(log.iterations.max()) if len(log) else 0,
        "halvings": res.step_cutbacks, "steps_per_s": steps / wall,
        "energy_balance_rel": log.relative_energy_error(), "window_s": window,
        "top_min_N": tt.min(), "top_max_N": tt.max(),
        "top_min_window_N": tt[in_window].min(), "top_max_window_N": tt[in_window].max(),
        "bottom_min_N": tb.min(), "bottom_max_N": tb.max(),
        "bottom_min_window_N": tb[in_window].min(),
        "bottom_max_window_N": tb[in_window].max(),
        "line_min_N": nt.min(), "line_max_N": nt.max(),
        "line_min_window_N": nt[in_window].min(), "line_max_window_N": nt[in_window].max(),
        "top_reversals_window": reversals(tt[in_window]),
        "lowest_z_min_window_m": line.z[in_window].min(),
        "lowest_z_max_window_m": line.z[in_window].min(axis=1).max(),
        "status": res.status,
    }
    # the frame nearest to the paper's Table 2 configuration (largest distance over
    # the nodes at S = 1..9 m)
    nodes = [int(np.argmin(np.abs(line.node_s - s))) for s in range(1, 10)]
    if np.allclose(line.node_s[nodes], np.arange(1, 10)):
        dist = np.hypot(line.x[:, nodes] - PAPER_TABLE2_XZ[:, 0],
                        line.z[:, nodes] - PAPER_TABLE2_XZ[:, 1]).max(axis=1)
        row["table2_best_distance_m"] = float(dist.min())
        row["table2_best_time_s"] = float(t[np.argmin(dist)])
    else:
        row["table2_best_distance_m"] = row["table2_best_time_s"] = float("nan")
    print(f"  {name}: {wall:.3g} s, {steps} steps, {res.step_iterations} iterations, "
          f"{res.step_cutbacks} halvings, {res.status}", file=sys.stderr, flush=True)
    return row


def kn(v):
    return f"{v / 1e3:.4g}"


def print_tables(rows):
    print("| case | steps | process wall [s] | steps/s | Newton it. (mean, max per step) "
          "| halvings | energy balance | top T whole run [kN] | top T window [kN] "
          "| bottom T whole run [kN] | bottom T window [kN] |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        done = "" if r["complete"] else " (incomplete)"
        print(f"| {r['case']}{done} | {r['steps']} | {r['process_wall_s']:.3g} "
              f"| {r['steps_per_s']:.0f} | {r['newton_iterations']} "
              f"({r['mean_iterations_per_step']:.2f}, {r['max_iterations_per_step']}) "
              f"| {r['halvings']} | {r['energy_balance_rel']:.1e} "
              f"| {kn(r['top_min_N'])} – {kn(r['top_max_N'])} "
              f"| {kn(r['top_min_window_N'])} – {kn(r['top_max_window_N'])} "
              f"| {kn(r['bottom_min_N'])} – {kn(r['bottom_max_N'])} "
              f"| {kn(r['bottom_min_window_N'])} – {kn(r['bottom_max_window_N'])} |")
    print()
    print("| case | window | frames | effective tension along the line, whole run [kN] "
          "| same, window [kN] | top T direction changes per frame, window "
          "| lowest point z, window [m] | nearest to paper Table 2 [m] (at t [s]) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['case']} | last {r['window_s']:g} s | {r['frames']} "
              f"| {kn(r['line_min_N'])} – {kn(r['line_max_N'])} "
              f"| {kn(r['line_min_window_N'])} – {kn(r['line_max_window_N'])} "
              f"| {r['top_reversals_window']:.2f} "
              f"| {r['lowest_z_min_window_m']:.3f} – {r['lowest_z_max_window_m']:.3f} "
              f"| {r['table2_best_distance_m']:.2g} ({r['table2_best_time_s']:g}) |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"),
                    help="rodyn executable (default: build/rodyn)")
    ap.add_argument("--cases", nargs="+", choices=list(CASES), default=list(CASES),
                    metavar="CASE", help=f"cases to run (default: all: {' '.join(CASES)})")
    ap.add_argument("--out", help="folder for the decks and results (kept; default: a "
                    "temporary folder, removed)")
    ap.add_argument("--csv", default=os.path.join(ROOT, "bench", "results",
                                                  "dynamic_cases.csv"),
                    help="CSV to write (default: bench/results/dynamic_cases.csv)")
    args = ap.parse_args()
    rodyn = os.path.abspath(args.rodyn)
    if not os.access(rodyn, os.X_OK):
        sys.exit(f"no executable rodyn at {rodyn} (build it, or give --rodyn)")

    facts = machine_facts(rodyn)
    facts["rodyn binary"] = f"{rodyn}, built " + datetime.datetime.fromtimestamp(
        os.path.getmtime(rodyn)).astimezone().strftime("%Y-%m-%d %H:%M %Z")
    print("# rodyn dynamic cases (dos Santos & Rochinha, section 5)\n")
    for k, v in facts.items():
        print(f"- {k}: {v}")
    print()

    if args.out:
        workdir = os.path.abspath(args.out)
        os.makedirs(workdir, exist_ok=True)
        rows = [run_case(rodyn, workdir, name) for name in args.cases]
    else:
        with tempfile.TemporaryDirectory(prefix="rodyn_dynamic_") as workdir:
            rows = [run_case(rodyn, workdir, name) for name in args.cases]

    print_tables(rows)
    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w") as f:
        for k, v in facts.items():
            f.write(f"# {k}: {v}\n")
        f.write(",".join(CSV_COLUMNS) + "\n")
        for r in rows:
            values = []
            for c in CSV_COLUMNS:
                v = r[c]
                if isinstance(v, bool):
                    v = "true" if v else "false"
                elif isinstance(v, float):
                    v = f"{v:.6e}"
                values.append(str(v))
            f.write(",".join(values) + "\n")
    print(f"\nwrote {os.path.relpath(os.path.abspath(args.csv), ROOT)}")


if __name__ == "__main__":
    main()
