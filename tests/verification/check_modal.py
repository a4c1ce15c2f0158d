#!/usr/bin/env python3
"""The modal analysis of a system (*MODAL, docs/theory.md eqs. (145)-(148)) against closed
forms.

string: decks/modal_string.inp, a taut cable (L = 99.9 m pulled to s = 100 m, EA 1e8 N,
10 kg/m) on 10, 20 and 40 cubic elements: the transverse periods 2 s / n, T = 2 s /
(n sqrt(T_0 s / m)), n = 1 .. 10 (two planes each), and the first axial period 2 L /
sqrt(EA / rhoA), told apart by their shapes, within 1e-4 on 20 elements; the observed
order of convergence of the first transverse and axial periods at least 3.5 between
each pair of meshes.

body: decks/modal_body_springs.inp, a body on uncoupled springs with an added mass in
every direction: the six periods 2 pi sqrt((m + A_ii) / k_i), each mode along its one
direction (shape of R), within 1e-6, and equal to the rigid-body periods of
static_body_modes.csv within 1e-9.

spar: decks/modal_spar.inp, the OC3-Hywind spar on its chains (20 cubic elements a line,
a FREE body and three lines joined through it): the ten longest periods by SOLVER=DENSE
(LAPACK) and SOLVER=LANCZOS (ARPACK) within 1e-9 of each other, the longest (surge) in
the spar (share of the kinetic energy above 0.9).

decay: decks/modal_spar_decay.inp, the same spar without drag released from 20 kN: the
surge period of R's x fitted over 1800 s (three sinusoids and a constant, least squares)
within 1 % of *MODAL's longest period about the equilibrium without the force.

Usage: check_modal.py RODYN DECK_DIR OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import re
import subprocess
import sys

EA, L, S, MU = 1.0e8, 99.9, 100.0, 10.0
DOFS = ("x", "y", "z", "rx", "ry", "rz")


def run(rodyn, deck, out, *sets):
    args = [rodyn, deck, "-o", out, "--quiet"]
    for s in sets:
        args += ["--set", s]
    proc = subprocess.run(args, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "static_modes.csv")) as f:
        modes = list(csv.DictReader(f))
    with open(os.path.join(out, "static_mode_shapes.csv")) as f:
        shapes = list(csv.DictReader(f))
    return modes, shapes


def string_periods(rodyn, deck, out, n):
    """Transverse periods in order (x-motion below 1e-6 of the largest) and axial."""
    modes, shapes = run(rodyn, deck, os.path.join(out, f"string_{n}"), f"N={n}")
    big = {}
    for r in shapes:
        k = int(r["mode"])
        b = big.setdefault(k, [0.0, 0.0])
        b[0] = max(b[0], abs(float(r["x"])))
        b[1] = max(b[1], abs(float(r["y"])), abs(float(r["z"])))
    trans = [float(m["period_s"]) for m in modes if big[int(m["mode"])][0] < 1e-6]
    axial = [float(m["period_s"]) for m in modes if big[int(m["mode"])][1] < 1e-6]
    return trans, axial


def check_string(rodyn, decks, out, fails):
    tension = EA * (S / L - 1.0)
    closed = [1.0 / (n / (2 * S) * math.sqrt(tension * S / (MU * L))) for n in range(1, 11)]
    axial_closed = 2 * L / math.sqrt(EA / MU)
    first = {}
    for n in (10, 20, 40):
        trans, axial = string_periods(rodyn, os.path.join(decks, "modal_string.inp"), out, n)
        if len(trans) < 20 or not axial:
            fails.append(f"string on {n} elements: {len(trans)} transverse and "
                         f"{len(axial)} axial modes found")
            return
        errs = [abs(trans[2 * i + j] / closed[i] - 1) for i in range(10) for j in (0, 1)]
        ax = abs(axial[0] / axial_closed - 1)
        first[n] = (errs[0], ax)
        print(f"string, {n} elements: transverse n = 1..10 largest error {max(errs):.2e} "
              f"(n = 1: {errs[0]:.2e}); axial n = 1: {axial[0]:.9f} s, error {ax:.2e}")
        if n == 20 and not (max(errs) <= 1e-4 and ax <= 1e-4):
            fails.append(f"string on 20 elements: errors {max(errs):.2e}, {ax:.2e} > 1e-4")
    for a, b in ((10, 20), (20, 40)):
        for i, name in enumerate(("transverse", "axial")):
            order = math.log(first[a][i] / first[b][i]) / math.log(b / a)
            print(f"string, {name} n = 1: observed order {order:.2f} ({a} -> {b} elements)")
            if not order >= 3.5:
                fails.append(f"string {name}: order {order:.2f} < 3.5 ({a} -> {b})")


def check_body(rodyn, decks, out, fails):
    out = os.path.join(out, "body")
    modes, shapes = run(rodyn, os.path.join(decks, "modal_body_springs.inp"), out)
    added = (200.0, 300.0, 500.0, 10.0, 25.0, 35.0)
    inertia = (1000.0,) * 3 + (100.0,) * 3
    stiff = (1.0e5, 1.0e5, 1.0e5 + 1.0, 1.0e4, 1.0e4, 1.0e4)   # the thread's EA/L in z
    closed = {d: 2 * math.pi * math.sqrt((m + a) / k)
              for d, m, a, k in zip(DOFS, inertia, added, stiff)}
    with open(os.path.join(out, "static_body_modes.csv")) as f:
        rigid = sorted((float(r["period_s"]) for r in csv.DictReader(f)), reverse=True)
    seen = set()
    for m, p_rigid in zip(modes, rigid):
        row = next(r for r in shapes if r["mode"] == m["mode"] and r["object"] == "BOX")
        shape = {d: float(row[d]) for d in DOFS}
        along = max(shape, key=lambda d: abs(shape[d]))
        period = float(m["period_s"])
        err = abs(period / closed[along] - 1)
        err_rigid = abs(period / p_rigid - 1)
        seen.add(along)
        print(f"body mode {m['mode']}: {period:.12f} s along {along}: closed form "
              f"{err:.1e}, rigid-body period {err_rigid:.1e}")
        if not err <= 1e-6:
            fails.append(f"body mode {m['mode']} ({along}) off the closed form by {err:.2e}")
        if not err_rigid <= 1e-9:
            fails.append(f"body mode {m['mode']} off static_body_modes by {err_rigid:.2e}")
    if seen != set(DOFS):
        fails.append(f"the body's modes are along {sorted(seen)}, not all six directions")


def check_spar(rodyn, decks, out, fails):
    deck = os.path.join(decks, "modal_spar.inp")
    dense, _ = run(rodyn, deck, os.path.join(out, "spar_dense"), "SOLVER=DENSE")
    lanczos, _ = run(rodyn, deck, os.path.join(out, "spar_lanczos"), "SOLVER=LANCZOS")
    if len(dense) != 10 or len(lanczos) != 10:
        fails.append(f"spar: {len(dense)} dense and {len(lanczos)} Lanczos modes, not 10")
        return
    diff = max(abs(float(a["period_s"]) / float(b["period_s"]) - 1)
               for a, b in zip(dense, lanczos))
    first = lanczos[0]
    print(f"spar: ten periods {float(lanczos[0]['period_s']):.3f} s to "
          f"{float(lanczos[-1]['period_s']):.3f} s; DENSE and LANCZOS differ by {diff:.1e}; "
          f"mode 1 in {first['dominant']} ({float(first['share']):.3f})")
    if not diff <= 1e-9:
        fails.append(f"spar: the solvers' periods differ by {diff:.2e}")
    if first["dominant"] != "SPAR" or not float(first["share"]) > 0.9:
        fails.append(f"spar: mode 1 in {first['dominant']} ({first['share']}), not the spar")


def check_decay(rodyn, decks, out, fails):
    import numpy as np
    from scipy.optimize import curve_fit
    deck = os.path.join(decks, "modal_spar_decay.inp")
    with open(deck) as f:
        text = f.read()
    modal_deck = os.path.join(out, "spar_modal.inp")
    os.makedirs(out, exist_ok=True)
    with open(modal_deck, "w") as f:
        f.write(re.sub(r"^\*DYNAMIC.*$", "*MODAL, MODES=3", text, flags=re.M))
    modes, _ = run(rodyn, modal_deck, os.path.join(out, "spar_modal"), "F=0.0")
    decay = os.path.join(out, "spar_decay")
    proc = subprocess.run([rodyn, deck, "-o", decay, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        fails.append(f"decay: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
        return
    with open(os.path.join(decay, "dynamic_bodies.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    x = np.array([float(r["x_m"]) for r in rows])

    def waves(t, c, *p):
        return c + sum(p[3 * k] * np.cos(p[3 * k + 2] * t) + p[3 * k + 1] *
                       np.sin(p[3 * k + 2] * t) for k in range(3))

    start = [float(modes[k]["period_s"]) for k in range(3)]
    p0 = [0.0]
    for k, period in enumerate(start):
        p0 += [0.5 if k == 0 else 0.01, 0.0, 2 * math.pi / period]
    p, _ = curve_fit(waves, t, x, p0=p0, maxfev=20000)
    fitted = 2 * math.pi / p[3]
    err = abs(fitted / start[0] - 1)
    print(f"decay: surge of R fitted {fitted:.3f} s over {t[-1]:.0f} s; *MODAL "
          f"{start[0]:.3f} s; difference {err:.1e}")
    if not err <= 0.01:
        fails.append(f"decay: surge period {fitted:.3f} s, *MODAL's {start[0]:.3f} s")


def main():
    rodyn, decks, out = sys.argv[1:4]
    fails = []
    check_string(rodyn, decks, out, fails)
    check_body(rodyn, decks, out, fails)
    check_spar(rodyn, decks, out, fails)
    check_decay(rodyn, decks, out, fails)
    for msg in fails:
        print("FAIL:", msg)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
