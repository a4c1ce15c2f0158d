#!/usr/bin/env python3
"""Run a command on a deck and check its exit code and error message.

Usage:
    python3 run_expect.py --exit CODE [--expect TEXT] [--no-warning] EXE ARGS... DECK

Runs `EXE ARGS... DECK`, then checks that
  * the exit code is CODE, and
  * stderr contains the text of every `** EXPECT: <text>` line of DECK (and every
    --expect TEXT given), as a plain substring, and
  * with --no-warning, stderr has no ': warning:' (a shipped deck that aliases its
    motion or writes too few frames to catch its extremes warns).
A DECK that does not exist has no EXPECT lines (used to test a missing deck).
Prints what it got on a mismatch. Exits 0 on a match, 1 otherwise.
"""
import argparse
import os
import subprocess
import sys

EXPECT_TAG = "** EXPECT:"
TIMEOUT_S = 120


def deck_expectations(deck):
    """The texts of the deck's `** EXPECT:` lines (none if the deck is missing)."""
    if not os.path.isfile(deck):
        return []
    texts = []
    with open(deck, encoding="utf-8", errors="replace") as f:
        for line in f:
            stripped = line.strip()
            if stripped.upper().startswith(EXPECT_TAG):
                texts.append(stripped[len(EXPECT_TAG):].strip())
    return texts


def main():
    parser = argparse.ArgumentParser(
        description="Run EXE ARGS... DECK; check exit code and ** EXPECT: text in stderr.")
    parser.add_argument("--exit", dest="code", type=int, required=True,
                        help="expected exit code")
    parser.add_argument("--expect", action="append", default=[],
                        help="extra text stderr must contain (repeatable)")
    parser.add_argument("--no-warning", action="store_true",
                        help="fail when rodyn warns (': warning:' in stderr)")
    parser.add_argument("command", nargs=argparse.REMAINDER,
                        help="EXE ARGS... DECK (the deck is the last argument)")
    args = parser.parse_args()
    if len(args.command) < 2:
        parser.error("need EXE and DECK")

    deck = args.command[-1]
    expected = deck_expectations(deck) + args.expect
    try:
        proc = subprocess.run(args.command, capture_output=True, text=True,
                              errors="replace", timeout=TIMEOUT_S)
    except (OSError, subprocess.TimeoutExpired) as exc:
        print(f"FAIL {deck}: could not run {args.command[0]}: {exc}")
        return 1

    problems = []
    if proc.returncode != args.code:
        problems.append(f"exit code {proc.returncode}, expected {args.code}")
    for text in expected:
        if text not in proc.stderr:
            problems.append(f"stderr lacks: {text}")
    if args.no_warning and ": warning:" in proc.stderr:
        problems.append("warns (--no-warning): " + next(
            line for line in proc.stderr.splitlines() if ": warning:" in line))

    if problems:
        print(f"FAIL {deck}")
        print("command: " + " ".join(args.command))
        for p in problems:
            print("  " + p)
        print("---- stdout:\n" + proc.stdout.rstrip())
        print("---- stderr:\n" + proc.stderr.rstrip())
        return 1
    print(f"ok {deck}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
