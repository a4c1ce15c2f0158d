#!/usr/bin/env bash
# Main job: set up, build (Release), run the default deck (the paper's cable) and plot it.
# Usage: bash tools/run.sh [DECK]     results in ./<deck name>/
set -euo pipefail
cd "$(dirname "$0")/.."
deck="${1:-input/paper_cable.inp}"
bash tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build build -j "$(nproc)" >/dev/null
./build/rodyn "$deck"
out="$(basename "${deck%.*}")"
python3 postproc/plot_static.py "$out"
