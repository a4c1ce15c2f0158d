#!/usr/bin/env python3
"""A body's quadratic drag on the velocity relative to the water (*BODY DRAG with a
current and with waves; docs/theory.md eq. (149)).

1. decks/body_current_drag.inp: a neutrally buoyant body on springs k_i in a uniform
   current U of 1.5 m/s towards 30 deg. The static offset along each axis is
   1/2 rho CdA_i |U_i| U_i / k_i (within 1e-9 of it), and the dynamics started there stays
   there (within 1e-9 m over 5 s).
2. decks/body_wave_drag.inp: the same body (with an added mass) on surge and heave springs
   in a regular wave (2 m, 6 s, towards +x, 100 m of water, no stretching, ramped in over
   6 s), moved only by the drag on its velocity relative to the wave's at R:
       (m + A) x'' + k1 x = q1 |u - x'| (u - x'),
       (m + A) z'' + k3 (z - z0) = q3 |w - z'| (w - z'),   q_i = 1/2 rho CdA_i,
   u, w the linear wave's velocity at R (Airy: a w cosh(k (z + d))/sinh(k d) cos(theta),
   a w sinh(k (z + d))/sinh(k d) sin(theta), theta = k x - w t, times the ramp), integrated
   independently (scipy's solve_ivp, rtol 1e-11). rodyn at DT = 0.02 and 0.01 s: surge
   and heave within 2e-4 of their largest value at 0.01 s, and the error falling at least
   threefold as DT halves (second order).

Usage: check_body_current_drag.py RODYN DECK_DIR OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

RHO, G = 1025.0, 9.80665


def run(rodyn, deck, out, *sets):
    args = [rodyn, deck, "-o", out, "--quiet"]
    for s in sets:
        args += ["--set", s]
    proc = subprocess.run(args, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode} on {deck}: {proc.stderr.strip()}")


def rows(out, name):
    with open(os.path.join(out, name)) as f:
        return list(csv.DictReader(f))


def current_case(rodyn, decks, out):
    run(rodyn, os.path.join(decks, "body_current_drag.inp"), out)
    u = 1.5 * np.array([math.cos(math.radians(30.0)), math.sin(math.radians(30.0))])
    ref = 0.5 * RHO * np.array([2.0, 3.0]) * np.abs(u) * u / np.array([1.0e5, 1.2e5])
    st = rows(out, "static_bodies.csv")[0]
    xs = np.array([float(st["x_m"]), float(st["y_m"])])
    err = np.abs(xs - ref).max() / np.abs(ref).max()
    drift = max(max(abs(float(r["x_m"]) - xs[0]), abs(float(r["y_m"]) - xs[1]))
                for r in rows(out, "dynamic_bodies_step.csv"))
    print(f"current: static offset ({xs[0]:.6e}, {xs[1]:.6e}) m against ({ref[0]:.6e}, "
          f"{ref[1]:.6e}): {err:.1e}; the dynamics stays within {drift:.1e} m of it")
    return err <= 1e-9 and drift <= 1e-9


def wave_reference(t_end, z0):
    a, period, depth, ramp = 1.0, 6.0, 100.0, 6.0
    w = 2 * math.pi / period
    k = w**2 / G
    for _ in range(200):
        k = w**2 / (G * math.tanh(k * depth))
    m = 1300.0
    q1, q3 = 0.5 * RHO * 20.0, 0.5 * RHO * 30.0
    k1, k3 = 1.0e4, 1.5e4

    def rhs(t, y):
        x, vx, z, vz = y
        r = 1.0 if t >= ramp else 0.5 * (1 - math.cos(math.pi * t / ramp))
        th = k * x - w * t
        uc = r * a * w * math.cosh(k * (z + depth)) / math.sinh(k * depth) * math.cos(th)
        wc = r * a * w * math.sinh(k * (z + depth)) / math.sinh(k * depth) * math.sin(th)
        fx = -k1 * x + q1 * abs(uc - vx) * (uc - vx)
        fz = -k3 * (z - z0) + q3 * abs(wc - vz) * (wc - vz)
        return [vx, fx / m, vz, fz / m]

    return solve_ivp(rhs, (0.0, t_end), [0.0, 0.0, z0, 0.0], rtol=1e-11, atol=1e-13,
                     dense_output=True)


def wave_case(rodyn, decks, out):
    errs = []
    for dt in ("0.02", "0.01"):
        o = os.path.join(out, "wave_dt" + dt)
        run(rodyn, os.path.join(decks, "body_wave_drag.inp"), o, "DT=" + dt)
        b = rows(o, "dynamic_bodies_step.csv")
        t = np.array([float(r["time_s"]) for r in b])
        x = np.array([float(r["x_m"]) for r in b])
        z = np.array([float(r["z_m"]) for r in b])
        sol = wave_reference(t[-1], z[0])
        ref = sol.sol(t)
        e = max(np.abs(x - ref[0]).max() / np.abs(ref[0]).max(),
                np.abs(z - ref[2]).max() / np.abs(ref[2] - z[0]).max())
        print(f"wave, DT {dt} s: surge up to {np.abs(ref[0]).max():.4f} m, heave up to "
              f"{np.abs(ref[2] - z[0]).max():.4f} m; largest error {e:.2e} of them")
        errs.append(e)
    ratio = errs[0] / errs[1]
    print(f"error ratio as DT halves: {ratio:.2f}")
    return errs[1] <= 2e-4 and ratio >= 3.0


def main():
    rodyn, decks, out = sys.argv[1:4]
    ok = current_case(rodyn, decks, os.path.join(out, "current"))
    ok &= wave_case(rodyn, decks, out)
    if not ok:
        sys.exit("FAIL")
    print("PASS")


if __name__ == "__main__":
    main()
