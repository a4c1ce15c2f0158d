#!/usr/bin/env python3
"""One MoorDyn (v2, Python package `moordyn`) run of the peers benchmark.

The line is one MoorDyn line of N segments between a Coupled point (end A, driven from
Python at every MoorDyn time step) and a Fixed point (end B), with the bending stiffness
in the EI column, no drag, no added mass and water density 0 (no buoyancy): the cable in
vacuum, as in rodyn.

Static start: MoorDyn's own initial-condition solvers need damping to settle, and in
vacuum there is none, so the static shape comes from a second system that differs only
where the static equilibrium does not look: water of 1025 kg/m3 with the mass per length
raised by the displaced mass (same net weight), and drag (Cd 1.2, scaled by CdScaleIC
during MoorDyn's dynamic relaxation, ICgenDynamic=1). Its state is passed with
moordyn.Serialize / moordyn.Deserialize to the vacuum system, started with Init_NoIC.

Motion: at each step k, moordyn.Step gets the position of end A at t_k and the velocity
(z(t_k+1) - z(t_k)) / dt, which MoorDyn extrapolates linearly over the step, so end A
follows the exact motion at every step end (piecewise linear in between).

Top tension: |moordyn.GetPointForce| of the Coupled point (the force of the line on it:
the end segment's tension and bending shear plus the end node's weight; MoorDyn does not
add the end node's inertia). Mid-line node: node N/2 (S = 5 m).

  python3 bench/peers/run_moordyn.py --case case4 --segments 20 --dt 1e-4 --out m.npz
"""
import argparse
import hashlib
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

DECK = """--------------------- MoorDyn Input File ------------------------------------
peers benchmark (bench/peers): the paper's cable, {purpose}
---------------------- LINE TYPES ----------------------------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
cable      {od}  {mass!r}   {ea:e}  {ba}   {ei:e}   {cd}    0.0    {cdax}     0.0
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Coupled    0.0     0.0   0.0    0      0       0      0
2     Fixed      8.0     0.0   -1.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     cable       1        2        {length}      {n}       -
---------------------- OPTIONS -----------------------------------------
0             writeLog
{dt!r}        dtM
{scheme}      tScheme
{g}           g
{rho}         rho
100.0         WtrDpth
{ic_options}
1             disableOutput
1             disableOutTime
------------------------- need this line -------------------------------------
"""
IC_OPTIONS = """1             ICgenDynamic
1.0           dtIC
{tmax_ic}     TmaxIC
{thresh_ic}   threshIC
5.0           CdScaleIC"""
RHO_IC = 1025.0
# a top tension above this ends the run as unstable (the reference peaks at ~51 kN)
UNSTABLE_N = 2.0e6


def deck_text(n, dt, ba, scheme, ic, tmax_ic=60.0, thresh_ic=1e-5):
    if ic:
        extra = RHO_IC * np.pi * common.OD**2 / 4.0
        return DECK.format(
            purpose="static start only: water with the displaced mass added to the line",
            od=common.OD, mass=common.MASS + extra, ea=common.EA, ba=ba, ei=common.EI,
            cd=1.2, cdax=0.0, length=common.LENGTH, n=n, dt=dt, scheme=scheme,
            g=common.GRAVITY, rho=RHO_IC,
            ic_options=IC_OPTIONS.format(tmax_ic=tmax_ic, thresh_ic=thresh_ic))
    return DECK.format(
        purpose="in vacuum (rho 0, no drag, no added mass)", od=common.OD,
        mass=common.MASS, ea=common.EA, ba=ba, ei=common.EI, cd=0.0, cdax=0.0,
        length=common.LENGTH, n=n, dt=dt, scheme=scheme, g=common.GRAVITY, rho=0.0,
        ic_options="")


def ic_dt(n):
    """Time step of the static-start system (RK2, BA -1): stable below ~2e-4 s for
    0.5 m segments; scaled with the segment length."""
    return 1.0e-4 * (common.LENGTH / n) / 0.5


def static_state(moordyn, n, workdir, quiet, scheme="RK2"):
    """Serialized static state of the line with n segments (cached in workdir); the
    time scheme must be the dynamic run's (the state layout depends on it)."""
    text = deck_text(n, ic_dt(n), -1.0, scheme, True)
    key = hashlib.sha1(text.encode()).hexdigest()[:12]
    cache = os.path.join(workdir, f"moordyn_ic_{n}_{key}.bin")
    if os.path.exists(cache):
        with open(cache, "rb") as fh:
            return fh.read(), 0.0
    path = os.path.join(workdir, f"moordyn_ic_{n}_{scheme}.txt")
    with open(path, "w") as fh:
        fh.write(text)
    sw = common.Stopwatch()
    s = moordyn.Create(path)
    moordyn.Init(s, list(common.END_A), [0.0, 0.0, 0.0])
    data = moordyn.Serialize(s)
    moordyn.Close(s)
    wall = sw()
    with open(cache, "wb") as fh:
        fh.write(data)
    return data, wall


def run(workdir, case, n, dt, out, ba=-0.5, scheme="RK2", t_end=common.T_END,
        quiet=True):
    import moordyn
    if n % 2:
        raise ValueError("the number of segments must be even (node N/2 at S = 5 m)")
    every = common.OUT_DT / dt
    if abs(every - round(every)) > 1e-6:
        raise ValueError(f"dt {dt} must divide the output interval {common.OUT_DT}")
    every = int(round(every))
    os.makedirs(workdir, exist_ok=True)
    data, wall_ic = static_state(moordyn, n, workdir, quiet, scheme)
    f = common.CASES[case]
    path = os.path.join(workdir, f"moordyn_{case}_{n}_{dt:g}_{ba:g}_{scheme}.txt")
    with open(path, "w") as fh:
        fh.write(deck_text(n, dt, ba, scheme, False))
    steps = int(round(t_end / dt))
    times = np.arange(steps + 1) * dt
    z = common.motion(times, f)[0]
    vz = np.diff(z) / dt
    xa, ya = common.END_A[0], common.END_A[1]
    sw = common.Stopwatch()
    s = moordyn.Create(path)
    moordyn.Init_NoIC(s, list(common.END_A), [0.0, 0.0, 0.0])
    moordyn.Deserialize(s, data)
    line = moordyn.GetLine(s, 1)
    point = moordyn.GetPoint(s, 1)
    wall_setup = sw()
    t_out, top, mid = [0.0], [], []
    top.append(float(np.linalg.norm(moordyn.GetPointForce(point))))
    mid.append(moordyn.GetLineNodePos(line, n // 2))
    failed = ""
    sw = common.Stopwatch()
    step = moordyn.Step
    for k in range(steps):
        step(s, [xa, ya, z[k]], [0.0, 0.0, vz[k]], times[k], dt)
        if (k + 1) % every == 0:
            fz = moordyn.GetPointForce(point)
            tt = float(np.linalg.norm(fz))
            t_out.append(times[k + 1])
            top.append(tt)
            mid.append(moordyn.GetLineNodePos(line, n // 2))
            if not np.isfinite(tt) or tt > UNSTABLE_N:
                failed = f"unstable at t = {times[k + 1]:g} s"
                break
    wall_dyn = sw()
    moordyn.Close(s)
    info = {"tool": "MoorDyn", "case": case, "segments": n, "dt": dt, "ba": ba,
            "scheme": scheme, "complete": not failed, "status": failed or "complete",
            "steps": steps, "wall_s": wall_dyn, "wall_dynamic_s": wall_dyn,
            "wall_setup_s": wall_setup, "wall_static_s": wall_ic,
            "wall_total_s": wall_dyn + wall_setup + wall_ic,
            "version": getattr(moordyn, "__version__", "")}
    common.save_result(out, t_out, top, np.array(mid), info)
    return info


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--case", choices=list(common.CASES), required=True)
    ap.add_argument("--segments", type=int, required=True)
    ap.add_argument("--dt", type=float, required=True)
    ap.add_argument("--ba", type=float, default=-0.5,
                    help="BA/-zeta column: internal damping [N s], or minus the damping ratio")
    ap.add_argument("--scheme", default="RK2")
    ap.add_argument("--time", type=float, default=common.T_END)
    ap.add_argument("--workdir", default=os.path.join(common.HERE, ".work"))
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    print(run(a.workdir, a.case, a.segments, a.dt, a.out, a.ba, a.scheme, a.time))


if __name__ == "__main__":
    main()
