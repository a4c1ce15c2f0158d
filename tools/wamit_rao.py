#!/usr/bin/env python3
"""Convert a WAMIT motion-RAO file (.4) to rodyn's *VESSEL, TYPE=RAO table.

    python3 tools/wamit_rao.py fpso.4 -o input/fpso_rao.csv --ulen 1 --mirror \
        --source "cybergalactic/MSS HYDRO/vessels_wamit/fpso/fpso.4 @ <commit>"

WAMIT's conventions (WAMIT User Manual, chapter 3; docs/vessels.md quotes them) and what
this script does with each:

- Columns of the .4 file: PER, BETA, I, |xi|, phase [deg], Re xi, Im xi (one row per
  period, heading and mode I = 1..6). PER is the wave period in seconds when the run's
  IPERIO/IPEROUT is 1 (the default; the FPSO's fpso.out prints "Wave period (sec)"); with
  --frequency the first column is read as omega [rad/s] and turned into a period.
- Nondimensional RAOs: translations (I = 1, 2, 3) per wave amplitude A, rotations
  (I = 4, 5, 6) per A/ULEN [rad]. rodyn wants m/m and deg/m (ROTATION UNITS=DEG): the
  rotations are divided by ULEN and turned into degrees.
- Phases: the output is Re(xi e^{i omega t}) with the incident wave's elevation at the
  origin Re(A e^{i omega t}); delta > 0 leads the wave. That is rodyn's PHASE=LEAD
  (H = R e^{+i eps}, xi = a R cos(omega t + phi + eps)): the phases are written as they are,
  and the deck must say PHASE=LEAD.
- BETA is the direction the waves travel, from the body's +x axis towards +y: 0 =
  following waves (from stern to bow), 180 = head seas: rodyn's relative heading.
- --mirror: a body symmetric about its x-z plane (port-starboard) has at heading -BETA
  (360 - BETA) the RAOs of BETA with sway, roll and yaw of the opposite sign (the mirror
  y -> -y turns those three; surge, heave and pitch are unchanged). Headings 0..180 are
  completed to 0..350 (the headings strictly between 180 and 360 that the file lacks).

Only the standard library is used. The script is run once to make the committed table;
tests/program/check_wamit_rao.py checks it.
"""
import argparse
import cmath
import math
import sys

MODES = 6


def read_wamit4(path, frequency=False):
    """{(period, beta): [complex xi_1..xi_6]} from a .4 file (Re and Im columns)."""
    table = {}
    with open(path) as fh:
        for lineno, line in enumerate(fh, 1):
            parts = line.split()
            if not parts:
                continue
            if len(parts) != 7:
                raise ValueError(f"{path}:{lineno}: expected 7 columns, got {len(parts)}")
            per, beta = float(parts[0]), float(parts[1])
            mode = int(parts[2])
            if not 1 <= mode <= MODES:
                raise ValueError(f"{path}:{lineno}: mode {mode} not in 1..6")
            if per <= 0.0:
                continue  # WAMIT's zero and infinite periods carry no RAO
            if frequency:
                per = 2.0 * math.pi / per
            xi = complex(float(parts[5]), float(parts[6]))
            row = table.setdefault((round(per, 9), round(beta % 360.0, 9)), [None] * MODES)
            row[mode - 1] = xi
    for key, row in table.items():
        if any(x is None for x in row):
            raise ValueError(f"{path}: period {key[0]} s heading {key[1]} deg lacks a mode")
    return table


def to_dimensional(table, ulen):
    """Translations per metre of A; rotations in degrees per metre of A."""
    out = {}
    for key, row in table.items():
        out[key] = [row[k] if k < 3 else row[k] / ulen * 180.0 / math.pi
                    for k in range(MODES)]
    return out


def mirror(table):
    """Add the headings 360 - beta of a port-starboard symmetric body."""
    out = dict(table)
    sign = [1, -1, 1, -1, 1, -1]  # surge, sway, heave, roll, pitch, yaw under y -> -y
    for (per, beta), row in table.items():
        if 0.0 < beta < 180.0:
            mb = round(360.0 - beta, 9)
            if (per, mb) not in table:
                out[(per, mb)] = [s * x for s, x in zip(sign, row)]
    return out


def check_grid(table):
    periods = sorted({p for p, _ in table})
    headings = sorted({b for _, b in table})
    missing = [(p, b) for p in periods for b in headings if (p, b) not in table]
    if missing:
        raise ValueError(f"not a full grid: {len(missing)} (period, heading) pairs "
                         f"missing, first {missing[0]}")
    return periods, headings


def write_table(table, path, header_lines):
    periods, headings = check_grid(table)
    with open(path, "w") as fh:
        for line in header_lines:
            fh.write(f"# {line}\n" if line else "#\n")
        fh.write("period_s, heading_deg, surge_m_m, sway_m_m, heave_m_m, roll_deg_m, "
                 "pitch_deg_m, yaw_deg_m, surge_ph_deg, sway_ph_deg, heave_ph_deg, "
                 "roll_ph_deg, pitch_ph_deg, yaw_ph_deg\n")
        for beta in headings:
            for per in periods:
                row = table[(per, beta)]
                amp = [abs(x) for x in row]
                # a zero RAO gets phase 0 (WAMIT prints 90 for an exact zero)
                ph = [math.degrees(cmath.phase(x)) if abs(x) > 0.0 else 0.0 for x in row]
                vals = [f"{per:.6g}", f"{beta:g}"] + [f"{a:.6e}" for a in amp] + \
                       [f"{p:.4f}" for p in ph]
                fh.write(", ".join(vals) + "\n")
    return periods, headings


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("wamit4", help="WAMIT .4 file (motion RAOs)")
    ap.add_argument("-o", "--output", required=True, help="rodyn RAO table to write")
    ap.add_argument("--ulen", type=float, required=True,
                    help="WAMIT's length scale ULEN [m] (fpso.out: 'Length scale')")
    ap.add_argument("--frequency", action="store_true",
                    help="the first column is omega [rad/s], not the period [s]")
    ap.add_argument("--mirror", action="store_true",
                    help="complete headings 0..180 to 0..350 by port-starboard symmetry")
    ap.add_argument("--source", default="", help="citation written in the header")
    args = ap.parse_args(argv)
    if args.ulen <= 0.0:
        ap.error("--ulen must be > 0")
    table = to_dimensional(read_wamit4(args.wamit4, args.frequency), args.ulen)
    if args.mirror:
        table = mirror(table)
    cmd = "python3 tools/wamit_rao.py " + " ".join(
        a if " " not in a else f'"{a}"' for a in (argv if argv is not None else sys.argv[1:]))
    header = [
        "rodyn *VESSEL, TYPE=RAO table, PHASE=LEAD, ROTATION UNITS=DEG (docs/vessels.md)",
        f"source: {args.source}" if args.source else f"source: {args.wamit4}",
        f"made by: {cmd}",
        "rows: wave period [s], relative heading [deg] (0 following, 180 head seas),",
        "  amplitudes surge, sway, heave [m/m], roll, pitch, yaw [deg/m], their phases",
        "  [deg], leads on the wave crest at the reference point (WAMIT's body origin)",
    ]
    if args.mirror:
        header.append("headings above 180 deg: mirrored from 360 - heading (sway, roll, "
                      "yaw sign changed)")
    periods, headings = write_table(table, args.output, header)
    print(f"{args.output}: {len(periods)} periods {periods[0]:g}-{periods[-1]:g} s, "
          f"{len(headings)} headings {headings[0]:g}-{headings[-1]:g} deg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
