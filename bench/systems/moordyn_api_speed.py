#!/usr/bin/env python3
"""MoorDyn's quasi-static chain cases through the C API: rodyn (librodyn, through
rodyn.moordyn) against MoorDyn (its PyPI package, bench/peers/.venv), the same driver
for both, on an idle machine.

The cases are MoorDyn's tests/quasi_static_chain.cpp (copied in tests/moordyn_suite/): a
chain of 410 m (41 segments) in 50 m of water, 600 m in 200 m (and so on: the files
Mooring/WD0050_Chain.txt, WD0200, WD0600), its fairlead moved by the motions ZZP1_A1 and
ZZP1_A2 (Mooring/QuasiStatic/) in coupling steps of 0.1 s, against the quasi-static
references of the same folder. Both tools read the same files (MoorDyn without its
fileIC option, whose saved state is not copied; its own initial-condition generator then
runs); each run is a process of its own.

Error: MoorDyn's test's measure, the largest |dT_fair - dT_ref| over twice the largest
|dT_ref| (dT: the fairlead tension's change from the statics), and the static fairlead
tension's error. CPU: the process's CPU over Create, Init and the steps (time.process_time
inside the worker, around those calls only: the import of Python modules, with the
loading of the shared library (MoorDyn's at its import, librodyn's on its first call,
made before the clock starts), and the reading of the motion file are not counted),
median of 3 runs.

Usage: python3 bench/systems/moordyn_api_speed.py   (writes
bench/results/moordyn_api_speed.csv)."""
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SUITE = os.path.join(ROOT, "tests", "moordyn_suite", "Mooring")
WORK = os.path.join(HERE, ".work", "moordyn_api_speed")
VENV_PY = os.path.join(ROOT, "bench", "peers", ".venv", "bin", "python")
OUT = os.path.join(ROOT, "bench", "results", "moordyn_api_speed.csv")
DEPTHS = ["0050", "0200", "0600"]
MOTIONS = ["ZZP1_A1", "ZZP1_A2"]
STATIC_FAIR = {"0050": 991.6e3, "0200": 2065.4e3, "0600": 5232.6e3}
DT = 0.1
REPEATS = 3


def read_tab(path):
    with open(path) as f:
        return [[float(v) for v in line.split("\t")] for line in f if line.strip()]


def worker(tool, depth, motion):
    """One run in this process: the driver of quasi_static_chain.cpp."""
    if tool == "rodyn":
        sys.path.insert(0, os.path.join(ROOT, "postproc"))
        import rodyn.moordyn as md
        from rodyn._lib import lib
        lib()       # librodyn loaded, as MoorDyn's module is at its import
    else:
        import moordyn as md
    case = os.path.join(WORK, tool)
    motion_data = read_tab(os.path.join(SUITE, "QuasiStatic", motion + ".txt"))
    ref = read_tab(os.path.join(SUITE, "QuasiStatic", f"WD{depth}_Chain_{motion}.txt"))
    c0 = time.process_time()
    system = md.Create(os.path.join(case, f"WD{depth}_Chain.txt"))
    if hasattr(md, "SetVerbosity"):
        md.SetVerbosity(system, 0)
    md.Init(system, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    fh, fv, _, _ = md.GetFASTtens(system, 1)
    f0 = math.hypot(fh[0], fv[0])
    c1 = time.process_time()
    t_ref0, i_ref, err, span = motion_data[0][0], 0, 0.0, 0.0
    for i in range(len(motion_data) - 1):
        x = motion_data[i][1:4]
        dx = [(motion_data[i + 1][j + 1] - x[j]) / DT for j in range(3)]
        md.Step(system, x, dx, motion_data[i][0] - t_ref0, DT)
        if motion_data[i][0] < 0.0:
            continue
        fh, fv, _, _ = md.GetFASTtens(system, 1)
        df = math.hypot(fh[0], fv[0]) - f0
        dref = 1e3 * ref[i_ref][3] - STATIC_FAIR[depth]
        err, span = max(err, abs(df - dref)), max(span, abs(dref))
        i_ref += 1
    c2 = time.process_time()
    md.Close(system)
    print(json.dumps({"cpu_s": c2 - c0, "cpu_init_s": c1 - c0, "cpu_steps_s": c2 - c1,
                      "static_error": abs(f0 - STATIC_FAIR[depth]) / STATIC_FAIR[depth],
                      "dynamic_error": err / (2.0 * span)}))


def prepare():
    for tool in ("rodyn", "moordyn"):
        d = os.path.join(WORK, tool)
        os.makedirs(d, exist_ok=True)
        for depth in DEPTHS:
            name = f"WD{depth}_Chain.txt"
            with open(os.path.join(SUITE, name)) as f:
                lines = f.readlines()
            if tool == "moordyn":   # its saved state (fileIC) is not copied
                lines = [ln for ln in lines if "fileIC" not in ln]
            with open(os.path.join(d, name), "w") as f:
                f.writelines(lines)


def run(tool, depth, motion):
    py = VENV_PY if tool == "moordyn" else sys.executable
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    proc = subprocess.run([py, __file__, "--worker", tool, depth, motion], env=env,
                          capture_output=True, text=True, cwd=os.path.join(WORK, tool))
    if proc.returncode != 0:
        raise RuntimeError(f"{tool} {depth} {motion}: {proc.stderr[-400:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        worker(*sys.argv[2:5])
        return
    if not os.path.exists(VENV_PY):
        sys.exit("bench/peers/.venv is missing: bench/peers/README.md sets it up")
    shutil.rmtree(WORK, ignore_errors=True)
    prepare()
    rows = []
    load0 = os.getloadavg()[0]
    for depth in DEPTHS:
        for motion in MOTIONS:
            for tool in ("rodyn", "moordyn"):
                runs = [run(tool, depth, motion) for _ in range(REPEATS)]
                med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
                med.update(tool=tool, depth=depth, motion=motion)
                rows.append(med)
                print(f"{tool:8s} WD{depth} {motion}: CPU {med['cpu_s']:.3f} s (init "
                      f"{med['cpu_init_s']:.3f}), static error {med['static_error']:.4f}, "
                      f"dynamic error {med['dynamic_error']:.4f}")
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "w", newline="") as f:
        f.write(f"# command: python3 bench/systems/moordyn_api_speed.py\n"
                f"# date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}\n"
                f"# load average before the runs (1 min): {load0:.2f}; after: "
                f"{os.getloadavg()[0]:.2f}\n# CPU: median of {REPEATS} runs, each a "
                "process; errors: see the script's docstring\n")
        w = csv.DictWriter(f, fieldnames=["tool", "depth", "motion", "cpu_s", "cpu_init_s",
                                          "cpu_steps_s", "static_error", "dynamic_error"])
        w.writeheader()
        for r in rows:
            w.writerow({k: r[k] for k in w.fieldnames})
    for depth in DEPTHS:
        for motion in MOTIONS:
            r, m = [next(x for x in rows if x["tool"] == t and x["depth"] == depth
                         and x["motion"] == motion) for t in ("rodyn", "moordyn")]
            print(f"WD{depth} {motion}: MoorDyn CPU / rodyn CPU = {m['cpu_s'] / r['cpu_s']:.2f}")


if __name__ == "__main__":
    main()
