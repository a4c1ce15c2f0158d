"""The cases of a batch: where they come from, their ids, parameters and hashes.

A case is one run of rodyn: a deck, an id (the name of its folder under the batch's
output folder) and the parameters given to the program with `--set NAME=VALUE`.
Cases come from (docs/batch.md):

- a list or glob of decks: one case per deck, id = the deck's file name without
  extension, no parameters;
- one parameterised deck and a case table (CSV: an `id` column and one column per
  parameter; an empty cell means "the deck's value");
- one parameterised deck and a grid (`--grid NAME=v1,v2 --grid OTHER=a,b`): the
  product, ids `NAME=v1_OTHER=a` (see `grid_id`).

Everything wrong with the input raises `BatchInputError`, whose one-line message names
the file and row (or the option) at fault; nothing has run when it is raised.
"""
from __future__ import annotations

import csv
import glob as globmod
import hashlib
import itertools
import json
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

from .errors import InputError

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_UNSAFE = re.compile(r"[^A-Za-z0-9._=+-]")


class BatchInputError(InputError):
    """Bad input of a batch (case table, grid, decks, scheduler): exit status 1."""


@dataclass(frozen=True)
class Case:
    """One case of a batch."""
    id: str
    deck: Path                                   # absolute path of the main deck
    params: Dict[str, str] = field(default_factory=dict)   # --set NAME=VALUE, in order
    origin: str = ""                             # where it was defined (file:row, option)


# --- decks -----------------------------------------------------------------------------

def _strip_comment(line: str) -> str:
    return "" if line.lstrip().startswith("**") else line


def _include_path(keyword_line: str, deck: Path) -> Optional[Path]:
    """The file of an `*INCLUDE, INPUT=file` keyword line (relative to the deck)."""
    m = re.search(r"INPUT\s*=\s*([^,]+)", keyword_line, flags=re.IGNORECASE)
    if not m:
        return None
    name = m.group(1).strip().strip('"')
    path = Path(name)
    return path if path.is_absolute() else deck.parent / path


def deck_text(deck: Path, _depth: int = 0) -> str:
    """The deck's text with its `*INCLUDE` files expanded (what the hash covers).
    An include that cannot be read is left as its keyword line (rodyn will report it)."""
    text = Path(deck).read_text(encoding="utf-8", errors="replace")
    if _depth > 20:
        return text
    out = []
    for line in text.splitlines(keepends=True):
        out.append(line)
        stripped = line.strip()
        if stripped.upper().startswith("*INCLUDE"):
            inc = _include_path(stripped, Path(deck))
            if inc is not None and inc.is_file():
                out.append(deck_text(inc, _depth + 1))
    return "".join(out)


def deck_parameters(deck: Path) -> Dict[str, str]:
    """Names (upper case) and value text of the parameters a deck declares: the
    `NAME = value` lines after a `*PARAMETER` keyword line, up to the next keyword line
    (comments `**` skipped), in the deck and its includes."""
    params: Dict[str, str] = {}
    inside = False
    for raw in deck_text(deck).splitlines():
        line = _strip_comment(raw).strip()
        if not line:
            continue
        if line.startswith("*"):
            inside = re.sub(r"\s+", "", line.upper()).split(",")[0] == "*PARAMETER"
            continue
        if inside and "=" in line:
            name = line.split("=", 1)[0].strip()
            params[name.upper()] = line.split("=", 1)[1].strip()
    return params


def case_hash(deck: Path, params: Dict[str, str]) -> str:
    """sha256 of the deck text (includes expanded) and the parameters: a case whose
    hash is unchanged and whose results are complete is not run again."""
    h = hashlib.sha256()
    h.update(deck_text(deck).encode("utf-8"))
    h.update(b"\0")
    h.update(json.dumps(sorted(params.items())).encode("utf-8"))
    return h.hexdigest()


# --- ids -------------------------------------------------------------------------------

def safe_id(text: str) -> str:
    """A folder name: characters other than letters, digits and . _ = + - become '_'."""
    out = _UNSAFE.sub("_", text.strip())
    if out in ("", ".", ".."):
        out = "_" + out
    if out.startswith("."):
        out = "_" + out[1:]
    return out


def grid_id(params: Dict[str, str]) -> str:
    """Id of a grid case: NAME=value joined by '_', e.g. `ELEMENTS=4_DT=0.05`."""
    return safe_id("_".join(f"{k}={v}" for k, v in params.items()))


# --- the three sources -------------------------------------------------------------------

def decks_from_patterns(patterns: Sequence[str]) -> List[Path]:
    """Decks named by files or glob patterns, in the order given (each glob sorted)."""
    decks: List[Path] = []
    for pattern in patterns:
        if any(ch in pattern for ch in "*?["):
            found = sorted(globmod.glob(pattern))
            if not found:
                raise BatchInputError(f"{pattern}: no deck matches this pattern")
            decks.extend(Path(p) for p in found)
        else:
            decks.append(Path(pattern))
    for deck in decks:
        if not deck.is_file():
            raise BatchInputError(f"{deck}: no such deck")
    return [d.resolve() for d in decks]


def cases_from_decks(decks: Sequence[Path], common: Dict[str, str]) -> List[Case]:
    """One case per deck, id = file name without extension."""
    cases = [Case(safe_id(d.stem), d, dict(common), str(d)) for d in decks]
    _check_unique(cases)
    return cases


def read_case_table(path: Path, deck: Path, common: Dict[str, str]) -> List[Case]:
    """Cases of a CSV case table: header `id,NAME,...`, one row per case."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise BatchInputError(f"{path}: cannot read the case table "
                              f"({exc.strerror or exc})") from None
    rows = [(n, r) for n, r in enumerate(csv.reader(text.splitlines()), 1)
            if r and any(c.strip() for c in r) and not r[0].lstrip().startswith("#")]
    if not rows:
        raise BatchInputError(f"{path}: empty case table (expected a header: id,NAME,...)")
    header_line, header = rows[0]
    header = [h.strip() for h in header]
    if "id" not in [h.lower() for h in header]:
        raise BatchInputError(f"{path}:{header_line}: the header has no 'id' column")
    id_col = [h.lower() for h in header].index("id")
    names = [h for i, h in enumerate(header) if i != id_col]
    for name in names:
        if not _NAME.match(name):
            raise BatchInputError(f"{path}:{header_line}: column {name!r} is not a "
                                  "parameter name (letters, digits, _)")
    if len(set(n.upper() for n in names)) != len(names):
        raise BatchInputError(f"{path}:{header_line}: a parameter column is repeated")
    cases = []
    for number, row in rows[1:]:
        row = [c.strip() for c in row]
        while len(row) > len(header) and row[-1] == "":
            row.pop()
        if len(row) != len(header):
            raise BatchInputError(f"{path}:{number}: {len(row)} fields, the header has "
                                  f"{len(header)}")
        case_id = row[id_col]
        if not case_id:
            raise BatchInputError(f"{path}:{number}: empty id")
        if safe_id(case_id) != case_id:
            raise BatchInputError(f"{path}:{number}: id {case_id!r} is not a folder name "
                                  "(letters, digits and . _ = + - only)")
        params = merge_params(common, {name: row[i] for i, name in enumerate(header)
                                       if i != id_col and row[i] != ""})
        cases.append(Case(case_id, deck, params, f"{path}:{number}"))
    _check_unique(cases)
    return cases


def merge_params(common: Dict[str, str], own: Dict[str, str]) -> Dict[str, str]:
    """`common` (--set) overridden by a case's own values; names compare without case."""
    out = {k: v for k, v in common.items() if k.upper() not in {n.upper() for n in own}}
    out.update(own)
    return out


def parse_assignment(text: str, option: str) -> Tuple[str, str]:
    """'NAME=VALUE' of --set or --grid (NAME as written; rodyn's parameter names are
    compared without case by the batch)."""
    if "=" not in text:
        raise BatchInputError(f"{option} {text!r}: expected NAME=VALUE")
    name, value = (part.strip() for part in text.split("=", 1))
    if not _NAME.match(name):
        raise BatchInputError(f"{option} {text!r}: {name!r} is not a parameter name")
    return name, value


def grid_cases(grid: Sequence[str], deck: Path, common: Dict[str, str]) -> List[Case]:
    """The product of `--grid NAME=v1,v2,...` options, the first varying slowest."""
    axes = []
    for item in grid:
        name, values = parse_assignment(item, "--grid")
        vals = [v.strip() for v in values.split(",")]
        if not vals or any(v == "" for v in vals):
            raise BatchInputError(f"--grid {item!r}: empty value in the list")
        if len(set(vals)) != len(vals):
            raise BatchInputError(f"--grid {item!r}: a value is repeated")
        if name.upper() in (a[0].upper() for a in axes):
            raise BatchInputError(f"--grid {name}: given twice")
        axes.append((name, vals))
    cases = []
    for combo in itertools.product(*(vals for _, vals in axes)):
        params = dict(zip((n for n, _ in axes), combo))
        full = merge_params(common, params)
        cases.append(Case(grid_id(params), deck, full,
                          "--grid " + " ".join(f"{k}={v}" for k, v in params.items())))
    _check_unique(cases)
    return cases


# Names of the batch's own files in OUT: no case may be called so.
RESERVED = ("batch.log", "batch_cases.json", "summary.csv", "summary.h5")


def _check_unique(cases: Sequence[Case]):
    seen: Dict[str, Case] = {}
    for case in cases:
        if case.id.lower() in RESERVED or case.id.lower().startswith(("compare_",
                                                                      "envelope_",
                                                                      "plot_")):
            raise BatchInputError(f"{case.origin}: case id {case.id!r} is a name the batch "
                                  "uses for its own files")
        key = case.id.lower()   # folders must differ on case-insensitive file systems too
        if key in seen:
            raise BatchInputError(f"{case.origin}: duplicate case id {case.id!r} (also "
                                  f"{seen[key].origin})")
        seen[key] = case


def check_declared(cases: Sequence[Case]):
    """Every parameter of every case is declared by its deck's *PARAMETER block."""
    declared: Dict[Path, Dict[str, str]] = {}
    for case in cases:
        if not case.params:
            continue
        if case.deck not in declared:
            declared[case.deck] = deck_parameters(case.deck)
        names = declared[case.deck]
        for name in case.params:
            if name.upper() not in names:
                known = ", ".join(names) or "none"
                raise BatchInputError(f"{case.origin}: parameter {name} is not declared by "
                                      f"*PARAMETER in {case.deck} (declared: {known})")
