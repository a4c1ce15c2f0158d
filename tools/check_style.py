#!/usr/bin/env python3
"""Quick style check of the Fortran sources, their fypp templates (.fypp) and the .pf tests
(docs/../shared style note): lines at most 100 columns, no tab characters, `implicit none`
in every module and program, no STOP in library code (only the main program ends the
run).
Usage: check_style.py REPO_ROOT. Exit 0 when clean, 1 with one line per finding."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
files = sorted(root.glob("src/**/*.f90")) + sorted(root.glob("src/**/*.fypp")) \
    + sorted(root.glob("tests/unit/*.pf")) + sorted(root.glob("tests/verification/*.pf"))
SOURCES = (".f90", ".fypp")  # Fortran of the library, hand-written or a template of it
problems = []
for path in files:
    text = path.read_text()
    rel = path.relative_to(root)
    for n, line in enumerate(text.splitlines(), 1):
        if len(line) > 100:
            problems.append(f"{rel}:{n}: line of {len(line)} columns (limit 100)")
        if "\t" in line:
            problems.append(f"{rel}:{n}: tab character")
        code = line.split("!")[0]
        if path.suffix in SOURCES and "app/rodyn_main" not in str(rel) and \
                re.search(r"^\s*(error\s+)?stop\b", code, re.IGNORECASE):
            problems.append(f"{rel}:{n}: STOP in library code")
    if path.suffix in SOURCES and not re.search(r"^\s*implicit none", text, re.M | re.I):
        problems.append(f"{rel}: no 'implicit none'")
for p in problems:
    print(p)
print(f"{len(files)} files checked, {len(problems)} findings")
sys.exit(1 if problems else 0)
