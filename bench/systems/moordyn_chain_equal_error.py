#!/usr/bin/env python3
"""MoorDyn's quasi-static chains through the C API at equal fairlead-force error: rodyn
(librodyn, its own discretisation in a rodyn deck) against MoorDyn (its PyPI package,
bench/peers/.venv), both driven by the same Python driver, each run a process.

The cases are those of MoorDyn's tests/quasi_static_chain.cpp (tests/moordyn_suite/): the
chain of Mooring/WD<depth>_Chain.txt, its fairlead (a Coupled point) moved by the motion
Mooring/QuasiStatic/ZZP1_A1.txt (from -10 s to 20 s in coupling steps of 0.1 s).

The physics is made independent of the discretisation: the file's internal damping is a
damping ratio of a segment (BA/-zeta = -1), which MoorDyn turns into BA = zeta (L/N)
sqrt(EA m) [N s] (Line.cpp), a damping that changes with N; both tools get the BA of the
file's own N as a fixed value instead. The fileIC line is dropped (MoorDyn's saved state
is not shipped); MoorDyn's initial-condition generator runs with the file's settings.

- MoorDyn: the file with NumSegs N (10 to 2 N0) and a dtM option of 2e-3 to 1.25e-4 s
  in place of its CFL (MoorDyn 2.7 then takes that step; a run that fails or gives
  non-finite forces is left out). With the fixed BA, the file's CFL of 0.1 fails on finer
  meshes: their segments are more than critically damped.
- rodyn: the file written as a rodyn deck (`rodyn --to-deck`: the fairlead a FIXED point
  with HOST=YES), its line of E cubic elements (ORDER=3) instead of N0 linear ones, a
  *DYNAMIC added (its DT replaced by the host's 0.1 s, or by MoorDyn_SetDt's smaller
  step).
- Quantity: the size of the force of the line on the fairlead, as MoorDyn_Step returns
  it, at every coupling step from t = 0 to 20 s (200 samples). In both tools it is the
  force on the coupled point: in MoorDyn the end segment's tension plus the end node's
  share of weight, buoyancy, drag and seabed.
- Reference: each tool's own finest run (rodyn 64 cubic elements with steps of 0.0125 s;
  MoorDyn 2 N0 segments, dtM 1.25e-4 s), each converging to its own model (their seabed
  contact and friction differ); the equal-error table takes each tool's error against
  its own reference, the CSV gives both and the two references' difference.
- Error: the largest |F - F_ref| over the samples, over the largest F_ref [%].
- CPU: time.process_time in the worker around Create, Init and the steps (the shared
  libraries loaded before: MoorDyn's at its import, librodyn's by a first call), median
  of 3 for the runs of the table (one for the sweep).

Usage: python3 bench/systems/moordyn_chain_equal_error.py [--depths 0050,0200,0600]
(writes bench/results/moordyn_chain_equal_error.csv)."""
import csv
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

from moordyn_api_speed import read_tab

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SUITE = os.path.join(ROOT, "tests", "moordyn_suite", "Mooring")
WORK = os.path.join(HERE, ".work", "moordyn_chain_equal_error")
VENV_PY = os.path.join(ROOT, "bench", "peers", ".venv", "bin", "python")
RODYN = os.environ.get("RODYN_EXE", os.path.join(ROOT, "build", "rodyn"))
OUT = os.path.join(ROOT, "bench", "results", "moordyn_chain_equal_error.csv")
MOTION = "ZZP1_A1"
DT = 0.1
RODYN_RUNS = [(e, h) for e in (3, 4, 6, 8, 12, 16) for h in (0.1, 0.05, 0.025, 0.0125)]
RODYN_REF = (64, 0.0125)
DTMS = (2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4)
LEVELS = (2.0, 1.0, 0.5, 0.25)
REPEATS = 3
NOTES = []


def worker(tool, path, h):
    """One run in this process: the fairlead force at each coupling step from t = 0."""
    if tool == "rodyn":
        sys.path.insert(0, os.path.join(ROOT, "postproc"))
        import rodyn.moordyn as md
        from rodyn._lib import lib
        lib()       # librodyn loaded, as MoorDyn's module is at its import
    else:
        import moordyn as md
    motion = read_tab(os.path.join(SUITE, "QuasiStatic", MOTION + ".txt"))
    c0 = time.process_time()
    system = md.Create(path)
    if hasattr(md, "SetVerbosity"):
        md.SetVerbosity(system, 0)
    if tool == "rodyn" and h < DT:
        md.SetDt(system, h)
    md.Init(system, motion[0][1:4], [0.0, 0.0, 0.0])
    force = []
    for i in range(len(motion) - 1):
        x = motion[i][1:4]
        dx = [(motion[i + 1][j + 1] - x[j]) / DT for j in range(3)]
        f = md.Step(system, x, dx, motion[i][0] - motion[0][0], DT)
        if motion[i + 1][0] >= -1e-9:
            force.append(math.sqrt(sum(v * v for v in f[:3])))
    cpu = time.process_time() - c0
    md.Close(system)
    print("\n" + json.dumps({"cpu_s": cpu, "force": force}))


def file_text(depth, segments=None, dtm=None):
    """The case's MoorDyn file: fixed BA, no fileIC, NumSegs and dtM as given."""
    with open(os.path.join(SUITE, f"WD{depth}_Chain.txt")) as f:
        lines = [ln for ln in f.readlines() if "fileIC" not in ln]
    out = []
    for ln in lines:
        w = ln.split()
        if len(w) == 10 and w[0] == "chain":
            mass, ea, zeta = float(w[2]), float(w[3]), float(w[4])
            ba_ln = ln
        if len(w) == 7 and w[0] == "1" and w[1] == "chain":
            length, n0 = float(w[4]), int(w[5])
    ba = -zeta * length / n0 * math.sqrt(ea * mass)
    for ln in lines:
        w = ln.split()
        if ln is ba_ln:
            w[4] = f"{ba:.6e}"
            ln = "   ".join(w) + "\n"
        elif len(w) == 7 and w[0] == "1" and w[1] == "chain" and segments:
            w[5] = str(segments)
            ln = "   ".join(w) + "\n"
        elif len(w) >= 2 and w[1].lower() == "cfl" and dtm:
            ln = f"{dtm}   dtM   MoorDyn's time step (s)\n"
        out.append(ln)
    return "".join(out), n0


def prepare(depth):
    """Write the MoorDyn files and rodyn decks of one depth; return the runs."""
    d = os.path.join(WORK, depth)
    os.makedirs(d, exist_ok=True)
    base, n0 = file_text(depth)
    md_runs = []
    for n in sorted({10, 20, n0 // 2, n0, 2 * n0}):
        for dtm in DTMS if n < 2 * n0 else DTMS[-2:]:
            p = os.path.join(d, f"md_N{n}_dtM{dtm}.txt")
            with open(p, "w") as f:
                f.write(file_text(depth, n, dtm)[0])
            md_runs.append(("moordyn", p, DT, f"{n} seg., dtM {dtm} s"))
    fixed = os.path.join(d, "fixed_ba.txt")
    with open(fixed, "w") as f:
        f.write(base)
    deck = subprocess.run([RODYN, "--to-deck", fixed], check=True, capture_output=True,
                          text=True).stdout
    deck = deck.replace("*OUTPUT, CSV=YES, HDF5=YES",
                        "*DYNAMIC, DT=1.0, TIME=1.0e7\n*OUTPUT, CSV=NO, HDF5=NO")
    rd_runs = []
    for e, h in RODYN_RUNS + [RODYN_REF, (RODYN_REF[0] // 2, 2 * RODYN_REF[1])]:
        p = os.path.join(d, f"rodyn_E{e}.inp")
        with open(p, "w") as f:
            f.write(re.sub(r"ELEMENTS=\d+, ORDER=1", f"ELEMENTS={e}, ORDER=3", deck))
        rd_runs.append(("rodyn", p, h, f"{e} el. p3, dt {h} s"))
    return md_runs, rd_runs, n0


def run(tool, path, h):
    py = VENV_PY if tool == "moordyn" else sys.executable
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    proc = subprocess.run([py, __file__, "--worker", tool, path, str(h)], env=env,
                          capture_output=True, text=True, cwd=os.path.dirname(path))
    if proc.returncode != 0:
        return None
    return json.loads(proc.stdout[proc.stdout.rindex('\n{"cpu_s"'):])


def error(force, ref):
    if force is None or len(force) != len(ref) or not all(math.isfinite(v) for v in force):
        return math.inf
    return 100.0 * max(abs(a - b) for a, b in zip(force, ref)) / max(ref)


def study(depth, rows):
    md_runs, rd_runs, n0 = prepare(depth)
    results = []
    for tool, path, h, label in rd_runs + md_runs:
        r = run(tool, path, h)
        results.append((tool, path, h, label, r))
        cpu = r["cpu_s"] if r else math.nan
        print(f"WD{depth} {tool:8s} {label:24s} CPU {cpu:.3f} s", flush=True)
    ref_r = next(r for t, p, h, lab, r in results
                 if t == "rodyn" and p.endswith(f"E{RODYN_REF[0]}.inp") and h == RODYN_REF[1])
    half = next(r for t, p, h, lab, r in results
                if t == "rodyn" and p.endswith(f"E{RODYN_REF[0] // 2}.inp")
                and h == 2 * RODYN_REF[1])
    ref_m = next(r for t, p, h, lab, r in results
                 if t == "moordyn" and f"_N{2 * n0}_dtM{DTMS[-1]}" in p)
    NOTES.append(f"WD{depth}: rodyn's reference against its half (32 el., dt 0.025 s): "
                 f"{error(half['force'], ref_r['force']):.4f} %; MoorDyn's reference "
                 f"against rodyn's: {error(ref_m['force'], ref_r['force']):.4f} %")
    print(NOTES[-1])
    for tool, path, h, label, r in results:
        rows.append({"depth": depth, "tool": tool, "run": label, "h": h, "path": path,
                     "cpu_s": r["cpu_s"] if r else math.nan,
                     "error_own": error(r and r["force"], (ref_r if tool == "rodyn"
                                                            else ref_m)["force"]),
                     "error_rodyn_ref": error(r and r["force"], ref_r["force"]),
                     "error_moordyn_ref": error(r and r["force"], ref_m["force"])})


def cheapest(rows, depth, tool, level, key):
    """The cheapest run of a tool within the level, but the references' meshes."""
    top = str(max(int(r["run"].split()[0]) for r in rows
                  if r["depth"] == depth and r["tool"] == "moordyn"))
    ok = [r for r in rows if r["depth"] == depth and r["tool"] == tool and r[key] <= level
          and "64 el." not in r["run"] and "32 el." not in r["run"]
          and not (tool == "moordyn" and r["run"].split()[0] == top)]
    return min(ok, key=lambda r: r["cpu_s"]) if ok else None


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        worker(sys.argv[2], sys.argv[3], float(sys.argv[4]))
        return
    if not os.path.exists(VENV_PY):
        sys.exit("bench/peers/.venv is missing: bench/peers/README.md sets it up")
    depths = ["0050", "0200", "0600"]
    if "--depths" in sys.argv:
        depths = sys.argv[sys.argv.index("--depths") + 1].split(",")
    shutil.rmtree(WORK, ignore_errors=True)
    load0 = os.getloadavg()[0]
    rows = []
    for depth in depths:
        study(depth, rows)
    table = []
    for depth in depths:
        for level in LEVELS:
            pair = [cheapest(rows, depth, t, level, "error_own") for t in ("rodyn", "moordyn")]
            if None in pair:
                table.append((depth, level, pair, None))
                continue
            cpus = []
            for r in pair:      # the table's runs timed again: median of REPEATS
                cpus.append(statistics.median(run(r["tool"], r["path"], r["h"])["cpu_s"]
                                              for _ in range(REPEATS)))
            table.append((depth, level, pair, cpus))
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "w", newline="") as f:
        f.write(f"# command: python3 bench/systems/moordyn_chain_equal_error.py\n"
                f"# date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}\n"
                f"# load average before the runs (1 min): {load0:.2f}; after: "
                f"{os.getloadavg()[0]:.2f}\n# sweep CPU: one run; errors [%]: see the "
                "script's docstring\n")
        for note in NOTES:
            f.write(f"# {note}\n")
        w = csv.DictWriter(f, fieldnames=["depth", "tool", "run", "cpu_s", "error_own",
                                          "error_rodyn_ref", "error_moordyn_ref"],
                           extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
        f.write("# equal error (each against its own reference): depth, level [%], rodyn run, "
                "its error, its CPU (median of 3), MoorDyn run, its error, its CPU, ratio\n")
        for depth, level, pair, cpus in table:
            if cpus is None:
                f.write(f"# {depth},{level},none\n")
                continue
            f.write(f"# {depth},{level},{pair[0]['run']},{pair[0]['error_own']:.3f},"
                    f"{cpus[0]:.4f},{pair[1]['run']},{pair[1]['error_own']:.3f},"
                    f"{cpus[1]:.4f},{cpus[1] / cpus[0]:.1f}\n")
    for depth, level, pair, cpus in table:
        if cpus is None:
            print(f"WD{depth} <= {level} %: none for one of the tools")
            continue
        print(f"WD{depth} <= {level} %: rodyn {pair[0]['run']} "
              f"({pair[0]['error_own']:.3f} %, {cpus[0]:.4f} s); MoorDyn "
              f"{pair[1]['run']} ({pair[1]['error_own']:.3f} %, {cpus[1]:.4f} s): "
              f"ratio {cpus[1] / cpus[0]:.1f}")


if __name__ == "__main__":
    main()
