#!/usr/bin/env python3
"""Structural damping of a section (*SECTION AXIAL DAMPING RATIO, BENDING DAMPING) in a
dynamic EMC run: the energy log books its dissipation as damping work.

1. The deck as given: no step breaks the energy balance, total - work in + damping work
   changes over any one step by at most TOL (default 1e-6, check_energy_balance.py's)
   times the largest work done on the line; the damping work never decreases (every
   step dissipates, to round-off) and reaches more than 1e-4 of the largest work (the
   damping acts).
2. With the deck's damping parameters set to 0 (--set NAME=0) the run writes the same
   CSV tables, byte for byte, as the deck with the damping parameters removed from its
   *SECTION line: zero damping changes nothing.

Usage: check_structural_damping.py RODYN DECK OUT_DIR NAME[,NAME...] [TOL]
(NAME: the deck's *PARAMETER names of the damping values). Exit 0 on success."""
import csv
import filecmp
import os
import re
import subprocess
import sys


def run(rodyn, deck, out, extra=()):
    proc = subprocess.run([rodyn, deck, "-o", out, "--quiet", *extra],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: rodyn {deck} exit {proc.returncode}: {proc.stderr.strip()}")
    with open(os.path.join(out, "dynamic_log.csv")) as f:
        return list(csv.DictReader(f))


def balance(rows, tol):
    """Failures of the damped run's energy balance and damping work, as text."""
    work_in = [float(r["external_work_J"]) + float(r["hydro_work_J"])
               + float(r["seabed_work_J"]) for r in rows]
    damp = [float(r["damping_work_J"]) for r in rows]
    bal = [float(r["total_J"]) - w + d for r, w, d in zip(rows, work_in, damp)]
    work = max(abs(w) for w in work_in) or max(float(r["kinetic_J"]) for r in rows)
    jump = max(abs(b - a) for a, b in zip(bal, bal[1:]))
    least = min(b - a for a, b in zip(damp, damp[1:]))
    print(f"{len(rows)} steps; largest one-step change of the balance {jump:.3g} J, "
          f"largest work {work:.3g} J, ratio {jump / work:.2e}; damping work "
          f"{damp[-1]:.4g} J ({damp[-1] / work:.2e} of the work), least step {least:.3g} J")
    fails = []
    if jump > tol * work:
        fails.append(f"energy balance {jump / work:.2e} of the work > {tol}")
    if least < -1e-12 * damp[-1]:
        fails.append(f"the damping work decreased by {-least:.3g} J in a step")
    if not damp[-1] > 1e-4 * work:
        fails.append(f"damping work {damp[-1]:.3g} J is not above 1e-4 of the work")
    return fails


def main():
    rodyn, deck, out, names = sys.argv[1:5]
    tol = float(sys.argv[5]) if len(sys.argv) > 5 else 1e-6
    names = names.split(",")
    fails = balance(run(rodyn, deck, os.path.join(out, "damped")), tol)
    # zero damping by --set against the deck without the damping parameters
    zero = os.path.join(out, "zero")
    run(rodyn, deck, zero, [a for n in names for a in ("--set", f"{n}=0")])
    with open(deck) as f:
        text = f.read()
    plain_text = text
    for n in names:
        plain_text = re.sub(r",\s*[A-Z ]+=<" + n + ">", "", plain_text)
    if plain_text == text or any(f"<{n}>" in plain_text for n in names):
        sys.exit("FAIL: the damping parameters were not found on the *SECTION line")
    plain_deck = os.path.join(out, "plain.inp")
    os.makedirs(out, exist_ok=True)
    with open(plain_deck, "w") as f:
        f.write(plain_text)
    plain = os.path.join(out, "plain")
    run(rodyn, plain_deck, plain)
    tables = sorted(n for n in os.listdir(plain) if n.endswith(".csv"))
    differ = [n for n in tables if not filecmp.cmp(os.path.join(zero, n),
                                                   os.path.join(plain, n), shallow=False)]
    print(f"zero damping against none: {len(tables)} CSV tables compared, "
          f"{len(differ)} differ {differ}")
    if differ or not tables:
        fails.append("zero damping changed " + ", ".join(differ or ["(no tables)"]))
    print("FAIL: " + "; ".join(fails) if fails else "PASS")
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
