"""The cases of a batch folder: OUT/batch_cases.json, shared by every batch run into OUT.

Batches run into one folder merge (docs/batch.md, "Two batches into one folder"): the
folder's case list is the union of the cases of every batch run into it, so that a
load-case matrix run in parts (two case tables, a grid and then some extra decks, a
second batch started while the first runs) has one summary of all its cases.

- A batch adds its cases to the list when it starts: cases with new ids are appended,
  a case whose id is listed already takes the new definition (deck and parameters) in
  its place. The parameter names are the union, in order of first appearance; the
  quantities extracted (`extract`) are the latest batch's.
- Case folders holding a `batch_case.json` but missing from the list (a folder that an
  older rodyn-batch, which kept the last batch's cases only, left behind) are adopted
  with the deck and parameters of their record.
- When a batch ends, and on `rodyn-batch summary OUT`, the summary is written for every
  case of the list: the batch's own cases from what it ran, the others from their
  folders; a case that another live batch is running is `running`, one never run (or
  whose folder holds another definition's results) `not run`.

The list is read, changed and written, and the summary written, under an exclusive
lock (`fcntl.flock` of OUT/.batch_cases.flock), so that batches ending at the same time
write one after the other and the last summary holds every case.
"""
from __future__ import annotations

import json
from contextlib import contextmanager
from pathlib import Path
from typing import Callable, Dict, List, Optional

from .batch_cases import BatchInputError
from .batch_run import RESULT_FILE, lock_is_live, lock_owner, lock_path, read_lock, read_record

STATE_FILE = "batch_cases.json"
STATE_LOCK = ".batch_cases.flock"   # not .<id>.lock: no case's lock


@contextmanager
def state_locked(out: Path):
    """Hold the exclusive lock of OUT's case list (blocks while another batch holds it:
    a read, a merge and a write, or writing the summary)."""
    import fcntl

    with open(Path(out) / STATE_LOCK, "a+", encoding="utf-8") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def read_state(out: Path) -> Optional[dict]:
    """OUT/batch_cases.json, None when there is none (BatchInputError when unreadable)."""
    path = Path(out) / STATE_FILE
    try:
        state = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise BatchInputError(f"{path}: cannot read the batch folder's cases "
                              f"({getattr(exc, 'strerror', None) or exc})") from None
    if not isinstance(state, dict) or not isinstance(state.get("cases"), list):
        raise BatchInputError(f"{path}: not a case list of rodyn-batch (no 'cases')")
    state.setdefault("parameters", [])
    return state


def write_state(out: Path, state: dict):
    """Write OUT/batch_cases.json (a temporary file renamed over it)."""
    tmp = Path(out) / f".{STATE_FILE}.tmp"
    tmp.write_text(json.dumps(state, indent=1), encoding="utf-8")
    tmp.replace(Path(out) / STATE_FILE)


def _names(*lists) -> List[str]:
    names: Dict[str, None] = {}
    for names_list in lists:
        for name in names_list:
            names.setdefault(name)
    return list(names)


def merge_cases(state: Optional[dict], cases: List[dict], parameters: List[str],
                extract: List[str]) -> tuple:
    """(merged state, ids of listed cases given a new definition, number of listed cases
    not among `cases`): `cases` (dicts id, deck, params, hash) added to `state`."""
    old = list((state or {}).get("cases", []))
    new = {c["id"]: c for c in cases}
    changed = [c["id"] for c in old if c["id"] in new and (
        c.get("hash") not in (None, new[c["id"]]["hash"])
        or c.get("params") != new[c["id"]]["params"])]
    merged = [new.pop(c["id"], c) for c in old] + list(new.values())
    others = len(merged) - len(cases)
    names = _names((state or {}).get("parameters", []), parameters)
    return ({"cases": merged, "parameters": names, "extract": list(extract)}, changed,
            others)


def adopt_folders(out: Path, state: dict) -> List[str]:
    """Add to `state` the case folders of OUT with a batch_case.json that it does not
    list (their deck, parameters and hash from the record); returns their ids."""
    listed = {c["id"] for c in state["cases"]}
    adopted = []
    for path in sorted(Path(out).glob(f"*/{RESULT_FILE}")):
        folder = path.parent
        if folder.name.startswith(".") or folder.name in listed:
            continue
        rec = read_record(folder)
        if rec is None or rec.get("id") != folder.name:
            continue
        params = {str(k): str(v) for k, v in (rec.get("params") or {}).items()}
        state["cases"].append({"id": folder.name, "deck": rec.get("deck", ""),
                               "params": params, "hash": rec.get("hash")})
        state["parameters"] = _names(state["parameters"], params)
        adopted.append(folder.name)
    return adopted


def summary_entries(out: Path, state: dict, own: Dict[str, dict], token: Optional[str],
                    refresh: Callable[[dict], dict]) -> List[dict]:
    """The summary's entries (id, params, record, and status / message when they
    override the record's) for every case of `state`, in its order: `own[id]` for the
    cases this batch ran or kept (when the list still has their definition), the
    others from their folders (`refresh(record)` extracts a record again when its
    quantities are not those of the summary)."""
    entries = []
    for case in state["cases"]:
        cid = case["id"]
        mine = own.get(cid)
        if mine is not None and case.get("hash") in (None, mine.get("hash")):
            entries.append(mine)
            continue
        entry = {"id": cid, "params": case.get("params") or {}, "record": None}
        info = read_lock(lock_path(out, cid))
        if lock_is_live(info, token or ""):
            entry.update(status="running",
                         message=f"being run by another batch ({lock_owner(info)})")
        else:
            rec = read_record(Path(out) / cid)
            if rec is not None and case.get("hash") not in (None, rec.get("hash")):
                entry.update(status="not run", message=f"{Path(out) / cid} holds the "
                             "results of another deck or parameters: run the batch again")
            elif rec is not None:
                entry["record"] = refresh(rec)
        entries.append(entry)
    return entries
