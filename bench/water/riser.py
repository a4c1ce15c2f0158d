"""The lazy-wave cable of input/riser_lazy_wave.inp: one definition shared by the riser
reference and comparison scripts (cabledyn_riser.py, compare_riser.py).

Lozon, Lekkala, Sirkis & Hall (2025), Ocean Engineering 322, 120473, Gulf of Mexico 80 m
dynamic cable, as modelled by Seo, Lim, Shim & Song (2026), Ocean Engineering 368, 128332
(CableDyn and OrcaFlex): hang-off (5, 0, -14) m, seabed end (125, 0, -80) m, both ends
ball joints; from the hang-off bare 68.114 m, buoyant 50 m, bare 52.101 m; flat
frictionless seabed at z = -80 m, contact stiffness 1e5 Pa/m; g 9.80665 m/s2, sea water
1025 kg/m3. Arc lengths here are unstretched and measured from the hang-off (rodyn's end
B; rodyn's S runs from the seabed end A, s = LENGTH - S).
"""
import csv
import math
import os

import numpy as np

G = 9.80665
RHO = 1025.0
DEPTH = 80.0
SEABED_Z = -DEPTH
K_BED = 1.0e5                     # Pa/m
HANGOFF = (5.0, 0.0, -14.0)
SEABED_END = (125.0, 0.0, -80.0)
# (name, length [m], outer diameter [m], mass in air [kg/m]) from the hang-off
SECTIONS = [("bare", 68.114, 0.16, 36.7), ("buoy", 50.0, 0.29, 59.53),
            ("bare", 52.101, 0.16, 36.7)]
LENGTH = sum(s[1] for s in SECTIONS)          # 170.215 m
EA = 4.69e8                       # N
EI = 1.99e4                       # N m2
CD, CDAX, CA, CAAX = 1.2, 0.1, 1.0, 0.0

# the heave of input/riser_lazy_wave_heave.inp
AMPLITUDE = 3.0                   # m
PERIOD = 12.0                     # s
RAMP = 12.0                       # s, (1 - cos(pi t / RAMP)) / 2 for t < RAMP
T_END = 24.0                      # s
DT = 0.05                         # s


def heave(t):
    """Hang-off z offset, velocity and acceleration at time t (the rodyn *MOTION)."""
    w = 2.0 * math.pi / PERIOD
    u, ud, udd = AMPLITUDE * math.sin(w * t), AMPLITUDE * w * math.cos(w * t), \
        -AMPLITUDE * w * w * math.sin(w * t)
    c = math.pi / RAMP
    if t < RAMP:
        r, rd, rdd = 0.5 * (1 - math.cos(c * t)), 0.5 * c * math.sin(c * t), \
            0.5 * c * c * math.cos(c * t)
    else:
        r, rd, rdd = 1.0, 0.0, 0.0
    return r * u, rd * u + r * ud, rdd * u + 2.0 * rd * ud + r * udd


def shape_features(s, x, z):
    """Hog bend (the highest point of the buoyant section), sag bend (the lowest point
    between the hang-off and the hog bend), touchdown (the first s past the hog bend where
    z reaches the seabed level, linear between nodes) of a shape given at increasing s
    from the hang-off."""
    s, x, z = (np.asarray(a, float) for a in (s, x, z))
    b0 = SECTIONS[0][1]
    b1 = b0 + SECTIONS[1][1]
    i_hog = int(np.argmax(np.where((s >= b0) & (s <= b1), z, -np.inf)))
    i_sag = int(np.argmin(np.where(s < s[i_hog], z, np.inf)))
    td = float("nan")
    for i in range(i_hog, len(s) - 1):
        if z[i + 1] <= SEABED_Z < z[i]:
            f = (z[i] - SEABED_Z) / (z[i] - z[i + 1])
            td = s[i] + f * (s[i + 1] - s[i])
            break
    return {"sag_z_m": z[i_sag], "sag_s_m": s[i_sag], "sag_x_m": x[i_sag],
            "hog_z_m": z[i_hog], "hog_s_m": s[i_hog], "hog_x_m": x[i_hog],
            "touchdown_s_m": td}


def read_rodyn_static(folder):
    """rodyn's static result of the cable: shape from the hang-off, top force, angle,
    curvature at the integration points, touchdown."""
    with open(os.path.join(folder, "static_nodes.csv")) as f:
        nodes = list(csv.DictReader(f))
    s = np.array([LENGTH - float(r["s_m"]) for r in nodes])[::-1]
    x = np.array([float(r["x_m"]) for r in nodes])[::-1]
    z = np.array([float(r["z_m"]) for r in nodes])[::-1]
    with open(os.path.join(folder, "static_reactions.csv")) as f:
        ends = {r["end"]: r for r in csv.DictReader(f)}
    top, bot = ends["B"], ends["A"]
    with open(os.path.join(folder, "static_elements.csv")) as f:
        el = list(csv.DictReader(f))
    ks = np.array([LENGTH - float(r["s_m"]) for r in el])
    kv = np.array([abs(float(r["curvature_per_m"])) for r in el])
    with open(os.path.join(folder, "static_lines.csv")) as f:
        td_own = LENGTH - float(next(csv.DictReader(f))["touchdown_s_m"])
    out = {"s_m": s, "x_m": x, "z_m": z, "curv_s_m": ks, "curv_per_m": kv,
           "top_tension_N": float(top["tension_N"]),
           "top_H_N": -float(top["Fx_N"]), "top_V_N": float(top["Fz_N"]),
           "seabed_end_H_N": float(bot["Fx_N"]), "touchdown_own_s_m": td_own}
    out.update(features(out))
    return out


def features(r):
    """Derived quantities of a shape dict with s_m, x_m, z_m, curv_s_m, curv_per_m."""
    out = shape_features(r["s_m"], r["x_m"], r["z_m"])
    # hang-off angle below the horizontal: the chord to the first node 0.1 m or more
    # down the line (the pinned end carries no moment: the curvature there is ~0)
    s, x, z = r["s_m"], r["x_m"], r["z_m"]
    j = int(np.searchsorted(s, 0.1))
    out["hangoff_angle_deg"] = math.degrees(math.atan2(z[0] - z[j], abs(x[j] - x[0])))
    # peak curvature away from the ends (5 m) and the touchdown's own peak
    m = (r["curv_s_m"] > 5.0) & (r["curv_s_m"] < LENGTH - 5.0)
    i = int(np.argmax(np.where(m, r["curv_per_m"], -1.0)))
    out["peak_curvature_per_m"] = float(r["curv_per_m"][i])
    out["peak_curvature_s_m"] = float(r["curv_s_m"][i])
    return out
