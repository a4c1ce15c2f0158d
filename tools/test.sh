#!/usr/bin/env bash
# Whole test suite: set up, build real pFUnit 4.9.0 once per machine into a cache outside
# the repository (tools/pfunit.sh; later runs reuse it), then
#  1. Debug build (-fcheck=all -ffpe-trap=invalid,zero,overflow, warnings on): every test;
#  2. Release build: every test again (optimised code paths), and the post-processing
#     tests (pytest) on a result made by the Release program.
# Usage: bash tools/test.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh --tests
pfunit="$(bash tools/pfunit.sh)"  # its install prefix
jobs="$(nproc)"

# Build quietly (stdout dropped), but show stderr (warnings, errors) except the two lines
# pFUnit's preprocessor writes for every .pf it translates. A failed build fails the script
# (pipefail: the status is cmake's).
build() {
  cmake --build "$1" -j "$jobs" 2>&1 >/dev/null |
    { grep -v -e '^Processing file ' -e '^ \.\.\. Done\.  Results in ' >&2 || true; }
}

cmake -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug -DBUILD_TESTING=ON \
      -DCMAKE_PREFIX_PATH="$pfunit" >/dev/null
build build-debug
(cd build-debug && ctest -j "$jobs" --output-on-failure)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON \
      -DCMAKE_PREFIX_PATH="$pfunit" >/dev/null
build build
(cd build && ctest -j "$jobs" --output-on-failure)

RODYN_EXE="$PWD/build/rodyn" python3 -m pytest -q postproc/tests
