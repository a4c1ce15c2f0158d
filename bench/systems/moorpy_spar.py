#!/usr/bin/env python3
"""rodyn and MoorPy on a floating body on three catenary legs: the OC3-Hywind spar.

The reference for rodyn's rigid bodies (*BODY): MoorPy 1.3.0 statics of the OC3-Hywind
spar on its three chains, written to bench/results/moorpy_spar.csv, and the decks
bench/systems/decks/spar_*.inp (docs/deck.md, *BODY).

Source: J. Jonkman, "Definition of the Floating System for Phase IV of OC3",
NREL/TP-500-47535, May 2010 (below: the report). Its numbers used here, from memory of
the report, checked against public copies of them where the code index had one (noted
[c]); Eq. (4-3), Table 5-1 and Eq. (5-3) are the report's numbering as its author cites it
(NREL forum, forums.nrel.gov/t/604), Table 3-1 is remembered:
  Table 3-1 (floating platform structural properties): draft 120 m; taper from 4 m to
    12 m below SWL; diameter 6.5 m above the taper, 9.4 m below it; platform mass
    including ballast 7,466,330 kg [c]; its CM 89.9155 m below SWL on the centreline [c];
    roll and pitch inertia about the CM 4,229,230,000 kg m2, yaw inertia about the
    centreline 164,230,000 kg m2 [c].
  Section 4 (hydrodynamics): displaced volume V0 = 8,029.21 m3 (rho g V0 = 80,708,100 N
    with the report's g = 9.80665) [c]; its linear hydrostatic restoring, Eq. (4-3):
    C33 = 332,941 N/m, C44 = C55 = -4,999,180,000 N m/rad [c] (from WAMIT's panel model,
    without the body's weight).
  Table 5-1 (mooring system properties): 3 lines 120 deg apart; water depth 320 m;
    fairleads 70.0 m below SWL at radius 5.2 m; anchors at radius 853.87 m; unstretched
    length 902.2 m; diameter 0.09 m; mass 77.7066 kg/m; weight in water 698.094 N/m
    (with g = 9.80665); EA 384,243,000 N [c]; an additional yaw spring of 98,340,000
    N m/rad.
  Eq. (5-3): the mooring system's linearised restoring about the undisplaced position,
    K11 = K22 = 41,180 N/m, K15 = -2,821,000 N/rad, K24 = 2,821,000 N/rad,
    K51 = -2,816,000 N, K42 = 2,816,000 N, K33 = 11,940 N/m, K44 = K55 = 311,100,000 N m/rad,
    K66 = 11,560,000 N m/rad, and the lines' vertical pretension load on the platform
    F0z = -1,607,000 N [c: the OC3-Hywind values in the comments of FAST's UserLine
    template]. (K15 and K51 differ in the report's fourth digit; MoorPy's are equal.)
Headings. The report gives the lines' spacing (120 deg), the OC3 FAST model of its author
puts line 1 along +x (downwind) and the others at 120 and 240 deg (Jonkman, NREL forum,
"Mooring lines parameters", forums.nrel.gov/t/339: "anchor and fairlead angles of 0 deg,
120 deg, and 240 deg ... one line is directed nominally downwind"). That layout is used
here: heading h of line k = 0, 120, 240 deg, measured from +x towards +y. (180, 60, 300
deg is the OC4-DeepCwind semi's layout, line 1 upwind; it is the mirror image x -> -x of
this one, so its answer to +1 MN along x is this layout's answer to -1 MN.)
Left out, as in the brief: the delta connection (crowfoot) of the real OC3 lines and the
additional yaw spring; each line runs straight from its anchor to its fairlead.

Values used (z up, still water level z = 0, flat frictionless seabed z = -320 m):
  g = 9.81 m/s2 (MoorPy's default, not the report's 9.80665), rho = 1025 kg/m3.
  Line: 902.2 m, d_vol = 0.09 m (MoorPy's volume-equivalent diameter; rodyn OD), 77.7066
    kg/m, EA 384.243e6 N; w = (m - rho pi d^2/4) g = 698.333 N/m (698.094 at the report's g).
  Anchor k at (853.87 cos h, 853.87 sin h, -320), fairlead k at (5.2 cos h, 5.2 sin h, -70)
    in body axes from the reference point, the point of the centreline on the SWL.
  Body reference point R at (0, 0, 0) undisplaced. Mass m = 7,466,330 kg at
    G = (0, 0, -89.9155). Volume V = 8029.21 m3 at B = (0, 0, zB) with zB = -62.065655 m,
    the centroid of the report's geometry (6.5 m cylinder 0-4 m, frustum 4-12 m, 9.4 m
    cylinder 12-120 m below SWL; it gives V = 8029.2092 m3, the report's V0), not 62.0 m.
    (The report's C44 of Eq. (4-3) implies a centroid 61.95 m deep, its C33 a waterplane
    0.18 % smaller than a 6.5 m circle: WAMIT's panels; the geometry is used here.)
    Waterplane: a circle of 6.5 m, A_wp = pi D^2/4 = 33.183072 m2, I_wp = pi D^4/64 =
    87.624051 m4; rho g A_wp = 333,664.09 N/m, rho g I_wp = 881,081.73 N m/rad.
  Inertias (decks only; statics does not use them): the report's platform values.

Cases (bench/systems/decks/spar_<case>.inp):
  fixed          the body FIXED at its undisplaced position: the lines' force and moment on
                 it, their 6x6 stiffness, the end tensions. A lines-only check too: each
                 line's tensions and horizontal tension against the single-line catenary.
  mean           the body FREE (6 DOF) with its hydrostatics, no external load.
  offset         the same with a steady 1 MN along +x at the reference point (MoorPy f6Ext).
  mean_system,   NOT in the brief, added because of what `mean` shows: the platform alone
  offset_system  (7,466,330 kg) is 5.9 MN lighter than its buoyancy less the lines' pull,
                 so `mean` floats 17.0 m up. The report's V0 balances the whole system:
                 platform + tower (249,718 kg, CM 43.4 m above SWL) + nacelle (240,000 kg,
                 taken 1.75 m above the 87.6 m tower top) + rotor (110,000 kg at the 90 m
                 hub height) = 8,066,048 kg with its CM at z = -78.0 m, lumped on the
                 centreline (the rotor's overhang and the nacelle's offset, which would
                 put the CM 1.2 cm upwind, are left out). With it the mean heave is 0.2 mm.
                 Same V, B, waterplane and inertias (the platform's) as the other cases.

MoorPy's model and conventions (MoorPy 1.3.0, moorpy/body.py, helpers.py, system.py):
  Body DOFs r6 = (x, y, z, roll, pitch, yaw) of its reference point [m, rad]. Orientation
    R = rotationMatrix(roll, pitch, yaw) = Rz(yaw) Ry(pitch) Rx(roll): Tait-Bryan angles,
    intrinsic z-y'-x'' (= extrinsic x-y-z: roll about global x, then pitch about global
    y, then yaw about global z). A body point at r_rel (body axes) is at x + R r_rel.
  Forces: global axes; moments about the body's (displaced) reference point, global axes:
    Body.getForces(lines_only=True) = sum over its points of (f, (R r_rel) x f), f the
    force of the lines on the point. f6Ext: a force and moment in global axes at the
    reference point, fixed in direction.
  Stiffness: Body.getStiffnessA(lines_only=True) = -d(getForces)/d(r6), analytic, from the
    points' 3x3 catenary stiffness K3 (other points held): K_tt = sum K3, K_tr = sum K3 H,
    K_rt = K_tr^T, K_rr = sum [(f.r) I - r f^T - H K3 H], H = getH(r) = -skew(r), r = R
    r_rel. Its rotational columns are derivatives with respect to the Euler angles; at
    zero rotation a single angle IS a rotation vector (R = exp(a skew(e_i))), so the
    matrix equals rodyn's K = -dF/dq with q = (x, rotation vector), exactly, and a
    central difference of single-angle steps tests both. K_tr and K_rt are each other's
    transposes by construction; K_rr has the non-symmetric term - r f^T, whose sum is
    symmetric here by the layout's 120 deg symmetry (at the undisplaced position; not at
    the offset equilibrium). Checked against a central difference of getForces
    (+-1e-3 m, +-1e-5 rad, catenaries solved to 1e-12 m) and an independent catenary.
  Hydrostatics (Body.getForces, lines_only=False): weight -m g e_z at R rCG; buoyancy
    +rho g v e_z at R rM, rM the METACENTRE (MoorPy's buoyancy is not applied at B: the
    waterplane's roll/pitch restoring is folded into the point the buoyancy acts at);
    heave restoring -rho g AWP z (the reference point's z; no other waterplane term,
    no change of the volume). Both forces stay vertical while their points turn with
    the body. Here rM = (0, 0, zB + I_wp / V) = (0, 0, -62.054742), AWP = A_wp. Its
    hydrostatic stiffness at zero offset (getStiffnessA(False) - getStiffnessA(True)) is
    diag(0, 0, rho g A_wp, -m g zG + rho g V zM, the same, 0) = diag(0, 0, 333664.09,
    1.575800e9, 1.575800e9, 0) for the platform alone (printed by --write and stored).
  rodyn's model (the decks): weight m g at G and buoyancy rho g V at B, vertical forces at
    points turning with the body, plus -C q with the deck's *BODY HYDROSTATICS C = diag(0,
    0, rho g A_wp, rho g I_wp, rho g I_wp, 0) about the reference point. At zero offset its
    6x6 (gravity + buoyancy + C) equals MoorPy's entry by entry: the only difference is
    that MoorPy turns rho g I_wp with the body (the moment rho g V (zM - zB) sin(theta))
    where rodyn keeps it linear (rho g I_wp theta): a moment rho g I_wp (theta -
    sin(theta)), 9 N m at the offset's pitch, a pitch difference of 5e-9 rad. At the
    offset equilibrium (pitch 0.0397 rad) the two 6x6s (incremental rotations about the
    global axes) differ by 696 N m/rad in K55 (rho g I_wp (1 - cos theta)), 580 in K44 and
    1.75e4 in K46 (rho g I_wp theta / 2: rodyn's C multiplies the rotation vector, which
    an incremental rotation changes through its Jacobian), 1.1e-5 of K44 at most. The
    independent solution below uses rodyn's model and shows the difference.
  MoorPy's analytic stiffness away from zero rotation (stored for the free cases, reference
    only) is with respect to incremental rotations about the global axes (R -> exp(d phi)
    R), neither the Euler angles nor the rotation vector's components.
  Lines: quasi-static elastic catenaries (Jonkman's, as in moorpy_points.py), frictionless
    rigid seabed (cb = 0), anchors on the bed. Equilibrium: System.solveEquilibrium, Newton
    with the analytic stiffness, stops when every step component is below tol [m] (tol /
    70.19 rad for the rotations); catenaries solved to 0.01 tol. Here tol = 1e-8 m;
    checked by a solve at 1e-10 m and by the residual force and moment.

Independent check (no MoorPy, scipy only): each line's end forces from the elastic
catenary equations with a grounded part on the frictionless bed (fsolve), the body's six
equations with rodyn's hydrostatic model (rotation vector, buoyancy at B, linear C) by an
outer fsolve from MoorPy's solution; the fixed body's lines stiffness by a central
difference of that solution (rotation vector steps).

Compared by --quick (|rodyn - MoorPy| / scale within the tolerance; dict TOL):
  body position x, y, z over the line length 902.2 m, 1e-5 (9 mm); rotation vector rx, ry,
  rz over 1 rad, 1e-5 (a relative tension error of 1e-5 moves the offset's pitch by about
  5e-7 rad and its surge by 0.4 mm); the lines' force on the body over its |F|, its moment
  over |F| times 70.19 m (the fairleads' distance from R), 1e-4; end tensions relative,
  1e-4 (static_reactions.csv tension_N); the fixed body's stiffness K_ij over
  sqrt(K_ii K_jj), 1e-4 (see Mesh below). Stored for reference only: Euler angles,
  horizontal tensions, grounded lengths, fairlead positions, the lines' stiffness at the
  free cases' equilibria, the hydrostatic 6x6, MoorPy's central difference, the
  independent solution and the report's Eq. (5-3).

Mesh: 480 cubic cable elements a line (1.88 m), for the stiffness.
Measured with --pinned (rodyn without bodies: the lines alone, ends pinned where MoorPy puts the
anchors and fairleads; the fixed body's 6x6 by central differences of rodyn's reactions,
+-1 cm, +-1e-4 rad), against MoorPy, max |dK_ij| / sqrt(K_ii K_jj): 1.3e-3 with 100
elements a line, 3.4e-4 (150), 4.1e-4 (200), 2.4e-4 (240), 1.0e-4 (300), 2.7e-5 (400),
1.5e-6 (600), largest in K33 and K11: the touchdown's resolution on the penalty bed (with
a ten times stiffer bed, 3e8 Pa/m: 2.7e-3 at 100, 3.8e-4 at 400). The end tensions are
within 6e-6 of MoorPy's already with 100 elements (suspended lines 1e-11). With the
body (spar_fixed.inp, static_stiffness.csv's lines_stiffness): 2.6e-4 at 240 elements,
1.3e-5 at 480, 1.5e-6 at 720.

  python3 bench/systems/moorpy_spar.py --write        # MoorPy + checks -> results, decks
  python3 bench/systems/moorpy_spar.py --quick [--rodyn build/rodyn]
                                     # rodyn on the decks against the stored values
  python3 bench/systems/moorpy_spar.py --pinned [--rodyn build/rodyn]
                                     # without *BODY: each case's lines alone,
                                     # ends PINNED where MoorPy puts the anchors and
                                     # fairleads: end tensions against MoorPy's, and the
                                     # fixed body's 6x6 from rodyn's reactions
Exit 1 if a tolerance is missed or rodyn refuses a deck (it does until *BODY exists).
Install MoorPy: python3 -m pip install moorpy==1.3.0; --quick and --pinned need only numpy.
"""
import argparse
import csv
import datetime
import math
import os
import subprocess
import sys
import tempfile
import warnings

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import benchlib  # noqa: E402

RESULTS_CSV = os.path.join(ROOT, "bench", "results", "moorpy_spar.csv")
DECKS = os.path.join(HERE, "decks")
SEABED = "*SEABED, STIFFNESS=3.0e7"   # ten times rodyn's default: the chain sinks 0.26 mm

# ---- environment (MoorPy's defaults; the report uses g = 9.80665)
G = 9.81
G_REPORT = 9.80665
RHO = 1025.0
DEPTH = 320.0                 # Table 5-1
# ---- lines (Table 5-1)
LENGTH = 902.2
DIAM = 0.09                   # volume-equivalent diameter
MASS_LINE = 77.7066
EA = 384.243e6
R_ANCHOR = 853.87
R_FAIRLEAD = 5.2
Z_FAIRLEAD = -70.0            # body axes from the reference point (on the SWL)
HEADINGS = (0.0, 120.0, 240.0)   # deg; line 1 downwind along +x (see the docstring)
ELEMENTS = 480                # cubic cable elements a line (the brief's 100: see the
                              # docstring, the stiffness needs more)
ORDER = 3
# ---- platform (Table 3-1, Section 4)
MASS_PLATFORM = 7466330.0
ZG_PLATFORM = -89.9155
INERTIA = (4229230000.0, 4229230000.0, 164230000.0)   # about G, body axes
VOLUME = 8029.21
D_WATERPLANE = 6.5
# ---- turbine, lumped on the centreline (the *_system cases)
TURBINE = ((249718.0, 43.4),      # tower mass [kg], CM above SWL [m]
           (240000.0, 87.6 + 1.75),  # nacelle
           (110000.0, 90.0))      # rotor, at the hub height
LOAD_X = 1.0e6                # N, the offset cases' steady force along +x


def frustum(h, r_top, r_bottom):
    """Volume and centroid depth below its top of a frustum of height h."""
    a = r_top**2 + r_top * r_bottom + r_bottom**2
    return (math.pi * h / 3.0 * a,
            h * (r_top**2 + 2.0 * r_top * r_bottom + 3.0 * r_bottom**2) / (4.0 * a))


def hull_centroid():
    """Volume and centroid z of the report's hull below the SWL."""
    v1, z1 = math.pi / 4.0 * 6.5**2 * 4.0, -2.0
    v2, c2 = frustum(8.0, 3.25, 4.7)
    z2 = -(4.0 + c2)
    v3, z3 = math.pi / 4.0 * 9.4**2 * 108.0, -66.0
    v = v1 + v2 + v3
    return v, (v1 * z1 + v2 * z2 + v3 * z3) / v


V_GEOMETRY, ZB = hull_centroid()
A_WP = math.pi / 4.0 * D_WATERPLANE**2
I_WP = math.pi * D_WATERPLANE**4 / 64.0
W = (MASS_LINE - RHO * math.pi / 4.0 * DIAM**2) * G      # N/m submerged weight
R_FAIR_DIST = math.hypot(R_FAIRLEAD, Z_FAIRLEAD)         # fairlead's distance from R


def system_mass():
    """Platform + tower + nacelle + rotor on the centreline: mass and CM z."""
    m = MASS_PLATFORM + sum(t[0] for t in TURBINE)
    z = (MASS_PLATFORM * ZG_PLATFORM + sum(t[0] * t[1] for t in TURBINE)) / m
    return m, z


M_SYSTEM, ZG_SYSTEM = system_mass()

CASES = {
    "fixed": dict(title="OC3-Hywind spar held at its undisplaced position: the lines' "
                        "stiffness", type="FIXED", mass=MASS_PLATFORM, zg=ZG_PLATFORM,
                  load=None),
    "mean": dict(title="OC3-Hywind spar (platform alone) free on its three lines",
                 type="FREE", mass=MASS_PLATFORM, zg=ZG_PLATFORM, load=None),
    "offset": dict(title="OC3-Hywind spar (platform alone) free, 1 MN along +x",
                   type="FREE", mass=MASS_PLATFORM, zg=ZG_PLATFORM,
                   load=(LOAD_X, 0.0, 0.0, 0.0, 0.0, 0.0)),
    "mean_system": dict(title="OC3-Hywind spar with the turbine's mass lumped on its axis, "
                              "free on its three lines", type="FREE", mass=M_SYSTEM,
                        zg=ZG_SYSTEM, load=None),
    "offset_system": dict(title="OC3-Hywind spar with the turbine's mass lumped on its "
                                "axis, free, 1 MN along +x", type="FREE", mass=M_SYSTEM,
                          zg=ZG_SYSTEM, load=(LOAD_X, 0.0, 0.0, 0.0, 0.0, 0.0)),
}
BODY = "SPAR"
LINES = [f"L{k + 1}" for k in range(len(HEADINGS))]
DOF = ("x", "y", "z", "rx", "ry", "rz")

# Tolerances of the compared quantities (|rodyn - MoorPy| / scale), see the docstring
TOL = dict(position=1e-5, rotation=1e-5, force=1e-4, tension=1e-4, stiffness=1e-4)

EQ_TOL = 1e-8         # m, MoorPy solveEquilibrium tol (catenaries 0.01 tol)
EQ_TOL_CHECK = 1e-10
FD_DX, FD_DTH = 1e-3, 1e-5     # central-difference steps [m], [rad]

# The report's Eq. (5-3) and F0z (g = 9.80665), 0-based (row, column): value
REPORT_K = {(0, 0): 41180.0, (1, 1): 41180.0, (0, 4): -2821000.0, (1, 3): 2821000.0,
            (4, 0): -2816000.0, (3, 1): 2816000.0, (2, 2): 11940.0, (3, 3): 311100000.0,
            (4, 4): 311100000.0, (5, 5): 11560000.0}
REPORT_F0Z = -1607000.0


def fmt(v):
    """A deck number: the shortest text that reads back to the same double."""
    return repr(float(v))


def anchor(k):
    """Anchor k, global [m], rounded to 1e-9 m (the decks and MoorPy use these numbers)."""
    h = math.radians(HEADINGS[k])
    return np.round([R_ANCHOR * math.cos(h), R_ANCHOR * math.sin(h), -DEPTH], 9) + 0.0


def fairlead_rel(k):
    """Fairlead k in body axes from the reference point [m], rounded to 1e-9 m."""
    h = math.radians(HEADINGS[k])
    return np.round([R_FAIRLEAD * math.cos(h), R_FAIRLEAD * math.sin(h), Z_FAIRLEAD], 9) + 0.0


def hydrostatic_matrix(g=G):
    """rodyn's *BODY HYDROSTATICS: the waterplane's linear restoring about R."""
    c = np.zeros((6, 6))
    c[2, 2] = RHO * g * A_WP
    c[3, 3] = c[4, 4] = RHO * g * I_WP
    return c


def rotvec_matrix(v):
    """Rotation matrix of a rotation vector (Rodrigues)."""
    v = np.asarray(v, float)
    t = float(np.linalg.norm(v))
    k = np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
    if t < 1e-12:
        return np.eye(3) + k
    return np.eye(3) + math.sin(t) / t * k + (1.0 - math.cos(t)) / t**2 * (k @ k)


def matrix_rotvec(r):
    """Rotation vector of a rotation matrix (angle below pi)."""
    c = max(-1.0, min(1.0, (np.trace(r) - 1.0) / 2.0))
    t = math.acos(c)
    w = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]) / 2.0
    if t < 1e-12:
        return w
    return w * t / math.sin(t)


def perturbed(q, j, h):
    """q moved by h along DOF j; a rotation DOF turns the body by h about the global axis
    j - 3 (an incremental rotation on top of R(q), MoorPy's analytic stiffness's)."""
    q = np.array(q, float)
    if j < 3:
        q[j] += h
        return q
    dphi = np.zeros(3)
    dphi[j - 3] = h
    q[3:] = matrix_rotvec(rotvec_matrix(dphi) @ rotvec_matrix(q[3:]))
    return q


def euler_matrix(roll, pitch, yaw):
    """MoorPy's rotationMatrix(roll, pitch, yaw) = Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    rz = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return rz @ ry @ rx


# ---------------------------------------------------------------------------- decks
def deck_text(name):
    """The rodyn deck of a case (docs/deck.md, *BODY)."""
    case = CASES[name]
    out = [f"** bench/systems/decks/spar_{name}.inp, the MoorPy cross-check of a floating body",
           "** on three catenary legs (the OC3-Hywind spar, Jonkman 2010, NREL/TP-500-47535):",
           "** written by bench/systems/moorpy_spar.py --write, which also compares rodyn's",
           "** statics with bench/results/moorpy_spar.csv (--quick).",
           "** (docs/deck.md: *BODY, *BODY HYDROSTATICS, *POINT TYPE=BODY, *LOAD BODY=)",
           "*HEADING",
           f"{case['title']} (MoorPy cross-check)",
           "** MoorPy's g (the report's is 9.80665) and the report's water density",
           "*GRAVITY",
           f"0.0, 0.0, -{fmt(G)}",
           "** still water level z = 0, flat frictionless seabed at z = -320 m; penalty contact",
           "** ten times the default stiffness: the grounded chain sinks w/(k OD) = 0.26 mm",
           "** (MoorPy's seabed is rigid)",
           f"*WATER, DEPTH={fmt(DEPTH)}, DENSITY={fmt(RHO)}",
           SEABED,
           "** the OC3 chain (the report's Table 5-1): 77.7066 kg/m, OD = volume-equivalent",
           f"** diameter 0.09 m (buoyancy), EA 384.243e6 N, no bending; w = {W:.6f} N/m",
           "** EA [N], EI1 [N m2], EI2 [N m2], GJ [N m2/rad], mass [kg/m]",
           f"*SECTION, NAME=CHAIN, OD={fmt(DIAM)}, CDN=1.2, CDA=0.05, CAN=1.0, CAA=0.0",
           f"{fmt(EA)}, 0.0, 0.0, 0.0, {fmt(MASS_LINE)}"]
    if case["type"] == "FIXED":
        out += ["** the body, held (TYPE=FIXED) at its undisplaced position: rodyn writes the",
                "** force, moment and 6x6 stiffness of the lines on it; its mass and volume do",
                "** not act"]
    else:
        out += ["** the body, free in 6 DOF: weight MASS g at G and buoyancy rho g VOLUME at B,",
                "** vertical forces at points turning with the body"]
    if name.endswith("_system"):
        out += ["** MASS: platform + tower + nacelle + rotor lumped on the centreline, G their",
                "** CM (not the brief's platform alone, which floats 17 m up: see the script);",
                "** the inertias are the platform's (statics does not use them)"]
    out += ["** data: reference point R (global, at the start); G, B (body axes from R);",
            "** inertia about G (body axes) [kg m2]. R on the centreline at the SWL; B the",
            "** centroid of the report's hull geometry (V0 = 8029.21 m3)",
            f"*BODY, NAME={BODY}, TYPE={case['type']}, MASS={fmt(case['mass'])}, "
            f"VOLUME={fmt(VOLUME)}",
            "0.0, 0.0, 0.0",
            f"0.0, 0.0, {fmt(case['zg'])}",
            f"0.0, 0.0, {fmt(ZB)}",
            ", ".join(fmt(i) for i in INERTIA)]
    if case["type"] == "FREE":
        c = hydrostatic_matrix()
        out += ["** the waterplane's linear restoring about R, -C q (q: R's displacement and the",
                "** body's small rotation vector): a 6.5 m circle, C33 = rho g A_wp,",
                "** C44 = C55 = rho g I_wp (I_wp = pi D^4/64); 6 lines of 6",
                f"*BODY HYDROSTATICS, BODY={BODY}"]
        out += [", ".join(fmt(v) for v in row) for row in c]
    out.append("** fairleads on the body (body axes from R) and anchors on the seabed; headings")
    out.append("** 0, 120, 240 deg from +x (line 1 downwind, the report's FAST model)")
    for k, ln in enumerate(LINES):
        out.append(f"*POINT, NAME=F{k + 1}, TYPE=BODY, BODY={BODY}")
        out.append(", ".join(fmt(c) for c in fairlead_rel(k)))
        out.append(f"*POINT, NAME=A{k + 1}, TYPE=FIXED")
        out.append(", ".join(fmt(c) for c in anchor(k)))
    out.append("** cubic cable elements from the anchor (end A) to the fairlead (end B)")
    for k, ln in enumerate(LINES):
        out.append(f"*LINE, NAME={ln}, SECTION=CHAIN, LENGTH={fmt(LENGTH)}, "
                   f"ELEMENTS={ELEMENTS}, ORDER={ORDER}, ELEMENT=CABLE, POINT A=A{k + 1}, "
                   f"POINT B=F{k + 1}")
    if case["load"] is not None:
        out.append("** a steady force and moment on the body at R, global axes, fixed in")
        out.append("** direction [N, N m] (MoorPy: the body's f6Ext)")
        out.append(f"*LOAD, BODY={BODY}")
        out.append(", ".join(fmt(v) for v in case["load"]))
    out.append("*STATIC, INCREMENTS=20, MAX ITERATIONS=50")
    out.append("*OUTPUT, CSV=YES, HDF5=NO")
    return "\n".join(out) + "\n"


def deck_path(name):
    return os.path.join(DECKS, f"spar_{name}.inp")


# ---------------------------------------------------------------------------- MoorPy
def moorpy_version():
    try:
        from importlib.metadata import version
        return version("moorpy")
    except Exception:  # noqa: BLE001
        return "unknown"


def build_moorpy(name, g=G):
    """MoorPy's system of a case: the body (number 1), its fairleads, anchors, lines."""
    import moorpy as mp
    case = CASES[name]
    ms = mp.System(depth=DEPTH, rho=RHO, g=g)
    ms.setLineType(name="chain", lineType=dict(m=MASS_LINE, d_vol=DIAM, EA=EA))
    load = np.zeros(6) if case["load"] is None else np.array(case["load"], float)
    body = ms.addBody(1 if case["type"] == "FIXED" else 0, np.zeros(6), m=case["mass"],
                      v=VOLUME, rCG=np.array([0.0, 0.0, case["zg"]]), AWP=A_WP,
                      rM=np.array([0.0, 0.0, ZB + I_WP / VOLUME]), f6Ext=load)
    for k in range(len(LINES)):
        ms.addPoint(1, list(anchor(k)))
        ms.addPoint(1, list(fairlead_rel(k)), body=1)      # fixed on the body
        ms.addLine(LENGTH, "chain", nSegs=200, pointA=2 * k + 1, pointB=2 * k + 2)
    ms.initialize()
    return ms, body


def solve_moorpy(name, tol, g=G):
    ms, body = build_moorpy(name, g)
    if CASES[name]["type"] == "FIXED":
        body.setPosition(np.zeros(6))
    else:
        ms.solveEquilibrium(tol=tol, maxIter=1000)
    for line in ms.lineList:                 # the final state, with the profiles
        line.staticSolve(tol=0.01 * tol, profiles=1)
    return ms, body


def moorpy_state(ms, body):
    """Position, rotation vector, lines' force on the body, end tensions of a solution."""
    r6 = np.array(body.r6, float)
    st = {"r6": r6, "q": np.concatenate([r6[:3], matrix_rotvec(euler_matrix(*r6[3:]))]),
          "F": np.array(body.getForces(lines_only=True, all_DOFs=True), float),
          "residual": np.array(body.getForces(all_DOFs=True), float),
          "T": {}, "H": {}, "VB": {}, "lbot": {}, "fair": {}}
    for k, ln in enumerate(LINES):
        line = ms.lineList[k]
        st["T"][(ln, "A")] = float(line.TA)
        st["T"][(ln, "B")] = float(line.TB)
        st["H"][ln] = float(line.HF)
        st["VB"][ln] = float(line.VF)
        st["lbot"][ln] = float(line.LBot)
        st["fair"][ln] = np.array(ms.pointList[2 * k + 1].r, float)
    return st


def solve_lines(ms, tol=1e-12):
    for line in ms.lineList:
        line.staticSolve(tol=tol)


def moorpy_stiffness(ms, body):
    """Lines-only 6x6 at the body's position: analytic, and MoorPy's forces differenced."""
    ka = np.array(body.getStiffnessA(lines_only=True, all_DOFs=True), float)
    r0 = np.array(body.r6, float)
    kfd = np.zeros((6, 6))
    for j in range(6):
        h = FD_DX if j < 3 else FD_DTH
        f = []
        for sgn in (1.0, -1.0):
            r = r0.copy()
            r[j] += sgn * h
            body.setPosition(r)
            solve_lines(ms)
            f.append(np.array(body.getForces(lines_only=True, all_DOFs=True), float))
        kfd[:, j] = -(f[0] - f[1]) / (2.0 * h)
    body.setPosition(r0)
    solve_lines(ms)
    return ka, kfd


def moorpy_hydrostatics(ms, body):
    """MoorPy's own (weight, buoyancy, waterplane) 6x6 at the body's position."""
    return (np.array(body.getStiffnessA(lines_only=False, all_DOFs=True), float)
            - np.array(body.getStiffnessA(lines_only=True, all_DOFs=True), float))


def relative_matrix_difference(a, b):
    """max |a_ij - b_ij| / sqrt(|b_ii b_jj|) over the entries (diagonal scale)."""
    d = np.sqrt(np.abs(np.outer(np.diag(b), np.diag(b))))
    return float(np.max(np.abs(a - b) / d))


# ------------------------------------------------------------- independent catenary
def span(h, vb, grounded):
    """Offset (horizontal along the line, z up) of end B from end A of the elastic catenary
    whose tension at B has horizontal part h > 0 and vertical part vb; grounded: A on the
    frictionless rigid bed, a part lies on it when vb < w L. Returns x, z, va, lying."""
    va = vb - W * LENGTH
    if grounded and va < 0.0:
        lb = LENGTH - vb / W
        x = lb + h / W * math.asinh(vb / h) + h * LENGTH / EA
        z = h / W * (math.hypot(1.0, vb / h) - 1.0) + vb**2 / (2.0 * W * EA)
        return x, z, 0.0, lb
    x = h / W * (math.asinh(vb / h) - math.asinh(va / h)) + h * LENGTH / EA
    z = (h / W * (math.hypot(1.0, vb / h) - math.hypot(1.0, va / h))
         + (vb**2 - va**2) / (2.0 * W * EA))
    return x, z, va, 0.0


def line_forces(ra, rb, guess):
    """End forces of a line between the anchor ra and rb: force on A, force on B (global),
    h, vb, va, grounded length (the catenary equations by fsolve from guess)."""
    from scipy.optimize import fsolve
    d = rb - ra
    xh = math.hypot(d[0], d[1])
    e = np.array([d[0] / xh, d[1] / xh, 0.0])
    grounded = abs(ra[2] + DEPTH) < 1e-9

    def res(u):
        x, z, _, _ = span(math.exp(u[0]), u[1], grounded)
        return [(x - xh) / LENGTH, (z - d[2]) / LENGTH]
    u = fsolve(res, [math.log(guess[0]), guess[1]], xtol=1e-15, full_output=True)[0]
    h, vb = math.exp(u[0]), u[1]
    _, _, va, lb = span(h, vb, grounded)
    return (h * e + np.array([0.0, 0.0, va]), -h * e - np.array([0.0, 0.0, vb]),
            h, vb, va, lb)


class Independent:
    """The spar's statics with rodyn's model, lines from the catenary equations."""

    def __init__(self, name, guesses):
        self.case = CASES[name]
        self.guess = dict(guesses)            # line -> (h, vb)

    def lines(self, q):
        """Lines' force and moment (about R, global) on the body at q, and per line data."""
        rot = rotvec_matrix(q[3:])
        f6 = np.zeros(6)
        out = {}
        for k, ln in enumerate(LINES):
            arm = rot @ fairlead_rel(k)
            fa, fb, h, vb, va, lb = line_forces(anchor(k), q[:3] + arm, self.guess[ln])
            self.guess[ln] = (h, vb)
            f6[:3] += fb
            f6[3:] += np.cross(arm, fb)
            out[ln] = (fa, fb, h, vb, va, lb, q[:3] + arm)
        return f6, out

    def own(self, q):
        """Weight at G, buoyancy at B (vertical, points turning), -C q, the load."""
        rot = rotvec_matrix(q[3:])
        f6 = np.zeros(6)
        for rel, fz in (((0.0, 0.0, self.case["zg"]), -self.case["mass"] * G),
                        ((0.0, 0.0, ZB), RHO * G * VOLUME)):
            f = np.array([0.0, 0.0, fz])
            f6[:3] += f
            f6[3:] += np.cross(rot @ np.array(rel), f)
        f6 -= hydrostatic_matrix() @ q
        if self.case["load"] is not None:
            f6 += np.array(self.case["load"])
        return f6

    def solve(self, q0):
        from scipy.optimize import fsolve
        scale = np.array([1e6, 1e6, 1e6, 1e8, 1e8, 1e8])
        if self.case["type"] == "FIXED":
            q = np.zeros(6)
        else:
            with warnings.catch_warnings():      # started at MoorPy's solution, fsolve
                warnings.simplefilter("ignore")  # may find no progress left to make
                q = fsolve(lambda q: (self.lines(q)[0] + self.own(q)) / scale, q0,
                           xtol=1e-14)
        f6, out = self.lines(q)
        resid = f6 + (self.own(q) if self.case["type"] == "FREE" else 0.0)
        st = {"q": q, "F": f6, "residual": resid, "T": {}, "H": {}, "VB": {}, "lbot": {},
              "fair": {}}
        for ln, (fa, fb, h, vb, va, lb, rf) in out.items():
            st["T"][(ln, "A")] = float(np.linalg.norm(fa))
            st["T"][(ln, "B")] = float(np.linalg.norm(fb))
            st["H"][ln], st["VB"][ln], st["lbot"][ln], st["fair"][ln] = h, vb, lb, rf
        return st

    def stiffness(self, q0):
        """-d(lines' force, moment)/dq by central differences, rotation-vector steps."""
        k = np.zeros((6, 6))
        for j in range(6):
            h = FD_DX if j < 3 else FD_DTH
            dq = np.zeros(6)
            dq[j] = h
            k[:, j] = -(self.lines(q0 + dq)[0] - self.lines(q0 - dq)[0]) / (2.0 * h)
        self.lines(q0)
        return k


# ------------------------------------------------------------- reference rows
def state_rows(name, st, source, compare=True):
    """Rows (case, quantity, value, unit, scale, tolerance, source) of one solution."""
    case = CASES[name]
    rows = []

    def tol(kind):
        return TOL[kind] if compare else None
    if case["type"] == "FREE":
        for c, v in zip(DOF[:3], st["q"][:3]):
            rows.append((f"{BODY}.{c}", v, "m", LENGTH, tol("position")))
        for c, v in zip(DOF[3:], st["q"][3:]):
            rows.append((f"{BODY}.{c}", v, "rad", 1.0, tol("rotation")))
    fscale = float(np.linalg.norm(st["F"][:3]))
    for c, v in zip(("Fx", "Fy", "Fz"), st["F"][:3]):
        rows.append((f"{BODY}.{c}", v, "N", fscale, tol("force")))
    for c, v in zip(("Mx", "My", "Mz"), st["F"][3:]):
        rows.append((f"{BODY}.{c}", v, "N m", fscale * R_FAIR_DIST, tol("force")))
    for ln in LINES:
        for end in "AB":
            t = st["T"][(ln, end)]
            rows.append((f"{ln}.{end}.tension", t, "N", t, tol("tension")))
    return [(name,) + r + (source,) for r in rows]


def info_rows(name, st, source):
    """Reference-only rows: horizontal and vertical tension, grounded length, fairlead."""
    rows = []
    for ln in LINES:
        rows.append((f"{ln}.H", st["H"][ln], "N"))
        rows.append((f"{ln}.B.V", st["VB"][ln], "N"))
        rows.append((f"{ln}.grounded_length", st["lbot"][ln], "m"))
    for k, ln in enumerate(LINES):
        for c, v in zip("xyz", st["fair"][ln]):
            rows.append((f"F{k + 1}.{c}", v, "m"))
    return [(name,) + r + (None, None, source) for r in rows]


def matrix_rows(name, prefix, k, source, compare=False):
    """36 rows prefix_<row>_<column> of a 6x6 (x, y, z, rx, ry, rz; K = -dF/dq)."""
    units = {(True, True): "N/m", (True, False): "N/rad", (False, True): "N",
             (False, False): "N m/rad"}
    rows = []
    for i in range(6):
        for j in range(6):
            scale = math.sqrt(abs(k[i, i] * k[j, j])) if compare else None
            rows.append((name, f"{BODY}.{prefix}_{DOF[i]}_{DOF[j]}", k[i, j],
                         units[(i < 3, j < 3)], scale, TOL["stiffness"] if compare else None,
                         source))
    return rows


def max_state_difference(a, b):
    """Largest difference of two solutions on the compared scales."""
    d = [abs(a["T"][k] / b["T"][k] - 1.0) for k in b["T"]]
    d.append(float(np.max(np.abs(a["q"][:3] - b["q"][:3]))) / LENGTH)
    d.append(float(np.max(np.abs(a["q"][3:] - b["q"][3:]))))
    fs = float(np.linalg.norm(b["F"][:3]))
    d.append(float(np.max(np.abs(a["F"][:3] - b["F"][:3]))) / fs)
    d.append(float(np.max(np.abs(a["F"][3:] - b["F"][3:]))) / (fs * R_FAIR_DIST))
    return max(d)


def write(args):
    import scipy
    mpv = moorpy_version()
    src = f"moorpy-{mpv}"
    rows, notes = [], []
    worst_ind = 0.0
    np.set_printoptions(linewidth=150)
    print(f"hull: V = {V_GEOMETRY:.4f} m3 (report 8029.21), B at z = {ZB:.6f} m; A_wp = "
          f"{A_WP:.6f} m2, I_wp = {I_WP:.6f} m4; w = {W:.6f} N/m; system mass "
          f"{M_SYSTEM:.0f} kg, CM z = {ZG_SYSTEM:.4f} m")
    for name, case in CASES.items():
        ms, body = solve_moorpy(name, EQ_TOL)
        st = moorpy_state(ms, body)
        tmax = max(st["T"].values())
        ms2, body2 = solve_moorpy(name, EQ_TOL_CHECK)
        d_tol = max_state_difference(moorpy_state(ms2, body2), st)
        guesses = {ln: (st["H"][ln], st["VB"][ln]) for ln in LINES}
        indep = Independent(name, guesses)
        ind = indep.solve(st["q"])
        d_ind = max_state_difference(ind, st)
        worst_ind = max(worst_ind, d_ind)
        line = f"== {name}: "
        if case["type"] == "FREE":
            rf, rm = np.max(np.abs(st["residual"][:3])), np.max(np.abs(st["residual"][3:]))
            line += (f"MoorPy tol {EQ_TOL:g} m: residual force {rf:.1e} N, moment {rm:.1e} "
                     f"N m ({rf / tmax:.0e} of the largest tension); tol {EQ_TOL_CHECK:g} m "
                     f"changes the results by {d_tol:.1e}; ")
            notes.append(f"{name}: residual force {rf / tmax:.0e} of the "
                         f"largest tension; tol {EQ_TOL_CHECK:g} m changes results by "
                         f"{d_tol:.1e}; the independent solution (rodyn's hydrostatic model) "
                         f"differs by {d_ind:.1e}")
        else:
            notes.append(f"{name}: the independent catenary differs by {d_ind:.1e}")
        line += f"independent solution differs by {d_ind:.1e}"
        if case["type"] == "FREE":
            line += (f" (its residual {np.max(np.abs(ind['residual'][:3])):.1e} N, "
                     f"{np.max(np.abs(ind['residual'][3:])):.1e} N m)")
        print(line)
        if case["type"] == "FREE":
            q = st["q"]
            print(f"   R at ({q[0]:.9f}, {q[1]:.9f}, {q[2]:.9f}) m, rotation vector "
                  f"({q[3]:.3e}, {q[4]:.9f}, {q[5]:.3e}) rad; Euler (roll, pitch, yaw) "
                  f"{st['r6'][3]:.3e}, {st['r6'][4]:.9f}, {st['r6'][5]:.3e}; independent "
                  f"- MoorPy: surge {ind['q'][0] - q[0]:.1e} m, heave {ind['q'][2] - q[2]:.1e}"
                  f" m, pitch {ind['q'][4] - q[4]:.1e} rad")
        print(f"   lines on the body: F = {np.array2string(st['F'][:3], precision=3)} N, "
              f"M = {np.array2string(st['F'][3:], precision=3)} N m")
        for ln in LINES:
            print(f"   {ln}: fairlead tension {st['T'][(ln, 'B')]:.6f} N, anchor "
                  f"{st['T'][(ln, 'A')]:.6f} N, H {st['H'][ln]:.6f} N, V_fairlead "
                  f"{st['VB'][ln]:.6f} N, grounded {st['lbot'][ln]:.4f} m (independent: "
                  f"{ind['T'][(ln, 'B')] / st['T'][(ln, 'B')] - 1.0:+.1e} in the fairlead "
                  f"tension, {ind['H'][ln] / st['H'][ln] - 1.0:+.1e} in H)")
        rows += state_rows(name, st, src)
        rows += info_rows(name, st, src)
        rows += [(name, f"{BODY}.euler_{c}", v, "rad", None, None, src)
                 for c, v in zip(("roll", "pitch", "yaw"), st["r6"][3:])]
        rows += [r[:4] + (None, None, "independent") for r in
                 state_rows(name, ind, "x", compare=False)]
        ka, kfd = moorpy_stiffness(ms, body)
        if name == "fixed":
            kind = indep.stiffness(np.zeros(6))
            d_fd = relative_matrix_difference(kfd, ka)
            d_ind_k = relative_matrix_difference(kind, ka)
            asym = float(np.max(np.abs(ka - ka.T)) / np.max(np.abs(ka)))
            print(f"   lines-only stiffness (Body.getStiffnessA), about R = (0, 0, 0):\n"
                  f"{np.array2string(ka, precision=6)}\n   max |K - K^T| / max |K| = "
                  f"{asym:.1e}; MoorPy's central difference (+-{FD_DX:g} m, +-{FD_DTH:g} rad) "
                  f"differs by {d_fd:.1e}, the independent catenary's by {d_ind_k:.1e} "
                  f"(max |dK_ij| / sqrt(K_ii K_jj))")
            notes.append(f"fixed: lines-only stiffness Body.getStiffnessA; max |K - K^T| / "
                         f"max |K| = {asym:.1e}; MoorPy's central difference (+-{FD_DX:g} m, "
                         f"+-{FD_DTH:g} rad) differs by {d_fd:.1e}, the independent "
                         f"catenary's central difference by {d_ind_k:.1e} (max |dK_ij| / "
                         f"sqrt(K_ii K_jj))")
            rows += matrix_rows(name, "K", ka, src, compare=True)
            rows += matrix_rows(name, "K", kfd, "moorpy_central_difference")
            rows += matrix_rows(name, "K", kind, "independent")
            # the report's Eq. (5-3), with MoorPy at the report's g
            msr, bodyr = solve_moorpy(name, EQ_TOL, g=G_REPORT)
            kr = np.array(bodyr.getStiffnessA(lines_only=True, all_DOFs=True), float)
            fz = float(bodyr.getForces(lines_only=True, all_DOFs=True)[2])
            cmp = [f"K{i + 1}{j + 1} {kr[i, j]:.6g} ({kr[i, j] / v - 1.0:+.1e})"
                   for (i, j), v in REPORT_K.items()]
            cmp.append(f"F0z {fz:.6g} ({fz / REPORT_F0Z - 1.0:+.1e})")
            print("   at the report's g = 9.80665, against its Eq. (5-3) (4 digits): "
                  + ", ".join(cmp))
            notes.append("fixed, with g = 9.80665, against the report's Eq. (5-3): "
                         + ", ".join(cmp))
            rows += [(name, f"{BODY}.K_{DOF[i]}_{DOF[j]}", v, "", None, None,
                      "report_eq_5_3_g9.80665") for (i, j), v in REPORT_K.items()]
            rows.append((name, f"{BODY}.Fz", REPORT_F0Z, "N", None, None,
                         "report_eq_5_3_g9.80665"))
            # hydrostatics at zero offset: MoorPy's against rodyn's model
            kh = moorpy_hydrostatics(ms, body)
            own = np.zeros((6, 6))
            own[3, 3] = own[4, 4] = (-MASS_PLATFORM * G * ZG_PLATFORM
                                     + RHO * G * VOLUME * ZB)
            krodyn = own + hydrostatic_matrix()
            print(f"   MoorPy's hydrostatic 6x6 at zero offset (platform alone):\n"
                  f"{np.array2string(kh, precision=6)}\n   rodyn's model (weight at G, "
                  f"buoyancy at B, + C) minus MoorPy's: max entry "
                  f"{np.max(np.abs(krodyn - kh)):.1e}")
            notes.append(f"hydrostatic 6x6 at zero offset (platform alone), MoorPy: K33 "
                         f"{kh[2, 2]:.6f} N/m, K44 = K55 {kh[3, 3]:.6f} N m/rad, others 0; "
                         f"rodyn's model differs by {np.max(np.abs(krodyn - kh)):.1e}")
            rows += matrix_rows("hydrostatics", "C", kh, src)
        else:
            rows += matrix_rows(name, "K", ka, src)
            if case["type"] == "FREE":
                # the hydrostatic models at the equilibrium: MoorPy's against rodyn's
                kh = moorpy_hydrostatics(ms, body)
                kr = np.zeros((6, 6))
                q0 = st["q"]
                for j in range(6):
                    h = FD_DX if j < 3 else FD_DTH
                    kr[:, j] = -(indep.own(perturbed(q0, j, h))
                                 - indep.own(perturbed(q0, j, -h))) / (2.0 * h)
                print(f"   hydrostatic 6x6 at the equilibrium, rodyn's model (central "
                      f"difference) - MoorPy's: largest entry "
                      f"{np.max(np.abs(kr - kh)):.1f} (K55 {kh[4, 4]:.6e})")
                notes.append(f"{name}: at the equilibrium the hydrostatic 6x6 of rodyn's "
                             f"model differs from MoorPy's by {np.max(np.abs(kr - kh)):.0f} "
                             f"at most (K55 {kh[4, 4]:.4e})")
    facts = benchlib.machine_facts(args.rodyn)
    header = [f"bench/systems/moorpy_spar.py: the OC3-Hywind spar on three catenary legs, "
              f"MoorPy {mpv} statics (solveEquilibrium tol {EQ_TOL:g} m, catenaries "
              f"{0.01 * EQ_TOL:g} m), scipy {scipy.__version__}, numpy {np.__version__}",
              "source: J. Jonkman, Definition of the Floating System for Phase IV of OC3, "
              "NREL/TP-500-47535 (2010); see the script's docstring",
              f"g {G} m/s2, rho {RHO} kg/m3, depth {DEPTH} m, w {W!r} N/m, EA {EA:g} N, "
              f"line {LENGTH} m, headings {HEADINGS} deg; V {VOLUME} m3, zB {ZB!r} m, "
              f"A_wp {A_WP!r} m2, I_wp {I_WP!r} m4; platform {MASS_PLATFORM} kg at zG "
              f"{ZG_PLATFORM} m; *_system: {M_SYSTEM} kg at zG {ZG_SYSTEM!r} m",
              "body DOFs: R's position [m] and rotation vector [rad]; forces and moments of "
              "the lines on the body, global axes, about R; K = -dF/dq, 6x6 in x,y,z,rx,ry,rz",
              "compared by --quick: rows of source moorpy-* with a tolerance, |rodyn - value|"
              " / scale; other rows: reference only",
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
        print(f"moorpy_spar: MoorPy and the independent solution differ by {worst_ind:.1e} "
              "(> 1e-6)")
        return 1
    return 0


# ---------------------------------------------------------------------------- rodyn
# rodyn's output for *BODY (docs/output.md); each reader returns plain values keyed simply, so
# that a change of file or column names touches only these lines.
BODIES_CSV = "static_bodies.csv"        # body,x_m,y_m,z_m,rx_rad,ry_rad,rz_rad,Fx_N,...,Mz_Nm
STIFFNESS_CSV = "static_stiffness.csv"   # row_object,row_dof,column_object,column_dof,...
REACTIONS_CSV = "static_reactions.csv"  # line,end,Fx_N,Fy_N,Fz_N,...,tension_N
BODY_COLUMNS = {"x": "x_m", "y": "y_m", "z": "z_m", "rx": "rx_rad", "ry": "ry_rad",
                "rz": "rz_rad", "Fx": "Fx_N", "Fy": "Fy_N", "Fz": "Fz_N", "Mx": "Mx_Nm",
                "My": "My_Nm", "Mz": "Mz_Nm"}


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_bodies(out):
    """{body: {x, y, z, rx, ry, rz, Fx, ..., Mz}} from static_bodies.csv."""
    return {r["body"]: {k: float(r[c]) for k, c in BODY_COLUMNS.items()}
            for r in read_csv(os.path.join(out, BODIES_CSV))}


def read_body_stiffness(out):
    """{body: {(row, column): K}} of the lines alone from static_stiffness.csv (rows and
    columns of one body; row, column: x..rz)."""
    k = {}
    for r in read_csv(os.path.join(out, STIFFNESS_CSV)):
        if r["row_object"] != r["column_object"]:
            continue
        k.setdefault(r["row_object"], {})[(r["row_dof"].strip().lower(),
                                           r["column_dof"].strip().lower())] = \
            float(r["lines_stiffness"])
    return k


def read_reactions(out):
    """{(line, end): tension} from static_reactions.csv."""
    return {(r["line"], r["end"]): float(r["tension_N"])
            for r in read_csv(os.path.join(out, REACTIONS_CSV))}


def rodyn_values(name, out):
    """rodyn's values under the reference's quantity names."""
    vals = {}
    body = read_bodies(out)[BODY]
    for k, v in body.items():
        if CASES[name]["type"] == "FREE" or k not in DOF:
            vals[f"{BODY}.{k}"] = v
    for (ln, end), t in read_reactions(out).items():
        vals[f"{ln}.{end}.tension"] = t
    if CASES[name]["type"] == "FIXED":
        for (i, j), v in read_body_stiffness(out)[BODY].items():
            vals[f"{BODY}.K_{i}_{j}"] = v
    return vals


def read_reference():
    with open(RESULTS_CSV) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def run_rodyn(rodyn, deck, out):
    """Run rodyn on a deck; False (with a message) when it refuses it or fails."""
    p = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True, text=True)
    if p.returncode != 0:
        msg = (p.stderr or p.stdout).strip().splitlines()
        print(f"moorpy_spar: rodyn refused or failed on {os.path.relpath(deck, ROOT)} "
              f"(exit {p.returncode}): {msg[0] if msg else '(no message)'}")
        for m in msg[1:4]:
            print(f"    {m}")
        return False
    return True


def compare(ref, values_by_case, title):
    """Print the table; True when every compared row is within its tolerance."""
    ok = True
    print(f"{title}\n{'case':14s} {'quantity':18s} {'MoorPy':>20s} {'rodyn':>20s} "
          f"{'diff/scale':>10s} {'tol':>7s}")
    for r in ref:
        if not r["source"].startswith("moorpy-") or not r["tolerance"]:
            continue
        vals = values_by_case.get(r["case"])
        if vals is None:
            continue
        if r["quantity"] not in vals:
            print(f"{r['case']:14s} {r['quantity']:18s} {float(r['value']):20.9g} "
                  f"{'(missing)':>20s}")
            ok = False
            continue
        v, ref_v = vals[r["quantity"]], float(r["value"])
        e = abs(v - ref_v) / float(r["scale"])
        tol = float(r["tolerance"])
        good = e <= tol
        ok &= good
        print(f"{r['case']:14s} {r['quantity']:18s} {ref_v:20.9g} {v:20.9g} {e:10.2e} "
              f"{tol:7.0e} {'ok' if good else 'MISSED'}")
    return ok


def quick(args):
    rodyn = benchlib.check_rodyn(args.rodyn)
    ref = read_reference()
    vals, refused = {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            deck = deck_path(name)
            with open(deck) as f:
                if f.read() != deck_text(name):
                    print(f"note: {os.path.relpath(deck, ROOT)} differs from what --write "
                          "writes (run as it is)")
            out = os.path.join(tmp, name)
            if not run_rodyn(rodyn, deck, out):
                refused.append(name)
                continue
            try:
                vals[name] = rodyn_values(name, out)
            except (OSError, KeyError, ValueError) as e:
                print(f"moorpy_spar: {name}: rodyn's results unreadable: {e!r}")
                refused.append(name)
    ok = True
    if vals:
        ok = compare(ref, vals,
                     f"rodyn ({rodyn}) against {os.path.relpath(RESULTS_CSV, ROOT)}")
    if refused:
        print(f"moorpy_spar: {len(refused)} of {len(CASES)} decks not run to the end "
              f"({', '.join(refused)}): nothing compared for them.")
    return 0 if ok and not refused else 1


def pinned_deck(name, ref, dq=None):
    """Without *BODY: the case's lines alone, each end PINNED where MoorPy puts it; with
    dq (the fixed case), the fairleads where the body moved by dq (rotation vector) puts
    them."""
    fair = {}
    for row in ref or []:
        if row["case"] == name and row["source"].startswith("moorpy-"):
            p, _, c = row["quantity"].partition(".")
            if p.startswith("F") and c in ("x", "y", "z"):
                fair.setdefault(p, [0.0, 0.0, 0.0])["xyz".index(c)] = float(row["value"])
    if dq is not None:
        fair = {f"F{k + 1}": dq[:3] + rotvec_matrix(dq[3:]) @ fairlead_rel(k)
                for k in range(len(LINES))}
    text = deck_text(name).split("** the body,")[0]
    for k, ln in enumerate(LINES):
        ends = np.concatenate([anchor(k), fair[f"F{k + 1}"]])
        text += (f"*LINE, NAME={ln}, SECTION=CHAIN, LENGTH={fmt(LENGTH)}, ELEMENTS={ELEMENTS}, "
                 f"ORDER={ORDER}, ELEMENT=CABLE\n" + ", ".join(fmt(c) for c in ends) + "\n"
                 f"*BOUNDARY, LINE={ln}, END=A, TYPE=PINNED\n"
                 f"*BOUNDARY, LINE={ln}, END=B, TYPE=PINNED\n")
    return text + "*STATIC, INCREMENTS=20, MAX ITERATIONS=50\n*OUTPUT, CSV=YES, HDF5=NO\n"


def read_reaction_forces(out):
    """{(line, end): force of the support on the line [N]} from static_reactions.csv."""
    return {(r["line"], r["end"]): np.array([float(r[c]) for c in ("Fx_N", "Fy_N", "Fz_N")])
            for r in read_csv(os.path.join(out, REACTIONS_CSV))}


def pinned_body_force(rodyn, tmp, dq):
    """The pinned lines' force and moment (about R moved by dq) on the fixed body."""
    deck = os.path.join(tmp, "fixed_dq.inp")
    with open(deck, "w") as f:
        f.write(pinned_deck("fixed", None, dq))
    out = os.path.join(tmp, "fixed_dq")
    if not run_rodyn(rodyn, deck, out):
        return None
    reac = read_reaction_forces(out)
    f6 = np.zeros(6)
    for k, ln in enumerate(LINES):
        f = -reac[(ln, "B")]                  # the line's force on the fairlead
        f6[:3] += f
        f6[3:] += np.cross(rotvec_matrix(dq[3:]) @ fairlead_rel(k), f)
    return f6


def pinned(args):
    """Each case's lines alone between ends pinned at MoorPy's anchors and fairleads: end
    tensions from the reactions against MoorPy's; and the fixed body's 6x6 from central
    differences (+-1 cm, +-1e-4 rad) of the pinned lines' force and moment on it."""
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
            vals[name] = {f"{ln}.{end}.tension": t
                          for (ln, end), t in read_reactions(out).items()}
        for j in range(6):
            h = 1e-2 if j < 3 else 1e-4
            dq = np.zeros(6)
            dq[j] = h
            fp, fm = pinned_body_force(rodyn, tmp, dq), pinned_body_force(rodyn, tmp, -dq)
            if fp is None or fm is None:
                failed = True
                break
            for i in range(6):
                vals["fixed"][f"{BODY}.K_{DOF[i]}_{DOF[j]}"] = -(fp[i] - fm[i]) / (2.0 * h)
    ok = compare([r for r in ref if r["quantity"].endswith(".tension")
                  or (r["case"] == "fixed" and ".K_" in r["quantity"])], vals,
                 "rodyn's lines alone, ends pinned at MoorPy's equilibrium: end tensions; "
                 "the fixed body's stiffness by central differences of rodyn's reactions")
    return 0 if ok and not failed else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--write", action="store_true",
                    help="solve with MoorPy, write bench/results/moorpy_spar.csv and the decks")
    ap.add_argument("--quick", action="store_true",
                    help="rodyn on bench/systems/decks/spar_*.inp against the stored values")
    ap.add_argument("--pinned", action="store_true",
                    help="rodyn without *BODY: each case's lines alone, pinned at MoorPy's "
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
