#!/usr/bin/env python3
"""The touchdown point within its bracket in every frame (docs/output.md, "Sign
conventions"): the mooring leg of input/mooring_surge.inp (120 cubic cable elements,
the fairlead surged 5 m) for 120 s, its touchdown moving across element boundaries.

usage: check_touchdown.py RODYN SOURCE_DIR WORK_DIR

In the static results and in every frame of the dynamic ones, the touchdown (CSV and
HDF5 alike) lies between the arc lengths of the two nodes that bracket the change from
seabed to suspended in that frame: the last node with a seabed normal force > 0 and
the node after it (read from the frame's contact forces, dynamic_nodes.csv and
/dynamic/LEG/seabed_normal). The touchdown must pass through more than one element
over the run (else the deck does not test what it is meant to).
"""
import csv
import pathlib
import subprocess
import sys
from collections import defaultdict

import numpy as np


def fail(msg):
    print(f"FAIL: {msg}", file=sys.stderr)
    sys.exit(1)


def bracket(s, normal):
    """(S_k, S_k+1) of the last node k in contact and the next; (S_n, S_n) when the last
    node is in contact; None when no node is."""
    touching = np.flatnonzero(np.asarray(normal) > 0.0)
    if touching.size == 0:
        return None
    k = touching[-1]
    return (s[k], s[k + 1]) if k + 1 < len(s) else (s[k], s[k])


def within(td, br):
    return (td == -1.0) if br is None else (br[0] <= td <= br[1])


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    exe, src, work = (pathlib.Path(a).resolve() for a in sys.argv[1:])
    out = work / "surge"
    p = subprocess.run([str(exe), str(src / "input" / "mooring_surge.inp"), "-o", str(out),
                        "-q"], capture_output=True, text=True, timeout=900)
    if p.returncode != 0:
        fail(f"rodyn exit {p.returncode}: {p.stderr}")
    import h5py

    # statics
    nodes = rows(out / "static_nodes.csv")
    s = np.array([float(r["s_m"]) for r in nodes])
    br = bracket(s, [float(r["seabed_normal_N_per_m"]) for r in nodes])
    td = float(rows(out / "static_lines.csv")[0]["touchdown_s_m"])
    with h5py.File(out / "results.h5", "r") as f:
        td_h5 = float(f["static/LEG"].attrs["touchdown_s"])
    if br is None or not within(td, br) or td_h5 != td:
        fail(f"statics: touchdown {td} m (results.h5 {td_h5}) outside {br}")
    print(f"statics: touchdown {td:.3f} m within [{br[0]:.3f}, {br[1]:.3f}] m")

    # element boundaries: element e spans nodes (e - 1) p + 1 ... e p + 1
    n_el = max(int(r["element"]) for r in rows(out / "static_elements.csv"))
    order = (len(s) - 1) // n_el
    bounds = s[::order]

    # every frame, from the CSV tables
    normal = defaultdict(list)
    node_s = defaultdict(list)
    for r in rows(out / "dynamic_nodes.csv"):
        normal[r["time_s"]].append(float(r["seabed_normal_N_per_m"]))
        node_s[r["time_s"]].append(float(r["s_m"]))
    frames = rows(out / "dynamic_lines.csv")
    outside, elements, tds = [], set(), []
    for r in frames:
        t, td = r["time_s"], float(r["touchdown_s_m"])
        br = bracket(np.array(node_s[t]), normal[t])
        if not within(td, br):
            outside.append((float(t), td, br))
        if td >= 0.0:
            elements.add(int(np.searchsorted(bounds, td, side="right")))
        tds.append(td)
    if outside:
        show = "; ".join(f"t = {t:g} s: {td:.3f} m outside [{b[0]:.3f}, {b[1]:.3f}]"
                         if b else f"t = {t:g} s: {td:.3f} m, no contact"
                         for t, td, b in outside[:5])
        fail(f"dynamic_lines.csv: {len(outside)} of {len(frames)} frames have the touchdown "
             f"outside its bracket: {show}")
    if len(elements) < 2:
        fail(f"the touchdown stays in element(s) {sorted(elements)}: no boundary crossed")

    # every frame, from dynamic.h5
    with h5py.File(out / "dynamic.h5", "r") as f:
        g = f["dynamic/LEG"]
        td_h5 = g["touchdown_s"][...]
        sn = g["seabed_normal"][...]
        s_h5 = g["node_s"][...]
    bad = [k for k in range(len(td_h5)) if not within(td_h5[k], bracket(s_h5, sn[k]))]
    if bad:
        fail(f"dynamic.h5: {len(bad)} of {len(td_h5)} frames have the touchdown outside its "
             f"bracket (first: frame {bad[0]}, {td_h5[bad[0]]:.3f} m)")
    if not np.array_equal(td_h5, np.array(tds)):
        fail("dynamic.h5 and dynamic_lines.csv give different touchdowns")
    print(f"{len(frames)} frames: every touchdown within its bracket (CSV and HDF5), "
          f"{min(tds):.3f} to {max(tds):.3f} m, through {len(elements)} elements "
          f"({min(elements)} to {max(elements)}) of {n_el}")
    print("OK")


if __name__ == "__main__":
    main()
