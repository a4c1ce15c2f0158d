"""rodyn_post as an installed package: every console command of postproc/pyproject.toml
is installed, resolves to its function and answers --help with exit status 0; every
command module names its console command and reads results only through the readers; no
file of postproc/ edits the module path.
"""
import importlib
import importlib.metadata
import importlib.util
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

import rodyn_post.commands

POSTPROC = Path(__file__).resolve().parents[1]
PATH_EDIT = "sys." + "path"  # spelled so that this file does not hold it


def console_scripts():
    """{command: 'module:function'} of [project.scripts] in postproc/pyproject.toml (read
    by hand: tomllib is Python 3.11+)."""
    text = (POSTPROC / "pyproject.toml").read_text(encoding="utf-8")
    section = re.search(r"^\[project\.scripts\]\n(.*?)(?=^\[|\Z)", text, re.M | re.S)
    assert section, "pyproject.toml has no [project.scripts]"
    return dict(re.findall(r'^([\w-]+)\s*=\s*"([\w.]+:\w+)"', section.group(1), re.M))


SCRIPTS = console_scripts()
COMMAND_MODULES = sorted(path.stem for path in Path(rodyn_post.commands.__file__).parent
                         .glob("*.py") if path.stem != "__init__")


def test_every_tool_has_a_command():
    assert len(COMMAND_MODULES) == 8, COMMAND_MODULES
    for name in COMMAND_MODULES:
        module = importlib.import_module(f"rodyn_post.commands.{name}")
        assert SCRIPTS.get(module.COMMAND) == f"rodyn_post.commands.{name}:main", name
    assert SCRIPTS.get("rodyn-batch") == "rodyn_post.batch:main"


def test_installed_entry_points_are_those_of_pyproject():
    """The installed metadata holds the commands of pyproject.toml (else the install is
    stale: tools/setup.sh reinstalls)."""
    installed = {ep.name: ep.value for ep in
                 importlib.metadata.distribution("rodyn_post").entry_points
                 if ep.group == "console_scripts"}
    assert installed == SCRIPTS


def executable(command):
    """Path of an installed console command: on the PATH, else in the scripts folder of
    this Python."""
    found = shutil.which(command)
    if found is None:
        candidate = Path(sysconfig.get_path("scripts")) / command
        found = str(candidate) if candidate.is_file() else None
    return found


@pytest.mark.parametrize("command", sorted(SCRIPTS))
def test_console_command_resolves_and_helps(command):
    module_name, function = SCRIPTS[command].split(":")
    if importlib.util.find_spec(module_name) is None:
        pytest.skip(f"{module_name} is not in this checkout yet (name reserved)")
    assert callable(getattr(importlib.import_module(module_name), function))
    path = executable(command)
    assert path, f"{command} is not installed (bash tools/setup.sh)"
    run = subprocess.run([path, "--help"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith(f"usage: {command}"), run.stdout[:200]
    assert "exit status" in run.stdout


def test_no_path_edits_in_postproc():
    offenders = []
    for path in sorted(POSTPROC.rglob("*")):
        parts = set(path.relative_to(POSTPROC).parts)
        if not path.is_file() or parts & {"__pycache__", ".pytest_cache"} or any(
                part.endswith(".egg-info") for part in parts):
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue  # a binary file
        offenders += [f"{path.relative_to(POSTPROC)}:{number}"
                      for number, line in enumerate(text.splitlines(), 1)
                      if PATH_EDIT in line]
    assert not offenders, offenders


def test_commands_read_through_the_readers():
    """The commands read results only through rodyn_post's readers (load_static,
    load_dynamic, ReferenceTable), never with h5py or the csv module of their own."""
    folder = Path(rodyn_post.commands.__file__).parent
    own_readers = re.compile(r"^\s*(import|from)\s+(h5py|csv)\b", re.M)
    offenders = [path.name for path in sorted(folder.glob("*.py"))
                 if own_readers.search(path.read_text(encoding="utf-8"))]
    assert not offenders, offenders


def _requirement_names(items):
    """The distribution names (with extras) of requirement strings, lower case."""
    return {re.match(r"\s*([A-Za-z0-9_.\-]+(\[[\w,]+\])?)", item).group(1).lower()
            for item in items}


def _pyproject_lists():
    """(dependencies, {extra: [requirements]}) of pyproject.toml, read by hand (tomllib is
    Python 3.11+): each list is a run of quoted strings in [project] and
    [project.optional-dependencies]."""
    text = (POSTPROC / "pyproject.toml").read_text(encoding="utf-8")
    deps = re.search(r"^dependencies = \[(.*?)^\]", text, re.M | re.S).group(1)
    extras_text = re.search(r"^\[project\.optional-dependencies\]\n(.*?)(?=^\[)", text,
                            re.M | re.S).group(1)
    extras = {name: re.findall(r'"([^"]+)"', body) for name, body in
              re.findall(r"^(\w+) = \[(.*?)\]\s*(?:#[^\n]*)?$", extras_text, re.M | re.S)}
    return re.findall(r'"([^"]+)"', deps), extras


def test_dependencies_plain_test_and_dask():
    """A plain install is numpy, matplotlib and h5py; scipy (used by a verification
    script of the tests only) is in the `test` extra, Dask in the `dask` extra; and
    requirements.txt (what tools/setup.sh installs) is the union of the three sets."""
    deps, extras = _pyproject_lists()
    assert _requirement_names(deps) == {"numpy", "matplotlib", "h5py"}
    assert _requirement_names(extras["test"]) == {"pytest", "scipy"}
    assert _requirement_names(extras["dask"]) == {"dask[distributed]"}
    lines = [line.split("#")[0].strip() for line in
             (POSTPROC / "requirements.txt").read_text(encoding="utf-8").splitlines()]
    assert _requirement_names([x for x in lines if x]) == _requirement_names(
        deps + extras["test"] + extras["dask"])
    importers = [p.name for p in sorted((POSTPROC / "rodyn_post").rglob("*.py"))
                 if re.search(r"^\s*(import|from)\s+(scipy|dask|distributed)\b",
                              p.read_text(encoding="utf-8"), re.M)
                 and p.name != "batch.py"]
    assert not importers, importers


def test_package_imports_without_dask_and_scipy(tmp_path):
    """Every module of rodyn_post imports with dask, distributed and scipy absent, and a
    local batch lists its cases; --scheduler then says which extra is missing (exit 1)."""
    deck = tmp_path / "a.inp"
    deck.write_text("*HEADING\nx\n")
    code = f"""
import importlib, pkgutil, sys
for name in ("dask", "distributed", "scipy"):
    sys.modules[name] = None                 # 'import name' raises ImportError
import rodyn_post, rodyn_post.commands
for info in pkgutil.walk_packages(rodyn_post.__path__, "rodyn_post."):
    importlib.import_module(info.name)
from rodyn_post import batch
argv = [{str(deck)!r}, "-o", {str(tmp_path / 'out')!r}, "--rodyn", sys.executable]
assert batch.main(argv + ["--list"]) == 0
sys.exit(batch.main(argv + ["--scheduler", "tcp://127.0.0.1:1"]))
"""
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120, cwd=tmp_path)
    assert run.returncode == 1, run.stderr
    assert run.stdout.startswith("a\trun\t"), run.stdout
    err = run.stderr.strip()
    assert len(err.splitlines()) == 1, err
    assert "Dask is not installed" in err and "rodyn-post[dask]" in err, err
