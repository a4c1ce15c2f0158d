#!/usr/bin/env python3
"""A taut line (tests/program/taut_line.inp: 99 m between points 100 m apart, EA 1e7 N):
its ends farther apart than its length, it starts straight and stretched and the statics
finds its equilibrium. Weightless, cable and rod elements: the force on end B is
EA (d/L - 1) along the chord, to 1e-9. With 50 kg/m in air: the force on end B against the
elastic catenary (Irvine, "Cable Structures", 1981, eqs. 2.2; its two end conditions
solved here by scipy), to 1e-9, on cable elements (no bending stiffness). And a buoyant
line slack between the same points (tests/program/buoyant_line.inp: 110 m, weight in
water w < 0): it starts as the catenary turned upside down and its end force is the
elastic catenary's with that negative w, to 1e-9.

Usage: check_taut_line.py RODYN DECK BUOYANT_DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

from scipy.optimize import fsolve

EA, L, X, Z, G = 1.0e7, 99.0, 80.0, 60.0, 9.80665


def force_b(rodyn, deck, out, elem, mass):
    d = os.path.join(out, f"{elem}_{mass}")
    sets = ["--set", f"ELEM={elem}", "--set", f"MASS={mass}"] if elem else []
    proc = subprocess.run([rodyn, deck, "-o", d, "--quiet"] + sets, capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: {elem} {mass} kg/m: rodyn exit {proc.returncode}: "
                 f"{proc.stderr.strip()}")
    with open(os.path.join(d, "static_points.csv")) as f:
        row = [r for r in csv.DictReader(f) if r["point"] == "B"][0]
    return float(row["Fx_N"]), float(row["Fz_N"])


def elastic_catenary(w, length=L, guess=(8.0e4, 3.0e4)):
    """H and the vertical force V_B at end B of the elastic catenary of weight w per
    length (< 0: buoyant) and unstretched length `length` between A and B."""
    def ends(p):
        h, v0 = p
        v1 = v0 + w * length
        x = h * length / EA + h / w * (math.asinh(v1 / h) - math.asinh(v0 / h))
        z = ((v0 * length + 0.5 * w * length * length) / EA
             + (math.hypot(h, v1) - math.hypot(h, v0)) / w)
        return [x - X, z - Z]
    h, v0 = fsolve(ends, list(guess), xtol=1e-12)
    return h, v0 + w * length


def main():
    rodyn, deck, buoyant, out = sys.argv[1:5]
    fails = []
    t = EA * (math.hypot(X, Z) / L - 1.0)
    for elem in ("CABLE", "ROD"):
        fx, fz = force_b(rodyn, deck, out, elem, 0.0)
        e = max(abs(-fx - t * X / 100.0), abs(-fz - t * Z / 100.0)) / t
        print(f"weightless {elem}: force on B ({fx:.6f}, {fz:.6f}) N, EA (d/L - 1) = "
              f"{t:.6f} N along the chord: {e:.1e}")
        if e > 1e-9:
            fails.append(f"weightless {elem}: {e:.1e}")
    h, vb = elastic_catenary(50.0 * G)
    fx, fz = force_b(rodyn, deck, out, "CABLE", 50.0)
    e = max(abs(-fx - h), abs(-fz - vb)) / math.hypot(h, vb)
    print(f"50 kg/m CABLE: force on B ({fx:.6f}, {fz:.6f}) N, elastic catenary "
          f"(H, V_B) = ({h:.6f}, {vb:.6f}) N: {e:.1e}")
    if e > 1e-9:
        fails.append(f"50 kg/m cable: {e:.1e}")
    w = (20.0 - 1025.0 * math.pi * 0.3 ** 2 / 4.0) * G
    h, vb = elastic_catenary(w, 110.0, (2.0e4, 4.0e4))
    fx, fz = force_b(rodyn, buoyant, out, "", "buoyant")
    e = max(abs(-fx - h), abs(-fz - vb)) / math.hypot(h, vb)
    print(f"buoyant slack line (w = {w:.3f} N/m): force on B ({fx:.6f}, {fz:.6f}) N, "
          f"elastic catenary (H, V_B) = ({h:.6f}, {vb:.6f}) N: {e:.1e}")
    if not h > 0.0 or e > 1e-9:
        fails.append(f"buoyant line: {e:.1e}")
    for f in fails:
        print("FAIL:", f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
