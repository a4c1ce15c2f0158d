#!/usr/bin/env python3
"""*PARAMETER and --set end to end (docs/deck.md, docs/output.md):

(a) params.inp run with --set N=12 --set PERIOD=1.3 --set amp=0.35 gives the same CSV
    files, byte for byte, as params_literal.inp, the same deck with the values written
    out (a static solution, then a short dynamic run);
(b) status.txt holds a 'parameter.NAME = text' line for every parameter, in the order
    of the deck, with the values after --set (and those computed from them), and the
    HDF5 files (results.h5, dynamic.h5) hold them as attributes of /parameters (a float
    for a number, a string for a string); the literal deck's files have none;
(c) a bad --set exits 1 with its message, before any output folder is made: a name the
    deck does not declare, no '=', a bad name, no value, a name given twice, a value
    whose arithmetic fails.

Usage: check_params.py RODYN PARAM_DECK LITERAL_DECK WORK_DIR. Exit 0 on success."""
import filecmp
import os
import shutil
import subprocess
import sys

import h5py

SETS = ["--set", "N=12", "--set", "PERIOD=1.3", "--set", "amp=0.35"]

# The values the run must use: (text in status.txt, value), in the order of the deck.
PERIOD = 1.3
DT = PERIOD / 50
EXPECTED = {
    "N": ("12", 12.0),
    "L": ("10", 10.0),
    "XB": ("8", 0.8 * 10.0),
    "ZB": ("-1", -(10.0 - 8) / 2),
    "SEC": ("paper_cable_section", None),
    "PERIOD": ("1.3", PERIOD),
    "AMP": ("0.35", 0.35),
    "F": (repr(1 / PERIOD), 1 / PERIOD),
    "DT": (repr(DT), DT),
    "T_END": (repr(20 * DT), 20 * DT),
    "DT_OUT": (repr(5 * DT), 5 * DT),
}

problems = []


def run(rodyn, args):
    """Run rodyn with `args`; (exit code, stderr)."""
    proc = subprocess.run([rodyn] + args, capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stderr


def status_parameters(folder):
    """The 'parameter.NAME = text' lines of status.txt, in order, as (NAME, text)."""
    pairs = []
    with open(os.path.join(folder, "status.txt"), encoding="utf-8") as f:
        for line in f:
            key, _, value = line.partition("=")
            if key.strip().startswith("parameter."):
                pairs.append((key.strip()[len("parameter."):], value.strip()))
    return pairs


def check_h5(path, expect_none=False):
    """/parameters of an HDF5 file against EXPECTED (or its absence)."""
    with h5py.File(path, "r") as f:
        if expect_none:
            if "parameters" in f:
                problems.append(f"{path}: /parameters written for a deck without *PARAMETER")
            return
        if "parameters" not in f:
            problems.append(f"{path}: no /parameters group")
            return
        attrs = f["parameters"].attrs
        if sorted(attrs.keys()) != sorted(EXPECTED):
            problems.append(f"{path}: /parameters has {sorted(attrs.keys())}")
        for name, (text, value) in EXPECTED.items():
            if name not in attrs:
                continue
            got = attrs[name]
            if value is None:
                got = got.decode() if isinstance(got, bytes) else str(got)
                if got != text:
                    problems.append(f"{path}: /parameters {name} = {got!r}, expected {text!r}")
            elif float(got) != value:
                problems.append(f"{path}: /parameters {name} = {got!r}, expected {value!r}")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    rodyn, deck, literal, work = sys.argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out_p = os.path.join(work, "param")
    out_l = os.path.join(work, "literal")

    # (a) the same results, byte for byte
    code, err = run(rodyn, [deck, "-o", out_p, "--quiet"] + SETS)
    if code != 0:
        sys.exit(f"FAIL: {deck} {' '.join(SETS)}: exit {code}: {err.strip()}")
    code, err = run(rodyn, [literal, "-o", out_l, "--quiet"])
    if code != 0:
        sys.exit(f"FAIL: {literal}: exit {code}: {err.strip()}")
    csvs = sorted(f for f in os.listdir(out_l) if f.endswith(".csv"))
    if len(csvs) < 9:
        problems.append(f"{out_l}: only {csvs}")
    for name in csvs:
        if not filecmp.cmp(os.path.join(out_p, name), os.path.join(out_l, name),
                           shallow=False):
            problems.append(f"{name}: the parameterised run differs from the literal one")

    # (b) the values in status.txt and the HDF5 files
    got = status_parameters(out_p)
    want = [(name, text) for name, (text, _) in EXPECTED.items()]
    if got != want:
        problems.append(f"status.txt parameters {got}, expected {want}")
    if status_parameters(out_l):
        problems.append("status.txt of the literal deck has parameter lines")
    for h5 in ("results.h5", "dynamic.h5"):
        check_h5(os.path.join(out_p, h5))
        check_h5(os.path.join(out_l, h5), expect_none=True)

    # (c) bad --set: exit 1, the message, nothing made
    bad = [
        (["--set", "NOPE=1"], "rodyn: error: --set NOPE: no *PARAMETER NOPE in "),
        (["--set", "N"], "rodyn: error: --set 'N': expected NAME=VALUE"),
        (["--set", "1N=3"], "is not a parameter name"),
        (["--set", "N="], "rodyn: error: --set 'N=': no value"),
        (["--set", "N=3", "--set", "n=4"], "rodyn: error: --set N given twice"),
        (["--set", "PERIOD=1/(L-10)"],
         "error: *PARAMETER: PERIOD: --set PERIOD=1/(L-10): bad expression '1/(L-10)': "
         "division by zero"),
        (["--set", "N=2.5"], "error: *LINE: ELEMENTS: '2.5' is not an integer"),
        # an integer too large is quoted as typed, not as its rounded real value ('1e20')
        (["--set", "N=99999999999999999999"],
         "error: *LINE: ELEMENTS: '99999999999999999999' is out of range"),
        # and so is a signed one ('-1e20' and "not an integer" before); a '+' is dropped
        (["--set", "N=-99999999999999999999"],
         "error: *LINE: ELEMENTS: '-99999999999999999999' is out of range"),
        (["--set", "N=+99999999999999999999"],
         "error: *LINE: ELEMENTS: '99999999999999999999' is out of range"),
        (["--set"], "rodyn: error: --set needs NAME=VALUE"),
    ]
    for k, (args, message) in enumerate(bad):
        out = os.path.join(work, f"bad{k}")
        code, err = run(rodyn, [deck, "-o", out] + args)
        if code != 1:
            problems.append(f"{' '.join(args)}: exit {code}, expected 1 ({err.strip()})")
        if message not in err:
            problems.append(f"{' '.join(args)}: stderr lacks {message!r}: {err.strip()}")
        if os.path.exists(out):
            problems.append(f"{' '.join(args)}: the output folder was made")

    for p in problems:
        print("FAIL:", p)
    if problems:
        return 1
    print(f"ok: {len(csvs)} CSV files equal byte for byte; {len(EXPECTED)} parameters in "
          f"status.txt, results.h5 and dynamic.h5; {len(bad)} bad --set refused")
    return 0


if __name__ == "__main__":
    sys.exit(main())
