"""The mooring leg of the water issue: one definition shared by the reference scripts.

Water depth 100 m, rho 1025 kg/m3, g 9.80665 m/s2, flat frictionless seabed at
z = -100 m. End A (anchor) pinned at (-400, 0, -100), end B (fairlead) at (0, 0, -10).
Unstretched length 450 m; 60 kg/m in air, volume-equivalent diameter 0.1 m (buoyancy
and drag both use d = 0.1 m); EA 6e8 N; no bending or torsion stiffness; Cd 1.2 (normal,
on d), CdAx 0.05 (axial, on pi d), Ca 1.0 (normal), CaAx 0.

Cases: (a) static; (b) surge: fairlead x(t) = 5 sin(2 pi t / 12) m times the ramp
(1 - cos(pi t / 12)) / 2 for t < 12 s (1 after), 120 s; (c) static in a uniform
1.0 m/s current along +y.
"""
import math

import numpy as np

G = 9.80665
RHO = 1025.0
DEPTH = 100.0
ANCHOR = (-400.0, 0.0, -100.0)
FAIRLEAD = (0.0, 0.0, -10.0)
LENGTH = 450.0
MASS = 60.0            # kg/m in air
DIAM = 0.1             # m, volume-equivalent (buoyancy) and drag diameter
EA = 6.0e8             # N
CD = 1.2               # normal drag, on d
CDAX = 0.05            # axial drag, on pi d
CA = 1.0               # normal added mass
CAAX = 0.0             # axial added mass
CURRENT = (0.0, 1.0, 0.0)

AMPLITUDE = 5.0        # m, surge amplitude
PERIOD = 12.0          # s
RAMP = 12.0            # s, (1 - cos(pi t / RAMP)) / 2 for t < RAMP
T_END = 120.0          # s
WINDOW = (72.0, 120.0)  # s, the last 48 s = 4 periods

# submerged weight per unstretched length [N/m]
W_SUB = (MASS - RHO * math.pi * DIAM**2 / 4.0) * G
XF = FAIRLEAD[0] - ANCHOR[0]   # 400 m horizontal span
ZF = FAIRLEAD[2] - ANCHOR[2]   # 90 m vertical span


def ramp(t):
    t = np.asarray(t, dtype=float)
    return np.where(t < RAMP, 0.5 * (1.0 - np.cos(np.pi * t / RAMP)), 1.0)


def surge(t):
    """Fairlead x offset from its static position [m]."""
    t = np.asarray(t, dtype=float)
    return ramp(t) * AMPLITUDE * np.sin(2.0 * np.pi * t / PERIOD)


def sig(x, digits=12):
    """A float rounded to `digits` significant digits (for the JSON files)."""
    if isinstance(x, (list, tuple, np.ndarray)):
        return [sig(v, digits) for v in x]
    x = float(x)
    if x == 0.0 or not math.isfinite(x):
        return x
    return float(f"{x:.{digits}g}")
