#!/usr/bin/env python3
"""The chain - wire - chain example of docs/deck.md (*SEGMENT) is the deck
tests/program/segment_chain_wire.inp, character for character, and runs its statics.

usage: check_doc_example.py RODYN SOURCE_DIR WORK_DIR
"""
import pathlib
import re
import subprocess
import sys


def main():
    rodyn, src, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    deck = (src / "tests" / "program" / "segment_chain_wire.inp").read_text()
    doc = (src / "docs" / "deck.md").read_text()
    blocks = [b for b in re.findall(r"```\n(.*?)```", doc, re.S) if "*SEGMENT, LINE=MOOR" in b]
    if blocks != [deck]:
        print("FAIL: docs/deck.md's *SEGMENT example is not tests/program/segment_chain_wire.inp")
        return 1
    work.mkdir(parents=True, exist_ok=True)
    path = work / "example.inp"
    path.write_text(blocks[0])
    run = subprocess.run([rodyn, str(path), "-o", str(work / "out"), "--quiet"],
                         capture_output=True, text=True, timeout=300)
    status = (work / "out" / "status.txt").read_text() if run.returncode == 0 else ""
    if run.returncode != 0 or "complete = true" not in status:
        print(f"FAIL: the example: exit {run.returncode}: {run.stderr.strip()}")
        return 1
    print("ok: docs/deck.md's *SEGMENT example runs its statics")
    return 0


if __name__ == "__main__":
    sys.exit(main())
