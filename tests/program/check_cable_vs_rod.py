#!/usr/bin/env python3
"""The cable element against the rod of a tiny bending stiffness on a dynamic case
(docs/element.md, the cable element): the surge case of input/mooring_surge.inp over its
first 48 s (ramp-in and three periods), 120 cubic elements at DT = 0.05 s, once with cable
elements and once as a rod of EI = GJ = 10 N m2 (the section's). The fairlead tension
histories agree to TOL_MAX of the largest tension and TOL_RMS in the root mean square
(measured 2.0e-3 and 6.3e-4; with 60 elements at DT = 0.1 s 6.3e-3, with 240 at 0.025 s
1.5e-3 and 3.1e-4: the rest is the rod's EI and rotary inertia and the touchdown's
impacts).

Usage: check_cable_vs_rod.py RODYN OUT_DIR. Exit 0 on success."""
import csv
import os
import shutil
import sys

import numpy as np

from deck_run import run_deck

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT = os.path.join(HERE, "..", "..", "input")
TOL_MAX = 5.0e-3
TOL_RMS = 1.0e-3


def tension(rodyn, deck, out, name):
    """Fairlead (end B) tension history of a run of the deck text."""
    res = run_deck(rodyn, deck, out, name)
    with open(os.path.join(res, "dynamic_ends.csv")) as f:
        return np.array([float(r["tension_N"]) for r in csv.DictReader(f) if r["end"] == "B"])


def main():
    rodyn, out = sys.argv[1:3]
    os.makedirs(out, exist_ok=True)
    shutil.copy(os.path.join(INPUT, "mooring_leg_section.inc"), out)
    with open(os.path.join(INPUT, "mooring_surge.inp")) as f:
        deck = f.read().replace("TIME=120.0", "TIME=48.0")
    if "ELEMENT=CABLE" not in deck or "TIME=48.0" not in deck:
        sys.exit("FAIL: input/mooring_surge.inp is not the deck this check expects")
    tc = tension(rodyn, deck, out, "cable")
    tr = tension(rodyn, deck.replace("ELEMENT=CABLE", "ELEMENT=ROD"), out, "rod")
    emax = np.abs(tc - tr).max() / tr.max()
    erms = np.sqrt(np.mean((tc - tr) ** 2)) / tr.max()
    print(f"{len(tc)} frames; fairlead tension, cable against rod: largest difference "
          f"{emax:.2e}, rms {erms:.2e} of the largest tension {tr.max():.1f} N")
    ok = emax <= TOL_MAX and erms <= TOL_RMS
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
