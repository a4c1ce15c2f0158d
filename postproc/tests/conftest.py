"""Fixtures shared by the post-processing tests.

The tests use the installed package rodyn_post (`python3 -m pip install -e postproc`,
which tools/setup.sh does); pytest puts this folder on the path for designed.py and the
helpers the test modules share. A rodyn_post installed from another checkout would be
tested instead of this one: the tests then stop before any of them runs.
"""
from pathlib import Path

import pytest

import rodyn_post
from designed import short_case2, write_designed

POSTPROC = Path(__file__).resolve().parents[1]
INSTALLED = Path(rodyn_post.__file__).resolve().parent
if INSTALLED != POSTPROC / "rodyn_post":
    pytest.exit(f"rodyn_post is installed from {INSTALLED}, not from this checkout's "
                f"{POSTPROC / 'rodyn_post'}: run `bash tools/setup.sh` (or `python3 -m pip "
                f"install -e {POSTPROC}`)", returncode=4)


@pytest.fixture(scope="session")
def short_run(tmp_path_factory):
    """Folder of 0.6 s of the paper's case 2 run by RODYN_EXE (skipped without it),
    made once per pytest run; tests copy it before writing into it."""
    return short_case2(tmp_path_factory.mktemp("rodyn") / "case2_short")


@pytest.fixture
def designed_run(tmp_path):
    """(folder, lines, log) of the synthetic run of designed.py (dynamic.h5 and CSV)."""
    folder = tmp_path / "designed"
    lines, log = write_designed(folder)
    return folder, lines, log
