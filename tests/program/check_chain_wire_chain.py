#!/usr/bin/env python3
"""input/chain_wire_chain.inp (the README's worked example) against the catenary.

    check_chain_wire_chain.py RODYN DECK WORK_DIR [T_END]

Runs the deck (with --set T_END=... when given) into WORK_DIR and checks its statics
against the elastic catenary of a line of segments on a frictionless seabed, computed
here from the deck's own *SECTION, *SEGMENT, *LINE, *WATER and *GRAVITY cards: from the
touchdown point up, each segment of submerged weight w, axial stiffness EA and length L
hangs as the elastic catenary carrying the vertical force V0 at its lower end,

    x = H/w (asinh(V1/H) - asinh(V0/H)) + H L/EA,
    z = H/w (sqrt(1 + (V1/H)^2) - sqrt(1 + (V0/H)^2)) + (V1^2 - V0^2)/(2 w EA),

V1 = V0 + w L, and the grounded length Lg lies straight with tension H. H and Lg are
found (by bisection) so that the line spans the deck's anchor-to-fairlead distances.
Checked: the horizontal tension and the fairlead tension within 0.1 %, the touchdown
arc length within a fifth of the local element. Then the dynamics: every step's tension
at both ends positive (the line never goes slack) and finite, every frame's touchdown on
the bottom chain. Prints the figures the README quotes: static tensions and touchdown
beside the catenary's, and the extremes of the fairlead tension and the touchdown after
the ramp-in beside the catenary's at each point of the fairlead's orbit (quasi-static).
"""
import csv
import math
import os
import subprocess
import sys


def cards(path):
    """The deck's keyword cards: (keyword, {param: value}, [data rows])."""
    out = []
    params = {}
    for raw in open(path, encoding="utf-8"):
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        for name, value in params.items():
            line = line.replace("<" + name + ">", value)
        if line.startswith("*"):
            parts = [p.strip() for p in line[1:].split(",")]
            kw = dict(p.split("=", 1) for p in parts[1:] if "=" in p)
            out.append((parts[0].upper(), {k.strip().upper(): v.strip() for k, v in kw.items()},
                        []))
        elif out and out[-1][0] == "PARAMETER":
            name, value = (s.strip() for s in line.split("=", 1))
            params[name.upper()] = value
        elif out:
            out[-1][2].append([v.strip() for v in line.split(",")])
    return out


def model(path):
    """Segments (L, w, EA, elements) from end A, anchor and fairlead points, depth."""
    grav, rho, sections, segments, ends, water = 9.80665, 1025.0, {}, [], None, None
    for kw, p, rows in cards(path):
        if kw == "GRAVITY":
            grav = -float(rows[0][2])
        elif kw == "WATER":
            rho = float(p.get("DENSITY", 1025.0))
            water = float(p.get("SURFACE", 0.0)) - float(p["DEPTH"])
        elif kw == "SECTION":
            ea, mass = float(rows[0][0]), float(rows[0][4])
            d = float(p.get("BUOYANCY DIAMETER", p["OD"]))
            sections[p["NAME"]] = (ea, mass, d)
        elif kw == "LINE":
            ends = [float(v) for v in rows[0]]
        elif kw == "SEGMENT":
            segments.append((p["SECTION"], float(p["LENGTH"]), int(p["ELEMENTS"])))
    segs = []
    for name, length, elements in segments:
        ea, mass, d = sections[name]
        segs.append((length, (mass - rho * math.pi * d * d / 4.0) * grav, ea, elements))
    return segs, ends[:3], ends[3:], water


def catenary(segs, H, Lg):
    """Span, rise, fairlead tension and vertical force of the line with H and Lg."""
    x, z, V, left = 0.0, 0.0, 0.0, Lg
    for L, w, EA, _ in segs:
        on_bed = min(left, L)
        left -= on_bed
        x += on_bed * (1.0 + H / EA)
        Ls = L - on_bed
        if Ls <= 0.0:
            continue
        V1 = V + w * Ls
        x += H / w * (math.asinh(V1 / H) - math.asinh(V / H)) + H * Ls / EA
        z += (H / w * (math.hypot(1.0, V1 / H) - math.hypot(1.0, V / H))
              + (V1 * V1 - V * V) / (2.0 * w * EA))
        V = V1
    return x, z, math.hypot(H, V), V


def bisect(f, a, b):
    fa = f(a)
    for _ in range(80):
        m = 0.5 * (a + b)
        fm = f(m)
        if (fm > 0.0) == (fa > 0.0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def solve(segs, span, rise):
    """H and the grounded length Lg (< the first segment) giving span and rise."""
    first = segs[0][0]

    def grounded(H):
        return bisect(lambda Lg: catenary(segs, H, Lg)[1] - rise, 0.0, first * (1 - 1e-12))

    H = bisect(lambda H: catenary(segs, H, grounded(H))[0] - span, 1e3, 1e8)
    Lg = grounded(H)
    return H, Lg, catenary(segs, H, Lg)[2]


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def main():
    rodyn, deck, work = sys.argv[1:4]
    t_end = sys.argv[4] if len(sys.argv) > 4 else None
    out = os.path.join(work, "chain_wire_chain")
    os.makedirs(work, exist_ok=True)
    cmd = [rodyn, deck, "-o", out, "--quiet"] + (["--set", "T_END=" + t_end] if t_end else [])
    if os.path.exists(out):
        subprocess.run(["rm", "-rf", out], check=True)
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL: {' '.join(cmd)} exited {run.returncode}\n{run.stderr}")
        return 1
    segs, anchor, fair, bed = model(deck)
    if abs(anchor[2] - bed) > 1e-9 or anchor[1] != fair[1]:
        print("FAIL: the check wants the anchor on a flat seabed, in the x-z plane")
        return 1
    span, rise = abs(fair[0] - anchor[0]), fair[2] - anchor[2]
    H, Lg, T = solve(segs, span, rise)
    reac = {r["end"]: r for r in rows(os.path.join(out, "static_reactions.csv"))}
    H_r, T_r = abs(float(reac["B"]["Fx_N"])), float(reac["B"]["tension_N"])
    td_r = float(rows(os.path.join(out, "static_lines.csv"))[0]["touchdown_s_m"])
    le = segs[0][0] / segs[0][3]
    fails = []
    print(f"statics: horizontal tension {H_r / 1e3:.2f} kN (catenary {H / 1e3:.2f} kN), "
          f"fairlead tension {T_r / 1e3:.2f} kN (catenary {T / 1e3:.2f} kN), "
          f"touchdown {td_r:.2f} m from the anchor (catenary {Lg:.2f} m)")
    for name, got, want in (("horizontal tension", H_r, H), ("fairlead tension", T_r, T)):
        if abs(got - want) > 1e-3 * want:
            fails.append(f"{name} {got:.6g} N, the catenary's {want:.6g} N (over 0.1 %)")
    if abs(td_r - Lg) > 0.2 * le:
        fails.append(f"touchdown {td_r:.3f} m, the catenary's {Lg:.3f} m (over {0.2 * le} m)")

    # the dynamics: no slack, nothing infinite, touchdown on the bottom chain
    ramp, motion = 3.0, {}
    for kw, p, data in cards(deck):
        if kw == "MOTION":
            ramp = float(p.get("RAMP", 3.0))
            motion = {r[0].upper(): [float(v) for v in r[1:]] for r in data}
    steps = rows(os.path.join(out, "dynamic_ends_step.csv"))
    tension = {"A": [], "B": []}
    for r in steps:
        t, ten = float(r["time_s"]), float(r["tension_N"])
        if not (math.isfinite(ten) and ten > 0.0):
            fails.append(f"end {r['end']} tension {ten} at t = {t} s")
        tension[r["end"]].append((t, ten))
    frames = [(float(r["time_s"]), float(r["touchdown_s_m"]))
              for r in rows(os.path.join(out, "dynamic_lines.csv"))]
    for t, td in frames:
        if not 0.0 < td < segs[0][0]:
            fails.append(f"touchdown {td} m at t = {t} s, not on the bottom chain")
    late_t = [ten for t, ten in tension["B"] if t >= ramp]
    late_td = [td for t, td in frames if t >= ramp]
    if late_t:
        # the catenary at each point of the fairlead's orbit (the motion at full amplitude)
        # (one frequency for every direction: the orbit is one closed curve)
        if len({freq for _, freq, _ in motion.values()}) != 1:
            fails.append("the check wants one frequency for every direction of *MOTION")
            motion = {}
        qs = []
        for k in range(36):
            dx, dz = 0.0, 0.0
            for axis, (amp, _, phase) in motion.items():
                u = amp * math.sin(2 * math.pi * k / 36.0 + math.radians(phase))
                dx += u if axis in ("X", "1") else 0.0
                dz += u if axis in ("Z", "3") else 0.0
            qs.append(solve(segs, span + math.copysign(1.0, fair[0] - anchor[0]) * dx,
                            rise + dz))
        print(f"dynamics after the {ramp:g} s ramp-in: fairlead tension "
              f"{min(late_t) / 1e3:.1f} to {max(late_t) / 1e3:.1f} kN (quasi-static "
              f"catenary over the orbit {min(q[2] for q in qs) / 1e3:.1f} to "
              f"{max(q[2] for q in qs) / 1e3:.1f} kN); touchdown {min(late_td):.1f} to "
              f"{max(late_td):.1f} m (quasi-static {min(q[1] for q in qs):.1f} to "
              f"{max(q[1] for q in qs):.1f} m)")
    for f in fails[:20]:
        print("FAIL:", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
