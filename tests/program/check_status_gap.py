#!/usr/bin/env python3
"""status.txt of a dynamic deck stopped between its statics and its dynamics
(docs/output.md, "status.txt").

usage: check_status_gap.py RODYN SOURCE_DIR WORK_DIR MODE

MODE
  gap    the paper's case 1 (4 s) killed with SIGKILL at the first thing its dynamics
         do to the output folder (removing an older checkpoint.h5, before dynamic.h5 and
         the dynamic tables are made): strace injects the signal into that unlink, so
         the kill falls between the statics and the dynamics every time, whatever the
         machine's speed. Then: the static files are there and no dynamic file;
         status.txt says complete = false, status = statics complete, dynamics to run;
         rodyn-batch counts the folder as not complete (and lists its case to run
         again); `rodyn DECK --restart DIR` runs the deck and leaves every CSV table
         byte for byte as an uninterrupted run's, with complete = true. Needs strace
         (ptrace): exit 77 (SKIP) without it.
  poll   the paper's case 1 (900 s, 9000 steps) run five times, its status.txt read
         over and over while it runs (complete = false at every read), and killed
         with SIGKILL as soon as the statics' status.txt has replaced the first one
         or the dynamics have begun (what the run has done decides when, never a
         delay): the kill falls in the gap between statics and dynamics or after it,
         as the machine goes; status.txt then says complete = false, and without
         the dynamic keys (the dynamics not begun) its status is 'statics complete,
         dynamics to run' and there is no dynamic file.
"""
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

SKIP = 77
STATIC = ["static_nodes.csv", "static_elements.csv", "static_reactions.csv",
          "static_lines.csv", "results.h5"]
TO_RUN = "statics complete, dynamics to run"


def fail(msg):
    print(f"FAIL: {msg}", file=sys.stderr)
    sys.exit(1)


def make_deck(src, work, name, time_s):
    """input/paper_case1.inp with its include made absolute and TIME=time_s."""
    text = (src / "input" / "paper_case1.inp").read_text()
    text = text.replace("INPUT=paper_cable_section.inc",
                        f"INPUT={src / 'input' / 'paper_cable_section.inc'}")
    if "TIME=900.0" not in text:
        fail("input/paper_case1.inp has no TIME=900.0 to shorten")
    text = text.replace("TIME=900.0", f"TIME={time_s}")
    deck = work / name
    deck.write_text(text)
    return deck


def read_status(out):
    """status.txt of folder out as a dict (None when missing)."""
    path = out / "status.txt"
    if not path.is_file():
        return None
    keys = {}
    for row in path.read_text().splitlines():
        key, _, value = row.partition(" = ")
        keys[key] = value
    return keys


def dynamic_files(out):
    return sorted(p.name for p in out.glob("dynamic*"))


def kill_in_gap(exe, deck, out):
    """Run deck into out under strace, killed at the unlink of out/checkpoint.h5."""
    target = str(out / "checkpoint.h5")
    cmd = ["strace", "-f", "-qq", "-o", os.devnull, "-P", target,
           "-e", "trace=unlink,unlinkat", "-e", "inject=unlink,unlinkat:signal=SIGKILL",
           str(exe), str(deck), "-o", str(out)]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    # strace ends as its tracee did: killed by the same signal
    if p.returncode not in (-signal.SIGKILL, 128 + signal.SIGKILL):
        fail(f"the run under strace ended with exit {p.returncode}, not killed at the "
             f"removal of {target}: {p.stderr.strip()[-400:]}")


def strace_usable():
    try:
        return subprocess.run(["strace", "-qq", "-o", os.devnull, "true"],
                              capture_output=True, timeout=60).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


def gap(exe, src, work):
    if shutil.which("strace") is None or not strace_usable():
        print("SKIP: strace missing or not allowed to trace (ptrace)")
        sys.exit(SKIP)
    sys.path.insert(0, str(src / "postproc"))
    from rodyn_post.batch_extract import newton_stats, status_complete

    deck = make_deck(src, work, "case1_4s.inp", 4.0)
    ref = work / "uninterrupted"
    p = subprocess.run([str(exe), str(deck), "-o", str(ref)], capture_output=True,
                       text=True, timeout=600)
    if p.returncode != 0 or read_status(ref).get("complete") != "true":
        fail(f"uninterrupted run: exit {p.returncode}: {p.stderr}")

    out = work / "killed"
    kill_in_gap(exe, deck, out)
    missing = [n for n in STATIC if not (out / n).is_file()]
    if missing:
        fail(f"killed in the gap: static files missing: {missing}")
    if dynamic_files(out):
        fail(f"killed in the gap: dynamic files exist already: {dynamic_files(out)}")
    st = read_status(out)
    if st is None:
        fail("killed in the gap: no status.txt")
    if st.get("complete") != "false" or st.get("status") != TO_RUN:
        fail(f"killed between statics and dynamics: status.txt says complete = "
             f"{st.get('complete')}, status = {st.get('status')} (wanted false, '{TO_RUN}')")
    if st.get("load_factor") != "1.0000000000000000E+00":
        fail(f"killed in the gap: load_factor = {st.get('load_factor')}, wanted 1")
    print(f"killed in the gap: status.txt says complete = false, status = {TO_RUN}")
    if status_complete(out) or newton_stats(out)["complete"] != 0:
        fail("rodyn-batch reads the folder killed in the gap as complete")

    # a batch whose case folder was stopped in the gap lists the case to run again
    batch_out = work / "batch"
    env = dict(os.environ, PYTHONPATH=str(src / "postproc"))
    batch = [sys.executable, "-m", "rodyn_post.batch", str(deck), "-o", str(batch_out),
             "--rodyn", str(exe), "--no-progress"]
    p = subprocess.run(batch, env=env, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        fail(f"batch: exit {p.returncode}: {p.stderr}")
    case = batch_out / deck.stem
    listed = subprocess.run(batch + ["--list"], env=env, capture_output=True, text=True)
    if f"{deck.stem}\tskip (complete)\t" not in listed.stdout:
        fail(f"batch --list after a complete batch: {listed.stdout}{listed.stderr}")
    shutil.rmtree(case)
    kill_in_gap(exe, deck, case)
    listed = subprocess.run(batch + ["--list"], env=env, capture_output=True, text=True)
    if f"{deck.stem}\trun\t" not in listed.stdout:
        fail(f"batch --list after the case was killed in the gap: {listed.stdout}"
             f"{listed.stderr}")
    print("rodyn-batch: the case killed in the gap is not complete and runs again")

    # --restart of the folder runs the deck
    p = subprocess.run([str(exe), str(deck), "--restart", str(out)], capture_output=True,
                       text=True, timeout=600)
    if p.returncode != 0:
        fail(f"--restart of the folder killed in the gap: exit {p.returncode}: {p.stderr}")
    if "the dynamics have not started" not in p.stdout:
        fail(f"--restart of the folder killed in the gap: stdout {p.stdout}")
    st = read_status(out)
    if st.get("complete") != "true" or st.get("status") != "complete":
        fail(f"after --restart: status.txt says complete = {st.get('complete')}, "
             f"status = {st.get('status')}")
    tables = sorted(p.name for p in ref.glob("*.csv"))
    if not any(t.startswith("dynamic_") for t in tables):
        fail(f"uninterrupted run: no dynamic tables in {tables}")
    for name in tables:
        if not (out / name).is_file():
            fail(f"after --restart: {name} missing")
        if (out / name).read_bytes() != (ref / name).read_bytes():
            fail(f"after --restart: {name} differs from the uninterrupted run's")
    print(f"--restart ran the deck: {len(tables)} CSV tables byte for byte as the "
          "uninterrupted run's, complete = true")


def poll(exe, src, work, kills=5):
    deck = make_deck(src, work, "case1_900s.inp", 900.0)
    seen = {}
    reads = 0
    for k in range(kills):
        out = work / f"poll_{k}"
        p = subprocess.Popen([str(exe), str(deck), "-o", str(out)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        deadline = time.monotonic() + 600      # a guard against a hung run only
        # status.txt is read at every poll (it is replaced whole, by a rename): it must
        # say complete = false every time; the kill comes once the statics' status.txt
        # has replaced the first one (the statics written) or the dynamics have begun
        while p.poll() is None and time.monotonic() < deadline:
            st = read_status(out)
            if st is not None:
                reads += 1
                if st.get("complete") != "false":
                    p.kill()
                    p.wait()
                    fail(f"run {k}: while it runs, status.txt says complete = "
                         f"{st.get('complete')}, status = {st.get('status')}")
                if st.get("status") != "running" or "dynamic" in st:
                    break
            time.sleep(0.0005)
        p.send_signal(signal.SIGKILL)
        code = p.wait()
        err = p.stderr.read().decode(errors="replace")
        p.stderr.close()
        if code != -signal.SIGKILL:
            fail(f"kill {k}: the run ended (exit {code}) before it was killed: {err}")
        st = read_status(out)
        dyn = dynamic_files(out)
        if st is None or not (out / "static_nodes.csv").is_file():
            fail(f"kill {k}: killed before the statics were written (the 600 s guard)")
        if st.get("complete") != "false":
            fail(f"kill {k}: status.txt says complete = {st.get('complete')}, status ="
                 f" {st.get('status')}, dynamic files {dyn}")
        begun = "dynamic" in st          # the dynamics' first status.txt written
        if not begun and (dyn or st.get("status") != TO_RUN):
            fail(f"kill {k}: status = {st.get('status')} without the dynamic keys, "
                 f"dynamic files {dyn}")
        where = f"{st.get('status')}, dynamics {'begun' if begun else 'not begun'}"
        seen[where] = seen.get(where, 0) + 1
    print(f"{kills} kills once the statics were written, complete = false each time and "
          f"at all {reads} reads of status.txt while running: "
          + "; ".join(f"{n} x {w}" for w, n in sorted(seen.items())))


def main():
    if len(sys.argv) != 5 or sys.argv[4] not in ("gap", "poll"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    exe = pathlib.Path(sys.argv[1]).resolve()
    src = pathlib.Path(sys.argv[2]).resolve()
    work = pathlib.Path(sys.argv[3]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    if sys.argv[4] == "gap":
        gap(exe, src, work)
    else:
        poll(exe, src, work)
    print("OK")


if __name__ == "__main__":
    main()
