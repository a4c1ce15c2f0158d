#!/usr/bin/env python3
"""Speed of rodyn-batch: overhead per case, 2 workers against 1, summary of
1000 cases. Prints the figures published in docs/batch.md.

    RODYN_EXE=build/rodyn PYTHONPATH=postproc python3 bench/batch_bench.py [--quick]

1. Overhead per case beyond the run itself: batches of N1 and N2 short cases on one
   worker (the paper cable, 4 elements, 1 s); the slope (T(N2) - T(N1)) / (N2 - N1)
   minus the mean time of the same rodyn runs started alone (subprocess, --quiet)
   is what the batch adds per case (process start-up through the thread, temporary
   folder, command.txt, status.txt, extraction, batch_case.json, rename, lock, log,
   the case's share of the summary). The fixed cost (start-up of the command and
   the summary) is reported apart.
2. Throughput: 100 cases (30 elements, 40 s of motion: ~0.3 s each) with -j 1 and
   -j 2; also 100 of the 1 s cases.
3. Summary of 1000 cases: 1000 case folders made by hard-linking one case's files,
   then `rodyn-batch summary` (a) with the extraction each case stored, (b) with
   `--extract all`, which reads every case's dynamic.h5 again.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from rodyn_post import batch

ROOT = Path(__file__).resolve().parents[1]
INCLUDE = ROOT / "input" / "paper_cable_section.inc"


def deck_text(k: int, elements: int, duration: float) -> str:
    text = (ROOT / "input" / "paper_case1.inp").read_text()
    text = text.replace("INPUT=paper_cable_section.inc", f"INPUT={INCLUDE}")
    text = text.replace("ELEMENTS=30", f"ELEMENTS={elements}")
    text = text.replace("TIME=900.0", f"TIME={duration}")
    amp = 0.1 + 0.3 * (k % 10) / 9
    return text.replace("Z, 0.4, 0.658, 0.0", f"Z, {amp:.4f}, 0.658, 0.0")


def write_decks(folder: Path, n: int, elements: int, duration: float) -> list:
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for k in range(n):
        p = folder / f"c{k:04d}.inp"
        p.write_text(deck_text(k, elements, duration))
        paths.append(p)
    return paths


CPU = {}


def run_batch(pattern: Path, out: Path, jobs: int, rodyn: str) -> float:
    """Wall time of a batch; CPU['self'], CPU['children']: its CPU seconds."""
    r0, c0 = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(
        resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    with contextlib.redirect_stdout(io.StringIO()):
        code = batch.main([str(pattern), "-o", str(out), "-j", str(jobs), "--rodyn", rodyn,
                           "--no-progress"])
    dt = time.perf_counter() - t0
    r1, c1 = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(
        resource.RUSAGE_CHILDREN)
    CPU["self"] = r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime
    CPU["children"] = c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime
    if code != 0:
        raise SystemExit(f"batch failed with exit status {code}")
    return dt


def lone_runs(decks: list, out: Path, rodyn: str) -> float:
    t0 = time.perf_counter()
    for d in decks:
        subprocess.run([rodyn, str(d), "-o", str(out / d.stem), "--quiet"], check=True)
    return time.perf_counter() - t0


def part1(work: Path, args, rodyn: str, n1: int, n2: int):
    """Overhead per case: slope of -j 1 batches of n1 and n2 short cases against the
    same rodyn runs alone. Leaves work/b2_0 (a batch of short cases) for part 3."""
    short = write_decks(work / "short", n2, 4, 1.0)
    sub = work / "short_n1"
    sub.mkdir()
    for d in short[:n1]:
        shutil.copy(d, sub / d.name)
    t_lone = min(lone_runs(short, work / f"lone{r}", rodyn) for r in range(args.repeat))
    t1 = min(run_batch(sub / "c*.inp", work / f"b1_{r}", 1, rodyn)
             for r in range(args.repeat))
    t2 = min(run_batch(work / "short" / "c*.inp", work / f"b2_{r}", 1, rodyn)
             for r in range(args.repeat))
    per_case_batch = (t2 - t1) / (n2 - n1)
    per_case_lone = t_lone / n2
    fixed = t1 - n1 * per_case_batch
    recs = [json.loads(p.read_text()) for p in (work / "b2_0").glob("c*/batch_case.json")]
    ext = statistics.median(r["extract_s"] for r in recs)
    print(f"1. overhead: lone rodyn run {1e3 * per_case_lone:.1f} ms a case; in a batch "
          f"(-j 1) {1e3 * per_case_batch:.1f} ms a case (slope of {n1} -> {n2} cases): "
          f"overhead {1e3 * (per_case_batch - per_case_lone):.1f} ms a case (of it "
          f"extraction {1e3 * ext:.1f} ms, median); fixed cost {1e3 * fixed:.0f} ms")


def part2(work: Path, args, rodyn: str, n_thr: int):
    """Throughput of -j 2 against -j 1."""
    for label, elements, duration in (("0.3 s cases", 30, 40.0), ("short cases", 4, 1.0)):
        decks = write_decks(work / f"thr{elements}", n_thr, elements, duration)
        times, cpu = {}, {}
        for jobs in (1, 2):
            times[jobs] = min(run_batch(decks[0].parent / "c*.inp",
                                        work / f"thr{elements}_j{jobs}_{r}", jobs, rodyn)
                              for r in range(1 if elements == 30 else args.repeat))
            cpu[jobs] = dict(CPU)
        print(f"2. throughput, {n_thr} {label} ({elements} elements, {duration:g} s): "
              f"-j 1 {times[1]:.2f} s, -j 2 {times[2]:.2f} s: "
              f"{times[1] / times[2]:.2f}x; CPU a case: rodyn "
              f"{1e3 * cpu[2]['children'] / n_thr:.1f} ms, batch driver "
              f"{1e3 * cpu[2]['self'] / n_thr:.1f} ms")


def part3(work: Path, rodyn: str, n_sum: int):
    """Summary of n_sum cases made by hard-linking one case's files."""
    if not (work / "b2_0").is_dir():
        write_decks(work / "one", 1, 4, 1.0)
        run_batch(work / "one" / "c*.inp", work / "b2_0", 1, rodyn)
    one = work / "b2_0" / "c0000"
    big = work / "big"
    big.mkdir()
    state = {"cases": [], "parameters": [], "extract": list(batch.DEFAULT_EXTRACT)}
    rec = json.loads((one / "batch_case.json").read_text())
    for k in range(n_sum):
        cid = f"c{k:04d}"
        shutil.copytree(one, big / cid, copy_function=os.link)
        (big / cid / "batch_case.json").unlink()
        rec["id"] = cid
        (big / cid / "batch_case.json").write_text(json.dumps(rec))
        state["cases"].append({"id": cid, "deck": "", "params": {}})
    (big / batch.STATE_FILE).write_text(json.dumps(state))
    t0 = time.perf_counter()
    with contextlib.redirect_stdout(io.StringIO()):
        assert batch.main(["summary", str(big)]) == 0
    t_cached = time.perf_counter() - t0
    t0 = time.perf_counter()
    with contextlib.redirect_stdout(io.StringIO()):
        assert batch.main(["summary", str(big), "--extract", "all"]) == 0
    t_extract = time.perf_counter() - t0
    size = (big / "summary.h5").stat().st_size
    print(f"3. summary of {n_sum} cases: {t_cached:.2f} s from the stored extractions, "
          f"{t_extract:.2f} s extracting every case again from dynamic.h5 "
          f"(summary.h5 {size / 1e6:.1f} MB)")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="smaller counts (a smoke run)")
    ap.add_argument("--repeat", type=int, default=3, help="repeats of each timing (best)")
    ap.add_argument("--only", choices=("overhead", "throughput", "summary"),
                    help="run one part only")
    args = ap.parse_args()
    rodyn = os.environ.get("RODYN_EXE") or shutil.which("rodyn")
    if not rodyn:
        raise SystemExit("set RODYN_EXE")
    n1, n2 = (10, 30) if args.quick else (20, 100)
    n_thr = 20 if args.quick else 100
    n_sum = 100 if args.quick else 1000
    work = Path(tempfile.mkdtemp(prefix="batch_bench_"))
    print(f"rodyn-batch benchmark, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}, work folder {work}")
    try:
        if args.only in (None, "overhead"):
            part1(work, args, rodyn, n1, n2)
        if args.only in (None, "throughput"):
            part2(work, args, rodyn, n_thr)
        if args.only in (None, "summary"):
            part3(work, rodyn, n_sum)
        print(f"load average at the end {os.getloadavg()[0]:.2f} (other processes share "
              "the cores: compare with the number of cores)")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
