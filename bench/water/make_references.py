#!/usr/bin/env python3
"""Regenerates every reference of bench/water/reference/ (see bench/water/README.md).

  closed form  catenary_seabed.py  -> mooring_static_closed_form.json
  MoorPy       moorpy_static.py    -> moorpy_static.json
  MoorDyn      moordyn_leg.py      -> moordyn_surge_summary.json, moordyn_surge_fairlead.csv,
                                      moordyn_current_static.json, moordyn/leg_N.dat
  CableDyn     cabledyn_riser.py   -> cabledyn_riser.json, cabledyn_riser_heave.csv (the
                                      lazy-wave cable of input/riser_lazy_wave*.inp)

MoorDyn runs are cached in bench/water/.work/ (git-ignored); --fresh re-runs them.
Needs numpy, and `pip install moorpy moordyn cabledyn==0.3.0` for the peers (--skip-peers:
closed form only).

  python3 bench/water/make_references.py [--segments 20 40 80 160] [--fresh]
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run(args):
    print("+", " ".join(args), flush=True)
    subprocess.run([sys.executable] + args, check=True, cwd=HERE)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80, 160],
                    help="MoorDyn segment counts of the surge study (the last is the "
                         "finest: its history goes to the CSV, it is re-run at dt/2)")
    ap.add_argument("--current-segments", type=int, nargs="+", default=[20, 40, 80],
                    help="MoorDyn segment counts of case (c)")
    ap.add_argument("--fresh", action="store_true", help="re-run cached MoorDyn runs")
    ap.add_argument("--skip-peers", action="store_true", help="closed form only")
    a = ap.parse_args()
    if a.skip_peers:
        run(["catenary_seabed.py", "--no-moorpy"])
        return
    run(["catenary_seabed.py"])
    run(["moorpy_static.py"])
    seg = [str(n) for n in a.segments]
    run(["moordyn_leg.py", "--decks-only", "--segments"] + seg)
    run(["moordyn_leg.py", "--references", "--segments"] + seg + (["--fresh"] if a.fresh else []))
    run(["moordyn_leg.py", "--current", "--segments"] + [str(n) for n in a.current_segments])
    run(["cabledyn_riser.py"])


if __name__ == "__main__":
    main()
