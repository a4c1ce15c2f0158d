#!/usr/bin/env python3
"""One CableDyn (Python package `cabledyn`, its native library in-process) run of the
peers benchmark.

The deck is a MoorDyn-style CableDyn deck (template below): one finite-EI line of N
cubic-Hermite elements from a Coupled point (end A) to a Fixed point (end B), pinned at
both ends (no END CONNECTIONS row), with the 14-column LINE TYPES row giving the shear
stiffness (= EA, as rodyn's default), GJ and the rotary inertias of rodyn (m OD^2/16
about the section axes, twice that about the line axis). No drag, no added mass; CableDyn
refuses a water density of 0, so rhoW is 1e-6 kg/m3 (buoyancy 3.5e-10 of the weight).

Static start: CableDyn's Newton static solve at initialisation. Each step,
CableDyn.step(dt, q, v, a) gets the exact position, velocity and acceleration of end A
at t + dt (the host-coupling boundary of the C API); generalised-alpha with the default
spectral radius (rhoInf 0.4) unless --rho-inf is given.

Top tension: |force the line exerts at the coupled point| from CableDyn.calc_output()
(the coupled reaction loads). Mid-line node: node N/2 (S = 5 m).

  python3 bench/peers/run_cabledyn.py --case case4 --elements 20 --dt 0.01 --out c.npz
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

DECK = """--------------------- CableDyn Input File ------------------------------------
peers benchmark (bench/peers): the paper's cable in vacuum, {n} elements, dtM {dt}
--------------------- LINE TYPES ---------------------------------------
TypeName Diam   MassDenInAir EA      BA/-zeta EI       GAs     GJ      Irt     Irn     Cd_n Cd_t Ca_n Ca_t
(-)      (m)    (kg/m)       (N)     (N-s/-)  (N-m^2)  (N)     (N-m^2) (kg-m)  (kg-m)  (-)  (-)  (-)  (-)
cable    {od}  {mass}  {ea:e}  {ba}   {ei:e}  {ea:e}  {gj:e}  {irt!r}  {irn!r}  0.0  0.0  0.0  0.0
--------------------- POINTS -------------------------------------------
ID    Type      X        Y      Z         Mass    Vol     CdA    Ca
(-)   (-)       (m)      (m)    (m)       (kg)    (m^3)   (m^2)  (-)
1     Coupled   0.0      0.0    0.0       0       0       0      0
2     Fixed     8.0      0.0    -1.0      0       0       0      0
--------------------- LINES --------------------------------------------
ID    NodeA   NodeB   Outputs
(-)   (-)     (-)     (-)
1     1       2       -
--------------------- SECTIONS -----------------------------------------
LineID   LineType   Length   NumSegs
(-)      (-)        (m)      (-)
1        cable      {length}    {n}
--------------------- OPTIONS ------------------------------------------
{g}      g         - Gravitational acceleration (m/s^2)
1.0e-6       rhoW      - Water density (kg/m^3): CableDyn needs > 0; in vacuum
{dt!r}      dtM       - time step (s)
{t_end!r}   TMax      - end time (s)
{rho_inf!r}   rhoInf    - generalised-alpha spectral radius
--------------------- OUTPUTS ------------------------------------------
"FairTen1"
--------------------- need this line -----------------------------------
"""


def deck_text(n, dt, t_end, rho_inf, ba=0.0):
    return DECK.format(n=n, dt=dt, od=common.OD, mass=common.MASS, ea=common.EA, ba=ba,
                       ei=common.EI, gj=common.GJ, irt=common.RHOI, irn=2.0 * common.RHOI,
                       length=common.LENGTH, g=common.GRAVITY, t_end=t_end,
                       rho_inf=rho_inf)


def run(workdir, case, n, dt, out, rho_inf=0.4, t_end=common.T_END):
    import cabledyn
    from cabledyn.model import CableDyn
    if n % 2:
        raise ValueError("the number of elements must be even (node N/2 at S = 5 m)")
    every = common.OUT_DT / dt
    if abs(every - round(every)) > 1e-6:
        raise ValueError(f"dt {dt} must divide the output interval {common.OUT_DT}")
    every = int(round(every))
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, f"cabledyn_{case}_{n}_{dt:g}_{rho_inf:g}.dat")
    with open(path, "w") as fh:
        fh.write(deck_text(n, dt, t_end, rho_inf))
    f = common.CASES[case]
    steps = int(round(t_end / dt))
    times = np.arange(steps + 1) * dt
    z, vz, az = common.motion(times, f)
    xa, ya = common.END_A[0], common.END_A[1]
    sw = common.Stopwatch()
    model = CableDyn(path)
    wall_static = sw()
    line = model.line(1)
    mid_node = n // 2
    t_out, top, mid = [0.0], [], []
    top.append(float(np.linalg.norm(model.calc_output()[:3])))
    mid.append(line.node_positions().reshape(-1, 3)[mid_node].copy()
               if line.node_positions().ndim == 1 else line.node_positions()[mid_node].copy())
    failed, iters = "", 0
    sw = common.Stopwatch()
    for k in range(steps):
        try:
            iters += model.step(dt, [xa, ya, z[k + 1]], [0.0, 0.0, vz[k + 1]],
                                [0.0, 0.0, az[k + 1]])
        except Exception as exc:  # noqa: BLE001 - any failure ends the run, reported
            failed = f"failed at t = {times[k + 1]:g} s: {exc}"
            break
        if (k + 1) % every == 0:
            t_out.append(times[k + 1])
            top.append(float(np.linalg.norm(model.calc_output()[:3])))
            p = line.node_positions()
            p = p.reshape(-1, 3) if p.ndim == 1 else p
            mid.append(p[mid_node].copy())
    wall_dyn = sw()
    model.close()
    info = {"tool": "CableDyn", "case": case, "elements": n, "dt": dt, "rho_inf": rho_inf,
            "complete": not failed, "status": failed or "complete", "steps": steps,
            "newton_iterations": iters, "wall_s": wall_dyn, "wall_dynamic_s": wall_dyn,
            "wall_static_s": wall_static, "wall_total_s": wall_dyn + wall_static,
            "version": getattr(cabledyn, "__version__", "")}
    common.save_result(out, t_out, top, np.array(mid), info)
    return info


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--case", choices=list(common.CASES), required=True)
    ap.add_argument("--elements", type=int, required=True)
    ap.add_argument("--dt", type=float, required=True)
    ap.add_argument("--rho-inf", type=float, default=0.4)
    ap.add_argument("--time", type=float, default=common.T_END)
    ap.add_argument("--workdir", default=os.path.join(common.HERE, ".work"))
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    print(run(a.workdir, a.case, a.elements, a.dt, a.out, a.rho_inf, a.time))


if __name__ == "__main__":
    main()
