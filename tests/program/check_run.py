#!/usr/bin/env python3
"""Run rodyn and check what a user would: exit status, messages, and the files left.

Usage:
    check_run.py --exit CODE [--expect TEXT]... [--stdout TEXT]...
                 [--outdir DIR [--status KEY=VALUE]... [--csv NAME]...] -- COMMAND...

--expect TEXT  must appear in stderr; --stdout TEXT in stdout;
--status       a `key = value` line of DIR/status.txt (values compared as text, or as
               numbers when --status KEY>VALUE / KEY<VALUE is used);
--csv NAME     DIR/NAME must exist, have a header row and only numbers or names in its
               rows, every row complete, i.e. be readable as written so far.
Exit 0 when everything matches, 1 otherwise (saying what differed).
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys


def read_status(path):
    values = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if "=" in line:
                key, value = line.split("=", 1)
                values[key.strip()] = value.strip()
    return values


def check_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        return "empty file"
    header = rows[0]
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            return f"line {i}: {len(row)} fields, header has {len(header)}"
        for field in row:
            if re.fullmatch(r"[A-Za-z][A-Za-z0-9_.-]*", field) and field.lower() not in (
                    "nan", "inf", "infinity"):
                continue          # a line name or an end (A, B)
            try:
                float(field)
            except ValueError:
                return f"line {i}: '{field}' is not a number"
    return None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exit", type=int, required=True)
    p.add_argument("--expect", action="append", default=[])
    p.add_argument("--stdout", action="append", default=[])
    p.add_argument("--outdir")
    p.add_argument("--status", action="append", default=[])
    p.add_argument("--csv", action="append", default=[])
    p.add_argument("command", nargs=argparse.REMAINDER)
    a = p.parse_args()
    cmd = a.command[1:] if a.command and a.command[0] == "--" else a.command
    if a.outdir and os.path.isdir(a.outdir):
        shutil.rmtree(a.outdir)
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    problems = []
    if run.returncode != a.exit:
        problems.append(f"exit status {run.returncode}, expected {a.exit}")
    problems += [f"stderr lacks {t!r}" for t in a.expect if t not in run.stderr]
    problems += [f"stdout lacks {t!r}" for t in a.stdout if t not in run.stdout]
    if "Traceback" in run.stderr or "Backtrace" in run.stderr or "Error termination" in run.stderr:
        problems.append("a crash trace on stderr")
    if a.outdir:
        status_file = os.path.join(a.outdir, "status.txt")
        if not os.path.isfile(status_file):
            problems.append("no status.txt")
        else:
            status = read_status(status_file)
            for item in a.status:
                m = re.match(r"([\w]+)\s*([=<>])\s*(.*)", item)
                key, op, want = m.groups()
                got = status.get(key)
                if got is None:
                    problems.append(f"status.txt lacks {key}")
                elif op == "=" and got != want:
                    problems.append(f"status {key} = {got}, expected {want}")
                elif op == ">" and not float(got) > float(want):
                    problems.append(f"status {key} = {got}, expected > {want}")
                elif op == "<" and not float(got) < float(want):
                    problems.append(f"status {key} = {got}, expected < {want}")
        for name in a.csv:
            path = os.path.join(a.outdir, name)
            if not os.path.isfile(path):
                problems.append(f"no {name}")
            else:
                bad = check_csv(path)
                if bad:
                    problems.append(f"{name}: {bad}")
        leftovers = [f for f in os.listdir(a.outdir)] if os.path.isdir(a.outdir) else []
        problems += [f"temporary file left: {f}" for f in leftovers if f.endswith(".tmp")]
    if problems:
        print("command:", " ".join(cmd))
        print("stdout:", run.stdout[-2000:])
        print("stderr:", run.stderr[-2000:])
        for line in problems:
            print("MISMATCH:", line)
        return 1
    print("ok:", " ".join(cmd))
    return 0


if __name__ == "__main__":
    sys.exit(main())
