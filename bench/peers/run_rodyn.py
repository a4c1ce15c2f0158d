#!/usr/bin/env python3
"""One rodyn run of the peers benchmark: writes the deck (template below) into a work
folder, runs `rodyn --quiet`, and saves top tension and mid-node history (.npz).

The deck writes HDF5 only, a frame every common.OUT_DT (the output times of every
tool), or with --every-step a frame every step (OUTPUT INTERVAL=0; used for the
reference). Saved: the frames at the output times as rodyn writes them (`top`): the
support force at the frame's time, interpolated by rodyn between the step-averaged
forces of the steps either side (docs/output.md, dynamic_ends.csv).

  python3 bench/peers/run_rodyn.py --case case4 --elements 30 --dt 0.0125 --out r.npz
"""
import argparse
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

# rodyn_post from this checkout: the peers' virtualenv (run_peers.py) has no copy of its own
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "postproc"))
from rodyn_post import load_dynamic  # noqa: E402

DECK = """** peers benchmark (bench/peers): the paper's cable, end A heaves 0.4 m at {f} Hz
** with the default 3 s ramp; {elements} elements of order {order}, DT={dt}
*HEADING
peers benchmark: paper cable, {case}, {elements} x p{order}, dt {dt}{scheme_note}
*GRAVITY
0.0, 0.0, -{g}
*SECTION, NAME=CABLE, OD={od}
{ea}, {ei}, {ei}, {gj}, {mass}
*LINE, NAME=CABLE, SECTION=CABLE, LENGTH={length}, ELEMENTS={elements}, ORDER={order}
0.0, 0.0, 0.0, 8.0, 0.0, -1.0
*BOUNDARY, LINE=CABLE, END=A, TYPE=PINNED
*BOUNDARY, LINE=CABLE, END=B, TYPE=PINNED
*MOTION, LINE=CABLE, END=A, TYPE=HARMONIC, RAMP={ramp}
Z, {amp}, {f}, 0.0
*DYNAMIC, DT={dt}, TIME={time}, OUTPUT INTERVAL={out_dt}{scheme}
*OUTPUT, CSV=NO, HDF5=YES
"""


def write_deck(path, case, elements, dt, order=3, t_end=common.T_END, scheme=None,
               every_step=False):
    text = DECK.format(
        f=common.CASES[case], case=case, elements=elements, order=order, dt=repr(dt),
        g=common.GRAVITY, od=common.OD, ea=common.EA, ei=common.EI, gj=common.GJ,
        mass=common.MASS, length=common.LENGTH, ramp=common.RAMP, amp=common.AMP,
        time=t_end, out_dt=0 if every_step else common.OUT_DT,
        scheme=f", SCHEME={scheme}" if scheme else "",
        scheme_note=f", {scheme}" if scheme else "")
    with open(path, "w") as fh:
        fh.write(text)


def run(rodyn, workdir, case, elements, dt, out, order=3, t_end=common.T_END, scheme=None,
        every_step=False):
    if (elements * order) % 2:
        raise ValueError("elements x order must be even to have a node at S = 5 m")
    steps_per_frame = common.OUT_DT / dt
    if abs(steps_per_frame - round(steps_per_frame)) > 1e-9:
        raise ValueError(f"dt {dt} must divide the output interval {common.OUT_DT}")
    os.makedirs(workdir, exist_ok=True)
    name = f"rodyn_{case}_{elements}p{order}_{dt:g}" + (f"_{scheme}" if scheme else "") \
        + ("_every" if every_step else "")
    deck = os.path.join(workdir, name + ".inp")
    write_deck(deck, case, elements, dt, order, t_end, scheme, every_step)
    folder = os.path.join(workdir, name)
    t0 = time.perf_counter()
    proc = subprocess.run([rodyn, deck, "-o", folder, "--quiet"], capture_output=True,
                          text=True)
    wall = time.perf_counter() - t0
    if proc.returncode not in (0, 2):
        raise RuntimeError(f"rodyn failed on {deck} (exit {proc.returncode}): {proc.stderr}")
    res = load_dynamic(folder)
    line = res.lines[0]
    k = int(np.argmin(np.abs(line.node_s - common.S_MID)))
    grid = np.arange(0, int(round(res.time[-1] / common.OUT_DT)) + 1) * common.OUT_DT
    idx = [int(np.argmin(np.abs(res.time - t))) for t in grid]
    if np.max(np.abs(res.time[idx] - grid)) > 1e-9:
        raise RuntimeError(f"{folder}: the frames miss the output times")
    mid = np.column_stack([line.x[idx, k], line.y[idx, k], line.z[idx, k]])
    top_all = line.end_tension[:, 0]
    extra = {}
    info = {"tool": "rodyn", "case": case, "elements": elements, "order": order, "dt": dt,
            "scheme": res.scheme, "complete": bool(res.complete), "status": res.status,
            "steps": int(res.steps), "newton_iterations": int(res.step_iterations),
            "wall_s": wall, "wall_dynamic_s": wall, "wall_total_s": wall,
            "status_wall_s": float(res.wall_time_s), "dofs": int(line.node_s.size) * 6,
            # static solve and time loop as rodyn times them inside the process
            # (status.txt's wall_time_s: without process start, deck reading and the
            # opening and closing of dynamic.h5; with the frames written during the loop)
            "wall_inprocess_s": float(res.wall_time_s)}
    info["every_step"] = every_step
    common.save_result(out, grid, top_all[idx], mid, info, **extra)
    return info


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(common.ROOT, "build", "rodyn"))
    ap.add_argument("--case", choices=list(common.CASES), required=True)
    ap.add_argument("--elements", type=int, required=True)
    ap.add_argument("--order", type=int, default=3)
    ap.add_argument("--dt", type=float, required=True)
    ap.add_argument("--time", type=float, default=common.T_END)
    ap.add_argument("--scheme", default=None)
    ap.add_argument("--every-step", action="store_true",
                    help="a frame every step (the reference's runs)")
    ap.add_argument("--workdir", default=os.path.join(common.HERE, ".work"))
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    info = run(os.path.abspath(a.rodyn), a.workdir, a.case, a.elements, a.dt, a.out,
               a.order, a.time, a.scheme, a.every_step)
    print(info)


if __name__ == "__main__":
    main()
