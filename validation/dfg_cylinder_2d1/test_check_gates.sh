#!/usr/bin/env bash
# The gates of dfg_check on synthetic series (no run): a steady c_D of 5.595 (+0.28 % of John &
# Matthies' 5.5795, above the published upper bound 5.59) passes `drag_every` (within 1 %) and
# fails `drag_bounds`; 5.585 passes both; an unknown gate is an error (exit 2).
# usage: test_check_gates.sh DFG_CHECK REFERENCE_CSV
set -u
check=$1 reference=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
series() {  # series BASE CD: two rows of a steady run with drag CD (control volume equal)
  {
    echo "time,body_000/drag_coefficient,body_000/lift_coefficient,body_000/cv_drag_coefficient,probe_000/pressure,probe_001/pressure,probe_002/pressure,probe_003/pressure,probe_004/pressure,probe_005/pressure"
    echo "9.9,$2,0.0106,$2,0.1,0.1,0.1,0.0,0.0,0.0"
    echo "10,$2,0.0106,$2,0.1,0.1,0.1,0.0,0.0,0.0"
  } > "$1_bodies.csv"
}
series "$dir/outside" 5.595
series "$dir/inside" 5.585
fail=0
expect() {  # expect CODE GATES BASE
  "$check" steady synthetic "$reference" "$2" "20:$3" > "$dir/out.txt" 2>&1
  local code=$?
  if [ "$code" -ne "$1" ]; then
    echo "FAIL: gates $2 on $(basename "$3"): exit $code, expected $1"; cat "$dir/out.txt"; fail=1
  else
    echo "ok: gates $2 on $(basename "$3"): exit $code"
  fi
}
expect 0 drag_every "$dir/outside"
expect 1 drag_bounds "$dir/outside"
expect 0 drag_bounds "$dir/inside"
expect 0 drag_every,drag_bounds "$dir/inside"
expect 1 drag_every,drag_bounds "$dir/outside"
expect 2 drag_bound "$dir/inside"
exit $fail
