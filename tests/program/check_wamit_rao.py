#!/usr/bin/env python3
"""tools/wamit_rao.py and the FPSO RAO table it made (input/fpso_rao.csv).

    check_wamit_rao.py TOOLS_DIR INPUT_DIR OUTDIR

1. The converter on 24 rows of the MSS FPSO's fpso.4 (T = 11.48 s; BETA 0, 30, 150, 180;
   numbers from github.com/cybergalactic/MSS HYDRO/vessels_wamit/fpso/fpso.4 at commit
   736a3d12): translations kept, rotations rad/(A/ULEN) -> deg/m (ULEN 1 and 2), phases
   kept (WAMIT's leads), headings 210 and 330 mirrored (sway, roll, yaw turned by 180 deg,
   the rest equal), 0 and 180 not duplicated.
2. The committed table against the RAOs WAMIT printed in fpso.out (same commit) at
   five (period, heading) pairs, six modes each: modulus to its 6 printed digits,
   phase to its printed whole degree.
3. The committed table's long-wave limits (T = 163.88 s, k A = 1.5e-4): heave 1, phase 0;
   surge 1 with the phase of the horizontal particle displacement (-90 deg in following
   seas, +90 in head seas: x = A sin(omega t) lags the crest by a quarter period); pitch
   the wave slope k A (deg/m) leading by 90 deg in following seas; sway and roll the
   same in beam seas (BETA 90) with phases -90.
4. The full grid (58 periods x 36 headings) and the mirror symmetry over all of it.
"""
import math
import os
import subprocess
import sys

ROWS_11_48 = """\
0.114800E+02 0.000000E+00 1 5.970959E-02 -1.384264E+02 -4.466899E-02 -3.962217E-02
0.114800E+02 0.000000E+00 2 0.000000E+00 9.000000E+01 0.000000E+00 0.000000E+00
0.114800E+02 0.000000E+00 3 8.120531E-02 3.655393E+01 6.523195E-02 4.836419E-02
0.114800E+02 0.000000E+00 4 0.000000E+00 9.000000E+01 0.000000E+00 0.000000E+00
0.114800E+02 0.000000E+00 5 1.617732E-02 8.333852E+01 1.876617E-03 1.606810E-02
0.114800E+02 0.000000E+00 6 0.000000E+00 9.000000E+01 0.000000E+00 0.000000E+00
0.114800E+02 0.300000E+02 1 1.443966E-01 -1.132694E+02 -5.704458E-02 -1.326510E-01
0.114800E+02 0.300000E+02 2 1.067531E-01 -9.038811E+01 -7.231164E-04 -1.067506E-01
0.114800E+02 0.300000E+02 3 2.701210E-01 -4.781592E+00 2.691809E-01 -2.251667E-02
0.114800E+02 0.300000E+02 4 5.118493E-03 9.379852E+01 -3.390908E-04 5.107248E-03
0.114800E+02 0.300000E+02 5 1.907521E-02 8.313699E+01 2.279410E-03 1.893853E-02
0.114800E+02 0.300000E+02 6 5.142908E-03 1.795954E+02 -5.142780E-03 3.631483E-05
0.114800E+02 0.150000E+03 1 1.066717E-01 8.879452E+01 2.244164E-03 1.066481E-01
0.114800E+02 0.150000E+03 2 1.091323E-01 -9.311824E+01 -5.936431E-03 -1.089707E-01
0.114800E+02 0.150000E+03 3 4.061221E-01 6.627143E+00 4.034084E-01 4.686962E-02
0.114800E+02 0.150000E+03 4 5.295437E-03 8.261005E+01 6.811073E-04 5.251452E-03
0.114800E+02 0.150000E+03 5 1.778734E-02 -1.080940E+02 -5.524336E-03 -1.690773E-02
0.114800E+02 0.150000E+03 6 5.158915E-03 2.632823E+00 5.153469E-03 2.369761E-04
0.114800E+02 0.180000E+03 1 1.214988E-02 7.487221E+01 3.170788E-03 1.172884E-02
0.114800E+02 0.180000E+03 2 2.848102E-09 -1.053859E+02 -7.556543E-10 -2.746028E-09
0.114800E+02 0.180000E+03 3 2.376836E-01 3.182934E+01 2.019414E-01 1.253522E-01
0.114800E+02 0.180000E+03 4 1.556337E-10 7.960825E+01 2.807284E-11 1.530809E-10
0.114800E+02 0.180000E+03 5 1.550346E-02 -1.082588E+02 -4.857378E-03 -1.472288E-02
0.114800E+02 0.180000E+03 6 2.317683E-10 2.567359E+00 2.315357E-10 1.038180E-11
"""

# fpso.out, "RESPONSE AMPLITUDE OPERATORS": period, heading -> (Mod, Pha) of modes 1..6
PRINTED = {
    (10.44, 180): [(1.21718E-01, -92), (1.91342E-09, 145), (2.07214E-01, 65),
                   (1.17531E-11, -16), (1.07538E-02, -120), (1.57790E-10, 1)],
    (11.48, 150): [(1.06672E-01, 89), (1.09132E-01, -93), (4.06122E-01, 7),
                   (5.29544E-03, 83), (1.77873E-02, -108), (5.15891E-03, 3)],
    (11.48, 30): [(1.44397E-01, -113), (1.06753E-01, -90), (2.70121E-01, -5),
                  (5.11849E-03, 94), (1.90752E-02, 83), (5.14291E-03, 180)],
    (13.91, 90): [(9.64765E-03, -175), (7.04503E-01, -97), (1.14507E+00, -3),
                  (2.00757E-01, -97), (2.96967E-04, 161), (3.81387E-04, 74)],
    (163.88, 0): [(9.98869E-01, -90), (0.0, 90), (9.99974E-01, 0),
                  (0.0, 90), (1.49796E-04, 90), (0.0, 90)],
}

FAILS = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILS.append(what)


def angle_diff(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


def read_table(path):
    rows = {}
    with open(path) as fh:
        for line in fh:
            s = line.strip()
            if not s or s.startswith("#") or s.startswith("period"):
                continue
            v = [float(x) for x in s.split(",")]
            assert len(v) == 14, line
            rows[(round(v[0], 6), round(v[1], 6))] = (v[2:8], v[8:14])
    return rows


def main():
    tools, inputs, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    conv = os.path.join(tools, "wamit_rao.py")
    src = os.path.join(out, "fpso_11_48.4")
    with open(src, "w") as fh:
        fh.write(ROWS_11_48.replace("\n", "\r\n"))  # CRLF as the MSS file has them
    raw = {}
    for line in ROWS_11_48.splitlines():
        p = line.split()
        raw[(float(p[1]), int(p[2]))] = complex(float(p[5]), float(p[6]))

    # 1. the converter on the rows
    worst = 0.0
    for ulen in (1.0, 2.0):
        dst = os.path.join(out, f"fpso_11_48_ulen{ulen:g}.csv")
        subprocess.run([sys.executable, conv, src, "-o", dst, "--ulen", f"{ulen:g}",
                        "--mirror"], check=True)
        t = read_table(dst)
        check(sorted({h for _, h in t}) == [0, 30, 150, 180, 210, 330],
              f"ULEN {ulen:g}: headings 0, 30, 150, 180 and the mirrored 210, 330")
        for (per, beta), (amp, ph) in t.items():
            src_beta = beta if beta <= 180 else 360 - beta
            for k in range(6):
                xi = raw[(src_beta, k + 1)]
                scale = 1.0 if k < 3 else 180.0 / math.pi / ulen
                sign = -1.0 if (beta > 180 and k in (1, 3, 5)) else 1.0
                want = sign * scale * xi
                got = amp[k] * complex(math.cos(math.radians(ph[k])),
                                       math.sin(math.radians(ph[k])))
                worst = max(worst, abs(got - want) / max(abs(want), 1e-300))
    check(worst < 2e-6, f"converted rows = WAMIT's Re, Im (rotations x 180/pi/ULEN, "
          f"mirrored signs): worst relative error {worst:.2e} (table's 7 digits)")

    # 2. the committed table against fpso.out's printed RAOs
    table = read_table(os.path.join(inputs, "fpso_rao.csv"))
    wmod = wph = 0.0
    for (per, beta), printed in PRINTED.items():
        amp, ph = table[(per, beta)]
        for k, (pm, pp) in enumerate(printed):
            a = amp[k] * (math.pi / 180.0 if k >= 3 else 1.0)
            wmod = max(wmod, abs(a - pm) / max(pm, 1e-30) if pm > 0 else a)
            if pm > 1e-6:
                wph = max(wph, angle_diff(ph[k], pp))
    check(wmod < 1e-5, f"moduli against fpso.out (30 values): worst {wmod:.2e} relative")
    check(wph <= 0.5, f"phases against fpso.out (whole degrees): worst {wph:.3f} deg")

    # 3. long-wave limits
    T = 163.88
    k = (2.0 * math.pi / T) ** 2 / 9.81  # deep water, WAMIT's g
    kdeg = math.degrees(k)
    amp0, ph0 = table[(T, 0)]
    amp180, ph180 = table[(T, 180)]
    amp90, ph90 = table[(T, 90)]
    dev = max(abs(amp0[2] - 1), abs(amp180[2] - 1), abs(amp90[2] - 1))
    check(dev < 1e-4, f"heave -> 1 at T = {T} s (headings 0, 90, 180): {dev:.1e} off")
    dph = max(angle_diff(ph0[2], 0), angle_diff(ph180[2], 0), angle_diff(ph90[2], 0))
    check(dph < 0.01, f"heave phase -> 0: {dph:.1e} deg")
    check(abs(amp0[0] - 1) < 2e-3 and abs(amp180[0] - 1) < 2e-3,
          f"surge -> 1 in following and head seas: {amp0[0]:.5f}, {amp180[0]:.5f}")
    check(angle_diff(ph0[0], -90) < 0.1 and angle_diff(ph180[0], 90) < 0.1,
          f"surge phase -90 (following), +90 (head): {ph0[0]:.3f}, {ph180[0]:.3f} deg")
    dp = max(abs(amp0[4] / kdeg - 1), abs(amp180[4] / kdeg - 1))
    check(dp < 1e-3, f"pitch -> wave slope k A = {kdeg:.4e} deg/m: {dp:.1e} off")
    check(angle_diff(ph0[4], 90) < 0.1 and angle_diff(ph180[4], -90) < 0.1,
          f"pitch phase +90 (following), -90 (head): {ph0[4]:.3f}, {ph180[4]:.3f} deg")
    check(abs(amp90[1] - 1) < 2e-3 and angle_diff(ph90[1], -90) < 0.1,
          f"beam seas: sway {amp90[1]:.5f} at {ph90[1]:.3f} deg")
    check(abs(amp90[3] / kdeg - 1) < 2e-3 and angle_diff(ph90[3], -90) < 0.1,
          f"beam seas: roll {amp90[3] / kdeg:.5f} k A at {ph90[3]:.3f} deg")

    # 4. grid and mirror symmetry
    periods = sorted({p for p, _ in table})
    headings = sorted({h for _, h in table})
    check(len(periods) == 58 and len(headings) == 36 and len(table) == 58 * 36
          and headings == [10.0 * i for i in range(36)],
          f"full grid: {len(periods)} periods x {len(headings)} headings 0..350")
    worst_a = worst_p = 0.0
    for (per, beta), (amp, ph) in table.items():
        if beta <= 180:
            continue
        amp_m, ph_m = table[(per, 360 - beta)]
        for k in range(6):
            worst_a = max(worst_a, abs(amp[k] - amp_m[k]))
            if amp[k] > 0:
                turn = 180.0 if k in (1, 3, 5) else 0.0
                worst_p = max(worst_p, angle_diff(ph[k], ph_m[k] + turn))
    check(worst_a == 0.0 and worst_p < 1e-3,
          f"mirror: |RAO| equal, sway/roll/yaw phases turned 180 deg (worst "
          f"{worst_p:.1e} deg) over {len(periods) * 17} (period, heading) pairs")
    if FAILS:
        print(f"{len(FAILS)} check(s) failed")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
