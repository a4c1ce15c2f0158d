#!/usr/bin/env python3
"""No history of work in the repository's text: docs, comments and scripts describe the
program and its current figures; the order in which the work was done belongs to git log.

usage: check_no_history.py SOURCE_DIR [--self-test]

Scans README.md, docs/, src/, postproc/, bench/ and tools/ (text files: .md, .f90, .F90,
.fypp, .pf, .inc, .py, .sh, .txt, .toml, .cmake, .inp, CMakeLists.txt; bench/results/, the
generated data, is left out) and reports FILE:LINE: history: TEXT for
  - `session` as a word (case-insensitive): "the ninth session", "this session"
    (identifiers such as start_new_session are not words of prose, and a pytest
    session, the run of a test suite, is not a session of work);
  - a round of work: "round of work/changes/levers/fixes", "first/second/.../this/last
    round";
  - `issue N` (a numbered issue of this project as the author of a change: "issue 12
    added", "(issue 14)"); an issue of another project named with its owner or
    repository ("MoorDyn issue 12", "owner/repo#12") is not flagged;
  - `today` / `today's` as a word;
  - a date tied to a change: "since 2026-11-27", "before 2026-11-23", "until ...",
    "as of ...", and "(since DATE" in parentheses;
  - a date in a comment of a source file (src/, postproc/, tools/, bench/ code) next to
    a word of change (added, changed, fixed, moved, removed, replaced, rewritten): a
    comment says what the code does, not when it changed (the date of a stored
    measurement a constant comes from may be named).
A table row (a line starting with `|`) and a list of machine facts ("- date: ...")
may carry the date of a measurement: that is the date the standards ask a table of
figures to name, so dates there are not flagged by the last two rules.

Exit 0 when nothing is found, 1 with one line per finding.
"""
import pathlib
import re
import sys

SCAN_DIRS = ("docs", "src", "postproc", "bench", "tools")
SUFFIXES = {".md", ".f90", ".F90", ".fypp", ".pf", ".inc", ".py", ".sh", ".txt", ".toml",
            ".cmake", ".inp"}
SKIP_PARTS = {"results", ".venv", ".work", "__pycache__", "build", ".git",
              "node_modules", ".pytest_cache"}
CODE_SUFFIXES = {".f90", ".F90", ".fypp", ".pf", ".inc", ".py", ".sh", ".cmake"}

DATE = r"20\d\d-[01]\d-[0-3]\d"
RULES = [
    ("'session'", re.compile(r"(?<![\w-])sessions?(?![\w-])", re.I)),
    ("a round of work", re.compile(
        r"\bround of (work|changes|levers|fixes|edits)\b|"
        r"\b(first|second|third|fourth|fifth|next|last|this|previous|earlier) round\b",
        re.I)),
    ("an issue number", re.compile(r"(?<![\w/#-])issues? (no\. ?)?#?\d+\b", re.I)),
    ("'today'", re.compile(r"\btoday('s)?\b", re.I)),
    ("a date tied to a change", re.compile(
        r"\b(since|before|until|till|as of|up to)\s+(the\s+)?" + DATE, re.I)),
]
COMMENT = {".f90": "!", ".F90": "!", ".fypp": "!", ".pf": "!", ".inc": "!", ".py": "#", ".sh": "#",
           ".cmake": "#"}
CHANGE_WORD = re.compile(
    r"\b(add|added|change|changed|fix|fixed|move|moved|removed|replaced|rewritten|"
    r"rewrote|introduced|dropped)\b", re.I)
# a pytest session (the run of a test suite) is not a session of work
PYTEST_SESSION = re.compile(
    r"scope\s*=\s*[\"']session|(test|pytest) session|once per session|"
    r"session (stops|ends|fails)|stops the session", re.I)
OTHER_PROJECT_ISSUE = re.compile(
    r"(moordyn|cabledyn|opensees|hdf5|gfortran|gcc|lapack|numpy|pfunit|h5py|valgrind|"
    r"cmake|github\.com/\S+)\W{0,3}\s*issues? #?\d+", re.I)


def files(root):
    out = []
    readme = root / "README.md"
    if readme.is_file():
        out.append(readme)
    for d in SCAN_DIRS:
        base = root / d
        if not base.is_dir():
            continue
        for p in sorted(base.rglob("*")):
            if not p.is_file() or SKIP_PARTS & set(p.relative_to(root).parts):
                continue
            if p.suffix in SUFFIXES or p.name == "CMakeLists.txt":
                out.append(p)
    return out


def is_fact_line(line):
    """A table row or a machine-facts item: where a measurement's date belongs."""
    s = line.lstrip()
    return s.startswith("|") or re.match(r"[-*] [\w ()/]+: ", s) is not None


def findings(path, text):
    out = []
    is_code = path.suffix in CODE_SUFFIXES
    mark = COMMENT.get(path.suffix)
    for n, line in enumerate(text.splitlines(), 1):
        for what, rx in RULES:
            m = rx.search(line)
            if not m:
                continue
            if what == "an issue number" and OTHER_PROJECT_ISSUE.search(line):
                continue
            if what == "'session'" and PYTEST_SESSION.search(line):
                continue
            if what == "a date tied to a change" and is_fact_line(line):
                continue
            out.append((n, what, line.strip()))
            break
        else:
            if is_code and mark and mark in line:
                comment = line.split(mark, 1)[1]
                if re.search(DATE, comment) and CHANGE_WORD.search(comment):
                    out.append((n, "a date in a comment", line.strip()))
    return out


def self_test():
    """The rules on lines that must and must not be flagged."""
    flag = ["Measured this session: 1.2 s", "the ninth session", "in the next round",
            "issue 12 added the writer", "(issue 14)", "Today's figure", "since 2026-11-27",
            "(before 2026-11-23 08:20 UTC only ...)", "a round of work on the kernels"]
    keep = ["start_new_session=True", '@pytest.fixture(scope="session")',
            "the short case runs once per session", "that stops the session.",
            "a session-less HDF5 file id", "MoorDyn issue 12",
            "| 2026-11-27 | 4.8 s |", "- date: 2026-11-27 09:41 UTC",
            "the rounding of the output", "no issue with the mesh", "a round-off floor",
            "measured 2026-11-25 (`python3 bench/x.py`)"]
    bad = [s for s in flag if not findings(pathlib.Path("x.md"), s)]
    bad += [s for s in keep if findings(pathlib.Path("x.md"), s)]
    code_flag = "x = 1  # 2026-11-25: moved here"
    code_keep = "X = 42.2  # docs/water.md: 320 segments, 2026-11-25, run once"
    if findings(pathlib.Path("x.py"), code_keep):
        bad.append(code_keep)
    if not findings(pathlib.Path("x.py"), code_flag):
        bad.append(code_flag)
    for s in bad:
        print(f"self-test: wrong verdict on {s!r}")
    return 1 if bad else 0


def main():
    if "--self-test" in sys.argv:
        return self_test()
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    if self_test():
        return 1
    found = 0
    scanned = files(root)
    for path in scanned:
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError as e:
            print(f"{path}: cannot read: {e}")
            found += 1
            continue
        for n, what, line in findings(path, text):
            print(f"{path.relative_to(root)}:{n}: history ({what}): {line[:160]}")
            found += 1
    print(f"{len(scanned)} files checked, {found} lines of history")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
