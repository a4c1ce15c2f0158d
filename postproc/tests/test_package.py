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


def test_dask_and_scipy_optional():
    """The package and a local batch import neither Dask nor scipy; --scheduler
    without Dask is refused in one line naming the extra rodyn-post[dask]."""
    code = (
        "import sys\n"
        "sys.modules['distributed'] = sys.modules['dask'] = sys.modules['scipy'] = None\n"
        "import rodyn_post, rodyn_post.batch, rodyn_post.commands.plot_all\n"
        "import rodyn_post.commands.to_paraview, rodyn_post.commands.range_graph\n"
        "sys.exit(rodyn_post.batch.main(['x.inp', '-o', 'o', '--scheduler', 'tcp://h:1',"
        " '--rodyn', sys.executable]))\n")
    import os
    import sys
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        Path(tmp, "x.inp").write_text("*HEADING\nx\n")
        done = subprocess.run([sys.executable, "-c", code], cwd=tmp, capture_output=True,
                              text=True, env=dict(os.environ, PYTHONPATH=str(POSTPROC)))
    assert done.returncode == 1, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "--scheduler needs Dask" in lines[0], done.stderr
    assert "postproc[dask]" in lines[0]
