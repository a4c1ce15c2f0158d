#!/usr/bin/env python3
"""Work-precision of the time-integration schemes on a dry cable and two lines in water:
error of the top force against a fine-step reference, against the CPU time of the run.

usage: python3 bench/scheme_choice.py [--rodyn PATH] [--quick] [--cases CASE ...]
                                      [--csv PATH] [--keep DIR]

Schemes (the *DYNAMIC card's SCHEME= and what follows it):
  EMC, RHO INF=1       the energy-momentum scheme, conservative
  EMC, RHO INF=0.8     the dissipative energy-momentum scheme
  EMC, RHO INF=0.6
  ALPHA, RHO INF=0.8   generalized-alpha
  ALPHA, RHO INF=0.0

Cases (shortened copies of the decks, written to a temporary folder; the *DYNAMIC card's
DT, TIME, OUTPUT INTERVAL and SCHEME set by text substitution, the meshes kept):
  case1    input/paper_case1.inp: the paper's cable (dry), end A heaved 0.4 m at
           0.658 Hz, ramped in over 3 s; 20 s; top force at end A; window the last
           3 periods, 15.44-20 s, sampled every 0.02 s; dt 0.2, 0.1, 0.05, 0.025 s
  mooring  input/mooring_surge.inp: a 450 m mooring leg in 100 m of water on a flat
           seabed, the fairlead (end B) surged 5 m at a period of 12 s, ramped in over
           12 s; 40 s; top force at end B; window the last two periods, 16-40 s,
           sampled every 0.05 s; dt 0.2, 0.1, 0.05, 0.025 s
  hanging  bench/decks/hanging_free_end.inp with NE=80, T_END=40: a 50 m line hanging in
           water with a free lower end, the top (end A) surged 2 m at a period of 10 s,
           ramped in over 12 s; top force at end A; window 20-40 s, sampled every
           0.05 s; dt 0.05, 0.025, 0.0125, 0.00625 s

Top force: the magnitude of the support force at the top end at every step
(dynamic_ends_step.csv, benchlib.read_end_forces), interpolated to the sampling instants
by 4-point Lagrange (benchlib.interp_cubic). Reference: EMC, RHO INF=0.8 at
dt = 0.003125 s (case1, mooring) or 0.0015625 s (hanging); the converged solution does
not depend on the scheme, and a check run (EMC at twice the reference step) bounds how
far the reference is from it: their difference is printed and written to the CSV.

Per run: relative RMS error RMS(T - T_ref) / RMS(T_ref - mean T_ref) over the window
(relative to the dynamic part of the reference's top force), the largest |T - T_ref|
in N, steps, Newton iterations and step halvings (status.txt: steps, step_iterations,
step_cutbacks), and the CPU time of the rodyn process (user + system, from
getrusage(RUSAGE_CHILDREN)); a failed run's return code and last line of stderr.
The same relative RMS error of the periodic part is given besides: P(T), the least-
squares fit over the window of the harmonics 0..K of the motion frequency f (K the
largest with K f <= 3 Hz; the windows hold whole periods), compared with P(T_ref) and
divided by RMS(P(T_ref) - mean). It leaves out what is above 3 Hz or not periodic at
the motion's frequency: axial vibrations of the line (16 Hz for the hanging line) and
what is left of the start. RMS(T_ref - P(T_ref)), the part of the reference outside
the fit, is printed.
Printed per case: the table of scheme x dt, and for the targets 10 %, 3 %, 1 % and 0.3 %
relative RMS error (of the force, and of its periodic part) the cheapest run (CPU) of
each scheme that reaches it.

The full run (about 80 s of CPU) writes bench/results/scheme_choice.csv with the
machine facts. --quick: case1 only, dt 0.2 and 0.1, EMC and ALPHA with RHO INF=0.8,
reference at dt = 0.00625 s and check run at 0.0125 s; writes no file unless --csv.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
SCHEMES = ["EMC, RHO INF=1", "EMC, RHO INF=0.8", "EMC, RHO INF=0.6", "ALPHA, RHO INF=0.8",
           "ALPHA, RHO INF=0.0"]
REF_SCHEME = "EMC, RHO INF=0.8"
CHECK_SCHEME = "EMC, RHO INF=1"
TARGETS = [0.10, 0.03, 0.01, 0.003]
F_CUT = 3.0                     # [Hz] highest harmonic of the periodic part

CASES = {
    "case1": dict(
        title="paper's case 1, dry cable heaved at 0.658 Hz (top = end A)",
        deck="input/paper_case1.inp", includes=["input/paper_cable_section.inc"],
        end="A", time=20.0, interval=0.2, window=(15.44, 20.0), sample=0.02,
        dts=[0.2, 0.1, 0.05, 0.025], ref_dt=0.003125, check_dt=0.00625, params=False,
        freq=0.658),
    "mooring": dict(
        title="mooring leg in water on the seabed, fairlead surged at 12 s (top = end B)",
        deck="input/mooring_surge.inp", includes=["input/mooring_leg_section.inc"],
        end="B", time=40.0, interval=1.0, window=(16.0, 40.0), sample=0.05,
        dts=[0.2, 0.1, 0.05, 0.025], ref_dt=0.003125, check_dt=0.00625, params=False,
        freq=1.0 / 12.0),
    "hanging": dict(
        title="hanging line with a free lower end in water, 80 elements (top = end A)",
        deck="bench/decks/hanging_free_end.inp", includes=[], end="A", time=40.0,
        interval=None, window=(20.0, 40.0), sample=0.05,
        dts=[0.05, 0.025, 0.0125, 0.00625], ref_dt=0.0015625, check_dt=0.003125,
        params=True, elements=80, freq=0.1),
}
QUICK = {"case1": dict(CASES["case1"], dts=[0.2, 0.1], ref_dt=0.00625, check_dt=0.0125)}
QUICK_SCHEMES = ["EMC, RHO INF=1", "ALPHA, RHO INF=0.8"]

CSV_COLUMNS = ["case", "role", "scheme", "dt_s", "returncode", "complete", "steps",
               "step_iterations", "step_cutbacks", "cpu_s", "error_rel_rms", "error_max_N",
               "periodic_error_rel_rms", "periodic_error_max_N", "ref_mean_N",
               "ref_dynamic_rms_N", "ref_unfitted_rms_N", "stderr_last_line"]


def make_deck(case, scheme, dt):
    """Deck text of a case with the scheme and, for the decks without *PARAMETER DT, the
    step, duration and frame interval set on its *DYNAMIC card."""
    text = benchlib.read_deck(case["deck"])
    params = {"SCHEME": scheme}
    if not case["params"]:
        params.update({"DT": dt, "TIME": case["time"], "OUTPUT INTERVAL": case["interval"]})
    return benchlib.set_params(text, "*DYNAMIC", params)


def sample_times(case):
    w0, w1 = case["window"]
    n = int(round((w1 - w0) / case["sample"]))
    return w0 + case["sample"] * np.arange(n + 1)


def run_one(rodyn, work, name, case, scheme, dt, role):
    """Run one deck; the row of the CSV and the top force at the sampling instants (None
    if the run failed)."""
    tag = f"{name}_{role}_{scheme.replace(', RHO INF=', '_r').replace(' ', '')}_dt{dt:g}"
    deck = benchlib.write_deck(work, tag, make_deck(case, scheme, dt), case["includes"])
    out = os.path.join(work, tag)
    args = [rodyn, deck, "-o", out, "--quiet"]
    if case["params"]:
        args += ["--set", f"NE={case['elements']}", "--set", f"DT={dt!r}",
                 "--set", f"T_END={case['time']!r}"]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(args, capture_output=True, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    st_path = os.path.join(out, "status.txt")
    st = benchlib.read_status(st_path) if os.path.isfile(st_path) else {}
    row = {"case": name, "role": role, "scheme": scheme, "dt_s": dt,
           "returncode": proc.returncode, "complete": st.get("complete") == "true",
           "steps": int(st.get("steps", 0) or 0),
           "step_iterations": int(st.get("step_iterations", 0) or 0),
           "step_cutbacks": int(st.get("step_cutbacks", 0) or 0), "cpu_s": cpu}
    err_lines = proc.stderr.replace(work + os.sep, "").strip().splitlines()
    if proc.returncode != 0 or not row["complete"]:
        row["stderr_last_line"] = err_lines[-1] if err_lines else "no stderr"
        return row, None
    t, f = benchlib.read_end_forces(out, case["end"])
    tq = sample_times(case)
    if t[-1] < tq[-1] - 1e-9:
        row["stderr_last_line"] = f"steps end at {t[-1]:g} s, before the window's end"
        return row, None
    tq = np.minimum(tq, t[-1])
    return row, benchlib.interp_cubic(t, np.linalg.norm(f, axis=1), tq)


def errors(tq_force, ref):
    """Relative RMS error (to the dynamic part of ref) and the largest error [N]."""
    dyn = np.sqrt(np.mean((ref - ref.mean()) ** 2))
    diff = tq_force - ref
    return float(np.sqrt(np.mean(diff ** 2)) / dyn), float(np.abs(diff).max())


def periodic_part(case, y):
    """Least-squares fit of the harmonics 0..K of the motion frequency (K f <= F_CUT) to
    y at the sampling instants."""
    t = sample_times(case)
    w = 2 * np.pi * case["freq"]
    cols = [np.ones_like(t)]
    for k in range(1, int(F_CUT / case["freq"] + 1e-9) + 1):
        cols += [np.cos(k * w * t), np.sin(k * w * t)]
    a = np.column_stack(cols)
    coef, *_ = np.linalg.lstsq(a, y, rcond=None)
    return a @ coef


def fmt_err(row, key="error"):
    if row.get(key + "_rel_rms") is None:
        return ["failed", "-"]
    return [f"{100 * row[key + '_rel_rms']:.3g} %", f"{row[key + '_max_N']:.4g}"]


def cheapest_table(rows, schemes, key):
    """Per scheme and target: the least CPU of a ladder run whose `key` error reaches it."""
    table = []
    for s in schemes:
        line = [s]
        for target in TARGETS:
            ok = [r for r in rows if r["role"] == "ladder" and r["scheme"] == s and
                  r.get(key) is not None and r[key] <= target]
            if ok:
                best = min(ok, key=lambda r: r["cpu_s"])
                line.append(f"{best['cpu_s']:.2f} s (dt {best['dt_s']:g}"
                            + (f", {best['step_cutbacks']} halv." if best["step_cutbacks"]
                               else "") + ")")
            else:
                line.append("not reached")
        table.append(line)
    head = ["scheme"] + [f"{100 * t:g} %" for t in TARGETS]
    return benchlib.md_table(head, table)


def print_case(name, case, rows, schemes):
    ref = next(r for r in rows if r["role"] == "reference")
    chk = next(r for r in rows if r["role"] == "check")
    nan = float("nan")
    print(f"\n## {name}: {case['title']}")
    print(f"window {case['window'][0]:g}-{case['window'][1]:g} s, sampled every "
          f"{case['sample']:g} s; periodic part: harmonics 0-"
          f"{int(F_CUT / case['freq'] + 1e-9)} of {case['freq']:.6g} Hz")
    print(f"reference {REF_SCHEME} at dt {case['ref_dt']:g} s: mean "
          f"{ref.get('ref_mean_N', nan):.6g} N, RMS of the dynamic part "
          f"{ref.get('ref_dynamic_rms_N', nan):.6g} N, of the part outside the fit "
          f"{ref.get('ref_unfitted_rms_N', nan):.4g} N; {ref['step_cutbacks']} "
          f"halvings, CPU {ref['cpu_s']:.1f} s")
    e, p = fmt_err(chk), fmt_err(chk, "periodic_error")
    print(f"check run {CHECK_SCHEME} at dt {case['check_dt']:g} s against the reference: "
          f"{e[0]} (max {e[1]} N), periodic part {p[0]} (max {p[1]} N); "
          f"{chk['step_cutbacks']} halvings, CPU {chk['cpu_s']:.1f} s"
          + (f"; rc {chk['returncode']}: {chk.get('stderr_last_line')}"
             if chk.get("error_rel_rms") is None else ""))
    table, failed = [], []
    for r in rows:
        if r["role"] != "ladder":
            continue
        e, p = fmt_err(r), fmt_err(r, "periodic_error")
        table.append([r["scheme"], f"{r['dt_s']:g}", e[0], e[1], p[0], p[1],
                      str(r["steps"]), str(r["step_iterations"]), str(r["step_cutbacks"]),
                      f"{r['cpu_s']:.2f}"])
        if r.get("error_rel_rms") is None:
            failed.append(f"{r['scheme']} at dt {r['dt_s']:g}: rc {r['returncode']}: "
                          f"{r.get('stderr_last_line')}")
    print()
    print("\n".join(benchlib.md_table(
        ["scheme", "dt [s]", "rel. RMS error", "max error [N]", "periodic: rel. RMS",
         "periodic: max [N]", "steps", "Newton it.", "halvings", "CPU [s]"], table)))
    for f in failed:
        print("failed: " + f)
    print("\ncheapest CPU reaching each relative RMS error target, top force:")
    print("\n".join(cheapest_table(rows, schemes, "error_rel_rms")))
    print("\nthe same, periodic part of the top force:")
    print("\n".join(cheapest_table(rows, schemes, "periodic_error_rel_rms")))


def run_case(rodyn, work, name, case, schemes):
    rows = []
    ref_row, ref = run_one(rodyn, work, name, case, REF_SCHEME, case["ref_dt"], "reference")
    rows.append(ref_row)
    if ref is None:
        print(f"{name}: the reference run failed (rc {ref_row['returncode']}: "
              f"{ref_row.get('stderr_last_line')})", flush=True)
        return rows, False
    ref_row["ref_mean_N"] = float(ref.mean())
    ref_row["ref_dynamic_rms_N"] = float(np.sqrt(np.mean((ref - ref.mean()) ** 2)))
    ref_per = periodic_part(case, ref)
    ref_row["ref_unfitted_rms_N"] = float(np.sqrt(np.mean((ref - ref_per) ** 2)))
    runs = [(CHECK_SCHEME, case["check_dt"], "check")] + \
        [(s, dt, "ladder") for s in schemes for dt in case["dts"]]
    for scheme, dt, role in runs:
        row, force = run_one(rodyn, work, name, case, scheme, dt, role)
        if force is not None:
            row["error_rel_rms"], row["error_max_N"] = errors(force, ref)
            row["periodic_error_rel_rms"], row["periodic_error_max_N"] = errors(
                periodic_part(case, force), ref_per)
        rows.append(row)
        e, p = fmt_err(row), fmt_err(row, "periodic_error")
        print(f"  {name} {role} {scheme} dt {dt:g}: {e[0]} (max {e[1]} N), periodic "
              f"{p[0]}; {row['step_cutbacks']} halvings, CPU {row['cpu_s']:.2f} s"
              + (f"; rc {row['returncode']}: {row.get('stderr_last_line')}"
                 if row.get("error_rel_rms") is None else ""), flush=True)
    print_case(name, case, rows, schemes)
    return rows, True


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    ap.add_argument("--quick", action="store_true",
                    help="case1 only, dt 0.2 and 0.1, two schemes, a coarser reference")
    ap.add_argument("--cases", nargs="+", choices=list(CASES), default=None)
    ap.add_argument("--csv", default=None,
                    help="results CSV (default bench/results/scheme_choice.csv; none with "
                         "--quick unless given)")
    ap.add_argument("--keep", default=None, help="run in this folder and keep the runs")
    args = ap.parse_args()
    rodyn = benchlib.check_rodyn(args.rodyn)
    facts = benchlib.rodyn_binary_facts(rodyn)
    cases = QUICK if args.quick else CASES
    schemes = QUICK_SCHEMES if args.quick else SCHEMES
    names = [n for n in (args.cases or list(cases)) if n in cases]
    if not names:
        sys.exit("no case to run (--quick has case1 only)")
    csv_path = args.csv or (None if args.quick else
                            os.path.join(ROOT, "bench", "results", "scheme_choice.csv"))
    rows, all_ok = [], True
    with tempfile.TemporaryDirectory() as tmp:
        work = os.path.abspath(args.keep) if args.keep else tmp
        os.makedirs(work, exist_ok=True)
        for name in names:
            case_rows, ok = run_case(rodyn, work, name, cases[name], schemes)
            rows += case_rows
            all_ok = all_ok and ok
    total = sum(r["cpu_s"] for r in rows)
    print(f"\nCPU of all runs: {total:.1f} s")
    if csv_path:
        comments = [f"{n}: {cases[n]['deck']}, top end {cases[n]['end']}, window "
                    f"{cases[n]['window'][0]:g}-{cases[n]['window'][1]:g} s sampled every "
                    f"{cases[n]['sample']:g} s, reference {REF_SCHEME} at dt "
                    f"{cases[n]['ref_dt']:g} s, check {CHECK_SCHEME} at dt "
                    f"{cases[n]['check_dt']:g} s" for n in names]
        comments += ["error_rel_rms = RMS(T - T_ref) / RMS(T_ref - mean T_ref) of the top "
                     "force magnitude over the window; error_max_N = max |T - T_ref|; "
                     "cpu_s = user + system CPU of the rodyn process",
                     "periodic_error_*: the same of the least-squares fits of harmonics "
                     f"0..K of the motion frequency f (K f <= {F_CUT:g} Hz); "
                     "ref_unfitted_rms_N = RMS(T_ref - its fit)",
                     f"CPU of all runs: {total:.1f} s"]
        benchlib.write_csv(csv_path, facts, CSV_COLUMNS, rows, comments=comments)
        print(f"wrote {os.path.relpath(csv_path, ROOT)}")
    sys.exit(0 if all_ok else 1)


if __name__ == "__main__":
    main()
