#!/usr/bin/env python3
"""Speed of a mooring system: the OC3-Hywind spar's three chains, rodyn against MoorDyn 2.7.2
and CableDyn 0.3.0 at equal fairlead-tension error.

The system (input/oc3_spar.inp's lines, bench/systems/moorpy_spar.py's numbers): three
chains of 902.2 m, 0.09 m volume-equivalent diameter, 77.7066 kg/m in air, EA 384.243e6 N,
no bending stiffness, from anchors at 853.87 m radius on the seabed (320 m of water) to
fairleads 70 m below the waterline at 5.2 m radius, at 0, 120 and 240 deg. Still water,
1025 kg/m3, g 9.80665 m/s2.

Driving, the same in every program: the three fairleads translate together along x by
    u(t) = r(t) (10 sin(2 pi t / 100) + 2 sin(2 pi t / 12)) m,
    r(t) = (1 - cos(pi t / 25)) / 2 for t < 25 s, 1 after,
sampled every 0.05 s and followed piecewise linearly between the samples, for 600 s from the
static equilibrium. The spar is a prescribed body moving in pure translation, so moving its
three fairleads is the same thing:
  rodyn    a FIXED *BODY with the fairleads as its points, moved by
           *MOTION, BODY=SPAR, TYPE=TABLE (the samples, RAMP=0: the ramp is in them; the
           table runs 20 s past the end, so that the step rodyn solves past the last frame
           sees the motion go on); lines of ELEMENT=CABLE; its default scheme in water
           (EMC, RHO INF 0.8), TANGENT=REUSE, tolerances 1e-8. rodyn runs to 601 s (its
           cost counts 0.17 % more steps than the peers'), with no frame but t = 0 and the
           end, the fairlead forces every step: with TIME (or a frame) at 600 s and DT
           dividing it, the time summed step by step ends a few 1e-10 s short, the last
           step is split in two halves, and the step force written at the change of step
           size jumps (by 9 % at 80 elements and DT 0.025 s): an artefact of the run's end
           that the window would otherwise catch.
  MoorDyn  three Coupled points; moordyn.Step every 0.05 s (MoorDyn sub-steps at dtM)
           with the position at t_k and the secant velocity (u(t_k+1) - u(t_k)) / 0.05 s,
           which MoorDyn extrapolates linearly over the interval: the same piecewise linear
           path. tScheme RK2 (its default), BA/-zeta = -1.
  CableDyn the same MoorDyn v2 deck (its MoorDyn-deck reader; EI = 0, so its tension-only
           lines), three Coupled points; CableDyn.step(dt, q, v, a) with the position at
           t + dt (on the samples: dt is a multiple of 0.05 s) and the ramped harmonic's
           exact velocity and acceleration; rhoInf 0.4 (its default) unless swept.

Conventions (rodyn's deck mapped onto MoorDyn's; docs/water.md): drag Cd 1.2 on the normal
relative velocity and on the diameter, CdAx 0.05 on pi d (rodyn CDN, CDA); added mass
Ca 1.0 on the normal, CaAx 0 (CAN, CAA), rho pi d^2/4 per unstretched length; weight and
buoyancy per unstretched length. Seabed: a vertical spring-damper per unit length
(kBot pen + cBot pen-rate) d with MoorDyn's defaults kBot 3e6 Pa/m, cBot 3e5 Pa s/m
(rodyn *SEABED STIFFNESS=3.0e6, DAMPING=3.0e5: the same law), no friction. MoorDyn's
option names are rho, kBot, cBot; CableDyn's rhoW, kBot, cBot. Differences of model that
stay: rodyn's drag acts on the stretched length (MoorDyn's on the unstretched: the strain
is below 0.4 %), MoorDyn's and CableDyn's line is lumped at its nodes; rodyn's is
continuous (cubic cable elements, consistent loads). MoorDyn's axial damping BA = -1
(a segment's critical damping) vanishes with the segment length, so the converged answer
does not depend on it; rodyn has no axial damping.

Fairlead tension: rodyn, |force of the support on the line| at end B every step
(dynamic_ends_step.csv: the step forces interpolated to the step's end, docs/output.md);
MoorDyn, |moordyn.GetPointForce| of each Coupled point after each coupling interval (the
end segment's tension plus the end node's half-segment weight, buoyancy, drag and seabed
force); CableDyn, |the coupled point's block of CableDyn.calc_output()| after each step.

Error metric: each fairlead's tension, linearly interpolated from the run's own sample
times onto t = 300, 300.1, ..., 600 s (rodyn's steps, MoorDyn's 0.05 s, CableDyn's dt: for
time steps <= 0.1 s the grid is a subset of the samples); error = max over the three
fairleads of max_t |T - T_ref| / max_t T_ref over that window, T_ref MoorDyn's converged
run (the finest of the reference ladder).

Cost: each run is a process of its own (rodyn's binary; the peers' a Python process with
the venv's interpreter), run with OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1; its CPU time
(user + sys, os.wait4) and wall time, with the 1-minute load average at its start. rodyn's
process does everything: deck, statics, 600 s of dynamics, the CSV files. MoorDyn's
process leaves out its static start (its initial condition is computed once per segment
count by its stationary solver, threshIC 1e-6 (1e-4 above 80 segments), in a process of
its own, and restored with moordyn.Deserialize); CableDyn's Newton statics run in its
process (cpu_setup_s). The peers' stepping alone (CPU inside the process around the time
loop, the Python loop included) is recorded too. The ratios divide the peer's
stepping CPU by rodyn's whole-process CPU (rodyn's statics and output counted against it),
and are also given process by process.

Runs are kept in bench/systems/.work/spar_speed/ (decks, results as .npz); a second run
reuses them unless --fresh. Phases:
  reference  MoorDyn at 40, 80, 160, 320 segments (dtM 0.25 l/c, l = L/N, c = sqrt(EA/m),
             a divisor of 0.05 s) and 160 at half that dtM: the convergence table;
             rodyn's own ladder (20, 40, 80 cubic elements, dt 0.1, 0.05, 0.025 s).
  sweep      each tool's cost knobs, one timed run each (rodyn: cubic and quadratic
             elements, dt; MoorDyn: segments, dtM at and below the stability limit;
             CableDyn: segments, dt); every run's error.
  final      per tool the three cheapest sweep runs with error <= 1 %, each timed
             --repeats times (default 3): the median CPU picks the tool's cheapest run;
             the ratios; MoorDyn's time loop without moordyn.Step (the Python share of its
             stepping CPU). --final does only this (the sweep's stored results pick the
             candidates), to re-time on an idle machine.

  python3 bench/systems/spar_speed.py                 # everything (~25 min of CPU)
  python3 bench/systems/spar_speed.py --final         # re-time the chosen runs (~2 min)
Writes bench/results/spar_speed.csv (machine facts as # lines, one row per run) and prints
the tables. The peers run from bench/peers/.venv (created with moordyn 2.7.2, cabledyn
0.3.0 and numpy from PyPI when missing, as bench/peers/run_peers.py does).
"""
import argparse
import hashlib
import json
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "bench"))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import moorpy_spar as spar  # noqa: E402

WORK = os.path.join(HERE, ".work", "spar_speed")
RESULTS_CSV = os.path.join(ROOT, "bench", "results", "spar_speed.csv")
VENV = os.path.join(ROOT, "bench", "peers", ".venv")
VENV_PY = os.path.join(VENV, "bin", "python")
PEER_PACKAGES = ("numpy", "moordyn==2.7.2", "cabledyn==0.3.0")
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")

# ---- the system (moorpy_spar.py's numbers, input/oc3_spar.inp's chain)
G = 9.80665
RHO = spar.RHO
DEPTH = spar.DEPTH
LENGTH = spar.LENGTH
DIAM = spar.DIAM
MASS = spar.MASS_LINE
EA = spar.EA
CDN, CDA, CAN, CAA = 1.2, 0.05, 1.0, 0.0
KBOT, CBOT = 3.0e6, 3.0e5
BA = -1.0
NLEG = len(spar.HEADINGS)
# ---- the driving
SURGE = ((10.0, 100.0), (2.0, 12.0))    # (amplitude [m], period [s])
RAMP = 25.0
H = 0.05                                # motion samples and MoorDyn's coupling interval
T_END = 600.0
T_TABLE = 620.0                         # the table goes on past the end
T_RODYN = 601.0                         # rodyn's TIME (the docstring says why)
WINDOW = (300.0, 600.0)
DT_GRID = 0.1
TARGET = 0.01
CELERITY = math.sqrt(EA / MASS)         # axial wave speed [m/s]


def surge(t):
    """u, u', u'' of the ramped two-harmonic surge [m, m/s, m/s2]."""
    t = np.asarray(t, dtype=float)
    u = sum(a * np.sin(2 * math.pi * t / p) for a, p in SURGE)
    ud = sum(a * (2 * math.pi / p) * np.cos(2 * math.pi * t / p) for a, p in SURGE)
    udd = sum(-a * (2 * math.pi / p) ** 2 * np.sin(2 * math.pi * t / p) for a, p in SURGE)
    c = math.pi / RAMP
    inr = t < RAMP
    r = np.where(inr, 0.5 * (1 - np.cos(c * t)), 1.0)
    rd = np.where(inr, 0.5 * c * np.sin(c * t), 0.0)
    rdd = np.where(inr, 0.5 * c * c * np.cos(c * t), 0.0)
    return r * u, rd * u + r * ud, rdd * u + 2 * rd * ud + r * udd


def samples():
    """The motion's samples every H up to T_TABLE: (t, u)."""
    t = np.round(np.arange(int(round(T_TABLE / H)) + 1) * H, 9)
    return t, surge(t)[0]


def fairleads():
    """Fairleads at rest, global [m] (the body's R at the origin), (3, 3)."""
    return np.array([spar.fairlead_rel(k) for k in range(NLEG)])


def grid():
    n = int(round((WINDOW[1] - WINDOW[0]) / DT_GRID))
    return WINDOW[0] + DT_GRID * np.arange(n + 1)


def on_grid(t, tension):
    """(3, n_grid) tensions interpolated linearly from the run's samples."""
    g = grid()
    return np.array([np.interp(g, t, tension[k]) for k in range(NLEG)])


def error(run, ref):
    """max over the fairleads of max |T - T_ref| / max T_ref over the window, and the
    per-fairlead values."""
    a, b = on_grid(run["t"], run["T"]), on_grid(ref["t"], ref["T"])
    per = [float(np.max(np.abs(a[k] - b[k])) / np.max(b[k])) for k in range(NLEG)]
    return max(per), per


# ----------------------------------------------------------------------------- decks
def rodyn_deck(elements, order, dt, table="motion.csv", scheme=None):
    fmt = spar.fmt
    head = (f"*HEADING\nspar_speed: OC3 spar chains, {elements} elements of order {order} a "
            f"line, dt {dt} s (bench/systems/spar_speed.py)\n")
    text = head + (f"*GRAVITY\n0.0, 0.0, {fmt(-G)}\n"
                   f"*WATER, DEPTH={fmt(DEPTH)}, DENSITY={fmt(RHO)}\n"
                   f"*SEABED, STIFFNESS={KBOT:.1e}, DAMPING={CBOT:.1e}\n"
                   f"*SECTION, NAME=CHAIN, OD={fmt(DIAM)}, CDN={CDN}, CDA={CDA}, "
                   f"CAN={CAN}, CAA={CAA}\n{fmt(EA)}, 0.0, 0.0, 0.0, {fmt(MASS)}\n"
                   "*BODY, NAME=SPAR, TYPE=FIXED\n0.0, 0.0, 0.0\n0.0, 0.0, 0.0\n"
                   "0.0, 0.0, 0.0\n0.0, 0.0, 0.0\n")
    for k in range(NLEG):
        f, a = spar.fairlead_rel(k), spar.anchor(k)
        text += (f"*POINT, NAME=F{k + 1}, TYPE=BODY, BODY=SPAR\n"
                 f"{', '.join(fmt(x) for x in f)}\n"
                 f"*POINT, NAME=A{k + 1}, TYPE=FIXED\n{', '.join(fmt(x) for x in a)}\n")
    for k in range(NLEG):
        text += (f"*LINE, NAME=L{k + 1}, SECTION=CHAIN, LENGTH={fmt(LENGTH)}, "
                 f"ELEMENTS={elements}, ORDER={order}, ELEMENT=CABLE, POINT A=A{k + 1}, "
                 f"POINT B=F{k + 1}\n")
    sch = f", SCHEME={scheme}" if scheme else ""
    text += (f"*MOTION, BODY=SPAR, TYPE=TABLE, INPUT={table}, RAMP=0\n"
             "*STATIC, INCREMENTS=20\n"
             f"*DYNAMIC, DT={dt!r}, TIME={T_RODYN!r}, OUTPUT INTERVAL={T_RODYN!r}{sch}\n"
             "*OUTPUT, CSV=YES, HDF5=NO\n")
    return text


def write_table(path):
    t, u = samples()
    with open(path, "w") as f:
        f.write("time_s, ux_m, uy_m, uz_m\n")
        for ti, ui in zip(t, u):
            f.write(f"{ti:.9g}, {float(ui)!r}, 0.0, 0.0\n")


def md_deck(n, tool, options):
    """A MoorDyn v2 deck of the system (anchors Fixed 1-3, fairleads Coupled 4-6)."""
    pts = []
    for k in range(NLEG):
        a = " ".join(spar.fmt(x) for x in spar.anchor(k))
        pts.append(f"{k + 1}  Fixed  {a}  0  0  0  0")
    for k, f in enumerate(fairleads()):
        f = " ".join(spar.fmt(x) for x in f)
        pts.append(f"{k + 4}  Coupled  {f}  0  0  0  0")
    lines = "\n".join(f"{k + 1}  chain  {k + 1}  {k + 4}  {LENGTH!r}  {n}  -"
                      for k in range(NLEG))
    opts = "\n".join(f"{v}  {k}" for v, k in options)
    return f"""--------------------- MoorDyn Input File ------------------------------------
OC3-Hywind spar chains, {n} segments a line, for {tool} (bench/systems/spar_speed.py)
---------------------- LINE TYPES ----------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain  {DIAM!r}  {MASS!r}  {EA:.6e}  {BA!r}  0.0  {CDN!r}  {CAN!r}  {CDA!r}  {CAA!r}
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
{chr(10).join(pts)}
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
{lines}
---------------------- OPTIONS -----------------------------------------
{opts}
------------------------- need this line -------------------------------------
"""


def moordyn_options(dtm, ic_thresh=1e-6):
    return [("0", "writeLog"), (repr(dtm), "dtM"), ("RK2", "tScheme"), (repr(G), "g"),
            (repr(RHO), "rho"), (repr(DEPTH), "WtrDpth"), (f"{KBOT:.1e}", "kBot"),
            (f"{CBOT:.1e}", "cBot"), ("0", "ICgenDynamic"), (f"{ic_thresh:g}", "threshIC"),
            ("2000.0", "TmaxIC"), ("1", "disableOutput"), ("1", "disableOutTime")]


def cabledyn_options(dt, rho_inf):
    return [("0", "writeLog"), (repr(dt), "dtM"), (repr(T_END), "TMax"), (repr(G), "g"),
            (repr(RHO), "rhoW"), (repr(DEPTH), "WtrDpth"), (f"{KBOT:.1e}", "kBot"),
            (f"{CBOT:.1e}", "cBot"), (repr(rho_inf), "rhoInf")]


def md_stable_dt(n, courant=0.25):
    """The largest divisor of H not above courant * (L/n) / c."""
    k = math.ceil(H / (courant * (LENGTH / n) / CELERITY) - 1e-9)
    return H / k


# ----------------------------------------------------------------------------- workers
# (run in the venv's Python: python spar_speed.py --worker ...)
class _Quiet:
    """MoorDyn and CableDyn write to the process's stdout/stderr: to /dev/null."""
    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = os.dup(1), os.dup(2)
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.dup2(null, 2)
        os.close(null)

    def __exit__(self, *exc):
        os.dup2(self.saved[0], 1)
        os.dup2(self.saved[1], 2)
        for fd in self.saved:
            os.close(fd)


def ic_path(n):
    thresh = 1e-6 if n <= 80 else 1e-4
    text = md_deck(n, "MoorDyn's initial condition", moordyn_options(md_stable_dt(n), thresh))
    key = hashlib.sha1(text.encode()).hexdigest()[:12]
    return os.path.join(WORK, f"moordyn_ic_{n}_{key}"), text


def worker_moordyn_ic(a):
    import moordyn
    base, text = ic_path(a.n)
    with open(base + ".dat", "w") as f:
        f.write(text)
    c0, w0 = time.process_time(), time.perf_counter()
    with _Quiet():
        s = moordyn.Create(base + ".dat")
        moordyn.Init(s, fairleads().ravel().tolist(), [0.0] * 3 * NLEG)
        data = moordyn.Serialize(s)
        tens = [float(np.linalg.norm(moordyn.GetPointForce(moordyn.GetPoint(s, k + 4))))
                for k in range(NLEG)]
        moordyn.Close(s)
    with open(base + ".bin", "wb") as f:
        f.write(data)
    with open(base + ".json", "w") as f:
        json.dump({"cpu_s": time.process_time() - c0, "wall_s": time.perf_counter() - w0,
                   "static_tension_N": tens}, f)


def moordyn_restored(moordyn, a, deck, x0):
    """MoorDyn on the deck of a.n segments and dtM a.dt (written to `deck`), its static
    state restored from the stationary solve (ic_path); the system and its three
    coupled points."""
    base, _ = ic_path(a.n)
    with open(base + ".bin", "rb") as f:
        data = f.read()
    with open(deck, "w") as f:
        f.write(md_deck(a.n, "MoorDyn", moordyn_options(a.dt)))
    s = moordyn.Create(deck)
    moordyn.Init_NoIC(s, x0.ravel().tolist(), [0.0] * 3 * NLEG)
    moordyn.Deserialize(s, data)
    return s, [moordyn.GetPoint(s, k + 4) for k in range(NLEG)]


def worker_moordyn(a):
    import moordyn
    ts, u = samples()
    nsteps = int(round(T_END / H))
    x0 = fairleads()
    out_t, out_T = [0.0], []
    c0, w0 = time.process_time(), time.perf_counter()
    with _Quiet():
        s, pts = moordyn_restored(moordyn, a, a.out[:-4] + ".dat", x0)
        force = moordyn.GetPointForce
        out_T.append([math.sqrt(sum(c * c for c in force(p))) for p in pts])
        c1, w1 = time.process_time(), time.perf_counter()
        step = moordyn.Step
        status = "complete"
        for k in range(nsteps):
            x = x0.copy()
            x[:, 0] += u[k]
            v = np.zeros_like(x0)
            v[:, 0] = (u[k + 1] - u[k]) / H
            step(s, x.ravel().tolist(), v.ravel().tolist(), float(ts[k]), H)
            tk = [math.sqrt(sum(c * c for c in force(p))) for p in pts]
            out_t.append(float(ts[k + 1]))
            out_T.append(tk)
            if not all(math.isfinite(x) and x < 1e9 for x in tk):
                status = f"unstable at t = {ts[k + 1]:g} s"
                break
        c2, w2 = time.process_time(), time.perf_counter()
        moordyn.Close(s)
    info = {"status": status, "cpu_setup_s": c1 - c0, "wall_setup_s": w1 - w0,
            "cpu_step_s": c2 - c1, "wall_step_s": w2 - w1}
    np.savez(a.out, t=np.array(out_t), T=np.array(out_T).T, info=json.dumps(info))


def worker_moordyn_loop(a):
    """The MoorDyn worker's time loop without moordyn.Step (the coupling arrays, the force
    read-outs): the Python share of its stepping CPU. Prints the CPU [s]."""
    import moordyn
    ts, u = samples()
    x0 = fairleads()
    with _Quiet():
        s, pts = moordyn_restored(moordyn, a, a.out, x0)
        force = moordyn.GetPointForce
        out = []
        c0 = time.process_time()
        for k in range(int(round(T_END / H))):
            x = x0.copy()
            x[:, 0] += u[k]
            v = np.zeros_like(x0)
            v[:, 0] = (u[k + 1] - u[k]) / H
            x.ravel().tolist(), v.ravel().tolist()
            out.append([math.sqrt(sum(c * c for c in force(p))) for p in pts])
        c1 = time.process_time()
        moordyn.Close(s)
    print(f"{c1 - c0!r}")


def worker_cabledyn(a):
    from cabledyn.model import CableDyn
    deck = a.out[:-4] + ".dat"
    with open(deck, "w") as f:
        f.write(md_deck(a.n, "CableDyn", cabledyn_options(a.dt, a.rho_inf)))
    ts, u = samples()
    every = a.dt / H
    if abs(every - round(every)) > 1e-9:
        raise SystemExit("dt must be a multiple of 0.05 s")
    every = int(round(every))
    nsteps = int(round(T_END / a.dt))
    c0, w0 = time.process_time(), time.perf_counter()
    with _Quiet():
        m = CableDyn(deck)
    c1, w1 = time.process_time(), time.perf_counter()
    hd = m.host_dofs()
    q0, _, _ = m.get_coupled_motion()
    hx = hd[0::3]                        # the x DOF of each coupled point

    def tensions():
        f = m.calc_output()[hd].reshape(NLEG, 3)
        return [float(np.linalg.norm(f[k])) for k in range(NLEG)]
    out_t, out_T, iters, status = [0.0], [tensions()], 0, "complete"
    c2, w2 = time.process_time(), time.perf_counter()
    for k in range(nsteps):
        t = (k + 1) * a.dt
        _, ud, udd = surge(t)
        q, v, acc = q0.copy(), np.zeros_like(q0), np.zeros_like(q0)
        q[hx] += u[(k + 1) * every]
        v[hx] = float(ud)
        acc[hx] = float(udd)
        try:
            with _Quiet():
                iters += m.step(a.dt, q, v, acc)
        except Exception as exc:  # noqa: BLE001 - a failed step ends the run, reported
            status = f"failed at t = {t:g} s: {str(exc).splitlines()[0][:120]}"
            break
        out_t.append(t)
        out_T.append(tensions())
    c3, w3 = time.process_time(), time.perf_counter()
    m.close()
    info = {"status": status, "cpu_setup_s": c1 - c0, "wall_setup_s": w1 - w0,
            "cpu_step_s": c3 - c2, "wall_step_s": w3 - w2, "newton_iterations": iters}
    np.savez(a.out, t=np.array(out_t), T=np.array(out_T).T, info=json.dumps(info))


# ----------------------------------------------------------------------------- runs
def ensure_venv():
    if os.path.exists(VENV_PY):
        return
    print(f"creating {os.path.relpath(VENV, ROOT)} ({', '.join(PEER_PACKAGES)}) ...",
          flush=True)
    subprocess.run([sys.executable, "-m", "venv", VENV], check=True)
    subprocess.run([VENV_PY, "-m", "pip", "install", "-q", *PEER_PACKAGES], check=True)


def timed(cmd, cwd=None):
    """Run cmd; (returncode, cpu user+sys [s], wall [s], load1 at the start, stderr)."""
    load1 = os.getloadavg()[0]
    w0 = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=cwd, env=ENV, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    err = p.stderr.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - w0
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, ru.ru_utime + ru.ru_stime, wall, load1, err


class Runner:
    def __init__(self, rodyn, fresh):
        self.rodyn = rodyn
        self.fresh = fresh
        os.makedirs(WORK, exist_ok=True)
        write_table(os.path.join(WORK, "motion.csv"))

    # each run: a dict with tool, knobs, tag, result (t, T), cost fields
    def rodyn_run(self, elements, order, dt, scheme="EMC", timing_only=False):
        tag = f"rodyn_e{elements}_p{order}_dt{dt:g}" + ("" if scheme == "EMC" else "_alpha")
        deck = os.path.join(WORK, tag + ".inp")
        out = os.path.join(WORK, tag)
        store = out + ".npz"
        if os.path.exists(store) and not self.fresh and not timing_only:
            return load(store)
        with open(deck, "w") as f:
            f.write(rodyn_deck(elements, order, dt, scheme=None if scheme == "EMC" else scheme))
        rc, cpu, wall, load1, err = timed([self.rodyn, deck, "-o", out, "--quiet"])
        st = benchlib.read_status(os.path.join(out, "status.txt")) \
            if os.path.exists(os.path.join(out, "status.txt")) else {}
        info = {"tool": "rodyn", "tag": tag, "elements": elements, "order": order, "dt": dt,
                "scheme": scheme,
                "status": st.get("status", f"exit {rc}") if rc == 0 or st else f"exit {rc}",
                "cpu_s": cpu, "wall_s": wall, "load1": load1,
                "steps": int(st.get("steps", 0) or 0),
                "newton_iterations": int(st.get("step_iterations", 0) or 0),
                "tangents": int(st.get("step_tangents", 0) or 0)}
        if timing_only:
            return info
        t, T = read_rodyn(out) if rc == 0 else (np.zeros(1), np.zeros((NLEG, 1)))
        save(store, t, T, info)
        return load(store)

    def rodyn_statics_cpu(self, elements, order):
        """CPU of the same deck without *DYNAMIC (deck, statics, its output)."""
        tag = f"rodyn_e{elements}_p{order}_static"
        deck = os.path.join(WORK, tag + ".inp")
        text = "".join(ln for ln in rodyn_deck(elements, order, 0.1).splitlines(True)
                       if not ln.startswith("*DYNAMIC"))
        with open(deck, "w") as f:
            f.write(text)
        rc, cpu, wall, load1, _ = timed([self.rodyn, deck, "-o",
                                         os.path.join(WORK, tag), "--quiet"])
        return cpu, wall, load1

    def moordyn_run(self, n, dtm, timing_only=False):
        tag = f"moordyn_n{n}_dt{dtm:.6g}"
        store = os.path.join(WORK, tag + ".npz")
        if os.path.exists(store) and not self.fresh and not timing_only:
            return load(store)
        base, _ = ic_path(n)
        ic_note = {}
        if not os.path.exists(base + ".bin"):
            rc, cpu, wall, _, err = timed([VENV_PY, __file__, "--worker", "moordyn-ic",
                                           "--n", str(n)])
            if rc != 0:
                raise RuntimeError(f"MoorDyn's initial condition, {n} segments: {err}")
        with open(base + ".json") as f:
            ic = json.load(f)
        ic_note = {"ic_cpu_s": ic["cpu_s"], "ic_wall_s": ic["wall_s"]}
        rc, cpu, wall, load1, err = timed([VENV_PY, __file__, "--worker", "moordyn",
                                           "--n", str(n), "--dt", repr(dtm),
                                           "--out", store + ".tmp.npz"])
        return self._peer_result("MoorDyn", tag, store, rc, cpu, wall, load1, err,
                                 dict(segments=n, dt=dtm, **ic_note), timing_only)

    def cabledyn_run(self, n, dt, rho_inf=0.4, timing_only=False):
        tag = f"cabledyn_n{n}_dt{dt:g}_r{rho_inf:g}"
        store = os.path.join(WORK, tag + ".npz")
        if os.path.exists(store) and not self.fresh and not timing_only:
            return load(store)
        rc, cpu, wall, load1, err = timed([VENV_PY, __file__, "--worker", "cabledyn",
                                           "--n", str(n), "--dt", repr(dt), "--rho-inf",
                                           repr(rho_inf), "--out", store + ".tmp.npz"])
        return self._peer_result("CableDyn", tag, store, rc, cpu, wall, load1, err,
                                 dict(segments=n, dt=dt, rho_inf=rho_inf), timing_only)

    @staticmethod
    def _peer_result(tool, tag, store, rc, cpu, wall, load1, err, knobs, timing_only):
        tmp = store + ".tmp.npz"
        info = {"tool": tool, "tag": tag, **knobs, "cpu_s": cpu, "wall_s": wall,
                "load1": load1}
        if rc != 0 or not os.path.exists(tmp):
            info["status"] = f"exit {rc}: {err.strip().splitlines()[-1][:160] if err else ''}"
            t, T = np.zeros(1), np.zeros((NLEG, 1))
        else:
            d = np.load(tmp)
            info.update(json.loads(str(d["info"])))
            t, T = d["t"], d["T"]
            os.remove(tmp)
        if timing_only:
            return info
        save(store, t, T, info)
        return load(store)


def read_rodyn(out):
    """Step times and (3, n) fairlead tensions (end B of L1..L3) from
    dynamic_ends_step.csv."""
    t = {k: [] for k in range(NLEG)}
    T = {k: [] for k in range(NLEG)}
    with open(os.path.join(out, "dynamic_ends_step.csv")) as f:
        head = f.readline().strip().split(",")
        it, il, ie, iT = (head.index(c) for c in ("time_s", "line", "end", "tension_N"))
        for line in f:
            c = line.split(",")
            if c[ie] == "B":
                k = int(c[il][1:]) - 1
                t[k].append(float(c[it]))
                T[k].append(float(c[iT]))
    return np.array(t[0]), np.array([T[k] for k in range(NLEG)])


def save(path, t, T, info):
    np.savez(path, t=np.asarray(t, float), T=np.asarray(T, float), info=json.dumps(info))


def load(path):
    d = np.load(path)
    return {"t": d["t"], "T": d["T"], "info": json.loads(str(d["info"]))}


def complete(run):
    return run["info"].get("status") == "complete" and run["t"][-1] >= T_END - 1e-6


# ----------------------------------------------------------------------------- plan
REF_MD = [(40, None), (80, None), (160, None), (320, None), (160, "half")]
REF_RODYN = [(20, 3, 0.1), (40, 3, 0.05), (80, 3, 0.025)]
SWEEP_RODYN = ([(e, 3, dt) for e in (3, 4, 5, 6, 8, 10, 15, 20)
                for dt in (0.05, 0.1, 0.15, 0.2)]
               + [(e, 3, dt) for e in (3, 4, 5, 6, 8, 10) for dt in (0.25, 0.3, 0.4)]
               + [(e, 3, dt) for e in (3, 4, 5, 6, 8) for dt in (0.5, 0.6)]
               + [(e, 2, dt) for e in (6, 8, 10, 15, 20) for dt in (0.1, 0.2)]
               + [(e, 3, dt, "ALPHA") for e in (5, 6, 8, 10) for dt in (0.1, 0.15, 0.2)])
# MoorDyn: dtM at Courant numbers 0.3, 0.25 and 0.125 of a segment (duplicates dropped)
SWEEP_MD = sorted({(n, md_stable_dt(n, c)) for n in (8, 10, 12, 14, 16, 18, 20, 24, 30, 40)
                   for c in (0.3, 0.25, 0.125)})
SWEEP_CD = [(n, dt) for n in (8, 10, 12, 14, 16, 20, 24, 30, 40)
            for dt in (0.05, 0.1, 0.2, 0.4)]
SWEEP_CD += [(n, dt) for n in (16, 20, 24) for dt in (0.5, 0.6, 0.8)]


def ref_md_dt(n, how):
    dt = md_stable_dt(n, 0.25)
    return dt / 2 if how == "half" else dt


def knobs(info):
    if info["tool"] == "rodyn":
        return (f"{info['elements']} el. p{info['order']}, dt {info['dt']:g} s"
                + ("" if info.get("scheme", "EMC") == "EMC" else f", {info['scheme']}"))
    s = f"{info['segments']} seg., dt {info['dt']:.4g} s"
    return s + (f", rhoInf {info['rho_inf']:g}" if info["tool"] == "CableDyn" else "")


def row(info, err=None, per=None, phase=""):
    r = {"phase": phase, "tool": info["tool"], "tag": info["tag"],
         "elements_or_segments": info.get("elements", info.get("segments")),
         "scheme": info.get("scheme"),
         "order": info.get("order", 1), "dt_s": repr(float(info["dt"])),
         "rho_inf": info.get("rho_inf"),
         "status": info.get("status"), "error": err,
         "error_F1": per[0] if per else None, "error_F2": per[1] if per else None,
         "error_F3": per[2] if per else None, "cpu_s": info["cpu_s"],
         "wall_s": info["wall_s"], "cpu_step_s": info.get("cpu_step_s"),
         "wall_step_s": info.get("wall_step_s"), "cpu_setup_s": info.get("cpu_setup_s"),
         "ic_cpu_s": info.get("ic_cpu_s"), "load1": info["load1"],
         "steps": info.get("steps"), "newton_iterations": info.get("newton_iterations"),
         "tangents": info.get("tangents")}
    return r


def cost(info):
    """The figure a run is ranked by: rodyn's process CPU, a peer's stepping CPU."""
    return info["cpu_s"] if info["tool"] == "rodyn" else info.get("cpu_step_s", info["cpu_s"])


def print_table(title, rows):
    print(f"\n{title}")
    print(f"{'tool':9s} {'settings':34s} {'error %':>8s} {'CPU s':>8s} {'step CPU':>8s} "
          f"{'wall s':>8s} {'load':>5s}  status")
    for r in rows:
        e = "" if r["error"] is None else f"{100 * r['error']:.3f}"
        sc = "" if r.get("cpu_step_s") is None else f"{r['cpu_step_s']:.3f}"
        print(f"{r['tool']:9s} {r['settings']:34s} {e:>8s} {r['cpu_s']:8.3f} {sc:>8s} "
              f"{r['wall_s']:8.3f} {r['load1']:5.2f}  {r['status']}")


def evaluate(runs, ref, phase):
    out = []
    for run in runs:
        info = run["info"]
        e, per = (error(run, ref) if complete(run) else (None, None))
        r = row(info, e, per, phase)
        r["settings"] = knobs(info)
        out.append(r)
    return out


def final_timing(runner, sweep_rows, repeats):
    """The three cheapest sweep runs at <= TARGET per tool, timed `repeats` times."""
    out, best = [], {}
    for tool in ("rodyn", "MoorDyn", "CableDyn"):
        ok = [r for r in sweep_rows if r["tool"] == tool and r["error"] is not None
              and r["error"] <= TARGET]
        ok.sort(key=lambda r: r["cpu_s"] if tool == "rodyn" else r["cpu_step_s"])
        for r in ok[:3]:
            dt, infos = float(r["dt_s"]), []
            for _ in range(repeats):
                if tool == "rodyn":
                    infos.append(runner.rodyn_run(r["elements_or_segments"], r["order"],
                                                  dt, r["scheme"], timing_only=True))
                elif tool == "MoorDyn":
                    infos.append(runner.moordyn_run(r["elements_or_segments"], dt,
                                                    timing_only=True))
                else:
                    infos.append(runner.cabledyn_run(r["elements_or_segments"], dt,
                                                     r["rho_inf"], timing_only=True))
            med = dict(infos[0])
            for k in ("cpu_s", "wall_s", "cpu_step_s", "wall_step_s", "cpu_setup_s"):
                if infos[0].get(k) is not None:
                    med[k] = statistics.median(i[k] for i in infos)
            med["load1"] = max(i["load1"] for i in infos)
            fr = row(med, r["error"], [r["error_F1"], r["error_F2"], r["error_F3"]],
                     "final")
            fr["settings"] = r["settings"]
            fr["repeats"] = repeats
            fr["cpu_all_s"] = " ".join(f"{i['cpu_s']:.3f}" for i in infos)
            fr["load1_all"] = " ".join(f"{i['load1']:.2f}" for i in infos)
            if tool != "rodyn":
                fr["cpu_step_all_s"] = " ".join(f"{i['cpu_step_s']:.3f}" for i in infos)
            out.append(fr)
            c = fr["cpu_s"] if tool == "rodyn" else fr["cpu_step_s"]
            if tool not in best or c < best[tool][0]:
                best[tool] = (c, fr)
    return out, best


COLUMNS = ["phase", "tool", "tag", "elements_or_segments", "order", "scheme", "dt_s",
           "rho_inf", "status", "error", "error_F1", "error_F2", "error_F3", "cpu_s",
           "wall_s", "cpu_step_s", "wall_step_s", "cpu_setup_s", "ic_cpu_s", "load1", "steps",
           "newton_iterations", "tangents", "repeats", "cpu_all_s", "cpu_step_all_s",
           "load1_all", "settings"]


def read_csv_rows():
    import csv
    with open(RESULTS_CSV) as f:
        rows = list(csv.DictReader(ln for ln in f if not ln.startswith("#")))
    for r in rows:
        for k in ("error", "error_F1", "error_F2", "error_F3", "cpu_s", "wall_s",
                  "cpu_step_s", "rho_inf", "load1"):
            r[k] = float(r[k]) if r.get(k) not in (None, "") else None
        for k in ("elements_or_segments", "order"):
            r[k] = int(r[k])
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--fresh", action="store_true", help="ignore the stored runs")
    ap.add_argument("--final", action="store_true",
                    help="only re-time the sweep's cheapest runs (stored sweep)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--worker", choices=("moordyn", "moordyn-ic", "moordyn-loop", "cabledyn"),
                    help=argparse.SUPPRESS)
    ap.add_argument("--n", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--dt", type=float, help=argparse.SUPPRESS)
    ap.add_argument("--rho-inf", type=float, default=0.4, help=argparse.SUPPRESS)
    ap.add_argument("--out", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.worker:
        {"moordyn": worker_moordyn, "moordyn-ic": worker_moordyn_ic,
         "moordyn-loop": worker_moordyn_loop, "cabledyn": worker_cabledyn}[a.worker](a)
        return 0
    rodyn = benchlib.check_rodyn(a.rodyn)
    ensure_venv()
    facts = benchlib.machine_facts(rodyn, load_average=True)
    runner = Runner(rodyn, a.fresh)
    for k, v in facts.items():
        print(f"{k}: {v}")

    # the reference: MoorDyn's ladder
    ref_runs = [runner.moordyn_run(n, ref_md_dt(n, how)) for n, how in REF_MD]
    ref = ref_runs[3]
    rows = evaluate(ref_runs, ref, "reference")
    for r, (n, how) in zip(rows, REF_MD):
        r["settings"] += " (half dtM)" if how else ""
    # successive changes of the ladder
    notes = []
    for i in range(1, 4):
        if complete(ref_runs[i]) and complete(ref_runs[i - 1]):
            e, _ = error(ref_runs[i - 1], ref_runs[i])
            notes.append(f"MoorDyn {REF_MD[i - 1][0]} -> {REF_MD[i][0]} segments: "
                         f"{100 * e:.3f} %")
    e, _ = error(ref_runs[4], ref_runs[2])
    notes.append(f"MoorDyn 160 segments, dtM halved: {100 * e:.4f} %")
    st = [json.load(open(ic_path(n)[0] + ".json"))["static_tension_N"][0]
          for n, how in REF_MD[:4]]
    notes.append("MoorDyn static fairlead tension F1 at 40/80/160/320 segments: "
                 + ", ".join(f"{x:.1f}" for x in st) + " N")
    rod_ref = [runner.rodyn_run(*k) for k in REF_RODYN]
    rows += evaluate(rod_ref, ref, "reference")
    for i in range(1, len(rod_ref)):
        e, _ = error(rod_ref[i - 1], rod_ref[i])
        notes.append(f"rodyn {REF_RODYN[i - 1][0]} -> {REF_RODYN[i][0]} cubic elements: "
                     f"{100 * e:.3f} %")
    notes.append("rodyn static fairlead tension F1 at 20/40/80 cubic elements: "
                 + ", ".join(f"{r['T'][0][0]:.1f}" for r in rod_ref) + " N")
    e_conv, _ = error(rod_ref[-1], ref)
    notes.append(f"rodyn converged (80 cubic, dt 0.025 s) against MoorDyn converged: "
                 f"{100 * e_conv:.3f} %")
    print_table("Reference (errors against MoorDyn 320 segments)", rows)
    for n_ in notes:
        print("  " + n_)

    if a.final:
        sweep_rows = [r for r in read_csv_rows() if r["phase"] == "sweep"]
    else:
        runs = [runner.rodyn_run(*k) for k in SWEEP_RODYN]
        runs += [runner.moordyn_run(n, dt) for n, dt in SWEEP_MD]
        runs += [runner.cabledyn_run(n, dt) for n, dt in SWEEP_CD]
        sweep_rows = evaluate(runs, ref, "sweep")
        print_table("Sweep (one run each; errors against MoorDyn 320 segments)", sweep_rows)

    final_rows, best = final_timing(runner, sweep_rows, a.repeats)
    print_table(f"Final: the three cheapest runs at <= 1 % per tool, median of {a.repeats}",
                final_rows)
    summary = []
    if "rodyn" in best:
        rc, rr = best["rodyn"]
        st_cpu, st_wall, _ = runner.rodyn_statics_cpu(rr["elements_or_segments"],
                                                      rr["order"])
        summary.append(f"rodyn's cheapest at <= 1 %: {rr['settings']}, error "
                       f"{100 * rr['error']:.3f} %, CPU {rr['cpu_s']:.3f} s, wall "
                       f"{rr['wall_s']:.3f} s (statics alone: CPU {st_cpu:.3f} s)")
        for tool in ("MoorDyn", "CableDyn"):
            if tool not in best:
                summary.append(f"{tool}: no run at <= 1 %")
                continue
            pc, pr = best[tool]
            if tool == "MoorDyn":
                loop = []
                for _ in range(a.repeats):
                    p = subprocess.run([VENV_PY, __file__, "--worker", "moordyn-loop", "--n",
                                        str(pr["elements_or_segments"]), "--dt", pr["dt_s"],
                                        "--out", os.path.join(WORK, "moordyn_loop.dat")],
                                       env=ENV, capture_output=True, text=True, check=True)
                    loop.append(float(p.stdout.split()[-1]))
                loop = statistics.median(loop)
                summary.append(
                    f"MoorDyn's time loop without moordyn.Step (Python, coupling arrays, "
                    f"force read-outs): CPU {loop:.3f} s, median of {a.repeats}; MoorDyn "
                    f"stepping less it / rodyn process CPU = "
                    f"{(pr['cpu_step_s'] - loop) / rr['cpu_s']:.2f}")
            summary.append(
                f"{tool}'s cheapest at <= 1 %: {pr['settings']}, error "
                f"{100 * pr['error']:.3f} %, stepping CPU {pr['cpu_step_s']:.3f} s "
                f"(process {pr['cpu_s']:.3f} s, wall {pr['wall_s']:.3f} s); "
                f"{tool} stepping / rodyn process CPU = {pr['cpu_step_s'] / rr['cpu_s']:.2f}, "
                f"process / process = {pr['cpu_s'] / rr['cpu_s']:.2f}, wall / wall = "
                f"{pr['wall_s'] / rr['wall_s']:.2f}, stepping / rodyn dynamics "
                f"(process less statics) = "
                f"{pr['cpu_step_s'] / max(rr['cpu_s'] - st_cpu, 1e-9):.2f}")
    print()
    for s in summary:
        print(s)
    allrows = rows + sweep_rows + final_rows
    facts["load average after the run (1/5/15 min)"] = " / ".join(
        f"{x:.2f}" for x in os.getloadavg())
    comments = ["error: max over F1-F3 of max |T - T_ref| / max T_ref, t = 300..600 s every "
                "0.1 s, T_ref MoorDyn 320 segments (see the script's docstring)",
                "cpu_s, wall_s: the run's whole process (os.wait4), "
                "OPENBLAS_NUM_THREADS=OMP_NUM_THREADS=1; cpu_step_s: a peer's time loop "
                "alone (in-process CPU); load1: 1-minute load average at the run's start "
                "(final rows: the largest of the repeats)"] + notes + summary
    benchlib.write_csv(RESULTS_CSV, facts, COLUMNS, allrows, comments)
    print("wrote", os.path.relpath(RESULTS_CSV, ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
