#!/usr/bin/env bash
# Does anything allocate inside rodyn's Newton loop?
#
# Runs the paper cable deck (10 cubic elements, pinned ends, self-weight) under
# valgrind memcheck and reads "total heap usage: N allocs". The deck is run with
# *STATIC, INCREMENTS=1 and INCREMENTS=8, with 10 and 40 elements, and again with a
# 20 kN point load at midspan (whether extra increments add Newton iterations to the
# paper deck alone depends on how the solver treats self-weight on a line that starts
# as a catenary; a point load is always ramped with the load factor, so there 8
# increments need several times the iterations of 1; the table shows the iterations
# of every run). For each mesh the allocation count must be the same
# whatever the number of increments and iterations; it may differ between meshes
# (set-up). The decks differ only in the digit of INCREMENTS, so deck parsing costs
# the same.
#
# Then the time loop: the paper's case 1 (10 cubic elements, end A heaved, EMC, no
# output files, frames at the start and the end only), 10 steps of 0.1 s with the
# tolerances FORCE TOL = DISP TOL = 1e-8 (the defaults) and 1e-11: the count must be the
# same (nothing allocated per Newton iteration); the same with the dissipative EMC
# (RHO INF=0.8). A run of 20 steps shows what a step adds.
#
# On FAIL the 40-element, 8-increment loaded run (or the 20-step run) is repeated with
# --xtree-memory=full and the routines that allocate are listed by allocation count.
#
# usage: bench/alloc_check.sh [--rodyn PATH] [--quick] [--keep] [--help]
#   --rodyn PATH   rodyn executable (default: build/rodyn of this repository)
#   --quick        statics with the 40-element loaded deck only (CTest
#                  bench_alloc_check_quick, about 15 s)
#   --keep         keep the temporary folder (decks, valgrind logs, xtree file)
# exit status: 0 PASS, 1 FAIL, 2 could not run
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rodyn="$root/build/rodyn"
keep=0
quick=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rodyn) rodyn="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "unknown option: $1" >&2; exit 2 ;;
  esac
done
rodyn="$(cd "$(dirname "$rodyn")" && pwd)/$(basename "$rodyn")"
[[ -x "$rodyn" ]] || { echo "no executable rodyn at $rodyn" >&2; exit 2; }
if ! command -v valgrind >/dev/null; then
  echo "valgrind not found; installing it with apt-get" >&2
  (apt-get update -qq && apt-get install -y -qq valgrind) >&2 || {
    echo "could not install valgrind" >&2; exit 2; }
fi

tmp="$(mktemp -d /tmp/rodyn_alloc.XXXXXX)"
if [[ $keep -eq 0 ]]; then trap 'rm -rf "$tmp"' EXIT; else echo "keeping $tmp"; fi

# deck NE INCREMENTS LOAD(0|1)
deck() {
  local ne=$1 inc=$2 load=$3 mid=$((3 * $1 / 2 + 1))
  cat <<EOF
** bench/alloc_check.sh: paper cable, $ne cubic elements
*HEADING
Paper cable (dos Santos & Rochinha, Table 1): static shape under self-weight
*GRAVITY
0.0, 0.0, -9.80665
*SECTION, NAME=CABLE, OD=0.3172
7.96e8, 5.882e4, 5.882e4, 9.25e6, 226.7
*LINE, NAME=CABLE, SECTION=CABLE, LENGTH=10.0, ELEMENTS=$ne, ORDER=3
0.0, 0.0, 0.0, 8.0, 0.0, -1.0
*BOUNDARY, LINE=CABLE, END=A, TYPE=PINNED
*BOUNDARY, LINE=CABLE, END=B, TYPE=PINNED
EOF
  if [[ $load -eq 1 ]]; then
    printf '*LOAD, LINE=CABLE, NODE=%d\n0.0, 0.0, -20000.0\n' "$mid"
  fi
  printf '*STATIC, INCREMENTS=%d\n*OUTPUT, CSV=NO, HDF5=NO\n' "$inc"
}

status_value() { sed -n "s/^$2 *= *//p" "$1/status.txt"; }

echo "rodyn: $rodyn ($("$rodyn" --version 2>&1 | head -1))"
echo "valgrind: $(valgrind --version)"
echo
printf '%-22s %9s %11s %11s %12s\n' case elements increments iterations allocs
fail=0
declare -A allocs
loads="0 1"; meshes="10 40"
[[ $quick -eq 1 ]] && { loads="1"; meshes="40"; }
for load in $loads; do
  for ne in $meshes; do
    for inc in 1 8; do
      name="$([[ $load -eq 1 ]] && echo "paper+20kN" || echo "paper")"
      tag="${name}_n${ne}_inc${inc}"
      deck "$ne" "$inc" "$load" >"$tmp/$tag.inp"
      rc=0
      valgrind --tool=memcheck --log-file="$tmp/$tag.vg" \
        "$rodyn" "$tmp/$tag.inp" -o "$tmp/out_$tag" --quiet >"$tmp/$tag.out" || rc=$?
      if [[ $rc -ne 0 ]]; then
        echo "rodyn exited with $rc on $tag:" >&2; cat "$tmp/$tag.vg" >&2; exit 2
      fi
      n=$(sed -n 's/.*total heap usage: \([0-9,]*\) allocs.*/\1/p' "$tmp/$tag.vg" | tr -d ,)
      it=$(status_value "$tmp/out_$tag" iterations)
      ninc=$(status_value "$tmp/out_$tag" increments)
      allocs[$tag]=$n
      printf '%-22s %9d %11s %11s %12d\n' "$name" "$ne" "$ninc" "$it" "$n"
    done
  done
done
echo
for load in $loads; do
  name="$([[ $load -eq 1 ]] && echo "paper+20kN" || echo "paper")"
  for ne in $meshes; do
    a=${allocs[${name}_n${ne}_inc1]}
    b=${allocs[${name}_n${ne}_inc8]}
    if [[ "$a" == "$b" ]]; then
      echo "PASS  $name, $ne elements: $a allocs with 1 and with 8 increments"
    else
      echo "FAIL  $name, $ne elements: $a allocs with 1 increment, $b with 8 (+$((b - a)))"
      fail=1
    fi
  done
done

# the time loop: 10 steps of the paper's case 1 with FORCE TOL = DISP TOL = 1e-08 (the
# defaults) and 1e-11 (more Newton iterations; the decks differ only in those digits);
# then 20 steps (information: what a step allocates, the support forces of each step)
dyn_deck() {
  deck 10 1 0 | sed '/^\*STATIC/d; /^\*OUTPUT/d'
  printf '*MOTION, LINE=CABLE, END=A, TYPE=HARMONIC\nZ, 0.4, 0.658, 0.0\n'
  printf '*DYNAMIC, DT=0.1, TIME=%s, OUTPUT INTERVAL=%s%s\n*OUTPUT, CSV=NO, HDF5=NO\n' \
    "$1" "$1" "$2"
}
echo
printf '%-22s %9s %11s %11s %12s\n' case elements steps iterations allocs
for tag in case1_t1 case1_t1_tight case1_t2 edmc_t1 edmc_t1_tight; do
  case $tag in
    case1_t1) dyn_deck 1.0 ", FORCE TOL=1e-08, DISP TOL=1e-08" >"$tmp/$tag.inp" ;;
    case1_t1_tight) dyn_deck 1.0 ", FORCE TOL=1e-11, DISP TOL=1e-11" >"$tmp/$tag.inp" ;;
    case1_t2) dyn_deck 2.0 ", FORCE TOL=1e-08, DISP TOL=1e-08" >"$tmp/$tag.inp" ;;
    edmc_t1) dyn_deck 1.0 ", FORCE TOL=1e-08, DISP TOL=1e-08, RHO INF=0.8" >"$tmp/$tag.inp" ;;
    edmc_t1_tight) dyn_deck 1.0 ", FORCE TOL=1e-11, DISP TOL=1e-11, RHO INF=0.8" \
      >"$tmp/$tag.inp" ;;
  esac
  rc=0
  valgrind --tool=memcheck --log-file="$tmp/$tag.vg" \
    "$rodyn" "$tmp/$tag.inp" -o "$tmp/out_$tag" --quiet >"$tmp/$tag.out" 2>&1 || rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "rodyn exited with $rc on $tag:" >&2; cat "$tmp/$tag.vg" >&2; exit 2
  fi
  allocs[$tag]=$(sed -n 's/.*total heap usage: \([0-9,]*\) allocs.*/\1/p' "$tmp/$tag.vg" | tr -d ,)
  printf '%-22s %9d %11s %11s %12d\n' "case 1 (dynamic)" 10 \
    "$(status_value "$tmp/out_$tag" steps)" "$(status_value "$tmp/out_$tag" step_iterations)" \
    "${allocs[$tag]}"
done
a=${allocs[case1_t1]}
b=${allocs[case1_t1_tight]}
c=${allocs[case1_t2]}
dyn_fail=0
if [[ "$a" == "$b" ]]; then
  echo "PASS  case 1 (dynamic), 10 steps: $a allocs with tolerances 1e-8 and 1e-11"
else
  echo "FAIL  case 1 (dynamic), 10 steps: $a allocs with tolerances 1e-8, $b with 1e-11 (+$((b - a)))"
  dyn_fail=1
fi
d=${allocs[edmc_t1]}
e=${allocs[edmc_t1_tight]}
if [[ "$d" == "$e" ]]; then
  echo "PASS  case 1 (dynamic, RHO INF=0.8), 10 steps: $d allocs with tolerances 1e-8 and 1e-11"
else
  echo "FAIL  case 1 (dynamic, RHO INF=0.8), 10 steps: $d allocs with 1e-8, $e with 1e-11 (+$((e - d)))"
  dyn_fail=1
fi
echo "info  case 1 (dynamic): 20 steps allocate $((c - a)) more than 10 (the support forces kept and written each step, after_step and write_pending; the warning of the longer deck)"

if [[ $fail -eq 0 && $dyn_fail -eq 0 ]]; then
  echo
  echo "PASS: the allocation count does not depend on increments or Newton iterations"
  exit 0
fi

echo
echo "FAIL: heap allocations grow with the number of increments, steps or iterations."
echo "Allocating routines (valgrind --xtree-memory=full; column = number of allocations"
echo "made in the routine and below):"
tag="paper+20kN_n40_inc8"
[[ $fail -eq 0 ]] && tag="case1_t1_tight"
valgrind --tool=memcheck --log-file="$tmp/xtree.vg" --xtree-memory=full \
  --xtree-memory-file="$tmp/xtree.kcg" \
  "$rodyn" "$tmp/$tag.inp" -o "$tmp/out_xtree" --quiet >/dev/null || true
callgrind_annotate --inclusive=yes --show=totBk --threshold=100 --auto=no "$tmp/xtree.kcg" \
  2>/dev/null | grep -E '__rodyn_|MAIN__' | grep -vE 'PROGRAM TOTALS' |
  sed -E 's/UnknownFile\?\?\?://; s/__rodyn_([a-z_]+)_MOD_/\1::/' | head -25
exit 1
