#!/usr/bin/env python3
"""One OpenSees (Python package `openseespy`) run of the peers benchmark.

Model: the cable in its vertical plane (x, z; the motion keeps it planar), N
elasticBeamColumn elements with the Corotational transformation (E = 1, A = EA,
I = EI), consistent mass (-cMass, 226.7 kg/m; no rotary inertia), weight as lumped
nodal loads (m g h / 2 at each element end), in vacuum. End A is held in x and driven in
z (MultipleSupport pattern, imposedMotion with the exact displacement, velocity and
acceleration series), end B is pinned; rotations are free at both ends.

Static start: OpenSees has no prestressed start, so the beam is built straight and
stress-free, 10 m long from end A towards end B, and the static analysis (Newton, load
control in STATIC_STEPS increments) first applies the weight with end B held at the
beam's end, then moves end B to (8, 0, -1) m. Dynamics: Newmark average acceleration
(gamma 1/2, beta 1/4; no numerical damping) unless --alpha is given (HHT, alpha in
[2/3, 1]), Newton with NormDispIncr.

Top tension: |reaction at end A| with the inertia forces (ops.reactions('-dynamic')),
i.e. the support force on the line. Mid-line node: node N/2 + 1 (S = 5 m).

  python3 bench/peers/run_opensees.py --case case4 --elements 40 --dt 0.00625 --out o.npz
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

STATIC_STEPS = 300     # load-control increments of the static start
MOVE = 5.0             # pseudo-time over which end B is moved


def build(ops, n):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    xa, za = common.END_A[0], common.END_A[2]
    xb, zb = common.END_B[0], common.END_B[2]
    chord = math.hypot(xb - xa, zb - za)
    ux, uz = (xb - xa) / chord, (zb - za) / chord
    h = common.LENGTH / n
    for i in range(n + 1):
        ops.node(i + 1, xa + i * h * ux, za + i * h * uz)
    ops.fix(1, 1, 1, 0)
    ops.geomTransf("Corotational", 1)
    for e in range(n):
        ops.element("elasticBeamColumn", e + 1, e + 1, e + 2, common.EA, 1.0, common.EI, 1,
                    "-mass", common.MASS, "-cMass")
    # static, in pseudo-time: the weight from 0 to 1 over [0, 1] with end B held at the
    # end of the straight beam, then end B moved to its place over [1, 1 + MOVE]
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 1.0e6, "-values", 0.0, 1.0, 1.0)
    ops.pattern("Plain", 1, 1)
    w = common.MASS * common.GRAVITY * h
    for i in range(n + 1):
        share = 0.5 if i in (0, n) else 1.0
        ops.load(i + 1, 0.0, -w * share, 0.0)
    ops.timeSeries("Path", 5, "-time", 0.0, 1.0, 1.0 + MOVE, 1.0e6,
                   "-values", 0.0, 0.0, 1.0, 1.0)
    ops.pattern("Plain", 5, 5)
    ops.sp(n + 1, 1, xb - (xa + common.LENGTH * ux))
    ops.sp(n + 1, 2, zb - (za + common.LENGTH * uz))
    return h


def static(ops):
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", (1.0 + MOVE) / STATIC_STEPS)
    ops.analysis("Static")
    if ops.analyze(STATIC_STEPS) != 0:
        raise RuntimeError("static analysis failed")
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()


def run(workdir, case, n, dt, out, alpha=None, t_end=common.T_END):
    import openseespy.opensees as ops
    if n % 2:
        raise ValueError("the number of elements must be even (a node at S = 5 m)")
    every = common.OUT_DT / dt
    if abs(every - round(every)) > 1e-6:
        raise ValueError(f"dt {dt} must divide the output interval {common.OUT_DT}")
    every = int(round(every))
    f = common.CASES[case]
    sw = common.Stopwatch()
    build(ops, n)
    static(ops)
    wall_static = sw()
    steps = int(round(t_end / dt))
    times = np.arange(steps + 2) * dt
    z, vz, az = common.motion(times, f)
    ops.timeSeries("Path", 2, "-dt", dt, "-values", *z.tolist())
    ops.timeSeries("Path", 3, "-dt", dt, "-values", *vz.tolist())
    ops.timeSeries("Path", 4, "-dt", dt, "-values", *az.tolist())
    ops.pattern("MultipleSupport", 2)
    ops.groundMotion(1, "Plain", "-disp", 2, "-vel", 3, "-accel", 4)
    ops.imposedMotion(1, 2, 1)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-10, 30)
    ops.algorithm("Newton")
    if alpha is None:
        ops.integrator("Newmark", 0.5, 0.25)
    else:
        ops.integrator("HHT", alpha)
    ops.analysis("Transient")
    mid_node = n // 2 + 1

    def sample():
        ops.reactions("-dynamic")
        r = ops.nodeReaction(1)
        c = ops.nodeCoord(mid_node)
        d = ops.nodeDisp(mid_node)
        return math.hypot(r[0], r[1]), (c[0] + d[0], 0.0, c[1] + d[1])

    t_out, top, mid = [0.0], [], []
    t0, m0 = sample()
    top.append(t0)
    mid.append(m0)
    failed = ""
    sw = common.Stopwatch()
    for k in range(steps // every):
        if ops.analyze(every, dt) != 0:
            failed = f"failed near t = {(k + 1) * every * dt:g} s"
            break
        tt, mm = sample()
        t_out.append((k + 1) * every * dt)
        top.append(tt)
        mid.append(mm)
    wall_dyn = sw()
    ops.wipe()
    info = {"tool": "OpenSees", "case": case, "elements": n, "dt": dt, "alpha": alpha,
            "complete": not failed, "status": failed or "complete", "steps": steps,
            "wall_s": wall_dyn, "wall_dynamic_s": wall_dyn, "wall_static_s": wall_static,
            "wall_total_s": wall_dyn + wall_static}
    common.save_result(out, t_out, top, np.array(mid), info)
    return info


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--case", choices=list(common.CASES), required=True)
    ap.add_argument("--elements", type=int, required=True)
    ap.add_argument("--dt", type=float, required=True)
    ap.add_argument("--alpha", type=float, default=None, help="HHT alpha (default: Newmark)")
    ap.add_argument("--time", type=float, default=common.T_END)
    ap.add_argument("--workdir", default=os.path.join(common.HERE, ".work"))
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    print(run(a.workdir, a.case, a.elements, a.dt, a.out, a.alpha, a.time))


if __name__ == "__main__":
    main()
