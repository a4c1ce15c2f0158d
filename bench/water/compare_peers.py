#!/usr/bin/env python3
"""rodyn's mooring leg against the closed form, MoorPy and MoorDyn (the references stored
in bench/water/reference/, made by make_references.py; no peer needs to be installed).

Cases (input/mooring_*.inp):
  static   fairlead tension and horizontal tension against Jonkman's closed-form catenary
           with a grounded length (MoorPy agrees with it to 5e-15), touchdown arc length;
           targets 0.1 % and 0.5 m
  current  fairlead force in a 1 m/s cross current against MoorDyn's finest run (rodyn's
           statics; MoorDyn's by dynamic relaxation; frictionless seabed); target 1 %
  surge    fairlead tension over 72-120 s: maximum, mean and first harmonic (12 s) against
           MoorDyn's finest run (N = 320); targets 1 %, 1 %, 5 %. MoorDyn's raw minimum
           carries touchdown impact spikes that shrink with its segment count and is not
           compared.
Prints a table, writes bench/results/water_peers.csv with --write, exits 1 if a target is
missed. --quick runs static and current only (about 1 s in a Release build). --sweep also
runs the surge deck with other elements, meshes and steps (cost against error,
docs/water.md).
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
REF = os.path.join(HERE, "reference")


def run(rodyn, deck, out):
    t0 = time.perf_counter()
    p = subprocess.run([rodyn, os.path.join(ROOT, "input", deck), "-o", out, "--quiet"],
                       capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit(f"compare_peers: {deck}: rodyn exited {p.returncode}: {p.stderr.strip()}")
    return wall


def end_rows(path, end):
    with open(path) as f:
        return [r for r in csv.DictReader(f) if r["end"] == end]


def static_case(rodyn, tmp):
    wall = run(rodyn, "mooring_catenary.inp", os.path.join(tmp, "static"))
    ref = json.load(open(os.path.join(REF, "mooring_static_closed_form.json")))
    b = end_rows(os.path.join(tmp, "static", "static_reactions.csv"), "B")[0]
    with open(os.path.join(tmp, "static", "static_lines.csv")) as f:
        td = float(next(csv.DictReader(f))["touchdown_s_m"])
    t, h = float(b["tension_N"]), abs(float(b["Fx_N"]))
    td_ref = ref.get("touchdown_arc_length_m", ref.get("touchdown_s_m"))
    if td_ref is None:
        td_ref = ref["leg"]["unstretched_length_m"] - ref["V_F_N"] / ref["leg"]["submerged_weight_N_m"]
    return [("static fairlead tension [N]", t, ref["fairlead_tension_N"], 1e-3, "rel"),
            ("static horizontal tension [N]", h, ref["H_N"], 1e-3, "rel"),
            ("static touchdown arc length [m]", td, td_ref, 0.5, "abs")], wall


def current_case(rodyn, tmp):
    wall = run(rodyn, "mooring_current.inp", os.path.join(tmp, "current"))
    last = end_rows(os.path.join(tmp, "current", "static_reactions.csv"), "B")[0]
    # force of the line on the fairlead = - support force on the line
    f = -np.array([float(last[k]) for k in ("Fx_N", "Fy_N", "Fz_N")])
    ref = json.load(open(os.path.join(REF, "moordyn_current_static.json")))
    fin = max(ref["runs"], key=lambda r: r["segments"])
    fr = np.array(fin["fairlead_force_N"])
    out = [(f"current fairlead F{c} [N] (MoorDyn N={fin['segments']})", f[i], fr[i], 1e-2, "relmag")
           for i, c in enumerate("xyz")]
    out.append(("current fairlead tension [N]", np.linalg.norm(f), np.linalg.norm(fr), 1e-2, "rel"))
    with open(os.path.join(tmp, "current", "static_nodes.csv")) as fh:
        ymax = max(float(r["y_m"]) for r in csv.DictReader(fh))
    out.append(("current largest sideways offset [m]", ymax, fin["max_y_m"], 1e-2, "rel"))
    return out, wall, np.linalg.norm(fr)


def surge_stats(folder):
    """Fairlead tension over 72-120 s: max, mean, first-harmonic amplitude (12 s)."""
    rows = end_rows(os.path.join(folder, "dynamic_ends.csv"), "B")
    t = np.array([float(r["time_s"]) for r in rows])
    T = np.array([float(r["tension_N"]) for r in rows])
    m = (t >= 72.0 - 1e-9) & (t < 120.0 - 1e-9)
    tt, TT = t[m], T[m]
    a = np.c_[np.ones_like(tt), np.cos(2 * np.pi * tt / 12), np.sin(2 * np.pi * tt / 12)]
    c, *_ = np.linalg.lstsq(a, TT, rcond=None)
    return TT.max(), TT.mean(), np.hypot(c[1], c[2])


SWEEP = [("CABLE", 3, 120, 0.05), ("CABLE", 3, 60, 0.1), ("CABLE", 3, 30, 0.1),
         ("CABLE", 3, 24, 0.1), ("CABLE", 3, 20, 0.1), ("CABLE", 2, 40, 0.1),
         ("ROD", 3, 120, 0.05), ("ROD", 3, 30, 0.1)]


def surge_sweep(rodyn, tmp, fin):
    """The surge deck with (element, order, elements, dt) changed: wall time and errors
    against MoorDyn's finest run."""
    with open(os.path.join(ROOT, "input", "mooring_surge.inp")) as f:
        deck = f.read()
    shutil.copy(os.path.join(ROOT, "input", "mooring_leg_section.inc"), tmp)
    print(f"{'element':>8s} {'order':>5s} {'elements':>8s} {'dt_s':>6s} {'wall_s':>7s} "
          f"{'max':>9s} {'mean':>9s} {'harm1':>9s}")
    for kind, order, ne, dt in SWEEP:
        text = deck.replace("ELEMENTS=120, ORDER=3, ELEMENT=CABLE",
                            f"ELEMENTS={ne}, ORDER={order}, ELEMENT={kind}")
        text = text.replace("DT=0.05,", f"DT={dt},")
        name = f"surge_{kind}_{order}_{ne}_{dt}"
        path = os.path.join(tmp, name + ".inp")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(tmp, name)
        t0 = time.perf_counter()
        p = subprocess.run([rodyn, path, "-o", out, "--quiet"], capture_output=True, text=True)
        wall = time.perf_counter() - t0
        head = f"{kind:>8s} {order:5d} {ne:8d} {dt:6.2f}"
        if p.returncode != 0:
            print(f"{head} failed: {p.stderr.strip()}")
            continue
        mx, mean, h1 = surge_stats(out)
        print(f"{head} {wall:7.2f} {mx / fin['max_N'] - 1:9.2e} "
              f"{mean / fin['mean_N'] - 1:9.2e} {h1 / fin['harmonic1_amplitude_N'] - 1:9.2e}")


def surge_case(rodyn, tmp):
    wall = run(rodyn, "mooring_surge.inp", os.path.join(tmp, "surge"))
    mx, mean, h1 = surge_stats(os.path.join(tmp, "surge"))
    ref = json.load(open(os.path.join(REF, "moordyn_surge_summary.json")))
    fin = max(ref["runs"] + ref.get("runs_extra", []), key=lambda r: r["segments"])
    n = fin["segments"]
    return [(f"surge max tension [N] (MoorDyn N={n})", mx, fin["max_N"], 1e-2, "rel"),
            (f"surge mean tension [N] (MoorDyn N={n})", mean, fin["mean_N"], 1e-2, "rel"),
            (f"surge 1st harmonic [N] (MoorDyn N={n})", h1, fin["harmonic1_amplitude_N"],
             5e-2, "rel")], wall, fin


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--quick", action="store_true", help="static and current cases only")
    ap.add_argument("--write", action="store_true", help="write bench/results/water_peers.csv")
    ap.add_argument("--sweep", action="store_true",
                    help="also the surge deck with coarser meshes and steps")
    args = ap.parse_args()
    rows, walls = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        r, walls["static"] = static_case(args.rodyn, tmp)
        rows += [x + (None,) for x in r]
        r, walls["current"], tref = current_case(args.rodyn, tmp)
        rows += [x + (tref,) for x in r]
        if not args.quick:
            r, walls["surge"], fin = surge_case(args.rodyn, tmp)
            rows += [x + (None,) for x in r]
            if args.sweep:
                surge_sweep(args.rodyn, tmp, fin)
    ok = True
    print(f"{'quantity':58s} {'rodyn':>12s} {'reference':>12s} {'error':>10s} {'target':>8s}")
    out = []
    for name, v, ref, tol, kind, scale in rows:
        if kind == "abs":
            e = v - ref
        elif kind == "relmag":
            e = (v - ref) / scale          # relative to the tension's magnitude
        else:
            e = v / ref - 1.0
        good = abs(e) <= tol
        ok &= good
        print(f"{name:58s} {v:12.1f} {ref:12.1f} {e:10.2e} {tol:8.0e} {'ok' if good else 'MISSED'}")
        out.append([name, v, ref, e, tol, good])
    print("rodyn wall time [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in walls.items()))
    if not args.quick:
        print(f"MoorDyn N={fin['segments']}: static {fin['wall_static_s']:.1f} s, "
              f"dynamic {fin['wall_dynamic_s']:.1f} s (bench/water/README.md)")
    if args.write:
        os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
        with open(os.path.join(ROOT, "bench", "results", "water_peers.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["quantity", "rodyn", "reference", "error", "target", "met"])
            w.writerows(out)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
