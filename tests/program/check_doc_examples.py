#!/usr/bin/env python3
"""The deck examples of docs/deck.md read and run.

Every complete deck among the doc's code blocks (one with a *LINE and a *BOUNDARY card)
is written to a folder of its own with the files it includes, each the code block the doc
introduces as "with `PATH`", and run: a deck without *DYNAMIC to the end of its statics
(status.txt complete = true), a dynamic one with --check. The chain - wire - chain example
of *SEGMENT is also the deck tests/program/segment_chain_wire.inp, character for
character (segment_chain_wire_rod.inp is that leg as rod elements).

usage: check_doc_examples.py RODYN SOURCE_DIR WORK_DIR
"""
import pathlib
import re
import subprocess
import sys

MIN_DECKS = 3  # the SCR of "Complete example", the paper's case 1, the *SEGMENT leg


def blocks_with_offsets(doc):
    """(offset, text) of every fenced code block without a language tag."""
    return [(m.start(), m.group(1)) for m in re.finditer(r"```\n(.*?)```", doc, re.S)]


def is_complete(text):
    cards = [ln.split(",")[0].strip().upper() for ln in text.splitlines()
             if ln.startswith("*") and not ln.startswith("**")]
    return "*LINE" in cards and "*BOUNDARY" in cards


def included_files(doc, blocks, text):
    """{path: text} of the deck's *INCLUDE files, from the block after "with `path`"."""
    files = {}
    for path in re.findall(r"^\*INCLUDE,\s*INPUT=(\S+)\s*$", text, re.M | re.I):
        intro = doc.find(f"with `{path}`")
        after = [b for off, b in blocks if intro >= 0 and off > intro]
        if not after:
            raise LookupError(f"no block of docs/deck.md introduced as 'with `{path}`'")
        files[path] = after[0]
    return files


def run_deck(rodyn, folder, text, files):
    """'' when the deck in folder runs as meant, else what went wrong."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "example.inp").write_text(text)
    for path, body in files.items():
        (folder / path).parent.mkdir(parents=True, exist_ok=True)
        (folder / path).write_text(body)
    dynamic = re.search(r"^\*DYNAMIC\b", text, re.M | re.I) is not None
    cmd = [rodyn, "--quiet"] + (["--check"] if dynamic else []) + ["example.inp", "-o", "out"]
    run = subprocess.run(cmd, cwd=folder, capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        return f"{' '.join(cmd[1:])}: exit {run.returncode}: {run.stderr.strip()}"
    if not dynamic:
        status = (folder / "out" / "status.txt").read_text()
        if "complete = true" not in status:
            return "statics not complete: " + status
    return ""


def main():
    rodyn = str(pathlib.Path(sys.argv[1]).resolve())
    src, work = pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    doc = (src / "docs" / "deck.md").read_text()
    blocks = blocks_with_offsets(doc)
    problems = []
    segment = [b for _, b in blocks if "*SEGMENT, LINE=MOOR" in b]
    deck = (src / "tests" / "program" / "segment_chain_wire.inp").read_text()
    if segment != [deck]:
        problems.append("docs/deck.md's *SEGMENT example is not "
                        "tests/program/segment_chain_wire.inp")
    decks = [(off, b) for off, b in blocks if is_complete(b)]
    if len(decks) < MIN_DECKS:
        problems.append(f"{len(decks)} complete decks found in docs/deck.md, expected at "
                        f"least {MIN_DECKS}")
    for k, (off, text) in enumerate(decks):
        where = f"docs/deck.md:{doc.count(chr(10), 0, off) + 1}"
        try:
            why = run_deck(rodyn, work / f"deck{k}", text, included_files(doc, blocks, text))
        except LookupError as exc:
            why = str(exc)
        if why:
            problems.append(f"{where}: {why}")
        else:
            print(f"ok: {where}")
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
