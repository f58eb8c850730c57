#!/usr/bin/env bash
# The `slow` tests <case>_reference_regenerates (validation/CMakeLists.txt, docs/compare.md):
# regenerates the ibms_*.csv references of one validation case with scripts/make-compare-references.sh
# (ONLY=CASE, REFERENCE_OUT=WORK_DIR/out) and compares each with the shipped
# validation/CASE/reference/ibms_*.csv by scripts/compare-reference.py within |d| <= ABS + REL |shipped|
# per cell, or, with ABS = mean-path:T0:T1 (chaotic particle trajectories), the mean centroid path
# length over T0 <= t <= T1 within the relative tolerance REL; with ABS = extrema:T0 (periodic
# force histories whose phase round-off sets) the largest, smallest and mean value of each column
# over t >= T0 within REL of the column's largest |value|.
# usage: scripts/reference-regenerates.sh IBMS_BINARY WORK_DIR CASE ABS REL [RUN_OUTPUT=NAME ...]
# WORK_DIR is emptied first (no stale run is reused); each RUN_OUTPUT=NAME links an existing run
# output of a ctest fixture (e.g. build/validation/cavity_deformable_objects/k10.h5) as
# WORK_DIR/NAME, so that the run is not made twice; a missing RUN_OUTPUT fails the test.
set -euo pipefail
ibms=$1; work=$2; case=$3; tol_abs=$4; tol_rel=$5; shift 5
src=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$work"
mkdir -p "$work"
for link in "$@"; do
  from=${link%%=*}; name=${link#*=}
  [[ -s $from ]] || { echo "FAIL: fixture output $from is missing or empty"; exit 2; }
  ln -s "$from" "$work/$name"
done
start=$(date +%s)
REFERENCE_OUT="$work/out" ONLY="$case" CAVITY_CASES="" "$src/scripts/make-compare-references.sh" "$ibms" "$work"
echo "regenerated in $(( $(date +%s) - start )) s (fixture runs not counted)"
status=0
shopt -s nullglob
shipped=("$src/validation/$case/reference/"ibms_*.csv)
made=("$work/out/$case/reference/"ibms_*.csv)
[[ ${#shipped[@]} -gt 0 ]] || { echo "FAIL: no shipped validation/$case/reference/ibms_*.csv"; exit 2; }
[[ ${#made[@]} -eq ${#shipped[@]} ]] || { echo "FAIL: ${#made[@]} references regenerated, ${#shipped[@]} shipped"; exit 2; }
for f in "${shipped[@]}"; do
  regenerated=$work/out/$case/reference/$(basename "$f")
  if [[ $tol_abs == mean-path:* ]]; then
    IFS=: read -r _ t0 t1 <<< "$tol_abs"
    /usr/bin/python3 "$src/scripts/compare-reference.py" --mean-path "$t0" "$t1" "$f" "$regenerated" "$tol_rel" || status=1
  elif [[ $tol_abs == extrema:* ]]; then
    /usr/bin/python3 "$src/scripts/compare-reference.py" --extrema "${tol_abs#extrema:}" "$f" "$regenerated" "$tol_rel" || status=1
  else
    /usr/bin/python3 "$src/scripts/compare-reference.py" "$f" "$regenerated" "$tol_abs" "$tol_rel" || status=1
  fi
done
exit $status
