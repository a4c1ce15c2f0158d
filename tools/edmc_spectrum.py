#!/usr/bin/env python3
"""Spectral properties of the dissipative EMC (docs/theory.md section 16, eqs.
(124)-(130)) and of generalized-alpha at the same RHO INF, for x'' + w^2 x = 0 at
W = w dt: the spectral radius of the one-step map at W = 1, 3, 10 and infinity, and the
damping ratio and relative period error of the principal root at W = 0.1, 0.3 and 1.

The dissipative EMC on the oscillator, state (x_n, u_n = dt v_n, x_n-1), eqs. (124)-(126)
with K0 = w^2:
    x1 - x0 = (u0 + u1)/2
    u1 - u0 = -W^2 [(x0 + x1)/2 + c1 (x1 - 2 x0 + xm) + 2 c2 (x1 - x0 - u0)]
with c2 = 2 c1^2 and c1 from RHO INF (eq. (129)). Generalized-alpha: Chung and Hulbert's
amplification matrix in (x, dt v, dt^2 a) with alpha_m = (2 rho - 1)/(rho + 1),
alpha_f = rho/(rho + 1), gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m +
alpha_f)^2/4.

usage: python3 tools/edmc_spectrum.py"""
import numpy as np


def edmc_map(om, c1):
    c2 = 2 * c1 * c1
    w2 = om * om
    a = np.array([[1.0, -0.5], [w2 * (0.5 + c1 + 2 * c2), 1.0]])
    b = np.array([[1.0, 0.5, 0.0],
                  [w2 * (-0.5 + 2 * c1 + 2 * c2), 1.0 + 2 * c2 * w2, -w2 * c1]])
    m = np.zeros((3, 3))
    m[:2] = np.linalg.solve(a, b)
    m[2, 0] = 1.0
    return m


def rho_inf_edmc(c1):
    c2 = 2 * c1 * c1
    return max(abs(np.roots([1 + 2 * c1 + 4 * c2, 2 - 2 * c1 - 8 * c2,
                             1 - 2 * c1 + 4 * c2, 2 * c1])))


def c1_for(rho):
    if rho >= 1.0:
        return 0.0
    lo, hi = 0.0, 0.086
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if rho_inf_edmc(mid) > rho else (lo, mid)
    return 0.5 * (lo + hi)


def alpha_map(om, rho):
    am = (2 * rho - 1) / (rho + 1)
    af = rho / (rho + 1)
    g = 0.5 - am + af
    b = 0.25 * (1 - am + af) ** 2
    w2 = om * om
    # unknowns (x1, u1, s1) with u = dt v, s = dt^2 a; state (x0, u0, s0)
    lhs = np.array([[1.0, 0.0, -b], [0.0, 1.0, -g], [w2 * (1 - af), 0.0, 1 - am]])
    rhs = np.array([[1.0, 1.0, 0.5 - b], [0.0, 1.0, 1 - g], [-w2 * af, 0.0, -am]])
    return np.linalg.solve(lhs, rhs)


def principal(m, om):
    ev = np.linalg.eigvals(m)
    z = ev[np.argmin(abs(np.angle(ev) - om))]
    lam = np.log(z)
    return -lam.real / abs(lam), abs(lam.imag) / om - 1.0


def main():
    print("| RHO INF | scheme | c1 | rho(1) | rho(3) | rho(10) | rho(inf) | "
          "zeta(0.1) | zeta(0.3) | zeta(1) | period error(0.3) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for rho in (1.0, 0.9, 0.8, 0.7, 0.6, 0.52):
        c1 = c1_for(rho)
        rows = [("EMC", lambda om: edmc_map(om, c1), f"{c1:.4f}")]
        if rho < 1.0:
            rows.append(("ALPHA", lambda om: alpha_map(om, rho), "-"))
        for name, fmap, c1s in rows:
            r = [max(abs(np.linalg.eigvals(fmap(om)))) for om in (1.0, 3.0, 10.0, 1e6)]
            z = [principal(fmap(om), om) for om in (0.1, 0.3, 1.0)]
            print(f"| {rho:g} | {name} | {c1s} | " + " | ".join(f"{x:.3f}" for x in r)
                  + " | " + " | ".join(f"{zz[0]:.1e}" for zz in z) + f" | {z[1][1]:+.2e} |")


if __name__ == "__main__":
    main()
