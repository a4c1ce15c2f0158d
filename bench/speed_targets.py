#!/usr/bin/env python3
"""The speed targets: the baseline figure, the one measured, the gain, met or not.

usage: python3 bench/speed_targets.py [--rodyn PATH] [--quick] [--skip ROW [ROW ...]]
                                      [--run-peers] [--csv PATH]
       (about 5 minutes, --quick 1 minute, without --run-peers; writes
        bench/results/speed_targets.csv and prints a markdown table)

One row per speed target (the program's and its cable element's), the baseline
hard-coded as the targets were set (2026-11-24; the cable element's from
docs/water.md, 2026-11-25). Rows (names for --skip):

  case1         the paper's case 1 deck as shipped (input/paper_case1.inp with
                input/paper_cable_section.inc, copied into a temporary folder): whole-process
                wall time, best of 2 runs. Target <= 1.5 s (baseline 8.5 s).
  newton        Newton iterations per step of that run (step_iterations / steps of its
                status.txt; tangents per step too, step_tangents / steps). Target <= 3
                (baseline 7.6; 12 971 tangents over 9000 steps = 1.44).
  instructions  instructions per step of case 1 shortened to TIME = 20 s: callgrind's total
                with collection in timeloop_run only (bench/profile_case.py's `callgrind`)
                over the steps of status.txt. Target <= 3e6 (baseline 1.35e7). Needs valgrind
                (skipped with a note without it). Where the link-time optimisation has
                inlined timeloop_run (its toggle then collects nothing), the instructions
                inclusive in run_dynamic, the routine that calls it (the time loop plus the
                dynamic set-up and opening the output), from one whole-run profile; the
                row's note says which count it is.
  scaling       exponent b of (time per step) ~ n^b, cubic and quadratic elements, 100,
                300, 1000, 3000 and 10 000 elements (--quick: 100, 1000, 3000): the decks,
                timing (median of repeats, static-only deck subtracted) and least-squares
                fit of bench/dynamic_scaling.py. Target <= 1.05 (baseline 1.16 and 1.22).
  scaling_instructions
                the same exponent from instructions instead of wall times: callgrind's
                count inclusive in run_dynamic (bench/profile_case.py's `callgrind`: the
                dynamic set-up, the 20 steps, closing the output; the static solve before
                is not counted) over the steps, cubic and quadratic elements, the sizes of
                the row scaling (--quick: 100, 300, 1000); about 4 minutes. Instruction
                counts repeat exactly, so this fit is free of the timing noise of small
                meshes, and of the memory hierarchy of large ones (a large mesh's step
                waits on memory: wall time per instruction grows with n). Needs valgrind.
  memory        memory per cubic element: (peak RSS - peak RSS at 10 elements) / n at
                10 000 elements (--quick: 3000), the decks and GNU time measurement of
                bench/memory_scaling.py. Target <= 19 KiB (baseline 19 KiB). Quadratic
                elements reported alongside.
  cable         the mooring surge case (input/mooring_surge.inp, bench/water/): 24 cubic
                cable elements and 30 cubic rod elements at dt = 0.1 s (the cheapest
                settings within 1 % of MoorDyn's 320-segment run on maximum, mean and first
                harmonic of the fairlead tension, docs/water.md), whole-process wall time,
                best of 2 runs; errors as bench/water/compare_peers.py takes them. Target:
                rod / cable >= 3 (baseline 2.1: 1.41 s / 0.67 s); MoorDyn's converged
                dynamics (320 segments, 42.2 s, a stored figure of docs/water.md, not
                re-run) / cable >= 30 (baseline 63).
  peers         at 1 % top-tension error, CableDyn's cheapest run over rodyn's cheapest
                (bench/peers/run_peers.py's best_at on bench/results/peers_case1.csv and
                peers_case4.csv: the smallest median wall time of a complete run with
                tension_max_rel <= 0.01). Target >= 5 (baseline 0.7 and 2.7). Reads the
                stored CSV files unless --run-peers is given, which first runs
                `bench/peers/run_peers.py --cases case1 case4 --tools rodyn cabledyn
                --fresh` (30 minutes or more; it installs the peers into its own venv).

Ratio: for a figure where smaller is better (times, iterations, instructions, exponents,
memory) the gain baseline / measured; where larger is better (speed-ups) measured /
baseline. A gain
above 1 is progress either way. --quick runs the timings of case1 and cable once
instead of best of 2, and the smaller sizes for scaling and memory (the scaling rows keep
dynamic_scaling.py's repeats: one run of a 20-step deck is too noisy to fit). Wall
times are only comparable on an otherwise idle machine: the load average before the
run is printed (and written to the CSV), with a warning above 0.5.
"""
import argparse
import csv
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
import dynamic_scaling  # noqa: E402
from memory_scaling import peak_kib  # noqa: E402
from profile_case import callgrind  # noqa: E402

ROOT = benchlib.ROOT
ROWS = ["case1", "newton", "instructions", "scaling", "scaling_instructions", "memory", "cable",
        "peers"]
ISSUE = "targets of 2026-11-24"
WATER = "docs/water.md, 2026-11-25"
CASE1_INC = ["input/paper_cable_section.inc"]
SCALING_SIZES = [100, 300, 1000, 3000, 10000]
SCALING_SIZES_QUICK = [100, 1000, 3000]
INSTR_SIZES = SCALING_SIZES
INSTR_SIZES_QUICK = [100, 300, 1000]
MOORDYN_320_WALL_S = 42.2      # docs/water.md: 320 segments, 2026-11-25, run once
SURGE_RUNS = [("cable", "CABLE", 3, 24, 0.1), ("rod", "ROD", 3, 30, 0.1)]
PEERS_TARGET_ERROR = 0.01


def load_module(name, relpath):
    """A bench script outside bench/ (bench/water/, bench/peers/) imported by its path."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, relpath))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def row(target, goal, baseline, source, now, smaller_better, met_rule, fmt, note=""):
    """One table row (a dict). `now` None: not measured (note says why); met_rule a
    function of `now`, or None for an information row."""
    r = {"target": target, "goal": goal, "baseline": baseline, "baseline_source": source,
         "now": now, "note": note, "ratio": None, "ratio_kind": "", "met": None, "fmt": fmt}
    if now is not None and baseline is not None and now > 0:
        if smaller_better:
            r["ratio"], r["ratio_kind"] = baseline / now, "baseline/measured"
        else:
            r["ratio"], r["ratio_kind"] = now / baseline, "measured/baseline"
    if now is not None and met_rule is not None:
        r["met"] = bool(met_rule(now))
    return r


def skipped(target, goal, baseline, source, fmt, why):
    return row(target, goal, baseline, source, None, True, None, fmt, why)


def best_run(rodyn, deck, out, runs):
    """Whole-process wall time, best of `runs`, and the status of the last run; exits if
    a run fails."""
    best, st = None, {}
    for _ in range(runs):
        r = benchlib.run_rodyn(rodyn, deck, out)
        if r["returncode"] != 0 or r["status"].get("complete") != "true":
            sys.exit(f"{deck}: rodyn exit {r['returncode']}, status "
                     f"{r['status'].get('status', '?')}: {r['stderr'][-300:]}")
        best = r["wall_s"] if best is None else min(best, r["wall_s"])
        st = r["status"]
    return best, st


def case1_rows(rodyn, tmp, runs, skip):
    """Rows case1 and newton: the shipped deck, best of `runs`."""
    deck = benchlib.write_deck(tmp, "paper_case1", benchlib.read_deck("input/paper_case1.inp"),
                               CASE1_INC)
    wall, st = best_run(rodyn, deck, os.path.join(tmp, "case1"), runs)
    print(f"  case 1 as shipped: {wall:.3f} s (best of {runs})", file=sys.stderr, flush=True)
    steps = int(st["steps"])
    it, tan = int(st["step_iterations"]) / steps, int(st["step_tangents"]) / steps
    out = []
    if "case1" not in skip:
        out.append(row("case 1 as shipped: process wall [s]", "<= 1.5", 8.5, ISSUE, wall, True,
                       lambda v: v <= 1.5, ".3g", f"best of {runs}"))
    if "newton" not in skip:
        out.append(row("case 1: Newton iterations per step", "<= 3", 7.6, ISSUE, it, True,
                       lambda v: v <= 3.0, ".2f",
                       f"{st['step_iterations']} iterations / {steps} steps"))
        out.append(row("case 1: tangents per step (information)", "–", 12971 / 9000, ISSUE,
                       tan, True, None, ".2f",
                       f"{st['step_tangents']} tangents / {steps} steps"))
    return out


def instructions_row(rodyn, tmp):
    """Row instructions: callgrind of case 1 shortened to 20 s, per step."""
    target, goal, base = "case 1 (20 s): instructions per step", "<= 3e6", 1.35e7
    if not (shutil.which("valgrind") and shutil.which("callgrind_annotate")):
        return skipped(target, goal, base, ISSUE, ".3g",
                       "skipped: no valgrind (apt-get install valgrind)")
    text = benchlib.read_deck("input/paper_case1.inp")
    if "TIME=900.0" not in text:
        sys.exit("input/paper_case1.inp has no TIME=900.0 to shorten")
    work = os.path.join(tmp, "callgrind")
    os.makedirs(work)
    deck = benchlib.write_deck(work, "case1_20s", text.replace("TIME=900.0", "TIME=20.0"),
                               CASE1_INC)
    try:
        total, _, st = callgrind(rodyn, deck, work)
        how = "time loop only (profile_case.py's count)"
    except ValueError:
        # nothing collected: timeloop_run is not a symbol of this binary (inlined by the
        # link-time optimisation), so profile_case.py's toggle never switches collection on
        total, whole, st = callgrind_run_dynamic(rodyn, deck, work)
        how = (f"timeloop_run is not in this binary (inlined), so profile_case.py counts "
               f"nothing: counted instead inclusive in run_dynamic (time loop with the "
               f"dynamic set-up and output opening; whole run {whole:.4g})")
    steps = int(st["steps"])
    print(f"  case 1 (20 s) under callgrind: {total:.4g} instructions, {steps} steps",
          file=sys.stderr, flush=True)
    return row(target, goal, base, ISSUE, total / steps, True, lambda v: v <= 3e6, ".3g",
               f"{total:.4g} instructions / {steps} steps, {how}")


def callgrind_run_dynamic(rodyn, deck, workdir):
    """Instructions of a whole run under callgrind and those inclusive in run_dynamic, the
    routine that calls timeloop_run (for a build where timeloop_run is inlined):
    (run_dynamic's count, whole run, status)."""
    out, res = os.path.join(workdir, "cg_whole.out"), os.path.join(workdir, "res_whole")
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", rodyn,
                    deck, "-o", res, "--quiet"], check=True, capture_output=True)
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                         check=True, capture_output=True, text=True).stdout
    total, loop = 0, 0
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(\S+)", line)
        if not m:
            continue
        count = int(m.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in line:
            total = count
        elif re.search(r"__rodyn_run_dynamic_MOD_run_dynamic($|\.)", m.group(2)):
            loop = max(loop, count)
    if not loop:
        sys.exit(f"callgrind: no run_dynamic in the profile of {deck}")
    return loop, total, benchlib.read_status(os.path.join(res, "status.txt"))


def scaling_rows(rodyn, tmp, sizes):
    """Rows scaling: bench/dynamic_scaling.py's run_case and fit, per order."""
    out = []
    for order, base in ((3, 1.16), (2, 1.22)):
        rows = []
        for n in sizes:
            r = dynamic_scaling.run_case(rodyn, tmp, n, order)
            rows.append(r)
            msg = (f"FAILED: {r['status']}" if r["failed"] else
                   f"{1e3 * r['per_step_s']:.4g} ms/step, {r['iterations_per_step']:.2f} "
                   "it./step")
            print(f"  scaling p={order} n={n}: {msg}", file=sys.stderr, flush=True)
        b = benchlib.fit_exponent(rows, "per_step_s", dynamic_scaling.FIT_MIN_N)
        failed = [str(r["elements"]) for r in rows if r["failed"]]
        per_step = [f"{1e3 * r['per_step_s']:.3g}" for r in rows if not r["failed"]]
        note = f"n = {', '.join(map(str, sizes))}; per step {', '.join(per_step)} ms"
        if failed:
            note += f"; failed (left out): n = {', '.join(failed)}"
        name = "cubic" if order == 3 else "quadratic"
        out.append(row(f"cost per step ~ n^b, {name}: b", "<= 1.05", base, ISSUE,
                       b if b == b else None, True, lambda v: v <= 1.05, ".3f", note))
    return out


def scaling_instructions_rows(rodyn, tmp, sizes):
    """Rows scaling_instructions: dynamic_scaling.py's decks under callgrind, collection
    in run_dynamic, instructions per step fitted as dynamic_scaling.py fits times."""
    target = "cost per step ~ n^b in instructions, {}: b"
    out = []
    if not (shutil.which("valgrind") and shutil.which("callgrind_annotate")):
        for name in ("cubic", "quadratic"):
            out.append(skipped(target.format(name), "<= 1.05", None, ISSUE, ".3f",
                               "skipped: no valgrind (apt-get install valgrind)"))
        return out
    for order in (3, 2):
        rows = []
        for n in sizes:
            work = os.path.join(tmp, f"cg_scaling_p{order}_n{n}")
            os.makedirs(work)
            deck = benchlib.write_deck(work, "deck", dynamic_scaling.make_deck(n, order, True))
            total, _, st = callgrind(rodyn, deck, work)
            steps = int(st["steps"])
            rows.append({"elements": n, "failed": False, "per_step": total / steps,
                         "per_iteration": total / int(st["step_iterations"]),
                         "tangents": int(st["step_tangents"]),
                         "iterations": int(st["step_iterations"])})
            print(f"  instructions p={order} n={n}: {total / steps:.4g} a step "
                  f"({st['step_iterations']} iterations, {st['step_tangents']} tangents)",
                  file=sys.stderr, flush=True)
        b = benchlib.fit_exponent(rows, "per_step", dynamic_scaling.FIT_MIN_N)
        bi = benchlib.fit_exponent(rows, "per_iteration", dynamic_scaling.FIT_MIN_N)
        note = (f"n = {', '.join(map(str, sizes))}; per step "
                + ", ".join(f"{r['per_step']:.3g}" for r in rows) + " instructions; "
                + "iterations / tangents in 20 steps "
                + ", ".join(f"{r['iterations']}/{r['tangents']}" for r in rows)
                + f" (instructions per Newton iteration ~ n^{bi:.3f}: the exponent per "
                "step also holds the iteration counts, which vary with n without a trend)")
        name = "cubic" if order == 3 else "quadratic"
        out.append(row(target.format(name), "<= 1.05", None, ISSUE, b, True,
                       lambda v: v <= 1.05, ".3f", note))
    return out


def memory_rows(rodyn, tmp, largest):
    """Rows memory: peak RSS above the 10-element run, per element, at `largest`
    elements (the decks of bench/memory_scaling.py)."""
    if not os.path.exists("/usr/bin/time"):
        return [skipped("memory per cubic element [KiB]", "<= 19", 19.0, ISSUE, ".3g",
                        "skipped: needs GNU time (apt-get install time)")]
    out = []
    for order in (3, 2):
        kib = {}
        for n in (10, largest):
            # as memory_scaling.main: outputs written, a frame every 5 steps
            text = dynamic_scaling.make_deck(n, order, True)
            text = re.sub(r"\*OUTPUT[^\n]*", "*OUTPUT, CSV=YES, HDF5=YES", text)
            text = benchlib.set_params(text, "*DYNAMIC", {"OUTPUT INTERVAL": 0.075})
            deck = benchlib.write_deck(tmp, f"mem_p{order}_n{n}", text)
            kib[n] = peak_kib(rodyn, deck, os.path.join(tmp, f"out_mem_p{order}_n{n}"))
        per = (kib[largest] - kib[10]) / largest
        print(f"  memory p={order}: {kib[10]} KiB at 10, {kib[largest]} KiB at {largest}",
              file=sys.stderr, flush=True)
        note = (f"({kib[largest]} - {kib[10]}) KiB / {largest} elements")
        if order == 3:
            out.append(row("memory per cubic element [KiB]", "<= 19", 19.0, ISSUE, per, True,
                           lambda v: v <= 19.0, ".3g", note))
        else:
            out.append(row("memory per quadratic element [KiB] (information)", "–", 11.3,
                           "docs/benchmarks.md, 2026-11-23", per, True, None, ".3g", note))
    return out


def cable_rows(rodyn, tmp, runs):
    """Rows cable: the surge deck as compare_peers.surge_sweep edits it, cable 24 and rod
    30 cubic elements at dt 0.1 s, best of `runs`; errors against MoorDyn's finest run."""
    cp = load_module("compare_peers", "bench/water/compare_peers.py")
    with open(os.path.join(cp.REF, "moordyn_surge_summary.json")) as f:
        ref = json.load(f)
    fin = max(ref["runs"] + ref.get("runs_extra", []), key=lambda r: r["segments"])
    text0 = benchlib.read_deck("input/mooring_surge.inp")
    mesh0, dt0 = "ELEMENTS=120, ORDER=3, ELEMENT=CABLE", "DT=0.05,"
    if mesh0 not in text0 or dt0 not in text0:
        sys.exit("input/mooring_surge.inp: no '" + mesh0 + "' or '" + dt0 + "' to edit "
                 "(as bench/water/compare_peers.py's surge_sweep does)")
    walls, errs = {}, {}
    for tag, kind, order, ne, dt in SURGE_RUNS:
        text = text0.replace(mesh0, f"ELEMENTS={ne}, ORDER={order}, ELEMENT={kind}")
        text = text.replace(dt0, f"DT={dt},")
        deck = benchlib.write_deck(tmp, f"surge_{tag}", text, ["input/mooring_leg_section.inc"])
        out = os.path.join(tmp, f"surge_{tag}")
        walls[tag], _ = best_run(rodyn, deck, out, runs)
        mx, mean, h1 = cp.surge_stats(out)
        errs[tag] = (mx / fin["max_N"] - 1, mean / fin["mean_N"] - 1,
                     h1 / fin["harmonic1_amplitude_N"] - 1)
        print(f"  surge {tag} ({ne} el., dt {dt}): {walls[tag]:.3f} s, errors max "
              f"{errs[tag][0]:+.2%}, mean {errs[tag][1]:+.3%}, 1st harmonic "
              f"{errs[tag][2]:+.2%}", file=sys.stderr, flush=True)

    def err_text(tag):
        e = errs[tag]
        within = "within" if max(abs(x) for x in e) <= 0.01 else "NOT within"
        return (f"{tag} {walls[tag]:.3g} s, errors max {e[0]:+.2%}, mean {e[1]:+.3%}, "
                f"1st harm. {e[2]:+.2%} ({within} 1 %)")
    n = fin["segments"]
    note = (f"{err_text('cable')}; {err_text('rod')}; against MoorDyn N={n}; "
            f"best of {runs}")
    return [row("surge case: rod / cable wall at equal error", ">= 3", 1.41 / 0.67, WATER,
                walls["rod"] / walls["cable"], False, lambda v: v >= 3.0, ".2f", note),
            row(f"surge case: MoorDyn converged (N={n}) dynamics / cable wall", ">= 30",
                MOORDYN_320_WALL_S / 0.67, WATER, MOORDYN_320_WALL_S / walls["cable"], False,
                lambda v: v >= 30.0, ".3g",
                f"MoorDyn {MOORDYN_320_WALL_S} s: a stored figure (docs/water.md, "
                "2026-11-25), not re-run")]


def read_peers_csv(path):
    """Rows of a bench/results/peers_<case>.csv as dicts (floats, complete as bool) and
    its '# key: value' lines."""
    facts, lines = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                k, _, v = line[1:].partition(":")
                facts[k.strip()] = v.strip()
            else:
                lines.append(line)
    rows = []
    for r in csv.DictReader(lines):
        d = dict(r)
        for k, v in r.items():
            if k in ("case", "tool", "settings", "status", "complete"):
                continue
            try:
                d[k] = float(v) if v != "" else float("nan")
            except ValueError:
                pass
        d["complete"] = r["complete"] == "true"
        rows.append(d)
    return facts, rows


def peers_rows(rodyn, run_peers):
    """Rows peers: CableDyn's cheapest / rodyn's cheapest at 1 % top-tension error."""
    script = os.path.join(ROOT, "bench", "peers", "run_peers.py")
    if run_peers:
        cmd = [sys.executable, script, "--cases", "case1", "case4", "--tools", "rodyn",
               "cabledyn", "--fresh", "--rodyn", rodyn]
        print("  running " + " ".join(cmd), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=True)
    rp = load_module("run_peers", "bench/peers/run_peers.py")
    out = []
    for case, base in (("case1", 0.7), ("case4", 2.7)):
        path = os.path.join(ROOT, "bench", "results", f"peers_{case}.csv")
        target = f"{case}: CableDyn / rodyn wall at 1 % top-tension error"
        if not os.path.isfile(path):
            out.append(skipped(target, ">= 5", base, ISSUE, ".2f",
                               f"no {os.path.relpath(path, ROOT)} (run with --run-peers)"))
            continue
        facts, rows = read_peers_csv(path)
        mine = rp.best_at(rows, "rodyn", "tension_max_rel", PEERS_TARGET_ERROR)
        peer = rp.best_at(rows, "CableDyn", "tension_max_rel", PEERS_TARGET_ERROR)
        when = (f"{os.path.relpath(path, ROOT)} of {facts.get('date', '?')} "
                f"(rodyn binary: {facts.get('rodyn binary', '?')})")
        if mine is None or peer is None:
            who = "rodyn" if mine is None else "CableDyn"
            out.append(skipped(target, ">= 5", base, ISSUE, ".2f",
                               f"no complete {who} run within 1 % in {when}"))
            continue
        if facts.get("date", "")[:10] < ISSUE[-10:]:
            when += ", older than the baseline: re-run with --run-peers"
        ratio = peer["wall_median_s"] / mine["wall_median_s"]
        total = peer["wall_total_median_s"] / mine["wall_total_median_s"]
        note = (f"{when}; CableDyn {peer['wall_median_s']:.3g} s ({peer['settings']}), "
                f"rodyn {mine['wall_median_s']:.3g} s ({mine['settings']}); "
                f"with the peers' static start (wall_total_median_s): {total:.2f}")
        # like for like (both timed inside the process over static start and stepping),
        # in CSV files that have the column
        lm = rp.best_at(rows, "rodyn", "tension_max_rel", PEERS_TARGET_ERROR,
                        "wall_inprocess_median_s")
        lp = rp.best_at(rows, "CableDyn", "tension_max_rel", PEERS_TARGET_ERROR,
                        "wall_inprocess_median_s")
        if lm is not None and lp is not None:
            note += (f"; like for like (wall_inprocess_median_s): "
                     f"{lp['wall_inprocess_median_s'] / lm['wall_inprocess_median_s']:.2f} "
                     f"(CableDyn {lp['wall_inprocess_median_s']:.3g} s, rodyn "
                     f"{lm['wall_inprocess_median_s']:.3g} s, {lm['settings']})")
        out.append(row(target, ">= 5", base, ISSUE, ratio, False, lambda v: v >= 5.0, ".2f",
                       note))
    return out


def cell(v, fmt):
    return "–" if v is None else format(v, fmt)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 2)[2])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"),
                    help="rodyn executable (default: build/rodyn)")
    ap.add_argument("--quick", action="store_true",
                    help="smaller sizes for scaling and memory, each timing once")
    ap.add_argument("--skip", nargs="+", default=[], choices=ROWS, metavar="ROW",
                    help="rows to skip: " + ", ".join(ROWS))
    ap.add_argument("--run-peers", action="store_true",
                    help="run bench/peers/run_peers.py (case1, case4, rodyn and CableDyn, "
                    "--fresh) before reading its CSV files")
    ap.add_argument("--csv", default=os.path.join(ROOT, "bench", "results",
                                                  "speed_targets.csv"))
    args = ap.parse_args()
    rodyn = benchlib.check_rodyn(args.rodyn)
    skip = set(args.skip)
    runs = 1 if args.quick else 2

    facts = benchlib.rodyn_binary_facts(rodyn)
    load1 = os.getloadavg()[0]
    print(f"load average before the run (1/5/15 min): "
          f"{facts['load average before the run (1/5/15 min)']}")
    if load1 > 0.5:
        print(f"WARNING: load average {load1:.2f} > 0.5: the machine is not idle, wall "
              "times are slower than they would be (instruction counts are not affected)")
    print()

    rows = []
    with tempfile.TemporaryDirectory(prefix="rodyn_targets_") as tmp:
        if not {"case1", "newton"} <= skip:
            rows += case1_rows(rodyn, tmp, runs, skip)
        if "instructions" not in skip:
            rows.append(instructions_row(rodyn, tmp))
        if "scaling" not in skip:
            rows += scaling_rows(rodyn, tmp,
                                 SCALING_SIZES_QUICK if args.quick else SCALING_SIZES)
        if "scaling_instructions" not in skip:
            rows += scaling_instructions_rows(
                rodyn, tmp, INSTR_SIZES_QUICK if args.quick else INSTR_SIZES)
        if "memory" not in skip:
            rows += memory_rows(rodyn, tmp, 3000 if args.quick else 10000)
        if "cable" not in skip:
            rows += cable_rows(rodyn, tmp, runs)
    if "peers" not in skip:
        rows += peers_rows(rodyn, args.run_peers)

    table = []
    for r in rows:
        met = "–" if r["met"] is None else "yes" if r["met"] else "no"
        ratio = "–" if r["ratio"] is None else f"{r['ratio']:.2f} ({r['ratio_kind']})"
        table.append([r["target"], r["goal"], cell(r["baseline"], r["fmt"]),
                      r["baseline_source"], cell(r["now"], r["fmt"]), ratio, met])
    for k, v in benchlib.machine_facts(rodyn).items():
        print(f"- {k}: {v}")
    print()
    print("\n".join(benchlib.md_table(["target", "goal", "baseline", "baseline's source",
                                       "measured", "gain", "met"], table, "llrlrrl")))
    print()
    print("gain: baseline/measured where smaller is better, measured/baseline where larger "
          "is better (above 1: progress).")
    for r in rows:
        if r["note"]:
            print(f"- {r['target']}: {r['note']}")
    if skip:
        print(f"- skipped: {', '.join(x for x in ROWS if x in skip)}")
    if args.quick:
        print("- --quick: each timing once, scaling over 100/1000/3000 elements, memory "
              "at 3000 elements")

    cols = ["target", "goal", "baseline", "baseline_source", "now", "ratio", "ratio_kind",
            "met", "note"]
    comments = [f"bench/speed_targets.py{' --quick' if args.quick else ''}"
                + (f" --skip {' '.join(args.skip)}" if skip else "")
                + (" --run-peers" if args.run_peers else ""),
                "ratio: baseline/now where smaller is better, now/baseline where larger is"]
    benchlib.write_csv(args.csv, facts, cols, rows, comments)
    print(f"\nwrote {args.csv}", file=sys.stderr)


if __name__ == "__main__":
    main()
