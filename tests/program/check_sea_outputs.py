#!/usr/bin/env python3
"""The sea and vessel outputs (docs/output.md, "Waves and vessels"):
wave elevation at the probes of *WAVE PROBE, vessel motion and the forces of the line
ends on the vessel, at the frames (dynamic_waves.csv, dynamic_vessels.csv,
dynamic_connections.csv) and every step (the _step tables).

1. The cable of check_vessel_motion.py hung from a vessel moved by displacement RAOs in a
   regular Airy wave (check_vessel_motion.py's deck, two probes added):
   - the elevation at both probes at every frame and every step against
     H/2 cos(k (x cos b + y sin b) - omega t + phase), k by scipy's brentq (1e-12 m);
   - the vessel's reference point and roll, pitch, yaw against r(t) a R_k cos(omega t +
     phi_O - eps_k) (check_vessel_motion.rao_motion) through X = O + Rz(psi0) xi_1:3,
     the heading psi0 (1e-12 m, rad);
   - the connection's force equals minus the support force of end A (dynamic_ends.csv
     at the frames, dynamic_ends_step.csv every step), bit for bit; in vessel axes
     R^T F with R = Rz(psi0) Rv from scipy's Rotation (relative 1e-12); the vessel's
     total force is the connection's and its moment (X_A - X_ref) x F, X_A end A's
     position in dynamic_nodes.csv (relative 1e-9);
   - the _step tables have one row per probe / vessel / connection per step, steps 0 to
     T_END/DT at times k DT; the frame tables one per frame;
   - rodyn_post.dynamic.load_dynamic reads the same values (load_dynamic(...).sea).
2. A JONSWAP sea (50 components, SEED, GAMMA, OMEGA MIN/MAX given), no vessel: the probes
   against the sum of the components computed here (sea_components of rodyn_waves
   ported: L'Ecuyer's generator, the spectrum, A_i = sqrt(2 S dw)), 1e-10 m; no vessel
   or connection tables are written.
3. Quasi-static: the vessel (TYPE=TABLE) surges 0.2 m slowly (a ramp of 40 s; the cable's
   first period is about 1 s) and holds: the connection tension at the end against the
   static end tension of the cable with end A moved there (a static run), 1e-3.
4. Restart: input/mooring_waves.inp (the fairlead on the FPSO in a regular wave) with a
   probe, 24 elements, 2 s, CHECKPOINT=0.5, killed after step 27 and continued
   (check_restart.py's helpers): every table, the sea tables too, byte for byte, and
   dynamic.h5's /dynamic/sea to the bit, as an uninterrupted run.

Usage: check_sea_outputs.py RODYN INPUT_DIR WORK_DIR. Exit 0 on success."""
import csv
import math
import os
import shutil
import subprocess
import sys

import numpy as np
from scipy.spatial.transform import Rotation

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "postproc"))
import check_vessel_motion as cvm  # noqa: E402

PROBES = {"P1": (0.0, 0.0), "OFF": (35.5, -12.25)}


def probe_cards():
    return "".join(f"*WAVE PROBE, NAME={n}\n{x}, {y}\n" for n, (x, y) in PROBES.items())


def run_deck(rodyn, workdir, name, deck):
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, name + ".inp")
    with open(path, "w") as f:
        f.write(deck)
    out = os.path.join(workdir, "out_" + name)
    proc = subprocess.run([rodyn, path, "-o", out, "--quiet"], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        sys.exit(f"{name}: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    return out


def rows(out, name):
    with open(os.path.join(out, name)) as f:
        return list(csv.DictReader(f))


def rz(psi):
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def vec(row, names):
    return np.array([float(row[n]) for n in names])


F_G = ["Fx_N", "Fy_N", "Fz_N"]
M_G = ["Mx_Nm", "My_Nm", "Mz_Nm"]
F_V = ["Fx_vessel_N", "Fy_vessel_N", "Fz_vessel_N"]
M_V = ["Mx_vessel_Nm", "My_vessel_Nm", "Mz_vessel_Nm"]


def case_rao(rodyn, input_dir, work):
    workdir = os.path.join(work, "rao")
    os.makedirs(workdir, exist_ok=True)
    shutil.copy(os.path.join(input_dir, "paper_cable_section.inc"), workdir)
    with open(os.path.join(workdir, "rao.csv"), "w") as f:
        for row in cvm.rao_rows():
            f.write(", ".join(repr(float(v)) for v in row) + "\n")
    deck = f"""*HEADING
Paper cable hung from a vessel moved by displacement RAOs in a regular wave, probes
{cvm.CABLE}*WATER, DEPTH={cvm.DEPTH}, SURFACE=-20.0
*WAVE, HEIGHT={cvm.WAVE_H}, PERIOD={cvm.WAVE_T}, HEADING={cvm.WAVE_DIR}, PHASE={cvm.WAVE_PHASE}
{probe_cards()}*VESSEL, NAME=SHIP, TYPE=RAO, INPUT=rao.csv, PHASE=LAG
{cvm.vessel_end()}"""
    out = run_deck(rodyn, workdir, "rao", deck)
    omega = 2 * math.pi / cvm.WAVE_T
    k = cvm.wave_number(omega, cvm.DEPTH)
    beta = math.radians(cvm.WAVE_DIR)

    def eta(x, y, t):
        return cvm.WAVE_H / 2 * math.cos(k * (x * math.cos(beta) + y * math.sin(beta))
                                         - omega * t + math.radians(cvm.WAVE_PHASE))

    ok = True
    n_steps = int(round(cvm.T_END / cvm.DT))
    # elevation
    worst, big = 0.0, 0.0
    counts = {}
    for table, step in (("dynamic_waves.csv", False), ("dynamic_waves_step.csv", True)):
        for r in rows(out, table):
            t = float(r["time_s"])
            x, y = PROBES[r["probe"]]
            worst = max(worst, abs(float(r["elevation_m"]) - eta(x, y, t)))
            big = max(big, abs(eta(x, y, t)))
            counts[table] = counts.get(table, 0) + 1
            if step and abs(t - int(r["step"]) * cvm.DT) > 1e-9:
                ok = False
                print(f"step {r['step']} at t = {t}")
    n_frames = len({r["time_s"] for r in rows(out, "dynamic_nodes.csv")})
    print(f"regular wave: elevation at 2 probes against the closed form: max error "
          f"{worst:.3e} m; rows {counts} (frames {n_frames}, steps {n_steps})")
    ok = ok and worst <= 1e-12 and big > 1.0
    ok = ok and counts.get("dynamic_waves_step.csv") == 2 * (n_steps + 1)
    ok = ok and counts.get("dynamic_waves.csv") == 2 * n_frames
    # vessel motion
    psi0 = math.radians(cvm.HEADING)
    worst_x = worst_a = 0.0
    for table in ("dynamic_vessels.csv", "dynamic_vessels_step.csv"):
        vrows = rows(out, table)
        if "step" in table and len(vrows) != n_steps + 1:
            ok = False
            print(f"{table}: {len(vrows)} rows, expected {n_steps + 1}")
        for r in vrows:
            t = float(r["time_s"])
            xi = cvm.ramp(t) * cvm.rao_motion(t)
            x_ref = cvm.ORIGIN + rz(psi0) @ xi[0:3]
            worst_x = max(worst_x, float(np.max(np.abs(vec(r, ["x_m", "y_m", "z_m"]) - x_ref))))
            ang = np.radians(xi[3:6])
            worst_a = max(worst_a, float(np.max(np.abs(
                vec(r, ["roll_rad", "pitch_rad", "yaw_rad"]) - ang))),
                abs(float(r["heading_rad"]) - psi0))
    print(f"vessel motion against the RAO closed form: reference point {worst_x:.3e} m, "
          f"angles {worst_a:.3e} rad")
    ok = ok and worst_x <= 1e-12 and worst_a <= 1e-12
    # connection forces
    ends = {r["time_s"]: r for r in rows(out, "dynamic_ends.csv") if r["end"] == "A"}
    ends_step = {r["step"]: r for r in rows(out, "dynamic_ends_step.csv") if r["end"] == "A"}
    nodes = {r["time_s"]: r for r in rows(out, "dynamic_nodes.csv") if r["node"] == "1"}
    vessels = {r["time_s"]: r for r in rows(out, "dynamic_vessels.csv")}
    mismatch, worst_v, worst_m, peak = 0, 0.0, 0.0, 0.0
    for table, ref, keyname in (("dynamic_connections.csv", ends, "time_s"),
                                ("dynamic_connections_step.csv", ends_step, "step")):
        crows = rows(out, table)
        if "step" in table and len(crows) != n_steps + 1:
            ok = False
            print(f"{table}: {len(crows)} rows, expected {n_steps + 1}")
        for r in crows:
            if (r["vessel"], r["line"], r["end"]) != ("SHIP", "CABLE", "A"):
                ok = False
            e = ref[r[keyname]]
            f = vec(r, F_G + M_G)
            if not np.array_equal(f, 0.0 - vec(e, F_G + M_G)) or \
                    float(r["tension_N"]) != float(e["tension_N"]):
                mismatch += 1
            peak = max(peak, float(r["tension_N"]))
            t = float(r["time_s"])
            xi = cvm.ramp(t) * cvm.rao_motion(t)
            ang = np.radians(xi[3:6])
            rot = rz(psi0) @ Rotation.from_euler("ZYX", [ang[2], ang[1], ang[0]]).as_matrix()
            scale = max(1.0, float(np.max(np.abs(f))))
            worst_v = max(worst_v, float(np.max(np.abs(vec(r, F_V + M_V) - np.concatenate(
                [rot.T @ f[0:3], rot.T @ f[3:6]])))) / scale)
            if table == "dynamic_connections.csv":
                v = vessels[r["time_s"]]
                arm = vec(nodes[r["time_s"]], ["x_m", "y_m", "z_m"]) - vec(v, ["x_m", "y_m",
                                                                             "z_m"])
                m_ref = np.cross(arm, f[0:3]) + f[3:6]
                worst_m = max(worst_m, float(np.max(np.abs(vec(v, F_G) - f[0:3]))) / scale,
                              float(np.max(np.abs(vec(v, M_G) - m_ref))) / (scale * 10.0),
                              float(np.max(np.abs(vec(v, F_V + M_V) - np.concatenate(
                                  [rot.T @ f[0:3], rot.T @ m_ref])))) / (scale * 10.0))
    print(f"connection force = -(support force of end A) bit for bit: {mismatch} rows "
          f"differ; in vessel axes {worst_v:.3e} (relative); vessel total force and "
          f"moment about its reference point {worst_m:.3e} (relative); peak {peak:.1f} N")
    ok = ok and mismatch == 0 and worst_v <= 1e-12 and worst_m <= 1e-9 and peak > 0.0
    # the reader
    from rodyn_post.dynamic import load_dynamic
    sea = load_dynamic(out).sea
    p = sea.probes["OFF"]
    ref = [float(r["elevation_m"]) for r in rows(out, "dynamic_waves_step.csv")
           if r["probe"] == "OFF"]
    c = sea.connections[("SHIP", "CABLE", "A")]
    same = (np.array_equal(p.step_column("elevation_m"), ref)
            and len(p.time) == n_frames and len(c.step) == n_steps + 1
            and np.array_equal(sea.vessels["SHIP"].frame_column("x_m"),
                               [float(vessels[k]["x_m"]) for k in vessels]))
    print(f"rodyn_post reads the same: {same}")
    return ok and same


def lecuyer(seed):
    s1 = 1 + seed % 2147483562
    s2 = 1 + (seed * 7919 + 12345) % 2147483398
    while True:
        s1 = (40014 * s1) % 2147483563
        s2 = (40692 * s2) % 2147483399
        z = (s1 - s2) % 2147483562
        if z == 0:
            z = 2147483562
        yield z / 2147483563.0


def jonswap(omega, hs, tp, gamma):
    wp = 2 * math.pi / tp
    s = 5.0 / 16.0 * hs**2 * wp**4 / omega**5 * math.exp(-1.25 * (wp / omega)**4)
    sigma = 0.07 if omega <= wp else 0.09
    return s * (1 - 0.287 * math.log(gamma)) * gamma**math.exp(
        -0.5 * ((omega - wp) / (sigma * wp))**2)


def case_jonswap(rodyn, input_dir, work):
    hs, tp, gamma, n, seed, head, wmin, wmax, ramp = 4.0, 9.0, 2.5, 50, 7, 30.0, 0.3, 2.8, 1.0
    workdir = os.path.join(work, "jonswap")
    os.makedirs(workdir, exist_ok=True)
    shutil.copy(os.path.join(input_dir, "paper_cable_section.inc"), workdir)
    deck = f"""*HEADING
Paper cable in air above a JONSWAP sea, probes
{cvm.CABLE}*WATER, DEPTH={cvm.DEPTH}, SURFACE=-20.0
*WAVE, TYPE=JONSWAP, HS={hs}, TP={tp}, GAMMA={gamma}, COMPONENTS={n}, SEED={seed}, \
HEADING={head}, OMEGA MIN={wmin}, OMEGA MAX={wmax}, RAMP={ramp}
{probe_cards()}*DYNAMIC, DT=0.05, TIME=3.0
*OUTPUT, CSV=YES, HDF5=NO
"""
    out = run_deck(rodyn, workdir, "jonswap", deck)
    gen = lecuyer(seed)
    dw = (wmax - wmin) / n
    comps = []
    for i in range(n):
        om = wmin + dw * (i + next(gen))
        amp = math.sqrt(2.0 * jonswap(om, hs, tp, gamma) * dw)
        phase = 2 * math.pi * next(gen)
        comps.append((amp, om, cvm.wave_number(om, cvm.DEPTH), phase))
    beta = math.radians(head)

    def eta(x, y, t):
        r = 1.0 if t >= ramp else 0.5 * (1 - math.cos(math.pi * t / ramp))
        return r * sum(a * math.cos(k * (x * math.cos(beta) + y * math.sin(beta)) - om * t + ph)
                       for a, om, k, ph in comps)

    worst, big, count = 0.0, 0.0, 0
    for table in ("dynamic_waves.csv", "dynamic_waves_step.csv"):
        for r in rows(out, table):
            x, y = PROBES[r["probe"]]
            e = eta(x, y, float(r["time_s"]))
            worst = max(worst, abs(float(r["elevation_m"]) - e))
            big = max(big, abs(e))
            count += 1
    absent = not any(os.path.exists(os.path.join(out, f)) for f in (
        "dynamic_vessels.csv", "dynamic_connections.csv", "dynamic_vessels_step.csv"))
    print(f"JONSWAP sea: elevation at 2 probes against the sum of the {n} components: "
          f"max error {worst:.3e} m over {count} rows (|eta| up to {big:.3f} m); "
          f"no vessel tables: {absent}")
    return worst <= 1e-10 and big > 0.1 and absent


def case_quasi_static(rodyn, input_dir, work):
    surge, t_ramp, t_end = 0.2, 40.0, 50.0
    workdir = os.path.join(work, "slow")
    os.makedirs(workdir, exist_ok=True)
    shutil.copy(os.path.join(input_dir, "paper_cable_section.inc"), workdir)
    with open(os.path.join(workdir, "slow.csv"), "w") as f:
        f.write("t, surge, sway, heave, roll, pitch, yaw\n")
        for i in range(201):
            t = t_end * i / 200
            s = surge * (0.5 * (1 - math.cos(math.pi * min(t, t_ramp) / t_ramp)))
            f.write(f"{t!r}, {s!r}, 0, 0, 0, 0, 0\n")
    deck = f"""*HEADING
Paper cable, its end A on a vessel surging slowly
{cvm.CABLE}*VESSEL, NAME=SHIP, TYPE=TABLE, INPUT=slow.csv
{cvm.ORIGIN[0]}, {cvm.ORIGIN[1]}, {cvm.ORIGIN[2]}, {cvm.HEADING}
*MOTION, LINE=CABLE, END=A, TYPE=VESSEL, VESSEL=SHIP, RAMP=0
*DAMPING, ALPHA=0.2
*DYNAMIC, DT=0.05, TIME={t_end}, OUTPUT INTERVAL=1.0
*OUTPUT, CSV=YES, HDF5=NO
"""
    out = run_deck(rodyn, workdir, "slow", deck)
    # the static cable with end A where the vessel has moved it
    psi0 = math.radians(cvm.HEADING)
    a = rz(psi0) @ np.array([surge, 0.0, 0.0])
    cable = cvm.CABLE.replace("0.0, 0.0, 0.0, 8.0, 0.0, -1.0",
                              f"{float(a[0])!r}, {float(a[1])!r}, {float(a[2])!r}, 8.0, 0.0, -1.0")
    if cable == cvm.CABLE:
        sys.exit("the cable's data line was not found")
    static = run_deck(rodyn, workdir, "static", f"*HEADING\nstatic\n{cable}"
                      "*OUTPUT, CSV=YES, HDF5=NO\n")
    t_static = [float(r["tension_N"]) for r in rows(static, "static_reactions.csv")
                if r["end"] == "A"][0]
    t0 = [float(r["tension_N"]) for r in rows(out, "static_reactions.csv")
          if r["end"] == "A"][0]
    last = rows(out, "dynamic_connections_step.csv")[-1]
    t_dyn = float(last["tension_N"])
    err = abs(t_dyn - t_static) / t_static
    print(f"quasi-static: connection tension at t = {last['time_s']} s {t_dyn:.4f} N "
          f"against the static end tension {t_static:.4f} N (relative {err:.2e}; "
          f"{t0:.4f} N before the surge)")
    return err <= 1e-3 and abs(t_static - t0) > 100 * abs(t_dyn - t_static)


def case_restart(rodyn, input_dir, work):
    import check_restart as cr
    work = os.path.join(work, "restart")
    os.makedirs(work, exist_ok=True)
    path = cr.deck(input_dir, work, "waves", "mooring_waves.inp",
                   [(r"ELEMENTS=120", "ELEMENTS=24"),
                    (r"\*VESSEL,", "*WAVE PROBE, NAME=P1\n10.0, 5.0\n*VESSEL,"),
                    (r"TIME=<T_END>, OUTPUT INTERVAL=0\.1",
                     "TIME=2.0, OUTPUT INTERVAL=0.1, CHECKPOINT=0.5")])
    ref = os.path.join(work, "ref")
    shutil.rmtree(ref, ignore_errors=True)
    cr.run(rodyn, [path, "-o", ref])
    tables = [n for n in os.listdir(ref) if n.startswith(("dynamic_waves", "dynamic_vessels",
                                                          "dynamic_connections"))]
    cr.killed_and_continued(rodyn, path, ref, work, "kill27", [27])
    print(f"restart: sea tables {sorted(tables)}; failures: {cr.FAILURES}")
    return len(tables) == 6 and not cr.FAILURES


def main():
    rodyn, input_dir, work = sys.argv[1:4]
    ok = case_restart(rodyn, input_dir, work)
    ok = case_rao(rodyn, input_dir, work) and ok
    ok = case_jonswap(rodyn, input_dir, work) and ok
    ok = case_quasi_static(rodyn, input_dir, work) and ok
    if not ok:
        sys.exit("FAILED")
    print("PASS")


if __name__ == "__main__":
    main()
