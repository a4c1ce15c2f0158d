#!/usr/bin/env bash
# Install what rodyn needs on a Debian machine, only what is missing:
# gfortran, CMake, LAPACK/BLAS, HDF5 with its Fortran interface (Debian packages),
# and numpy, matplotlib, h5py, pytest for the post-processing (PyPI).
set -euo pipefail
cd "$(dirname "$0")/.."

debs=(gfortran cmake make liblapack-dev libblas-dev libhdf5-dev)
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

if ! python3 -c 'import numpy, matplotlib, scipy, h5py, pytest' >/dev/null 2>&1; then
  echo "setup: installing Python packages from postproc/requirements.txt"
  python3 -m pip install -q -r postproc/requirements.txt 2>/dev/null ||
    python3 -m pip install -q --break-system-packages -r postproc/requirements.txt
fi
echo "setup: $(gfortran --version | head -1); $(cmake --version | head -1)"
