"""Fixtures shared by the post-processing tests."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))         # designed.py
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))     # postproc/

from designed import short_case2, write_designed  # noqa: E402


@pytest.fixture(scope="session")
def short_run(tmp_path_factory):
    """Folder of 0.6 s of the paper's case 2 run by RODYN_EXE (skipped without it),
    made once per test session; tests copy it before writing into it."""
    return short_case2(tmp_path_factory.mktemp("rodyn") / "case2_short")


@pytest.fixture
def designed_run(tmp_path):
    """(folder, lines, log) of the synthetic run of designed.py (dynamic.h5 and CSV)."""
    folder = tmp_path / "designed"
    lines, log = write_designed(folder)
    return folder, lines, log
