#!/usr/bin/env python3
"""Force RAOs of a vertical column (a spar or a buoy) by strip theory, as rows of
*BODY WAVE LOAD (docs/deck.md): period, heading, |Fx| |Fy| |Fz| [N/m], |Mx| |My| |Mz|
[N m/m] about the reference point R on the axis at the still water level, then the six
phase lags behind the crest passing R [deg].

The column is a stack of conical or cylindrical segments (z_top, z_bottom, D_top,
D_bottom), z up from the still water level. Linear Airy waves of amplitude 1 m in water
of depth d travel towards the heading beta; on the axis the elevation is cos(w t). Each
slice takes the Morison inertia force of the long-wave limit (G. I. Taylor; DNV-RP-C205,
2021, section 6.2): (1 + Ca) rho A(z) times the water's horizontal acceleration
w^2 cosh(k (z + d))/sinh(k d) (leading the crest by 90 deg), and the column's downward-
and upward-facing surfaces (the base, the steps between segments and the cones' slopes)
take the wave's dynamic pressure rho g cosh(k (z + d))/cosh(k d) (in phase with the
crest):

    F_h = (1 + Ca) rho w^2 int A(z) cosh(k (z + d))/sinh(k d) dz        (lead 90 deg)
    M_h = (1 + Ca) rho w^2 int z A(z) cosh(k (z + d))/sinh(k d) dz
    F_z = sum over faces of rho g A_face cosh(k (z + d))/cosh(k d)  (+ looking down)

with (Fx, Fy) = F_h (cos beta, sin beta) and (Mx, My) = M_h (-sin beta, cos beta) (the
moment about R of a force at depth z); Mz = 0. It holds while the column is slender
against the wave (k D < 0.5 or so; diffraction lowers the force beyond, MacCamy & Fuchs
1954) and leaves out the heave added mass's inertia and the radiation damping.

Usage:
  column_wave_load.py --segments="0,-4,6.5,6.5;-4,-12,6.5,9.4;-12,-120,9.4,9.4" \\
      --depth 320 --periods 4:30:0.5 --headings 0:345:15 > rao.csv
"""
import argparse
import math
import sys

import numpy as np

G = 9.80665


def wave_number(omega, depth, g=G):
    """The root k of omega^2 = g k tanh(k d)."""
    k = omega**2 / g
    for _ in range(200):
        k_new = omega**2 / (g * math.tanh(k * depth))
        if abs(k_new - k) <= 1e-15 * k:
            return k_new
        k = k_new
    return k


def column_loads(segments, period, depth, rho=1025.0, ca=1.0, g=G, n=400):
    """(F_h, M_h, F_z) per metre of wave amplitude, heading 0, for the column."""
    omega = 2 * math.pi / period
    k = wave_number(omega, depth, g)
    fh = mh = fz = 0.0
    for z1, z2, d1, d2 in segments:
        # Gauss-Legendre over the slice: A(z) is quadratic in z, the depth factor smooth
        x, w = np.polynomial.legendre.leggauss(n)
        z = 0.5 * (z1 + z2) + 0.5 * (z1 - z2) * x
        dz = 0.5 * abs(z1 - z2) * w
        dia = d2 + (d1 - d2) * (z - z2) / (z1 - z2)
        area = math.pi * dia**2 / 4
        cx = np.cosh(k * (z + depth)) / math.sinh(k * depth)
        fh += (1 + ca) * rho * omega**2 * np.sum(area * cx * dz)
        mh += (1 + ca) * rho * omega**2 * np.sum(z * area * cx * dz)
        # a conical segment's surface: the pressure on its horizontal projection, dA/dz
        # (< 0 for a cone widening downwards, whose surface faces up: a downward force)
        dadz = math.pi / 2 * dia * (d1 - d2) / (z1 - z2)
        pz = np.cosh(k * (z + depth)) / math.cosh(k * depth)
        fz += rho * g * np.sum(pz * dadz * dz)
    # the steps between segments and the base: faces looking down (> 0) or up (< 0)
    for (z1, z2, d1, d2), nxt in zip(segments, segments[1:] + [None]):
        d_below = nxt[2] if nxt is not None else 0.0
        area = math.pi / 4 * (d2**2 - d_below**2)
        fz += rho * g * area * math.cosh(k * (z2 + depth)) / math.cosh(k * depth)
    return fh, mh, fz


def rows(segments, periods, headings, depth, rho, ca):
    out = []
    for h in headings:
        b = math.radians(h)
        for t in periods:
            fh, mh, fz = column_loads(segments, t, depth, rho, ca)
            comp = [fh * math.cos(b), fh * math.sin(b), fz,
                    -mh * math.sin(b), mh * math.cos(b), 0.0]
            base = [-90.0, -90.0, 0.0, -90.0, -90.0, 0.0]   # lags: the inertia leads
            amp, lag = [], []
            for c, p in zip(comp, base):
                amp.append(abs(c))
                lag.append(p + (180.0 if c < 0 else 0.0))
            out.append([t, h] + amp + lag)
    return out


def span(text):
    a, b, s = (float(v) for v in text.split(":"))
    return list(np.round(np.arange(a, b + 0.5 * s, s), 10))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--segments", required=True,
                    help="z_top,z_bottom,D_top,D_bottom of each segment, top down, ';' "
                         "between segments [m]")
    ap.add_argument("--depth", type=float, required=True, help="water depth [m]")
    ap.add_argument("--periods", default="4:30:0.5", help="first:last:step [s]")
    ap.add_argument("--headings", default="0:345:15", help="first:last:step [deg]")
    ap.add_argument("--rho", type=float, default=1025.0, help="water density [kg/m3]")
    ap.add_argument("--ca", type=float, default=1.0, help="added-mass coefficient [-]")
    a = ap.parse_args(argv)
    segs = [tuple(float(v) for v in s.split(",")) for s in a.segments.split(";")]
    sys.stdout.write("period_s, heading_deg, Fx, Fy, Fz, Mx, My, Mz, lag_Fx, lag_Fy, "
                     "lag_Fz, lag_Mx, lag_My, lag_Mz\n")
    for r in rows(segs, span(a.periods), span(a.headings), a.depth, a.rho, a.ca):
        sys.stdout.write(", ".join(f"{v:.10g}" for v in r) + "\n")


if __name__ == "__main__":
    main()
