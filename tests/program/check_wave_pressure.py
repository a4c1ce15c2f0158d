#!/usr/bin/env python3
"""A taut vertical line in a regular wave: effective and wall tension against closed forms.

    check_wave_pressure.py RODYN DECK WORK_DIR

The deck (vertical_wave_pressure.inp) pins a vertical cable of outer area A between
z_b = -75 m and z_t = -15 m in 100 m of water (density rho, g) and runs a regular Airy
wave (H 4 m, T 16 s, towards +x, ramp r(t) over 16 s, no stretching) for 40 s. The line
is so taut (about 1e6 N) that it stays straight (the wave's lateral load bends it by
about 1 mm), and axially it is quasi-static (EA 1e10 N); the scheme is ALPHA (the deck
says why). Along it the axial balance per unit unstretched length S is
dT_eff/dS = w_s - rho A a_wz, with the submerged weight w_s = (m - rho A) g and the
vertical Froude-Krylov load rho A a_wz = -A dp_d/dz (docs/theory.md (71), (122)), so

  T_eff(S, t) - T_eff(S_b, t) = w_s (S - S_b) + A int_{S_b}^{S} dp_d/dz dS
                              ~ w_s (S - S_b) + A [p_d(z, t) - p_d(z_b, t)]
  T_wall = T_eff - p A,  p = rho g (z_s - z) + p_d                         ((123))

with p_d = rho g r(t) (H/2) cosh(k (z + d))/cosh(k d) cos(omega t) at x = 0 (k from the
dispersion relation by brentq): the dynamic pressure cancels from the wall tension's
variation along the line. The integral is taken along the deformed line (z(S) from the
nodes; strain 1e-4). The unknown T_eff(S_b, t) (set by the line's total stretch)
cancels. Held over every frame after the ramp, at every integration point: the largest
error of each difference, relative to the largest |A [p_d(z) - p_d(z_b)]|, below 1e-4.
Without the axial Froude-Krylov load, or without p_d in the wall tension, the error is
of order 1.
"""
import math
import os
import subprocess
import sys

import h5py
import numpy as np
from scipy.optimize import brentq

RHO, G, DEPTH, H, T, RAMP = 1025.0, 9.80665, 100.0, 4.0, 16.0, 16.0
D, MASS = 0.1, 20.0
TOL = 1e-4


def main():
    rodyn, deck, work = (os.path.abspath(a) for a in sys.argv[1:4])
    os.makedirs(work, exist_ok=True)
    subprocess.run([rodyn, deck], cwd=work, check=True, stdout=subprocess.DEVNULL)
    name = os.path.splitext(os.path.basename(deck))[0]
    with h5py.File(os.path.join(work, name, "dynamic.h5"), "r") as f:
        time = f["dynamic/time"][...]
        g = f["dynamic/RISER"]
        node_s, gp_s = g["node_s"][...], g["gp_s"][...]
        z_nodes, x_nodes = g["z"][...], g["x"][...]
        teff, twall = g["effective_tension"][...], g["wall_tension"][...]
    area = math.pi * D**2 / 4
    omega = 2 * math.pi / T
    k = brentq(lambda kk: omega**2 - G * kk * math.tanh(kk * DEPTH), 1e-8, 10.0,
               xtol=1e-15, rtol=1e-15)
    ws = (MASS - RHO * area) * G
    keep = time >= RAMP
    print(f"{keep.sum()} frames after the ramp; largest lateral deflection "
          f"{np.abs(x_nodes).max() * 1e3:.3f} mm")
    err_e = err_w = scale = 0.0
    for i in np.nonzero(keep)[0]:
        z = np.interp(gp_s, node_s, z_nodes[i])     # heights of the points
        zb = z_nodes[i, 0]
        pd = RHO * G * (H / 2) * np.cosh(k * (z + DEPTH)) / math.cosh(k * DEPTH) \
            * math.cos(omega * time[i])
        pdb = RHO * G * (H / 2) * math.cosh(k * (zb + DEPTH)) / math.cosh(k * DEPTH) \
            * math.cos(omega * time[i])
        dyn = area * (pd - pdb)
        # the rodyn differences are taken from the lowest point, extrapolated to z_b
        # through the closed form (the point sits a fraction of an element above it)
        # the Froude-Krylov load per unstretched length, integrated over S along the
        # deformed line: A int dp_d/dz dS (z(S) linear between the nodes)
        sf = np.linspace(node_s[0], node_s[-1], 20001)
        zf = np.interp(sf, node_s, z_nodes[i])
        dpdz = RHO * G * (H / 2) * k * np.sinh(k * (zf + DEPTH)) / math.cosh(k * DEPTH) \
            * math.cos(omega * time[i])
        fk = np.concatenate(([0.0], np.cumsum(0.5 * (dpdz[1:] + dpdz[:-1]) * np.diff(sf))))
        e_closed = ws * (gp_s - node_s[0]) + area * np.interp(gp_s, sf, fk)
        # T_wall = T_eff - p A with p = rho g (z_s - z) + p_d (z_s = 0)
        w_closed = e_closed - area * (RHO * G * (zb - z) + pd - pdb)
        e_rodyn = teff[i] - (teff[i, 0] - e_closed[0])
        w_rodyn = twall[i] - (twall[i, 0] - w_closed[0])
        if os.environ.get("VERBOSE"):
            print(f"{time[i]:6.2f}", np.round((e_rodyn - e_closed)[::6], 4))
        err_e = max(err_e, np.abs(e_rodyn - e_closed).max())
        err_w = max(err_w, np.abs(w_rodyn - w_closed).max())
        scale = max(scale, np.abs(dyn).max())
    print(f"largest |A (p_d(z) - p_d(z_b))| = {scale:.2f} N")
    print(f"effective tension: largest error {err_e:.3e} N = {err_e / scale:.2e} of it")
    print(f"wall tension:      largest error {err_w:.3e} N = {err_w / scale:.2e} of it")
    ok = scale > 50.0 and err_e / scale < TOL and err_w / scale < TOL
    print("ok" if ok else f"FAILED (tolerance {TOL:g})")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
