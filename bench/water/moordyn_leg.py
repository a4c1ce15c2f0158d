#!/usr/bin/env python3
"""MoorDyn v2 (Python package `moordyn`) runs of the water issue's mooring leg.

Writes the MoorDyn v2 input files bench/water/moordyn/leg_N.dat (one line of N segments
from a Fixed point at the anchor to a Coupled point at the fairlead), then for each N:

  static  MoorDyn's own initial equilibrium (moordyn.Init, stationary solver,
          ICgenDynamic 0, with threshIC and TmaxIC tightened, see IC_* below), then a
          check: the static state is held for STATIC_HOLD s of dynamics with the
          fairlead fixed and the drift of the fairlead force is reported.
  surge   from that state the fairlead moves in x by leg.surge(t) for 120 s. Every
          moordyn.Step call advances one MoorDyn time step dt (the coupling interval is
          dt): it gets the fairlead position at t_k and the secant velocity
          (x(t_k+1) - x(t_k)) / dt, which MoorDyn extrapolates linearly over the step,
          so the fairlead follows the exact motion at every step end.

Fairlead force = moordyn.GetPointForce of the Coupled point: the force of the line on
the fairlead (the end segment's tension and damping plus the end node's half-segment
weight, buoyancy, drag and seabed force; MoorDyn leaves the end node's inertia to the
coupled body and does not include it). The end segment's tension
(moordyn.GetLineFairTen, the tension at the middle of the last segment) is stored too.

Conventions of MoorDyn v2 (source/Line.cpp of v2.7): node mass and weight from the
unstretched segment lengths, W = (m - rho pi d^2/4) g per unstretched length; normal
drag 0.5 rho Cd d |vp| vp and axial drag 0.5 rho CdAx pi d |vq| vq per unstretched
length (axial drag on the surface pi d); added mass rho pi d^2/4 (Ca (I - qq^T) +
CaAx qq^T); internal damping BA [N s] times the strain rate, and BA < 0 means
-BA times the critical damping of one segment's axial mode, BA = -BA_in (L/N)
sqrt(EA m); seabed: vertical spring-damper (kbot pen - cbot vz) d l per node, kbot
3e6 Pa/m, cbot 3e5 Pa s/m (defaults), no friction (FrictionCoefficient 0 default).

  python3 bench/water/moordyn_leg.py --segments 20 40 80 160
  python3 bench/water/moordyn_leg.py --segments 40 --dt 2e-4 --static-only
"""
import argparse
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import leg  # noqa: E402

DECK_DIR = os.path.join(HERE, "moordyn")
BA_DEFAULT = -1.0          # critical damping of each segment's axial mode
IC_THRESH = 1.0e-9         # threshIC (MoorDyn default 0.001)
IC_TMAX = 2000.0           # TmaxIC [s] (MoorDyn default 120)
STATIC_HOLD = 0.0

DECK = """--------------------- MoorDyn Input File ------------------------------------
{title}
---------------------- LINE TYPES ----------------------------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      {d!r}   {m!r}   {ea:.6e}   {ba!r}   0.0   {cd!r}   {ca!r}   {cdax!r}   {caax!r}
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed      {xa!r}  {ya!r}  {za!r}   0      0       0      0
2     Coupled    {xb!r}  {yb!r}  {zb!r}   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     chain       1        2        {length!r}      {n}       -
---------------------- OPTIONS -----------------------------------------
0             writeLog
{dt!r}        dtM
RK2           tScheme
{g!r}         g
{rho!r}       rho
{depth!r}     WtrDpth
3.0e6         kbot
{cbot}      cbot
{wavekin}0             ICgenDynamic
{ic_thresh!r} threshIC
{ic_tmax!r}   TmaxIC
1             disableOutput
1             disableOutTime
------------------------- need this line -------------------------------------
"""


CURRENT_PROFILE = """MoorDyn current profile: uniform current of the water issue's case (c)
z (m)   Ux (m/s)   Uy (m/s)   Uz (m/s)
---------------------------------------
{rows}
"""


def current_static(n, dt=None, ba=BA_DEFAULT, t_max=4000.0, check=20.0, tol=1e-3):
    """Case (c): static equilibrium in a uniform current (Currents 1: a steady
    profile read from current_profile.txt next to the input file, here
    bench/water/moordyn/current/). MoorDyn v2 computes its initial condition without
    water kinematics (currents are set up after the IC), so moordyn.Init gives the
    still-water shape and the current's equilibrium is reached by dynamic relaxation:
    MoorDyn's dynamics with the fairlead held fixed, until the fairlead force changes
    by less than tol [N] (each component) over `check` seconds, at most t_max s.
    Returns the fairlead force and the shape."""
    import moordyn as md
    dt = dt or default_dt(n)
    folder = os.path.join(DECK_DIR, "current")
    os.makedirs(folder, exist_ok=True)
    u = leg.CURRENT
    rows = "\n".join(f"{z:8.2f}  {u[0]!r}  {u[1]!r}  {u[2]!r}"
                     for z in (-leg.DEPTH - 10.0, -leg.DEPTH, 0.0, 10.0))
    with open(os.path.join(folder, "current_profile.txt"), "w") as fh:
        fh.write(CURRENT_PROFILE.format(rows=rows))
    text = deck_text(n, dt, ba).replace(
        "0             ICgenDynamic", "1             Currents\n0             ICgenDynamic")
    path = os.path.join(folder, f"leg_current_{n}.dat")
    with open(path, "w") as fh:
        fh.write(text)
    t0 = time.perf_counter()
    s = md.Create(path)
    md.Init(s, list(leg.FAIRLEAD), [0.0, 0.0, 0.0])
    point = md.GetPoint(s, 2)
    line = md.GetLine(s, 1)
    t, f_prev, hist = 0.0, np.array(md.GetPointForce(point)), []
    while t < t_max - 1e-9:
        for _ in range(int(round(check / 0.1))):
            md.Step(s, list(leg.FAIRLEAD), [0.0, 0.0, 0.0], t, 0.1)
            t += 0.1
        f = np.array(md.GetPointForce(point))
        hist.append([t] + f.tolist())
        if np.max(np.abs(f - f_prev)) < tol:
            break
        f_prev = f
    wall = time.perf_counter() - t0
    shape = np.array([md.GetLineNodePos(line, i) for i in range(n + 1)])
    out = {"segments": n, "dt": dt, "ba": ba, "wall_s": wall, "relaxation_time_s": t,
           "last_change_N": float(np.max(np.abs(f - f_prev))),
           "fairlead_force_N": f.tolist(), "fairlead_tension_N": float(np.linalg.norm(f)),
           "end_segment_tension_N": float(md.GetLineFairTen(line)),
           "anchor_segment_tension_N": float(np.linalg.norm(md.GetLineNodeTen(line, 0))),
           "max_y_m": float(shape[:, 1].max()), "shape_m": shape.tolist()}
    md.Close(s)
    return out


def default_dt(n):
    """dtM used for n segments: RK2 with BA = -1 is stable up to about
    0.3 l / c (l = L/n, c = sqrt(EA/m)); we take 0.25 l / c rounded down to a divisor
    of 0.1 s (measured: see README)."""
    c = np.sqrt(leg.EA / leg.MASS)
    dt = 0.25 * (leg.LENGTH / n) / c
    k = int(np.ceil(0.1 / dt))
    return 0.1 / k


def deck_text(n, dt, ba=BA_DEFAULT, title=None, cbot="3.0e5", wavekin=None,
              ic_thresh=IC_THRESH, ic_tmax=IC_TMAX):
    """The leg's MoorDyn input; bench/waves/moordyn_waves.py writes its own with another
    title, seabed damping cbot (as written), WaveKin and initial-condition controls."""
    title = title or (f"rodyn bench/water: mooring leg of the water issue, {n} segments "
                      "(generated by moordyn_leg.py)")
    wk = "" if wavekin is None else f"{wavekin:<14d}WaveKin\n"
    return DECK.format(n=n, d=leg.DIAM, m=leg.MASS, ea=leg.EA, ba=ba, cd=leg.CD, ca=leg.CA,
                       cdax=leg.CDAX, caax=leg.CAAX, xa=leg.ANCHOR[0], ya=leg.ANCHOR[1],
                       za=leg.ANCHOR[2], xb=leg.FAIRLEAD[0], yb=leg.FAIRLEAD[1],
                       zb=leg.FAIRLEAD[2], length=leg.LENGTH, dt=dt, g=leg.G,
                       rho=leg.RHO, depth=leg.DEPTH, ic_thresh=ic_thresh, ic_tmax=ic_tmax,
                       title=title, cbot=cbot, wavekin=wk)


def write_deck(n, dt, ba=BA_DEFAULT, path=None):
    path = path or os.path.join(DECK_DIR, f"leg_{n}.dat")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(deck_text(n, dt, ba))
    return path


def touchdown(md, line, n):
    """x of the first node (from the anchor) above the seabed by more than 1 cm, and its
    node index (the nodes on the seabed sink by about w / (kbot d) = 1.7 mm)."""
    for i in range(n + 1):
        p = md.GetLineNodePos(line, i)
        if p[2] > -leg.DEPTH + 0.01:
            return i, p[0]
    return n, float("nan")


def static(n, dt=None, ba=BA_DEFAULT):
    import moordyn as md
    dt = dt or default_dt(n)
    if dt == default_dt(n) and ba == BA_DEFAULT:
        path = write_deck(n, dt, ba)      # the stored deck bench/water/moordyn/leg_N.dat
    else:
        path = write_deck(n, dt, ba, os.path.join(WORK, f"leg_{n}_{dt:.6g}_{ba:g}.dat"))
    t0 = time.perf_counter()
    s = md.Create(path)
    md.Init(s, list(leg.FAIRLEAD), [0.0, 0.0, 0.0])
    wall = time.perf_counter() - t0
    point = md.GetPoint(s, 2)
    line = md.GetLine(s, 1)
    f = np.array(md.GetPointForce(point))
    ten_end = md.GetLineFairTen(line)
    ten_a = md.GetLineNodeTen(line, 0)
    itd, xtd = touchdown(md, line, n)
    shape = np.array([md.GetLineNodePos(line, i) for i in range(n + 1)])
    out = {"segments": n, "dt": dt, "ba": ba, "wall_static_s": wall,
           "fairlead_force_N": f.tolist(), "fairlead_tension_N": float(np.linalg.norm(f)),
           "end_segment_tension_N": float(ten_end),
           "anchor_segment_tension_N": float(np.linalg.norm(ten_a)),
           "first_suspended_node": itd, "first_suspended_node_x_m": float(xtd),
           "shape_m": shape.tolist()}
    return s, out


def surge(n, dt=None, ba=BA_DEFAULT, t_end=leg.T_END, out_dt=0.1, quiet=False):
    import moordyn as md
    dt = dt or default_dt(n)
    every = out_dt / dt
    if abs(every - round(every)) > 1e-6:
        raise ValueError(f"dt {dt} must divide the output interval {out_dt}")
    every = int(round(every))
    s, st = static(n, dt, ba)
    point = md.GetPoint(s, 2)
    line = md.GetLine(s, 1)
    steps = int(round(t_end / dt))
    times = np.arange(steps + 1) * dt
    x = leg.FAIRLEAD[0] + leg.surge(times)
    vx = np.diff(x) / dt
    yb, zb = leg.FAIRLEAD[1], leg.FAIRLEAD[2]
    rec_t, rec_f, rec_te = [0.0], [md.GetPointForce(point)], [md.GetLineFairTen(line)]
    step = md.Step
    t0 = time.perf_counter()
    for k in range(steps):
        step(s, [x[k], yb, zb], [vx[k], 0.0, 0.0], times[k], dt)
        if (k + 1) % every == 0:
            f = md.GetPointForce(point)
            rec_t.append(times[k + 1])
            rec_f.append(f)
            rec_te.append(md.GetLineFairTen(line))
            if not np.all(np.isfinite(f)) or np.linalg.norm(f) > 1e8:
                raise RuntimeError(f"N={n} dt={dt}: unstable at t={times[k + 1]}")
    wall = time.perf_counter() - t0
    md.Close(s)
    f = np.array(rec_f)
    res = {"time_s": np.array(rec_t), "F": f, "tension": np.linalg.norm(f, axis=1),
           "end_segment_tension": np.array(rec_te), "wall_dynamic_s": wall,
           "static": st, "dt": dt, "ba": ba, "segments": n, "steps": steps}
    if not quiet:
        print(f"N={n} dt={dt:.4g}: static {st['fairlead_tension_N']:.2f} N "
              f"({st['wall_static_s']:.1f} s), surge wall {wall:.1f} s", flush=True)
    return res


def harmonic(t, y, period=leg.PERIOD, window=leg.WINDOW):
    """Mean and first harmonic (amplitude, phase of the cosine: y ~ mean +
    a cos(2 pi t / period + phase)) by least squares over the window (samples with
    window[0] <= t <= window[1]; the window spans whole periods; the end sample is
    dropped so that the samples are uniform over exactly whole periods)."""
    sel = (t >= window[0] - 1e-9) & (t < window[1] - 1e-9)
    tt, yy = t[sel], y[sel]
    w = 2.0 * np.pi / period
    a = np.column_stack([np.ones_like(tt), np.cos(w * tt), np.sin(w * tt)])
    c = np.linalg.lstsq(a, yy, rcond=None)[0]
    amp = float(np.hypot(c[1], c[2]))
    phase = float(np.arctan2(-c[2], c[1]))
    return float(c[0]), amp, phase


def summary(res):
    t, ten = res["time_s"], res["tension"]
    sel = (t >= leg.WINDOW[0] - 1e-9) & (t <= leg.WINDOW[1] + 1e-9)
    mean_h, amp, phase = harmonic(t, ten)
    return {"segments": int(res["segments"]), "dt_s": float(res["dt"]), "ba": float(res["ba"]),
            "static_fairlead_tension_N": res["static"]["fairlead_tension_N"],
            "max_N": float(ten[sel].max()), "min_N": float(ten[sel].min()),
            "mean_N": float(ten[sel][:-1].mean()),
            "harmonic1_amplitude_N": amp, "harmonic1_phase_rad": phase,
            "harmonic_mean_N": mean_h,
            "wall_static_s": res["static"]["wall_static_s"],
            "wall_dynamic_s": float(res["wall_dynamic_s"]), "steps": int(res["steps"]),
            "raw_min_note": "min_N includes the touchdown impact spikes of the discrete "
                            "line (they shrink with N)"}


WORK = os.path.join(HERE, ".work")
REF = os.path.join(HERE, "reference")


def cached_surge(n, dt=None, ba=BA_DEFAULT, fresh=False):
    """surge() with its result kept in bench/water/.work/moordyn_surge_N_dt_ba.npz."""
    dt = dt or default_dt(n)
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, f"moordyn_surge_{n}_{dt:.6g}_{ba:g}.npz")
    if os.path.exists(path) and not fresh:
        z = np.load(path, allow_pickle=True)
        return {k: (z[k].item() if z[k].dtype == object else z[k]) for k in z.files}
    res = surge(n, dt, ba)
    res["static"].pop("shape_m", None)
    np.savez(path, **{k: (np.array(v, dtype=object) if isinstance(v, dict) else v)
                      for k, v in res.items()})
    return res


def write_references(segments, dt_check=True, fresh=False, ba=BA_DEFAULT):
    """Runs the surge case for each N (cached), writes moordyn_surge_summary.json and
    the finest run's fairlead history moordyn_surge_fairlead.csv."""
    import moordyn as md
    runs = [cached_surge(n, None, ba, fresh) for n in segments]
    rows = [summary(r) for r in runs]
    finest = runs[-1]
    checks = []
    if dt_check:
        r2 = cached_surge(finest["segments"], finest["dt"] / 2.0, ba, fresh)
        checks.append(summary(r2))
    import leg as _leg
    out = {"description": "MoorDyn v2 surge case (b) of the water issue's mooring leg: "
                          "force of the line on the fairlead (moordyn.GetPointForce of the "
                          "Coupled point). Statistics over 72-120 s (4 periods of 12 s); "
                          "harmonic: least squares fit T ~ mean + a cos(2 pi t/12 + phase) "
                          "to the 0.1 s samples with 72 <= t < 120 s. Generated by "
                          "bench/water/moordyn_leg.py.",
           "moordyn_version": getattr(md, "__version__", "") or "2.7.2 (pip)",
           "time_scheme": "RK2", "ba_input": ba,
           "ba_note": "BA/-zeta column -1: internal damping = critical damping of one "
                      "segment's axial mode, BA = (L/N) sqrt(EA m) N s",
           "coupling": "one moordyn.Step per dtM; fairlead position exact at step ends, "
                       "secant velocity over the step",
           "static_ic": f"moordyn.Init, stationary solver (ICgenDynamic 0), threshIC "
                        f"{IC_THRESH:g}, TmaxIC {IC_TMAX:g} s",
           "window_s": list(_leg.WINDOW), "runs": rows, "dt_check": checks,
           "csv": f"moordyn_surge_fairlead.csv is the N = {finest['segments']} run"}
    os.makedirs(REF, exist_ok=True)
    with open(os.path.join(REF, "moordyn_surge_summary.json"), "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    t, f = finest["time_s"], finest["F"]
    with open(os.path.join(REF, "moordyn_surge_fairlead.csv"), "w") as fh:
        fh.write(f"# MoorDyn {out['moordyn_version']} surge case, N = {finest['segments']}, "
                 f"dtM = {finest['dt']:.6g} s, BA {ba:g}; force of the line on the "
                 "fairlead [N] (global axes)\n")
        fh.write("time_s,fairlead_tension_N,Fx_N,Fy_N,Fz_N\n")
        for k in range(len(t)):
            fh.write(f"{t[k]:.1f},{np.linalg.norm(f[k]):.10g},{f[k][0]:.10g},"
                     f"{f[k][1]:.10g},{f[k][2]:.10g}\n")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80, 160])
    ap.add_argument("--dt", type=float, default=None, help="dtM [s] (default: default_dt(N))")
    ap.add_argument("--ba", type=float, default=BA_DEFAULT,
                    help="BA/-zeta column (default -1: critical damping per segment)")
    ap.add_argument("--time", type=float, default=leg.T_END)
    ap.add_argument("--static-only", action="store_true")
    ap.add_argument("--current", action="store_true",
                    help="case (c): static in the uniform current, print a summary")
    ap.add_argument("--decks-only", action="store_true", help="write leg_N.dat and stop")
    ap.add_argument("--references", action="store_true",
                    help="run all N (cached in .work/), the finest also at dt/2, and write "
                         "reference/moordyn_surge_summary.json and moordyn_surge_fairlead.csv")
    ap.add_argument("--fresh", action="store_true", help="ignore cached runs")
    a = ap.parse_args()
    if a.references:
        out = write_references(a.segments, fresh=a.fresh, ba=a.ba)
        for r in out["runs"] + out["dt_check"]:
            print(json.dumps(r))
        return
    if a.current:
        rows = []
        for n in a.segments:
            st = current_static(n, a.dt, a.ba)
            rows.append(st)
            print(json.dumps({k: v for k, v in st.items() if k != "shape_m"}), flush=True)
        import moordyn as md
        sig = leg.sig
        for r in rows[:-1]:
            r.pop("shape_m")
        rows[-1]["shape_m"] = [sig(p) for p in rows[-1]["shape_m"]]
        out = {"description": "MoorDyn v2 case (c): static in a uniform 1 m/s current along "
                              "+y, by dynamic relaxation from MoorDyn's still-water IC with "
                              "the fairlead fixed (see current_static in "
                              "bench/water/moordyn_leg.py). Force of the line on the "
                              "fairlead (GetPointForce), global axes. Shape: node "
                              "positions of the finest run.",
               "moordyn_version": getattr(md, "__version__", "") or "2.7.2 (pip)",
               "current_m_s": list(leg.CURRENT), "runs": rows}
        with open(os.path.join(REF, "moordyn_current_static.json"), "w") as fh:
            json.dump(out, fh, indent=1)
            fh.write("\n")
        return
    for n in a.segments:
        if a.decks_only:
            print(write_deck(n, a.dt or default_dt(n), a.ba))
            continue
        if a.static_only:
            import moordyn as md
            s, st = static(n, a.dt, a.ba)
            md.Close(s)
            st.pop("shape_m")
            print(json.dumps(st))
            continue
        res = surge(n, a.dt, a.ba, a.time)
        print(json.dumps(summary(res)))


if __name__ == "__main__":
    main()
