"""Running the cases of a batch: one case (`run_case`), the locks, the executors.

A case runs `rodyn DECK -o TMP [--set NAME=VALUE ...]` into a hidden temporary
folder `OUT/.<id>.tmp-<pid>-<random>` next to its final folder, writes there
`command.txt`, `stdout.txt`, `stderr.txt` and, last, `batch_case.json` (exit status,
message, wall time, Newton statistics, extremes and envelopes), then renames the
folder to `OUT/<id>` (replacing an earlier one). A case folder is therefore either
the old one or a finished new one, never half written, whatever stops the batch.

The driver (the process running `rodyn-batch`) holds a lock file `OUT/.<id>.lock`
(JSON: pid, host, batch token, time) for every case it runs, from before the first
case starts until the case is in place. A case is published only while the lock still
holds the batch's token. A lock whose process is gone (same host, pid not running) is
stale and taken over; another live batch's lock makes the batch refuse to start.

`run_case` is a plain function of picklable arguments: the local executor calls it in
threads (the work is in the rodyn process; numpy and h5py release the GIL for the
reading), the Dask executor ships it to the workers.
"""
from __future__ import annotations

import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Dict, List, Optional

RESULT_FILE = "batch_case.json"
HOST = socket.gethostname()        # asked once: ~0.1 ms a call
COMMAND_FILE = "command.txt"


@dataclass(frozen=True)
class CaseSpec:
    """What a worker needs to run one case (picklable, paths absolute)."""
    id: str
    deck: str
    params: Dict[str, str]
    out: str                      # the batch output folder
    rodyn: str                    # the executable
    hash: str                     # batch_cases.case_hash of deck and parameters
    token: str                    # the batch's token (in its lock files)
    timeout: Optional[float] = None
    extract: tuple = ()
    extra_args: tuple = field(default=())   # more rodyn options (e.g. --quiet)


def command_of(spec: CaseSpec, outdir: str) -> List[str]:
    """The rodyn command line of a case writing into `outdir`."""
    cmd = [spec.rodyn, spec.deck, "-o", outdir]
    for name, value in spec.params.items():
        cmd += ["--set", f"{name}={value}"]
    return cmd + list(spec.extra_args)


def quote(cmd: List[str]) -> str:
    """A command line as a shell would take it."""
    import shlex
    return " ".join(shlex.quote(c) for c in cmd)


# --- locks -------------------------------------------------------------------------------

def lock_path(out: Path, case_id: str) -> Path:
    return Path(out) / f".{case_id}.lock"


def read_lock(path: Path) -> Optional[dict]:
    """The lock's content, None when there is no lock ({} when unreadable)."""
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError):
        return {}


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def lock_is_live(info: Optional[dict], token: str) -> bool:
    """Whether a lock belongs to another batch that may still be running: not ours,
    and its process is alive (or on another host, where we cannot tell)."""
    if info is None:
        return False
    if info.get("batch") == token:
        return False
    if info.get("host") == HOST:
        try:
            return _pid_alive(int(info.get("pid", -1)))
        except (TypeError, ValueError):
            return False
    return bool(info)


def lock_owner(info: dict) -> str:
    return (f"pid {info.get('pid', '?')} on {info.get('host', '?')} since "
            f"{info.get('time', '?')}")


def acquire_lock(out: Path, case_id: str, token: str) -> Optional[dict]:
    """Take the lock of a case; returns None, or the live lock of another batch."""
    path = lock_path(out, case_id)
    content = json.dumps({"pid": os.getpid(), "host": HOST,
                          "batch": token, "time": time.strftime("%Y-%m-%dT%H:%M:%S%z")})
    for _ in range(3):
        try:
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        except FileExistsError:
            info = read_lock(path)
            if lock_is_live(info, token):
                return info
            try:                       # stale (or ours): take it over
                path.unlink()
            except FileNotFoundError:
                pass
            continue
        with os.fdopen(fd, "w") as f:
            f.write(content + "\n")
        return None
    return read_lock(path) or {"pid": "?", "host": "?"}


def release_lock(out: Path, case_id: str, token: str):
    """Remove the lock of a case if it is ours."""
    path = lock_path(out, case_id)
    info = read_lock(path)
    if info is not None and info.get("batch") == token:
        try:
            path.unlink()
        except FileNotFoundError:
            pass


# --- one case ----------------------------------------------------------------------------

def _last_error_line(text: str) -> str:
    """The line of rodyn's stderr that says what went wrong: the last one with
    'error', else the last non-empty one."""
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    for ln in reversed(lines):
        if "error" in ln.lower():
            return ln
    return lines[-1] if lines else ""


def _die_with_parent():
    """In the child (Linux): be killed when the process that started us dies, so a
    killed Dask worker leaves no rodyn running on. Only on Dask workers: a preexec
    function makes Python fork() instead of vfork(), ~10 ms a case for the driver."""
    try:
        import ctypes
        libc = ctypes.CDLL("libc.so.6", use_errno=True)
        libc.prctl(1, signal.SIGKILL)          # PR_SET_PDEATHSIG
    except Exception:  # noqa: BLE001 - not Linux: nothing to do
        pass


class Running:
    """The rodyn processes of the local executor, so that Ctrl-C can stop them."""

    def __init__(self):
        self.lock = threading.Lock()
        self.procs: Dict[str, subprocess.Popen] = {}
        self.stop = False

    def add(self, case_id: str, proc: subprocess.Popen):
        with self.lock:
            self.procs[case_id] = proc
            if self.stop:
                proc.kill()

    def remove(self, case_id: str):
        with self.lock:
            self.procs.pop(case_id, None)

    def kill_all(self):
        with self.lock:
            self.stop = True
            for proc in self.procs.values():
                try:
                    proc.kill()
                except OSError:
                    pass

    @property
    def count(self) -> int:
        with self.lock:
            return len(self.procs)


def run_case(spec: CaseSpec, running: Optional[Running] = None) -> dict:
    """Run one case and publish its folder; returns the record of batch_case.json.

    status: 'complete' (exit 0 and status.txt complete), 'failed' (an exit status
    other than 0, or incomplete results), 'timeout', 'signal' (killed by a signal),
    'error' (rodyn could not be started), 'cancelled' (the batch was stopped first),
    'abandoned' (the batch's lock was gone: not published)."""
    from .batch_extract import extract_case, newton_stats

    out = Path(spec.out)
    record = {"id": spec.id, "params": dict(spec.params), "deck": spec.deck,
              "hash": spec.hash, "host": HOST, "pid": os.getpid(),
              "extract_keys": list(spec.extract)}
    if running is not None and running.stop:
        record.update(status="cancelled", exit_code=None, message="batch interrupted",
                      wall_time_s=0.0)
        return record
    tmp = out / f".{spec.id}.tmp-{os.getpid()}-{secrets.token_hex(4)}"
    tmp.mkdir(parents=True)
    cmd = command_of(spec, str(tmp))
    record["command"] = quote(cmd)
    (tmp / COMMAND_FILE).write_text(record["command"] + "\n", encoding="utf-8")
    t0 = time.perf_counter()
    record["started"] = time.strftime("%Y-%m-%dT%H:%M:%S%z")
    timed_out = False
    try:
        with open(tmp / "stdout.txt", "wb") as fo, open(tmp / "stderr.txt", "wb") as fe:
            proc = subprocess.Popen(cmd, stdout=fo, stderr=fe, stdin=subprocess.DEVNULL,
                                    cwd=str(tmp), start_new_session=True,
                                    preexec_fn=_die_with_parent if running is None
                                    and sys.platform.startswith("linux") else None)
            if running is not None:
                running.add(spec.id, proc)
            try:
                code = proc.wait(timeout=spec.timeout)
            except subprocess.TimeoutExpired:
                timed_out = True
                proc.kill()
                code = proc.wait()
            finally:
                if running is not None:
                    running.remove(spec.id)
    except OSError as exc:
        shutil.rmtree(tmp, ignore_errors=True)
        record.update(status="error", exit_code=None, wall_time_s=0.0,
                      message=f"cannot run {spec.rodyn}: {exc.strerror or exc}")
        return record
    wall = time.perf_counter() - t0
    stderr = (tmp / "stderr.txt").read_text(encoding="utf-8", errors="replace")
    last = _last_error_line(stderr)
    newton = newton_stats(tmp)
    record["newton"] = {k: v for k, v in newton.items() if k not in ("status_txt",)}
    record["exit_code"] = code
    record["wall_time_s"] = wall
    if running is not None and running.stop and code != 0:
        shutil.rmtree(tmp, ignore_errors=True)
        record.update(status="cancelled", message="batch interrupted")
        return record
    if timed_out:
        record["status"] = "timeout"
        record["message"] = f"time limit of {spec.timeout:g} s reached: killed" + (
            f" (last line: {last})" if last else "")
    elif code < 0:
        try:
            name = signal.Signals(-code).name
        except ValueError:
            name = f"signal {-code}"
        record["status"] = "signal"
        record["message"] = f"killed by {name}" + (f" (last line: {last})" if last else "")
    elif code != 0 or not newton["complete"]:
        record["status"] = "failed"
        record["message"] = last or newton["status_txt"] or f"exit status {code}"
    else:
        record["status"] = "complete"
        record["message"] = ""
    try:
        record["extract"] = extract_case(tmp, spec.extract)
    except Exception as exc:  # noqa: BLE001 - a failed run may leave nothing readable
        record["extract"] = None
        record["extract_error"] = " ".join(str(exc).split())
    record["extract_s"] = time.perf_counter() - t0 - wall
    (tmp / RESULT_FILE).write_text(json.dumps(record, allow_nan=True), encoding="utf-8")
    return publish(spec, tmp, record)


def publish(spec: CaseSpec, tmp: Path, record: dict) -> dict:
    """Rename the finished temporary folder to OUT/<id> while our lock holds."""
    out = Path(spec.out)
    info = read_lock(lock_path(out, spec.id))
    if info is None or info.get("batch") != spec.token:
        shutil.rmtree(tmp, ignore_errors=True)
        record["status"] = "abandoned"
        record["message"] = "the batch's lock on the case was gone: results discarded"
        return record
    final = out / spec.id
    old = None
    if final.exists():
        old = out / f".{spec.id}.old-{secrets.token_hex(4)}"
        os.replace(final, old)
    os.replace(tmp, final)
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
    return record


def read_record(folder: Path) -> Optional[dict]:
    """batch_case.json of a case folder, None when missing or unreadable."""
    try:
        return json.loads((Path(folder) / RESULT_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def clean_temporaries(out: Path, case_ids):
    """Remove the temporary folders a stopped run of these cases left behind."""
    for case_id in case_ids:
        for pattern in (f".{case_id}.tmp-*", f".{case_id}.old-*"):
            for p in Path(out).glob(pattern):
                shutil.rmtree(p, ignore_errors=True)


def spec_dict(spec: CaseSpec) -> dict:
    return asdict(spec)
