#!/usr/bin/env python3
"""MoorDyn v2 input files run by rodyn (docs/moordyn.md).

1. MoorDyn's OC3-Hywind lines (its tests/Mooring/lines.txt, three 902.2 m chains from
   anchors on the seabed at 853.87 m radius to fairleads held at 70 m depth):
   - `rodyn lines.txt` and `rodyn` on the deck `rodyn --to-deck lines.txt` writes give the
     same static_points.csv and static_nodes.csv, byte for byte;
   - MoorDyn's discretisation (20 segments: 20 linear elements) gives the fairlead force
     within 2e-3 of the grounded elastic catenary (Irvine, "Cable Structures", 1981:
     the touchdown form, no friction, rigid seabed; solved here by scipy), and the same
     deck on 40 cubic elements within 5e-5, closer (what is left is the seabed's
     compliance: the grounded chain sinks w/(kBot d) = 2.6 mm);
   - the weight in water the catenary uses is MoorDyn's: (Mass/m - rho pi Diam^2/4) g.
2. A buoy (a FREE body of 2000 kg and 5 m3, its CG 1 m above its reference point) on two
   chains (tests/program/moordyn_buoy.txt): the lines' force on the body balances its
   weight less its buoyancy at CG, (rho V - M) g, to 1e-9; the options of MoorDyn's
   explicit integrator are noted as ignored; a negative UnstrLen is that many times the
   distance between the ends and a point below WtrDpth lowers the seabed to it (both as
   in MoorDyn, both noted).
3. A Fixed rod from which two chains hang to anchors (their ends R1A and R1B): the same
   nodes as the file with the rod's ends as two Fixed points, to 1e-10 m (round-off: a
   body's points hold their ends through the junctions), and the same forces on the rod's
   ends to 1e-10.

4. MoorDyn's cantilever (its tests/Mooring/BeamCantilevered.txt: a 10 m beam, EI 1e7 N m2,
   100 kg/m in vacuum, 19 segments, clamped at a fixed rod's end B and free at the
   other, starting 0.1 m below the rod's axis): every node within 1e-3 of the tip
   deflection of the Euler-Bernoulli cantilever under its own weight, z = -p x^2 (6 L^2 -
   4 x L + x^2) / (24 EI), the tip p L^4 / (8 EI) = 0.1226 m; and the same from the
   rod's end A with the rod turned end for end (the clamp's axis leaves each end
   outwards, as MoorDyn's Line::setEndOrientation).

Usage: check_moordyn_file.py RODYN LINES_TXT BUOY_TXT OUT_DIR CANTILEVER_TXT. Exit 0 on
success."""
import csv
import math
import os
import re
import subprocess
import sys

from scipy.optimize import fsolve

G, RHO = 9.80665, 1025.0
EA, LENGTH, DIAM, MASS = 384.243e6, 902.2, 0.09, 77.7066
ANCHOR_R, FAIR_R, DEPTH, FAIR_Z = 853.87, 5.2, 320.0, -70.0


def run(cmd):
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.strip()}")
    return proc


def points(out):
    with open(os.path.join(out, "static_points.csv")) as f:
        return {r["point"]: r for r in csv.DictReader(f)}


def grounded_catenary(w, x, z):
    """H and V at the fairlead of the grounded elastic catenary, no friction, the
    fairlead x across and z above the anchor."""

    def ends(p):
        h, v = p
        ls = v / w
        xs = (LENGTH - ls) * (1.0 + h / EA) + h / w * math.asinh(v / h) + h * ls / EA
        zs = h / w * (math.hypot(1.0, v / h) - 1.0) + v * v / (2.0 * EA * w)
        return [xs - x, zs - z]
    return fsolve(ends, [7.0e5, 5.0e5], xtol=1e-13)


def fairlead_error(out, w):
    """Largest relative error of the three fairlead forces (P4-P6, of lines from the
    anchors P1-P3) against the grounded catenary's (H, V)."""
    errs = []
    pts = points(out)
    for k in range(3):
        a, f = pts[f"P{k + 1}"], pts[f"P{k + 4}"]
        x = math.hypot(float(f["x_m"]) - float(a["x_m"]), float(f["y_m"]) - float(a["y_m"]))
        h, v = grounded_catenary(w, x, float(f["z_m"]) - float(a["z_m"]))
        fh = math.hypot(float(f["Fx_N"]), float(f["Fy_N"]))
        errs.append(math.hypot(fh - h, -float(f["Fz_N"]) - v) / math.hypot(h, v))
    return max(errs)


def check_lines(rodyn, lines, out, fails):
    a, b, c = (os.path.join(out, k) for k in ("moordyn", "deck", "fine"))
    run([rodyn, lines, "-o", a, "--quiet"])
    deck = run([rodyn, "--to-deck", lines]).stdout
    with open(os.path.join(out, "lines.inp"), "w") as f:
        f.write(deck)
    run([rodyn, os.path.join(out, "lines.inp"), "-o", b, "--quiet"])
    for name in ("static_points.csv", "static_nodes.csv"):
        same = open(os.path.join(a, name)).read() == open(os.path.join(b, name)).read()
        print(f"rodyn lines.txt and its --to-deck deck: {name} {'the same' if same else 'DIFFER'}")
        if not same:
            fails.append(f"--to-deck round trip: {name} differs")
    fine = deck.replace("ELEMENTS=20, ORDER=1", "ELEMENTS=40, ORDER=3")
    if fine.count("ORDER=3") != 3:
        fails.append("the deck of lines.txt has not its 3 lines of 20 linear elements")
    with open(os.path.join(out, "fine.inp"), "w") as f:
        f.write(fine)
    run([rodyn, os.path.join(out, "fine.inp"), "-o", c, "--quiet"])
    w = (MASS - RHO * math.pi * DIAM ** 2 / 4.0) * G
    h, v = grounded_catenary(w, ANCHOR_R - FAIR_R, DEPTH + FAIR_Z)
    e20, e40 = fairlead_error(a, w), fairlead_error(c, w)
    print(f"grounded elastic catenary, w = {w:.4f} N/m: line 1's H = {h:.3f} N, "
          f"V = {v:.3f} N")
    print(f"fairlead force: 20 linear elements (MoorDyn's) {e20:.2e}, 40 cubic {e40:.2e}")
    if not (e20 < 2e-3 and e40 < 5e-5 and e40 < e20):
        fails.append(f"fairlead force against the catenary: {e20:.2e} (< 2e-3), "
                     f"{e40:.2e} (< 5e-5)")


def check_buoy(rodyn, buoy, out, fails):
    d = os.path.join(out, "buoy")
    proc = run([rodyn, buoy, "-o", d])
    with open(os.path.join(d, "static_bodies.csv")) as f:
        body = next(csv.DictReader(f))
    fz, want = float(body["Fz_N"]), -(RHO * 5.0 - 2000.0) * G
    e = abs(fz - want) / abs(want)
    print(f"buoy: the lines' vertical force on it {fz:.6f} N, -(rho V - M) g = {want:.6f} N: "
          f"{e:.1e}")
    if e > 1e-9:
        fails.append(f"buoy's force balance: {e:.1e}")
    deck = run([rodyn, "--to-deck", buoy]).stdout
    length = float(re.search(r"NAME=L2, SECTION=chain, LENGTH=([^,]+)", deck).group(1))
    want = 1.02 * math.hypot(80.0 - 1.0, 60.0 - 5.0)
    print(f"line 2 of UnstrLen -1.02: LENGTH {length!r}, 1.02 times its ends' distance "
          f"{want!r}")
    if abs(length - want) > 1e-12 * want:
        fails.append(f"negative UnstrLen: {length} != {want}")
    if "*WATER, DEPTH=60, " not in deck:
        fails.append("the point at z = -60 below WtrDpth 50 has not lowered the seabed")
    for text in ("note: OPTIONS dtM, cfl ignored", "UnstrLen -1.02 times the distance",
                 "is below the water depth: the depth is 60 m"):
        if text not in proc.stdout:
            fails.append(f"the notes lack: {text}")
    print("notes:\n" + proc.stdout.strip())


ROD_FILE = """--------------------- MoorDyn Input File ----------------------
two chains hanging from {what}
---------------------- LINE TYPES ----------------------
Name  Diam  Mass/m  EA     BA/-zeta  EI  Cd   Ca   CdAx  CaAx
(-)   (m)   (kg/m)  (N)    (N-s)     (-) (-)  (-)  (-)   (-)
chain 0.1   20.0    1.0e8  -0.5      0   1.2  1.0  0.2   0.0
{rods}---------------------- POINTS ----------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -80 0 -50 0 0 0 0
2 Fixed 80 0 -50 0 0 0 0
{points}---------------------- LINES ----------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 {a} 95 12 -
2 chain 2 {b} 95 12 -
---------------------- OPTIONS ----------------------
1025 WtrDnsty
50 WtrDpth
---------------------- need this line ----------------------
"""
RODS = """---------------------- ROD TYPES ----------------------
Name Diam Mass/m Cd Ca CdEnd CaEnd
(-) (m) (kg/m) (-) (-) (-) (-)
pipe 0.5 100 1.0 1.0 0.6 1.0
---------------------- RODS ----------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 pipe Fixed -1 0 -5 1 0 -5 4 -
"""


def check_rod(rodyn, out, fails):
    nodes, ends = [], []
    for tag, rods, more, a, b in (
            ("rod", RODS, "", "R1A", "R1B"),
            ("points", "", "3 Fixed -1 0 -5 0 0 0 0\n4 Fixed 1 0 -5 0 0 0 0\n", "3", "4")):
        path = os.path.join(out, f"moordyn_{tag}.txt")
        with open(path, "w") as f:
            f.write(ROD_FILE.format(what=tag, rods=rods, points=more, a=a, b=b))
        run([rodyn, path, "-o", os.path.join(out, tag), "--quiet"])
        with open(os.path.join(out, tag, "static_nodes.csv")) as f:
            nodes.append([[float(r[k]) for k in ("x_m", "y_m", "z_m")]
                          for r in csv.DictReader(f)])
        pts = points(os.path.join(out, tag))
        ends.append([[float(pts[p][k]) for k in ("Fx_N", "Fz_N")]
                     for p in ((("R1A", "R1B") if tag == "rod" else ("P3", "P4")))])
    dx = max(abs(a - b) for ra, rb in zip(*nodes) for a, b in zip(ra, rb))
    df = max(abs(a - b) / abs(b) for ra, rb in zip(*ends) for a, b in zip(ra, rb))
    print(f"a Fixed rod's ends and two Fixed points: nodes within {dx:.1e} m, the forces "
          f"on the ends within {df:.1e}")
    if not (len(nodes[0]) == len(nodes[1]) == 26 and dx <= 1e-10 and df <= 1e-10):
        fails.append(f"the rod's ends and two fixed points: {dx:.1e} m, {df:.1e}")


def check_cantilever(rodyn, cantilever, out, fails):
    with open(cantilever) as f:
        text = f.read()
    turned = text.replace("-10.0 0     10.0  0.0   0     10.0", "0.0   0     10.0  -10.0 0     10.0")
    turned = turned.replace("R1B      1", "R1A      1")
    if turned.count("R1A") != 1 or "-10.0 0     10.0  0.0" in turned:
        fails.append("the cantilever file is not MoorDyn's BeamCantilevered.txt")
        return
    p, length, ei = 100.0 * 9.80665, 10.0, 1.0e7
    tip = p * length ** 4 / (8.0 * ei)
    for tag, body in (("cantilever_B", text), ("cantilever_A", turned)):
        path = os.path.join(out, tag + ".txt")
        with open(path, "w") as f:
            f.write(body)
        run([rodyn, path, "-o", os.path.join(out, tag), "--quiet"])
        with open(os.path.join(out, tag, "static_nodes.csv")) as f:
            nodes = [(float(r["x_m"]), float(r["z_m"]) - 10.0) for r in csv.DictReader(f)
                     if r["line"] == "L1"]
        err = max(abs(z + p * x * x * (6 * length ** 2 - 4 * x * length + x * x)
                      / (24.0 * ei)) for x, z in nodes) / tip
        print(f"{tag}: {len(nodes)} nodes within {err:.1e} of the tip deflection "
              f"{tip:.4f} m (tip {nodes[-1][1]:.5f} m)")
        if not (len(nodes) == 20 and err <= 1e-3):
            fails.append(f"{tag}: {err:.1e} of the tip deflection")


def main():
    rodyn, lines, buoy, out, cantilever = sys.argv[1:6]
    os.makedirs(out, exist_ok=True)
    fails = []
    check_lines(rodyn, lines, out, fails)
    check_buoy(rodyn, buoy, out, fails)
    check_rod(rodyn, out, fails)
    check_cantilever(rodyn, cantilever, out, fails)
    for f in fails:
        print("FAIL:", f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
