#!/usr/bin/env python3
"""Work-precision of rodyn's time integrators: error against a converged reference
against wall time, varying the time step, the element count and the element order.

usage: python3 bench/work_precision.py [--rodyn PATH] [--quick] [--cases CASE ...]
                                       [--csv PATH] [--png-dir DIR] [--md PATH]
                                       [--keep DIR]

Cases (EMC, MIDPOINT, TRAPEZOIDAL and ALPHA with RHO INF = 0.8 on the base mesh, and EMC
on further meshes; every mesh at every time step of its list):

  case1  the paper's case 1 (input/paper_case1.inp): the paper's cable, end A heaves
         0.4 m at 0.658 Hz, 3 s ramp-in; 20 s simulated, errors over the last 3 periods
         (15.44-20 s); frames every 0.2 s; dt 0.2 ... 0.0125 s; base mesh 30 cubic
         elements (the paper's), EMC also on 10 cubic, 10 and 30 quadratic, 30 and 100
         linear elements; reference 60 quadratic elements at dt = 0.003125 s
  case4  the paper's case 4 (input/paper_case4.inp): the same at 1.5 Hz; 10 s, last
         3 periods (8-10 s); frames every 0.04 s; dt 0.04 ... 0.005 s; the same meshes;
         reference 60 quadratic elements at dt = 0.00125 s
  scr    a 1000 m steel catenary riser-like line (bench/decks/scr1000.inp: 10.75 in x
         20.6 mm steel pipe, pinned at (0,0,0) and (740,0,-600) m, weight in water by
         scaled gravity, top heave 2 m at 10 s period ramped in over 10 s, 5 % mass-
         proportional damping at 0.1 Hz); 60 s, last 2 periods (40-60 s); frames every
         1 s; dt 1 ... 1/32 s; base mesh 200 quadratic elements, also 200 linear (all
         dt), 2000 linear (dt 0.5 ... 0.125), 1000 quadratic and 200 cubic (dt 0.5 and
         0.25); reference 300 quadratic elements at dt = 1/128 s

Errors, over the window of the last periods, at the frames of the run:
  tension error   RMS(T - T_ref) / RMS(T_ref - mean T_ref), T the top support force
                  |F| at end A as written by rodyn (dynamic.h5 end_tension), i.e.
                  relative to the dynamic part of the top tension. rodyn writes the
                  support force at the frame time (the step-averaged force, which belongs
                  to the step's middle, interpolated between the steps either side of
                  the frame), so T and T_ref are compared at the same time, unshifted.
                  (Builds before this change stamped the step average at the step's end,
                  half a step late; an earlier version of this script also reported a
                  "centred" error that undid that shift. It is wrong for the current
                  build and has been dropped.) ALPHA's step force belongs to its force
                  point t_n + (1 - alpha_f) dt, not the middle: interpolated as a mid-step
                  value it is written 0.056 dt early, and its error stays first order.
  position error  RMS of |x - x_ref| (m) of the mid-line node (S = L/2), and that divided
                  by the RMS distance of the reference's node from its mean position
                  in the window.
The reference T_ref(t) and x_ref(t) are read off the reference run by cubic interpolation
between its frames. How converged it is: it is compared with a
check run (the base mesh at twice the reference step); the difference bounds its error.

Timing: whole-process wall time of `rodyn --quiet` (static equilibrium, dynamics,
writing dynamic.h5 with CSV=NO), median of 3 runs for runs under 2 s, one run above.

Checks (exit status 1 if one fails): every EMC run completes; the reference agrees with
its check run (tension within 1 %, position within 0.1 %); on the base mesh the EMC
position error falls with dt at an observed order >= 1.5 (second order; between the two
smallest dt whose errors are above 3 times the check run's difference d), and so does
the EMC tension error (as written) e, with d removed in quadrature (sqrt(e^2 - d^2),
between the two smallest dt with e > 2 d): the tension has a floor, a free vibration
of the undamped paper cable whose phase depends on the step, that no affordable
reference resolves.

--quick (about 10 s on the 06:20 build): case 1 only, 10 s, dt 0.2/0.1/0.05, the four
schemes on the base mesh and EMC on 10 quadratic elements, reference 20 quadratic elements at
dt = 0.003125 s (check run: the same mesh at 0.00625 s); prints the tables
and the checks, writes no file unless --csv, --png-dir or --md is given. The full run
(about 11 minutes on the 04:45 snapshot build, 4 on the 06:20 build) writes
bench/results/work_precision.csv, docs/img/work_precision_<case>.png and the results part of
docs/benchmarks_work_precision.md (below its marker line).
"""
import argparse
import math
import os
import sys
import tempfile

import numpy as np

from benchlib import (ROOT, check_rodyn, rodyn_binary_facts, read_deck, set_params,
                      note_heading, write_deck, timed_run, run_rodyn, load_results,
                      interp_cubic, md_table, write_csv)

SCHEMES = ["EMC", "MIDPOINT", "TRAPEZOIDAL", "ALPHA"]
RHO_INF = 0.8                       # ALPHA's default (set in the decks' defaults)
TARGETS = [1e-2, 1e-3, 1e-4]
MARKER = "<!-- generated by bench/work_precision.py: everything below is rewritten -->"

CASES = {
    "case1": dict(
        title="paper's case 1 (0.658 Hz)", deck="input/paper_case1.inp",
        includes=["input/paper_cable_section.inc"], freq=0.658, time=20.0, periods=3,
        interval=0.2, length=10.0, dts=[0.2, 0.1, 0.05, 0.025, 0.0125], base=(3, 30),
        meshes={(3, 10): None, (2, 10): None, (2, 30): None, (1, 30): None,
                (1, 100): None},
        ref=dict(mesh=(2, 60), dt=0.003125, interval=0.0125),
        check=dict(mesh=(3, 30), dt=0.00625, interval=0.0125)),
    "case4": dict(
        title="paper's case 4 (1.5 Hz)", deck="input/paper_case4.inp",
        includes=["input/paper_cable_section.inc"], freq=1.5, time=10.0, periods=3,
        interval=0.04, length=10.0, dts=[0.04, 0.02, 0.01, 0.005], base=(3, 30),
        meshes={(3, 10): None, (2, 10): None, (2, 30): None, (1, 30): None,
                (1, 100): None},
        ref=dict(mesh=(2, 60), dt=0.00125, interval=0.005),
        check=dict(mesh=(3, 30), dt=0.0025, interval=0.005)),
    "scr": dict(
        title="1000 m SCR-like line (0.1 Hz heave)", deck="bench/decks/scr1000.inp",
        includes=[], freq=0.1, time=60.0, periods=2, interval=1.0, length=1000.0,
        dts=[1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125], base=(2, 200),
        meshes={(1, 200): None, (1, 2000): [0.5, 0.25, 0.125],
                (2, 1000): [0.5, 0.25], (3, 200): [0.5, 0.25]},
        ref=dict(mesh=(2, 300), dt=0.0078125, interval=0.0625),
        check=dict(mesh=(2, 200), dt=0.015625, interval=0.0625)),
}
QUICK = {
    "case1": dict(CASES["case1"], time=10.0, dts=[0.2, 0.1, 0.05], meshes={(2, 10): None},
                  ref=dict(mesh=(2, 20), dt=0.003125, interval=0.0125),
                  check=dict(mesh=(2, 20), dt=0.00625, interval=0.0125)),
}
CSV_COLUMNS = ["case", "role", "scheme", "order", "elements", "dt_s", "time_s",
               "complete", "status", "steps", "step_iterations", "step_cutbacks",
               "wall_median_s", "wall_min_s", "wall_max_s", "runs",
               "tension_error_rel", "position_error_m",
               "position_error_rel", "energy_balance_rel"]


def make_deck(case, scheme, mesh, dt, time, interval):
    text = read_deck(case["deck"])
    order, n = mesh
    text = set_params(text, "*LINE", {"ELEMENTS": n, "ORDER": order})
    text = set_params(text, "*DYNAMIC", {"DT": dt, "TIME": time, "OUTPUT INTERVAL": interval,
                                         "SCHEME": scheme})
    text = set_params(text, "*OUTPUT", {"CSV": "NO", "HDF5": "YES"})
    return note_heading(text, f"bench/work_precision.py: {scheme}, {n} elements of order "
                        f"{order}, DT={dt:g}, TIME={time:g}")


def run_one(rodyn, workdir, name, case, scheme, mesh, dt, time, interval, role, timing):
    tag = f"{name}_{role}_{scheme}_p{mesh[0]}_n{mesh[1]}_dt{dt:g}"
    deck = write_deck(workdir, tag, make_deck(case, scheme, mesh, dt, time, interval),
                      case["includes"])
    r = timed_run(rodyn, deck) if timing else run_rodyn(rodyn, deck)
    r.setdefault("runs", 1)
    r.setdefault("wall_min_s", r["wall_s"])
    r.setdefault("wall_max_s", r["wall_s"])
    st = r["status"]
    row = {"case": name, "role": role, "scheme": scheme, "order": mesh[0],
           "elements": mesh[1], "dt_s": dt, "time_s": time,
           "complete": st.get("complete") == "true" and r["returncode"] == 0,
           "status": st.get("status", r["stderr"][:80] or "no status.txt"),
           "steps": int(st.get("steps", 0)), "step_iterations": int(st.get("step_iterations", 0)),
           "step_cutbacks": int(st.get("step_cutbacks", 0)),
           "wall_median_s": r["wall_s"], "wall_min_s": r["wall_min_s"],
           "wall_max_s": r["wall_max_s"], "runs": r["runs"], "out": r["out"],
           "returncode": r["returncode"]}
    if r["returncode"] in (0, 2) and os.path.isfile(os.path.join(r["out"], "dynamic.h5")):
        row["results"] = load_results(r["out"])
        row["energy_balance_rel"] = row["results"].log.relative_energy_error()
    print(f"  {tag}: {row['wall_median_s']:.3g} s ({row['runs']} run(s)), "
          f"{row['steps']} steps, {row['step_iterations']} it., "
          f"{row['step_cutbacks']} halvings, {row['status']}", file=sys.stderr, flush=True)
    return row


class Reference:
    """The reference histories of a case: top tension at true time, mid-node position."""

    def __init__(self, row, case):
        res = row["results"]
        line = res.lines[0]
        self.dt = row["dt_s"]
        keep = res.time > 0.0
        # the support force is written at the frame time (see the docstring)
        self.t_force = res.time[keep]
        self.tension = line.end_tension[keep, 0]
        self.t = res.time
        mid = mid_node(line, case["length"])
        self.pos = np.column_stack([line.x[:, mid], line.y[:, mid], line.z[:, mid]])
        t_end = case["time"]
        self.t0 = t_end - case["periods"] / case["freq"] - 1e-9
        w = (self.t_force >= self.t0) & (self.t_force <= t_end)
        self.tension_scale = float(np.std(self.tension[w]))
        wp = self.t >= self.t0
        self.pos_scale = float(np.sqrt(np.mean(np.sum(
            (self.pos[wp] - self.pos[wp].mean(axis=0)) ** 2, axis=1))))

    def tension_at(self, t):
        return interp_cubic(self.t_force, self.tension, t)

    def position_at(self, t):
        return interp_cubic(self.t, self.pos, t)


def mid_node(line, length):
    k = int(np.argmin(np.abs(line.node_s - 0.5 * length)))
    if abs(line.node_s[k] - 0.5 * length) > 1e-6 * length:
        raise ValueError(f"no node at S = L/2 (nearest S = {line.node_s[k]})")
    return k


def add_errors(row, ref, case):
    if "results" not in row or not row["complete"]:
        return
    res = row["results"]
    line = res.lines[0]
    t = res.time
    w = t >= ref.t0
    T = line.end_tension[w, 0]
    e = T - ref.tension_at(t[w])
    row["tension_error_rel"] = float(np.sqrt(np.mean(e ** 2)) / ref.tension_scale)
    mid = mid_node(line, case["length"])
    pos = np.column_stack([line.x[w, mid], line.y[w, mid], line.z[w, mid]])
    d = np.sqrt(np.sum((pos - ref.position_at(t[w])) ** 2, axis=1))
    row["position_error_m"] = float(np.sqrt(np.mean(d ** 2)))
    row["position_error_rel"] = row["position_error_m"] / ref.pos_scale


def run_case(rodyn, workdir, name, case):
    print(f"{name}: {case['title']}", file=sys.stderr, flush=True)
    T = case["time"]
    rows = []
    ref_row = run_one(rodyn, workdir, name, case, "EMC", case["ref"]["mesh"], case["ref"]["dt"],
                      T, case["ref"]["interval"], "reference", False)
    chk_row = run_one(rodyn, workdir, name, case, "EMC", case["check"]["mesh"],
                      case["check"]["dt"], T, case["check"]["interval"], "check", False)
    if not ref_row["complete"]:
        print(f"  {name}: the reference run failed: {ref_row['status']}", file=sys.stderr)
        return [ref_row, chk_row], None
    ref = Reference(ref_row, case)
    add_errors(chk_row, ref, case)
    rows += [ref_row, chk_row]
    runs = [(s, case["base"], case["dts"]) for s in SCHEMES]
    runs += [("EMC", m, dts or case["dts"]) for m, dts in case["meshes"].items()]
    for scheme, mesh, dts in runs:
        for dt in dts:
            row = run_one(rodyn, workdir, name, case, scheme, mesh, dt, T, case["interval"],
                          "sweep", True)
            add_errors(row, ref, case)
            rows.append(row)
    for r in rows:
        r.pop("results", None)
    return rows, ref


def pct(x):
    if x is None or not np.isfinite(x):
        return "–"
    return f"{100 * x:.2g} %" if x >= 1e-4 else f"{100 * x:.1e} %"


def mesh_label(r):
    return f"p{r['order']}×{r['elements']}"


def observed_orders(rows, key):
    """Observed orders of `key` between successive dt of a list of rows (dt decreasing)."""
    out = []
    for a, b in zip(rows, rows[1:]):
        ea, eb = a.get(key), b.get(key)
        if ea and eb and ea > 0 and eb > 0:
            out.append(math.log(ea / eb) / math.log(a["dt_s"] / b["dt_s"]))
    return out


def floor_corrected_orders(rows, key, floor):
    """Observed orders of sqrt(e^2 - floor^2) between successive dt, for the rows whose
    error e is above 2 floor (rows with dt decreasing)."""
    floor = floor or 0.0
    good = [dict(r, **{key: math.sqrt(r[key] ** 2 - floor ** 2)}) for r in rows
            if r.get(key) and r[key] > 2 * floor]
    return observed_orders(good, key)


def cheapest(rows, key, target, scheme=None):
    ok = [r for r in rows if r["role"] == "sweep" and r.get(key) is not None
          and r[key] <= target and (scheme is None or r["scheme"] == scheme)]
    return min(ok, key=lambda r: r["wall_median_s"]) if ok else None


def bounds_of(rows):
    """How far the reference can be trusted: the check run's difference from it, for the
    tension (as written) and for the position (relative)."""
    chk = [r for r in rows if r["role"] == "check"][0]
    return {"tension": chk.get("tension_error_rel") or float("nan"),
            "position": chk.get("position_error_rel") or float("nan")}


def case_report(name, case, rows, bounds):
    """Markdown lines for one case."""
    L = [f"### {name}: {case['title']}", ""]
    ref = [r for r in rows if r["role"] == "reference"][0]
    chk = [r for r in rows if r["role"] == "check"][0]
    L.append(f"Simulated {case['time']:g} s; errors over the last {case['periods']} periods "
             f"({case['time'] - case['periods'] / case['freq']:.4g}–{case['time']:g} s); "
             f"frames every {case['interval']:g} s. Reference: EMC, "
             f"{ref['elements']} elements of order {ref['order']}, Δt = {ref['dt_s']:g} s "
             f"({ref['steps']} steps, {ref['wall_median_s']:.3g} s). Check run: "
             f"{chk['elements']} elements of order {chk['order']}, Δt = {chk['dt_s']:g} s: "
             f"it differs from the reference by {pct(chk.get('tension_error_rel'))} "
             f"in the top tension "
             f"and by {pct(chk.get('position_error_rel'))} in the mid-node position "
             f"({chk.get('position_error_m', float('nan')):.2g} m). Tension errors below "
             f"about {pct(bounds['tension'])} and position errors below about "
             f"{pct(bounds['position'])} are therefore not measured by this reference "
             "(shaded in the plot; \"not measurable\" in the tables).")
    L.append("")
    header = ["scheme", "mesh", "Δt [s]", "steps", "Newton it.", "halvings", "wall [s]",
              "runs", "tension error", "position error [m]", "position (rel.)",
              "energy balance"]
    body = []
    for r in rows:
        if r["role"] != "sweep":
            continue
        if not r["complete"]:
            body.append([r["scheme"], mesh_label(r), f"{r['dt_s']:g}", r["steps"],
                         r["step_iterations"], r["step_cutbacks"],
                         f"{r['wall_median_s']:.3g}", r["runs"],
                         f"failed: {r['status']}", "", "", ""])
            continue
        body.append([r["scheme"], mesh_label(r), f"{r['dt_s']:g}", r["steps"],
                     r["step_iterations"], r["step_cutbacks"], f"{r['wall_median_s']:.3g}",
                     r["runs"], pct(r.get("tension_error_rel")),
                     f"{r.get('position_error_m', float('nan')):.2e}",
                     pct(r.get("position_error_rel")),
                     f"{r.get('energy_balance_rel', float('nan')):.1e}"])
    L += md_table(header, body, "lllrrrrrrrrr")
    L.append("")
    for key, what, bound in (
            ("tension_error_rel", "top tension error (as written)", bounds["tension"]),
            ("position_error_rel", "mid-node position error (relative)",
             bounds["position"])):
        L.append(f"Cheapest settings (median wall time) reaching a {what} of:")
        L.append("")
        head = ["target"] + SCHEMES + ["any scheme"]
        body = []
        for target in TARGETS:
            cells = [pct(target)]
            for s in SCHEMES + [None]:
                r = cheapest(rows, key, target, s)
                if target < bound:
                    cells.append("not measurable" + (
                        "" if r is None else f" ({mesh_label(r)}, Δt {r['dt_s']:g}: "
                        f"{pct(r[key])})"))
                    continue
                cells.append("not reached" if r is None else
                             (f"{r['scheme']} " if s is None else "") +
                             f"{mesh_label(r)}, Δt {r['dt_s']:g}: {r['wall_median_s']:.3g} s "
                             f"({pct(r[key])})")
            body.append(cells)
        L += md_table(head, body, "l" * len(head))
        L.append("")
    base = [r for r in rows if r["role"] == "sweep" and r["scheme"] == "EMC"
            and (r["order"], r["elements"]) == case["base"] and r["complete"]]
    for key, what in (("position_error_m", "position"), ("tension_error_rel", "tension")):
        o = observed_orders(base, key)
        L.append(f"- EMC, {case['base'][1]} elements of order {case['base'][0]}: observed "
                 f"order of the {what} error between successive Δt: "
                 + ", ".join(f"{x:.2f}" for x in o))
    o = floor_corrected_orders(base, "tension_error_rel", bounds["tension"])
    L.append(f"- The same for the tension error e with the reference's difference d = "
             f"{pct(bounds['tension'])} removed in quadrature, sqrt(e² − d²), where "
             f"e > 2d: " + (", ".join(f"{x:.2f}" for x in o) or "no pair"))
    L.append(f"- Orders are only meaningful while the errors are well above the "
             f"reference's accuracy ({pct(bounds['tension'])} in tension, "
             f"{pct(bounds['position'])} in position); below it they flatten or scatter.")
    L.append("")
    L.append(f"![work-precision, {name}](img/work_precision_{name}.png)")
    L.append("")
    return L


def checks(name, case, rows, bounds):
    """(description, passed) pairs."""
    out = []
    emc = [r for r in rows if r["role"] == "sweep" and r["scheme"] == "EMC"]
    failed = [f"{mesh_label(r)} Δt {r['dt_s']:g}" for r in emc if not r["complete"]]
    out.append((f"{name}: every EMC run completes" + (f" (failed: {', '.join(failed)})"
                                                     if failed else ""), not failed))
    chk = [r for r in rows if r["role"] == "check"][0]
    ct, cx = chk.get("tension_error_rel"), chk.get("position_error_rel")
    out.append((f"{name}: reference vs check run: tension {pct(ct)} <= 1 %, "
                f"position {pct(cx)} <= 0.1 %",
                ct is not None and cx is not None and ct <= 1e-2 and cx <= 1e-3))
    base = [r for r in emc if (r["order"], r["elements"]) == case["base"] and r["complete"]]
    # orders only between errors well above the reference's own accuracy
    good = [r for r in base if r.get("position_error_rel", 0) > 3 * (cx or 0)]
    o = observed_orders(good, "position_error_m")
    out.append((f"{name}: EMC position error order >= 1.5 on the base mesh between the two "
                "smallest Δt whose errors are above 3x the reference's (observed "
                + ", ".join(f"{x:.2f}" for x in o) + ")", bool(o) and o[-1] >= 1.5))
    # the tension's floor (the reference's own error, about ct: a free vibration whose
    # phase depends on the step, see docs/benchmarks_work_precision.md) is removed in
    # quadrature, and only errors above 2 ct are used
    o = floor_corrected_orders(base, "tension_error_rel", ct)
    out.append((f"{name}: EMC tension error (as written) order >= 1.5 on the base mesh "
                "between the two smallest Δt whose errors e are above 2x the reference's d, "
                "with d removed in quadrature, sqrt(e² - d²) (observed "
                + ", ".join(f"{x:.2f}" for x in o) + "; errors "
                + ", ".join(pct(r.get("tension_error_rel")) for r in base) + ")",
                bool(o) and o[-1] >= 1.5))
    return out


def plot_case(name, case, rows, bounds, facts, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colors = {"EMC": "C0", "MIDPOINT": "C1", "TRAPEZOIDAL": "C2", "ALPHA": "C3"}
    meshes = [case["base"]] + list(case["meshes"])
    markers = dict(zip(meshes, "osD^vP*Xh"))
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.2))
    keys = [("tension_error_rel", "top tension error, as written (rel. to dynamic part)"),
            ("position_error_rel", "mid-line node position error (rel.)")]
    for ax, (key, label) in zip(axes, keys):
        ref_bound = bounds["position" if key.startswith("position") else "tension"]
        for scheme in SCHEMES:
            for mesh in meshes:
                sub = [r for r in rows if r["role"] == "sweep" and r["scheme"] == scheme
                       and (r["order"], r["elements"]) == mesh and r.get(key)]
                if not sub:
                    continue
                ax.loglog([r["wall_median_s"] for r in sub], [r[key] for r in sub],
                          marker=markers[mesh], color=colors[scheme],
                          ls="-" if mesh == case["base"] else ":", ms=5, lw=1,
                          label=f"{scheme} p{mesh[0]}×{mesh[1]}")
                if scheme == "EMC" and mesh == case["base"]:
                    for r in sub:
                        ax.annotate(f"{r['dt_s']:g}", (r["wall_median_s"], r[key]),
                                    fontsize=6, color="0.3", xytext=(3, 3),
                                    textcoords="offset points")
        for t in TARGETS:
            ax.axhline(t, color="0.6", lw=0.6, ls="--")
        ax.axhspan(1e-12, ref_bound, color="0.85", zorder=0)
        ax.set_ylim(bottom=max(1e-6, min([r.get(key) or 1 for r in rows] + [1e-4]) / 2))
        ax.set_xlabel("wall time [s] (median)")
        ax.set_title(label, fontsize=9)
        ax.grid(True, which="both", lw=0.3)
    axes[0].set_ylabel("relative RMS error over the last periods")
    axes[1].legend(fontsize=6, ncol=2, loc="lower left")
    fig.suptitle(f"rodyn work-precision: {case['title']} (labels: Δt of EMC on the base "
                 "mesh; grey: below the reference's accuracy)", fontsize=10)
    fig.text(0.01, 0.01, f"{facts['cpu']}, {facts['rodyn']}, {facts['date']}", fontsize=6,
             color="0.4")
    fig.tight_layout(rect=(0, 0.02, 1, 0.96))
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {os.path.relpath(path, ROOT)}", file=sys.stderr)


def write_md(path, facts, text_lines):
    intro = ("# Benchmark: work-precision of the time integrators\n\n"
             "Generated by `python3 bench/work_precision.py`.\n\n")
    if os.path.isfile(path):
        with open(path) as f:
            old = f.read()
        if MARKER in old:
            intro = old.split(MARKER)[0]
    with open(path, "w") as f:
        f.write(intro + MARKER + "\n\n" + "\n".join(text_lines) + "\n")
    print(f"wrote {os.path.relpath(path, ROOT)}", file=sys.stderr)


def main():
    doc = __doc__.split("\n\n")
    ap = argparse.ArgumentParser(description=doc[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n\n".join(doc[2:]))
    ap.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"),
                    help="rodyn executable (default: build/rodyn)")
    ap.add_argument("--quick", action="store_true", help="short version (about 10 s)")
    ap.add_argument("--cases", nargs="+", choices=list(CASES), help="cases to run "
                    "(default: all; with --quick: case1)")
    ap.add_argument("--csv", help="CSV to write (default: bench/results/work_precision.csv; "
                    "none with --quick)")
    ap.add_argument("--png-dir", help="folder of the plots (default: docs/img; none with "
                    "--quick)")
    ap.add_argument("--md", help="markdown page to update (default: "
                    "docs/benchmarks_work_precision.md; none with --quick)")
    ap.add_argument("--keep", help="folder for the decks and results (kept; default: a "
                    "temporary folder, removed)")
    args = ap.parse_args()
    rodyn = check_rodyn(args.rodyn)
    table = QUICK if args.quick else CASES
    names = args.cases or list(table)
    names = [n for n in names if n in table]
    if not names:
        sys.exit("--quick runs case1 only")
    if not args.quick:
        args.csv = args.csv or os.path.join(ROOT, "bench", "results", "work_precision.csv")
        args.png_dir = args.png_dir or os.path.join(ROOT, "docs", "img")
        args.md = args.md or os.path.join(ROOT, "docs", "benchmarks_work_precision.md")

    facts = rodyn_binary_facts(rodyn)
    all_rows, lines, results = [], [], []
    import time as _time
    t_start = _time.perf_counter()

    def work(workdir):
        for name in names:
            case = table[name]
            rows, ref = run_case(rodyn, workdir, name, case)
            all_rows.extend(rows)
            # the check run differs from the reference by d; the reference's own error
            # is below d (below d/3 for a second-order error in dt)
            bound = bounds_of(rows)
            if ref is None:
                results.append((f"{name}: the reference run completes", False))
                continue
            lines.extend(case_report(name, case, rows, bound))
            results.extend(checks(name, case, rows, bound))
            if args.png_dir:
                plot_case(name, case, rows, bound, facts,
                          os.path.join(args.png_dir, f"work_precision_{name}.png"))

    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        work(os.path.abspath(args.keep))
    else:
        with tempfile.TemporaryDirectory(prefix="rodyn_wp_") as workdir:
            work(workdir)
    elapsed = _time.perf_counter() - t_start
    facts["load average after the run (1/5/15 min)"] = " / ".join(
        f"{x:.2f}" for x in os.getloadavg())
    facts["script run time"] = f"{elapsed:.0f} s" + (" (--quick)" if args.quick else "")

    head = ["## Machine and program", ""] + [f"- {k}: {v}" for k, v in facts.items()] + [""]
    summary = ["## Checks", ""] + [f"- {'PASS' if ok else 'FAIL'}: {d}" for d, ok in results]
    out = head + ["## Results", ""] + lines + summary + [""]
    print("\n".join(out))
    if args.csv:
        write_csv(args.csv, facts, CSV_COLUMNS, all_rows,
                  comments=["bench/work_precision.py" + (" --quick" if args.quick else ""),
                            "errors: see the docstring of bench/work_precision.py"])
        print(f"wrote {os.path.relpath(os.path.abspath(args.csv), ROOT)}", file=sys.stderr)
    if args.md:
        write_md(args.md, facts, out)
    n_fail = sum(1 for _, ok in results if not ok)
    print(f"\nwork_precision: {len(results) - n_fail} checks passed, {n_fail} failed",
          file=sys.stderr)
    sys.exit(1 if n_fail else 0)


if __name__ == "__main__":
    main()
