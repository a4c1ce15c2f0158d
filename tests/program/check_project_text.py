#!/usr/bin/env python3
"""The project speaks of itself only, and its README is a user guide.

usage: check_project_text.py SOURCE_DIR

- README.md: under 300 lines; gives the two set-up commands, `bash tools/run.sh` and
  `bash tools/test.sh`, the latter being exactly what .ci/run runs; no dated line.
- README.md, LICENSE present, and the files of src/, tools/, postproc/, tests/ and the
  docs listed in CHECKED_DOCS: no account of the work (a "session", a "round of work",
  "issue N"), no ISO date outside a table row; the other docs and bench/: no account of
  the work (their measurements carry their dates). A pytest *session* and Python's
  start_new_session are words of the tools, not of the work, and are allowed.
"""
import pathlib
import re
import sys

HISTORY = re.compile(r"\bsessions?\b|\bround of work\b|\bissue [0-9]+", re.I)
ALLOWED = re.compile(r"start_new_session|scope=\"session\"|test session|pytest session|"
                     r"once per session|stops the session", re.I)
DATE = re.compile(r"\b20[0-9]{2}-[0-9]{2}-[0-9]{2}\b")
CHECKED = ["src", "tools", "postproc", "tests"]
CHECKED_DOCS = ["docs/theory.md", "docs/architecture.md"]
# no account of the work, measurements dated as they are: the other docs and bench/
HISTORY_ONLY = ["docs", "bench"]
PENDING = []
SUFFIXES = {".f90", ".fypp", ".py", ".sh", ".md", ".txt", ".pf", ".toml", ".inp", ".inc"}
# git-ignored folders a local run leaves in the tree (the peers' virtualenv, work
# folders, caches): not the project's text
UNTRACKED = {".venv", ".work", "__pycache__", ".pytest_cache", "node_modules"}


def findings(path, rel, dates=True):
    out = []
    for k, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        if HISTORY.search(ALLOWED.sub("", line)):
            out.append(f"{rel}:{k}: an account of the work: {line.strip()[:90]}")
        if dates and DATE.search(line) and not line.lstrip().startswith("|"):
            out.append(f"{rel}:{k}: a dated line: {line.strip()[:90]}")
    return out


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    problems = []
    readme = (root / "README.md").read_text()
    if len(readme.splitlines()) >= 300:
        problems.append(f"README.md has {len(readme.splitlines())} lines (a guide: < 300)")
    for cmd in ("bash tools/run.sh", "bash tools/test.sh"):
        if cmd not in readme:
            problems.append(f"README.md does not give the set-up command {cmd!r}")
    ci = [ln for ln in (root / ".ci" / "run").read_text().splitlines()
          if ln.strip() and not ln.startswith("#") and not ln.startswith("set ")
          and not ln.startswith("cd ")]
    if ci != ["bash tools/test.sh"]:
        problems.append(f".ci/run runs {ci}, not the README's test command")
    if not (root / "LICENSE").is_file():
        problems.append("no LICENSE")
    files = [root / "README.md"] + [root / d for d in CHECKED_DOCS]
    for top in CHECKED:
        files += [p for p in sorted((root / top).rglob("*"))
                  if p.is_file() and p.suffix in SUFFIXES and "egg-info" not in str(p)
                  and not UNTRACKED & set(p.relative_to(root).parts)]
    # this check and check_no_history.py quote what they look for in their self-tests
    me = {pathlib.Path(__file__).resolve(), pathlib.Path(__file__).resolve().with_name(
        "check_no_history.py")}
    for p in files:
        if p.resolve() not in me:
            problems += findings(p, p.relative_to(root))
    seen = set(files)
    for top in HISTORY_ONLY:
        for p in sorted((root / top).rglob("*")):
            rel = p.relative_to(root)
            if (p.is_file() and p.suffix in SUFFIXES and p not in seen
                    and str(rel) not in PENDING and not UNTRACKED & set(rel.parts)):
                files.append(p)
                problems += findings(p, rel, dates=False)
    for p in problems:
        print("FAIL:", p)
    print(f"{len(files)} files checked, {len(problems)} findings")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
