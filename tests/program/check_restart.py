#!/usr/bin/env python3
"""Checkpoint and restart (docs/dynamics.md "Checkpoint and restart"): a run
killed with SIGKILL and continued with `rodyn DECK --restart DIR` leaves the same files
as a run never interrupted: every CSV table byte for byte, every dataset and
attribute of dynamic.h5 and results.h5 equal to the bit (h5py, numpy.array_equal), and
status.txt (but wall_time_s, which counts the continued run only).

The kill is the test hook RODYN_TEST_KILL_AFTER_STEP=N (rodyn raises SIGKILL on itself
once step N has been handed to the writer: a kill at a fixed step, also between a
checkpoint and the next). Decks, from the shipped ones, shortened:

- case 1 (EMC, dt = 0.1 s), 6 s, frames every 0.5 s, CHECKPOINT=1.5: killed after steps
  23, 47 and 59 (the last); killed twice (19, then 43 in the continued run); killed
  after step 7, before the first checkpoint: --restart refused (exit 1);
- case 1 with SCHEME=ALPHA (accelerations in the state), killed after step 37;
- the mooring leg surged in water (cable elements, drag, added mass, seabed contact;
  24 elements, dt = 0.05 s, 2 s, frames every 0.1 s, CHECKPOINT=0.5), killed after 27;
- the same with the dissipative EMC (SCHEME=EMC, RHO INF=0.6: its strain-rate histories
  in the checkpoint), killed after 27, and case 1 with it (RHO INF=0.7), killed after 37;
- the OC3-Hywind spar system (a FREE body on three chains through points; one chain on
  16 elements), 6 s, dt = 0.2 s, frames every 1 s, CHECKPOINT=2: killed after step 17.

Refused with exit 1 and a message naming the cause: a checkpoint continued with another
deck (an amplitude edited), with another --set value, and one written by another build
(its program identity altered in the file).

Usage: check_restart.py RODYN INPUT_DIR WORK_DIR. Exit 0 on success."""
import os
import re
import shutil
import subprocess
import sys

import h5py
import numpy as np

FAILURES = []


def deck(input_dir, work, name, source, subs):
    """Write a shortened copy of a shipped deck (regex substitutions, its *INCLUDE files
    read in place) into work."""
    with open(os.path.join(input_dir, source)) as f:
        text = f.read()
    text = re.sub(r"(?m)^\*INCLUDE, INPUT=(\S+)\n",
                  lambda m: open(os.path.join(input_dir, m.group(1))).read(), text)
    for old, new in subs:
        text, n = re.subn(old, new, text)
        if n != 1:
            sys.exit(f"{source}: {old!r} found {n} times")
    text = re.sub(r"INPUT=(\w)", "INPUT=" + os.path.abspath(input_dir) + r"/\1", text)
    path = os.path.join(work, name + ".inp")
    with open(path, "w") as f:
        f.write(text)
    return path


def run(rodyn, args, kill=None, expect=0):
    env = dict(os.environ)
    env.pop("RODYN_TEST_KILL_AFTER_STEP", None)
    if kill is not None:
        env["RODYN_TEST_KILL_AFTER_STEP"] = str(kill)
    proc = subprocess.run([rodyn] + args + ["--quiet"], capture_output=True, text=True,
                          env=env, timeout=300)
    if proc.returncode != expect:
        FAILURES.append(f"{' '.join(args)} (kill {kill}): exit {proc.returncode}, "
                        f"expected {expect}: {proc.stderr.strip()[-300:]}")
    return proc


def datasets(path):
    """{name: value} of every dataset, and of every attribute as 'object@name' (but
    wall_time_s: the continued run's counts its own part only)."""
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out[name] = obj[()]
        for key, value in obj.attrs.items():
            if key != "wall_time_s":
                out[f"{name}@{key}"] = value

    with h5py.File(path, "r") as f:
        visit("/", f)
        f.visititems(visit)
    return out


def status_lines(path):
    """status.txt without its wall_time_s line."""
    with open(path) as f:
        return [line for line in f if not line.startswith("wall_time_s")]


def same_files(ref, other, tag):
    """Every CSV byte for byte, every HDF5 dataset to the bit; the number compared."""
    n = 0
    for name in sorted(os.listdir(ref)):
        a, b = os.path.join(ref, name), os.path.join(other, name)
        if name == "status.txt" and status_lines(a) != status_lines(b):
            FAILURES.append(f"{tag}: status.txt differs (wall_time_s aside)")
        if name.endswith(".csv"):
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if fa.read() != fb.read():
                    FAILURES.append(f"{tag}: {name} differs from the uninterrupted run's")
            n += 1
        elif name.endswith(".h5") and name != "checkpoint.h5":
            da, db = datasets(a), datasets(b)
            for key, value in da.items():
                if key not in db or not np.array_equal(value, db[key]):
                    FAILURES.append(f"{tag}: {name}:/{key} differs")
                n += 1
            if set(db) != set(da):
                FAILURES.append(f"{tag}: {name}: other datasets {set(db) ^ set(da)}")
    return n


def killed_and_continued(rodyn, path, ref, work, tag, kills):
    out = os.path.join(work, tag)
    shutil.rmtree(out, ignore_errors=True)
    run(rodyn, [path, "-o", out], kill=kills[0], expect=-9)
    for k in kills[1:]:
        run(rodyn, [path, "--restart", out], kill=k, expect=-9)
    run(rodyn, [path, "--restart", out])
    n = same_files(ref, out, tag)
    print(f"{tag}: killed after step(s) {kills}, continued: {n} files and datasets "
          "compared")
    return out


def main():
    rodyn, input_dir, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    case1 = [(r"TIME=900\.0, OUTPUT INTERVAL=0\.1",
              "TIME=6.0, OUTPUT INTERVAL=0.5, CHECKPOINT=1.5")]
    emc = deck(input_dir, work, "case1", "paper_case1.inp", case1)
    alpha = deck(input_dir, work, "case1_alpha", "paper_case1.inp",
                 [(case1[0][0], case1[0][1] + ", SCHEME=ALPHA")])
    surge = deck(input_dir, work, "surge", "mooring_surge.inp",
                 [(r"ELEMENTS=120", "ELEMENTS=24"),
                  (r"TIME=120\.0, OUTPUT INTERVAL=0\.1",
                   "TIME=2.0, OUTPUT INTERVAL=0.1, CHECKPOINT=0.5")])
    surge_ed = deck(input_dir, work, "surge_edmc", "mooring_surge.inp",
                    [(r"ELEMENTS=120", "ELEMENTS=24"),
                     (r"TIME=120\.0, OUTPUT INTERVAL=0\.1",
                      "TIME=2.0, OUTPUT INTERVAL=0.1, CHECKPOINT=0.5, SCHEME=EMC, "
                      "RHO INF=0.6")])
    case1_ed = deck(input_dir, work, "case1_edmc", "paper_case1.inp",
                    [(case1[0][0], case1[0][1] + ", RHO INF=0.7")])
    # a system: the OC3 spar (a FREE body, points, three lines), frames every 5 steps
    spar = deck(input_dir, work, "spar", "oc3_spar.inp",
                [(r"ELEMENTS=60, ORDER=3, ELEMENT=CABLE, POINT A=A1", "ELEMENTS=16, ORDER=3, "
                  "ELEMENT=CABLE, POINT A=A1"),
                 (r"TIME=600\.0, OUTPUT INTERVAL=1\.0",
                  "TIME=6.0, OUTPUT INTERVAL=1.0, CHECKPOINT=2.0")])
    refs = {}
    for path in (emc, alpha, surge, surge_ed, case1_ed, spar):
        ref = os.path.join(work, os.path.basename(path)[:-4] + "_ref")
        shutil.rmtree(ref, ignore_errors=True)
        run(rodyn, [path, "-o", ref])
        refs[path] = ref
    for kill in (23, 47, 59):
        killed_and_continued(rodyn, emc, refs[emc], work, f"emc_kill{kill}", [kill])
    killed_and_continued(rodyn, emc, refs[emc], work, "emc_kill19_43", [19, 43])
    killed_and_continued(rodyn, alpha, refs[alpha], work, "alpha_kill37", [37])
    killed_and_continued(rodyn, surge, refs[surge], work, "surge_kill27", [27])
    killed_and_continued(rodyn, surge_ed, refs[surge_ed], work, "surge_edmc_kill27", [27])
    killed_and_continued(rodyn, case1_ed, refs[case1_ed], work, "case1_edmc_kill37", [37])
    killed_and_continued(rodyn, spar, refs[spar], work, "spar_kill17", [17])

    # killed before the first checkpoint: nothing to continue
    early = os.path.join(work, "emc_kill7")
    shutil.rmtree(early, ignore_errors=True)
    run(rodyn, [emc, "-o", early], kill=7, expect=-9)
    proc = run(rodyn, [emc, "--restart", early], expect=1)
    if "no checkpoint" not in proc.stderr:
        FAILURES.append(f"kill before the first checkpoint: message {proc.stderr!r}")

    # another deck, another parameter, another build: refused, the files untouched
    kept = os.path.join(work, "emc_kill40")
    run(rodyn, [emc, "-o", kept], kill=40, expect=-9)
    before = {n: open(os.path.join(kept, n), "rb").read() for n in os.listdir(kept)
              if n.endswith(".csv")}
    other = deck(input_dir, work, "case1_other", "paper_case1.inp",
                 case1 + [(r"Z, 0\.4, 0\.658", "Z, 0.41, 0.658")])
    proc = run(rodyn, [other, "--restart", kept], expect=1)
    if "another deck" not in proc.stderr:
        FAILURES.append(f"another deck: message {proc.stderr!r}")
    param = os.path.join(work, "case1_param.inp")
    with open(emc) as f, open(param, "w") as g:
        g.write("*PARAMETER\nAMP = 0.4\n" + f.read().replace("Z, 0.4,", "Z, <AMP>,"))
    run(rodyn, [param, "-o", os.path.join(work, "param")], kill=40, expect=-9)
    proc = run(rodyn, [param, "--restart", os.path.join(work, "param"), "--set",
                       "AMP=0.5"], expect=1)
    if "another deck" not in proc.stderr:
        FAILURES.append(f"another --set value: message {proc.stderr!r}")
    with h5py.File(os.path.join(kept, "checkpoint.h5"), "r+") as f:
        text = f["program"].asstr()[()]
        del f["program"]
        f["program"] = text.replace("build ", "build 0")
    proc = run(rodyn, [emc, "--restart", kept], expect=1)
    if "another build" not in proc.stderr:
        FAILURES.append(f"another build: message {proc.stderr!r}")
    after = {n: open(os.path.join(kept, n), "rb").read() for n in before}
    if after != before:
        FAILURES.append("a refused restart changed the files")
    print("refused: killed before the first checkpoint, another deck, another --set "
          "value, another build")
    for f in FAILURES:
        print("FAIL:", f)
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
