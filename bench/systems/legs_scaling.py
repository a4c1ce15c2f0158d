#!/usr/bin/env python3
"""Cost of a mooring system against its size: n legs (3, 6, 12, 24, 48) of the OC3 spar's
chain around one body, rodyn's CPU time per step and of the statics against the total
element count.

The system is bench/systems/spar_speed.py's with n legs instead of three: the same chain
(902.2 m, 0.09 m, 77.7066 kg/m, EA 384.243e6 N, Cd 1.2 / CdAx 0.05 / Ca 1 / CaAx 0, seabed
3e6 Pa/m and 3e5 Pa s/m), anchors at 853.87 m radius on the seabed in 320 m of water and
fairleads 70 m down at 5.2 m radius, the legs at headings 360 k / n deg; a FIXED body
carrying the fairleads moved by spar_speed.py's surge (10 m at 100 s plus 2 m at 12 s,
ramped over 25 s; *MOTION, BODY=, TYPE=TABLE). Each leg has E cubic cable elements (E = 10
and 20 by default), so the system has n E elements, all lines on the body's six unknowns
(the arrowhead solver, docs/systems.md).

For each n and E: the deck with *DYNAMIC (DT 0.1 s, 100 s: 1000 steps, the step forces
every step, no frames but t = 0 and the end) and the same deck without it (the statics
alone), each run --repeats times (default 3) as a process of its own with
OPENBLAS_NUM_THREADS=OMP_NUM_THREADS=1; CPU time user + sys (os.wait4) and wall time,
the 1-minute load average at each run's start; the medians. CPU per step = (CPU of the
dynamic run - CPU of the statics alone) / steps; per Newton iteration likewise. A
least-squares line CPU/step = a + b (n E) over all points of one E, and each point's
deviation from it (over the largest CPU/step); the exponent of CPU/step ~ (n E)^p on log-log
axes; the CPU per step and element, and per iteration and element, of 48 legs over 3.

  python3 bench/systems/legs_scaling.py [--elements 10 20] [--legs 3 6 12 24 48]
      [--repeats 3] [--time 100] [--rodyn build/rodyn]
Writes bench/results/legs_scaling.csv (machine facts as # lines, one row per n and E).
About 2 minutes of CPU with the defaults.
"""
import argparse
import math
import os
import statistics
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench"))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import moorpy_spar as spar  # noqa: E402
import spar_speed as ss  # noqa: E402

RESULTS_CSV = os.path.join(ROOT, "bench", "results", "legs_scaling.csv")
DT = 0.1


def deck(nleg, elements, t_end, dynamic=True):
    fmt = spar.fmt
    text = (f"*HEADING\nlegs_scaling: {nleg} legs of the OC3 spar's chain, {elements} cubic "
            f"elements each (bench/systems/legs_scaling.py)\n"
            f"*GRAVITY\n0.0, 0.0, {fmt(-ss.G)}\n"
            f"*WATER, DEPTH={fmt(ss.DEPTH)}, DENSITY={fmt(ss.RHO)}\n"
            f"*SEABED, STIFFNESS={ss.KBOT:.1e}, DAMPING={ss.CBOT:.1e}\n"
            f"*SECTION, NAME=CHAIN, OD={fmt(ss.DIAM)}, CDN={ss.CDN}, CDA={ss.CDA}, "
            f"CAN={ss.CAN}, CAA={ss.CAA}\n{fmt(ss.EA)}, 0.0, 0.0, 0.0, {fmt(ss.MASS)}\n"
            "*BODY, NAME=SPAR, TYPE=FIXED\n0.0, 0.0, 0.0\n0.0, 0.0, 0.0\n"
            "0.0, 0.0, 0.0\n0.0, 0.0, 0.0\n")
    for k in range(nleg):
        h = 2.0 * math.pi * k / nleg
        c, s = math.cos(h), math.sin(h)
        text += (f"*POINT, NAME=F{k + 1}, TYPE=BODY, BODY=SPAR\n"
                 f"{fmt(round(spar.R_FAIRLEAD * c, 9) + 0.0)}, "
                 f"{fmt(round(spar.R_FAIRLEAD * s, 9) + 0.0)}, {fmt(spar.Z_FAIRLEAD)}\n"
                 f"*POINT, NAME=A{k + 1}, TYPE=FIXED\n"
                 f"{fmt(round(spar.R_ANCHOR * c, 9) + 0.0)}, "
                 f"{fmt(round(spar.R_ANCHOR * s, 9) + 0.0)}, {fmt(-ss.DEPTH)}\n")
    for k in range(nleg):
        text += (f"*LINE, NAME=L{k + 1}, SECTION=CHAIN, LENGTH={fmt(ss.LENGTH)}, "
                 f"ELEMENTS={elements}, ORDER=3, ELEMENT=CABLE, POINT A=A{k + 1}, "
                 f"POINT B=F{k + 1}\n")
    text += "*MOTION, BODY=SPAR, TYPE=TABLE, INPUT=motion.csv, RAMP=0\n*STATIC, INCREMENTS=20\n"
    if dynamic:
        text += f"*DYNAMIC, DT={DT!r}, TIME={t_end!r}, OUTPUT INTERVAL={t_end!r}\n"
    return text + "*OUTPUT, CSV=YES, HDF5=NO\n"


def run(rodyn, work, tag, text, repeats):
    path = os.path.join(work, tag + ".inp")
    with open(path, "w") as f:
        f.write(text)
    cpu, wall, load = [], [], []
    for _ in range(repeats):
        rc, c, w, l1, err = ss.timed([rodyn, path, "-o", os.path.join(work, tag), "--quiet"])
        if rc != 0:
            raise RuntimeError(f"{tag}: rodyn exit {rc}: {err.strip()[:300]}")
        cpu.append(c)
        wall.append(w)
        load.append(l1)
    st = benchlib.read_status(os.path.join(work, tag, "status.txt"))
    return {"cpu": statistics.median(cpu), "wall": statistics.median(wall),
            "cpu_all": cpu, "load_all": load, "status": st}


def md_text(nleg, segments, dtm):
    """MoorDyn v2 deck of the n-leg system: anchors Fixed 1..n, fairleads Coupled n+1..2n."""
    pts = []
    for k in range(nleg):
        h = 2.0 * math.pi * k / nleg
        pts.append(f"{k + 1}  Fixed  {spar.R_ANCHOR * math.cos(h)!r}  "
                   f"{spar.R_ANCHOR * math.sin(h)!r}  {-ss.DEPTH!r}  0  0  0  0")
    for k, f in enumerate(md_fairleads(nleg)):
        pts.append(f"{nleg + k + 1}  Coupled  {f[0]!r}  {f[1]!r}  {f[2]!r}  0  0  0  0")
    text = ss.md_deck(3, "MoorDyn", ss.moordyn_options(dtm))
    head, rest = text.split("---------------------- POINTS", 1)
    _, opts = rest.split("---------------------- OPTIONS", 1)
    lines = "\n".join(f"{k + 1}  chain  {k + 1}  {nleg + k + 1}  {ss.LENGTH!r}  {segments}  -"
                      for k in range(nleg))
    return (head + "---------------------- POINTS ---------------------------------------\n"
            "ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca\n"
            "(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)\n"
            + "\n".join(pts) + "\n---------------------- LINES ---------------------------"
            "-------------\nID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs\n"
            "(#)   (name)     (ID)     (ID)      (m)       (-)      (-)\n" + lines
            + "\n---------------------- OPTIONS" + opts)


def md_fairleads(nleg):
    return np.array([[spar.R_FAIRLEAD * math.cos(2.0 * math.pi * k / nleg),
                      spar.R_FAIRLEAD * math.sin(2.0 * math.pi * k / nleg), spar.Z_FAIRLEAD]
                     for k in range(nleg)])


def worker_moordyn(a):
    """In the venv's Python: MoorDyn's static solve, then its time loop over a.time s with
    the surge at every 0.05 s coupling step (as spar_speed.py drives it); CPU of each."""
    import json
    import time
    import moordyn
    nleg, n = a.worker_legs, a.segments
    dtm = ss.md_stable_dt(n)
    path = a.out[:-5] + ".dat"
    with open(path, "w") as f:
        f.write(md_text(nleg, n, dtm))
    ts, u = ss.samples()
    x0 = md_fairleads(nleg)
    with ss._Quiet():
        c0 = time.process_time()
        s = moordyn.Create(path)
        moordyn.Init(s, x0.ravel().tolist(), [0.0] * 3 * nleg)
        c1 = time.process_time()
        pts = [moordyn.GetPoint(s, nleg + k + 1) for k in range(nleg)]
        nsteps = int(round(a.time / ss.H))
        for k in range(nsteps):
            x = x0.copy()
            x[:, 0] += u[k]
            v = np.zeros_like(x0)
            v[:, 0] = (u[k + 1] - u[k]) / ss.H
            moordyn.Step(s, x.ravel().tolist(), v.ravel().tolist(), float(ts[k]), ss.H)
            for p in pts:
                moordyn.GetPointForce(p)
        c2 = time.process_time()
        moordyn.Close(s)
    with open(a.out, "w") as f:
        json.dump({"ic_cpu_s": c1 - c0, "step_cpu_s": c2 - c1, "dtm": dtm,
                   "steps": int(round(a.time / dtm))}, f)


def run_moordyn(work, nleg, n, t_end, repeats):
    import json
    out = os.path.join(work, f"md_n{nleg}_s{n}.json")
    res = []
    for _ in range(repeats):
        rc, c, w, l1, err = ss.timed([ss.VENV_PY, os.path.abspath(__file__), "--worker-legs",
                                      str(nleg), "--segments", str(n), "--time", repr(t_end),
                                      "--out", out])
        if rc != 0:
            raise RuntimeError(f"MoorDyn {nleg} legs: exit {rc}: {err.strip()[-300:]}")
        with open(out) as f:
            r = json.load(f)
        r.update(cpu=c, wall=w, load=l1)
        res.append(r)
    med = {k: statistics.median(r[k] for r in res)
           for k in ("ic_cpu_s", "step_cpu_s", "cpu", "wall")}
    med.update(steps=res[0]["steps"], dtm=res[0]["dtm"],
               cpu_all=[r["step_cpu_s"] for r in res], load_all=[r["load"] for r in res])
    return med


def linear_fit(x, y):
    a = np.column_stack([np.ones_like(x), x])
    (c0, c1), *_ = np.linalg.lstsq(a, y, rcond=None)
    return c0, c1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--legs", type=int, nargs="+", default=[3, 6, 12, 24, 48])
    ap.add_argument("--elements", type=int, nargs="+", default=[10, 20])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--time", type=float, default=100.0)
    ap.add_argument("--csv", default=RESULTS_CSV)
    ap.add_argument("--md-segments", type=int, nargs="*", default=[16],
                    help="MoorDyn's segments a leg (none: rodyn only)")
    ap.add_argument("--worker-legs", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--segments", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--out", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.worker_legs:
        worker_moordyn(a)
        return 0
    rodyn = benchlib.check_rodyn(a.rodyn)
    facts = benchlib.machine_facts(rodyn, load_average=True)
    for k, v in facts.items():
        print(f"{k}: {v}")
    rows = []
    with tempfile.TemporaryDirectory(prefix="legs_scaling_") as work:
        ss.write_table(os.path.join(work, "motion.csv"))
        for e in a.elements:
            for n in a.legs:
                d = run(rodyn, work, f"n{n}_e{e}", deck(n, e, a.time), a.repeats)
                s = run(rodyn, work, f"n{n}_e{e}_static", deck(n, e, a.time, False),
                        a.repeats)
                st, ss_ = d["status"], s["status"]
                if st.get("status") != "complete":
                    raise RuntimeError(f"n {n}, E {e}: {st.get('status')}")
                steps = int(st["steps"])
                its = int(st["step_iterations"])
                dyn = d["cpu"] - s["cpu"]
                rows.append({
                    "tool": "rodyn", "legs": n, "elements_a_leg": e, "elements": n * e,
                    "steps": steps,
                    "newton_iterations": its, "tangents": int(st["step_tangents"]),
                    "cutbacks": int(st["step_cutbacks"]),
                    "cpu_s": d["cpu"], "wall_s": d["wall"], "static_cpu_s": s["cpu"],
                    "static_wall_s": s["wall"],
                    "static_iterations": int(ss_["iterations"]),
                    "cpu_per_step_s": dyn / steps, "cpu_per_iteration_s": dyn / its,
                    "cpu_per_step_element_us": 1e6 * dyn / steps / (n * e),
                    "cpu_per_iteration_element_us": 1e6 * dyn / its / (n * e),
                    "cpu_all_s": " ".join(f"{c:.3f}" for c in d["cpu_all"]),
                    "static_cpu_all_s": " ".join(f"{c:.3f}" for c in s["cpu_all"]),
                    "load1_all": " ".join(f"{x:.2f}" for x in d["load_all"] + s["load_all"]),
                })
                r = rows[-1]
                print(f"legs {n:3d}  E {e:3d}  elements {n * e:5d}  CPU {d['cpu']:7.3f} s "
                      f"(statics {s['cpu']:.3f} s, {r['static_iterations']} it.)  "
                      f"per step {1e3 * r['cpu_per_step_s']:.3f} ms  it./step "
                      f"{its / steps:.2f}  load {max(d['load_all']):.2f}", flush=True)
        if a.md_segments:
            ss.ensure_venv()
        for sg in a.md_segments:
            for n in a.legs:
                m = run_moordyn(work, n, sg, a.time, a.repeats)
                rows.append({
                    "tool": "MoorDyn", "legs": n, "elements_a_leg": sg, "elements": n * sg,
                    "steps": m["steps"], "cpu_s": m["cpu"], "wall_s": m["wall"],
                    "static_cpu_s": m["ic_cpu_s"],
                    "cpu_per_step_s": m["step_cpu_s"] / m["steps"],
                    "cpu_per_step_element_us": 1e6 * m["step_cpu_s"] / m["steps"] / (n * sg),
                    "cpu_all_s": " ".join(f"{c:.3f}" for c in m["cpu_all"]),
                    "load1_all": " ".join(f"{x:.2f}" for x in m["load_all"]),
                })
                print(f"MoorDyn legs {n:3d}  segments {sg:3d}  total {n * sg:5d}  stepping "
                      f"CPU {m['step_cpu_s']:.3f} s ({m['steps']} steps of {m['dtm']:.4g} s, "
                      f"{1e6 * m['step_cpu_s'] / m['steps']:.2f} us a step)  static solve "
                      f"{m['ic_cpu_s']:.3f} s  load {max(m['load_all']):.2f}", flush=True)
    notes = []
    for tool, e in [("rodyn", e) for e in a.elements] + [("MoorDyn", s) for s in a.md_segments]:
        sel = [r for r in rows if r["elements_a_leg"] == e and r["tool"] == tool]
        e = f"{e} ({tool})" if tool == "MoorDyn" else e
        x = np.array([r["elements"] for r in sel], float)
        keys = ((("cpu_per_step_s", "step"), ("cpu_per_iteration_s", "iteration"),
                 ("static_cpu_s", "statics")) if tool == "rodyn"
                else (("cpu_per_step_s", "step"), ("static_cpu_s", "statics")))
        for key, name in keys:
            y = np.array([r[key] for r in sel])
            c0, c1 = linear_fit(x, y)
            dev = (y - (c0 + c1 * x)) / np.max(y)
            p = np.polyfit(np.log(x), np.log(y), 1)[0]
            for r, dv in zip(sel, dev):
                r[f"{key}_fit_deviation"] = float(dv)
            notes.append(f"E = {e}: CPU/{name} = {c0:.4g} s + {c1:.4g} s x elements; largest "
                         f"deviation from the line {100 * np.max(np.abs(dev)):.1f} % of the "
                         f"largest value; exponent {p:.3f}")
        for key in ("cpu_per_step_element_us", "cpu_per_iteration_element_us"):
            if key not in sel[0]:
                continue
            v = [r[key] for r in sel]
            notes.append(f"E = {e}: {key} from {v[0]:.3f} ({sel[0]['legs']} legs) to "
                         f"{v[-1]:.3f} ({sel[-1]['legs']} legs), ratio {v[-1] / v[0]:.3f}")
        if tool == "rodyn":
            notes.append(f"E = {e}: Newton iterations a step from "
                         f"{sel[0]['newton_iterations'] / sel[0]['steps']:.2f} to "
                         f"{sel[-1]['newton_iterations'] / sel[-1]['steps']:.2f}")
    print()
    for n_ in notes:
        print(n_)
    facts["load average after the run (1/5/15 min)"] = " / ".join(
        f"{x:.2f}" for x in os.getloadavg())
    cols = ["tool", "legs", "elements_a_leg", "elements", "steps", "newton_iterations",
            "tangents", "cutbacks", "cpu_s", "wall_s", "static_cpu_s", "static_wall_s",
            "static_iterations", "cpu_per_step_s", "cpu_per_step_s_fit_deviation",
            "cpu_per_iteration_s", "cpu_per_iteration_s_fit_deviation",
            "cpu_per_step_element_us", "cpu_per_iteration_element_us",
            "static_cpu_s_fit_deviation", "cpu_all_s", "static_cpu_all_s", "load1_all"]
    benchlib.write_csv(a.csv, facts, cols, rows,
                       [f"rodyn: DT {DT} s, TIME {a.time} s; medians of {a.repeats} runs; CPU "
                        "per step = (dynamic run - statics alone) / steps",
                        "MoorDyn: elements_a_leg = segments a leg, dtM 0.25 l/c (spar_speed.py's "
                        "md_stable_dt), steps = its time steps; static_cpu_s = its stationary "
                        "solve (in-process CPU), cpu_per_step_s = its time loop's CPU (in-process,"
                        " Python loop included) / steps"] + notes)
    print("wrote", os.path.relpath(a.csv, ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
