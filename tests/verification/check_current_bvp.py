#!/usr/bin/env python3
"""A taut vertical riser in a uniform current: rodyn's static shape and end tensions
against an independent boundary-value solution computed here (docs/water.md,
verification).

The scene: a riser pinned at (0, 0, -100) in water (no seabed contact), unstretched
length 89.97 m, laid straight up and its top pulled to (0, 0, -10) (the pretension);
EA = 1e8 N, EI = GJ = 2e7 N m2 (a bending stiffness that matters: the elastic length
sqrt(EI/T) is about a sixth of the span), 20 kg/m in air, outer and drag diameter 0.1 m, Cdn = 1.2, Cda = 0.05; a uniform
current of 1.5 m/s along +x. It bows 1.3 m downstream; with 15, 30 and 60 cubic
elements the largest position error is 7.5e-6, 2.9e-7 and 2.0e-8 of the bow (fourth
order).

The boundary-value problem, the planar Reissner rod in the x-z plane per unstretched arc
length s (rodyn's drag law, rodyn_hydro.f90, with the line at rest):
    n' = -f,   M' = -(x'_x n_z - x'_z n_x),   theta' = M / EI,
    x' = (1 + n.d3 / EA) d3 + (n.d1 / GA) d1,   d3 = (cos theta, sin theta),
    d1 = (-sin theta, cos theta),  GA = EA (rodyn's default),
    f = -w e_z + 1/2 rho C_dn D lam |u_n| u_n + 1/2 rho C_da pi D lam |u_t| u_t,
    lam = |x'|, t = x'/lam, u = (U, 0), u_t = (u.t) t, u_n = u - u_t,
    w = (m - rho pi D^2/4) g;
n the force that the part beyond s exerts on the part before it (tension positive), M
the bending moment about +y counted so that M = EI theta'. Pinned ends: x(0), x(L)
given, M(0) = M(L) = 0. Solved by collocation (scipy's solve_bvp), then polished by shooting from its start
values (DOP853 at a relative tolerance of 1e-13, Newton to a misfit below 1e-10 m).

Usage: check_current_bvp.py RODYN OUT_DIR. Exit 0 when the node positions agree to
TOL_X of the bow and the end tensions to TOL_T, relative."""
import csv
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_bvp, solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "program"))
from deck_run import run_deck  # noqa: E402

G = 9.80665
RHO = 1025.0
L0, EA, EI, MASS, D, CDN, CDA, U = 89.97, 1.0e8, 2.0e7, 20.0, 0.1, 1.2, 0.05, 1.5
ZA, ZB = -100.0, -10.0
ELEMENTS = 30
W = (MASS - RHO * math.pi * D**2 / 4.0) * G   # submerged weight [N/m]
TOL_X = 1.0e-6   # node positions, relative to the bow
TOL_T = 1.0e-7   # end tensions, relative

DECK = f"""*HEADING
Taut riser in a uniform current (tests/verification/check_current_bvp.py)
*GRAVITY
0.0, 0.0, -{G}
*WATER, DEPTH=200.0, DENSITY={RHO}
*CURRENT
-200.0, {U}, 0.0
0.0, {U}, 0.0
*SECTION, NAME=RISER, OD={D}, CDN={CDN}, CDA={CDA}, CAN=1.0, CAA=0.0
{EA}, {EI}, {EI}, {EI}, {MASS}
*LINE, NAME=RISER, SECTION=RISER, LENGTH={L0}, ELEMENTS={ELEMENTS}, ORDER=3
0.0, 0.0, {ZA}, 0.0, 0.0, {ZA + L0}
*BOUNDARY, LINE=RISER, END=A, TYPE=PINNED
** the top pulled up from the unstretched length to its place: the pretension
*BOUNDARY, LINE=RISER, END=B, TYPE=POSITION
0.0, 0.0, {ZB}
*STATIC, INCREMENTS=5
*OUTPUT, CSV=YES, HDF5=NO
"""


def rhs(_s, y):
    """d/ds of (x, z, theta, n_x, n_z, M)."""
    th, nx, nz, m = y[2], y[3], y[4], y[5]
    c, s = math.cos(th), math.sin(th)
    na, nq = nx * c + nz * s, -nx * s + nz * c      # n.d3, n.d1
    xpx = (1.0 + na / EA) * c - (nq / EA) * s
    xpz = (1.0 + na / EA) * s + (nq / EA) * c
    lam = math.hypot(xpx, xpz)
    tx, tz = xpx / lam, xpz / lam
    ua = U * tx                                     # u.t
    unx, unz = U - ua * tx, -ua * tz                # u_n
    cn = 0.5 * RHO * CDN * D * lam * math.hypot(unx, unz)
    ct = 0.5 * RHO * CDA * math.pi * D * lam * abs(ua) * ua
    fx = cn * unx + ct * tx
    fz = -W + cn * unz + ct * tz
    return [xpx, xpz, m / EI, -fx, -fz, -(xpx * nz - xpz * nx)]


def solve_rod():
    """Collocation (scipy's solve_bvp, 4th order) from the straight taut line, the mesh
    refined until the relative residual is below 1e-11."""
    s = np.linspace(0.0, L0, 201)
    y = np.zeros((6, s.size))
    y[1] = ZA + s
    y[2] = np.pi / 2
    y[4] = 8.0e4

    def f(s_, y_):
        return np.array([rhs(0.0, y_[:, j]) for j in range(y_.shape[1])]).T

    def bc(ya, yb):
        return np.array([ya[0], ya[1] - ZA, ya[5] / EI, yb[0], yb[1] - ZB, yb[5] / EI])

    guess = solve_bvp(f, bc, s, y, tol=1e-6, max_nodes=100000)
    if not guess.success:
        sys.exit(f"FAIL: the collocation did not converge: {guess.message}")
    # polish: shooting from the collocation's start values, Newton on a difference
    # Jacobian with the unknowns scaled, DOP853 at a relative tolerance of 1e-13
    scale = np.array([1.0, 1.0e4, 1.0e4])
    p = guess.y[2:5, 0] / scale
    for _ in range(20):
        r, sol = shoot(p * scale)
        if np.max(np.abs(r)) < 1e-10:
            return shoot(p * scale, dense=True)[1]
        jac = np.empty((3, 3))
        for k in range(3):
            q = p.copy()
            q[k] += 1e-7
            jac[:, k] = (shoot(q * scale)[0] - r) / 1e-7
        p = p - np.linalg.solve(jac, r)
    sys.exit("FAIL: the shooting did not converge")


def shoot(p, dense=False):
    """Integrate from s = 0 with theta, n_x, n_z = p: the misfit at s = L."""
    y0 = [0.0, ZA, p[0], p[1], p[2], 0.0]
    sol = solve_ivp(rhs, (0.0, L0), y0, method="DOP853", rtol=1e-13, atol=1e-10,
                    dense_output=dense)
    yl = sol.y[:, -1]
    return np.array([yl[0], yl[1] - ZB, yl[5] / EI]), sol


def main():
    rodyn, out = sys.argv[1:3]
    res = run_deck(rodyn, DECK, out, "current_bvp")
    with open(os.path.join(res, "static_nodes.csv")) as f:
        nodes = list(csv.DictReader(f))
    with open(os.path.join(res, "static_reactions.csv")) as f:
        reac = {r["end"]: float(r["tension_N"]) for r in csv.DictReader(f)}
    sol = solve_rod()
    s = np.array([float(r["s_m"]) for r in nodes])
    xr = np.array([[float(r["x_m"]), float(r["y_m"]), float(r["z_m"])] for r in nodes])
    yb = sol.sol(s)
    bow = np.max(np.abs(yb[0]))
    ex = max(np.max(np.abs(xr[:, 0] - yb[0])), np.max(np.abs(xr[:, 2] - yb[1])),
             np.max(np.abs(xr[:, 1]))) / bow
    ta = np.hypot(*sol.y[3:5, 0])
    tb = np.hypot(*sol.y[3:5, -1])
    et = max(abs(reac["A"] - ta) / ta, abs(reac["B"] - tb) / tb)
    print(f"bow {bow:.4f} m; bottom tension {ta:.2f} N, top {tb:.2f} N (BVP)")
    print(f"rodyn, {ELEMENTS} cubic elements: positions within {ex:.2e} of the bow, "
          f"end tensions within {et:.2e}")
    ok = ex <= TOL_X and et <= TOL_T
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
