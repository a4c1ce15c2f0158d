#!/usr/bin/env python3
"""The rigid-body natural periods of the OC3-Hywind spar on its three chains (*MODAL,
docs/theory.md eqs. (145)-(148), (152)-(153)) against the published ones, on
decks/oc3_periods.inp (its sources in its comments: the spar's mass and inertia with the
turbine's, its WAMIT added mass about the waterline as a 6 x 6 matrix, *BODY ADDED MASS,
FORM=MATRIX, and the report's additional yaw spring).

published: J. Jonkman, "Definition of the Floating System for Phase IV of OC3",
NREL/TP-500-47535, 2010, Table 7-1, the full-system natural frequencies of FAST's
linearised model (flexible tower, rotor parked): surge and sway 0.0080 Hz, heave 0.0324
Hz, roll 0.0342 Hz, pitch 0.0343 Hz, yaw 0.1210 Hz. The spar's modes among *MODAL's are
told apart by the motion of R (static_mode_shapes.csv, object SPAR): the largest of |x|,
|y|, |z| and 100 m times |rx|, |ry|, |rz| (a pitch about the fairleads moves R by 70 m a
radian, a surge turns it by under 1e-4 rad a metre); each period within 3 % of the
published one, the spar holding more than 0.9 of the mode's kinetic energy.

decay: the same spar held pitched by a moment of 30 MN m at R in the statics, released
over the first step, 200 s of dynamics (EMC, dt 0.2 s, the lines' drag on): the pitch
period fitted to R's ry (two sinusoids and a constant, least squares) within 1e-3 of
*MODAL's pitch period.

Usage: check_oc3_periods.py RODYN DECK OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import re
import subprocess
import sys

PUBLISHED_HZ = {"surge": 0.0080, "sway": 0.0080, "heave": 0.0324, "roll": 0.0342,
                "pitch": 0.0343, "yaw": 0.1210}
MOTION = {"x": "surge", "y": "sway", "z": "heave", "rx": "roll", "ry": "pitch",
          "rz": "yaw"}
ARM = 100.0          # m: a rotation's weight against a translation of R
MOMENT = 3.0e7       # N m, the decay's pitch moment at R


def run(rodyn, deck, out):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")


def spar_modes(out):
    """{motion: (period, share)} of the spar's modes, the longest of each kind."""
    with open(os.path.join(out, "static_modes.csv")) as f:
        modes = {r["mode"]: r for r in csv.DictReader(f)}
    found = {}
    with open(os.path.join(out, "static_mode_shapes.csv")) as f:
        for r in csv.DictReader(f):
            if r["object"] != "SPAR" or modes[r["mode"]]["dominant"] != "SPAR":
                continue
            size = {d: abs(float(r[d])) * (ARM if d.startswith("r") else 1.0)
                    for d in MOTION}
            kind = MOTION[max(size, key=size.get)]
            m = modes[r["mode"]]
            if kind not in found:
                found[kind] = (float(m["period_s"]), float(m["share"]))
    return found


def check_periods(found, fails):
    for kind, hz in PUBLISHED_HZ.items():
        if kind not in found:
            fails.append(f"no {kind} mode of the spar among *MODAL's")
            continue
        period, share = found[kind]
        diff = period * hz - 1.0
        print(f"{kind}: {period:.3f} s (share {share:.3f}), published {1.0 / hz:.3f} s "
              f"({hz} Hz): {100.0 * diff:+.2f} %")
        if not abs(diff) <= 0.03:
            fails.append(f"{kind}: {period:.3f} s, {100.0 * diff:+.2f} % off the published")
        if not share > 0.9:
            fails.append(f"{kind}: the spar holds {share:.3f} of the mode's energy")


def check_decay(rodyn, deck, out, pitch, fails):
    import numpy as np
    from scipy.optimize import curve_fit
    with open(deck) as f:
        text = f.read()
    load = ("*AMPLITUDE, NAME=RELEASE\n0.0, 1.0\n0.2, 0.0\n*LOAD, BODY=SPAR, "
            f"AMPLITUDE=RELEASE\n0.0, 0.0, 0.0, 0.0, {MOMENT}, 0.0\n*STATIC")
    text = re.sub(r"^\*STATIC", load.replace("\\", "\\\\"), text, flags=re.M)
    text = re.sub(r"^\*MODAL.*$", "*DYNAMIC, DT=0.2, TIME=200.0, OUTPUT INTERVAL=0.2",
                  text, flags=re.M)
    os.makedirs(out, exist_ok=True)
    decay_deck = os.path.join(out, "oc3_pitch_decay.inp")
    with open(decay_deck, "w") as f:
        f.write(text)
    run(rodyn, decay_deck, out)
    with open(os.path.join(out, "dynamic_bodies.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    ry = np.array([float(r["ry_rad"]) for r in rows])

    def waves(t, c, a1, b1, w1, a2, b2, w2):
        return (c + a1 * np.cos(w1 * t) + b1 * np.sin(w1 * t) + a2 * np.cos(w2 * t) +
                b2 * np.sin(w2 * t))

    p0 = [0.0, ry[0], 0.0, 2 * math.pi / pitch, 0.0, 0.0, 2 * math.pi / 120.0]
    p, _ = curve_fit(waves, t, ry, p0=p0, maxfev=20000)
    fitted = 2 * math.pi / p[3]
    err = abs(fitted / pitch - 1)
    print(f"decay: pitch of R from {ry[0]:.4f} rad, fitted {fitted:.4f} s over "
          f"{t[-1]:.0f} s; *MODAL {pitch:.4f} s; difference {err:.1e}")
    if not err <= 1e-3:
        fails.append(f"decay: pitch period {fitted:.4f} s, *MODAL's {pitch:.4f} s")


def main():
    rodyn, deck, out = sys.argv[1:4]
    fails = []
    run(rodyn, deck, os.path.join(out, "modal"))
    found = spar_modes(os.path.join(out, "modal"))
    check_periods(found, fails)
    if "pitch" in found:
        check_decay(rodyn, deck, os.path.join(out, "decay"), found["pitch"][0], fails)
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
