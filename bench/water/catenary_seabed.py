#!/usr/bin/env python3
"""Closed-form elastic catenary with a flat, frictionless seabed (and fully suspended).

Source: J. Jonkman, "Dynamics of Offshore Floating Wind Turbines - Model Development and
Verification", Wind Energy 12 (2009) 459-492, and NREL/TP-500-41958 (2007), Section 4.2
("quasi-static mooring line module", eqs. for the elastic catenary with seabed contact);
the same equations are in MAP++'s documentation (NREL/TP-500-47535 lists the FAST
mooring routine) and in MoorPy's `Catenary.catenary` (adapted from FAST v7's
`Catenary` subroutine). Here the seabed friction coefficient C_B = 0.

Frame: end A (anchor) at the origin on the seabed, x horizontal towards end B
(fairlead), z up. Unknowns: the horizontal tension H (constant along the line, no
friction) and the fairlead's vertical tension V_F. w is the submerged weight per
unstretched length, L the unstretched length, EA the axial stiffness (linear:
strain = T / EA, weight carried by the unstretched length).

Touching the seabed (grounded length L_B = L - V_F / w >= 0):
    X_F = L_B + (H/w) asinh(V_F/H) + H L / EA
    Z_F = (H/w) (sqrt(1 + (V_F/H)^2) - 1) + V_F^2 / (2 EA w)
Fully suspended (V_A = V_F - w L > 0 is the anchor's vertical tension):
    X_F = (H/w) (asinh(V_F/H) - asinh(V_A/H)) + H L / EA
    Z_F = (H/w) (sqrt(1 + (V_F/H)^2) - sqrt(1 + (V_A/H)^2)) + (V_F L - w L^2 / 2) / EA

Shape along the unstretched arc length s from the anchor (grounded case):
    s <= L_B: x = s (1 + H / EA), z = 0
    s >  L_B: x = L_B + (H/w) asinh(w (s - L_B) / H) + H s / EA
              z = (H/w) (sqrt(1 + (w (s - L_B) / H)^2) - 1) + w (s - L_B)^2 / (2 EA)
Tension T(s) = sqrt(H^2 + V(s)^2), V(s) = w max(0, s - L_B) (suspended: V_A + w s).

Solved by Newton's method with the analytic Jacobian, iterated until the step stops
decreasing (round-off). Run as a script: solves the issue's leg, cross-checks against
MoorPy's catenary (if MoorPy is installed) and writes
bench/water/reference/mooring_static_closed_form.json.

  python3 bench/water/catenary_seabed.py [--out FILE] [--no-moorpy]
"""
import argparse
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import leg  # noqa: E402


def _residual(h, v, xf, zf, length, ea, w, grounded):
    r = v / h
    sr = math.sqrt(1.0 + r * r)
    if grounded:
        lb = length - v / w
        fx = lb + h / w * math.asinh(r) + h * length / ea - xf
        fz = h / w * (sr - 1.0) + v * v / (2.0 * ea * w) - zf
        j = np.array([[math.asinh(r) / w - r / (w * sr) + length / ea,
                       -1.0 / w + 1.0 / (w * sr)],
                      [(sr - 1.0) / w - r * r / (w * sr),
                       r / (w * sr) + v / (ea * w)]])
    else:
        b = (v - w * length) / h
        sb = math.sqrt(1.0 + b * b)
        fx = h / w * (math.asinh(r) - math.asinh(b)) + h * length / ea - xf
        fz = h / w * (sr - sb) + (v * length - 0.5 * w * length**2) / ea - zf
        j = np.array([[(math.asinh(r) - math.asinh(b)) / w - (r / sr - b / sb) / w
                       + length / ea,
                       (1.0 / sr - 1.0 / sb) / w],
                      [(sr - sb) / w - (r * r / sr - b * b / sb) / w,
                       (r / sr - b / sb) / w + length / ea]])
    return np.array([fx, fz]), j


def _newton(xf, zf, length, ea, w, grounded, h0, v0, maxit=200):
    h, v = h0, v0
    last = math.inf
    small = 0
    for it in range(maxit):
        f, j = _residual(h, v, xf, zf, length, ea, w, grounded)
        dh, dv = np.linalg.solve(j, -f)
        # keep H positive (halve the step)
        lam = 1.0
        while h + lam * dh <= 0.0:
            lam *= 0.5
        h, v = h + lam * dh, v + lam * dv
        size = abs(dh) / h + abs(dv) / max(abs(v), h)
        # converged: the relative step is at round-off, or stopped decreasing there
        if size < 1e-15 or (size < 1e-12 and size >= last):
            small += 1
            if small >= 2:
                break
        last = size
    f, _ = _residual(h, v, xf, zf, length, ea, w, grounded)
    return h, v, it + 1, f


def solve(xf=leg.XF, zf=leg.ZF, length=leg.LENGTH, ea=leg.EA, w=leg.W_SUB):
    """Static elastic catenary from an anchor on a flat frictionless seabed (end A at
    the origin) to a fairlead at horizontal distance xf and height zf above it.
    Returns a dict with H, V_F, tensions, grounded length, touchdown and a shape
    function."""
    # initial guess of Peyrot & Goulois (as in FAST / MoorPy)
    chord = math.hypot(xf, zf)
    if length <= chord:
        lam = 0.2
    else:
        lam = math.sqrt(3.0 * ((length**2 - zf**2) / xf**2 - 1.0))
    h0 = abs(0.5 * w * xf / lam)
    v0 = 0.5 * w * (zf / math.tanh(lam) + length)
    # try the grounded regime first; if L_B < 0 it is fully suspended
    h, v, it, res = _newton(xf, zf, length, ea, w, True, h0, min(v0, w * length), )
    grounded = length - v / w >= 0.0
    if not grounded:
        h, v, it, res = _newton(xf, zf, length, ea, w, False, h0, v0)
    lb = max(0.0, length - v / w) if grounded else 0.0
    va = 0.0 if grounded else v - w * length

    def shape(s):
        """(x, z) relative to the anchor, and tension, at unstretched arc length s."""
        s = np.asarray(s, dtype=float)
        if grounded:
            u = np.maximum(s - lb, 0.0)
            x = np.where(s <= lb, s * (1.0 + h / ea),
                         lb + h / w * np.arcsinh(w * u / h) + h * s / ea)
            z = np.where(s <= lb, 0.0,
                         h / w * (np.sqrt(1.0 + (w * u / h)**2) - 1.0)
                         + w * u**2 / (2.0 * ea))
            vv = w * u
        else:
            vv = va + w * s
            x = h / w * (np.arcsinh(vv / h) - np.arcsinh(va / h)) + h * s / ea
            z = (h / w * (np.sqrt(1.0 + (vv / h)**2) - np.sqrt(1.0 + (va / h)**2))
                 + (va * s + 0.5 * w * s**2) / ea)
        return x, z, np.sqrt(h * h + vv * vv)

    return {"H": h, "V_F": v, "V_A": va, "grounded": grounded,
            "fairlead_tension": math.hypot(h, v), "anchor_tension": math.hypot(h, va),
            "grounded_length": lb, "touchdown_arc_length": lb,
            "touchdown_x": lb * (1.0 + h / ea) if grounded else 0.0,
            "iterations": it, "residual_m": [float(res[0]), float(res[1])],
            "shape": shape, "w": w}


def moorpy_check(sol, xf=leg.XF, zf=leg.ZF, length=leg.LENGTH, ea=leg.EA, w=leg.W_SUB):
    """MoorPy's catenary (Jonkman's equations, its own Newton solver) on the same leg."""
    from moorpy.Catenary import catenary
    fah, fav, fbh, fbv, info = catenary(xf, zf, length, ea, w, CB=0.0, Tol=1e-12,
                                        MaxIter=500)
    import moorpy
    out = {"moorpy_version": getattr(moorpy, "__version__", ""),
           "H": info["HF"], "V_F": info["VF"], "LBot": info["LBot"],
           "fairlead_tension": math.hypot(info["HF"], info["VF"]),
           "anchor_tension": math.hypot(fah, fav)}
    out["rel_diff"] = {k: abs(out[k] - sol[k2]) / abs(sol[k2]) for k, k2 in
                       (("H", "H"), ("V_F", "V_F"), ("fairlead_tension", "fairlead_tension"),
                        ("anchor_tension", "anchor_tension"))}
    out["rel_diff"]["LBot"] = abs(out["LBot"] - sol["grounded_length"]) / length
    return out


def leg_result(with_moorpy=True):
    sol = solve()
    xa, ya, za = leg.ANCHOR
    s = np.linspace(0.0, leg.LENGTH, 91)
    s = np.unique(np.append(s, sol["touchdown_arc_length"]))
    x, z, t = sol["shape"](s)
    sig = leg.sig
    out = {
        "description": "Closed-form elastic catenary with a flat frictionless seabed "
                       "(Jonkman, NREL/TP-500-41958; as in FAST v7, MAP++, MoorPy) for the "
                       "water issue's mooring leg, case (a) static. Generated by "
                       "bench/water/catenary_seabed.py.",
        "leg": {"depth_m": leg.DEPTH, "rho_kg_m3": leg.RHO, "g_m_s2": leg.G,
                "anchor_m": list(leg.ANCHOR), "fairlead_m": list(leg.FAIRLEAD),
                "unstretched_length_m": leg.LENGTH, "mass_kg_m": leg.MASS,
                "diameter_m": leg.DIAM, "EA_N": leg.EA,
                "submerged_weight_N_m": sig(leg.W_SUB)},
        "conventions": "w = (m - rho pi d^2/4) g per unstretched length; strain = T/EA; "
                       "no seabed friction, so H is constant and the anchor tension is H "
                       "(horizontal). Force of the line on the fairlead: (-H, 0, -V_F). "
                       "Touchdown x is global (anchor x + L_B (1 + H/EA)).",
        "H_N": sig(sol["H"]), "V_F_N": sig(sol["V_F"]),
        "fairlead_tension_N": sig(sol["fairlead_tension"]),
        "fairlead_angle_from_horizontal_deg": sig(math.degrees(math.atan2(sol["V_F"], sol["H"]))),
        "fairlead_force_on_fairlead_N": sig([-sol["H"], 0.0, -sol["V_F"]]),
        "anchor_tension_N": sig(sol["anchor_tension"]),
        "grounded_length_m": sig(sol["grounded_length"]),
        "touchdown_arc_length_from_anchor_m": sig(sol["touchdown_arc_length"]),
        "touchdown_x_m": sig(xa + sol["touchdown_x"]),
        "suspended_length_m": sig(leg.LENGTH - sol["grounded_length"]),
        "newton_iterations": sol["iterations"],
        "residual_m": [float(f"{r:.3g}") for r in sol["residual_m"]],
        "shape": {"s_m": sig(s), "x_m": sig(xa + x), "z_m": sig(za + z),
                  "tension_N": sig(t)},
    }
    if with_moorpy:
        try:
            mp = moorpy_check(sol)
            out["moorpy_catenary_check"] = {k: (sig(v) if not isinstance(v, (dict, str))
                                                else ({kk: float(f"{vv:.3g}") for kk, vv in v.items()}
                                                      if isinstance(v, dict) else v))
                                            for k, v in mp.items()}
        except ImportError:
            out["moorpy_catenary_check"] = "MoorPy not installed"
    return out, sol


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=os.path.join(HERE, "reference",
                                                  "mooring_static_closed_form.json"))
    ap.add_argument("--no-moorpy", action="store_true", help="skip the MoorPy cross-check")
    a = ap.parse_args()
    out, sol = leg_result(not a.no_moorpy)
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    with open(a.out, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    for k in ("H_N", "V_F_N", "fairlead_tension_N", "anchor_tension_N",
              "touchdown_arc_length_from_anchor_m", "touchdown_x_m", "newton_iterations",
              "residual_m"):
        print(f"{k:38s} {out[k]}")
    if isinstance(out.get("moorpy_catenary_check"), dict):
        print("MoorPy catenary rel. diff:", out["moorpy_catenary_check"]["rel_diff"])
    print("wrote", a.out)


if __name__ == "__main__":
    main()
