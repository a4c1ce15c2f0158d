#!/usr/bin/env python3
"""rodyn and MoorPy on lines joined at points: three static mooring systems.

Cases (all lines: the chain-like section of bench/water/leg.py, 60 kg/m in air,
volume-equivalent diameter 0.1 m, EA 6e8 N; cable elements in rodyn; water depth 100 m,
still water level z = 0, flat seabed z = -100 m; z up):
  buoy          a subsea buoy joining two lines (a tethered buoy): FIXED ANCHOR (0, 0, -100),
                FREE BUOY (MASS 2000 kg, VOLUME 20 m3) started at (35, 0, -52), FIXED
                FAIRLEAD (300, 0, -10); TETHER ANCHOR->BUOY 60 m, RISER BUOY->FAIRLEAD 300 m.
                The tether is taut (its anchor end is lifted), the riser sags to 7.1 m above
                the seabed; nothing touches the seabed but the anchor point.
  crowfoot      three legs of 420 m from FIXED anchors at radius 400 m, headings 0, 120,
                240 deg, z = -100, to one FREE HUB (MASS 5000 kg, VOLUME 30 m3) started at
                (0, 0, -30), with a steady external force of 50 kN along +x on the HUB
                (rodyn: `*LOAD, POINT=HUB`; MoorPy: the point's fExt).
                The legs lie partly on the seabed (241 to 282 m grounded).
  chain_of_two  two lines of 110 m in series between FIXED P1 (0, 0, -20) and P3
                (200, 0, -20) through a FREE CONNECTOR of 500 kg (no volume) started at
                (100, 0, -40); no seabed contact. Also solved in closed form (below).
The buoy's and the connector's starting positions lie within reach of their lines (the
distance between a line's ends may not exceed its length in rodyn); MoorPy starts from
the same positions. No length needed adjusting: MoorPy converges with these, the tether
is taut and no line touches the seabed in buoy and chain_of_two.

MoorPy's conventions (MoorPy 1.3.0: moorpy/system.py, point.py, line.py, Catenary.py):
  g 9.81 m/s2 and rho 1025 kg/m3 (MoorPy's System defaults, passed explicitly), so the
  decks have `*GRAVITY 0, 0, -9.81` and `*WATER, DENSITY=1025.0`.
  Line: quasi-static elastic catenary of Jonkman (FAST v7), strain T/EA with T the
  effective tension; weight per unstretched length w = (m - rho pi d^2/4) g with d the
  volume-equivalent diameter d_vol (rodyn: the section's OD, its buoyancy diameter) =
  509.626251 N/m. No bending. Its profile points (nSegs) do not enter the forces.
  Seabed: flat, rigid, frictionless (a line end on the seabed gets CB = 0: friction
  coefficient 0); only a line whose end A is on the seabed can lie on it here (the
  crowfoot's legs run from the anchor, end A). rodyn's seabed is a penalty: the decks'
  *SEABED STIFFNESS is 3e7 Pa/m on the diameter, ten times rodyn's default, so that the
  grounded chain sinks w/(k d) = 0.17 mm instead of 1.7 mm. Measured with --pinned
  (rodyn without points: the crowfoot's legs alone, ends pinned at MoorPy's equilibrium), the
  legs' end tensions differ from MoorPy's by at most 5.6e-6 with 3e7 Pa/m and 240 cubic
  elements a leg, but 4.6e-5 with 3e6 Pa/m (the sinking) and 1.6e-5 with 120 elements
  (the touchdown's resolution); the crowfoot's legs therefore have 240 elements, the
  other lines (no contact) 40, at which --pinned agrees to 1e-10.
  Point: force = -m g + rho g v (v fully submerged: z below -1 m with MoorPy's default
  zSpan [-1, 1]; all points here are) + fExt (the crowfoot's 50 kN) + the attached
  lines' end forces; its seabed term is zero more than 2 m above the bed (all free points).
  End forces: Line.fA, Line.fB are the forces of the line ON its end points, global axes;
  Line.TA, Line.TB their magnitudes, the end tensions (the effective tension at the ends).
  rodyn's static_points.csv F is the sum of the attached lines' forces on the point (the
  sum of MoorPy's fA/fB of the lines on it); static_reactions.csv gives the force of a held
  support on the line (minus MoorPy's fA or fB) and its magnitude tension_N.
  Equilibrium: System.solveEquilibrium (Newton on the free points' positions with the
  analytic stiffness, dsolve2) stops when every component of the last Newton step is
  below tol [m]; its catenaries are solved to 0.01 tol [m]. MoorPy's default tol 0.05 m
  (catenaries 5e-4 m) is too coarse for a 1e-6 reference (its crowfoot tensions move by
  2.6e-6 between tol 1e-4 and 1e-6); here tol = 1e-8 m (catenaries 1e-10 m). Checked:
  the free points' force residual (below 1e-12 of the largest tension), a second solve
  at tol 1e-10 m, and an independent solution of the same equations (below).
  Stiffness (crowfoot): Point.getStiffnessA(lines_only=True), the analytic 3x3 stiffness
  of the HUB (sum of the attached ends' KB from the catenary's analytic derivatives),
  -dF/dx of the lines' force on the HUB with the anchors held; here the HUB is the only
  free object, so it equals System.getSystemStiffnessA. Checked against a central
  difference (+-1e-3 m, catenaries to 1e-12 m). Reference only: rodyn writes no stiffness.
  (System.getSystemStiffness, MoorPy's finite difference, is not used: at equilibrium its
  step refinement compares curvature with the residual force, which is ~0, and shrinks
  the step to 1e-3 dx with catenaries solved to 0.05 dx, giving a wrong matrix.)

Independent check (no MoorPy): the same statics from the elastic catenary equations
(Irvine; with a grounded part on a frictionless rigid bed when end A lies on the seabed
and the vertical force at end B is below w L), each line's end forces from its ends'
offsets by scipy's fsolve and the free points' balance by an outer fsolve, started from
MoorPy's solution. chain_of_two in closed form: by symmetry the connector lies at x =
100 m and each line carries half the connector's weight at its lower end: one elastic
catenary with vertical force m g/2 at its lower end and 100 m of horizontal span, whose
horizontal tension H is the root of one equation (brentq); the connector's z follows.

Compared (--quick), each row of bench/results/moorpy_points.csv with a tolerance, as
|rodyn - MoorPy| / scale: positions of free points over the shortest attached line's
length; end tensions relative (ends on FIXED points: static_reactions.csv tension_N;
ends on the FREE point: static_elements.csv's effective tension at the end element's
Gauss points, extrapolated to the end by the Lagrange polynomial through them); point
forces F component by component over |F| of that point. Tolerance 1e-4 for all, but the
crowfoot anchors' Fz, not compared: MoorPy's grounded chain meets the anchor flat (Fz = 0),
rodyn's penalty bed holds the anchor node at z = -100 while the chain beside it sinks
0.17 mm, so the anchor carries a vertical force of the order of w times a node spacing
(--pinned: 84 to 104 N, 1e-3 of |F|; the tension moves by 1e-6). Stiffness, grounded
lengths and lowest points are stored for reference only.

  python3 bench/systems/moorpy_points.py --write            # MoorPy (+ checks) -> results
                                                            # and decks (~2 s)
  python3 bench/systems/moorpy_points.py --quick [--rodyn build/rodyn]
                                          # rodyn on the decks against the stored values
  python3 bench/systems/moorpy_points.py --pinned [--rodyn build/rodyn]
                                          # without *POINT: each case's lines
                                          # alone, ends PINNED at MoorPy's equilibrium
Results: bench/results/moorpy_points.csv; decks: bench/systems/decks/<case>.inp
(written by --write from the CASES below; --quick runs the files as they are and says
when one differs from what --write would write). Exit 1 if a tolerance is missed.
Install MoorPy: python3 -m pip install moorpy==1.3.0 (add --break-system-packages if pip
refuses); --quick and --pinned need only numpy.
"""
import argparse
import csv
import datetime
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import benchlib  # noqa: E402

RESULTS_CSV = os.path.join(ROOT, "bench", "results", "moorpy_points.csv")
SEABED = "*SEABED, STIFFNESS=3.0e7, DAMPING=3.0e5"   # see the docstring
DECKS = os.path.join(HERE, "decks")

G = 9.81            # m/s2, MoorPy's default
RHO = 1025.0        # kg/m3, MoorPy's default
DEPTH = 100.0       # m
MASS = 60.0         # kg/m in air
DIAM = 0.1          # m, volume-equivalent (rodyn: OD, the buoyancy diameter)
EA = 6.0e8          # N
W = (MASS - RHO * math.pi / 4.0 * DIAM**2) * G   # N/m submerged weight

EQ_TOL = 1e-8       # m, MoorPy solveEquilibrium tol (catenaries 0.01 tol)
EQ_TOL_CHECK = 1e-10
TOL = 1e-4          # default tolerance of a compared quantity
ORDER = 3           # cubic elements (3 Gauss points each)

# name, type, start position, mass [kg], volume [m3]
CASES = {
    "buoy": dict(
        title="Subsea buoy joining a taut tether and a sagging riser",
        points=[("ANCHOR", "FIXED", (0.0, 0.0, -100.0), 0.0, 0.0),
                ("BUOY", "FREE", (35.0, 0.0, -52.0), 2000.0, 20.0),
                ("FAIRLEAD", "FIXED", (300.0, 0.0, -10.0), 0.0, 0.0)],
        # name, length [m], point A, point B, elements
        lines=[("TETHER", 60.0, "ANCHOR", "BUOY", 40),
               ("RISER", 300.0, "BUOY", "FAIRLEAD", 40)],
        loads={}, increments=20),
    "crowfoot": dict(
        title="Three legs from anchors at 400 m to a buoyant hub pulled by 50 kN along +x",
        points=[("A1", "FIXED", (400.0, 0.0, -100.0), 0.0, 0.0),
                ("A2", "FIXED", (-200.0, 200.0 * math.sqrt(3.0), -100.0), 0.0, 0.0),   # 120 deg
                ("A3", "FIXED", (-200.0, -200.0 * math.sqrt(3.0), -100.0), 0.0, 0.0),  # 240 deg
                ("HUB", "FREE", (0.0, 0.0, -30.0), 5000.0, 30.0)],
        lines=[("LEG1", 420.0, "A1", "HUB", 240),     # the touchdown needs 240 (docstring)
               ("LEG2", 420.0, "A2", "HUB", 240),
               ("LEG3", 420.0, "A3", "HUB", 240)],
        loads={"HUB": (5.0e4, 0.0, 0.0)}, increments=20),
    "chain_of_two": dict(
        title="Two lines in series through a 500 kg connector between two fixed points",
        points=[("P1", "FIXED", (0.0, 0.0, -20.0), 0.0, 0.0),
                ("CONNECTOR", "FREE", (100.0, 0.0, -40.0), 500.0, 0.0),
                ("P3", "FIXED", (200.0, 0.0, -20.0), 0.0, 0.0)],
        lines=[("L1", 110.0, "P1", "CONNECTOR", 40),
               ("L2", 110.0, "CONNECTOR", "P3", 40)],
        loads={}, increments=20),
}


def fmt(v):
    """A deck number: the shortest text that reads back to the same double."""
    return repr(float(v))


def case_points(case):
    return {p[0]: dict(name=p[0], type=p[1], r=np.array(p[2], float), mass=p[3],
                       volume=p[4]) for p in case["points"]}


# ---------------------------------------------------------------------------- decks
def deck_text(name):
    """The rodyn deck of a case in the *POINT syntax (docs/deck.md, *POINT)."""
    case = CASES[name]
    pts = case_points(case)
    out = [f"** bench/systems/decks/{name}.inp, the MoorPy cross-check of lines joined at",
           "** points: written by bench/systems/moorpy_points.py --write, which also compares",
           "** rodyn's statics with bench/results/moorpy_points.csv (--quick).",
           "*HEADING",
           f"{case['title']} (MoorPy cross-check)",
           "** MoorPy's g and water density (its System defaults)",
           "*GRAVITY",
           f"0.0, 0.0, -{fmt(G)}",
           "** still water level z = 0, flat frictionless seabed at z = -100 m; penalty contact",
           "** ten times the default stiffness, so that a grounded chain sinks only",
           "** w/(k OD) = 0.17 mm (MoorPy's seabed is rigid)",
           f"*WATER, DEPTH={fmt(DEPTH)}, DENSITY={fmt(RHO)}",
           SEABED,
           "** chain-like section: 60 kg/m in air, OD = volume-equivalent diameter 0.1 m (MoorPy's",
           f"** d_vol: buoyancy), EA 6e8 N, no bending: a cable section; w = {W:.6f} N/m",
           "** EA [N], EI1 [N m2], EI2 [N m2], GJ [N m2/rad], mass [kg/m]",
           "*SECTION, NAME=CHAIN, OD=0.1, CDN=1.2, CDA=0.05, CAN=1.0, CAA=0.0",
           f"6.0e8, 0.0, 0.0, 0.0, {fmt(MASS)}"]
    out.append("** the points: FIXED ones hold, FREE ones find their equilibrium (from the")
    out.append("** positions given);")
    out.append("** a FREE point's force is MASS g less rho g VOLUME (fully submerged)")
    for p in case["points"]:
        pt = pts[p[0]]
        card = f"*POINT, NAME={pt['name']}, TYPE={pt['type']}"
        if pt["type"] == "FREE":
            card += f", MASS={fmt(pt['mass'])}"
            if pt["volume"] > 0.0:
                card += f", VOLUME={fmt(pt['volume'])}"
        out.append(card)
        out.append(", ".join(fmt(c) for c in pt["r"]))
    out.append("** cubic cable elements; both ends on points: no data line")
    for ln, length, a, b, ne in case["lines"]:
        out.append(f"*LINE, NAME={ln}, SECTION=CHAIN, LENGTH={fmt(length)}, ELEMENTS={ne}, "
                   f"ORDER={ORDER}, ELEMENT=CABLE, POINT A={a}, POINT B={b}")
    for pname, f in case["loads"].items():
        out.append("** a steady force on the point, global axes [N] (MoorPy: the point's fExt)")
        out.append(f"*LOAD, POINT={pname}")
        out.append(", ".join(fmt(c) for c in f))
    out.append(f"*STATIC, INCREMENTS={case['increments']}, MAX ITERATIONS=50")
    out.append("*OUTPUT, CSV=YES, HDF5=NO")
    return "\n".join(out) + "\n"


def deck_path(name):
    return os.path.join(DECKS, name + ".inp")


# ---------------------------------------------------------------------------- MoorPy
def moorpy_version():
    try:
        from importlib.metadata import version
        return version("moorpy")
    except Exception:  # noqa: BLE001
        return "unknown"


def build_moorpy(name):
    import moorpy as mp
    case = CASES[name]
    ms = mp.System(depth=DEPTH, rho=RHO, g=G)
    ms.setLineType(name="chain", lineType=dict(m=MASS, d_vol=DIAM, EA=EA))
    ids = {}
    for pname, ptype, r, m, v in case["points"]:
        fext = np.array(case["loads"].get(pname, (0.0, 0.0, 0.0)), dtype=float)  # a new array:
        # Point's default fExt is one shared array
        ms.addPoint(1 if ptype == "FIXED" else 0, list(r), m=m, v=v, fExt=fext)
        ids[pname] = len(ms.pointList)
    for ln, length, a, b, _ in case["lines"]:
        ms.addLine(length, "chain", nSegs=200, pointA=ids[a], pointB=ids[b])
    ms.initialize()
    return ms, ids


def solve_moorpy(name, tol):
    ms, ids = build_moorpy(name)
    ms.solveEquilibrium(tol=tol, maxIter=1000)
    for line in ms.lineList:                 # the final state, with the profiles
        line.staticSolve(tol=0.01 * tol, profiles=1)
    return ms, ids


def moorpy_state(ms, ids, name):
    """Positions, point forces (lines only), end tensions and forces of a solved system."""
    case = CASES[name]
    st = {"r": {}, "F": {}, "T": {}, "fend": {}, "residual": {}, "lbot": {}, "zmin": {},
          "profile": {}, "HV": {}}
    for pname, i in ids.items():
        p = ms.pointList[i - 1]
        st["r"][pname] = np.array(p.r, float)
        st["F"][pname] = np.array(p.getForces(lines_only=True, xyz=True), float)
        if p.type == 0:
            st["residual"][pname] = np.array(p.getForces(xyz=True), float)
    for k, (ln, *_rest) in enumerate(case["lines"]):
        line = ms.lineList[k]
        st["T"][(ln, "A")] = float(line.TA)
        st["T"][(ln, "B")] = float(line.TB)
        st["fend"][(ln, "A")] = np.array(line.fA, float)
        st["fend"][(ln, "B")] = np.array(line.fB, float)
        st["lbot"][ln] = float(line.LBot)
        st["zmin"][ln] = float(np.min(line.Zs))
        st["profile"][ln] = int(line.info["ProfileType"])
        st["HV"][ln] = (float(line.HF), float(line.VF))
    return st


def moorpy_stiffness(ms, ids, pname, dx=1e-3):
    """HUB's analytic stiffness (Point.getStiffnessA, lines only) and a central difference."""
    p = ms.pointList[ids[pname] - 1]
    ka = np.array(p.getStiffnessA(lines_only=True, xyz=True), float)
    ks = np.array(ms.getSystemStiffnessA(), float)
    r0 = np.array(p.r, float)
    kfd = np.zeros((3, 3))
    for j in range(3):
        f = []
        for sgn in (1.0, -1.0):
            r = r0.copy()
            r[j] += sgn * dx
            p.setPosition(r)
            for line in ms.lineList:
                line.staticSolve(tol=1e-12)
            f.append(np.array(p.getForces(lines_only=True, xyz=True), float))
        kfd[:, j] = -(f[0] - f[1]) / (2.0 * dx)
    p.setPosition(r0)
    for line in ms.lineList:
        line.staticSolve(tol=1e-12, profiles=1)
    return ka, ks, kfd


# ------------------------------------------------------------- independent catenary
def span(length, h, vb, grounded):
    """Offset (x along the line's horizontal direction, z up) of end B from end A of an
    elastic catenary (w, EA) whose tension at end B has horizontal part h > 0 and vertical
    part vb (along the line, from A to B); grounded: end A on a frictionless rigid seabed,
    so a part lies on it when vb < w L. Returns x, z, va (vertical tension at A, 0 when
    grounded), lying (grounded length)."""
    va = vb - W * length
    if grounded and va < 0.0:
        lb = length - vb / W
        x = lb + h / W * math.asinh(vb / h) + h * length / EA
        z = h / W * (math.hypot(1.0, vb / h) - 1.0) + vb**2 / (2.0 * W * EA)
        return x, z, 0.0, lb
    x = h / W * (math.asinh(vb / h) - math.asinh(va / h)) + h * length / EA
    z = (h / W * (math.hypot(1.0, vb / h) - math.hypot(1.0, va / h))
         + (vb**2 - va**2) / (2.0 * W * EA))
    return x, z, va, 0.0


def line_forces(length, ra, rb, guess, grounded):
    """End forces of a line between ra and rb (the catenary equations solved for h, vb by
    fsolve from guess): force on A, force on B (global), h, vb, va, grounded length."""
    from scipy.optimize import fsolve
    d = rb - ra
    xh = math.hypot(d[0], d[1])
    e = np.array([d[0] / xh, d[1] / xh, 0.0])

    def res(u):
        h, vb = math.exp(u[0]), u[1]
        x, z, _, _ = span(length, h, vb, grounded)
        return [(x - xh) / length, (z - d[2]) / length]
    u, _, ier, msg = fsolve(res, [math.log(guess[0]), guess[1]], xtol=1e-15, full_output=True)
    h, vb = math.exp(u[0]), u[1]
    _, _, va, lb = span(length, h, vb, grounded)
    fa = h * e + np.array([0.0, 0.0, va])
    fb = -h * e - np.array([0.0, 0.0, vb])
    return fa, fb, h, vb, va, lb


def independent(name, mp_state):
    """The case's free points' equilibrium from the catenary equations, started from
    MoorPy's solution. Returns positions, end tensions, residual and min clearances."""
    from scipy.optimize import fsolve
    case = CASES[name]
    pts = case_points(case)
    free = [p for p in pts if pts[p]["type"] == "FREE"]
    guesses = {ln: mp_state["HV"][ln] for ln, *_ in case["lines"]}

    def evaluate(x):
        r = {p: pts[p]["r"].copy() for p in pts}
        for k, p in enumerate(free):
            r[p] = np.array(x[3 * k:3 * k + 3])
        f = {p: np.zeros(3) for p in pts}
        out = {}
        for ln, length, a, b, _ in case["lines"]:
            grounded = abs(r[a][2] + DEPTH) < 1e-9
            fa, fb, h, vb, va, lb = line_forces(length, r[a], r[b], guesses[ln], grounded)
            guesses[ln] = (h, vb)
            f[a] += fa
            f[b] += fb
            out[ln] = (fa, fb, h, vb, va, lb)
        tot = []
        for p in free:
            own = np.array([0.0, 0.0, -pts[p]["mass"] * G + RHO * G * pts[p]["volume"]])
            own += np.array(case["loads"].get(p, (0.0, 0.0, 0.0)))
            tot.append(f[p] + own)
        return r, f, out, np.concatenate(tot)
    x0 = np.concatenate([mp_state["r"][p] for p in free])
    x = fsolve(lambda x: evaluate(x)[3] / 1e4, x0, xtol=1e-14, full_output=True)[0]
    r, f, out, resid = evaluate(x)
    tens = {}
    zmin = {}
    for ln, length, a, b, _ in case["lines"]:
        fa, fb, h, vb, va, lb = out[ln]
        tens[(ln, "A")] = float(np.linalg.norm(fa))
        tens[(ln, "B")] = float(np.linalg.norm(fb))
        # lowest point of a suspended line dipping below its end A: where V = 0
        if lb > 0.0:
            zmin[ln] = -DEPTH
        elif va >= 0.0:          # rising all along from A
            zmin[ln] = r[a][2]
        elif vb <= 0.0:          # falling all along to B
            zmin[ln] = r[b][2]
        else:
            zmin[ln] = r[a][2] + h / W * (1.0 - math.hypot(1.0, va / h)) - va**2 / (2 * W * EA)
    return dict(r=r, F=f, T=tens, residual=resid, zmin=zmin,
                lbot={ln: out[ln][5] for ln, *_ in case["lines"]})


def closed_form_chain():
    """chain_of_two by symmetry: the left line from the CONNECTOR (lower end, vertical force
    m g / 2) up to P1, 100 m of horizontal span: H from one equation (brentq)."""
    from scipy.optimize import brentq
    case = CASES["chain_of_two"]
    pts = case_points(case)
    length = case["lines"][0][1]
    half = 0.5 * (pts["P3"]["r"][0] - pts["P1"]["r"][0])
    va = 0.5 * pts["CONNECTOR"]["mass"] * G     # vertical tension at the connector end
    vb = va + W * length                        # at the top

    def xspan(h):
        return h / W * (math.asinh(vb / h) - math.asinh(va / h)) + h * length / EA - half
    h = brentq(xspan, 1.0, 1e8, xtol=1e-14, rtol=4 * np.finfo(float).eps, maxiter=500)
    rise = (h / W * (math.hypot(1.0, vb / h) - math.hypot(1.0, va / h))
            + (vb**2 - va**2) / (2.0 * W * EA))
    zc = pts["P1"]["r"][2] - rise
    return dict(H=h, x=pts["P1"]["r"][0] + half, z=zc, T_connector=math.hypot(h, va),
                T_top=math.hypot(h, vb), V_top=vb, V_connector=va)


# ------------------------------------------------------------- reference rows
def shortest_line(case, pname):
    return min(length for ln, length, a, b, _ in case["lines"] if pname in (a, b))


def grounded_anchor(case, pname, st):
    """A FIXED point where a line with a grounded part starts (its end A on the seabed)."""
    return case_points(case)[pname]["type"] == "FIXED" and any(
        a == pname and st["lbot"][ln] > 0.0 for ln, _, a, _, _ in case["lines"])


def reference_rows(name, st, source, compare=True):
    """Rows (case, quantity, value, unit, scale, tolerance, source) of one solution."""
    case = CASES[name]
    pts = case_points(case)
    rows = []
    for pname in pts:
        if pts[pname]["type"] == "FREE":
            scale = shortest_line(case, pname)
            for c, v in zip("xyz", st["r"][pname]):
                rows.append((name, f"{pname}.{c}", v, "m", scale, TOL if compare else None))
    if "F" in st:
        for pname in pts:
            fvec = st["F"][pname]
            scale = float(np.linalg.norm(fvec))
            for c, v in zip(("Fx", "Fy", "Fz"), fvec):
                tol = TOL if compare else None
                if c == "Fz" and grounded_anchor(case, pname, st):
                    tol = None   # see the docstring: the penalty bed's anchor force
                rows.append((name, f"{pname}.{c}", v, "N", scale, tol))
    for ln, *_ in case["lines"]:
        for end in "AB":
            t = st["T"][(ln, end)]
            rows.append((name, f"{ln}.{end}.tension", t, "N", t, TOL if compare else None))
    return [r + (source,) for r in rows]


def info_rows(name, st, source):
    """Reference-only rows: grounded lengths and lowest points of the lines."""
    rows = []
    for ln, *_ in CASES[name]["lines"]:
        rows.append((name, f"{ln}.grounded_length", st["lbot"][ln], "m", None, None, source))
        rows.append((name, f"{ln}.lowest_z", st["zmin"][ln], "m", None, None, source))
    return rows


def max_position_difference(name, a, b):
    """Largest |r_a - r_b| of the free points over their shortest line."""
    return max(float(np.linalg.norm(a["r"][p] - b["r"][p])) / shortest_line(CASES[name], p)
               for p in b["residual"])


def write(args):
    import scipy
    mpv = moorpy_version()
    src = f"moorpy-{mpv}"
    rows, notes = [], []
    worst_ind = 0.0
    for name in CASES:
        ms, ids = solve_moorpy(name, EQ_TOL)
        st = moorpy_state(ms, ids, name)
        # self-consistency: residual and a tighter solve
        tmax = max(st["T"].values())
        res = max((float(np.linalg.norm(v)) for v in st["residual"].values()), default=0.0)
        ms2, ids2 = solve_moorpy(name, EQ_TOL_CHECK)
        st2 = moorpy_state(ms2, ids2, name)
        d_tol = max(max(abs(st2["T"][k] / st["T"][k] - 1.0) for k in st["T"]),
                    max_position_difference(name, st2, st))
        ind = independent(name, st)
        d_ind_t = max(abs(ind["T"][k] / st["T"][k] - 1.0) for k in st["T"])
        d_ind_r = max_position_difference(name, ind, st)
        worst_ind = max(worst_ind, d_ind_t, d_ind_r)
        print(f"== {name}: MoorPy tol {EQ_TOL:g} m; free-point residual {res:.2e} N "
              f"({res / tmax:.1e} of the largest tension); tol {EQ_TOL_CHECK:g} m moves "
              f"positions and tensions by {d_tol:.1e}; independent catenary solution: "
              f"tensions {d_ind_t:.1e}, positions {d_ind_r:.1e} (residual "
              f"{float(np.max(np.abs(ind['residual']))):.1e} N)")
        notes.append(f"{name}: residual {res / tmax:.1e} of the largest tension; tol "
                     f"{EQ_TOL_CHECK:g} m changes results by {d_tol:.1e}; independent catenary "
                     f"solve differs by {max(d_ind_t, d_ind_r):.1e}")
        for ln, *_ in CASES[name]["lines"]:
            print(f"   {ln:8s} profile type {st['profile'][ln]}  grounded {st['lbot'][ln]:9.4f} "
                  f"m  lowest z {st['zmin'][ln]:9.4f} m (independent: grounded "
                  f"{ind['lbot'][ln]:9.4f} m, lowest {ind['zmin'][ln]:9.4f} m)")
        for p, r in st["r"].items():
            if p in st["residual"]:
                print(f"   {p} at ({r[0]:.9f}, {r[1]:.9f}, {r[2]:.9f}) m")
        for k, t in st["T"].items():
            print(f"   {k[0]}.{k[1]} tension {t:.6f} N")
        rows += reference_rows(name, st, src)
        rows += info_rows(name, st, src)
        rows += [r[:4] + (None, None, "independent_catenary") for r in
                 reference_rows(name, ind, "x", compare=False)
                 if not r[1].endswith(("Fx", "Fy", "Fz"))]
        if name == "crowfoot":
            ka, ks, kfd = moorpy_stiffness(ms, ids, "HUB")
            d_sys = float(np.max(np.abs(ks - ka)) / np.max(np.abs(ka)))
            d_fd = float(np.max(np.abs(kfd - ka)) / np.max(np.abs(ka)))
            print(f"   HUB stiffness [N/m], analytic (Point.getStiffnessA, lines only):\n"
                  f"{np.array2string(ka, precision=4)}\n   getSystemStiffnessA differs by "
                  f"{d_sys:.1e}, central difference (1e-3 m) by {d_fd:.1e} of the largest entry")
            notes.append(f"crowfoot HUB stiffness: Point.getStiffnessA (analytic); "
                         f"getSystemStiffnessA differs by {d_sys:.1e}, a central difference "
                         f"(+-1e-3 m) by {d_fd:.1e} of the largest entry")
            for i, a in enumerate("xyz"):
                for j, b in enumerate("xyz"):
                    rows.append((name, f"HUB.K_{a}{b}", ka[i, j], "N/m", None, None, src))
        if name == "chain_of_two":
            cf = closed_form_chain()
            cfr = [("CONNECTOR.x", cf["x"], "m"), ("CONNECTOR.y", 0.0, "m"),
                   ("CONNECTOR.z", cf["z"], "m"),
                   ("L1.A.tension", cf["T_top"], "N"), ("L1.B.tension", cf["T_connector"], "N"),
                   ("L2.A.tension", cf["T_connector"], "N"), ("L2.B.tension", cf["T_top"], "N"),
                   ("H", cf["H"], "N")]
            r = st["r"]["CONNECTOR"]
            d_z = abs(cf["z"] - r[2]) / 110.0
            d_t = max(abs(cf["T_top"] / st["T"][("L1", "A")] - 1.0),
                      abs(cf["T_connector"] / st["T"][("L1", "B")] - 1.0),
                      abs(cf["T_connector"] / st["T"][("L2", "A")] - 1.0),
                      abs(cf["T_top"] / st["T"][("L2", "B")] - 1.0))
            print(f"   closed form: H {cf['H']:.6f} N, connector z {cf['z']:.9f} m, tensions "
                  f"{cf['T_connector']:.6f} (connector), {cf['T_top']:.6f} N (top); MoorPy - "
                  f"closed form: z {r[2] - cf['z']:.2e} m ({d_z:.1e} of 110 m), tensions "
                  f"{d_t:.1e} relative")
            notes.append(f"chain_of_two: MoorPy against the closed form: connector z "
                         f"{r[2] - cf['z']:.2e} m, tensions {d_t:.1e} relative")
            rows += [(name, q, v, u, None, None, "closed_form") for q, v, u in cfr]
    facts = benchlib.machine_facts(args.rodyn)
    header = [f"bench/systems/moorpy_points.py: lines joined at points, MoorPy {mpv} statics "
              f"(solveEquilibrium tol {EQ_TOL:g} m, catenaries {0.01 * EQ_TOL:g} m), "
              f"scipy {scipy.__version__}, numpy {np.__version__}",
              f"g {G} m/s2, rho {RHO} kg/m3, depth {DEPTH} m, w {W!r} N/m, EA {EA:g} N",
              "compared by --quick: rows of source moorpy-* with a tolerance, |rodyn - value| / "
              "scale; other rows: reference only",
              f"command: {facts['command']}",
              f"commit (of the checkout the script ran from): "
              f"{facts['commit (of the checkout the script ran from)']}",
              f"date: {datetime.datetime.now().astimezone().strftime('%Y-%m-%d %H:%M %Z')}"]
    header += notes
    os.makedirs(os.path.dirname(RESULTS_CSV), exist_ok=True)
    with open(RESULTS_CSV, "w", newline="") as f:
        for h in header:
            f.write("# " + h + "\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "quantity", "value", "unit", "scale", "tolerance", "source"])
        for case, q, v, u, scale, tol, source in rows:
            w.writerow([case, q, repr(float(v)), u, "" if scale is None else repr(float(scale)),
                        "" if tol is None else f"{tol:g}", source])
    print("wrote", os.path.relpath(RESULTS_CSV, ROOT))
    os.makedirs(DECKS, exist_ok=True)
    for name in CASES:
        with open(deck_path(name), "w") as f:
            f.write(deck_text(name))
        print("wrote", os.path.relpath(deck_path(name), ROOT))
    if worst_ind > 1e-6:
        print(f"moorpy_points: MoorPy and the independent solution differ by {worst_ind:.1e} "
              "(> 1e-6)")
        return 1
    return 0


# ---------------------------------------------------------------------------- rodyn
def read_reference():
    rows = []
    with open(RESULTS_CSV) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            rows.append(r)
    return rows


def run_rodyn(rodyn, deck, out):
    p = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if p.returncode != 0:
        print(f"moorpy_points: rodyn {os.path.basename(deck)}: exit {p.returncode}: "
              f"{(p.stderr or p.stdout).strip()}")
        return False
    return True


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def end_tension_from_elements(rows, line, end, length):
    """Effective tension at end A or B of a line: the Lagrange polynomial through the Gauss
    points of its first or last element, evaluated at S = 0 or L."""
    mine = [r for r in rows if r["line"] == line]
    el = min if end == "A" else max
    k = el(int(r["element"]) for r in mine)
    pts = [(float(r["s_m"]), float(r["effective_tension_N"])) for r in mine
           if int(r["element"]) == k]
    s0 = 0.0 if end == "A" else length
    t = 0.0
    for i, (si, ti) in enumerate(pts):
        li = 1.0
        for j, (sj, _) in enumerate(pts):
            if j != i:
                li *= (s0 - sj) / (si - sj)
        t += li * ti
    return t


def rodyn_values(name, out):
    """rodyn's values under the reference's quantity names."""
    case = CASES[name]
    pts = case_points(case)
    vals = {}
    for r in read_csv(os.path.join(out, "static_points.csv")):
        p = r["point"]
        for c in "xyz":
            vals[f"{p}.{c}"] = float(r[f"{c}_m"])
        for c in ("Fx", "Fy", "Fz"):
            vals[f"{p}.{c}"] = float(r[f"{c}_N"])
    reac = {(r["line"], r["end"]): float(r["tension_N"])
            for r in read_csv(os.path.join(out, "static_reactions.csv"))}
    elems = read_csv(os.path.join(out, "static_elements.csv"))
    for ln, length, a, b, _ in case["lines"]:
        for end, p in (("A", a), ("B", b)):
            if pts[p]["type"] == "FIXED" and (ln, end) in reac:
                vals[f"{ln}.{end}.tension"] = reac[(ln, end)]
            else:
                vals[f"{ln}.{end}.tension"] = end_tension_from_elements(elems, ln, end, length)
    return vals


def compare(ref, values_by_case, title):
    """Print the table; True when every compared row is within its tolerance."""
    ok = True
    print(f"{title}\n{'case':13s} {'quantity':20s} {'MoorPy':>20s} {'rodyn':>20s} "
          f"{'diff/scale':>10s} {'tol':>7s}")
    for r in ref:
        if not r["source"].startswith("moorpy") or not r["scale"]:
            continue
        vals = values_by_case.get(r["case"])
        if vals is None:
            continue
        if not r["tolerance"]:     # reference only (the docstring says why)
            if r["quantity"] in vals:
                v, ref_v = vals[r["quantity"]], float(r["value"])
                print(f"{r['case']:13s} {r['quantity']:20s} {ref_v:20.9g} {v:20.9g} "
                      f"{abs(v - ref_v) / float(r['scale']):10.2e} {'-':>7s} not compared")
            continue
        if r["quantity"] not in vals:
            print(f"{r['case']:13s} {r['quantity']:20s} {float(r['value']):20.9g} "
                  f"{'(missing)':>20s}")
            ok = False
            continue
        v, ref_v = vals[r["quantity"]], float(r["value"])
        e = abs(v - ref_v) / float(r["scale"])
        tol = float(r["tolerance"])
        good = e <= tol
        ok &= good
        print(f"{r['case']:13s} {r['quantity']:20s} {ref_v:20.9g} {v:20.9g} {e:10.2e} "
              f"{tol:7.0e} {'ok' if good else 'MISSED'}")
    return ok


def quick(args):
    rodyn = benchlib.check_rodyn(args.rodyn)
    ref = read_reference()
    vals, failed = {}, False
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            deck = deck_path(name)
            with open(deck) as f:
                if f.read() != deck_text(name):
                    print(f"note: {os.path.relpath(deck, ROOT)} differs from what --write "
                          "writes (run as it is)")
            out = os.path.join(tmp, name)
            if run_rodyn(rodyn, deck, out):
                try:
                    vals[name] = rodyn_values(name, out)
                except (OSError, KeyError, ValueError) as e:
                    print(f"moorpy_points: {name}: rodyn's results unreadable: {e!r}")
                    failed = True
            else:
                failed = True
    ok = compare(ref, vals, f"rodyn ({rodyn}) against {os.path.relpath(RESULTS_CSV, ROOT)}")
    return 0 if ok and not failed else 1


def pinned_deck(name, ref):
    """Without points: the case's lines alone, each end PINNED where MoorPy puts its point."""
    case = CASES[name]
    pts = case_points(case)
    r = {p: pts[p]["r"].copy() for p in pts}
    for row in ref:
        if row["case"] == name and row["source"].startswith("moorpy"):
            p, _, c = row["quantity"].partition(".")
            if p in pts and c in ("x", "y", "z"):
                r[p]["xyz".index(c)] = float(row["value"])
    text = deck_text(name).split("** the points:")[0]
    for ln, length, a, b, ne in case["lines"]:
        text += (f"*LINE, NAME={ln}, SECTION=CHAIN, LENGTH={fmt(length)}, ELEMENTS={ne}, "
                 f"ORDER={ORDER}, ELEMENT=CABLE\n"
                 + ", ".join(repr(float(c)) for c in np.concatenate([r[a], r[b]])) + "\n"
                 f"*BOUNDARY, LINE={ln}, END=A, TYPE=PINNED\n"
                 f"*BOUNDARY, LINE={ln}, END=B, TYPE=PINNED\n")
    text += f"*STATIC, INCREMENTS={case['increments']}, MAX ITERATIONS=50\n"
    text += "*OUTPUT, CSV=YES, HDF5=NO\n"
    return text


def pinned(args):
    """Each case's lines alone between ends pinned at MoorPy's equilibrium: end tensions from
    the reactions and from the extrapolated element tensions, against MoorPy's."""
    rodyn = benchlib.check_rodyn(args.rodyn)
    ref = read_reference()
    vals, failed = {}, False
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            deck = os.path.join(tmp, name + ".inp")
            with open(deck, "w") as f:
                f.write(pinned_deck(name, ref))
            out = os.path.join(tmp, name)
            if not run_rodyn(rodyn, deck, out):
                failed = True
                continue
            reac = {(r["line"], r["end"]): float(r["tension_N"])
                    for r in read_csv(os.path.join(out, "static_reactions.csv"))}
            elems = read_csv(os.path.join(out, "static_elements.csv"))
            v = {}
            for ln, length, a, b, _ in CASES[name]["lines"]:
                for end in "AB":
                    v[f"{ln}.{end}.tension"] = reac[(ln, end)]
                    te = end_tension_from_elements(elems, ln, end, length)
                    print(f"{name:13s} {ln}.{end}: reaction {reac[(ln, end)]:.6f} N, elements "
                          f"extrapolated {te:.6f} N ({te / reac[(ln, end)] - 1.0:+.1e})")
            vals[name] = v
    ok = compare([r for r in ref if r["quantity"].endswith(".tension")], vals,
                 "rodyn's lines alone, ends pinned at MoorPy's equilibrium: end tensions")
    return 0 if ok and not failed else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--write", action="store_true",
                    help="solve with MoorPy, write bench/results/moorpy_points.csv and the decks")
    ap.add_argument("--quick", action="store_true",
                    help="rodyn on bench/systems/decks/*.inp against the stored MoorPy values")
    ap.add_argument("--pinned", action="store_true",
                    help="rodyn without *POINT: each case's lines alone, pinned at MoorPy's "
                         "equilibrium, end tensions against MoorPy's")
    args = ap.parse_args()
    if not (args.write or args.quick or args.pinned):
        ap.error("give --write, --quick or --pinned")
    status = 0
    if args.write:
        status |= write(args)
    if args.quick:
        status |= quick(args)
    if args.pinned:
        status |= pinned(args)
    sys.exit(status)


if __name__ == "__main__":
    main()
