#!/usr/bin/env python3
"""CableDyn reference for the lazy-wave cable of input/riser_lazy_wave.inp and
riser_lazy_wave_heave.inp (bench/water/riser.py): writes
bench/water/reference/cabledyn_riser.json (static equilibrium) and
bench/water/reference/cabledyn_riser_heave.csv (top force in the 3 m, 12 s heave).

CableDyn (Seo et al. 2026, Ocean Engineering 368, 128332; PyPI package `cabledyn`, in
process through its C API) is an independent finite-EI code: cubic-Hermite Kirchhoff-rod
elements (position and tangent, no rotations), penalty seabed, generalised-alpha. It is
given the same cable as rodyn: the deck below is CableDyn's own example
lozon_gomex80_power_cable.dat (the article's 1024-element mesh, 448/320/256 elements per
section from the hang-off), with dtM and TMax added because the Python API requires them.
Both ends are ball joints (no END CONNECTIONS row), the seabed frictionless (kBot 1e5
Pa/m, cBot 1e4 Pa s/m). In the heave, the coupled hang-off point gets the exact
position, velocity and acceleration of rodyn's *MOTION at every step (dt 0.05 s,
rhoInf 0.4, CableDyn's default); the top force is the load CableDyn.calc_output()
returns at the coupled point (the force of the line on the hang-off).

  python3 -m pip install cabledyn==0.3.0
  python3 bench/water/cabledyn_riser.py [--segments 448 320 256] [--out-dir DIR]
"""
import argparse
import csv
import json
import math
import os
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import leg  # noqa: E402  (sig)
import riser  # noqa: E402

DECK = """--------------------- CableDyn Input File ------------------------------------
Lozon et al. (2025) Gulf of Mexico 80 m lazy-wave dynamic power cable (bench/water/riser.py)
--------------------- LINE TYPES ---------------------------------------------
TypeName  Diam   MassDenInAir  EA       BA   EI       Cd_n  Cd_t  Ca_n  Ca_t
(-)       (m)    (kg/m)        (N)      (-)  (N-m2)   (-)   (-)   (-)   (-)
bare      0.160  36.70         4.69e8   0.0  1.99e4   1.2   0.1   1.0   0.0
buoy      0.290  59.53         4.69e8   0.0  1.99e4   1.2   0.1   1.0   0.0
--------------------- POINTS ------------------------------------------------
ID  Type     X       Y    Z
(-) (-)      (m)     (m)  (m)
1   Coupled  5.0     0.0  -14.0
2   Fixed    125.0   0.0  -80.0
--------------------- LINES -------------------------------------------------
ID  NodeA  NodeB  Outputs
(-) (-)    (-)    (-)
1   1      2      -
--------------------- SECTIONS ----------------------------------------------
LineID  LineType  Length   NumSegs
(-)     (-)       (m)      (-)
1       bare      68.114   {n1}
1       buoy      50.000   {n2}
1       bare      52.101   {n3}
--------------------- OPTIONS -----------------------------------------------
9.80665  g
1025.0   rhoW
80.0     WtrDpth
1.0e5    kBot
1.0e4    cBot
{dt}     dtM
{tmax}   TMax
--------------------- OUTPUTS -----------------------------------------------
"FairTen1"
"AnchTen1"
"FairIncl1"
--------------------- need this line ----------------------------------------
"""


def unstretched_s(segments):
    """Unstretched arc length of the nodes from the hang-off (uniform per section)."""
    s, s0 = [0.0], 0.0
    for (_, length, _, _), n in zip(riser.SECTIONS, segments):
        s += [s0 + length * k / n for k in range(1, n + 1)]
        s0 += length
    return np.array(s)


def static(path, segments):
    from cabledyn.model import CableDyn
    t0 = time.perf_counter()
    m = CableDyn(path)
    wall = time.perf_counter() - t0
    line = m.line(1)
    p = np.asarray(line.node_positions(), float).reshape(-1, 3)
    k = np.abs(np.asarray(line.curvature(), float))
    f = m.calc_output()[:3]              # force of the line on the hang-off
    s = unstretched_s(segments)
    r = {"s_m": s, "x_m": p[:, 0], "z_m": p[:, 2], "curv_s_m": s, "curv_per_m": k}
    r.update(riser.features(r))
    fair, anch, incl = m.channels(["FairTen1", "AnchTen1", "FairIncl1"])
    m.close()
    return r, {"top_tension_N": float(np.linalg.norm(f)), "top_H_N": float(f[0]),
               "top_V_N": float(-f[2]), "FairTen_N": fair, "AnchTen_N": anch,
               "FairIncl_deg": incl, "wall_static_s": wall}


def heave(path):
    from cabledyn.model import CableDyn
    t0 = time.perf_counter()
    m = CableDyn(path)
    x0, y0, z0 = riser.HANGOFF
    rows = [(0.0, *m.calc_output()[:3])]
    n = int(round(riser.T_END / riser.DT))
    for k in range(1, n + 1):
        t = k * riser.DT
        u, v, a = riser.heave(t)
        m.step(riser.DT, [x0, y0, z0 + u], [0.0, 0.0, v], [0.0, 0.0, a])
        rows.append((t, *m.calc_output()[:3]))
    m.close()
    return rows, time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--segments", type=int, nargs=3, default=[448, 320, 256],
                    help="Hermite elements per section from the hang-off")
    ap.add_argument("--coarse", type=int, nargs=3, default=[136, 100, 104],
                    help="a coarser mesh, for CableDyn's own mesh convergence")
    ap.add_argument("--out-dir", default=os.path.join(HERE, "reference"))
    a = ap.parse_args()
    import cabledyn
    with tempfile.TemporaryDirectory() as tmp:
        def deck(seg, tmax):
            path = os.path.join(tmp, f"riser_{'_'.join(map(str, seg))}_{tmax:g}.dat")
            with open(path, "w") as f:
                f.write(DECK.format(n1=seg[0], n2=seg[1], n3=seg[2], dt=riser.DT, tmax=tmax))
            return path
        fine, fine_ends = static(deck(a.segments, riser.T_END), a.segments)
        coarse, coarse_ends = static(deck(a.coarse, riser.T_END), a.coarse)
        rows, wall_dyn = heave(deck(a.segments, riser.T_END))
    keys = ["sag_z_m", "sag_s_m", "sag_x_m", "hog_z_m", "hog_s_m", "hog_x_m", "touchdown_s_m",
            "hangoff_angle_deg", "peak_curvature_per_m", "peak_curvature_s_m"]
    out = {"tool": "CableDyn", "version": getattr(cabledyn, "__version__", ""),
           "deck": DECK.format(n1=a.segments[0], n2=a.segments[1], n3=a.segments[2],
                               dt=riser.DT, tmax=riser.T_END),
           "segments": a.segments,
           "static": {**{k: leg.sig(v) for k, v in fine_ends.items()},
                      **{k: leg.sig(fine[k]) for k in keys}},
           "coarse": {"segments": a.coarse,
                      **{k: leg.sig(v) for k, v in coarse_ends.items()},
                      **{k: leg.sig(coarse[k]) for k in keys}},
           "shape": {"s_m": leg.sig(fine["s_m"], 10), "x_m": leg.sig(fine["x_m"], 10),
                     "z_m": leg.sig(fine["z_m"], 10),
                     "curvature_per_m": leg.sig(fine["curv_per_m"], 8)},
           "heave": {"dt_s": riser.DT, "t_end_s": riser.T_END, "rho_inf": 0.4,
                     "wall_s": wall_dyn}}
    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "cabledyn_riser.json"), "w") as f:
        json.dump(out, f, indent=1)
    with open(os.path.join(a.out_dir, "cabledyn_riser_heave.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s", "top_tension_N", "Fx_N", "Fy_N", "Fz_N"])
        for t, fx, fy, fz in rows:
            w.writerow([f"{t:.4f}", f"{math.sqrt(fx * fx + fy * fy + fz * fz):.10g}",
                        f"{fx:.10g}", f"{fy:.10g}", f"{fz:.10g}"])
    st = out["static"]
    print(f"CableDyn {out['version']}, {sum(a.segments)} elements: top tension "
          f"{st['top_tension_N']:.3f} N, H {st['top_H_N']:.3f} N, angle "
          f"{st['hangoff_angle_deg']:.3f} deg, touchdown {st['touchdown_s_m']:.3f} m, peak "
          f"curvature {st['peak_curvature_per_m']:.5f} 1/m at {st['peak_curvature_s_m']:.2f} m; "
          f"heave {wall_dyn:.1f} s")


if __name__ == "__main__":
    main()
