#!/usr/bin/env python3
"""rodyn and MoorDyn v2 on a flexible jumper in a regular wave, at headings 0, 45 and 90 deg.

The case (bench/decks/jumper_waves.inp): a U-shaped flexible jumper, unstretched length
170 m, outer diameter 0.396 m, 165 kg/m, EA 500e6 N, EI 120.8e3 N m2, normal drag and
added-mass coefficients 1, axial ones 0, pinned at (-100, 0, -55) (end A) and (0, 0, -5)
(end B, the top); water 1000 kg/m3, 100 m deep (flat seabed at z = -100; the line's lowest
point is 8 m above it), g 9.807 m/s2. A regular Airy wave of amplitude 5 m and period 10 s
travelling towards the heading b (from +x towards +y: 0 along the jumper's plane, 90
across it), eta = A cos(k (x cos b + y sin b) - w t), at full height from t = 0 on both
sides (no ramp); each side starts from its still-water static equilibrium.

MoorDyn gets the wave through its external kinematics (WaveKin 1): before every MoorDyn
time step this script reads the points where it wants them
(moordyn.ExternalWaveKinGetCoordinates: the line's nodes, then the points and the ground
body), evaluates the same Airy formulas as rodyn there, and hands the velocities and
accelerations over (moordyn.ExternalWaveKinSet); MoorDyn holds them over the step (its
two RK2 stages). MoorDyn v2.7 source (source/Waves.cpp, setWaveKinematics; source/
Line.cpp): the external mode sets velocity and acceleration only; the elevation zeta and
the dynamic pressure stay 0 (the API has no argument for them): MoorDyn's line is in the
water to z = 0 throughout, and its dynamic pressure enters only the pressure-bending term
of lines with internal pressure, which this line does not have.

Conventions, the same on both sides (rodyn: docs/waves.md, docs/water.md; MoorDyn v2.7:
source/Line.cpp):
  g 9.807 m/s2, rho 1000 kg/m3, depth 100 m.
  Waves: linear Airy at finite depth d = 100 m, k from w^2 = g k tanh(k d) to round-off
  (k d = 4.03: k is 0.063 % above the deep-water w^2/g; the profiles C = cosh(k (z + d)) /
  sinh(k d) and S = sinh(k (z + d)) / sinh(k d) are within 0.07 % of e^(k z) at the top,
  2.8 % at end A (z = -55) and 52 % at the lowest point (z = -91.9, where e^(k z) is
  0.025); rodyn's *WAVE computes them so at the deck's depth, and the script the same):
  u_h = A w C cos th along b, w = A w S sin th, a_h = A w^2 C sin th,
  a_z = -A w^2 S cos th, th = k (x cos b + y sin b) - w t.
  Stretching: none on both sides (rodyn STRETCHING=NONE, which below the mean surface is
  linear theory's profile as it is; the script evaluates that profile at the node's z).
  The line stays below z = -5 m; a trough of 5 m reaches the top end. rodyn takes the
  buoyancy, drag and inertia to the instantaneous surface: within 0.2 m (the radius) of
  the top end the line is partly out of the water near a trough. MoorDyn's elevation is
  0 in the external mode, so its line stays fully submerged.
  Drag: normal 0.5 rho Cd d |u_n| u_n, Cd 1; axial 0 (CDA 0, CdAx 0); on the relative
  velocity. Inertia: rho A [(1 + Ca) a_w,n + (1 + CaAx) a_w,t] - rho A [Ca a_n + CaAx a_t],
  Ca 1, CaAx 0: the Froude-Krylov force of the whole wave acceleration plus the added
  mass on the relative one (rodyn's inertia load, docs/waves.md; MoorDyn's Ap and Aq,
  Ap = rho (1 + Can) V a_p, Aq = rho (1 + Cat) V a_q, mass rho V (Can (I - qq) + Cat qq)).
  Buoyancy as a vertical distributed force (rho g A). So the tension of both is the
  effective tension (MoorDyn's line tension; rodyn's effective_tension_N).
  rodyn: 40 cubic rod elements (EI 120.8e3 N m2 about both axes, GJ 1e5 N m2/rad, the
  shear stiffness EA), dt 0.025 s, EMC with RHO INF 0.8 (the default in water); static analysis first. MoorDyn
  2.7.2: a line with EI from a Fixed point to a Fixed point (pinned ends), lumped mass,
  RK2, BA = -1 (-1 times the critical damping of one segment's axial mode, vanishing
  with N; as bench/water and bench/waves/moordyn_waves.py), dtM = 0.25 l/c
  (c = sqrt(EA/m)) rounded down to a divisor of 0.025 s; the kinematics of each step at
  its mid-time, at the nodes' positions at its start. Static start by its stationary
  solver (ICgenDynamic 0, threshIC 1e-9, TmaxIC 300 s).
  Top force: rodyn's support force at end B (dynamic_ends_step.csv, every step: the
  force of the support on the line, T_eff along the tangent plus the shear at the pinned
  end); MoorDyn's force of the line's end node on the top point, moordyn.GetLineNodeForce
  (line, N) (the end segment's tension and damping, the end node's bending force, weight,
  buoyancy, drag and Froude-Krylov force). With a Fixed point MoorDyn 2.7.2's
  GetPointForce stays 0 (its time loop computes the force of Coupled and Free points
  only); a Coupled point held at (0, 0, -5) gives GetPointForce equal to that force bit
  for bit (checked at N = 34, 90 deg). Effective tension at the top, for information:
  rodyn's at the last integration point (0.48 m below the top with 40 cubic elements,
  dynamic_elements.csv every 0.025 s); MoorDyn's top segment tension GetLineFairTen
  (tension plus damping of the last segment, l/2 below the top).
Signals: both every 0.025 s (rodyn's steps; MoorDyn sampled after every 0.025 s); the
same least-squares fit of the mean and the 1st and 2nd harmonics of the wave frequency,
over 20 <= t < 50 s (3 periods after a 20 s start), of the magnitude of the top force.
Target: rodyn's mean, 1st and 2nd harmonic within 5 % of MoorDyn's finest run (N = 136)
at each heading.

Measured (2026-11-29, Release build; docs/waves.md, "Cross-check with MoorDyn: a jumper
in regular waves"; bench/results/jumper_moordyn.csv): rodyn (40 elements, dt 0.025 s)
against MoorDyn N = 136, top force mean, 1st and 2nd harmonic [N]:
   0 deg  47137.5 / 47140.3 (-0.006 %)  5226.4 / 5227.4 (-0.02 %)  1210.4 / 1206.4 (+0.34 %)
  45 deg  47124.2 / 47127.2 (-0.006 %)  5466.6 / 5467.5 (-0.02 %)  1881.7 / 1875.9 (+0.31 %)
  90 deg  47129.6 / 47132.8 (-0.007 %)  5573.1 / 5573.4 (-0.005 %)  1527.8 / 1522.7 (+0.33 %)
rodyn is converged (20 to 80 elements, dt 0.05 to 0.0125 s: within 0.075 %); MoorDyn's 2nd
harmonic still rises with N (1469.8, 1511.1, 1522.7 N at N = 34, 68, 136, 90 deg) towards
rodyn's. Static top force: rodyn 47113.0 N, MoorDyn 47115.9 N (N = 136). --quick runs
rodyn at 20 elements and dt 0.05 s (1 s of CPU in Release, 8.5 s in Debug for the three
headings); it fails if a figure is beyond 5 % (checked: the stored 90 deg series scaled
by 1.06 fails it).

  python3 bench/waves/jumper_moordyn.py --write   # MoorDyn N = 34, 68, 136 and rodyn at
                                                  # each heading (MoorDyn cached in .work/)
  python3 bench/waves/jumper_moordyn.py --quick   # rodyn against the stored MoorDyn series
                                                  # (CTest bench_jumper_moordyn_quick)
Results: bench/results/jumper_moordyn.csv (harmonics of every run), jumper_moordyn_top.csv
(the finest MoorDyn run's top force at each heading, every 0.025 s). Exit 1 if a 5 %
target is missed.
"""
import argparse
import csv
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import benchlib  # noqa: E402

DECK = os.path.join(ROOT, "bench", "decks", "jumper_waves.inp")
RESULTS = os.path.join(ROOT, "bench", "results")
SUMMARY_CSV = os.path.join(RESULTS, "jumper_moordyn.csv")
SERIES_CSV = os.path.join(RESULTS, "jumper_moordyn_top.csv")
WORK = os.path.join(HERE, ".work")

# the case (bench/decks/jumper_waves.inp)
LENGTH = 170.0          # m
DIAM = 0.396            # m
MASS = 165.0            # kg/m
EA = 500.0e6            # N
EI = 120.8e3            # N m2
CD, CA, CDAX, CAAX = 1.0, 1.0, 0.0, 0.0
END_A = (-100.0, 0.0, -55.0)
END_B = (0.0, 0.0, -5.0)  # the top
G = 9.807
RHO = 1000.0
DEPTH = 100.0
AMPLITUDE = 5.0         # m
PERIOD = 10.0           # s
HEADINGS = (0.0, 45.0, 90.0)

T_END = 50.0            # s
WINDOW = (20.0, 50.0)   # s: three periods after a 20 s start
SAMPLE = 0.025          # s: rodyn's step, MoorDyn's sampling
TOLERANCE = 0.05
RODYN_RUNS = [(20, 0.05), (20, 0.025), (40, 0.025), (80, 0.025), (40, 0.0125)]
RODYN_CASE = (40, 0.025)        # the case's setting, compared in --write
RODYN_QUICK = (20, 0.05)        # --quick (CTest): within 0.06 % of (40, 0.025), 0.04 % of 80
MOORDYN_N = [34, 68, 136]
BA = -1.0
IC_THRESH = 1.0e-9
IC_TMAX = 300.0

def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def wave_number(omega=2.0 * np.pi / PERIOD, depth=DEPTH, g=G):
    """k of omega^2 = g k tanh(k d) by Newton to round-off (rodyn's wave_number)."""
    k = omega**2 / g / np.sqrt(np.tanh(omega**2 * depth / g))
    for _ in range(50):
        f = g * k * np.tanh(k * depth) - omega**2
        df = g * np.tanh(k * depth) + g * k * depth / np.cosh(k * depth)**2
        k = k - f / df
    return float(k)


def airy(points, t, heading):
    """Velocity and acceleration of the regular wave at points (n, 3) and time t, linear
    theory at finite depth without stretching (rodyn's STRETCHING=NONE below the mean
    surface), eta = A cos(k (x cos b + y sin b) - w t)."""
    p = np.asarray(points, dtype=float)
    w = 2.0 * np.pi / PERIOD
    k = wave_number()
    b = np.radians(heading)
    cb, sb = np.cos(b), np.sin(b)
    th = k * (p[:, 0] * cb + p[:, 1] * sb) - w * t
    z = p[:, 2] + DEPTH
    c = np.cosh(k * z) / np.sinh(k * DEPTH)
    s = np.sinh(k * z) / np.sinh(k * DEPTH)
    uh = AMPLITUDE * w * c * np.cos(th)
    ah = AMPLITUDE * w * w * c * np.sin(th)
    u = np.column_stack([uh * cb, uh * sb, AMPLITUDE * w * s * np.sin(th)])
    a = np.column_stack([ah * cb, ah * sb, -AMPLITUDE * w * w * s * np.cos(th)])
    return u, a


def harmonics(t, y):
    """Mean and amplitudes of the 1st and 2nd harmonics of the wave frequency: the
    least-squares fit of 1, cos(j w t), sin(j w t), j = 1, 2, to y over WINDOW
    (WINDOW[0] <= t < WINDOW[1]). The one function for both codes."""
    t, y = np.asarray(t), np.asarray(y)
    m = (t >= WINDOW[0] - 1e-9) & (t < WINDOW[1] - 1e-9)
    tt, yy = t[m], y[m]
    w = 2.0 * np.pi / PERIOD
    cols = [np.ones_like(tt)]
    for j in (1, 2):
        cols += [np.cos(j * w * tt), np.sin(j * w * tt)]
    c = np.linalg.lstsq(np.column_stack(cols), yy, rcond=None)[0]
    return float(c[0]), float(np.hypot(c[1], c[2])), float(np.hypot(c[3], c[4]))


# ------------------------------------------------------------------------------ rodyn
def run_rodyn(rodyn, tmp, heading, elements, dt, tension=True):
    """rodyn on the deck at one heading; returns the step times, the top force (n, 3),
    the times and effective tension at the last integration point (frames every
    SAMPLE s; None unless `tension`) and (wall, CPU)."""
    out = os.path.join(tmp, f"jumper_{heading:g}_{elements}_{dt:g}")
    frame = max(SAMPLE, dt) if tension else T_END
    cmd = [rodyn, DECK, "-o", out, "--quiet", "--set", f"HEADING={heading!r}",
           "--set", f"ELEMENTS={elements}", "--set", f"DT={dt!r}",
           "--set", f"T_END={T_END!r}", "--set", f"FRAME={frame!r}"]
    t0, c0 = time.perf_counter(), child_cpu()
    p = subprocess.run(cmd, capture_output=True, text=True)
    cost = (time.perf_counter() - t0, child_cpu() - c0)
    if p.returncode != 0:
        sys.exit(f"jumper_moordyn: rodyn exit {p.returncode}: {p.stderr.strip()}")
    t, f = benchlib.read_end_forces(out, "B")
    ten = None
    if tension:
        te, tv = [], []
        with open(os.path.join(out, "dynamic_elements.csv")) as fh:
            for r in csv.DictReader(fh):
                if int(r["element"]) == elements and int(r["point"]) == 3:
                    te.append(float(r["time_s"]))
                    tv.append(float(r["effective_tension_N"]))
        ten = (np.array(te), np.array(tv))
    with open(os.path.join(out, "static_reactions.csv")) as fh:
        static = [r for r in csv.DictReader(fh) if r.get("end") == "B"]
    fs = [float(static[0][c]) for c in ("Fx_N", "Fy_N", "Fz_N")] if static else None
    return t, f, ten, cost, fs


# ---------------------------------------------------------------------------- MoorDyn
def md_dt(n):
    """MoorDyn's dtM for n segments: 0.25 l/c, c = sqrt(EA/m), rounded down to a divisor
    of SAMPLE."""
    dt = 0.25 * (LENGTH / n) / np.sqrt(EA / MASS)
    return SAMPLE / int(np.ceil(SAMPLE / dt))


def md_deck(n, dt):
    return benchlib.moordyn_line_deck(
        f"rodyn bench/waves: flexible jumper in a regular wave, {n} segments, "
        "external wave kinematics (jumper_moordyn.py)",
        dict(name="jumper", d=DIAM, m=MASS, ea=EA, ba=BA, ei=EI, cd=CD, ca=CA, cdax=CDAX,
             caax=CAAX),
        [("Fixed",) + tuple(END_A) + (0.0,), ("Fixed",) + tuple(END_B) + (0.0,)], LENGTH, n,
        [(0, "writeLog"), (repr(dt), "dtM"), ("RK2", "tScheme"), (repr(G), "g"),
         (repr(RHO), "rho"), (repr(DEPTH), "WtrDpth"), (1, "WaveKin"), (0, "ICgenDynamic"),
         (repr(IC_THRESH), "threshIC"), (repr(IC_TMAX), "TmaxIC"), (1, "disableOutput"),
         (1, "disableOutTime")])


def run_moordyn(n, heading, fresh=False):
    """MoorDyn v2 on the jumper with N segments at one heading, cached in
    bench/waves/.work/jumper_N_HEADING.npz; returns the sample times, the top force (the
    line's end node on the top point), the top segment tension, the static top force
    and (wall, CPU) of the static solve and of the time loop."""
    dt = md_dt(n)
    cache = os.path.join(WORK, f"jumper_{n}_{heading:g}_{dt:.6g}_{T_END:g}.npz")
    if os.path.exists(cache) and not fresh:
        z = np.load(cache)
        return z["t"], z["f"], z["ten"], z["static"], tuple(z["ic"]), tuple(z["loop"])
    import moordyn as md
    folder = os.path.join(WORK, f"jumper_{n}")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "jumper.dat")
    with open(path, "w") as fh:
        fh.write(md_deck(n, dt))
    t0, c0 = time.perf_counter(), time.process_time()
    s = md.Create(path)
    md.Init(s, [], [])
    ic = (time.perf_counter() - t0, time.process_time() - c0)
    md.ExternalWaveKinInit(s)
    line = md.GetLine(s, 1)
    static = np.array(md.GetLineNodeForce(line, n))
    every = int(round(SAMPLE / dt))
    steps = int(round(T_END / SAMPLE)) * every
    rec_t = [0.0]
    rec_f = [md.GetLineNodeForce(line, n)]
    rec_ten = [md.GetLineFairTen(line)]
    t0, c0 = time.perf_counter(), time.process_time()
    for j in range(steps):
        t = j * dt
        u, a = airy(md.ExternalWaveKinGetCoordinates(s), t + 0.5 * dt, heading)
        if md.ExternalWaveKinSet(s, u.tolist(), a.tolist(), t) != 0:
            raise RuntimeError(f"MoorDyn N={n}: ExternalWaveKinSet failed at t={t}")
        md.Step(s, [], [], t, dt)
        if (j + 1) % every == 0:
            f = md.GetLineNodeForce(line, n)
            if not np.all(np.isfinite(f)):
                raise RuntimeError(f"MoorDyn N={n}: not finite at t={(j + 1) * dt}")
            rec_t.append((j + 1) * dt)
            rec_f.append(f)
            rec_ten.append(md.GetLineFairTen(line))
    loop = (time.perf_counter() - t0, time.process_time() - c0)
    md.Close(s)
    out = (np.array(rec_t), np.array(rec_f), np.array(rec_ten), static, ic, loop)
    os.makedirs(WORK, exist_ok=True)
    np.savez(cache, t=out[0], f=out[1], ten=out[2], static=out[3], ic=out[4], loop=out[5])
    return out


# ------------------------------------------------------------------------ results
COLUMNS = ["code", "heading_deg", "elements", "dt_s", "mean_N", "harmonic1_N",
           "harmonic2_N", "tension_mean_N", "tension_harmonic1_N", "tension_harmonic2_N",
           "static_top_force_N", "wall_s", "cpu_s"]


def write_results(rows, series):
    os.makedirs(RESULTS, exist_ok=True)
    with open(SUMMARY_CSV, "w", newline="") as fh:
        fh.write(f"# bench/waves/jumper_moordyn.py --write: the flexible jumper in a regular "
                 f"wave (A {AMPLITUDE} m, T {PERIOD} s), magnitude of the top force, mean and "
                 f"1st and 2nd harmonics over {WINDOW[0]:g}-{WINDOW[1]:g} s; tension_*: "
                 "effective tension at the top (rodyn: last integration point; MoorDyn: "
                 "top segment); rodyn cubic rod elements, MoorDyn 2.7.2 segments\n")
        w = csv.writer(fh)
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([r[0], f"{r[1]:g}", r[2], f"{r[3]:.6g}"]
                       + [f"{v:.2f}" for v in r[4:11]] + [f"{v:.1f}" for v in r[11:13]])
    with open(SERIES_CSV, "w", newline="") as fh:
        fh.write("# MoorDyn 2.7.2, the finest run of bench/waves/jumper_moordyn.py at each "
                 "heading: force of the line's top node on the top point [N] (global axes, "
                 "GetLineNodeForce), every 0.025 s\n")
        fh.write("heading_deg,segments,time_s,Fx_N,Fy_N,Fz_N,top_force_N\n")
        for heading, n, t, f in series:
            for k in range(len(t)):
                fh.write(f"{heading:g},{n},{t[k]:.3f},{f[k][0]:.9g},{f[k][1]:.9g},"
                         f"{f[k][2]:.9g},{np.linalg.norm(f[k]):.9g}\n")


def stored_reference():
    """The stored finest MoorDyn run per heading: its harmonics, fitted again from the
    stored series by harmonics()."""
    ref = {}
    with open(SERIES_CSV) as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    for heading in HEADINGS:
        sel = [r for r in rows if float(r["heading_deg"]) == heading]
        if not sel:
            sys.exit(f"jumper_moordyn: no heading {heading:g} in {SERIES_CSV}")
        t = np.array([float(r["time_s"]) for r in sel])
        f = np.array([float(r["top_force_N"]) for r in sel])
        ref[heading] = (int(sel[0]["segments"]),) + harmonics(t, f)
    return ref


def compare(rodyn, ref):
    """rodyn's (mean, harmonic 1, harmonic 2) per heading against MoorDyn's, each within
    TOLERANCE."""
    ok = True
    print(f"{'top force':28s} {'rodyn [N]':>10s} {'MoorDyn [N]':>12s} {'rel. diff':>10s} "
          f"{'target':>7s}")
    for heading in HEADINGS:
        n = ref[heading][0]
        for name, v, r in zip(("mean", "1st harmonic", "2nd harmonic"), rodyn[heading],
                              ref[heading][1:]):
            e = v / r - 1.0
            good = abs(e) <= TOLERANCE
            ok &= good
            print(f"{heading:5.0f} deg {name:14s} N={n:<4d}{v:10.1f} {r:12.1f} {e:10.2e} "
                  f"{TOLERANCE:7.0e} {'ok' if good else 'MISSED'}")
    return ok


FMT = ("%-7s %4.0f deg %4d %9.4g  mean %8.1f  harm1 %7.1f  harm2 %7.1f  | tension %8.1f "
       "%7.1f %7.1f | static %8.1f  wall %6.1f s  CPU %6.1f s")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--quick", action="store_true",
                    help="rodyn at the three headings against the stored MoorDyn series")
    ap.add_argument("--write", action="store_true",
                    help="write bench/results/jumper_moordyn*.csv")
    ap.add_argument("--segments", type=int, nargs="+", default=MOORDYN_N)
    ap.add_argument("--fresh", action="store_true", help="ignore MoorDyn runs kept in .work/")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        if args.quick:
            res = {}
            for heading in HEADINGS:
                t, f, _, cost, _ = run_rodyn(args.rodyn, tmp, heading, *RODYN_QUICK,
                                             tension=False)
                res[heading] = harmonics(t, np.linalg.norm(f, axis=1))
                print(f"rodyn {RODYN_QUICK[0]} elements, dt {RODYN_QUICK[1]} s, heading "
                      f"{heading:g} deg: {cost[0]:.1f} s wall, {cost[1]:.1f} s CPU")
            sys.exit(0 if compare(res, stored_reference()) else 1)
        rows, series, case = [], [], {}
        for heading in HEADINGS:
            for ne, dt in RODYN_RUNS:
                t, f, ten, cost, fs = run_rodyn(args.rodyn, tmp, heading, ne, dt)
                h = harmonics(t, np.linalg.norm(f, axis=1))
                if (ne, dt) == RODYN_CASE:
                    case[heading] = h
                rows.append(("rodyn", heading, ne, dt) + h + harmonics(*ten)
                             + (float(np.linalg.norm(fs)),) + cost)
                print(FMT % rows[-1], flush=True)
            fin = None
            for n in args.segments:
                t, f, ten, static, ic, loop = run_moordyn(n, heading, fresh=args.fresh)
                rows.append(("moordyn", heading, n, md_dt(n))
                            + harmonics(t, np.linalg.norm(f, axis=1)) + harmonics(t, ten)
                            + (float(np.linalg.norm(static)), ic[0] + loop[0],
                               ic[1] + loop[1]))
                print(FMT % rows[-1], flush=True)
                if fin is None or n > fin[1]:
                    fin = (heading, n, t, f)
            series.append(fin)
    ref = {s[0]: (s[1],) + harmonics(s[2], np.linalg.norm(s[3], axis=1)) for s in series}
    ok = compare(case, ref)
    if args.write:
        write_results(rows, series)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
