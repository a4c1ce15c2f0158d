#!/usr/bin/env python3
"""The static solution of a grounded mooring leg in a cross current against the same
leg brought to rest in that current by dynamic relaxation (docs/water.md, verification).

The leg of input/mooring_current.inp as a rod with a bending and torsion stiffness of
1e5 N m2 (a rod of the chain's EI = 10 is out of the static solver's reach: docs/water.md,
limitations; the deck itself uses cable elements). Run 1, statics with the 1 m/s current
along +y in full. Run 2, statics in still water, then the current ramped in over 30 s and
600 s of motion, the drag damping the leg into its steady shape. The dynamics never use the
static solver's homotopy or its roll gauge, so the two paths share only the physics.

Usage: check_static_cross_current.py RODYN OUT_DIR. Exit 0 when the fairlead force and
the touchdown of the two runs agree to TOL."""
import csv
import os
import sys

from deck_run import run_deck

DECK = """*HEADING
Mooring leg (a rod of EI = GJ = 1e5 N m2) in a 1 m/s current across its plane
*GRAVITY
0.0, 0.0, -9.80665
*WATER, DEPTH=100.0, DENSITY=1025.0
*SEABED, STIFFNESS=3.0e6, DAMPING=3.0e5
*CURRENT{ramp}
-100.0, 1.0, 90.0
0.0, 1.0, 90.0
*SECTION, NAME=CHAIN, OD=0.1, CDN=1.2, CDA=0.05, CAN=1.0, CAA=0.0
6.0e8, 1.0e5, 1.0e5, 1.0e5, 60.0
*LINE, NAME=LEG, SECTION=CHAIN, LENGTH=450.0, ELEMENTS=120, ORDER=3
-400.0, 0.0, -100.0, 0.0, 0.0, -10.0
*BOUNDARY, LINE=LEG, END=A, TYPE=PINNED
*BOUNDARY, LINE=LEG, END=B, TYPE=PINNED
*STATIC, INCREMENTS={increments}
{dynamic}*OUTPUT, CSV=YES, HDF5=NO
"""
TOL = 1.0e-6


def main():
    rodyn, out = sys.argv[1:3]
    os.makedirs(out, exist_ok=True)
    static = DECK.format(ramp="", increments=20, dynamic="")
    relax = DECK.format(ramp=", RAMP=30.0", increments=10,
                        dynamic="*DYNAMIC, DT=0.2, TIME=600.0, OUTPUT INTERVAL=50.0\n")
    rs = run_deck(rodyn, static, out, "static")
    rd = run_deck(rodyn, relax, out, "relaxed")
    with open(os.path.join(rs, "static_reactions.csv")) as f:
        fs = [float(r[k]) for r in csv.DictReader(f) if r["end"] == "B"
              for k in ("Fx_N", "Fy_N", "Fz_N")]
    with open(os.path.join(rd, "dynamic_ends.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["end"] == "B"]
    fd = [float(rows[-1][k]) for k in ("Fx_N", "Fy_N", "Fz_N")]
    with open(os.path.join(rs, "static_lines.csv")) as f:
        ts = float(next(csv.DictReader(f))["touchdown_s_m"])
    with open(os.path.join(rd, "dynamic_lines.csv")) as f:
        td = float(list(csv.DictReader(f))[-1]["touchdown_s_m"])
    big = max(abs(v) for v in fs)
    ef = max(abs(a - b) for a, b in zip(fs, fd)) / big
    et = abs(ts - td) / 450.0
    print(f"fairlead force, static {fs} N, relaxed {fd} N: within {ef:.2e}")
    print(f"touchdown, static {ts:.6f} m, relaxed {td:.6f} m: within {et:.2e} of the length")
    ok = ef <= TOL and et <= TOL
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
