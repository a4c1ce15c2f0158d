"""Helpers shared by the benchmark scripts: machine facts, status files, fitted exponents."""
import datetime
import math
import os
import platform
import subprocess
import sys

def read_status(path):
    """status.txt as a dict of text values."""
    status = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                k, v = line.split("=", 1)
                status[k.strip()] = v.strip()
    return status


def fit_exponent(rows, key, min_n=100):
    """Least-squares exponent b of rows[key] ~ elements^b over the rows with
    elements >= min_n (failed runs left out)."""
    pts = [(math.log(r["elements"]), math.log(r[key])) for r in rows
           if r["elements"] >= min_n and not r["failed"] and r[key] > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx


def machine_facts(rodyn, load_average=False):
    """Command, build, date, machine and versions a measurement was taken on: every
    table a script writes names them."""
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass

    def cmd(args):
        try:
            r = subprocess.run(args, capture_output=True, text=True)
            return (r.stdout or r.stderr).strip().splitlines()[0]
        except (OSError, IndexError):
            return "unknown"
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    commit = cmd(["git", "-C", root, "describe", "--always", "--dirty", "--abbrev=10"])
    facts = {
        "command": "python3 " + " ".join(
            [os.path.relpath(os.path.abspath(sys.argv[0]), root)] + sys.argv[1:]),
        "commit (of the checkout the script ran from)": commit,
        "date": datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z"),
        "cpu": cpu,
        "cores": str(os.cpu_count()),
        "os": f"{platform.system()} {platform.release()}",
        "rodyn": cmd([rodyn, "--version"]),
        "gfortran": cmd(["gfortran", "--version"]),
    }
    if load_average:
        facts["load average before the run (1/5/15 min)"] = " / ".join(
            f"{x:.2f}" for x in os.getloadavg())
    return facts


# --- helpers of the dynamic stress tests and the work-precision study -------------------
# (bench/stress_tests.py, bench/work_precision.py)

import re
import shutil
import statistics
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rodyn_binary_facts(rodyn):
    """machine_facts plus the path and modification time of the rodyn binary and the
    load average before the run."""
    facts = machine_facts(rodyn, load_average=True)
    facts["rodyn binary"] = f"{rodyn}, built " + datetime.datetime.fromtimestamp(
        os.path.getmtime(rodyn)).astimezone().strftime("%Y-%m-%d %H:%M %Z")
    return facts


def check_rodyn(path):
    """Absolute path of an executable rodyn, or exit with a message."""
    import sys
    rodyn = os.path.abspath(path)
    if not os.access(rodyn, os.X_OK):
        sys.exit(f"no executable rodyn at {rodyn} (build it, or give --rodyn)")
    return rodyn


def _param_pattern(name):
    """Regex for ', NAME = value' on a keyword line (blanks in NAME: any run of blanks)."""
    words = r"\s+".join(re.escape(w) for w in name.split())
    return re.compile(r",\s*" + words + r"\s*=\s*[^,]*", re.I)


def set_params(text, keyword, params, occurrence=0):
    """Deck text with the parameters of a keyword line set: params maps a parameter name
    ('DT', 'OUTPUT INTERVAL', ...) to its value (replaced where given, appended
    otherwise) or to None (removed). `keyword` is the keyword with its star ('*DYNAMIC');
    the `occurrence`-th card of that keyword (from 0) is edited. Raises ValueError when
    the deck has no such card."""
    lines = text.splitlines()
    key = re.sub(r"\s+", " ", keyword.strip().upper())
    seen = -1
    for i, line in enumerate(lines):
        s = line.strip()
        if not s.startswith("*") or s.startswith("**"):
            continue
        name = re.sub(r"\s+", " ", s.split(",", 1)[0].upper())
        if name != key:
            continue
        seen += 1
        if seen != occurrence:
            continue
        out = line.rstrip().rstrip(",")
        for p, v in params.items():
            pat = _param_pattern(p)
            if v is None:
                out = pat.sub("", out)
            elif pat.search(out):
                out = pat.sub(f", {p}={fmt_value(v)}", out, count=1)
            else:
                out += f", {p}={fmt_value(v)}"
        lines[i] = out
        return "\n".join(lines) + "\n"
    raise ValueError(f"no {keyword} card (occurrence {occurrence}) in the deck")


def set_data_lines(text, keyword, data, occurrence=0):
    """Deck text with the data lines of the `occurrence`-th `keyword` card replaced by
    `data` (a list of strings). Comment lines among the old data lines are dropped."""
    lines = text.splitlines()
    key = re.sub(r"\s+", " ", keyword.strip().upper())
    seen, start = -1, None
    for i, line in enumerate(lines):
        s = line.strip()
        if s.startswith("*") and not s.startswith("**"):
            if start is not None:
                return "\n".join(lines[:start] + list(data) + lines[i:]) + "\n"
            name = re.sub(r"\s+", " ", s.split(",", 1)[0].upper())
            if name == key:
                seen += 1
                if seen == occurrence:
                    start = i + 1
    if start is not None:
        return "\n".join(lines[:start] + list(data)) + "\n"
    raise ValueError(f"no {keyword} card (occurrence {occurrence}) in the deck")


def add_card(text, card, before="*OUTPUT"):
    """Deck text with the lines of `card` inserted before the first `before` keyword
    line (at the end if there is none)."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.strip().upper().startswith(before.upper()):
            return "\n".join(lines[:i] + card.strip("\n").splitlines() + lines[i:]) + "\n"
    return "\n".join(lines + card.strip("\n").splitlines()) + "\n"


def note_heading(text, note):
    """Deck text with `note` appended to the *HEADING title line."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.strip().upper().startswith("*HEADING"):
            for j in range(i + 1, len(lines)):
                if lines[j].strip() and not lines[j].strip().startswith("**"):
                    lines[j] = lines[j].rstrip() + f" [{note}]"
                    return "\n".join(lines) + "\n"
    return text


def fmt_value(v):
    """A deck value: floats with repr precision, others as text."""
    if isinstance(v, float):
        return repr(v) if v != int(v) or abs(v) >= 1e15 else f"{v:.1f}"
    return str(v)


def read_deck(name):
    """Text of a deck given relative to the repository root (input/..., bench/decks/...)."""
    with open(os.path.join(ROOT, name)) as f:
        return f.read()


def write_deck(workdir, tag, text, includes=()):
    """Write deck text to workdir/tag.inp and copy the included files (paths relative to
    the repository root) next to it; returns the deck path."""
    for inc in includes:
        dst = os.path.join(workdir, os.path.basename(inc))
        if not os.path.isfile(dst):
            shutil.copy(os.path.join(ROOT, inc), dst)
    path = os.path.join(workdir, tag + ".inp")
    with open(path, "w") as f:
        f.write(text)
    return path


def run_rodyn(rodyn, deck, out=None, timeout=None):
    """Run `rodyn DECK -o OUT --quiet` once. Returns a dict: returncode, wall_s (whole
    process, seen from Python), stderr, status (status.txt as a dict, {} if missing),
    out; returncode None (and 'timeout' in stderr) if the run was killed at `timeout`."""
    out = out or os.path.splitext(deck)[0]
    if os.path.isdir(out):
        shutil.rmtree(out)
    t0 = time.perf_counter()
    try:
        proc = subprocess.run([rodyn, deck, "-o", out, "--quiet"], capture_output=True,
                              text=True, timeout=timeout)
        rc, err = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired:
        rc, err = None, f"timeout after {timeout} s"
    wall = time.perf_counter() - t0
    st_path = os.path.join(out, "status.txt")
    status = read_status(st_path) if os.path.isfile(st_path) else {}
    return {"returncode": rc, "wall_s": wall, "stderr": err.strip(), "status": status,
            "out": out}


def timed_run(rodyn, deck, out=None, repeats=3, repeat_below_s=2.0, timeout=None):
    """Run a deck, and again up to `repeats` times in all if one run takes less than
    `repeat_below_s` seconds; the result of the last run with wall_s = median of the
    process wall times, plus runs, wall_min_s, wall_max_s. A failed run (exit status
    other than 0) is not repeated."""
    walls, r = [], None
    for k in range(max(1, repeats)):
        r = run_rodyn(rodyn, deck, out, timeout)
        walls.append(r["wall_s"])
        if r["returncode"] != 0 or r["wall_s"] >= repeat_below_s:
            break
    r["runs"] = len(walls)
    r["wall_s"] = statistics.median(walls)
    r["wall_min_s"], r["wall_max_s"] = min(walls), max(walls)
    return r


def load_results(out):
    """rodyn_post.load_dynamic of a results folder (the installed package of postproc/:
    bash tools/setup.sh)."""
    from rodyn_post import load_dynamic
    return load_dynamic(out)


def interp_cubic(t, y, tq):
    """Values at times tq of the series y (rows) sampled at increasing times t, by
    4-point Lagrange (cubic) interpolation on the nearest samples; y may be 1-D or 2-D
    (rows = samples). tq must lie within [t[0], t[-1]]."""
    import numpy as np
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    tq = np.asarray(tq, float)
    if len(t) < 4:
        return np.interp(tq, t, y) if y.ndim == 1 else np.column_stack(
            [np.interp(tq, t, y[:, k]) for k in range(y.shape[1])])
    i = np.clip(np.searchsorted(t, tq) - 2, 0, len(t) - 4)
    out = np.zeros(tq.shape + y.shape[1:])
    for j in range(4):
        w = np.ones_like(tq)
        for m in range(4):
            if m != j:
                w = w * (tq - t[i + m]) / (t[i + j] - t[i + m])
        out += w.reshape(w.shape + (1,) * (y.ndim - 1)) * y[i + j]
    return out


def md_table(header, rows, align=None):
    """Markdown table lines: header (list of str), rows (lists of str), align a string
    of 'l'/'r' per column (default: first left, others right)."""
    align = align or "l" + "r" * (len(header) - 1)
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---" if a == "l" else "---:" for a in align) + "|"]
    lines += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return lines


def write_csv(path, facts, columns, rows, comments=()):
    """CSV with the machine facts and comments as '#' lines, then a header and one row
    per dict of `rows` (floats as %.6e, bools as true/false, missing as empty)."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        for k, v in facts.items():
            f.write(f"# {k}: {v}\n")
        for c in comments:
            f.write(f"# {c}\n")
        f.write(",".join(columns) + "\n")
        for r in rows:
            vals = []
            for c in columns:
                v = r.get(c)
                if v is None:
                    vals.append("")
                elif isinstance(v, bool):
                    vals.append("true" if v else "false")
                elif isinstance(v, float):
                    vals.append(f"{v:.6e}")
                else:
                    s = str(v)
                    vals.append('"' + s.replace('"', "'") + '"' if "," in s else s)
            f.write(",".join(vals) + "\n")


# --- shared by the MoorDyn cross-checks (bench/water, bench/waves) ----------------------

def read_end_forces(out, end, line=None):
    """Times [s] and forces of the support on the line (n, 3) [N] at end 'A' or 'B', every
    step, from a run folder's dynamic_ends_step.csv (of the only line, or of `line`)."""
    import csv
    import numpy as np
    t, f = [], []
    with open(os.path.join(out, "dynamic_ends_step.csv")) as fh:
        for row in csv.DictReader(r for r in fh if not r.startswith("#")):
            if row["end"] == end and (line is None or row["line"] == line):
                t.append(float(row["time_s"]))
                f.append([float(row[c]) for c in ("Fx_N", "Fy_N", "Fz_N")])
    return np.array(t), np.array(f)


def moordyn_line_deck(title, ltype, points, length, segments, options):
    """A MoorDyn v2 input file of one line between two points. ltype: dict with name, d,
    m, ea, ba, ei, cd, ca, cdax, caax; points: two (attachment, x, y, z, mass) of end A
    and end B; options: (value, name) pairs of the OPTIONS section."""
    lt = ("{name}  {d!r}  {m!r}  {ea:.6e}  {ba!r}  {ei!r}  {cd!r}  {ca!r}  {cdax!r}  "
          "{caax!r}").format(**ltype)
    pts = "\n".join(f"{i}  {a}  {x!r}  {y!r}  {z!r}  {m!r}  0  0  0"
                    for i, (a, x, y, z, m) in enumerate(points, 1))
    opts = "\n".join(f"{v}  {k}" for v, k in options)
    return f"""--------------------- MoorDyn Input File ------------------------------------
{title}
---------------------- LINE TYPES ----------------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
{lt}
---------------------- POINTS ---------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
{pts}
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     {ltype['name']}  1  2  {length!r}  {segments}  -
---------------------- OPTIONS -----------------------------------------
{opts}
------------------------- need this line -------------------------------------
"""
