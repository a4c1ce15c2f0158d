"""Run rodyn on a deck written from text, for the check_*.py scripts of the test suite."""
import os
import subprocess
import sys


def run_deck(rodyn, text, out, name):
    """Write `text` to OUT/NAME.inp, run rodyn on it into OUT/NAME and return that folder;
    exit the script with FAIL and rodyn's message if rodyn does not exit 0."""
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, name + ".inp")
    with open(path, "w") as f:
        f.write(text)
    res = os.path.join(out, name)
    proc = subprocess.run([rodyn, path, "-o", res, "--quiet"], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: {name}: rodyn exit {proc.returncode}: {proc.stderr.strip()}")
    return res
