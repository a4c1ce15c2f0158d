#!/usr/bin/env python3
"""Deck fuzzer: run rodyn on seeded mutations of the shipped and test decks.

Each case takes one seed deck (input/, input/batch/, tests/decks/good, tests/decks/bad,
tests/program) with the files it reads (*INCLUDE, INPUT= tables), applies one to three
mutations drawn from a seeded generator (deleted, duplicated, swapped and moved lines,
extreme and non-numeric values, long lines, odd bytes and encodings, include loops and
missing includes, *PARAMETER gone wrong, ...), and runs rodyn on it in a folder of its
own, with `--check` in about half of the cases and as a full run otherwise. A full run
is kept short: on every *DYNAMIC card TIME is cut to at most 10 steps (TIME <= 10 DT),
*STATIC INCREMENTS to at most 10, MAX ITERATIONS (*STATIC and *DYNAMIC) to 20 and
CUTBACKS to 3 (written on the card when it has none), and a line's or segment's ELEMENTS
to 60 (the cuts are written into the deck after the mutation, on values rodyn accepts:
a value beyond rodyn's bounds, such as INCREMENTS=2147483647, stays for rodyn to refuse;
a deck whose DT or TIME is no number, nor a parameter set to one, runs with `--check`,
and so do the three seeds of CHECK_ONLY, which take seconds even so).

Every case must keep rodyn's contract (README.md, docs/deck.md, docs/output.md):
  * exit status 0, 1, 2 or 3, never a signal, never a Fortran runtime error;
  * done within the time limit (--timeout, default 20 s);
  * exit 1 prints `FILE:LINE: error: ` (or `rodyn: error: ` for the command line,
    `PATH: error: cannot open deck` for a missing main deck), FILE a file of the case
    and LINE one of its lines;
  * exit 2 only from a run (never from --check, which computes nothing), leaving
    status.txt with `complete = false` and a status that names what failed;
  * exit 3 prints a message with `error`; exit 0 of a run leaves `complete = true`.
A case that breaks it is saved under --save (the deck files, the command, stdout and
stderr) for reproduction. Prints a summary table; exits 1 on any violation.

The same --seed and --count give the same decks (case k uses its own generator seeded
with "SEED:k", whatever --jobs is).

    python3 tools/fuzz_decks.py --rodyn build/rodyn --count 300           # quick
    python3 tools/fuzz_decks.py --rodyn build/rodyn --count 10000 --jobs 2
"""
import argparse
import collections
import concurrent.futures
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED_GLOBS = [("input", ".inp"), ("input/batch", ".inp"), ("tests/decks/good", ".inp"),
              ("tests/decks/bad", ".inp"), ("tests/program", ".inp")]
KEYWORDS = ["HEADING", "GRAVITY", "INCLUDE", "SECTION", "LINE", "SEGMENT", "BOUNDARY",
            "LOAD", "STATIC", "OUTPUT", "DYNAMIC", "DAMPING", "AMPLITUDE", "MOTION",
            "INITIAL VELOCITY", "WATER", "CURRENT", "SEABED", "ATTACHMENT", "PARAMETER"]
EXTREME = ["0", "-0.0", "1e99", "-1e99", "9.99e99", "1e100", "1e-99", "1e-100", "1e-101",
           "1e308", "1e309", "-1e309", "4.9e-324", "2147483647", "2147483648", "-2147483649",
           "99999999999999999999", "10000001", "-1", "1", "1e9", "3.0e-9", "+0", ".0", "0."]
GARBAGE = ["", " ", "nan", "NaN", "inf", "-Infinity", "abc", "1.0.5", "1e", "e5", "2kN",
           "1_wp", "0x10", "+-1", "--1", "1,5", "1;2", "\"", "'", "<", ">", "<X>", "<>",
           "=", "==", "*", "**", "Y", "TRUE", "\u0661", "\u00bd", "1e+", "..", "-",
           "1 2", "(1)", "1d0", "1q0", "\t"]
ODD_BYTES = [b"\x00", b"\xff", b"\xfe", b"\x1a", b"\x7f", b"\x0b", b"\x0c", b"\x1b[2J",
             b"\xc3\x28", b"\xe2\x82\xac", b"\xef\xbb\xbf", b"\r", b"\t", b"\x80\x80\x80",
             b"\xf0\x9f\x8c\x8a", b"\x00" * 64]
NUMBER_RE = re.compile(rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?")
PARAM_RE = re.compile(rb"(?P<name>[A-Za-z][A-Za-z ]*?)\s*=\s*(?P<value>[^,]*)")
INPUT_RE = re.compile(rb"INPUT\s*=\s*\"?([^,\"\r\n]+)\"?", re.IGNORECASE)
LOC_RE = re.compile(r"^(\S[^\n]*?):(\d+): error: ", re.MULTILINE)
CLI_RE = re.compile(r"^rodyn: error: |^\S[^\n]*: error: cannot open deck", re.MULTILINE)
CRASH_RE = re.compile(r"Fortran runtime error|Program received signal|Backtrace for this "
                      r"error|Error termination|Segmentation fault|malloc\(\)|"
                      r"double free|HDF5-DIAG")
MEMORY_LIMIT_KIB = 3 << 20    # address space of one rodyn process [KiB]
# rodyn runs under a memory limit (the fuzzer must not take the machine's memory) and
# without core dumps; exec keeps its exit status and signal
LIMITS = ["/bin/sh", "-c", f'ulimit -v {MEMORY_LIMIT_KIB}; ulimit -c 0; exec "$@"', "sh"]
# seeds run with --check only: their shortened run still takes 2 to 6 s (a homotopy of
# hundreds of Newton iterations; riser_lazy_wave*: 570 iterations in 14 increments;
# riser_storm.inp hangs the same cable)
CHECK_ONLY = {"input/riser_lazy_wave.inp", "input/riser_lazy_wave_heave.inp",
              "input/riser_storm.inp", "tests/decks/good/water_segmented.inp"}
BAD_SEED_SHARE = 0.25         # share of cases mutating a deck of tests/decks/bad
MAX_STEPS, MAX_INCREMENTS, MAX_ITERATIONS, MAX_CUTBACKS, MAX_ELEMENTS = 10, 10, 20, 3, 60
MAX_STEPS_BOUND, BIG = 100000000, 1.0e100   # rodyn's bounds on TIME/DT and on reals


# ---------------------------------------------------------------- seed decks and bundles
def included_paths(data):
    """Paths named by INPUT= on the keyword lines of a deck file (as bytes)."""
    paths = []
    for line in data.splitlines():
        if line.lstrip().startswith(b"*") and not line.lstrip().startswith(b"**"):
            for m in INPUT_RE.finditer(line):
                paths.append(m.group(1).strip().decode("utf-8", "replace"))
    return paths


def bundle(deck):
    """The deck and every file it reads, as {path relative to the deck's folder: bytes}.
    Paths naming a parameter, or files that do not exist, are left out (the deck then
    fails as it would unfuzzed)."""
    top = os.path.dirname(deck)
    files, todo = {}, [os.path.basename(deck)]
    while todo:
        rel = os.path.normpath(todo.pop())
        path = os.path.join(top, rel)
        if rel in files or "<" in rel or not os.path.isfile(path):
            continue
        with open(path, "rb") as f:
            files[rel] = f.read()
        for inc in included_paths(files[rel]):
            todo.append(os.path.join(os.path.dirname(rel), inc))
    return files


def seed_decks(root):
    """Sorted list of (name, main file, files) of the seed decks."""
    seeds = []
    for folder, ext in SEED_GLOBS:
        d = os.path.join(root, folder)
        for name in sorted(os.listdir(d)):
            if name.endswith(ext):
                files = bundle(os.path.join(d, name))
                seeds.append((f"{folder}/{name}", name, files))
    return seeds


# ---------------------------------------------------------------- mutations
def lines_of(data):
    return data.splitlines(keepends=True) or [b""]


def pick_line(rng, lines, keyword=None):
    """Index of a random line (a keyword line when keyword is True, a data line when
    False; any line when None)."""
    idx = list(range(len(lines)))
    if keyword is not None:
        sel = [i for i in idx if is_keyword(lines[i]) == keyword]
        idx = sel or idx
    return rng.choice(idx)


def is_keyword(line):
    s = line.lstrip()
    return s.startswith(b"*") and not s.startswith(b"**")


def m_delete(rng, data, ctx):
    lines = lines_of(data)
    for _ in range(rng.choice([1, 1, 1, 2, 5])):
        if len(lines) > 1:
            del lines[pick_line(rng, lines)]
    return b"".join(lines), "delete line(s)"


def m_duplicate(rng, data, ctx):
    lines = lines_of(data)
    i = pick_line(rng, lines)
    times = rng.choice([1, 1, 2, 100])
    at = rng.choice([i, pick_line(rng, lines)])
    lines[at:at] = [lines[i] if lines[i].endswith(b"\n") else lines[i] + b"\n"] * times
    return b"".join(lines), f"duplicate line {i + 1} x{times}"


def m_swap(rng, data, ctx):
    lines = lines_of(data)
    i, j = pick_line(rng, lines), pick_line(rng, lines)
    lines[i], lines[j] = lines[j], lines[i]
    return b"".join(lines), f"swap lines {i + 1} and {j + 1}"


def m_move_block(rng, data, ctx):
    """Move a keyword card with its data lines elsewhere."""
    lines = lines_of(data)
    i = pick_line(rng, lines, keyword=True)
    j = i + 1
    while j < len(lines) and not is_keyword(lines[j]):
        j += 1
    block = lines[i:j]
    del lines[i:j]
    at = rng.randrange(len(lines) + 1)
    lines[at:at] = block
    return b"".join(lines), f"move card at line {i + 1} to {at + 1}"


def replace_number(rng, data, values, keyword=None):
    lines = lines_of(data)
    for _ in range(8):
        i = pick_line(rng, lines, keyword)
        nums = list(NUMBER_RE.finditer(lines[i]))
        if nums:
            m = rng.choice(nums)
            v = rng.choice(values).encode("utf-8")
            lines[i] = lines[i][:m.start()] + v + lines[i][m.end():]
            return b"".join(lines), f"line {i + 1}: {m.group().decode()} -> {v!r}"
    return data, "no number found"


def m_extreme(rng, data, ctx):
    return replace_number(rng, data, EXTREME, rng.choice([None, True, False]))


def m_garbage(rng, data, ctx):
    return replace_number(rng, data, GARBAGE, rng.choice([None, True, False]))


def m_param_value(rng, data, ctx):
    """On a keyword line: a parameter's value made extreme, garbage or empty, the
    parameter dropped, given twice, or an unknown one added."""
    lines = lines_of(data)
    i = pick_line(rng, lines, keyword=True)
    line = lines[i]
    params = list(PARAM_RE.finditer(line))
    what = rng.choice(["value", "value", "drop", "twice", "unknown", "bare"])
    if not params or what == "unknown":
        lines[i] = line.rstrip(b"\r\n") + b", BOGUS=1\n"
        return b"".join(lines), f"line {i + 1}: unknown parameter"
    m = rng.choice(params)
    if what == "value":
        v = rng.choice(EXTREME + GARBAGE + ["YES", "NO", "A", "B", "EMC", "X" * 40,
                                             "<DT>", "CABLE"]).encode("utf-8")
        lines[i] = line[:m.start("value")] + v + line[m.end("value"):]
        desc = f"{m.group('name').decode()}={v!r}"
    elif what == "drop":
        lines[i] = line[:m.start()] + line[m.end():]
        desc = f"drop {m.group('name').decode()}"
    elif what == "twice":
        lines[i] = line.rstrip(b"\r\n") + b", " + m.group() + b"\n"
        desc = f"{m.group('name').decode()} twice"
    else:
        lines[i] = line[:m.start()] + m.group("name") + line[m.end():]
        desc = f"{m.group('name').decode()} without value"
    return b"".join(lines), f"line {i + 1}: {desc}"


def m_long_line(rng, data, ctx):
    lines = lines_of(data)
    i = rng.randrange(len(lines) + 1)
    n = rng.choice([200, 1000, 5000, 100000])
    kind = rng.choice(["comment", "data", "keyword", "name", "value", "expression"])
    if kind == "comment":
        new = b"**" + b"x" * n + b"\n"
    elif kind == "data":
        new = b", ".join([b"1.0"] * (n // 5)) + b"\n"
    elif kind == "keyword":
        new = b"*" + b"A" * n + b"\n"
    elif kind == "name":
        new = b"*SECTION, NAME=" + b"N" * n + b"\n1, 1, 1, 1, 1\n"
    elif kind == "value":
        new = b"*GRAVITY\n0, 0, -" + b"9" * n + b"\n"
    else:
        new = b"*PARAMETER\nFUZZ_X = " + deep_expression(rng) + b"\n"
    lines.insert(i, new)
    return b"".join(lines), f"long {kind} line ({n}) at {i + 1}"


def m_odd_bytes(rng, data, ctx):
    pos = rng.randrange(len(data) + 1)
    b = rng.choice(ODD_BYTES)
    return data[:pos] + b + data[pos:], f"bytes {b[:8]!r} at offset {pos}"


def m_encoding(rng, data, ctx):
    kind = rng.choice(["bom", "utf16le", "utf16be", "cr", "crlf", "tabs", "no_eol",
                       "trailing", "lower", "nul_end", "latin1"])
    if kind == "bom":
        return b"\xef\xbb\xbf" + data, "UTF-8 BOM"
    if kind == "utf16le":
        return b"\xff\xfe" + data.decode("utf-8", "replace").encode("utf-16-le"), "UTF-16LE"
    if kind == "utf16be":
        return b"\xfe\xff" + data.decode("utf-8", "replace").encode("utf-16-be"), "UTF-16BE"
    if kind == "cr":
        return data.replace(b"\n", b"\r"), "CR line ends"
    if kind == "crlf":
        return data.replace(b"\n", b"\r\n"), "CRLF line ends"
    if kind == "tabs":
        return data.replace(b" ", b"\t").replace(b",", rng.choice([b",\t", b"\t"])), "tabs"
    if kind == "no_eol":
        return data.rstrip(b"\n"), "no final newline"
    if kind == "trailing":
        return data.replace(b"\n", b"  \t\n"), "trailing blanks"
    if kind == "lower":
        return data.lower(), "lower case"
    if kind == "nul_end":
        return data + b"\x00" * rng.choice([1, 4096]), "NULs at the end"
    return data.replace(b"e", b"\xe9"), "Latin-1 bytes"


def m_truncate(rng, data, ctx):
    pos = rng.randrange(len(data) + 1)
    return data[:pos], f"truncated at {pos} of {len(data)} bytes"


def m_keyword(rng, data, ctx):
    """A keyword line renamed, mangled, or a stray card inserted."""
    lines = lines_of(data)
    i = pick_line(rng, lines, keyword=True)
    kind = rng.choice(["rename", "insert", "mangle", "star"])
    if kind == "rename":
        kw = rng.choice(KEYWORDS).encode()
        lines[i] = re.sub(rb"^\s*\*[A-Za-z ]+", b"*" + kw, lines[i])
        return b"".join(lines), f"line {i + 1} renamed *{kw.decode()}"
    if kind == "insert":
        kw = rng.choice(KEYWORDS).encode()
        lines.insert(rng.randrange(len(lines) + 1), b"*" + kw + b"\n")
        return b"".join(lines), f"bare *{kw.decode()} inserted"
    if kind == "mangle":
        lines[i] = lines[i].replace(b"*", rng.choice([b"* ", b"*,", b" *", b"***", b"*="]), 1)
        return b"".join(lines), f"line {i + 1} keyword mangled"
    lines.insert(rng.randrange(len(lines) + 1), rng.choice([b"*\n", b"*,\n", b"*, A=1\n"]))
    return b"".join(lines), "lone star"


def m_include(rng, data, ctx):
    """Include loops, missing, empty, odd and deep includes."""
    lines = lines_of(data)
    at = rng.randrange(len(lines) + 1)
    me = os.path.basename(ctx["file"]).encode()
    kind = rng.choice(["self", "loop", "missing", "folder", "empty", "absolute",
                       "quoted", "noinput", "deep", "binary"])
    extra = {}
    if kind == "self":
        new = b"*INCLUDE, INPUT=" + me + b"\n"
    elif kind == "loop":
        new = b"*INCLUDE, INPUT=fuzz_loop.inc\n"
        extra["fuzz_loop.inc"] = b"** loop back\n*INCLUDE, INPUT=" + me + b"\n"
    elif kind == "missing":
        new = b"*INCLUDE, INPUT=no/such/file.inc\n"
    elif kind == "folder":
        new = b"*INCLUDE, INPUT=.\n"
    elif kind == "empty":
        new = b"*INCLUDE, INPUT=fuzz_empty.inc\n"
        extra["fuzz_empty.inc"] = b""
    elif kind == "absolute":
        new = b"*INCLUDE, INPUT=/nonexistent/fuzz.inc\n"
    elif kind == "quoted":
        new = b'*INCLUDE, INPUT="' + me + b'\n'
    elif kind == "noinput":
        new = b"*INCLUDE\n"
    elif kind == "deep":
        n = rng.choice([9, 10, 11, 50])
        new = b"*INCLUDE, INPUT=fuzz_d1.inc\n"
        for k in range(1, n + 1):
            extra[f"fuzz_d{k}.inc"] = (f"*INCLUDE, INPUT=fuzz_d{k + 1}.inc\n"
                                       if k < n else "** bottom\n").encode()
    else:
        new = b"*INCLUDE, INPUT=fuzz_bin.inc\n"
        extra["fuzz_bin.inc"] = bytes(rng.randrange(256) for _ in range(512))
    lines.insert(at, new)
    ctx["extra"].update(extra)
    return b"".join(lines), f"include {kind} at line {at + 1}"


def m_parameter(rng, data, ctx):
    """*PARAMETER gone wrong: a definition removed, redefined, circular, bad, or a
    reference to nothing."""
    lines = lines_of(data)
    defs = [i for i, ln in enumerate(lines) if re.match(rb"\s*[A-Za-z_]\w*\s*=", ln)
            and not is_keyword(ln)]
    kind = rng.choice(["undefined_ref", "open_ref", "block", "block", "del_def",
                       "redefine", "bad_expr"])
    if kind in ("del_def", "redefine", "bad_expr") and not defs:
        kind = "block"
    if kind == "undefined_ref" or kind == "open_ref":
        ref = b"<NOPE>" if kind == "undefined_ref" else rng.choice([b"<DT", b"<", b"<1>"])
        return replace_number(rng, data, [ref.decode()], rng.choice([True, False]))
    if kind == "del_def":
        i = rng.choice(defs)
        del lines[i]
        return b"".join(lines), f"definition at line {i + 1} deleted"
    if kind == "redefine":
        i = rng.choice(defs)
        lines.insert(i + 1, lines[i])
        return b"".join(lines), f"definition at line {i + 1} twice"
    if kind == "bad_expr":
        i = rng.choice(defs)
        name = lines[i].split(b"=")[0]
        e = rng.choice([b"1/0", b"0**-1", b"(1", b"1)", b"2**2000", b"-8**0.5", b"x+",
                        b"\"open", b"1e400", b"A" * 40, b"2**2**2**2**2", b"" + name.strip(),
                        deep_expression(rng)])
        lines[i] = name + b"= " + e + b"\n"
        return b"".join(lines), f"line {i + 1}: {e[:20]!r}"
    body = rng.choice([b"A = 1\nB = <A>\n", b"A = <B>\nB = 1\n", b"A = 1\nA = 2\n",
                       b"DT = 1/0\n", b"= 3\n", b"1A = 2\n", b"S = \"text\nT = S * 2\n",
                       b"X = 1e99 * 1e99\n", b"Y\n", b"Z = \n", b"P = (((1)\n"])
    at = rng.randrange(len(lines) + 1)
    lines[at:at] = [b"*PARAMETER\n", body]
    return b"".join(lines), f"*PARAMETER block {body[:24]!r} at line {at + 1}"


def deep_expression(rng):
    """Parentheses, signs or powers nested 50 to 100 000 deep."""
    n = rng.choice([50, 99, 101, 5000, 100000])
    kind = rng.choice(["paren", "sign", "power"])
    if kind == "paren":
        return b"(" * n + b"1" + b")" * n
    if kind == "sign":
        return b"-" * n + b"1"
    return b"1**" * n + b"1"


def m_splice(rng, data, ctx):
    """A line of another seed deck inserted."""
    other = rng.choice(ctx["seeds"])[2]
    src = lines_of(rng.choice(list(other.values())))
    line = rng.choice(src)
    lines = lines_of(data)
    lines.insert(rng.randrange(len(lines) + 1), line if line.endswith(b"\n") else line + b"\n")
    return b"".join(lines), "line spliced from another deck"


def m_empty(rng, data, ctx):
    return rng.choice([b"", b"\n", b"**\n", b"\x00", b"*\n"]), "emptied"


MUTATIONS = [(m_delete, 10), (m_duplicate, 8), (m_swap, 8), (m_move_block, 5),
             (m_extreme, 14), (m_garbage, 10), (m_param_value, 12), (m_long_line, 4),
             (m_odd_bytes, 6), (m_encoding, 6), (m_truncate, 3), (m_keyword, 6),
             (m_include, 5), (m_parameter, 6), (m_splice, 5), (m_empty, 1)]


def mutate(rng, seeds, seed):
    """Mutated files of a seed deck and the list of what was done."""
    name, main, files = seed
    files = dict(files)
    ctx = {"seeds": seeds, "extra": {}}
    done = []
    funcs, weights = zip(*MUTATIONS)
    for _ in range(rng.choice([1, 1, 1, 2, 2, 3])):
        target = main if rng.random() < 0.8 or len(files) == 1 else \
            rng.choice(sorted(files))
        ctx["file"] = target
        f = rng.choices(funcs, weights)[0]
        files[target], desc = f(rng, files[target], ctx)
        done.append(f"{target}: {f.__name__[2:]}: {desc}")
    for k, v in ctx["extra"].items():
        files.setdefault(k, v)
    return files, done


# ---------------------------------------------------------------- short runs
def param_values(files):
    """NAME -> number of the deck's *PARAMETER lines written as plain numbers."""
    values = {}
    for data in files.values():
        for m in re.finditer(rb"^\s*([A-Za-z_]\w*)\s*=\s*([-+0-9.eEdD]+)\s*$", data, re.M):
            try:
                values[m.group(1).upper().decode()] = float(m.group(2).replace(b"d", b"e")
                                                           .replace(b"D", b"e"))
            except ValueError:
                pass
    return values


def number(text, values):
    text = text.strip()
    m = re.fullmatch(rb"<([A-Za-z_]\w*)>", text)
    if m:
        return values.get(m.group(1).upper().decode())
    try:
        return float(text.replace(b"d", b"e").replace(b"D", b"e"))
    except ValueError:
        return None


def cap_param(line, name, cap, bound, add=False):
    """The keyword line with parameter NAME cut to cap when it is a number above cap and
    at most bound (the largest rodyn accepts: a value beyond is left for rodyn to
    refuse); with add, NAME=cap is appended when the line lacks NAME."""
    rx = re.compile(rb"(,\s*" + name + rb"\s*=\s*)([^,\r\n]*)", re.IGNORECASE)
    m = rx.search(line)
    if m:
        try:
            if cap < float(m.group(2)) <= bound:
                return line[:m.start(2)] + str(cap).encode() + line[m.end(2):]
        except ValueError:
            pass
    elif add and not re.search(name, line, re.IGNORECASE):
        body = line.rstrip(b"\r\n")
        return body + b", " + name + b"=" + str(cap).encode() + line[len(body):]
    return line


def cap_for_run(files):
    """Files cut to a short run (see the module text), or None when a *DYNAMIC card's
    TIME or DT is not a number."""
    values = param_values(files)
    out = {}
    for rel, data in files.items():
        lines = lines_of(data)
        for i, line in enumerate(lines):
            s = line.lstrip().upper()
            if s.startswith(b"*DYNAMIC"):
                dt = re.search(rb",\s*DT\s*=\s*([^,\r\n]*)", line, re.IGNORECASE)
                tm = re.search(rb",\s*TIME\s*=\s*([^,\r\n]*)", line, re.IGNORECASE)
                if dt and tm:
                    vdt, vtm = number(dt.group(1), values), number(tm.group(1), values)
                    if vdt is None or vtm is None:
                        return None
                    if 0 < vdt < BIG and vtm < BIG and \
                            MAX_STEPS * vdt < vtm <= MAX_STEPS_BOUND * vdt:
                        new = repr(MAX_STEPS * vdt).encode()
                        line = line[:tm.start(1)] + new + line[tm.end(1):]
            if s.startswith(b"*STATIC"):
                line = cap_param(line, rb"INCREMENTS", MAX_INCREMENTS, 100000)
            if s.startswith(b"*STATIC") or s.startswith(b"*DYNAMIC"):
                line = cap_param(line, rb"MAX ITERATIONS", MAX_ITERATIONS, 1000, add=True)
                line = cap_param(line, rb"CUTBACKS", MAX_CUTBACKS, 30, add=True)
            if s.startswith(b"*LINE") or s.startswith(b"*SEGMENT"):
                line = cap_param(line, rb"ELEMENTS", MAX_ELEMENTS, 10000000)
            lines[i] = line
        out[rel] = b"".join(lines)
    return out


# ---------------------------------------------------------------- one case
def place(files, folder):
    """Write files into folder, the main deck's folder deep enough that every '..' path
    stays inside; returns the main deck's folder."""
    depth = max((rel.split(os.sep).count("..") for rel in files), default=0)
    top = os.path.join(folder, *(["d"] * depth)) if depth else folder
    for rel, data in files.items():
        path = os.path.normpath(os.path.join(top, rel))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    return top


def read_status(path):
    status = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if "=" in line:
                    k, v = line.split("=", 1)
                    status[k.strip()] = v.strip()
    except OSError:
        return None
    return status


def bad_location(path, line, top):
    """'' when FILE:LINE of a message names a file of the case (relative to its folder
    top) and a line of it (1 to its number of lines, counted at LF, CR or CR LF, plus
    one for a message at the end), else what is wrong."""
    try:
        with open(os.path.join(top, path), "rb") as f:
            data = f.read()
    except OSError:
        return f"exit 1 naming a file that is not there: {path}"
    n = max(data.count(b"\n"), len(data.splitlines())) + 1
    if not 1 <= line <= n:
        return f"exit 1 naming line {line} of {path}, which has {n - 1} lines"
    return ""


def judge(code, out, err, check, top):
    """The verdict of one case: (category, violation text or ''); top is the folder
    rodyn ran in, its output folder top/out."""
    outdir = os.path.join(top, "out")
    if code is None:
        return "hang", "no exit within the time limit"
    if code < 0:
        return "signal", f"killed by signal {signal.Signals(-code).name}"
    if CRASH_RE.search(err) or CRASH_RE.search(out):
        if "Allocation would exceed memory limit" in err:
            return "memory", "more memory than the fuzzer's limit"
        return "crash", "runtime error or crash text on the output"
    if code not in (0, 1, 2, 3):
        return "bad exit", f"exit status {code}"
    if code == 1:
        if CLI_RE.search(err):
            return "exit 1", ""
        m = LOC_RE.search(err)
        if not m:
            return "exit 1", "exit 1 without FILE:LINE: error:"
        return "exit 1", bad_location(m.group(1), int(m.group(2)), top)
    if code == 2:
        if check:
            return "exit 2", "exit 2 from --check, which computes nothing"
        st = read_status(os.path.join(outdir, "status.txt"))
        if st is None:
            return "exit 2", "exit 2 without status.txt"
        msg = st.get("status", "")
        if st.get("complete") != "false" or msg in ("", "complete", "running"):
            return "exit 2", f"status.txt not honest: complete={st.get('complete')}, " \
                             f"status={msg!r}"
        return "exit 2", ""
    if code == 3:
        return "exit 3", "" if "error" in err else "exit 3 without an error message"
    if not check:
        st = read_status(os.path.join(outdir, "status.txt"))
        if st is None or st.get("complete") != "true":
            return "exit 0", "exit 0 without status.txt saying complete = true"
    return "exit 0", ""


def run_limited(cmd, cwd, timeout):
    """(exit status, stdout, stderr) of cmd; status None when it ran past timeout [s]
    (then it is killed with everything it started)."""
    proc = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
        return proc.returncode, out, err
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        return None, out, err


def run_case(k, args, seeds):
    """Record of random case k: a seed deck mutated and run."""
    rng = random.Random(f"{args.seed}:{k}")
    bad = [s for s in seeds if s[0].startswith("tests/decks/bad/")]
    good = [s for s in seeds if not s[0].startswith("tests/decks/bad/")]
    seed = rng.choice(bad if rng.random() < BAD_SEED_SHARE else good)
    files, done = mutate(rng, seeds, seed)
    check = rng.random() < args.check_fraction or seed[0] in CHECK_ONLY
    if not check:
        capped = cap_for_run(files)
        if capped is None:
            check = True
        else:
            files = capped
    return run_files(k, args, seed, files, done, check)


def run_files(k, args, seed, files, done, check):
    """Record of case k: files written into a folder of their own, rodyn run on seed's
    main deck there (with --check when check), the outcome judged."""
    folder = tempfile.mkdtemp(prefix=f"case{k:05d}_", dir=args.work)
    top = place(files, folder)
    cmd = [args.rodyn, "--quiet"] + (["--check"] if check else []) + [seed[1], "-o", "out"]
    t0 = time.monotonic()
    code, out, err = run_limited(LIMITS + cmd, top, args.timeout)
    wall = time.monotonic() - t0
    out = out.decode("utf-8", "replace")
    err = err.decode("utf-8", "replace")
    category, violation = judge(code, out, err, check, top)
    if category == "signal" and code == -signal.SIGFPE and args.fpe_trap_ok:
        category, violation = "FPE trap", ""
    record = {"case": k, "seed_deck": seed[0], "mode": "check" if check else "run",
              "mutations": done, "exit": code, "category": category,
              "violation": violation, "wall_s": round(wall, 4)}
    if violation and args.save:
        dest = os.path.join(args.save, f"case{k:05d}")
        shutil.rmtree(dest, ignore_errors=True)
        shutil.copytree(folder, dest, symlinks=True)
        with open(os.path.join(dest, "fuzz_case.txt"), "w", encoding="utf-8") as f:
            f.write(f"cd {os.path.relpath(top, folder) or '.'} && {' '.join(cmd[1:])}\n")
            f.write(json.dumps(record, indent=1) + "\n---- stdout\n" + out[-20000:]
                    + "\n---- stderr\n" + err[-20000:] + "\n")
    shutil.rmtree(folder, ignore_errors=True)
    return record


# ---------------------------------------------------------------- regressions
# Decks that broke the contract once, rebuilt here (too big to keep as files), run with
# --check before the random cases in every mode: (name, text appended to
# tests/decks/good/minimal.inp).
REGRESSIONS = [
    ("keyword of 1 000 000 characters (17 s at 200 000, cubic)",
     b"*" + b"A" * 1000000 + b"\n"),
    ("parentheses nested 100 000 deep (stack overflow, SIGSEGV)",
     b"*PARAMETER\nX = " + b"(" * 100000 + b"1" + b")" * 100000 + b"\n"),
    ("100 000 unary signs (stack overflow, SIGSEGV)",
     b"*PARAMETER\nX = " + b"-" * 100000 + b"1\n"),
    ("100 000 powers in a row (stack overflow, SIGSEGV)",
     b"*PARAMETER\nX = " + b"1**" * 100000 + b"1\n"),
]


def run_regressions(args, seeds):
    """Records of the REGRESSIONS cases (numbered -1, -2, ...)."""
    minimal = [sd for sd in seeds if sd[0] == "tests/decks/good/minimal.inp"][0]
    records = []
    for k, (name, tail) in enumerate(REGRESSIONS):
        files = {minimal[1]: minimal[2][minimal[1]] + tail}
        records.append(run_files(-1 - k, args, (minimal[0], minimal[1]), files,
                                 [f"regression: {name}"], True))
    return records


# ---------------------------------------------------------------- self-test
# Stand-ins for rodyn that break its contract one way each (and two that keep it): the
# harness must flag every case of the first kind and none of the second.
DECK_ARG = 'for a; do [ "$a" = -o ] && break; d=$a; done; '   # the deck: before -o
FAKES = {
    "segfault": ("signal", 'kill -SEGV $$'),
    "hang": ("hang", 'sleep 30'),
    "exit 1 without FILE:LINE": ("exit 1", 'echo "error: bad deck" >&2; exit 1'),
    "exit 2 without status.txt": ("exit 2", 'echo "x.inp: error: statics" >&2; exit 2'),
    "exit 2 with status complete": ("exit 2", 'mkdir -p out; printf "complete = true\\n'
                                    'status = complete\\n" > out/status.txt; exit 2'),
    "runtime error": ("crash", 'echo "Fortran runtime error: Index 3 out of bounds" >&2; '
                               'exit 2'),
    "exit 5": ("bad exit", 'exit 5'),
    "exit 0 of a run, no status.txt": ("exit 0", 'exit 0'),
    "exit 1 at a file that is not there": ("exit 1", 'echo "nothere.inp:1: error: *LINE: x"'
                                           ' >&2; exit 1'),
    "exit 1 beyond the last line": ("exit 1", DECK_ARG + 'echo "$d:999999: error: *LINE: x"'
                                    ' >&2; exit 1'),
}
KEEPS = {
    "exit 1 at FILE:LINE": DECK_ARG + 'echo "$d:1: error: *LINE: x" >&2; exit 1',
    "exit 0, status complete": 'mkdir -p out; printf "complete = true\\nstatus = complete'
                               '\\n" > out/status.txt; exit 0',
}


def self_test(args, seeds):
    """Run the harness on the stand-ins; True when every verdict is the expected one."""
    ok = True
    for name, (category, body) in list(FAKES.items()) + [(k, (None, v)) for k, v in
                                                          KEEPS.items()]:
        fake = os.path.join(args.work, "fake_rodyn")
        with open(fake, "w", encoding="utf-8") as f:
            f.write("#!/bin/sh\n" + body + "\n")
        os.chmod(fake, 0o755)
        sub = argparse.Namespace(**vars(args))
        sub.rodyn, sub.timeout, sub.save, sub.check_fraction = fake, 1.0, None, 0.0
        rec = run_case(0, sub, seeds)
        good = (rec["violation"] != "" and rec["category"] == category) if category \
            else rec["violation"] == ""
        ok = ok and good
        print(f"{'ok  ' if good else 'FAIL'} {name}: {rec['category']}, "
              f"{rec['violation'] or 'no violation'}")
    # the same seed gives the same decks; another seed, others
    def decks(seed):
        out = []
        for k in range(50):
            rng = random.Random(f"{seed}:{k}")
            out.append(mutate(rng, seeds, rng.choice(seeds)))
        return out
    same, other = decks("a") == decks("a"), decks("a") != decks("b")
    print(f"{'ok  ' if same and other else 'FAIL'} deterministic: 50 cases of one seed "
          f"{'equal' if same else 'differ'}, of two seeds {'differ' if other else 'equal'}")
    return ok and same and other


# ---------------------------------------------------------------- driver
def summary_table(records, wall):
    cats = collections.Counter(r["category"] for r in records)
    bad = collections.Counter(r["violation"].split(":")[0] for r in records if r["violation"])
    modes = collections.Counter(r["mode"] for r in records)
    times = sorted(r["wall_s"] for r in records)
    lines = ["| outcome | cases |", "|---|---|"]
    for c in ["exit 0", "exit 1", "exit 2", "exit 3", "FPE trap", "signal", "crash",
              "hang", "bad exit", "memory"]:
        lines.append(f"| {c} | {cats.get(c, 0)} |")
    nviol = sum(1 for r in records if r["violation"])
    lines.append(f"| **violations** | **{nviol}** |")
    for v, n in sorted(bad.items()):
        lines.append(f"| - {v} | {n} |")
    lines.append("")
    nreg = sum(1 for r in records if r["case"] < 0)
    lines.append(f"{len(records) - nreg} random decks and {nreg} regression decks "
                 f"({modes.get('check', 0)} with --check, "
                 f"{modes.get('run', 0)} run), {wall:.1f} s wall; per deck median "
                 f"{times[len(times) // 2]:.3f} s, max {times[-1]:.3f} s")
    return "\n".join(lines), nviol


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rodyn", default=os.path.join(ROOT, "build", "rodyn"))
    p.add_argument("--root", default=ROOT, help="repository (seed decks)")
    p.add_argument("--count", type=int, default=300, help="number of decks (300)")
    p.add_argument("--seed", default="1", help="seed of the generator (1)")
    p.add_argument("--first", type=int, default=0, help="first case number (0)")
    p.add_argument("--timeout", type=float, default=20.0, help="wall time per deck [s]")
    p.add_argument("--check-fraction", type=float, default=0.5,
                   help="share of cases run with --check (0.5)")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--work", default=None, help="folder for the cases (a temporary one)")
    p.add_argument("--save", default=None,
                   help="folder for failing cases (default: WORK/failures, kept)")
    p.add_argument("--json", default=None, help="write every case's record here")
    p.add_argument("--fpe-trap-ok", action="store_true",
                   help="a SIGFPE is no violation (a Debug build traps overflow on purpose)")
    p.add_argument("--self-test", action="store_true",
                   help="check the harness on stand-ins that break the contract")
    args = p.parse_args()
    if args.self_test:
        args.work = tempfile.mkdtemp(prefix="rodyn_fuzz_self_")
        args.rodyn = "fake_rodyn"
        ok = self_test(args, seed_decks(args.root))
        shutil.rmtree(args.work, ignore_errors=True)
        return 0 if ok else 1
    args.rodyn = os.path.abspath(args.rodyn)
    if not os.access(args.rodyn, os.X_OK):
        p.error(f"no program at {args.rodyn}")
    made_work = args.work is None
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="rodyn_fuzz_"))
    os.makedirs(args.work, exist_ok=True)
    if args.save is None:        # WORK/failures holds this run's failures only
        args.save = os.path.join(args.work, "failures")
        shutil.rmtree(args.save, ignore_errors=True)
    args.save = os.path.abspath(args.save)
    seeds = seed_decks(args.root)
    t0 = time.monotonic()
    cases = range(args.first, args.first + args.count)
    records = run_regressions(args, seeds)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        records += list(pool.map(lambda k: run_case(k, args, seeds), cases))
    wall = time.monotonic() - t0
    table, nviol = summary_table(records, wall)
    print(f"rodyn deck fuzzer: seed {args.seed}, cases {args.first}.."
          f"{args.first + args.count - 1}, {len(seeds)} seed decks, {args.rodyn}")
    print(table)
    for r in records:
        if r["violation"]:
            print(f"VIOLATION case {r['case']} ({r['seed_deck']}, {r['mode']}, exit "
                  f"{r['exit']}): {r['violation']}; {'; '.join(r['mutations'])}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"seed": args.seed, "wall_s": wall, "cases": records}, f, indent=0)
    if nviol:
        print(f"failing cases saved in {args.save}")
    elif made_work:
        shutil.rmtree(args.work, ignore_errors=True)
    return 1 if nviol else 0


if __name__ == "__main__":
    sys.exit(main())
