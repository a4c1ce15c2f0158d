#!/usr/bin/env bash
# Install what rodyn needs on a Debian machine, only what is missing:
# gfortran, CMake, LAPACK/BLAS, ARPACK, HDF5 with its Fortran interface, m4 (to build pFUnit for
# the tests: tools/pfunit.sh) (Debian packages),
# numpy, matplotlib, h5py for the post-processing, pytest and scipy for the tests, Dask
# for batches beyond one machine, fypp for the build (PyPI), and the post-processing
# package itself (postproc/, editable, with its extra 'dask': its console commands go on
# the PATH).
set -euo pipefail
cd "$(dirname "$0")/.."

debs=(gfortran cmake make liblapack-dev libblas-dev libarpack2-dev libhdf5-dev m4)
# --tests (tools/test.sh): also valgrind, for the allocation check of the Newton loops
# (bench/alloc_check.sh, CTest bench_alloc_check_quick), and strace, which stops a run at
# a chosen system call (tests/program/check_status_gap.py), and g++, which builds MoorDyn's
# own C++ tests against librodyn (tests/moordyn_suite/)
[ "${1:-}" = "--tests" ] && debs+=(valgrind strace g++)
# python3 and pip may come from elsewhere (pyenv): ask Debian only when absent
command -v python3 >/dev/null 2>&1 || debs+=(python3)
python3 -m pip --version >/dev/null 2>&1 || debs+=(python3-pip)
missing=()
for p in "${debs[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing Debian packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi

if ! python3 -c 'import numpy, matplotlib, scipy, h5py, pytest, distributed' >/dev/null 2>&1; then
  echo "setup: installing Python packages from postproc/requirements.txt"
  python3 -m pip install -q -r postproc/requirements.txt 2>/dev/null ||
    python3 -m pip install -q --break-system-packages -r postproc/requirements.txt
fi

# fypp, the preprocessor the build runs (CMakeLists.txt) to generate the per-type and
# per-rank routines of the HDF5 layer from src/io/rodyn_hdf5_arrays.fypp
if ! command -v fypp >/dev/null 2>&1; then
  echo "setup: installing fypp (PyPI)"
  python3 -m pip install -q 'fypp>=3.1' 2>/dev/null ||
    python3 -m pip install -q --break-system-packages 'fypp>=3.1'
  if command -v pyenv >/dev/null 2>&1; then pyenv rehash; fi  # the shim of its command
fi

# The post-processing package (postproc/pyproject.toml: rodyn_post and its console
# commands rodyn-plot-all, rodyn-compare, ...), installed in editable mode from this
# checkout. Several checkouts may share one Python: install again when the installed
# rodyn_post is another checkout's, or its commands or version are not those of
# pyproject.toml; otherwise nothing is done (a fraction of a second).
# RODYN_SKIP_PY_INSTALL=1 leaves the installed one alone (a throw-away clone on a machine
# whose Python others use: run its tests with PYTHONPATH=<clone>/postproc instead).
if [ "${RODYN_SKIP_PY_INSTALL:-0}" = 1 ]; then
  echo "setup: RODYN_SKIP_PY_INSTALL=1: the post-processing package is not installed"
elif ! python3 - "$PWD/postproc" >/dev/null 2>&1 <<'EOF'
import importlib.metadata, importlib.util, re, sys
from pathlib import Path
postproc = Path(sys.argv[1]).resolve()
spec = importlib.util.find_spec("rodyn_post")
assert spec and Path(spec.origin).resolve() == postproc / "rodyn_post" / "__init__.py"
text = (postproc / "pyproject.toml").read_text(encoding="utf-8")
scripts = re.search(r"^\[project\.scripts\]\n(.*?)(?=^\[|\Z)", text, re.M | re.S).group(1)
scripts = dict(re.findall(r'^([\w-]+)\s*=\s*"([\w.]+:\w+)"', scripts, re.M))
dist = importlib.metadata.distribution("rodyn_post")  # the dist-info name (3.9 too)
assert {e.name: e.value for e in dist.entry_points if e.group == "console_scripts"} == scripts
assert dist.version == re.search(r'^version\s*=\s*"([^"]+)"', text, re.M).group(1)
EOF
then
  echo "setup: installing the post-processing package from postproc/ (pip install -e, with Dask)"
  python3 -m pip install -q -e 'postproc[dask]' 2>/dev/null ||
    python3 -m pip install -q --break-system-packages -e 'postproc[dask]'
  if command -v pyenv >/dev/null 2>&1; then pyenv rehash; fi  # shims of the new commands
fi
command -v rodyn-plot-all >/dev/null 2>&1 ||
  echo "setup: warning: the console commands (rodyn-plot-all, ...) are not on the PATH;" \
       "pip put them in $(python3 -c 'import sysconfig; print(sysconfig.get_path("scripts"))')" \
       "(or ~/.local/bin for a user install)" >&2
echo "setup: $(gfortran --version | head -1); $(cmake --version | head -1)"
