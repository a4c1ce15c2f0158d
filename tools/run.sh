#!/usr/bin/env bash
# Main job: set up, build (Release), run the paper's cable and plot it.
# Usage: bash tools/run.sh [DECK]     results in ./<deck name>/
# Without DECK: the paper's static cable (input/paper_cable.inp) and its four dynamic
# cases (input/paper_case1.inp .. paper_case4.inp, the paper's Figures 3 to 6), and the
# mooring leg in water (input/mooring_catenary.inp, mooring_surge.inp,
# mooring_current.inp) and the published lazy-wave cable (input/riser_lazy_wave.inp,
# riser_lazy_wave_heave.inp), the chain - wire - chain leg of the README
# (input/chain_wire_chain.inp), and two mooring systems: a tethered subsea buoy
# (input/tethered_buoy.inp), the OC3-Hywind spar on its three chains
# (input/oc3_spar.inp, and in a regular wave input/oc3_spar_waves.inp) and a
# semi-submersible losing a chain (input/semisub_failure.inp),
# each into ./<deck name>/ with every plot of
# rodyn-plot-all (the post-processing package of postproc/, installed by tools/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then
  decks=("$1")
else
  decks=(input/paper_cable.inp input/paper_case1.inp input/paper_case2.inp
         input/paper_case3.inp input/paper_case4.inp input/mooring_catenary.inp
         input/mooring_surge.inp input/mooring_current.inp input/riser_lazy_wave.inp
         input/riser_lazy_wave_heave.inp input/chain_wire_chain.inp input/tethered_buoy.inp
         input/oc3_spar.inp input/oc3_spar_waves.inp input/semisub_failure.inp)
fi
bash tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build build -j "$(nproc)" >/dev/null
for deck in "${decks[@]}"; do
  ./build/rodyn "$deck"
  rodyn-plot-all "$(basename "${deck%.*}")"
done
