#!/usr/bin/env python3
"""A coupled body (*MOTION, BODY= on a FIXED body): a chain on a point of a body moved
harmonically (decks/coupled_body.inp) against the same chain with its end moved directly
by *MOTION, LINE= (decks/coupled_end.inp), EMC, 300 steps: the end force at every step
within 1e-6 of its largest value and every node within 1e-6 m; a coupled point (*MOTION,
POINT=, decks/coupled_point.inp) moves its line end as the direct motion does: every
table equal byte for byte (the same prescribed node); the body's R follows
the prescribed motion (within 1e-12 m); every step keeps EMC's energy identity with the
moved body's work booked (300 steps, no cut-back).

A body moved with a vessel (*MOTION, BODY=, TYPE=VESSEL; decks/coupled_vessel_body.inp:
the vessel's six motions from a table, rolling 2, pitching 3 and yawing 4 degrees, at 20
degrees of heading) against the same chain's end fixed to the vessel directly
(decks/coupled_vessel_end.inp): the same comparisons, and the body's R and its rotation
vector on the vessel's rigid motion X = O + R0 (xi + Rv p), Q = R0 Rv R0^T (1e-12). A
point moved with that vessel (*MOTION, POINT=, TYPE=VESSEL; decks/coupled_vessel_point.inp)
moves the chain's end as the direct motion does: every table equal byte for byte.

A rod clamped to that body (*POINT, CONNECTION=CLAMPED; decks/clamped_vessel_body.inp)
against the rod's top clamped to the vessel directly (decks/clamped_vessel_end.inp): its
top's force and moment within 1e-6 of their largest values, its nodes within 1e-6 m.

Usage: check_coupled_body.py RODYN DECK_DIR OUT_DIR. Exit 0 on success."""
import csv
import math
import os
import subprocess
import sys

import numpy as np


def run(rodyn, deck, out):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: {deck}: exit {proc.returncode}: {proc.stderr.strip()}")


def rows(out, name):
    with open(os.path.join(out, name)) as f:
        return list(csv.DictReader(f))


def ramp(t, r=5.0):
    """The *MOTION ramp (docs/deck.md): (1 - cos(pi t / r)) / 2 over r seconds."""
    return 1.0 if t >= r else 0.5 * (1.0 - math.cos(math.pi * t / r))


def compare(body, end, fails, moments=False):
    """End B's force (and moment) and the nodes of a run through a body against the
    direct one's."""
    fb = [r for r in rows(body, "dynamic_ends_step.csv") if r["end"] == "B"]
    fe = [r for r in rows(end, "dynamic_ends_step.csv") if r["end"] == "B"]
    keys = ("Fx_N", "Fy_N", "Fz_N")
    scale = max(abs(float(r[k])) for r in fe for k in keys)
    dforce = max(abs(float(a[k]) - float(b[k])) for a, b in zip(fb, fe) for k in keys)
    if moments:
        mk = ("Mx_Nm", "My_Nm", "Mz_Nm")
        mscale = max(abs(float(r[k])) for r in fe for k in mk)
        dmom = max(abs(float(a[k]) - float(b[k])) for a, b in zip(fb, fe) for k in mk)
        print(f"{os.path.basename(body)}: end moment: largest difference "
              f"{dmom / mscale:.1e} of {mscale:.4g} N m")
        if not dmom <= 1e-6 * mscale:
            fails.append(f"end moment differs by {dmom / mscale:.2e}")
    nb, ne = rows(body, "dynamic_nodes.csv"), rows(end, "dynamic_nodes.csv")
    dnode = max(abs(float(a[k]) - float(b[k])) for a, b in zip(nb, ne)
                for k in ("x_m", "y_m", "z_m"))
    print(f"{os.path.basename(body)}: end force: {len(fb)} steps, largest difference "
          f"{dforce / scale:.1e} of {scale:.4g} N; nodes: {len(nb)} rows, largest "
          f"difference {dnode:.1e} m")
    if len(fb) != len(fe) or len(fb) < 300 or not dforce <= 1e-6 * scale:
        fails.append(f"end force differs by {dforce / scale:.2e}")
    if len(nb) != len(ne) or not dnode <= 1e-6:
        fails.append(f"nodes differ by {dnode:.2e} m")


def rot(axis, a):
    c, s = math.cos(a), math.sin(a)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m = np.eye(3)
    m[i, i] = m[j, j] = c
    m[i, j], m[j, i] = -s, s
    return m


def rotation_vector(q):
    angle = math.acos(max(-1.0, min(1.0, (np.trace(q) - 1) / 2)))
    if angle < 1e-12:
        return np.zeros(3)
    w = np.array([q[2, 1] - q[1, 2], q[0, 2] - q[2, 0], q[1, 0] - q[0, 1]])
    return angle / (2 * math.sin(angle)) * w


def vessel_path(decks, body, fails):
    """The body's R and rotation on the vessel's rigid motion (docs/vessels.md)."""
    table = np.loadtxt(os.path.join(decks, "vessel_motion.csv"), delimiter=",", skiprows=1)
    o, psi0 = np.array([2.0, -1.0, 0.0]), math.radians(20.0)
    r0 = rot(2, psi0)
    p = r0.T @ (np.zeros(3) - o)          # R at rest (the origin) in vessel axes
    dr = dq = 0.0
    for r in rows(body, "dynamic_bodies.csv"):
        t = float(r["time_s"])
        xi = np.array([np.interp(t, table[:, 0], table[:, k]) for k in range(1, 7)])
        ang = np.radians(xi[3:])
        rv = rot(2, ang[2]) @ rot(1, ang[1]) @ rot(0, ang[0])
        x = o + r0 @ (xi[:3] + rv @ p)
        th = rotation_vector(r0 @ rv @ r0.T)
        dr = max(dr, np.abs(x - [float(r[k]) for k in ("x_m", "y_m", "z_m")]).max())
        dq = max(dq, np.abs(th - [float(r[k]) for k in ("rx_rad", "ry_rad", "rz_rad")]).max())
    print(f"the vessel's body: R within {dr:.1e} m, rotation within {dq:.1e} rad of the "
          "vessel's motion")
    if not (dr <= 1e-12 and dq <= 1e-12):
        fails.append(f"the vessel's body off its motion by {dr:.2e} m, {dq:.2e} rad")


def no_cutbacks(body, fails):
    """EMC's energy identity (theory.md (43)) is checked by the run at every step, with
    the moved body's work booked: a step breaking it would have been cut back."""
    log = rows(body, "dynamic_log.csv")
    cut = sum(int(r["cutbacks"]) for r in log)
    work = float(log[-1]["external_work_J"])
    print(f"{len(log)} steps, {cut} cut-backs; work of the moved body and the loads by "
          f"the end {work:.4g} J")
    if len(log) != 300 or cut != 0:
        fails.append(f"{len(log)} steps and {cut} cut-backs (300 and 0 expected)")


def same_tables(what, a, b, fails):
    """The node, end-force and element tables of two runs equal byte for byte."""
    for table in ("dynamic_nodes.csv", "dynamic_ends_step.csv", "dynamic_elements.csv"):
        with open(os.path.join(a, table), "rb") as f, open(os.path.join(b, table), "rb") as g:
            same = f.read() == g.read()
        print(f"{what}: {table} {'equal' if same else 'DIFFERENT'} byte for byte")
        if not same:
            fails.append(f"the {what}'s {table} differs from the direct motion's")


def main():
    rodyn, decks, out = sys.argv[1:4]
    body, end = os.path.join(out, "body"), os.path.join(out, "end")
    run(rodyn, os.path.join(decks, "coupled_body.inp"), body)
    run(rodyn, os.path.join(decks, "coupled_end.inp"), end)
    fails = []
    compare(body, end, fails)
    point = os.path.join(out, "point")
    run(rodyn, os.path.join(decks, "coupled_point.inp"), point)
    same_tables("coupled point", point, end, fails)
    dr = 0.0
    for r in rows(body, "dynamic_bodies.csv"):
        t = float(r["time_s"])
        x = 3.0 * ramp(t) * math.sin(2 * math.pi * 0.1 * t)
        z = 1.0 * ramp(t) * math.sin(2 * math.pi * 0.1 * t + math.pi / 2)
        dr = max(dr, abs(float(r["x_m"]) - x), abs(float(r["z_m"]) - z))
    print(f"the body's R against the prescribed motion: {dr:.1e} m")
    if not dr <= 1e-12:
        fails.append(f"R off the prescribed motion by {dr:.2e} m")
    no_cutbacks(body, fails)
    vbody, vend = os.path.join(out, "vessel_body"), os.path.join(out, "vessel_end")
    run(rodyn, os.path.join(decks, "coupled_vessel_body.inp"), vbody)
    run(rodyn, os.path.join(decks, "coupled_vessel_end.inp"), vend)
    compare(vbody, vend, fails)
    vpoint = os.path.join(out, "vessel_point")
    run(rodyn, os.path.join(decks, "coupled_vessel_point.inp"), vpoint)
    same_tables("point moved with the vessel", vpoint, vend, fails)
    vessel_path(decks, vbody, fails)
    no_cutbacks(vbody, fails)
    cbody, cend = os.path.join(out, "clamped_body"), os.path.join(out, "clamped_end")
    run(rodyn, os.path.join(decks, "clamped_vessel_body.inp"), cbody)
    run(rodyn, os.path.join(decks, "clamped_vessel_end.inp"), cend)
    compare(cbody, cend, fails, moments=True)
    no_cutbacks(cbody, fails)
    for msg in fails:
        print("FAIL:", msg)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
