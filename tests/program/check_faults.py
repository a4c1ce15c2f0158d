#!/usr/bin/env python3
"""rodyn's output under faults (docs/output.md "Failures and locking").

usage: check_faults.py RODYN SOURCE_DIR WORK_DIR MODE [options]

MODE
  disk-full   the output folder a small tmpfs (sizes 4 KiB ... 4 MiB), a static and a
              dynamic deck: exit 3 (or 0 when everything fitted), no crash, a message
              naming the file, nothing incomplete under a final name (every file under
              a final name equal to a reference run's, or a whole-frame prefix of it for
              the dynamic tables), status.txt true and in step with the files, no
              temporary and no lock left. Needs root (mount): exit 77 (SKIP) otherwise.
  lock        two runs started together into one folder, N times (HDF5=NO and HDF5):
              exactly one runs (exit 0, its files equal to a reference run's), the other
              is refused at once with exit 3 naming the folder; a stale lock (dead
              process) is taken over; a live one refuses; the lock is gone after every
              exit (0, 2, 3).
  stale       temporaries of a killed run are removed by the next run into the folder;
              a run killed (SIGKILL) while it writes (once status.txt says it has
              committed 1, 2000 and 5000 time steps: no fixed delay) leaves status.txt,
              the CSV tables and dynamic.h5 holding the same frames up to the sizes status.txt gives
              (frames, committed_bytes.NAME; a kill inside a sync may leave a tail of
              later rows beyond them), and rodyn_post reads exactly those frames, from
              dynamic.h5 and from the CSV tables alike.
"""
import argparse
import os
import pathlib
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

import numpy as np

SKIP = 77
FINAL_STATIC = ["static_nodes.csv", "static_elements.csv", "static_reactions.csv",
                "static_lines.csv"]
DYN_TABLES = ["dynamic_nodes.csv", "dynamic_elements.csv", "dynamic_ends.csv",
              "dynamic_lines.csv"]
STATUS_KEYS = ["complete", "status", "load_factor", "increments", "iterations",
               "cutbacks", "wall_time_s"]
# the kill points of the stale mode: committed time steps of the long deck
KILL_AFTER_STEPS = (1, 2000, 5000)
SIZES = ["4k", "8k", "16k", "32k", "64k", "128k", "256k", "512k", "1m", "4m"]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def make_deck(src, work, name, time_s, hdf5=True, interval=None):
    """input/paper_case1.inp with TIME=time_s (the include made absolute) and, when given,
    OUTPUT INTERVAL=interval."""
    text = (src / "input" / "paper_case1.inp").read_text()
    inc = (src / "input" / "paper_cable_section.inc").resolve()
    text = text.replace("INPUT=paper_cable_section.inc", f"INPUT={inc}")
    text = re.sub(r"TIME=900\.0", f"TIME={time_s}", text)
    if interval is not None:
        text = re.sub(r"OUTPUT INTERVAL=[0-9.]+", f"OUTPUT INTERVAL={interval}", text)
    if not hdf5:
        text = text.replace("*OUTPUT, CSV=YES, HDF5=YES", "*OUTPUT, CSV=YES, HDF5=NO")
    path = work / name
    path.write_text(text)
    return path


def run(exe, deck, out, timeout=120):
    p = subprocess.run([str(exe), str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stderr


def read_status(path):
    """status.txt as a dict; fails on a file that is not whole."""
    text = path.read_text()
    if not text.endswith("\n"):
        fail(f"{path}: status.txt does not end with a line feed (not whole)")
    st = {}
    for line in text.splitlines():
        if " = " not in line:
            fail(f"{path}: malformed line {line!r}")
        k, v = line.split(" = ", 1)
        st[k] = v
    for k in STATUS_KEYS + ["rodyn_version", "deck"]:
        if k not in st:
            fail(f"{path}: key {k} missing (status.txt not whole)")
    return st


def frames(text):
    """(time, rows) of each frame of a dynamic table's text, in order."""
    out = []
    for line in text.splitlines()[1:]:
        t = line.split(",", 1)[0]
        if out and out[-1][0] == t:
            out[-1][1] += 1
        else:
            out.append([t, 1])
    return out


def h5_check(path, ref_path, h5py):
    """A results.h5 or dynamic.h5 under its final name opens and holds the reference's
    datasets (dynamic series: a prefix of the reference's frames). Returns the last
    frame time of /dynamic/time (None for a static file)."""
    last = None
    try:
        f = h5py.File(path, "r", locking=False)
    except Exception as e:       # noqa: BLE001
        fail(f"{path}: does not open ({e})")
    with f, h5py.File(ref_path, "r", locking=False) as r:
        names = []
        r.visit(names.append)
        for n in names:
            if n not in f:
                fail(f"{path}: {n} missing")
            if isinstance(r[n], h5py.Dataset) and r[n].dtype.kind == "f":
                a, b = f[n][()], r[n][()]
                if getattr(a, "shape", ()) and a.shape != b.shape:
                    if not n.startswith("dynamic/") or a.shape[1:] != b.shape[1:] or \
                            (a != b[:a.shape[0]]).any():
                        fail(f"{path}: {n} is not a prefix of the reference's")
                elif n.startswith("static/") and (a != b).any():
                    fail(f"{path}: {n} differs from the reference")
        if "dynamic/time" in f:
            t = f["dynamic/time"][()]
            last = float(t[-1]) if len(t) else None
    return last


def check_folder(out, ref, code, stderr, h5py):
    """Everything under a final name in `out` is whole and true (see the module doc)."""
    names = sorted(p.name for p in out.iterdir()) if out.exists() else []
    for n in names:
        if n.endswith(".tmp") or n == ".rodyn.lock":
            fail(f"{out}: {n} left behind")
    if code == 3 and str(out) not in stderr:
        fail(f"exit 3 without a message naming a file in {out}: {stderr!r}")
    st = read_status(out / "status.txt") if "status.txt" in names else None
    if code == 0:
        if st is None or st["complete"] != "true":
            fail(f"{out}: exit 0 without status.txt complete = true")
        for n in sorted(p.name for p in ref.iterdir()):
            if n not in names:
                fail(f"{out}: exit 0 but {n} missing")
    elif st is not None and st["complete"] != "false":
        fail(f"{out}: exit {code} but status.txt says complete = {st['complete']}")
    for n in FINAL_STATIC:
        if n in names and (out / n).read_bytes() != (ref / n).read_bytes():
            fail(f"{out}/{n}: differs from the reference (incomplete under its final name)")
    if "results.h5" in names:
        h5_check(out / "results.h5", ref / "results.h5", h5py)
    dyn = st is not None and st.get("dynamic") == "true"
    last_frame = None
    for n in DYN_TABLES + ["dynamic_log.csv"]:
        if n not in names:
            continue
        if st is not None and not dyn:
            fail(f"{out}/{n}: a dynamic table but status.txt has no dynamic keys")
        text = (out / n).read_text()
        reft = (ref / n).read_text()
        if not reft.startswith(text) or not text.endswith("\n"):
            fail(f"{out}/{n}: not a whole-row prefix of the reference's")
        size = st.get("committed_bytes." + n) if dyn else None
        if size is not None and int(size) != len(text.encode()):
            fail(f"{out}/{n}: {len(text.encode())} bytes, status.txt says {size} committed")
        if n == "dynamic_log.csv":
            if dyn and len(text.splitlines()) - 1 != int(st["steps"]):
                fail(f"{out}/{n}: {len(text.splitlines()) - 1} steps, status.txt says "
                     f"{st['steps']}")
            continue
        fr, rf = frames(text), dict((t, k) for t, k in frames(reft))
        if fr and fr[-1][1] != rf[fr[-1][0]]:
            fail(f"{out}/{n}: last frame cut short")
        t = float(fr[-1][0]) if fr else None
        if last_frame is not None and t != last_frame:
            fail(f"{out}: the dynamic tables end at different frames")
        last_frame = t
    if dyn:
        reached = float(st["time_reached_s"])
        if last_frame is not None and last_frame != reached:
            fail(f"{out}: tables end at t = {last_frame}, status.txt says {reached}")
        if last_frame is None and any(n in names for n in DYN_TABLES) and reached != 0.0:
            fail(f"{out}: no frame in the tables, status.txt says t = {reached}")
    if "dynamic.h5" in names:
        t = h5_check(out / "dynamic.h5", ref / "dynamic.h5", h5py)
        if dyn and t is not None and t != float(st["time_reached_s"]):
            fail(f"{out}/dynamic.h5 ends at t = {t}, status.txt says "
                 f"{st['time_reached_s']}")
    return st


def big_static(src, work):
    """input/paper_cable.inp with 2500 elements: 4.4 MB of output, more than 4 MiB."""
    text = (src / "input" / "paper_cable.inp").read_text()
    inc = (src / "input" / "paper_cable_section.inc").resolve()
    text = text.replace("INPUT=paper_cable_section.inc", f"INPUT={inc}")
    text = text.replace("ELEMENTS=10,", "ELEMENTS=2500,")
    path = work / "big_static.inp"
    path.write_text(text)
    return path


def disk_full(exe, src, work, sizes, big):
    if os.geteuid() != 0:
        print("SKIP: mounting a tmpfs needs root")
        sys.exit(SKIP)
    import h5py
    decks = {"static": src / "input" / "paper_cable.inp",
             "dynamic": make_deck(src, work, "case1_short.inp", 2.0)}
    if big:      # every size too small: exit 3 each time
        decks = {"static": big_static(src, work),
                 "dynamic": make_deck(src, work, "case1_120s.inp", 120.0)}
    mnt = work / "mnt"
    mnt.mkdir(exist_ok=True)
    probe = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4k", "tmpfs", str(mnt)],
                           capture_output=True, text=True)
    if probe.returncode != 0:
        print(f"SKIP: cannot mount a tmpfs: {probe.stderr.strip()}")
        sys.exit(SKIP)
    subprocess.run(["umount", str(mnt)], check=True)
    counts = {"exit 3": 0, "exit 0": 0}
    for kind, deck in decks.items():
        ref = work / f"ref_{kind}"
        shutil.rmtree(ref, ignore_errors=True)
        code, err = run(exe, deck, ref)
        if code != 0:
            fail(f"reference run of {deck}: exit {code}: {err}")
        for size in sizes:
            subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(mnt)],
                           check=True)
            try:
                out = mnt / "out"
                code, err = run(exe, deck, out)
                if code not in (0, 3):
                    fail(f"{kind} at {size}: exit {code} (a signal or a wrong status): "
                         f"{err[-500:]}")
                check_folder(out, ref, code, err, h5py)
                if big and code != 3:
                    fail(f"{kind} at {size}: exit {code}, the output does not fit")
                counts[f"exit {code}"] += 1
                print(f"{kind:8s} {size:>5s}: exit {code}  "
                      f"{err.strip().splitlines()[-1] if err.strip() else ''}")
            finally:
                subprocess.run(["umount", str(mnt)], check=True)
    print(f"disk full: {len(sizes)} sizes x static and dynamic: {counts}, "
          "nothing incomplete under a final name, no crash")


def two_runs(exe, deck, out):
    shutil.rmtree(out, ignore_errors=True)
    t0 = time.monotonic()
    a = subprocess.Popen([str(exe), str(deck), "-o", str(out), "--quiet"],
                         stderr=subprocess.PIPE, text=True)
    b = subprocess.Popen([str(exe), str(deck), "-o", str(out), "--quiet"],
                         stderr=subprocess.PIPE, text=True)
    res = []
    for p in (a, b):
        _, err = p.communicate(timeout=120)
        res.append((p.returncode, err, time.monotonic() - t0))
    return res


def lock(exe, src, work, n):
    import h5py
    host = socket.gethostname()
    for hdf5 in (False, True):
        deck = make_deck(src, work, f"lock_{int(hdf5)}.inp", 6.0, hdf5=hdf5)
        ref = work / f"ref_lock_{int(hdf5)}"
        shutil.rmtree(ref, ignore_errors=True)
        code, err = run(exe, deck, ref)
        if code != 0:
            fail(f"reference run: exit {code}: {err}")
        refused = 0
        for i in range(n):
            out = work / "shared"
            res = two_runs(exe, deck, out)
            codes = sorted(r[0] for r in res)
            if codes != [0, 3]:
                fail(f"HDF5={hdf5} pair {i}: exits {[r[0] for r in res]}, "
                     f"stderr {[r[1][-300:] for r in res]}")
            loser = [r for r in res if r[0] == 3][0]
            winner = [r for r in res if r[0] == 0][0]
            if "is in use by another rodyn run" not in loser[1] or str(out) not in loser[1]:
                fail(f"refused run without a clear message: {loser[1]!r}")
            check_folder(out, ref, 0, winner[1], h5py)
            for name in FINAL_STATIC + DYN_TABLES + ["dynamic_log.csv"]:
                if (out / name).read_bytes() != (ref / name).read_bytes():
                    fail(f"HDF5={hdf5} pair {i}: {name} differs from a single run's")
            refused += 1
        print(f"two runs into one folder, HDF5={'YES' if hdf5 else 'NO'}: "
              f"refused {refused} of {n}")
    deck = src / "input" / "paper_cable.inp"
    out = work / "stale_lock"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir()
    dead = subprocess.Popen(["true"])
    dead.wait()
    (out / ".rodyn.lock").write_text(f"{dead.pid} {host}\n")
    code, err = run(exe, deck, out)
    if code != 0 or (out / ".rodyn.lock").exists():
        fail(f"stale lock (process {dead.pid} gone) not taken over: exit {code} {err!r}")
    (out / ".rodyn.lock").write_text(f"{os.getpid()} {host}\n")
    code, err = run(exe, deck, out)
    if code != 3 or str(os.getpid()) not in err:
        fail(f"a live lock did not refuse the run: exit {code} {err!r}")
    if (out / ".rodyn.lock").read_text() != f"{os.getpid()} {host}\n":
        fail("the refused run touched the other run's lock")
    (out / ".rodyn.lock").unlink()
    print("stale lock taken over, live lock refused")
    for name, want in (("partial.inp", 2), ("dynamic_fail.inp", 2)):
        out = work / f"unlock_{name}"
        code, err = run(exe, src / "tests" / "program" / name, out)
        if code != want or (out / ".rodyn.lock").exists():
            fail(f"{name}: exit {code} (wanted {want}), lock left: "
                 f"{(out / '.rodyn.lock').exists()}")
    print("lock removed after exit 2")


def check_committed(out, st, h5py, src):
    """The files of a killed run hold what status.txt says was committed: each CSV table
    at least committed_bytes.NAME bytes, whose part ends with a whole row and the frame
    at time_reached_s (the nodes table: `frames` frames; the log: `steps` rows); beyond
    it at most an uncommitted tail of later rows. dynamic.h5 holds at least those frames
    and steps. rodyn_post reads exactly the committed frames and steps, from dynamic.h5
    and from the CSV tables alike, with the same values. Returns whether a tail was
    found."""
    reached, steps, nframes = float(st["time_reached_s"]), int(st["steps"]), int(st["frames"])
    tail = False
    for n in DYN_TABLES + ["dynamic_log.csv", "dynamic_ends_step.csv"]:
        key = "committed_bytes." + n
        if key not in st:
            fail(f"killed run: status.txt has no {key}")
        data, size = (out / n).read_bytes(), int(st[key])
        if len(data) < size:
            fail(f"killed run: {n} has {len(data)} bytes, status.txt says {size} committed")
        text, rest = data[:size].decode(), data[size:].decode()
        tail = tail or bool(rest)
        if not text.endswith("\n"):
            fail(f"killed run: the committed part of {n} does not end with a whole row")
        rows, later = text.splitlines()[1:], rest.splitlines(keepends=True)
        later = [r for r in later if r.endswith("\n")]   # a last row may be cut short
        col = 1 if n in ("dynamic_log.csv", "dynamic_ends_step.csv") else 0
        if n == "dynamic_log.csv":
            if len(rows) != steps:
                fail(f"killed run: dynamic_log.csv has {len(rows)} committed steps, "
                     f"status.txt {steps}")
        elif n != "dynamic_ends_step.csv":
            fr = frames(text)
            if not fr or float(fr[-1][0]) != reached:
                fail(f"killed run: the committed part of {n} ends at "
                     f"{fr[-1][0] if fr else 'no frame'}, status.txt says {reached}")
            if n == "dynamic_nodes.csv" and len(fr) != nframes:
                fail(f"killed run: {n} holds {len(fr)} committed frames, status.txt "
                     f"{nframes}")
        last = float(rows[-1].split(",")[col]) if rows else -1.0
        for r in later:
            if float(r.split(",")[col]) <= last:
                fail(f"killed run: {n}: a row after the committed part is not later "
                     f"({r[:40]!r})")
    with h5py.File(out / "dynamic.h5", "r", locking=False) as f:
        t, step = f["dynamic/time"][()], f["dynamic/log/step"][()]
        if len(t) < nframes or float(t[nframes - 1]) != reached or len(step) < steps:
            fail(f"killed run: dynamic.h5 holds {len(t)} frames and {len(step)} steps, "
                 f"status.txt says {nframes} up to t = {reached} and {steps}")
    sys.path.insert(0, str(src / "postproc"))
    from rodyn_post import load_dynamic
    csv_only = out.parent / (out.name + "_csv")
    shutil.rmtree(csv_only, ignore_errors=True)
    shutil.copytree(out, csv_only, ignore=shutil.ignore_patterns("dynamic.h5"))
    for res in (load_dynamic(out), load_dynamic(csv_only)):
        if (len(res.time) != nframes or float(res.time[-1]) != reached
                or len(res.log) != steps):
            fail(f"killed run: rodyn_post reads {len(res.time)} frames to "
                 f"t = {res.time[-1]} and {len(res.log)} steps from {res.source.name}, "
                 f"status.txt says {nframes}, {reached}, {steps}")
    a, b = load_dynamic(out), load_dynamic(csv_only)
    if not all(np.array_equal(la.x, lb.x) and np.array_equal(la.reactions, lb.reactions)
               for la, lb in zip(a.lines, b.lines)):
        fail("killed run: dynamic.h5 and the CSV tables read differently")
    shutil.rmtree(csv_only)
    return tail


def stale(exe, src, work):
    import h5py
    deck = make_deck(src, work, "stale.inp", 2.0)
    ref = work / "ref_stale"
    shutil.rmtree(ref, ignore_errors=True)
    code, err = run(exe, deck, ref)
    if code != 0:
        fail(f"reference run: exit {code}: {err}")
    out = work / "stale"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir()
    junk = [".results.h5.tmp", ".static_nodes.csv.tmp", ".status.txt.tmp",
            ".dynamic.h5.tmp", ".static_elements.csv.tmp", ".environment.csv.tmp"]
    for j in junk:
        (out / j).write_text("left by a killed run\n")
    code, err = run(exe, deck, out)
    if code != 0:
        fail(f"run into a folder with stale temporaries: exit {code}: {err}")
    left = [j for j in junk if (out / j).exists()]
    if left:
        fail(f"stale temporaries not removed: {left}")
    check_folder(out, ref, 0, err, h5py)
    print(f"{len(junk)} stale temporaries removed by the next run")
    # kill -9 while the run writes: status.txt, CSV tables and dynamic.h5 agree.
    # When to kill is decided by what the run has done, never by the clock: the test
    # watches status.txt and kills once it has committed the given number of time steps.
    # The deck has 10^6 steps (TIME=1e5 s at DT=0.1 s), so that no machine finishes it in
    # the moment between reading status.txt and the kill; frames every 10 steps keep
    # the files small. status.txt moves at each sync (docs/output.md: at the first frame,
    # every 1024 step rows, or after a second of wall time), so the three kills fall at
    # the first sync after a step, near step 2048 and near step 5120, whatever the machine's speed.
    long_deck = make_deck(src, work, "killed.inp", 1.0e5, interval=1.0)
    agree = 0
    for k, target in enumerate(KILL_AFTER_STEPS):
        out = work / f"killed_{k}"
        shutil.rmtree(out, ignore_errors=True)
        p = subprocess.Popen([str(exe), str(long_deck), "-o", str(out), "--quiet"],
                             stderr=subprocess.DEVNULL)
        seen = wait_for_steps(p, out / "status.txt", target)
        p.send_signal(signal.SIGKILL)
        p.wait()
        if seen is None:
            fail(f"killed run: the run ended (exit {p.returncode}) before it committed "
                 f"{target} steps")
        st = read_status(out / "status.txt")
        if st["complete"] != "false" or st["status"] != "running":
            fail(f"killed run: status.txt says complete = {st['complete']}, "
                 f"status = {st['status']}")
        if int(st["steps"]) < target:
            fail(f"killed run: status.txt says {st['steps']} steps after {seen} were seen")
        tail = check_committed(out, st, h5py, src)
        agree += 1
        print(f"killed once {seen} steps were committed (wanted {target}): status.txt, "
              f"tables and dynamic.h5 end at t = {st['time_reached_s']} s, "
              f"{st['steps']} steps, {st['frames']} frames"
              f" ({'an uncommitted tail after them' if tail else 'no tail'})")
        # the next run into the folder cleans up and runs
        code, err = run(exe, deck, out)
        if code != 0:
            fail(f"run after a killed one: exit {code}: {err}")
    print(f"killed runs: files and status.txt agree in {agree} of {len(KILL_AFTER_STEPS)}")


def wait_for_steps(p, status, target):
    """Polls status (status.txt of the running process p) until it says `steps` >= target
    and returns that count; None when p ends first. status.txt is replaced whole by a
    rename, so a read sees one version or another; a folder not yet made, or a status
    without a steps line (statics), reads as no steps."""
    while p.poll() is None:
        try:
            m = re.search(r"^steps = (\d+)$", status.read_text(), re.M)
        except OSError:
            m = None
        if m and int(m.group(1)) >= target:
            return int(m.group(1))
        time.sleep(0.002)
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("src")
    ap.add_argument("work")
    ap.add_argument("mode", choices=["disk-full", "lock", "stale"])
    ap.add_argument("--sizes", default=",".join(SIZES))
    ap.add_argument("--pairs", type=int, default=10)
    ap.add_argument("--big", action="store_true",
                    help="disk-full with decks whose output exceeds 4 MiB (a benchmark)")
    a = ap.parse_args()
    exe = pathlib.Path(a.exe).resolve()
    src = pathlib.Path(a.src).resolve()
    work = pathlib.Path(a.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    if a.mode == "disk-full":
        disk_full(exe, src, work, a.sizes.split(","), a.big)
    elif a.mode == "lock":
        lock(exe, src, work, a.pairs)
    else:
        stale(exe, src, work)
    print("OK")


if __name__ == "__main__":
    tempfile.tempdir = None
    main()
