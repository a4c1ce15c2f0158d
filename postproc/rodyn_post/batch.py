"""rodyn-batch: run a load-case matrix of rodyn decks and boil it down to one summary.

    rodyn-batch [run] DECK [DECK ...] -o OUT [--cases TABLE.csv | --grid NAME=v1,v2 ...]
                [--set NAME=VALUE ...] [-j N | --scheduler ADDRESS [--retries N]]
                [--timeout S] [--rodyn PATH] [--extract LIST] [--force] [--no-progress]
    rodyn-batch summary OUT [--extract LIST]
    rodyn-batch plot OUT (--y COLUMN --x PARAM [--by PARAM] | --envelope Q) [-o PNG]
    rodyn-batch compare OUT REFDIR (--at WHERE | --range STAT) [--quantity Q] ...

Cases (docs/batch.md): decks given by name or glob (one case each, id = file name
without extension); or ONE parameterised deck (*PARAMETER) with a case table
(--cases: CSV with an `id` column and one column per parameter) or a grid (--grid
NAME=v1,v2,...: the product of the lists, ids like `N=10_DT=0.1`). --set NAME=VALUE
gives a parameter to every case. Each case runs
`rodyn DECK -o <temporary> [--set NAME=VALUE ...]`, logged in OUT/<id>/command.txt
and OUT/batch.log, and ends up in OUT/<id>.

Executors: local threads each running one rodyn process (-j N, default the number of
cores), or a Dask distributed cluster (--scheduler ADDRESS; rodyn, the decks and OUT
on a file system shared by the workers; a worker lost mid-case has the case run again
elsewhere).

A second run skips the cases whose folder holds complete results of the same deck
text (includes expanded) and parameters (a hash in OUT/<id>/batch_case.json), and
runs the others (--force: all). Ctrl-C stops the batch: finished cases stay as they
are, running ones are killed and leave nothing.

Writes OUT/summary.csv and OUT/summary.h5: a row per case with its parameters,
status, exit status, message, wall time, Newton statistics and the extremes chosen
by --extract (default end_tension,tension,moment,curvature,seabed; or all).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path
from typing import Dict, List, Optional

from .errors import EXIT_OK, EXIT_USAGE, EXIT_WRITE
from .cli import run as cli_run
from .batch_cases import (BatchInputError, Case, case_hash, cases_from_decks,
                          check_declared, decks_from_patterns, grid_cases,
                          merge_params, parse_assignment, read_case_table)
from .batch_extract import DEFAULT_EXTRACT, extract_case, parse_extract, status_complete
from .batch_run import (RESULT_FILE, CaseSpec, Running, acquire_lock, clean_temporaries,
                        command_of, quote,
                        lock_is_live, lock_owner, lock_path, read_lock, read_record,
                        release_lock, run_case)

PROG = "rodyn-batch"
EXIT_CASES_FAILED = 4      # some cases did not complete (the batch itself ran)
EXIT_INTERRUPTED = 130     # Ctrl-C or SIGTERM: finished cases kept
STATE_FILE = "batch_cases.json"
LOG_FILE = "batch.log"
SUBCOMMANDS = ("run", "summary", "plot", "compare")
EPILOG = ("exit status: 0 every case complete, 1 bad input (nothing run), 2 bad command "
          "line, 3 cannot write the summary, 4 some cases failed (the others ran), "
          "130 interrupted (Ctrl-C)")


# --- progress ------------------------------------------------------------------------------

def _clock(seconds: float) -> str:
    if not math.isfinite(seconds):
        return "?"
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"


class Progress:
    """Cases done, failed and running and the time left, on stderr: a bar redrawn in
    place on a terminal, else one line per finished case."""

    def __init__(self, total: int, skipped: int, stream=None, enabled: bool = True):
        self.stream = stream or sys.stderr
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.enabled = enabled
        self.total, self.skipped = total, skipped
        self.done = self.failed = self.running = 0
        self.t0 = time.monotonic()
        self.lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = None
        if self.enabled and self.tty:
            self._thread = threading.Thread(target=self._tick, daemon=True)
            self._thread.start()

    def _tick(self):
        while not self._stop.wait(0.5):
            self.draw()

    def left(self) -> float:
        """Seconds left: the time per case of this run so far times the cases left."""
        ran = self.done - self.skipped
        remaining = self.total - self.done
        if remaining == 0:
            return 0.0
        if ran <= 0:
            return math.nan
        return (time.monotonic() - self.t0) / ran * remaining

    def text(self) -> str:
        return (f"{self.done}/{self.total} done, {self.failed} failed, {self.running} "
                f"running, {_clock(self.left())} left")

    def draw(self):
        if not (self.enabled and self.tty):
            return
        with self.lock:
            width = 24
            fill = int(width * self.done / max(self.total, 1))
            self.stream.write(f"\r{PROG}: [{'#' * fill}{'.' * (width - fill)}] "
                              f"{self.text()}   ")
            self.stream.flush()

    def finished(self, case_id: str, status: str, wall: float, running: int):
        with self.lock:
            self.done += 1
            self.failed += status != "complete"
            self.running = running
            if self.enabled and not self.tty:
                self.stream.write(f"{PROG}: [{self.done}/{self.total}] {case_id}: {status} "
                                  f"({wall:.2f} s); {self.failed} failed, {self.running} "
                                  f"running, {_clock(self.left())} left\n")
                self.stream.flush()
        self.draw()

    def close(self):
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        if self.enabled and self.tty:
            self.draw()
            self.stream.write("\n")
            self.stream.flush()


# --- command line --------------------------------------------------------------------------

def _run_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog=f"{PROG} [run]", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog=EPILOG)
    p.add_argument("decks", nargs="+", metavar="DECK",
                   help="decks or glob patterns (one deck with --cases or --grid)")
    p.add_argument("-o", "--output", required=True, metavar="OUT",
                   help="batch folder: one sub-folder per case, the summary, the log")
    src = p.add_mutually_exclusive_group()
    src.add_argument("--cases", metavar="TABLE", help="case table (CSV: id, parameters)")
    src.add_argument("--grid", action="append", metavar="NAME=v1,v2,...",
                     help="a parameter's values; several --grid: their product")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="a parameter value for every case")
    p.add_argument("-j", "--jobs", type=int, default=None, metavar="N",
                   help="local workers (default: the number of cores)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on the Dask distributed cluster at ADDRESS")
    p.add_argument("--retries", type=int, default=1, metavar="N",
                   help="Dask: retries of a case whose task raised (default 1); a case "
                        "on a worker that dies is rerun by the scheduler anyway")
    p.add_argument("--connect-timeout", type=float, default=10.0, metavar="S",
                   help="Dask: seconds to reach the scheduler (default 10)")
    p.add_argument("--timeout", type=float, default=None, metavar="S",
                   help="time limit of a case [s] (default: none)")
    p.add_argument("--rodyn", metavar="PATH",
                   help="rodyn executable (default: $RODYN_EXE, else rodyn on PATH)")
    p.add_argument("--rodyn-arg", action="append", default=[], metavar="ARG",
                   help="one more option for rodyn (e.g. --rodyn-arg=--verbose)")
    p.add_argument("--extract", default=",".join(DEFAULT_EXTRACT), metavar="LIST",
                   help="quantities of the summary: all or some of end_tension, tension, "
                        "wall_tension, moment, curvature, torque, seabed (default: "
                        + ",".join(DEFAULT_EXTRACT) + ")")
    p.add_argument("--force", action="store_true",
                   help="run every case, also those already complete")
    p.add_argument("--no-progress", action="store_true", help="no progress on stderr")
    p.add_argument("--list", action="store_true",
                   help="print each case (id, run or skip, command line) and run nothing")
    return p


def _summary_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog=f"{PROG} summary", description=(
        "Write OUT/summary.csv and OUT/summary.h5 again from the case folders (the "
        "cases of every batch run into OUT, in OUT/batch_cases.json); cases extracted "
        "with other "
        "quantities are extracted again."), epilog=EPILOG)
    p.add_argument("output", metavar="OUT")
    p.add_argument("--extract", default=None, metavar="LIST",
                   help="quantities (default: those of the last run)")
    return p


def find_rodyn(option: Optional[str]) -> str:
    """--rodyn, else $RODYN_EXE, else rodyn on PATH (absolute)."""
    for where, value in (("--rodyn", option), ("RODYN_EXE", os.environ.get("RODYN_EXE"))):
        if value:
            path = shutil.which(value) or (value if Path(value).is_file() else None)
            if path is None or not os.access(path, os.X_OK):
                raise BatchInputError(f"{value}: rodyn executable not found ({where})")
            return str(Path(path).resolve())
    path = shutil.which("rodyn")
    if path is None:
        raise BatchInputError("rodyn: not found on PATH (give --rodyn or RODYN_EXE)")
    return str(Path(path).resolve())


def rodyn_has_set(rodyn: str) -> bool:
    """Whether `rodyn --help` lists the --set option (parameterised decks)."""
    try:
        done = subprocess.run([rodyn, "--help"], capture_output=True, text=True,
                              timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return "--set" in done.stdout + done.stderr


def build_cases(args) -> List[Case]:
    """The cases of the command line (BatchInputError on bad input)."""
    common: Dict[str, str] = {}
    for item in args.set:
        name, value = parse_assignment(item, "--set")
        common = merge_params(common, {name: value})
    if args.cases or args.grid:
        if len(args.decks) != 1 or any(c in args.decks[0] for c in "*?["):
            raise BatchInputError(f"{'--cases' if args.cases else '--grid'} takes one "
                                  f"parameterised deck, got {' '.join(args.decks)}")
        deck = decks_from_patterns(args.decks)[0]
        cases = (read_case_table(Path(args.cases), deck, common) if args.cases
                 else grid_cases(args.grid, deck, common))
    else:
        cases = cases_from_decks(decks_from_patterns(args.decks), common)
    if not cases:
        raise BatchInputError(f"{args.cases}: no case (no row after the header)")
    check_declared(cases)
    return cases


def _log(out: Path, text: str):
    with open(out / LOG_FILE, "a", encoding="utf-8") as f:
        f.write(f"{time.strftime('%Y-%m-%dT%H:%M:%S')} {text}\n")


def _param_names(cases: List[Case]) -> List[str]:
    names: Dict[str, None] = {}
    for case in cases:
        for name in case.params:
            names.setdefault(name)
    return list(names)


def _ensure_extracted(out: Path, record: dict, keys: tuple) -> dict:
    """A skipped case's record, extracted again when its quantities differ."""
    if tuple(record.get("extract_keys") or ()) == tuple(keys) and record.get("extract"):
        return record
    folder = out / record["id"]
    try:
        record["extract"] = extract_case(folder, keys)
        record.pop("extract_error", None)
    except Exception as exc:  # noqa: BLE001
        record["extract"] = None
        record["extract_error"] = " ".join(str(exc).split())
    record["extract_keys"] = list(keys)
    tmp = folder / f".{RESULT_FILE}.tmp"
    tmp.write_text(json.dumps(record), encoding="utf-8")
    tmp.replace(folder / RESULT_FILE)
    return record


# --- executors -------------------------------------------------------------------------------

def _run_local(specs: List[CaseSpec], jobs: int, on_done, progress: Progress):
    """Run the cases on `jobs` threads, each waiting for its rodyn process."""
    running = Running()
    pool = ThreadPoolExecutor(max_workers=jobs)
    futures = {pool.submit(run_case, spec, running): spec for spec in specs}
    left = len(futures)
    try:
        for fut in as_completed(futures):   # one waiter per future: O(n) in all
            spec = futures[fut]
            left -= 1
            try:
                record = fut.result()
            except Exception as exc:  # noqa: BLE001 - a bug or an I/O error
                record = {"id": spec.id, "status": "error", "exit_code": None,
                          "message": " ".join(f"{type(exc).__name__}: {exc}".split()),
                          "wall_time_s": 0.0}
            on_done(spec, record, min(running.count, left))
    except KeyboardInterrupt:
        running.kill_all()
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)


def connect(address: str, timeout: float):
    """A dask.distributed Client of the scheduler at `address` (BatchInputError when
    distributed is missing or the scheduler cannot be reached)."""
    try:
        from distributed import Client
    except ImportError:
        raise BatchInputError("--scheduler needs Dask, the optional extra of "
                              "rodyn-post: python3 -m pip install -e 'postproc[dask]' "
                              "(or 'dask[distributed]')") from None
    try:
        return Client(address, timeout=f"{timeout}s")
    except (OSError, TimeoutError) as exc:
        raise BatchInputError(f"{address}: cannot reach the Dask scheduler "
                              f"({' '.join(str(exc).split())[:200]})") from None
    except ValueError as exc:
        raise BatchInputError(f"{address}: not a scheduler address ({exc})") from None


def _run_dask(client, specs: List[CaseSpec], retries: int, on_done, progress: Progress):
    """Run the cases as Dask tasks; a task lost with its worker is rerun by the
    scheduler (distributed's allowed-failures), one that raised `retries` times."""
    from distributed import as_completed

    slots = max(1, sum(client.nthreads().values()))
    futures = {}
    for spec in specs:
        fut = client.submit(run_case, spec, key=f"rodyn-case-{spec.id}-{spec.token}",
                            pure=False, retries=retries)
        futures[fut] = spec
    left = len(futures)
    progress.running = min(slots, left)
    try:
        for fut in as_completed(list(futures)):
            spec = futures[fut]
            left -= 1
            try:
                record = fut.result()
            except Exception as exc:  # noqa: BLE001 - KilledWorker, lost task, ...
                record = {"id": spec.id, "status": "error", "exit_code": None,
                          "message": " ".join(f"dask: {type(exc).__name__}: {exc}"
                                              .split())[:500], "wall_time_s": 0.0}
            on_done(spec, record, min(slots, left))
    except KeyboardInterrupt:
        client.cancel(list(futures))
        raise


def _terminate(signum, frame):
    """SIGTERM (kill, scancel) stops the batch as Ctrl-C does."""
    raise KeyboardInterrupt


# --- the batch -------------------------------------------------------------------------------

def run_batch(args) -> int:
    """Check the input, run the cases not yet complete, write the summary."""
    from .batch_summary import write_summary

    keys = parse_extract(args.extract)
    if args.jobs is not None and args.jobs < 1:
        raise BatchInputError(f"-j {args.jobs}: at least 1")
    if args.timeout is not None and not args.timeout > 0:
        raise BatchInputError(f"--timeout {args.timeout}: must be positive")
    cases = build_cases(args)
    rodyn = find_rodyn(args.rodyn)
    if any(c.params for c in cases) and not rodyn_has_set(rodyn):
        raise BatchInputError(f"{rodyn}: this rodyn has no --set option (`rodyn --help`); "
                              "parameterised decks need a rodyn with *PARAMETER")
    client = connect(args.scheduler, args.connect_timeout) if args.scheduler else None
    out = Path(args.output).resolve()
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise BatchInputError(f"{out}: cannot create the batch folder "
                              f"({exc.strerror or exc})") from None
    token = f"{os.getpid()}-{os.urandom(6).hex()}"
    param_names = _param_names(cases)
    hashes = {c.id: case_hash(c.deck, c.params) for c in cases}

    # which cases are complete already; locks of another live batch refuse the batch
    entries: Dict[str, dict] = {}
    todo: List[Case] = []
    for case in cases:
        entry = {"id": case.id, "params": case.params, "record": None}
        entries[case.id] = entry
        rec = None if args.force else read_record(out / case.id)
        if (rec is not None and rec.get("status") == "complete"
                and rec.get("hash") == hashes[case.id] and status_complete(out / case.id)):
            entry["record"], entry["skipped"] = rec, True
        else:
            todo.append(case)
    if args.list:
        for case in cases:
            what = "skip (complete)" if entries[case.id].get("skipped") else "run"
            spec = CaseSpec(id=case.id, deck=str(case.deck), params=dict(case.params),
                            out=str(out), rodyn=rodyn, hash=hashes[case.id], token=token)
            print(f"{case.id}\t{what}\t{quote(command_of(spec, str(out / case.id)))}")
        return EXIT_OK
    for case in todo:
        info = read_lock(lock_path(out, case.id))
        if lock_is_live(info, token):
            raise BatchInputError(f"{out / case.id}: being written by another batch "
                                  f"({lock_owner(info)}; lock {lock_path(out, case.id)})")
    locked = []
    for case in todo:
        info = acquire_lock(out, case.id, token)
        if info is not None:
            for cid in locked:
                release_lock(out, cid, token)
            raise BatchInputError(f"{out / case.id}: being written by another batch "
                                  f"({lock_owner(info)})")
        locked.append(case.id)
    clean_temporaries(out, locked)
    with _state_lock(out):
        earlier = _merge_state(out, cases, keys)
    if earlier:
        print(f"{PROG}: {out} holds {earlier} case(s) of another batch: the summary lists "
              f"them with this batch's {len(cases)}", file=sys.stderr)

    extra = tuple(args.rodyn_arg) or ("--quiet",)
    specs = [CaseSpec(id=c.id, deck=str(c.deck), params=dict(c.params), out=str(out),
                      rodyn=rodyn, hash=hashes[c.id], token=token, timeout=args.timeout,
                      extract=keys, extra_args=extra) for c in todo]
    skipped = len(cases) - len(todo)
    where = f"Dask scheduler {args.scheduler}" if client else \
        f"{args.jobs or os.cpu_count() or 1} local workers"
    _log(out, f"batch {token}: {len(cases)} cases, {skipped} complete already, "
              f"{len(todo)} to run on {where}; rodyn {rodyn}")
    progress = Progress(len(cases), skipped, enabled=not args.no_progress)
    progress.done = skipped

    def on_done(spec: CaseSpec, record: dict, running: int):
        entries[spec.id]["record"] = record
        release_lock(out, spec.id, token)
        stamp = time.strftime('%Y-%m-%dT%H:%M:%S')
        _log(out, f"case {spec.id}: {record.get('command', '(not started)')}\n{stamp} "
                  f"case {spec.id}: {record['status']}, exit {record.get('exit_code')}, "
                  f"{record.get('wall_time_s', 0.0):.3f} s"
                  + (f": {record['message']}" if record.get("message") else ""))
        progress.finished(spec.id, record["status"], record.get("wall_time_s") or 0.0,
                          running)

    for case in cases:
        if entries[case.id].get("skipped"):
            entries[case.id]["record"] = _ensure_extracted(out, entries[case.id]["record"],
                                                           keys)
    interrupted = False
    previous = None
    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, _terminate)   # as Ctrl-C (scancel)
    try:
        if client is not None:
            _run_dask(client, specs, args.retries, on_done, progress)
        else:
            _run_local(specs, args.jobs or os.cpu_count() or 1, on_done, progress)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
        progress.close()
        for cid in locked:
            release_lock(out, cid, token)
        clean_temporaries(out, locked)
        if client is not None:
            client.close()
    meta = {"created": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "extract": ",".join(keys),
            "rodyn": rodyn}
    ordered = [entries[c.id] for c in cases]
    for entry in ordered:
        if entry["record"] is None or entry["record"].get("status") in ("cancelled",
                                                                         "abandoned"):
            # finished and published, but stopped before the driver took note of it
            rec = read_record(out / entry["id"])
            if (rec is not None and rec.get("status") == "complete"
                    and rec.get("hash") == hashes[entry["id"]]):
                entry["record"] = _ensure_extracted(out, rec, keys)
                continue
            entry["status"] = "not run"
            entry["message"] = "batch interrupted" if interrupted else (
                entry["record"] or {}).get("message", "")
    with _state_lock(out):
        # the folder's cases as they stand now: another batch may have added some
        state = _read_state(out) or {"cases": [], "parameters": param_names}
        mine = {e["id"]: e for e in ordered}
        listed = [mine.get(c["id"]) or _other_entry(out, c, keys, token)
                  for c in state["cases"]]
        csv_path, h5_path = write_summary(out, listed, state["parameters"], meta)
    failed = [e["id"] for e in ordered if (e.get("status") or e["record"]["status"])
              != "complete"]
    _log(out, f"batch {token}: {'interrupted' if interrupted else 'finished'}; "
              f"{len(cases) - len(failed)} complete, {len(failed)} not")
    print(csv_path)
    print(h5_path)
    if interrupted:
        print(f"{PROG}: interrupted: finished cases are kept; run again to go on",
              file=sys.stderr)
        return EXIT_INTERRUPTED
    if failed:
        print(f"{PROG}: {len(failed)} of {len(cases)} cases not complete: "
              f"{', '.join(failed[:10])}{' ...' if len(failed) > 10 else ''}",
              file=sys.stderr)
        return EXIT_CASES_FAILED
    return EXIT_OK


# --- the folder's cases: every batch run into it -----------------------------------------

class _state_lock:
    """An exclusive lock (flock of the folder itself: no file is left behind) while the
    folder's list of cases (batch_cases.json) and the summary are read and written."""

    def __init__(self, out: Path):
        self.path = Path(out)

    def __enter__(self):
        import fcntl
        self.fd = os.open(self.path, os.O_RDONLY)
        fcntl.flock(self.fd, fcntl.LOCK_EX)
        return self

    def __exit__(self, *exc):
        import fcntl
        fcntl.flock(self.fd, fcntl.LOCK_UN)
        os.close(self.fd)


def _read_state(out: Path) -> Optional[dict]:
    """batch_cases.json, None when absent or unreadable."""
    try:
        state = json.loads((Path(out) / STATE_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return state if isinstance(state, dict) and isinstance(state.get("cases"), list) else None


def _unlisted_cases(out: Path, listed) -> List[dict]:
    """Case folders of OUT holding a batch's record (batch_case.json of their own id)
    that batch_cases.json does not list: cases of a batch whose list was replaced by a
    later batch's (rodyn-batch kept only the last batch's list before it merged them)."""
    found = []
    for path in sorted(Path(out).glob(f"*/{RESULT_FILE}")):
        folder = path.parent
        if folder.name in listed or folder.name.startswith("."):
            continue
        rec = read_record(folder)
        if rec is not None and rec.get("id") == folder.name:
            found.append({"id": folder.name, "deck": str(rec.get("deck", "")),
                          "params": dict(rec.get("params") or {})})
    return found


def _merge_state(out: Path, cases: List[Case], keys: tuple) -> int:
    """Write batch_cases.json as the folder's cases: those of earlier batches that this
    one does not define again (listed, or found as case folders the list lacks), then
    this batch's (a case id given again takes its new definition); parameters in order
    of first use. Returns how many earlier cases stay."""
    state = _read_state(out) or {"cases": [], "parameters": []}
    state["cases"] = state["cases"] + _unlisted_cases(
        out, {c.get("id") for c in state["cases"]})
    ids = {c.id for c in cases}
    kept = [c for c in state["cases"] if c.get("id") not in ids]
    merged = kept + [{"id": c.id, "deck": str(c.deck), "params": c.params} for c in cases]
    names: Dict[str, None] = dict.fromkeys(state.get("parameters") or [])
    for c in merged:
        names.update(dict.fromkeys(c.get("params") or {}))
    new = {"cases": merged, "parameters": list(names), "extract": list(keys)}
    (Path(out) / STATE_FILE).write_text(json.dumps(new, indent=1), encoding="utf-8")
    return len(kept)


def _other_entry(out: Path, case: dict, keys: tuple, token: str) -> dict:
    """The summary entry of a case of another batch: its published record, else
    'running' while another batch holds its lock, else 'not run'."""
    entry = {"id": case["id"], "params": case.get("params") or {}, "record": None}
    rec = read_record(out / case["id"])
    if rec is not None:
        entry["record"] = _ensure_extracted(out, rec, keys)
    elif lock_is_live(read_lock(lock_path(out, case["id"])), token):
        entry["status"], entry["message"] = "running", "being run by another batch"
    else:
        entry["status"], entry["message"] = "not run", "defined by another batch"
    return entry


def rebuild_summary(args) -> int:
    """`rodyn-batch summary OUT`: the summary again from the case folders."""
    from .batch_summary import write_summary

    out = Path(args.output)
    if _read_state(out) is None:
        raise BatchInputError(f"{out / STATE_FILE}: cannot read the batch's cases "
                              "(missing or not a batch's list)")
    with _state_lock(out):
        state = _read_state(out)
        keys = (parse_extract(args.extract) if args.extract
                else tuple(state.get("extract") or DEFAULT_EXTRACT))
        _merge_state(out, [], keys)     # takes in case folders the list lacks
        state = _read_state(out)
        entries = [_other_entry(out, case, keys, "") for case in state["cases"]]
        paths = write_summary(out, entries, state["parameters"],
                              {"created": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
                               "extract": ",".join(keys)})
    for path in paths:
        print(path)
    return EXIT_OK


def main(argv=None) -> int:
    """The command line; returns the exit status (rodyn_post.cli.run turns the known
    failures, bad input and unwritable outputs, into a one-line message and status)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    command = argv.pop(0) if argv and argv[0] in SUBCOMMANDS else "run"

    def body():
        try:
            if command == "run":
                return run_batch(_run_parser().parse_args(argv))
            if command == "summary":
                return rebuild_summary(_summary_parser().parse_args(argv))
            if command == "plot":
                from .batch_plot import main as plot_main
                return plot_main(argv)
            from .batch_compare import main as compare_main
            return compare_main(argv)
        except ValueError as exc:      # --extract and other option values
            print(f"{PROG}: error: {' '.join(str(exc).split())}", file=sys.stderr)
            return EXIT_USAGE
        except OSError as exc:
            print(f"{PROG}: error: {exc.filename or ''}: {exc.strerror or exc}",
                  file=sys.stderr)
            return EXIT_WRITE
    return cli_run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
