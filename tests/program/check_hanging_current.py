#!/usr/bin/env python3
"""A free-hanging riser (pinned at its top, its lower end free) in a uniform current
against the solution of the extensible cable's equations (docs/water.md, verification).

The equations, per unstretched length s from the top (0) to the free end (L):
  n' + f = 0,  n = T t,  x' = lambda t,  lambda = 1 + T/EA,  n(L) = 0,
  f = (0, 0, -w) + C_N lambda |u_n| u_n + C_T lambda |u_t| u_t,
with w = (m - rho pi D^2/4) g the weight in water, u = (U, 0, 0) the current, u_n, u_t its
parts across and along t, C_N = rho C_dn D / 2, C_T = rho C_da pi D / 2 (rodyn's drag law,
docs/water.md). Integrated by scipy from the free end up (rtol 1e-12), starting along the
angle where the drag across the line balances the weight's part across it,
  C_N U^2 cos^2(theta) = w sin(theta).
The riser's bending stiffness is left out of the equations: along a line this nearly
straight it changes nothing (no curvature but that of the stretch, about 1e-7 /m). The
check is the largest distance of a node from the solution at its s, for a rod and for
cable elements. Before the static solver ramped the weight first (rodyn_statics), this
riser converged upside down (its lower end 99 m above its top).

Usage: check_hanging_current.py RODYN OUT_DIR. Exit 0 when both runs are within TOL of
the line's length."""
import csv
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

from deck_run import run_deck

G = 9.80665
RHO, U, OD, CDN, CDA, MASS, EA, L = 1025.0, 1.0, 0.16, 1.2, 0.1, 36.7, 4.69e8, 100.0
DECK = """*HEADING
Free-hanging riser in a uniform 1 m/s current along +x ({element})
*GRAVITY
0.0, 0.0, -{g}
*WATER, DEPTH=300.0, DENSITY={rho}
*CURRENT
-300.0, {u}, 0.0
0.0, {u}, 0.0
*SECTION, NAME=PIPE, OD={od}, CDN={cdn}, CDA={cda}, CAN=1.0, CAA=0.0
{ea}, 1.99e4, 1.99e4, 1.5e4, {mass}
*LINE, NAME=RISER, SECTION=PIPE, LENGTH=100.0, ELEMENTS=20, ORDER=3, ELEMENT={element}
0.0, 0.0, -1.0, 0.0, 0.0, -101.0
*BOUNDARY, LINE=RISER, END=A, TYPE=PINNED
*STATIC, INCREMENTS=10
*OUTPUT, CSV=YES, HDF5=NO
"""
TOL = 1.0e-7   # measured: rod 8.6e-9, cable 3.0e-8 (its zero-tension free end)


def solution():
    """x(s) of the cable equations (module header), top at (0, 0, -1): a function of s."""
    cn, ct = 0.5 * RHO * CDN * OD, 0.5 * RHO * CDA * math.pi * OD
    w = (MASS - RHO * math.pi * OD ** 2 / 4.0) * G
    u = np.array([U, 0.0, 0.0])

    def load(t, lam):
        s_t = u @ t
        un = u - s_t * t
        return (np.array([0.0, 0.0, -w]) + cn * lam * np.linalg.norm(un) * un
                + ct * lam * abs(s_t) * s_t * t)

    def rhs(s, y):
        n = y[:3]
        tension = np.linalg.norm(n)
        t, lam = n / tension, 1.0 + tension / EA
        return np.concatenate([-load(t, lam), lam * t])

    sin_t = (-w + math.sqrt(w * w + 4.0 * cn * cn * U ** 4)) / (2.0 * cn * U * U)
    t_end = np.array([sin_t, 0.0, -math.sqrt(1.0 - sin_t ** 2)])
    eps = 1.0e-9
    y0 = np.concatenate([eps * load(t_end, 1.0), np.zeros(3)])   # n(L - eps) = eps f
    sol = solve_ivp(rhs, (L - eps, 0.0), y0, rtol=1e-12, atol=1e-12, dense_output=True)
    top = sol.sol(0.0)[3:]

    def x_at(s):
        return sol.sol(min(s, L - eps))[3:] - top + np.array([0.0, 0.0, -1.0])
    return x_at, math.degrees(math.asin(sin_t))


def worst(folder, x_at):
    """Largest node distance from the solution over the line's length, and the end."""
    with open(os.path.join(folder, "static_nodes.csv")) as f:
        rows = list(csv.DictReader(f))
    out = 0.0
    for r in rows:
        x = np.array([float(r[k]) for k in ("x_m", "y_m", "z_m")])
        out = max(out, float(np.linalg.norm(x - x_at(float(r["s_m"])))) / L)
    return out, [float(rows[-1][k]) for k in ("x_m", "z_m")]


def main():
    rodyn, out = sys.argv[1:3]
    x_at, theta0 = solution()
    ex = x_at(L)
    print(f"solution: lower end at x = {ex[0]:.6f} m, z = {ex[2]:.6f} m "
          f"(theta {theta0:.4f} deg at the free end)")
    ok = True
    for element in ("ROD", "CABLE"):
        text = DECK.format(element=element, g=G, rho=RHO, u=U, od=OD, cdn=CDN, mass=MASS,
                           ea=EA, cda=CDA)
        res = run_deck(rodyn, text, out, element.lower())
        e, end = worst(res, x_at)
        print(f"{element}: lower end at x = {end[0]:.6f} m, z = {end[1]:.6f} m; "
              f"largest node distance {e:.2e} of the length")
        ok = ok and e <= TOL
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
