#!/usr/bin/env python3
"""rodyn's lazy-wave cable (input/riser_lazy_wave.inp, riser_lazy_wave_heave.inp; Lozon et
al. 2025, Gulf of Mexico 80 m) against the published figures and against CableDyn's run of
the same cable stored in bench/water/reference/ (made by cabledyn_riser.py; CableDyn need
not be installed).

Published (Seo, Lim, Shim & Song 2026, Ocean Engineering 368, 128332, and its validation
record; CableDyn's tutorial for the shape): hang-off effective tension 9.32 kN (OrcaFlex
11.6d and CableDyn), peak static curvature 0.0968 1/m (OrcaFlex) and 0.09683 1/m at
s/L = 0.3412 (CableDyn), first grounded node at s/L = 0.7967, hang-off angle 81.6 deg, sag
bend z = -64.1 m at s = 58.5 m, hog bend z = -52.5 m at s = 87.2 m (CableDyn); s from the
hang-off.
Stored CableDyn 0.3.0 run (1024 Hermite elements): the same static quantities to more
digits, the whole shape, and the top tension in the 3 m, 12 s heave (max, min, mean over
the last 12 s and the largest difference at the output times).

Prints a table, writes bench/results/riser_peers.csv with --write, exits 1 if a target is
missed. --quick: the two decks only (about 4 s in a Release build). Without it also
rodyn's mesh (85 to 680 elements) and step (dt/2) checks, the effect of EI (EI/1000) and
the start from the seabed end that stops at the homotopy's turning point.
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
REF = os.path.join(HERE, "reference")
sys.path.insert(0, HERE)
import riser  # noqa: E402

L = riser.LENGTH
# Seo et al. (2026) and CableDyn's tutorial 3 (lazy-wave power cable), as printed
PUBLISHED = [
    ("top tension [N], OrcaFlex 11.6d (Seo 2026)", "top_tension_N", 9320.0, 1e-3, "rel"),
    ("top tension [N], CableDyn (Seo 2026)", "top_tension_N", 9320.0, 1e-3, "rel"),
    ("peak curvature [1/m], OrcaFlex 11.6d (Seo 2026)", "peak_curvature_per_m", 0.0968,
     1e-2, "rel"),
    ("peak curvature [1/m], CableDyn (Seo 2026)", "peak_curvature_per_m", 0.09683, 1e-2,
     "rel"),
    ("peak curvature s [m], CableDyn (Seo 2026)", "peak_curvature_s_m", 0.3412 * L, 0.5,
     "abs"),
    ("first grounded node s [m], CableDyn (Seo 2026)", "touchdown_s_m", 0.7967 * L, 0.5,
     "abs"),
    ("hang-off angle [deg], CableDyn tutorial", "hangoff_angle_deg", 81.6, 0.05, "abs"),
    ("sag bend z [m], CableDyn tutorial", "sag_z_m", -64.1, 0.05, "abs"),
    ("sag bend s [m], CableDyn tutorial", "sag_s_m", 58.5, 0.5, "abs"),
    ("hog bend z [m], CableDyn tutorial", "hog_z_m", -52.5, 0.05, "abs"),
    ("hog bend s [m], CableDyn tutorial", "hog_s_m", 87.2, 0.5, "abs"),
]
# against the stored CableDyn run: (label, key, tolerance, kind)
CABLEDYN = [
    ("top tension [N]", "top_tension_N", 1e-4, "rel"),
    ("top horizontal force [N]", "top_H_N", 1e-4, "rel"),
    ("top vertical force [N]", "top_V_N", 1e-4, "rel"),
    ("hang-off angle [deg]", "hangoff_angle_deg", 0.01, "abs"),
    ("sag bend z [m]", "sag_z_m", 0.01, "abs"),
    ("sag bend s [m]", "sag_s_m", 0.5, "abs"),
    ("hog bend z [m]", "hog_z_m", 0.01, "abs"),
    ("hog bend s [m]", "hog_s_m", 0.5, "abs"),
    ("touchdown s (z reaches the seabed) [m]", "touchdown_s_m", 0.1, "abs"),
    ("peak curvature [1/m]", "peak_curvature_per_m", 2e-3, "rel"),
    ("peak curvature s [m]", "peak_curvature_s_m", 0.5, "abs"),
]


def run(rodyn, deck, out, expect_ok=True):
    t0 = time.perf_counter()
    p = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if expect_ok and p.returncode != 0:
        sys.exit(f"compare_riser: {deck}: rodyn exited {p.returncode}: {p.stderr.strip()}")
    return wall, p


def deck_variant(tmp, name, deck, replace, section_replace=None):
    """A copy of an input deck (and its section file) with text replaced."""
    with open(os.path.join(ROOT, "input", deck)) as f:
        text = f.read()
    for a, b in replace:
        if a not in text:
            sys.exit(f"compare_riser: {deck} has no '{a}'")
        text = text.replace(a, b)
    sec = os.path.join(ROOT, "input", "riser_lazy_wave_section.inc")
    with open(sec) as f:
        stext = f.read()
    for a, b in section_replace or []:
        stext = stext.replace(a, b)
    folder = os.path.join(tmp, name + "_deck")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "riser_lazy_wave_section.inc"), "w") as f:
        f.write(stext)
    path = os.path.join(folder, deck)
    with open(path, "w") as f:
        f.write(text)
    return path


def shape_difference(r, ref):
    """Largest distance [m] between rodyn's nodes and CableDyn's shape at the same s."""
    xs = np.interp(r["s_m"], ref["s_m"], ref["x_m"])
    zs = np.interp(r["s_m"], ref["s_m"], ref["z_m"])
    return float(np.max(np.hypot(r["x_m"] - xs, r["z_m"] - zs)))


def heave_top(folder):
    with open(os.path.join(folder, "dynamic_ends.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["end"] == "B"]
    return (np.array([float(r["time_s"]) for r in rows]),
            np.array([float(r["tension_N"]) for r in rows]))


def err(v, ref, kind):
    return v - ref if kind == "abs" else v / ref - 1.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--quick", action="store_true", help="the two decks only")
    ap.add_argument("--write", action="store_true", help="write bench/results/riser_peers.csv")
    a = ap.parse_args()
    cd = json.load(open(os.path.join(REF, "cabledyn_riser.json")))
    with open(os.path.join(REF, "cabledyn_riser_heave.csv")) as f:
        cdh = np.array([[float(r["time_s"]), float(r["top_tension_N"])]
                        for r in csv.DictReader(f)])
    rows, walls, notes = [], {}, []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "static")
        walls["static"], _ = run(a.rodyn, os.path.join(ROOT, "input", "riser_lazy_wave.inp"),
                                 out)
        r = riser.read_rodyn_static(out)
        for label, key, ref, tol, kind in PUBLISHED:
            rows.append((label, r[key], ref, err(r[key], ref, kind), tol))
        st = cd["static"]
        for label, key, tol, kind in CABLEDYN:
            rows.append((label + f", CableDyn {cd['version']} run", r[key], st[key],
                         err(r[key], st[key], kind), tol))
        rows.append(("shape: largest node distance [m], CableDyn run",
                     shape_difference(r, cd["shape"]), 0.0, shape_difference(r, cd["shape"]),
                     0.02))
        rows.append(("touchdown s, rodyn's own (static_lines.csv) [m]", r["touchdown_own_s_m"],
                     st["touchdown_s_m"], r["touchdown_own_s_m"] - st["touchdown_s_m"], 0.1))
        out = os.path.join(tmp, "heave")
        walls["heave"], _ = run(a.rodyn,
                                os.path.join(ROOT, "input", "riser_lazy_wave_heave.inp"), out)
        t, T = heave_top(out)
        Tc = np.interp(t, cdh[:, 0], cdh[:, 1])
        w = t >= riser.T_END - riser.PERIOD - 1e-9
        rng = Tc[w].max() - Tc[w].min()
        for label, f in (("max", np.max), ("min", np.min), ("mean", np.mean)):
            rows.append((f"heave top tension {label} [N], CableDyn run", f(T[w]), f(Tc[w]),
                         err(f(T[w]), f(Tc[w]), "rel"), 1e-3))
        d = float(np.max(np.abs(T - Tc)))
        rows.append(("heave top tension: largest difference / range, CableDyn run", d, rng,
                     d / rng, 5e-3))
        if not a.quick:
            notes += extra_checks(a.rodyn, tmp, r, t, T)
    ok = True
    print(f"{'quantity':66s} {'rodyn':>12s} {'reference':>12s} {'error':>10s} {'target':>8s}")
    table = []
    for name, v, ref, e, tol in rows:
        good = abs(e) <= tol
        ok &= good
        print(f"{name:66s} {v:12.6g} {ref:12.6g} {e:10.2e} {tol:8.0e} "
              f"{'ok' if good else 'MISSED'}")
        table.append([name, v, ref, e, tol, good])
    for n in notes:
        print(n)
    print("rodyn wall time [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in walls.items()))
    if a.write:
        os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
        with open(os.path.join(ROOT, "bench", "results", "riser_peers.csv"), "w",
                  newline="") as f:
            wr = csv.writer(f)
            wr.writerow(["quantity", "rodyn", "reference", "error", "target", "met"])
            wr.writerows(table)
    sys.exit(0 if ok else 1)


def extra_checks(rodyn, tmp, base, t0, T0):
    """Mesh and step of rodyn, EI's effect, the start from the seabed end."""
    notes = ["rodyn mesh (elements per section from the seabed end; the deck: 52/50/68):"]
    for n in ((26, 25, 34), (104, 100, 136), (208, 200, 272)):
        deck = deck_variant(tmp, f"mesh{sum(n)}", "riser_lazy_wave.inp",
                            [("ELEMENTS=52", f"ELEMENTS={n[0]}"),
                             ("ELEMENTS=50", f"ELEMENTS={n[1]}"),
                             ("ELEMENTS=68", f"ELEMENTS={n[2]}")])
        out = os.path.join(tmp, f"mesh{sum(n)}")
        wall, _ = run(rodyn, deck, out)
        r = riser.read_rodyn_static(out)
        notes.append(f"  {sum(n):4d} elements: top tension {r['top_tension_N']:.3f} N, "
                     f"peak curvature {r['peak_curvature_per_m']:.5f} 1/m, touchdown "
                     f"{r['touchdown_s_m']:.3f} m ({wall:.2f} s)")
    deck = deck_variant(tmp, "dt", "riser_lazy_wave_heave.inp",
                        [("DT=0.05,", "DT=0.025,")])
    out = os.path.join(tmp, "dt")
    run(rodyn, deck, out)
    t, T = heave_top(out)
    notes.append(f"rodyn heave at dt/2: top tension changes by at most "
                 f"{np.max(np.abs(np.interp(t0, t, T) - T0)):.2f} N")
    deck = deck_variant(tmp, "lowei", "riser_lazy_wave.inp", [],
                        [("4.69e8, 1.99e4, 1.99e4", "4.69e8, 1.99e1, 1.99e1")])
    out = os.path.join(tmp, "lowei")
    run(rodyn, deck, out)
    r = riser.read_rodyn_static(out)
    notes.append(f"EI/1000: top tension {r['top_tension_N']:.1f} N "
                 f"({r['top_tension_N'] / base['top_tension_N'] - 1:+.2%}), H "
                 f"{r['top_H_N']:.1f} N ({r['top_H_N'] / base['top_H_N'] - 1:+.2%}), "
                 f"touchdown {r['touchdown_s_m']:.2f} m "
                 f"({r['touchdown_s_m'] - base['touchdown_s_m']:+.2f} m), sag z "
                 f"{r['sag_z_m']:.2f} m, hog z {r['hog_z_m']:.2f} m, peak curvature "
                 f"{r['peak_curvature_per_m']:.4f} 1/m at {r['peak_curvature_s_m']:.1f} m")
    deck = deck_variant(tmp, "fold", "riser_lazy_wave.inp",
                        [("150.0, 0.0, -14.0, 5.0, 0.0, -14.0",
                          "125.0, 0.0, -80.0, 5.0, 0.0, -14.0"),
                         ("*BOUNDARY, LINE=CABLE, END=A, TYPE=POSITION\n125.0, 0.0, -80.0",
                          "*BOUNDARY, LINE=CABLE, END=A, TYPE=PINNED")])
    _, p = run(rodyn, deck, os.path.join(tmp, "fold"), expect_ok=False)
    m = re.search(r"load factor\s+([0-9.]+)", p.stderr)
    notes.append(f"started at the seabed end (grounded catenary): exit {p.returncode}, "
                 + (f"stops at load factor {m.group(1)}" if m else p.stderr.strip()))
    return notes


if __name__ == "__main__":
    main()
